#version 150
// SPDX-License-Identifier: MIT
// VDSM, per covered pixel: the exact segment-triangle test
// (vdsm_segment.glsl) from the pixel's visible surface point to the light
// against the triangle whose shadow polygon covers it. A hit writes 0 into
// the light's mask channel (the colour mask keeps the others); anything
// else is discarded, so the polygons' order does not matter.
flat in vec3 f_v0;
flat in vec3 f_v1;
flat in vec3 f_v2;
out vec4 frag_color;

// @chunks

void main()
{
    float t, det, unit;
    if (!vdsm_segment(f_v0, f_v1, f_v2, t, det, unit))
        discard;
    frag_color = vec4(0.0);
}
