// SPDX-License-Identifier: MIT
// Per-light visibility from the screen mask (technique "volume" on GLSL
// tiers with FBOs, src/render/screen_mask.c): channel i of u_shadow_map holds light
// i of this pass, 1 lit. u_shadow_kind 0: no mask in this pass (the stencil
// test, if any, already decided).
uniform int u_shadow_kind;
uniform vec4 u_shadow_params; // xy: 1 / the mask's size in texels
uniform sampler2D u_shadow_map;

vec3 shadow_transmittance(int light)
{
    if (u_shadow_kind == 0)
        return vec3(1.0);
    vec4 m = texture2D(u_shadow_map, gl_FragCoord.xy * u_shadow_params.xy);
    float v = light == 0 ? m.r : light == 1 ? m.g : light == 2 ? m.b : m.a;
    return vec3(v);
}
