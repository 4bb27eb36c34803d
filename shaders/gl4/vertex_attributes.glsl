// SPDX-License-Identifier: MIT
// The mesh attributes of the vertex shaders that draw meshes (spliced in by
// gl/shader.c; tess_eval.glsl declares them instead when the shader is a
// tessellation evaluation stage). Unused ones are inactive.
in vec4 a_position;
in vec3 a_normal;
in vec2 a_uv;
in vec4 a_tangent;
