#version 110
// SPDX-License-Identifier: MIT
// The GPU CSG resolve's stencil-tested quads on the far plane (z = w: window
// depth 1), where no fragment depth can be written (bare OpenGL ES 2.0's
// packed resolve, src/csg/merge.c).
attribute vec4 a_position;

void main()
{
    gl_Position = vec4(a_position.xy, a_position.w, a_position.w);
}
