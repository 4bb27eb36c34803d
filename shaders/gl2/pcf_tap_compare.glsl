// SPDX-License-Identifier: MIT
// map-pcf's tap where the map compares (ARB_shadow): the hardware's 2x2
// percentage-closer compare of depth z at `at` (LEQUAL, LINEAR filtering).
uniform sampler2DShadow u_shadow_map;

float pcf_tap(vec2 at, float z, vec2 texel)
{
    return shadow2D(u_shadow_map, vec3(at, z)).r;
}
