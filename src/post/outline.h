/* SPDX-License-Identifier: MIT */
/* The deferred outline (post/outline.c; stin.h, OUTLINE): a frame stage after
 * the lights that draws the surfaces' normals and depth into the screen
 * mask and blends the outline colour over the frame where a filter over
 * them finds an edge. */
#ifndef STIN_OUTLINE_H
#define STIN_OUTLINE_H

#include "stin/stin.h"
#include "gl/gl_types.h"
#include "render/path.h"

typedef struct stin__outline_state {
    GLuint program;  /* 0: the context cannot outline */
    GLint u_normal, u_depth, u_inverse_projection, u_viewport, u_texel, u_params, u_color;
} stin__outline_state;

/* Whether frames may ask for an outline (GLSL lighting, framebuffer
 * objects, packed depth-stencil and the program built). */
int stin__outline_supported(const stin_context *ctx);
/* The program at stin_create (after the shadows' set-up: the mask's
 * capabilities), and its release. */
void stin__outline_init(stin_context *ctx);
void stin__outline_release(stin_context *ctx);
/* The stage: with the frame's target bound, and bound again after. */
void stin__outline_stage(stin_context *ctx, const stin__path *path);

#endif
