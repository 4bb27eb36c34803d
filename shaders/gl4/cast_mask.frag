#version 150
// SPDX-License-Identifier: MIT
// vdsm's screen mask where it cannot cast the CSG products itself (no
// storage buffers; shadow/cast_map.c): 0 into the light's channel wherever
// the products' map shadows the surface in the position buffer (half its
// kernel or more); elsewhere the channel keeps vdsm's visibility.
uniform sampler2D u_position;
out vec4 frag_color;
vec3 v_world;

// The chunk uses GLSL 1.10's names: map them.
#define shadow2D(s, c) vec4(texture(s, c))
// float cast_visibility(): cast_test.glsl
// @chunks

void main()
{
    vec4 p = texelFetch(u_position, ivec2(gl_FragCoord.xy), 0);
    v_world = p.xyz;
    if (p.w <= 0.0 || cast_visibility() >= 0.5)
        discard;
    frag_color = vec4(0.0);
}
