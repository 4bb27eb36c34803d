#version 150
// SPDX-License-Identifier: MIT
// VDSM shadow polygons of the parts the culling pass kept (vdsm_cull.geom):
// one point each, carrying its triangle's corners, DC's clip depth and which
// part of the triangle's volume it is; that face drawn as the one-pass
// program draws it (vdsm_volume.glsl). One face per invocation keeps the
// stage's output at 12 vertices, and no invocation runs faces it skips.
layout(points) in;
layout(triangle_strip, max_vertices = 12) out;
in vec4 g_v0[];
in vec4 g_v1[];
in vec4 g_v2[];

// the light (vdsm_side.glsl) and the volume
// @chunks

void main()
{
    vec3 v[3] = vec3[3](g_v0[0].xyz, g_v1[0].xyz, g_v2[0].xyz);
    int part = int(g_v1[0].w);
    vec4 far[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
    if (part < PART_OWN)
        far_ends(v, g_v0[0].w, far);
    vdsm_part(v, far, part);
}
