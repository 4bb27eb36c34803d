// SPDX-License-Identifier: MIT
// stin's visibility map for the application's own fragment shaders
// (stin_visibility_glsl, stin.h): light i is channel i % 3 of tile i / 3,
// tiles two to a row, window pixel (x, y) at texel (x, y) of its tile; where
// the frame had deep or colour maps, light i's transmittance (RGB) is tile
// stin_visibility_transmittance + i.
#if __VERSION__ >= 130
#define STIN_VISIBILITY_FETCH(s, uv) texture(s, uv)
#else
#define STIN_VISIBILITY_FETCH(s, uv) texture2D(s, uv)
#endif
// On ES the texel address is highp where the fragment stage has it,
// whatever default the program declared: mediump's 11 bits are off by a
// texel at 2,048. Samplers default to lowp there. Desktop GLSL before 1.30
// has no precision qualifiers.
#if defined(GL_ES) && defined(GL_FRAGMENT_PRECISION_HIGH)
#define STIN_VISIBILITY_P highp
#elif defined(GL_ES)
#define STIN_VISIBILITY_P mediump
#else
#define STIN_VISIBILITY_P
#endif
uniform STIN_VISIBILITY_P sampler2D stin_visibility_map;
// tile width, tile height, 1 / map width, 1 / map height
uniform STIN_VISIBILITY_P vec4 stin_visibility_layout;
uniform STIN_VISIBILITY_P float stin_visibility_lights;
// the first transmittance tile (0: none)
uniform STIN_VISIBILITY_P float stin_visibility_transmittance;

vec4 stin_visibility_tile(STIN_VISIBILITY_P float tile)
{
    STIN_VISIBILITY_P vec2 origin =
        vec2(mod(tile, 2.0), floor(tile / 2.0)) * stin_visibility_layout.xy;
    return STIN_VISIBILITY_FETCH(stin_visibility_map,
                                 (origin + gl_FragCoord.xy) * stin_visibility_layout.zw);
}

float stin_visibility(int light)
{
    float l = float(light);
    if (l < 0.0 || l >= stin_visibility_lights)
        return 1.0;
    float tile = floor(l / 3.0);
    float channel = l - 3.0 * tile;
    vec4 v = stin_visibility_tile(tile);
    return channel < 0.5 ? v.r : channel < 1.5 ? v.g : v.b;
}

vec3 stin_shadow_transmittance(int light)
{
    float l = float(light);
    vec3 t = vec3(1.0);
    if (stin_visibility_transmittance > 0.5 && l >= 0.0 && l < stin_visibility_lights)
        t = stin_visibility_tile(stin_visibility_transmittance + l).rgb;
    return stin_visibility(light) * t;
}
