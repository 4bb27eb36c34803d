// SPDX-License-Identifier: MIT
// Surface "normal": tangent-space normal mapping (after surface_frame.glsl).
vec3 surface_normal(inout vec2 uv, vec3 v)
{
    surface_frame();
    return surface_map_normal(uv);
}

float surface_shadow(vec2 uv, vec3 l)
{
    return 1.0;
}
