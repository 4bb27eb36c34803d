#version 150
// SPDX-License-Identifier: MIT
#ifdef GL_ARB_shader_image_load_store
#extension GL_ARB_shader_image_load_store : enable
#endif
// VDSM, per covered pixel: the exact segment-triangle test
// (vdsm_segment.glsl) from the pixel's visible surface point to the light
// against the triangle whose shadow polygon covers it. A hit writes 0 into
// the light's mask channel (the colour mask keeps the others); anything
// else is discarded, so the polygons' order does not matter.
// The polygons' depth test (vdsm.geom, u_depth_test) writes no depth, so it
// may run before this stage whatever it discards: where GLSL can say so,
// it does, and a fragment behind the visible surface costs no test.
#ifdef GL_ARB_shader_image_load_store
layout(early_fragment_tests) in;
#endif
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
