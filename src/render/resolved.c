/* SPDX-License-Identifier: MIT */
/* The resolved depth's hooks called for the passes, doing nothing where
 * the frame lent none (render/resolved.h). */
#include "internal.h"

const stin__draw *stin__resolved_faces(const stin_context *ctx, uint32_t *count)
{
    *count = 0;
    return ctx->resolved ? ctx->resolved->faces(ctx, count) : NULL;
}

int stin__resolved_face_begin(stin_context *ctx, const stin__draw *d, stin__pass_state *saved)
{
    return ctx->resolved ? ctx->resolved->face_begin(ctx, d, saved) : 0;
}

void stin__resolved_face_end(stin_context *ctx, const stin__pass_state *saved)
{
    if (ctx->resolved)
        ctx->resolved->face_end(ctx, saved);
}

void stin__resolved_depth_again(stin_context *ctx, const stin__path *path)
{
    if (ctx->resolved)
        ctx->resolved->depth_again(ctx, path);
}

GLuint stin__resolved_depth_texture(stin_context *ctx, int origin[2])
{
    return ctx->resolved ? ctx->resolved->depth_texture(ctx, origin) : 0;
}

void stin__resolved_snap_band(const stin_context *ctx, const stin__draw *d, float band[2])
{
    band[0] = band[1] = 0.0f;
    if (ctx->resolved)
        ctx->resolved->snap_band(ctx, d, band);
}
