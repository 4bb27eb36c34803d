// SPDX-License-Identifier: MIT
// A window depth in [0,1] as 24 bits across R, G and B of an RGBA8 target
// (high byte first, A one): map-pcf's maps where no depth texture exists
// (bare OpenGL ES 2.0), and the GPU CSG resolve's result there;
// pcf_tap_depth.glsl and unpack_depth read them back. 2^24 - 1 steps are
// exact in a highp float (24-bit significand).
vec4 pack_depth(float z)
{
    float v = floor(clamp(z, 0.0, 1.0) * 16777215.0 + 0.5);
    float r = floor(v / 65536.0);
    v -= r * 65536.0;
    float g = floor(v / 256.0);
    return vec4(r, g, v - g * 256.0, 255.0) / 255.0;
}

// the bytes back (rounded: a texel holds exact 255ths) as 24 bits
float unpack_depth(vec4 c)
{
    vec3 b = floor(c.rgb * 255.0 + 0.5);
    return dot(b, vec3(65536.0, 256.0, 1.0)) / 16777215.0;
}
