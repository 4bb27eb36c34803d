#version 150
// SPDX-License-Identifier: MIT
// VDSM shadow polygons and light pass, vertex stage: world positions for the
// geometry shader (one program text, so both passes see the same points).
uniform mat4 u_model;
in vec4 a_position;
in vec3 a_normal; // displacement
in vec2 a_uv;
out vec3 g_world;

// the displacement chunk (gl2's displace.glsl or displace_none.glsl)
#define texture2DLod textureLod
// @chunks

void main()
{
    g_world = displace_world(u_model * a_position, a_normal, a_uv).xyz;
}
