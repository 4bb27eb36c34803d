// SPDX-License-Identifier: MIT
// A window depth in [0,1] as 24 bits across R, G and B of an RGBA8 target
// (high byte first, A one): map-pcf's maps where no depth texture exists
// (bare OpenGL ES 2.0); pcf_tap_depth.glsl reads them back. 2^24 - 1 steps
// are exact in a highp float (24-bit significand).
vec4 pack_depth(float z)
{
    float v = floor(clamp(z, 0.0, 1.0) * 16777215.0 + 0.5);
    float r = floor(v / 65536.0);
    v -= r * 65536.0;
    float g = floor(v / 256.0);
    return vec4(r, g, v - g * 256.0, 255.0) / 255.0;
}
