/* SPDX-License-Identifier: MIT */
/* The full-viewport quad: one vertex table for every pass that covers the
 * viewport (composites, resolves, vdsm's screen passes, the outline, the
 * screen mask) and its draw through the bound program. */
#include "internal.h"

/* Clip-space xyzw, two counter-clockwise triangles at depth 0 and on the
 * far plane; static, since client arrays are read at the draw and the
 * pointer stays set after it. */
static const float quads[2][6 * 4] = {
    {-1, -1, 0, 1, 1, -1, 0, 1, 1, 1, 0, 1, -1, -1, 0, 1, 1, 1, 0, 1, -1, 1, 0, 1},
    {-1, -1, 1, 1, 1, -1, 1, 1, 1, 1, 1, 1, -1, -1, 1, 1, 1, 1, 1, 1, -1, 1, 1, 1},
};

const float *stin__screen_quad_vertices(int far)
{
    return quads[far ? 1 : 0];
}

/* GL4: through the streamed volume buffer, whose vertex array has
 * attribute 0 alone enabled. */
static void streamed(stin_context *ctx)
{
    GL(ctx, BindVertexArray)(ctx->volume_vao);
    GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, ctx->volume_vbo);
    GL(ctx, BufferData)(GL_ARRAY_BUFFER, (GLsizeiptr)sizeof quads[0], quads[0], GL_STREAM_DRAW);
    GL(ctx, DrawArrays)(GL_TRIANGLES, 0, 6);
    GL(ctx, BindVertexArray)(0);
    GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
}

/* GL2: from client memory (on OpenGL ES 3.0+ through the stream buffer);
 * the quad feeds attribute 0 alone, so the mesh
 * arrays the GLSL path keeps enabled are off for the draw. */
static void client_arrays(stin_context *ctx)
{
    int i;
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_VBO))
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, ctx->volume_vbo);
    if (ctx->volume_vbo) /* OpenGL ES 3.0+: WebGL 2 has no client arrays */
        GL(ctx, BufferData)(GL_ARRAY_BUFFER, (GLsizeiptr)sizeof quads[0], quads[0], GL_STREAM_DRAW);
    for (i = 1; i < 4; i++)
        GL(ctx, DisableVertexAttribArray)((GLuint)i);
    GL(ctx, VertexAttribPointer)(0, 4, GL_FLOAT, GL_FALSE, 0, ctx->volume_vbo ? NULL : quads[0]);
    GL(ctx, DrawArrays)(GL_TRIANGLES, 0, 6);
    if (ctx->volume_vbo)
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
    for (i = 1; i < 4; i++)
        GL(ctx, EnableVertexAttribArray)((GLuint)i);
}

void stin__screen_quad(stin_context *ctx)
{
    if (ctx->volume_vao)
        streamed(ctx);
    else
        client_arrays(ctx);
    ctx->bound_mesh = 0xffffffffu;
}
