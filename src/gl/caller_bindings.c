/* SPDX-License-Identifier: MIT */
/* Caller state that stin's uploads and draws would otherwise write through
 * or read from: the bound vertex array object (element buffer, attribute
 * pointers) and the pixel-unpack state (row length, skips, alignment, a
 * bound pixel unpack buffer). Each is set aside for the call and put back. */
#include "internal.h"

#define VERTEX_ARRAY_BINDING 0x85B5
#define UNPACK_ROW_LENGTH 0x0CF2
#define UNPACK_SKIP_ROWS 0x0CF3
#define UNPACK_SKIP_PIXELS 0x0CF4
#define PIXEL_UNPACK_BUFFER 0x88EC
#define PIXEL_UNPACK_BUFFER_BINDING 0x88EF

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

/* Pixel unpack buffers are GL 2.1 (buffer objects bound to a new target). */
static int has_unpack_buffer(const stin_context *ctx)
{
    return (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_VBO)) &&
           ctx->caps.gl_major * 10 + ctx->caps.gl_minor >= 21;
}

static const GLenum store[STIN__UNPACK_STORE] = {GL_UNPACK_ALIGNMENT, UNPACK_ROW_LENGTH,
                                                 UNPACK_SKIP_ROWS, UNPACK_SKIP_PIXELS};
static const GLint tight[STIN__UNPACK_STORE] = {1, 0, 0, 0};

void stin__unpack_begin(stin_context *ctx, stin__unpack_saved *s)
{
    int i;
    for (i = 0; i < STIN__UNPACK_STORE; i++) {
        s->store[i] = tight[i];
        GL(ctx, GetIntegerv)(store[i], &s->store[i]);
        if (s->store[i] != tight[i])
            GL(ctx, PixelStorei)(store[i], tight[i]);
    }
    s->buffer = 0;
    if (has_unpack_buffer(ctx)) {
        GL(ctx, GetIntegerv)(PIXEL_UNPACK_BUFFER_BINDING, &s->buffer);
        if (s->buffer)
            GL(ctx, BindBuffer)(PIXEL_UNPACK_BUFFER, 0);
    }
}

void stin__unpack_end(stin_context *ctx, const stin__unpack_saved *s)
{
    int i;
    for (i = 0; i < STIN__UNPACK_STORE; i++)
        if (s->store[i] != tight[i])
            GL(ctx, PixelStorei)(store[i], s->store[i]);
    if (s->buffer)
        GL(ctx, BindBuffer)(PIXEL_UNPACK_BUFFER, (GLuint)s->buffer);
}
