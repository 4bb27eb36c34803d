#version 110
// SPDX-License-Identifier: MIT
// World-space shading normal as 0.5 + 0.5 n (the N output).
varying vec3 v_world;
varying vec3 v_normal;
varying vec2 v_uv;

void main()
{
    gl_FragColor = vec4(0.5 + 0.5 * normalize(v_normal), 1.0);
}
