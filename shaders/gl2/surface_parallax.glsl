// SPDX-License-Identifier: MIT
// Surface "parallax": parallax mapping with offset limiting (Kaneko 2001,
// Welsh 2004), after surface_frame.glsl: one height fetch at uv,
//   uv' = uv + V.xy * (h * scale - bias)   (V: unit, toward the eye, tangent frame)
// with no division by V.z, so the shift never exceeds |h * scale - bias|
// scene units; the normal map and the albedo are sampled at uv'.
vec3 surface_normal(inout vec2 uv, vec3 v)
{
    surface_frame();
    vec2 vt = vec2(dot(v, s_t), dot(v, s_b));
    float h = surface_height(uv) * u_surface.x - u_surface.y;
    uv += surface_uv_offset(vt * h);
    return surface_map_normal(uv);
}

float surface_shadow(vec2 uv, vec3 l)
{
    return 1.0;
}
