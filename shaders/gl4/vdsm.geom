#version 150
// SPDX-License-Identifier: MIT
// VDSM shadow polygons in one pass (seed 000): each triangle culled by the
// chain's steps (vdsm_cull.glsl), then its volume's faces drawn
// (vdsm_volume.glsl). Frames whose triangles are tessellated, and contexts
// whose culling pass does not build, draw this way; the others cull first
// into a buffer (vdsm_cull.geom) and draw the survivors (vdsm_fed.geom).
layout(triangles) in;
layout(triangle_strip, max_vertices = 48) out;
in vec3 g_world[];
uniform int u_caps; // also draw the triangle itself where the eye sees its volume through it

// the light (vdsm_side.glsl), the chain's steps and the volume
// @chunks

void main()
{
    vec3 v[3] = vec3[3](g_world[0], g_world[1], g_world[2]);
    float clip;
    if (vdsm_casts(v, clip))
        vdsm_volume(v, clip, u_caps != 0);
}
