#version 150
// SPDX-License-Identifier: MIT
// VDSM shadow polygons, vertex stage: world positions for the geometry shader.
uniform mat4 u_model;
in vec4 a_position;
out vec3 g_world;

void main()
{
    g_world = (u_model * a_position).xyz;
}
