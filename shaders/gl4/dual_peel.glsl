// SPDX-License-Identifier: MIT
// dual-peel (src/transparency/dual_peel.c), spliced in after the other
// chunks of the lit programs: while a layer is drawn (u_peel_params.w = 1) a
// fragment survives only at the depth this pass recorded for the layer,
// compared float for float with the gl_FragCoord.z the min-max pass stored
// (the same vertex stage: the same value): the nearest surface left (front
// layer, z = 1), or the farthest where it is not the nearest too (back
// layer, z = 2: a surface left alone is the front layer's, drawn once).
// It runs first thing in main, through surface_normal.
uniform sampler2D u_peel_previous; // this pass's (-near, far)
uniform vec4 u_peel_params;        // 1 / texture size (x, y), front 1 / back 2, drawing a layer

void peel_clip()
{
    if (u_peel_params.w == 0.0)
        return;
    vec2 nf = texture(u_peel_previous, gl_FragCoord.xy * u_peel_params.xy).rg;
    float near = -nf.x;
    if (u_peel_params.z < 1.5 ? gl_FragCoord.z != near : gl_FragCoord.z != nf.y || nf.y == near)
        discard;
}

vec3 peel_surface_normal(inout vec2 uv, vec3 v)
{
    peel_clip();
    return surface_normal(uv, v);
}
#define surface_normal peel_surface_normal
