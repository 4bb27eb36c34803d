#version 150
// SPDX-License-Identifier: MIT
// VDSM position buffer: per pixel the visible surface's world position (w = 1,
// 0 where nothing was drawn) and its facet normal turned to the side the eye
// sees. The facet normal comes from the position's screen derivatives, which
// are exact for the triangle's plane (its interpolation is linear).
uniform vec4 u_camera; // world: the eye (w 1), or the direction toward it (w 0)
// CSG products' faces (z 1): only where the fragment lies on the resolved
// surface, its window depth within w + u_csg_grow / (clip w) of the
// resolve's (texel = pixel - xy). A tolerance, not depth EQUAL: the
// resolve's depth came back through a float copy whose rounding into this
// buffer's depth format may differ, and a face the near plane cuts is
// clipped with another rounding here.
uniform vec4 u_csg;
uniform float u_csg_grow;
uniform sampler2D u_csg_depth;
in vec3 v_world;
out vec4 o_position;
out vec4 o_normal;

void main()
{
    if (u_csg.z > 0.0 &&
        abs(gl_FragCoord.z - texelFetch(u_csg_depth, ivec2(gl_FragCoord.xy - u_csg.xy), 0).r) >
            u_csg.w + u_csg_grow * gl_FragCoord.w)
        discard;
    vec3 n = cross(dFdx(v_world), dFdy(v_world));
    float len = length(n);
    n = len > 0.0 ? n / len : vec3(0.0);
    if (dot(n, u_camera.xyz - v_world * u_camera.w) < 0.0)
        n = -n;
    o_position = vec4(v_world, 1.0);
    o_normal = vec4(n, 0.0);
}
