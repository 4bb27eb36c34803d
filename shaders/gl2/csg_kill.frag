#version 110
// SPDX-License-Identifier: MIT
// The GPU CSG resolve's stencil-tested quads (src/csg/merge.c): a
// candidate's losing pixels pushed to the far plane, and (depth writes
// off) the threshold counts of a stencil. Without depth textures (bare
// OpenGL ES 2.0: no fragment depth either) the quad itself lies on the far
// plane (csg_far.vert) and colour writes are off.
void main()
{
#ifdef STIN_NO_DEPTH_TEXTURE
    gl_FragColor = vec4(1.0);
#else
    gl_FragDepth = 1.0;
#endif
}
