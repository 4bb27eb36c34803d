#version 150
// SPDX-License-Identifier: MIT
// The GPU CSG resolve's last step (src/csg_merge.c): a product's face
// fragment is kept only where it lies on the resolved surface (within a
// band of the result), so the frame's depth gets the face's own depth.
uniform sampler2D u_result; // the result's depth (texel = window pixel)
uniform vec4 u_params;      // x: the band; zw: unused here

void main()
{
    if (abs(gl_FragCoord.z - texelFetch(u_result, ivec2(gl_FragCoord.xy), 0).r) > u_params.x)
        discard;
}
