#version 150
// SPDX-License-Identifier: MIT
// VDSM, first pass of a light: 1 where the side of the surface the eye sees
// faces the light by its facet or by its shading normal (the terminator
// rule, vdsm_position.frag), 0 where both turn away (it shadows itself, as
// the reference defines it). The shadow polygons then write 0 where a
// triangle lies between the surface and the light.
uniform sampler2D u_position;
uniform sampler2D u_normal;
uniform sampler2D u_shading;
uniform vec4 u_light; // world: position (w 1), or the direction toward the light (w 0)
out vec4 frag_color;

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 p = texelFetch(u_position, px, 0);
    vec3 n = texelFetch(u_normal, px, 0).xyz;
    vec3 s = texelFetch(u_shading, px, 0).xyz;
    vec3 to_light = u_light.xyz - p.xyz * u_light.w;
    float facing = max(dot(n, to_light), dot(s, to_light));
    frag_color = vec4(p.w > 0.0 && facing > 0.0 ? 1.0 : 0.0);
}
