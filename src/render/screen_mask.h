/* SPDX-License-Identifier: MIT */
/* Screen visibility masks (render/screen_mask.c): an RGBA8 texture the size
 * of the frame's viewport, one light per channel, with its own depth-stencil
 * texture holding the frame's depth; the lit pass reads four lights' masks
 * at once through shadow_mask.glsl. Its state is render's own: the stages
 * that draw into the mask or read it (shadow techniques, post) go through
 * the functions below. */
#ifndef STIN_SCREEN_MASK_H
#define STIN_SCREEN_MASK_H

#include <stddef.h>

#include "stin/stin.h"
#include "gl/gl_types.h"
#include "render/path.h"

#define STIN__MASK_CHANNELS 4

/* Bytes of the mask's private state (a slot of frame/modules.c). */
size_t stin__mask_state_bytes(const stin_desc *d);
/* At stin_create, before the shadow module's set-up: decides whether masks
 * can be drawn (the visibility export, any path) and read by the lit passes
 * (GLSL lighting and a texture unit: the frame's lights). */
void stin__mask_init(stin_context *ctx);
void stin__mask_release(stin_context *ctx);
/* The context can draw masks: framebuffer objects and packed depth-stencil
 * textures (the visibility export's needs too). */
int stin__mask_drawable(const stin_context *ctx);
/* Masks can be drawn now: the context can and the mask's framebuffer did
 * not turn out incomplete (from stin__mask_init on). */
int stin__mask_available(const stin_context *ctx);
/* And the lit passes read them: the frame's lights go through the mask. */
int stin__mask_usable(const stin_context *ctx);
/* The mask's framebuffer, colour and depth-stencil textures and their
 * allocated size (texels covering the viewport at its window coordinates),
 * for the stages that draw into it or read it; all 0 until the first
 * stin__mask_begin made them. */
typedef struct stin__mask_target {
    GLuint fbo, color, depth_stencil;
    int width, height;
} stin__mask_target;
stin__mask_target stin__mask_target_of(const stin_context *ctx);
/* Binds the mask as the target, clearing its colour. With `depth`, the
 * first time in a frame also its depth and stencil, and the frame's depth
 * (draws `which`) is drawn into it; without, the passes bring their own. 0:
 * the mask cannot be made (logged once), draw the lights the old way. The
 * viewport stays the frame's (the mask has the same window coordinates). */
int stin__mask_begin(stin_context *ctx, const stin__path *path, int which, int depth);
/* After a technique left the stencil passing where light is visible:
 * `share` into `channel` there, replacing it at 1, added below 1 (the
 * samples of an area light, whose shares sum to 1 in whole 255ths). */
void stin__mask_write(stin_context *ctx, const stin__path *path, int channel, float share);
/* A technique whose mask_depth is 0 names the depth its visibility was
 * decided against (vdsm: its position buffer's), after stin__mask_begin;
 * the lit pass into a multisampled target reads it (screen_mask.c). */
void stin__mask_depth_from(stin_context *ctx, GLuint depth);
/* Back to the frame's target, the mask bound for the lit pass. */
void stin__mask_end(stin_context *ctx);
/* The lit pass that read the mask is done. */
void stin__mask_read_done(stin_context *ctx);
/* The frame is over: the next one draws its depth again. */
void stin__mask_frame_end(stin_context *ctx);
/* The shadow_mask.glsl uniforms of program p. */
void stin__mask_uniforms(stin_context *ctx, const stin__program *p);

#endif
