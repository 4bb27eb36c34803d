#version 150
// SPDX-License-Identifier: MIT
// Per-pixel Blinn-Phong with GL's fixed-function equation (local viewer,
// attenuation, spot cone), for one batch of up to 8 lights.
// Light i is four vec4s: position (w 0 = directional), direction + cos(cutoff)
// (cos = -2 for no cone), colour * intensity + spot exponent, attenuation.
// The general program takes the batch and material from uniforms; programs
// specialised to one (src/render/lit_specialise.c) define STIN_SPECIALISED and
// keep only the parts of the equation that batch and material use.
#ifndef STIN_SPECIALISED
#define STIN_LIGHT_COUNT 8 // bounded by u_light_count
#define STIN_DIRECTIONAL 1
#define STIN_POSITIONAL 1
#define STIN_SPOT 1
#define STIN_ATTENUATION 1
#define STIN_ALBEDO_TEX 1
#endif
out vec4 frag_color;
uniform vec3 u_eye;
uniform vec3 u_ambient;
uniform vec4 u_albedo;
uniform vec3 u_specular;
uniform float u_shininess;
uniform int u_light_count;
uniform vec4 u_lights[32];
uniform sampler2D u_albedo_tex;
uniform int u_has_albedo_tex;
in vec3 v_world;
in vec3 v_normal;
in vec3 v_plane_dn; // the terminator rule's tangent planes (lit.vert)
in vec3 v_plane_nn;
in vec3 v_plane_nx;
in vec2 v_uv;
in vec4 v_tangent; // world tangent, w = handedness

// Length of the filtered normal-map normal (Toksvig); surface_normal sets it.
float s_normal_length = 1.0;

// The chunks are shared with shaders/gl2 and use GLSL 1.10's names: map them.
#define texture2D texture
#define shadow2D(s, c) vec4(texture(s, c))
// The unmoved footprint: no mip jumps where pom steps; level 0 of the height
// field, defined inside loops too.
#ifdef STIN_NO_DERIVATIVES // masked: no footprint known, the moved uv's own
#define SAMPLE_FOOTPRINT(t, uv, dx, dy) texture(t, uv)
#else
#define SAMPLE_FOOTPRINT(t, uv, dx, dy) textureGrad(t, uv, dx, dy)
#endif
#define SAMPLE_LEVEL0(t, uv) textureLod(t, uv, 0.0)

// @chunks
// The chunks spliced in here define (see src/render/path_glsl.c and src/surface/glsl.c):
//   vec3 surface_normal(inout vec2 uv, vec3 v)  the unit shading normal; may move uv (parallax)
//   float surface_shadow(vec2 uv, vec3 l)       the height field's shadow toward l (1 lit)
//   vec4 surface_sample(sampler2D t, vec2 uv)   a colour map at the (moved) uv
//   vec3 shadow_transmittance(int light)        what reaches the point of light's colour (1 lit)

// pow(0, 0) is undefined in GLSL; GL's lighting takes it as 1.
float safe_pow(float x, float e)
{
    return e == 0.0 ? 1.0 : pow(max(x, 0.0), e);
}

void main()
{
    vec3 v = normalize(u_eye - v_world);
    vec2 uv = v_uv;
    vec3 n = surface_normal(uv, v);
    // Toksvig: a shorter mean normal (a filtered normal map) widens the lobe;
    // exactly u_shininess when the length is 1
    float shininess = u_shininess * s_normal_length /
                      (s_normal_length + u_shininess * (1.0 - s_normal_length));
    vec3 diffuse = vec3(0.0);
    vec3 specular = vec3(0.0);
    for (int i = 0; i < STIN_LIGHT_COUNT; i++) {
#ifndef STIN_SPECIALISED
        if (i >= u_light_count)
            break;
#endif
        vec4 pos = u_lights[4 * i];
        vec4 col = u_lights[4 * i + 2];
#if STIN_DIRECTIONAL && STIN_POSITIONAL
        vec3 l = pos.w == 0.0 ? pos.xyz : pos.xyz - v_world;
#elif STIN_POSITIONAL
        vec3 l = pos.xyz - v_world;
#else
        vec3 l = pos.xyz;
#endif
        float d = length(l);
        l /= d;
        float k = 1.0;
#if STIN_ATTENUATION
        vec3 att = u_lights[4 * i + 3].xyz;
#if STIN_DIRECTIONAL
        k = pos.w == 0.0 ? 1.0 : 1.0 / (att.x + att.y * d + att.z * d * d);
#else
        k = 1.0 / (att.x + att.y * d + att.z * d * d);
#endif
#endif
#if STIN_SPOT
        vec4 dir = u_lights[4 * i + 1];
        if (dir.w > -1.5) {
            float s = dot(-l, dir.xyz);
            k *= s < dir.w ? 0.0 : safe_pow(s, col.w);
        }
#endif
        float ndotl = dot(n, l);
        if (ndotl > 0.0) {
            // per channel: a coloured transmittance tints the light it lets through
            vec3 c = shadow_transmittance(i) * (k * surface_shadow(uv, l)) * col.rgb;
            vec3 h = normalize(l + v);
            diffuse += ndotl * c;
            specular += safe_pow(dot(n, h), shininess) * c;
        }
    }
#if !STIN_ALBEDO_TEX
    vec4 tex = vec4(1.0);
#elif defined(STIN_SPECIALISED)
    vec4 tex = surface_sample(u_albedo_tex, uv);
#else
    vec4 tex = u_has_albedo_tex != 0 ? surface_sample(u_albedo_tex, uv) : vec4(1.0);
#endif
    vec3 color = (u_ambient + diffuse) * u_albedo.rgb * tex.rgb + specular * u_specular;
    frag_color = vec4(clamp(color, 0.0, 1.0), u_albedo.a * tex.a);
}
