#version 110
// SPDX-License-Identifier: MIT
// The GPU CSG resolve's merge (src/csg/merge.c): the work buffer's depth
// under the fragment (texel = window pixel) written as the fragment's
// depth, where a candidate is (not 0, not the far plane); the depth test
// keeps the nearer. (interval, which selects by its walk, is GL4's.)
uniform sampler2D u_depth; // the work buffer's depth
uniform vec4 u_params;     // zw: 1 / texture size

void main()
{
    float d = texture2D(u_depth, gl_FragCoord.xy * u_params.zw).r;
    if (d <= 0.0 || d >= 1.0)
        discard;
    gl_FragDepth = d;
}
