#version 150
// SPDX-License-Identifier: MIT
// VDSM shadow polygons of the triangles the culling pass kept
// (vdsm_cull.geom): one point each, carrying its corners, DC's clip depth
// and whether it draws its own face; its volume's faces as in the one-pass
// program (vdsm_volume.glsl).
layout(points) in;
layout(triangle_strip, max_vertices = 48) out;
in vec4 g_v0[];
in vec4 g_v1[];
in vec4 g_v2[];

// the light (vdsm_side.glsl) and the volume
// @chunks

void main()
{
    vec3 v[3] = vec3[3](g_v0[0].xyz, g_v1[0].xyz, g_v2[0].xyz);
    vdsm_volume(v, g_v0[0].w, g_v1[0].w != 0.0);
}
