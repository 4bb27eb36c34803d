// SPDX-License-Identifier: MIT
// Per-light visibility from the screen mask (technique "volume" on GLSL
// tiers with FBOs, src/render/screen_mask.c): channel i of u_shadow_map holds light
// i of this pass, 1 lit. u_shadow_kind 0: no mask in this pass (the stencil
// test, if any, already decided).
uniform int u_shadow_kind;
// xy: 1 / the mask's size in texels; z: 1 where the target is multisampled
// (the lookup below); w: how far, in window depth, the mask's depth may lie
// from this fragment's and still be its surface
uniform vec4 u_shadow_params;
uniform sampler2D u_shadow_map;
uniform sampler2D u_shadow_depth; // the depth the mask was drawn against

// The mask texel of this fragment's own surface. The mask holds one surface
// a pixel, the one at its centre; into a multisampled target a fragment can
// come from another surface that covers only some of the pixel's samples
// (a silhouette), and the centre's visibility would be the wrong one (a
// halo). Then the neighbour whose depth is nearest this fragment's stands
// in: the same surface one pixel on, never the one behind or in front.
vec2 shadow_mask_texel()
{
    vec2 at = gl_FragCoord.xy;
    float z = gl_FragCoord.z;
    if (u_shadow_params.z == 0.0 ||
        abs(texture2D(u_shadow_depth, at * u_shadow_params.xy).r - z) <= u_shadow_params.w)
        return at * u_shadow_params.xy;
    vec2 pick = at;
    float best = 2.0;
    for (int j = -1; j <= 1; j++)
        for (int i = -1; i <= 1; i++) {
            vec2 p = at + vec2(float(i), float(j));
            float d = abs(texture2D(u_shadow_depth, p * u_shadow_params.xy).r - z);
            if (d < best) {
                best = d;
                pick = p;
            }
        }
    return pick * u_shadow_params.xy;
}

vec3 shadow_transmittance(int light)
{
    if (u_shadow_kind == 0)
        return vec3(1.0);
    vec4 m = texture2D(u_shadow_map, shadow_mask_texel());
    float v = light == 0 ? m.r : light == 1 ? m.g : light == 2 ? m.b : m.a;
    return vec3(v);
}
