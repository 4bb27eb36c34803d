#version 150
// SPDX-License-Identifier: MIT
// VDSM position buffer: per pixel the point the shadow test starts from (w =
// 1, 0 where nothing was drawn), the facet normal turned to the side the eye
// sees, and the shading normal; the side faces a light where either normal
// does. The facet normal comes from the position's screen derivatives, which
// are exact for the triangle's plane (its interpolation is linear). A flat
// triangle stores its position and the facet normal twice. A smooth one
// (vertex normals bent away from
// its facet) follows the terminator rule the reference shares (Hanika,
// "Hacking the Shadow Terminator", Ray Tracing Gems II, 2021): the point on
// the curved surface its normals describe - the position projected onto each
// corner's tangent plane, blended by the barycentrics - where that lies above
// the facet (a concave corner keeps the position), and the interpolated
// shading normal turned to the side of the facet the eye sees, so a side lit
// by its shading normal never shadows itself along the facets' steps, while
// one whose facet faces the light stays lit (seen from the light, all is).
uniform vec4 u_camera; // world: the eye (w 1), or the direction toward it (w 0)
// CSG products' faces and peeled layers (z 1): only where the fragment lies
// on the resolved surface or the layer, its window depth within w +
// u_csg_grow / (clip w) of the resolve's or the layer's (texel = pixel -
// xy). A tolerance, not depth EQUAL: the resolve's depth came back through
// a float copy whose rounding into this buffer's depth format may differ,
// the geometry stage may round a layer's depth otherwise than the lit
// programs that drew it, and a face the near plane cuts is clipped with
// another rounding here.
uniform vec4 u_csg;
uniform float u_csg_grow;
uniform sampler2D u_csg_depth;
in vec3 v_world;
in vec3 v_bary;
flat in mat3 v_corners;
flat in mat3 v_normals;
flat in float v_smooth;
out vec4 o_position;
out vec4 o_normal;
out vec4 o_shading;

void main()
{
    if (u_csg.z > 0.0 &&
        abs(gl_FragCoord.z - texelFetch(u_csg_depth, ivec2(gl_FragCoord.xy - u_csg.xy), 0).r) >
            u_csg.w + u_csg_grow * gl_FragCoord.w)
        discard;
    vec3 to_eye = u_camera.xyz - v_world * u_camera.w;
    vec3 n = cross(dFdx(v_world), dFdy(v_world)); // before any branch: derivatives
    float len = length(n);
    n = len > 0.0 ? n / len : vec3(0.0);
    if (dot(n, to_eye) < 0.0)
        n = -n;
    o_position = vec4(v_world, 1.0);
    o_normal = vec4(n, 0.0);
    o_shading = o_normal;
    if (v_smooth > 0.0) {
        vec3 facet = cross(v_corners[1] - v_corners[0], v_corners[2] - v_corners[0]);
        if (dot(facet, to_eye) < 0.0)
            facet = -facet;
        vec3 lift = vec3(0.0);
        for (int k = 0; k < 3; k++)
            lift += v_bary[k] * dot(v_corners[k] - v_world, v_normals[k]) * v_normals[k];
        vec3 s = normalize(v_normals * v_bary);
        if (dot(lift, facet) > 0.0)
            o_position.xyz += lift;
        o_shading.xyz = dot(s, facet) < 0.0 ? -s : s;
    }
}
