#version 150
// SPDX-License-Identifier: MIT
// VDSM for an area light, last: the share of the 64 segments that no
// triangle met (vdsm_soft.frag's bits, ORed), blended as a factor into the
// light's mask channel, where the facing pass left 1 or 0. With
// STIN_SOFT_IMAGE (OpenGL ES) the two words lie side by side in one R32UI
// texel row, as vdsm_soft.frag's image atomics ORed them.
uniform usampler2D u_bits;
out vec4 frag_color;

// The bits set in b, by halves (GLSL 1.50 has no bitCount).
uint bits_set(uint b)
{
    b = b - ((b >> 1u) & 0x55555555u);
    b = (b & 0x33333333u) + ((b >> 2u) & 0x33333333u);
    b = (b + (b >> 4u)) & 0x0f0f0f0fu;
    return (b * 0x01010101u) >> 24u;
}

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
#ifdef STIN_SOFT_IMAGE
    uvec2 b = uvec2(texelFetch(u_bits, ivec2(px.x * 2, px.y), 0).r,
                    texelFetch(u_bits, ivec2(px.x * 2 + 1, px.y), 0).r);
#else
    uvec2 b = texelFetch(u_bits, px, 0).rg;
#endif
    frag_color = vec4(float(64u - bits_set(b.x) - bits_set(b.y)) / 64.0);
}
