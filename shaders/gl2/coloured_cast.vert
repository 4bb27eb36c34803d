#version 120
// SPDX-License-Identifier: MIT
// Coloured shadow maps (technique "coloured", src/translucent/coloured.c):
// a transparent caster's vertices in the light's clip space, its uv for the
// albedo texture. Both passes of a face draw through it, so the depth pass
// and the colour pass cover the same texels.
invariant gl_Position;
uniform mat4 u_model;
uniform mat4 u_view_proj;
attribute vec4 a_position;
attribute vec3 a_normal; // displacement
attribute vec2 a_uv;
varying vec2 v_uv;

// the displacement chunk (displace.glsl or displace_none.glsl)
// @chunks

void main()
{
    vec4 world = displace_world(u_model * a_position, a_normal, a_uv);
    v_uv = a_uv;
    gl_Position = u_view_proj * world;
}
