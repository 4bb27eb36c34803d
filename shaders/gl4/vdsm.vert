#version 150
// SPDX-License-Identifier: MIT
// VDSM shadow polygons and light pass, vertex stage: world positions for the
// geometry shader (one program text, so both passes see the same points).
uniform mat4 u_model;
in vec4 a_position;
out vec3 g_world;

void main()
{
    g_world = (u_model * a_position).xyz;
}
