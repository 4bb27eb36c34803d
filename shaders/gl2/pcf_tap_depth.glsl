// SPDX-License-Identifier: MIT
// map-pcf's tap where depth textures cannot compare (no ARB_shadow: OpenGL
// ES 2.0 with OES_depth_texture), or where there are none
// (STIN_NO_DEPTH_TEXTURE: bare ES 2.0, the depth packed into an RGBA8 map by
// pack_depth.glsl): the map is read as a number (NEAREST, no compare mode)
// and the shader does what the hardware's LINEAR compare does: the four texels around `at`, each lit where z <= its depth (LEQUAL,
// z clamped to [0,1] as a fixed-point depth texture clamps its reference),
// weighted bilinearly. The same kernel and biases as with the compare.
uniform sampler2D u_shadow_map;

float pcf_depth(vec2 at)
{
#ifdef STIN_NO_DEPTH_TEXTURE
    // the bytes back (rounded: a texel holds exact 255ths) as 24 bits
    vec3 b = floor(texture2D(u_shadow_map, at).rgb * 255.0 + 0.5);
    return dot(b, vec3(65536.0, 256.0, 1.0)) / 16777215.0;
#else
    return texture2D(u_shadow_map, at).r;
#endif
}

float pcf_tap(vec2 at, float z, vec2 texel)
{
    vec2 f = at / texel - 0.5;
    vec2 i = floor(f);
    vec2 w = f - i;
    vec2 c = (i + 0.5) * texel; // the lower left texel's centre
    float r = clamp(z, 0.0, 1.0);
    float a = step(r, pcf_depth(c));
    float b = step(r, pcf_depth(c + vec2(texel.x, 0.0)));
    float d = step(r, pcf_depth(c + vec2(0.0, texel.y)));
    float e = step(r, pcf_depth(c + texel));
    return mix(mix(a, b, w.x), mix(d, e, w.x), w.y);
}
