#version 150
// SPDX-License-Identifier: MIT
// A full-viewport quad in clip space (the VDSM facing pass).
in vec4 a_position;

void main()
{
    gl_Position = a_position;
}
