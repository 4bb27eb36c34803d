// SPDX-License-Identifier: MIT
// No shadow test in the shader (none, or the stencil already decided).
vec3 shadow_transmittance(int light)
{
    return vec3(1.0);
}
