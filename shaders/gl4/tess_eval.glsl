// SPDX-License-Identifier: MIT
// Displacement by tessellation, evaluation stage: spliced into a vertex
// shader that draws meshes when gl/shader.c builds it as the program's
// evaluation stage. The attributes become globals holding the point's
// barycentric blend of the patch's corners, and the vertex shader's own main
// runs on them (renamed below), so every pass keeps its one vertex program
// text and displaces the tessellated points exactly as VTF displaces
// vertices. The blend is `precise` where GLSL has it: two patches sharing an
// edge must compute its points bit for bit alike (no fused multiply-add on
// one side only), or cracks open.
layout(triangles, equal_spacing, ccw) in;
in vec4 e_position[];
in vec3 e_normal[];
in vec2 e_uv[];
in vec4 e_tangent[];
vec4 a_position;
vec3 a_normal;
vec2 a_uv;
vec4 a_tangent;

void stin_vertex_main();

void main()
{
    vec3 b = gl_TessCoord;
    STIN_PRECISE vec4 position = b.x * e_position[0] + b.y * e_position[1] + b.z * e_position[2];
    STIN_PRECISE vec3 normal = b.x * e_normal[0] + b.y * e_normal[1] + b.z * e_normal[2];
    STIN_PRECISE vec2 uv = b.x * e_uv[0] + b.y * e_uv[1] + b.z * e_uv[2];
    a_position = position;
    a_normal = normal;
    a_uv = uv;
    a_tangent = b.x * e_tangent[0] + b.y * e_tangent[1] + b.z * e_tangent[2];
    stin_vertex_main();
}

#define main stin_vertex_main
