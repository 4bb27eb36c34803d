/* SPDX-License-Identifier: MIT */
/* Both peels into a multisampled target. The layers are single-sampled
 * (one surface a pixel, the one at its centre), so a composite laid over
 * every sample of a pixel would colour the samples of the floor beside a
 * pane's edge with the pane, and leave the samples a pane covers without it
 * where the centre has none: no antialiased edge, and another surface's
 * colour on a sample, a one-pixel halo. So before the last quad the
 * blended draws are drawn once more into the frame's own target, depth
 * LESS with writes against its per-sample opaque depth and no colour,
 * marking in its stencil (cleared over the viewport first) each sample a
 * blended surface covers in front of the opaque ones; their nearest depth
 * is the frame's depth there, per sample. The quad (shaders: the
 * composite's u_params.w) then colours only the marked samples, with no
 * depth test: the pixel's composite, or where the centre holds no layer,
 * the nearest neighbour's that does (the pane one pixel on). What stays
 * per pixel: a covered sample takes the whole composite of the layers at
 * the centre (or that neighbour's), so an edge of a blended surface seen
 * through another, or the layers behind an opaque edge at the centre, are
 * one pixel sharp as any per-pixel shading. */
#include "transparency/transparency_private.h"

#define COVERED 1

int stin__peel_coverage(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    stin__pass_state ps = stin__pass_defaults;
    const int *vp = ctx->frame.viewport;
    int i;
    s->coverage = ctx->target.multisampled && ctx->target.stencil_bits > 0 && s->path;
    if (!s->coverage)
        return 0;
    ps.scissor = 1; /* the frame's stencil is its own over the viewport alone */
    for (i = 0; i < 4; i++)
        ps.scissor_box[i] = vp[i];
    ps.color_write = 0;
    ps.depth_write = 0;
    stin__pass_apply(ctx, &ps);
    GL(ctx, ClearStencil)(0);
    GL(ctx, Clear)(GL_STENCIL_BUFFER_BIT);
    ps.stencil_test = 1;
    ps.front.func = GL_ALWAYS;
    ps.front.ref = COVERED;
    ps.front.zpass = GL_REPLACE;
    ps.back = ps.front;
    stin__pass_apply(ctx, &ps); /* the path's depth pass keeps the stencil as applied */
    s->path->ambient(ctx, STIN__BLENDED, 1);
    ctx->stats.passes++;
    ps.depth_test = 0;
    ps.color_write = 1;
    ps.blend = 1;
    ps.blend_src = GL_ONE;
    ps.blend_dst = GL_ONE_MINUS_SRC_ALPHA;
    ps.front.func = GL_EQUAL;
    ps.front.zpass = GL_KEEP;
    ps.back = ps.front;
    stin__pass_apply(ctx, &ps);
    return 1;
}

void stin__peel_coverage_done(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    stin__pass_state ps = stin__pass_defaults;
    if (!s->coverage)
        return;
    s->coverage = 0;
    stin__pass_apply(ctx, &ps); /* no stencil test for the passes after */
}
