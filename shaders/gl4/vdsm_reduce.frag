#version 150
// SPDX-License-Identifier: MIT
// VDSM light-view pyramid (src/shadow/vdsm_pyramid.c), one level per pass.
// Level 0 from the accumulation texture: x = the occluders' depth bound, BIG
// where no draw covers the texel wholly (nothing is known there); y = the
// deepest receiver, -BIG where none. Each coarser
// level is the maximum of its four children in both: an unknown child makes
// its parent unknown (the seed mapped empty children to -1 before the
// maximum, which let a triangle over an empty texel be culled).
uniform sampler2D u_source; // its base level is the level read
uniform int u_first;        // 1: level 0 from the accumulation texture
out vec4 frag_color;

const float BIG = 1e30;

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (u_first != 0) {
        vec4 a = texelFetch(u_source, px, 0);
        bool known = a.x > -0.5 * BIG;
        frag_color = vec4(known ? -a.x : BIG, a.y, 0.0, 0.0);
        return;
    }
    ivec2 q = px * 2;
    vec4 a = texelFetch(u_source, q, 0), b = texelFetch(u_source, q + ivec2(1, 0), 0),
         c = texelFetch(u_source, q + ivec2(0, 1), 0), d = texelFetch(u_source, q + ivec2(1, 1), 0);
    frag_color = max(max(a, b), max(c, d));
}
