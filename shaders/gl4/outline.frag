#version 150
// SPDX-License-Identifier: MIT
// The deferred outline (src/post/outline.c): the outline colour where the
// filter (gl2's outline.glsl) finds an edge, blended over the frame by its
// alpha.
#define texture2D texture
uniform vec4 u_color;
out vec4 frag_color;

// @chunks

void main()
{
    if (!outline_edge())
        discard;
    frag_color = u_color;
}
