#version 150
// SPDX-License-Identifier: MIT
// Shadow-volume vertices: homogeneous object space, w = 0 at infinity. The
// transform is written exactly as in lit.vert so coincident caps get equal depths.
// Invariant: the depth of a volume cap must equal, bit for bit, the depth the
// lit passes wrote for the surface it lies on (z-fail counts it behind).
invariant gl_Position;
uniform mat4 u_model;
uniform mat4 u_view_proj;
in vec4 a_position;

void main()
{
    vec4 world = u_model * a_position;
    gl_Position = u_view_proj * world;
}
