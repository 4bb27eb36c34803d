#version 150
// SPDX-License-Identifier: MIT
// The CSG resolve's depth into the depth buffer on core profiles (no
// glDrawPixels): each pixel's depth as the CPU kept it, from an R32F texture
// whose texel (0, 0) is the viewport's corner.
uniform sampler2D u_depth;
uniform vec4 u_origin; // xy: the viewport's corner in window pixels

void main()
{
    gl_FragDepth = texelFetch(u_depth, ivec2(gl_FragCoord.xy - u_origin.xy), 0).r;
}
