#version 110
// SPDX-License-Identifier: MIT
// The terminator band of a light (shadow/volume.c): fragments whose facet
// turns away from the light while their shading normal (the terminator
// rule's, as terminator_point.glsl has it) turns toward it; every other fragment
// is discarded. On a closed mesh such a fragment lies inside its own
// mesh's volume once, and this pass takes that count back.
uniform vec4 u_color; // the light: its position (w 1) or the direction toward it (w 0)
uniform vec3 u_eye;
varying vec3 v_world;
varying vec3 v_normal;
varying vec3 v_plane_dn; // the terminator rule's tangent planes (lit.vert)
varying vec3 v_plane_nn;
varying vec3 v_plane_nx;

void main()
{
    mat3 nn = mat3(v_plane_nn.x, v_plane_nx.x, v_plane_nx.y,
                   v_plane_nx.x, v_plane_nn.y, v_plane_nx.z,
                   v_plane_nx.y, v_plane_nx.z, v_plane_nn.z);
    vec3 lift = v_plane_dn - nn * v_world;
    vec3 s = normalize(v_normal);
#ifdef STIN_NO_DERIVATIVES
    // no facet here: what it decides (its side of the light and of the eye,
    // the corners' normals on the eye's side, the curved surface above it)
    // is constant over a triangle and was asked of each on the CPU
    // (render/terminator_fixed.c), which draws only the triangles that pass;
    // one that keeps its facets (u_terminator 0) has no band
    if (v_plane_nn.x + v_plane_nn.y + v_plane_nn.z < 0.5)
        discard;
    vec3 world = v_world + lift;
    vec3 to_light = u_color.w == 0.0 ? u_color.xyz : u_color.xyz - world;
    if (dot(s, to_light) <= 0.0)
        discard;
#else
    vec3 ng = normalize(cross(dFdx(v_world), dFdy(v_world)));
    if (dot(ng, u_eye - v_world) < 0.0)
        ng = -ng;
    // a flat triangle (every corner's normal its facet's) or one that keeps
    // its facets (u_terminator 0) has no band
    if (v_plane_nn.x + v_plane_nn.y + v_plane_nn.z < 0.5 || dot(ng, nn * ng) >= 1.0 - 1e-6)
        discard;
    // where the curved surface lies below the facet (a concave corner) the
    // rule keeps the position, whose way to the light crosses its own facet
    if (dot(lift, ng) <= 0.0)
        discard;
    vec3 world = v_world + lift;
    vec3 to_light = u_color.w == 0.0 ? u_color.xyz : u_color.xyz - world;
    if (dot(ng, to_light) > 0.0 || dot(dot(s, ng) < 0.0 ? -s : s, to_light) <= 0.0)
        discard;
#endif
    gl_FragColor = vec4(0.0);
}
