#version 150
// SPDX-License-Identifier: MIT
// The frame's surfaces again under a light's shadow volumes, for the casters
// volumes cannot cast (shadow/cast_map.c): written exactly as lit.vert so the
// pass meets the lit passes' depth EQUAL.
invariant gl_Position;
uniform mat4 u_model;
uniform mat4 u_view_proj;
out vec3 v_world;

// the attributes (vertex_attributes.glsl, or tess_eval.glsl for a
// tessellation evaluation stage) and the displacement chunk
#define texture2DLod textureLod
// @chunks

void main()
{
    vec4 world = displace_world(u_model * a_position, a_normal, a_uv);
    v_world = world.xyz;
    gl_Position = u_view_proj * world;
}
