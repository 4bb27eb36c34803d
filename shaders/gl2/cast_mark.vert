#version 120
// SPDX-License-Identifier: MIT
// The frame's surfaces again under a light's shadow volumes, for the casters
// volumes cannot cast (shadow/cast_map.c): written exactly as lit.vert so the
// pass meets the lit passes' depth EQUAL.
invariant gl_Position;
uniform mat4 u_model;
uniform mat4 u_view_proj;
attribute vec4 a_position;
attribute vec3 a_normal; // displacement
attribute vec2 a_uv;
varying vec3 v_world;

// the displacement chunk (displace.glsl or displace_none.glsl)
// @chunks

void main()
{
    vec4 world = displace_world(u_model * a_position, a_normal, a_uv);
    v_world = world.xyz;
    gl_Position = u_view_proj * world;
}
