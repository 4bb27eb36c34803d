#version 120
// SPDX-License-Identifier: MIT
// The GPU CSG resolve's last step (src/csg_merge.c): a product's face
// fragment is kept only where it lies on the resolved surface (within a
// band of the result), so the frame's depth gets the face's own depth.
uniform sampler2D u_result; // the result's depth (texel = window pixel)
uniform vec4 u_params;      // x: the band; zw: 1 / texture size

void main()
{
    float r = texture2D(u_result, gl_FragCoord.xy * u_params.zw).r;
    if (abs(gl_FragCoord.z - r) > u_params.x)
        discard;
}
