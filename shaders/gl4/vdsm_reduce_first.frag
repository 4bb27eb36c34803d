#version 430
// SPDX-License-Identifier: MIT
// VDSM light-view pyramid, level 0 where the receivers came by atomics
// (vdsm_receiver_atomic.frag): x from the occluders' accumulation as
// vdsm_reduce.frag takes it, y from the texel's ordered bits, which it sets
// back to 0 (none) for the next light: every texel is drawn here once.
layout(std430, binding = 0) buffer vdsm_deepest
{
    uint deepest[];
};
uniform sampler2D u_source; // the accumulation
uniform int u_size;         // texels a side of level 0
out vec4 frag_color;

const float BIG = 1e30;

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    int i = px.y * u_size + px.x;
    vec4 a = texelFetch(u_source, px, 0);
    uint d = deepest[i];
    deepest[i] = 0u;
    bool known = a.x > -0.5 * BIG;
    float y = d == 0u ? -BIG
                      : uintBitsToFloat((d & 0x80000000u) != 0u ? d & 0x7fffffffu : ~d);
    frag_color = vec4(known ? -a.x : BIG, y, 0.0, 0.0);
}
