#version 150
// SPDX-License-Identifier: MIT
// Deep shadow maps, one peel pass from the light: the transparent casters'
// vertices in the light's clip space, and their uv for the albedo texture.
// Invariant: every pass of a face must rasterise a surface to the same depth,
// bit for bit, or a layer would be peeled twice or lost.
invariant gl_Position;
uniform mat4 u_model;
uniform mat4 u_view_proj;
out vec2 v_uv;

// the attributes (vertex_attributes.glsl) and the displacement chunk (gl2's
// displace.glsl or displace_none.glsl)
#define texture2DLod textureLod
// @chunks

void main()
{
    vec4 world = displace_world(u_model * a_position, a_normal, a_uv);
    v_uv = a_uv;
    gl_Position = u_view_proj * world;
}
