// SPDX-License-Identifier: MIT
// Surface "pom": parallax occlusion mapping (after surface_frame.glsl). The
// height field is recessed: h = 1 lies in the polygon, h = 0 at u_surface.x
// scene units below it. The view ray enters at uv and is marched in depth
// (0..1 of the scale) with n linear steps, n growing from the min (looking
// straight on) to the max (grazing); the step that first lands under the
// field is refined by bisection and a final secant step. Depth written is
// the polygon's (no silhouettes, see stin.h).
const int POM_MAX = 64;

// The ray from the hit toward the light (tangent frame t): 1 where it
// leaves the field unblocked; soft: a penumbra estimate from how far the
// field rises above the ray, weighted toward the hit (Tatarchuk 2006).
float surface_shadow(vec2 uv, vec3 l)
{
    if (u_self_shadow == 0 || s_depth <= 0.0)
        return 1.0;
    vec3 lt = vec3(dot(l, s_t), dot(l, s_b), dot(l, s_n));
    if (lt.z <= 0.0)
        return 0.0; // toward a light under the polygon the ray never leaves the field
    float n = floor(mix(u_surface.w, u_surface.z, lt.z) + 0.5);
    // uv change per unit of depth climbed toward the light
    vec2 dir = surface_uv_offset(lt.xy / lt.z * u_surface.x);
    float worst = 0.0;
    for (int i = 1; i <= POM_MAX; i++) {
        if (float(i) >= n)
            break;
        float f = float(i) / n;
        float ray = s_depth * (1.0 - f);                  // depth of the ray here
        float field = 1.0 - surface_height(uv + dir * (s_depth - ray));
        float above = ray - field;                        // > 0: the field is above the ray
        if (u_self_shadow == 1) {
            if (above > 0.004)
                return 0.0;
        } else {
            worst = max(worst, above * (1.0 - f));
        }
    }
    return u_self_shadow == 1 ? 1.0 : 1.0 - clamp(worst * 16.0, 0.0, 1.0);
}

vec3 surface_normal(inout vec2 uv, vec3 v)
{
    surface_frame();
    vec3 vt = vec3(dot(v, s_t), dot(v, s_b), dot(v, s_n));
    float vz = max(vt.z, 1e-3);
    float n = clamp(floor(mix(u_surface.w, u_surface.z, vz) + 0.5), 1.0, float(POM_MAX));
    // uv change per unit of depth along the view ray (away from the eye)
    vec2 dir = surface_uv_offset(-vt.xy / vz * u_surface.x);
    float lo = 0.0, hi = 0.0;             // ray depths above / under the field
    float glo = 1.0 - surface_height(uv); // field depth - ray depth at lo (> 0: above)
    float ghi = 0.0;                      // ray depth - field depth at hi (>= 0)
    if (glo > 0.0) {
        for (int i = 1; i <= POM_MAX; i++) {
            float d = min(float(i) / n, 1.0);
            float g = 1.0 - surface_height(uv + dir * d) - d;
            if (g <= 0.0 || d >= 1.0) { // at depth 1 every ray is under the field
                hi = d;
                ghi = max(-g, 0.0);
                break;
            }
            lo = d;
            glo = g;
        }
        for (int k = 0; k < 5; k++) { // bisection of [lo, hi]
            float mid = 0.5 * (lo + hi);
            float g = 1.0 - surface_height(uv + dir * mid) - mid;
            if (g <= 0.0) {
                hi = mid;
                ghi = -g;
            } else {
                lo = mid;
                glo = g;
            }
        }
        // secant: the field taken as linear across the last interval
        s_depth = lo + (hi - lo) * glo / max(glo + ghi, 1e-6);
    }
    uv += dir * s_depth;
    return surface_map_normal(uv);
}
