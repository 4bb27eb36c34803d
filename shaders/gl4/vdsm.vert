#version 150
// SPDX-License-Identifier: MIT
// VDSM shadow polygons and light pass, vertex stage: world positions for the
// geometry shader (one program text, so both passes see the same points).
uniform mat4 u_model;
out vec3 g_world;

// the attributes (vertex_attributes.glsl, or tess_eval.glsl for a
// tessellation evaluation stage) and the displacement chunk (gl2's
// displace.glsl or displace_none.glsl)
#define texture2DLod textureLod
// @chunks

void main()
{
    g_world = displace_world(u_model * a_position, a_normal, a_uv).xyz;
}
