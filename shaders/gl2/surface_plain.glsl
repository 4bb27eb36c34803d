// SPDX-License-Identifier: MIT
// Surface "plain": the interpolated vertex normal, no height field.
vec3 surface_normal(inout vec2 uv, vec3 v)
{
    return normalize(v_normal);
}

float surface_shadow(vec2 uv, vec3 l)
{
    return 1.0;
}

vec4 surface_sample(sampler2D t, vec2 uv)
{
    return texture2D(t, uv);
}
