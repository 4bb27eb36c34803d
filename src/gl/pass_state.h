/* SPDX-License-Identifier: MIT */
/* Render state of a pass as one struct, applied through a cache of what GL
 * holds (gl/pass_state.c), so passes say what they need instead of toggling GL
 * by hand, and the end of a frame is "apply the defaults". Texture units the
 * frame binds are recorded so the end can unbind exactly those. */
#ifndef STIN_PASS_STATE_H
#define STIN_PASS_STATE_H

#include "stin/stin.h"
#include "gl/gl_types.h"


typedef struct stin__stencil_face {
    GLenum func;
    GLint ref;
    GLuint mask;
    GLenum fail, zfail, zpass;
} stin__stencil_face;

typedef struct stin__pass_state {
    unsigned char depth_test, depth_write, color_write, blend, cull, polygon_offset, scissor,
        depth_clamp, stencil_test;
    unsigned char two_sided; /* front and back stencil differ (separate or EXT two-side) */
    GLenum depth_func, blend_src, blend_dst, cull_face, front_face;
    float offset_factor, offset_units;
    int scissor_box[4];
    GLuint stencil_write_mask;
    stin__stencil_face front, back; /* back is used only when two_sided */
    unsigned char color_only; /* with color_write: 0 every channel, 1-4 only R, G, B or A */
} stin__pass_state;

/* GL's defaults: the state the header promises after a frame. */
extern const stin__pass_state stin__pass_defaults;

/* Makes GL hold s, issuing only the calls whose state differs from the cache. */
void stin__pass_apply(struct stin_context *ctx, const stin__pass_state *s);
/* Whether one pass can give front and back faces their own stencil ops
 * (two-sided or separate stencil). */
int stin__pass_two_sided(const struct stin_context *ctx);
/* Whether one pass can count both faces with wrapping increments and
 * decrements (stencil wrap and two-sided or separate stencil): else front
 * faces then back faces, increments first, clamped. */
int stin__pass_two_sided_wrap(const struct stin_context *ctx);
/* What GL holds now (the last applied state). */
const stin__pass_state *stin__pass_current(const struct stin_context *ctx);
/* Forget the cache: the next apply sets everything (the caller's state is unknown). */
void stin__pass_forget(struct stin_context *ctx);
/* Common shapes. additive: depth EQUAL without writes, blend ONE/ONE (or
 * SRC_ALPHA/ONE with alpha); opaque: depth LESS with writes, no blend (or
 * SRC_ALPHA/ONE_MINUS_SRC_ALPHA with alpha). The stencil test is kept as the
 * cache holds it (a shadow technique's stencil test spans the lit passes). */
stin__pass_state stin__pass_draw(const struct stin_context *ctx, int additive, int blend_alpha);

/* Binds texture `name` of `target` on unit `unit` and records the unit as
 * used this frame; leaves `unit` active. */
void stin__bind_unit(struct stin_context *ctx, int unit, GLenum target, GLuint name);
/* Unbinds every 2D, 1D and cube-map texture on the units of the bit mask
 * `units` (bit u: unit u) and makes unit 0 active. */
void stin__unbind_units(struct stin_context *ctx, uint32_t units);
/* The same for the units the frame used. */
void stin__unbind_used_units(struct stin_context *ctx);

#endif
