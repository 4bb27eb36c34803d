#version 150
// SPDX-License-Identifier: MIT
// The GPU CSG resolve's stencil-tested quads (src/csg/merge.c): a
// candidate's losing pixels pushed to the far plane, and (depth writes
// off) the threshold counts of a stencil.
void main()
{
    gl_FragDepth = 1.0;
}
