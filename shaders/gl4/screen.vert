#version 150
// SPDX-License-Identifier: MIT
// A full-viewport quad in clip space: the screen passes of vdsm (facing,
// pyramid), the CSG resolve (depth write-back, merges, interval's walk) and
// the peel composites.
in vec4 a_position;

void main()
{
    gl_Position = a_position;
}
