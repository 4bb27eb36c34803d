#version 110
// SPDX-License-Identifier: MIT
// The deferred outline (src/post/outline.c): the outline colour where the
// filter (outline.glsl) finds an edge, blended over the frame by its alpha.
uniform vec4 u_color;

// @chunks

void main()
{
    if (!outline_edge())
        discard;
    gl_FragColor = u_color;
}
