#version 150
// SPDX-License-Identifier: MIT
// The GPU CSG resolve's merge (src/csg/merge.c): the work buffer's depth
// under the fragment (texel = window pixel) written as the fragment's
// depth, where a candidate is (not 0, not the far plane); the depth test
// keeps the nearer.
uniform sampler2D u_depth;  // the work buffer's depth
uniform sampler2D u_select; // interval's walk: per pixel its chosen layer + 1, over 255
uniform vec4 u_params;      // x: the layer + 1 to keep (< 0: every pixel); zw: unused here

void main()
{
    ivec2 at = ivec2(gl_FragCoord.xy);
    float d = texelFetch(u_depth, at, 0).r;
    if (d <= 0.0 || d >= 1.0)
        discard;
    if (u_params.x >= 0.0 && abs(texelFetch(u_select, at, 0).r * 255.0 - u_params.x) > 0.5)
        discard;
    gl_FragDepth = d;
}
