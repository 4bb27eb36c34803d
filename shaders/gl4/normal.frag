#version 150
// SPDX-License-Identifier: MIT
// World-space shading normal as 0.5 + 0.5 n (the N output).
out vec4 frag_color;
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;

void main()
{
    frag_color = vec4(0.5 + 0.5 * normalize(v_normal), 1.0);
}
