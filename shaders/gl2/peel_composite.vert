#version 110
// SPDX-License-Identifier: MIT
// depth-peel's composite: a full-viewport quad in clip space.
attribute vec4 a_position;

void main()
{
    gl_Position = a_position;
}
