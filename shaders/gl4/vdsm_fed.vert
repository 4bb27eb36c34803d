#version 150
// SPDX-License-Identifier: MIT
// VDSM shadow polygons of the culling pass's triangles: each vertex is one
// kept triangle (vdsm_cull.geom's t_v0..2), passed to vdsm_fed.geom.
in vec4 a_v0;
in vec4 a_v1;
in vec4 a_v2;
out vec4 g_v0;
out vec4 g_v1;
out vec4 g_v2;

void main()
{
    g_v0 = a_v0;
    g_v1 = a_v1;
    g_v2 = a_v2;
}
