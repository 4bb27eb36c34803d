#version 150
// SPDX-License-Identifier: MIT
// The GPU CSG resolve's snap (src/csg/merge.c): a product's face
// fragment is kept only where it lies on the resolved surface (within a
// band of the result, or in a direct resolve of the candidate taken), so
// the frame's depth gets the face's own depth.
uniform sampler2D u_result; // that depth (texel = window pixel)
uniform vec4 u_params;      // x: the band; y: its growth by 1 / w (near-cut faces); zw: unused here

void main()
{
    float r = texelFetch(u_result, ivec2(gl_FragCoord.xy), 0).r;
    // 0 (scs's term where no plain primitive drew) and the far plane (a
    // candidate's lost pixels) hold no surface
    if (r <= 0.0 || r >= 1.0 || abs(gl_FragCoord.z - r) > u_params.x + u_params.y * gl_FragCoord.w)
        discard;
}
