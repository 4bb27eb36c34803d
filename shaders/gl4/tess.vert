#version 150
// SPDX-License-Identifier: MIT
// Displacement by tessellation ("displace-tess"), vertex stage: the mesh's
// attributes as they are. The control stage sizes each patch, the evaluation
// stage (the program's own vertex shader, see tess_eval.glsl) displaces.
in vec4 a_position;
in vec3 a_normal;
in vec2 a_uv;
in vec4 a_tangent;
out vec4 c_position;
out vec3 c_normal;
out vec2 c_uv;
out vec4 c_tangent;

void main()
{
    c_position = a_position;
    c_normal = a_normal;
    c_uv = a_uv;
    c_tangent = a_tangent;
}
