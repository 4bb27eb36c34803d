#version 150
// SPDX-License-Identifier: MIT
// VDSM position buffer, vertex stage: the world position of each vertex, drawn
// exactly as lit.vert draws it so the buffer holds the frame's visible surface.
invariant gl_Position;
uniform mat4 u_model;
uniform mat4 u_view_proj;
in vec4 a_position;
out vec3 v_world;

void main()
{
    vec4 world = u_model * a_position;
    v_world = world.xyz;
    gl_Position = u_view_proj * world;
}
