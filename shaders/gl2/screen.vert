#version 110
// SPDX-License-Identifier: MIT
// A full-viewport quad in clip space: depth-peel's composite and the GPU
// CSG resolve's merges.
attribute vec4 a_position;

void main()
{
    gl_Position = a_position;
}
