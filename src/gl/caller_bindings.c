/* SPDX-License-Identifier: MIT */
/* Caller state that stin's uploads, draws and read-backs would otherwise
 * write through or read from: the bound vertex array object (element
 * buffer, attribute pointers) and the pixel unpack and pack state (row
 * length, skips, alignment, a bound pixel buffer, pixel transfer). Each is set aside for
 * the call and put back. */
#include "internal.h"

#define VERTEX_ARRAY_BINDING 0x85B5
#define UNPACK_ROW_LENGTH 0x0CF2
#define UNPACK_SKIP_ROWS 0x0CF3
#define UNPACK_SKIP_PIXELS 0x0CF4
#define PIXEL_UNPACK_BUFFER 0x88EC
#define PIXEL_UNPACK_BUFFER_BINDING 0x88EF
#define PACK_ROW_LENGTH 0x0D02
#define PACK_SKIP_ROWS 0x0D03
#define PACK_SKIP_PIXELS 0x0D04
#define PIXEL_PACK_BUFFER 0x88EB
#define PIXEL_PACK_BUFFER_BINDING 0x88ED

GLuint stin__vao_begin(stin_context *ctx)
{
    GLint saved = 0;
    if (!(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_VAO)))
        return 0;
    GL(ctx, GetIntegerv)(VERTEX_ARRAY_BINDING, &saved);
    if (saved)
        GL(ctx, BindVertexArray)(0);
    return (GLuint)saved;
}

void stin__vao_end(stin_context *ctx, GLuint saved)
{
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_VAO))
        GL(ctx, BindVertexArray)(saved);
}

/* Pixel pack and unpack buffers are GL 2.1 (buffer objects bound to new targets). */
static int has_pixel_buffer(const stin_context *ctx)
{
    return (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_VBO)) &&
           ctx->caps.gl_major * 10 + ctx->caps.gl_minor >= 21;
}

/* One direction's pixel store: its parameters and its buffer target. */
typedef struct pixel_store {
    GLenum store[STIN__UNPACK_STORE];
    GLenum buffer, binding;
} pixel_store;

static const pixel_store unpack = {
    {GL_UNPACK_ALIGNMENT, UNPACK_ROW_LENGTH, UNPACK_SKIP_ROWS, UNPACK_SKIP_PIXELS},
    PIXEL_UNPACK_BUFFER, PIXEL_UNPACK_BUFFER_BINDING};
static const pixel_store pack = {
    {GL_PACK_ALIGNMENT, PACK_ROW_LENGTH, PACK_SKIP_ROWS, PACK_SKIP_PIXELS},
    PIXEL_PACK_BUFFER, PIXEL_PACK_BUFFER_BINDING};
static const GLint tight[STIN__UNPACK_STORE] = {1, 0, 0, 0};

/* Pixel transfer, GL's defaults: the GL1 tier sets them for its frame
 * (gl/caller_state.c); the GLSL tiers of a compatibility context read
 * back and draw depth and stencil through them too (the CSG resolve). */
static const GLenum transfer[STIN__PIXEL_TRANSFER] = {
    GL_RED_SCALE, GL_GREEN_SCALE, GL_BLUE_SCALE, GL_ALPHA_SCALE, GL_DEPTH_SCALE,
    GL_RED_BIAS,  GL_GREEN_BIAS,  GL_BLUE_BIAS,  GL_ALPHA_BIAS,  GL_DEPTH_BIAS,
    GL_MAP_COLOR, GL_MAP_STENCIL, GL_INDEX_SHIFT, GL_INDEX_OFFSET};
static const float transfer_default[STIN__PIXEL_TRANSFER] = {1, 1, 1, 1, 1, 0, 0,
                                                             0, 0, 0, 0, 0, 0, 0};

static int has_transfer(const stin_context *ctx)
{
    return (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FIXED_FUNCTION)) != 0;
}

/* How many of the pixel-store values the context has: OpenGL ES 2.0 has
 * only the alignment (row length and skips are ES 3.0's). */
static int store_count(const stin_context *ctx)
{
    return ctx->caps.es && ctx->caps.gl_major < 3 ? 1 : STIN__UNPACK_STORE;
}

static void store_begin(stin_context *ctx, const pixel_store *p, stin__unpack_saved *s)
{
    int i;
    for (i = 0; i < STIN__UNPACK_STORE; i++)
        s->store[i] = tight[i];
    for (i = 0; i < store_count(ctx); i++) {
        GL(ctx, GetIntegerv)(p->store[i], &s->store[i]);
        if (s->store[i] != tight[i])
            GL(ctx, PixelStorei)(p->store[i], tight[i]);
    }
    s->buffer = 0;
    if (has_pixel_buffer(ctx)) {
        GL(ctx, GetIntegerv)(p->binding, &s->buffer);
        if (s->buffer)
            GL(ctx, BindBuffer)(p->buffer, 0);
    }
    for (i = 0; i < STIN__PIXEL_TRANSFER; i++) {
        s->transfer[i] = transfer_default[i];
        if (!has_transfer(ctx))
            continue;
        GL(ctx, GetFloatv)(transfer[i], &s->transfer[i]);
        if (s->transfer[i] != transfer_default[i])
            GL(ctx, PixelTransferf)(transfer[i], transfer_default[i]);
    }
}

static void store_end(stin_context *ctx, const pixel_store *p, const stin__unpack_saved *s)
{
    int i;
    for (i = 0; i < store_count(ctx); i++)
        if (s->store[i] != tight[i])
            GL(ctx, PixelStorei)(p->store[i], s->store[i]);
    if (s->buffer)
        GL(ctx, BindBuffer)(p->buffer, (GLuint)s->buffer);
    for (i = 0; i < STIN__PIXEL_TRANSFER; i++)
        if (s->transfer[i] != transfer_default[i])
            GL(ctx, PixelTransferf)(transfer[i], s->transfer[i]);
}

void stin__unpack_begin(stin_context *ctx, stin__unpack_saved *s)
{
    store_begin(ctx, &unpack, s);
}

void stin__unpack_end(stin_context *ctx, const stin__unpack_saved *s)
{
    store_end(ctx, &unpack, s);
}

void stin__pack_begin(stin_context *ctx, stin__unpack_saved *s)
{
    store_begin(ctx, &pack, s);
}

void stin__pack_end(stin_context *ctx, const stin__unpack_saved *s)
{
    store_end(ctx, &pack, s);
}
