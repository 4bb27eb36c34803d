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

/* Bytes of the outline's private state (post/outline.c). */
size_t stin__outline_state_bytes(const stin_desc *d);
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
