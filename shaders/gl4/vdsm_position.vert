#version 150
// SPDX-License-Identifier: MIT
// VDSM position buffer, vertex stage: the world position of each vertex, drawn
// exactly as lit.vert draws it so the buffer holds the frame's visible surface,
// and its world normal for the terminator rule (vdsm_position.geom).
invariant gl_Position;
uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform mat3 u_normal_matrix; // zero: the draw keeps its facets (displaced, CSG caps)
out vec3 vs_world;
out vec3 vs_normal;

// the attributes (vertex_attributes.glsl, or tess_eval.glsl for a
// tessellation evaluation stage) and the displacement chunk (gl2's
// displace.glsl or displace_none.glsl)
#define texture2DLod textureLod
// @chunks

void main()
{
    vec4 world = displace_world(u_model * a_position, a_normal, a_uv);
    vs_world = world.xyz;
    vs_normal = u_normal_matrix * a_normal;
    gl_Position = u_view_proj * world;
}
