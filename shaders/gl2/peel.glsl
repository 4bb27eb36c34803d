// SPDX-License-Identifier: MIT
// depth-peel (src/transparency/peel.c), spliced in after the other chunks of
// the lit programs: while a camera layer is peeled (u_peel_params.w = 1) a
// fragment survives only behind the layer before it (after the first) and in
// front of the opaque depth, so the depth test keeps the nearest surface
// left: the layer. It runs first thing in main, through surface_normal.
uniform sampler2D u_peel_previous; // layer k - 1's depth
uniform sampler2D u_peel_opaque;   // the opaque draws' depth
uniform vec4 u_peel_params;        // 1 / texture size (x, y), after the first layer, peeling

void peel_clip()
{
    if (u_peel_params.w == 0.0)
        return;
    vec2 at = gl_FragCoord.xy * u_peel_params.xy;
    // A 24-bit depth buffer stores z rounded: the layer before is passed by
    // more than that rounding, or the same surface would come back.
    if (gl_FragCoord.z >= texture2D(u_peel_opaque, at).r)
        discard;
    if (u_peel_params.z != 0.0 && gl_FragCoord.z <= texture2D(u_peel_previous, at).r + 1.0 / 8388608.0)
        discard;
}

vec3 peel_surface_normal(inout vec2 uv, vec3 v)
{
    peel_clip();
    return surface_normal(uv, v);
}
#define surface_normal peel_surface_normal
