/* SPDX-License-Identifier: MIT */
/* "sorted": the blended draws after the opaque ones, each drawn whole, far
 * to near by the eye depth of its bounds' centre (frame/frame.c orders them), with
 * depth LESS and writes. Exact for separate convex objects; objects that
 * intersect, interleave in depth, or overlap themselves (a box's two sides)
 * show whichever surface the order or the triangle order puts last.
 * Shadowed where the shadows technique tests a map per fragment in the lit
 * pass (map-pcf, GL1's map-depth and map-combine): frame/frame.c lights each draw
 * pass by pass through path->blended_one, the technique's test around each
 * light's pass. Volumes and vdsm cannot: their visibility is per pixel of
 * the nearest opaque surface (a stencil count, a screen mask), and a draw
 * drawn whole has no depth of its own to count or mask against. */
#include "transparency/transparency_private.h"

static int frame_blended(const stin_context *ctx)
{
    uint32_t i;
    for (i = 0; i < ctx->draw_count; i++)
        if (ctx->draws[i].material.color[3] < 1.0f)
            return 1;
    return 0;
}

void stin__sorted_frame(stin_context *ctx)
{
    if (ctx->peel->said_sorted || !frame_blended(ctx))
        return;
    ctx->peel->said_sorted = 1;
    stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
              "transparency: blended draws are drawn sorted, per object far to near; "
              "intersecting or self-overlapping transparent objects are not exact");
}

int stin__sorted_shadowed(stin_context *ctx)
{
    const stin__shadow_technique *t = ctx->shadow;
    if ((ctx->desc.debug_flags & STIN_DEBUG_SORTED_UNSHADOWED) || !frame_blended(ctx))
        return 0; /* (nothing to say in a frame without blended draws) */
    if (t->fragment_test)
        return 1;
    if (!ctx->peel->said_sorted_unshadowed)
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "transparency: sorted blended draws are lit unshadowed under %s: its "
                  "visibility is counted or masked against the nearest opaque surface, and "
                  "a blended draw drawn whole has no depth of its own to test against",
                  stin_technique_name(ctx->sel.choice[STIN_FEATURE_SHADOWS].technique));
    ctx->peel->said_sorted_unshadowed = 1;
    return 0;
}

int stin__sorted_light_shadowed(stin_context *ctx, uint32_t li)
{
    const stin__shadow_technique *t = ctx->shadow;
    /* (no test at all: stin__sorted_shadowed said so for the whole frame) */
    if (!t->fragment_test || t->fragment_test(ctx, li))
        return 1;
    if (!ctx->peel->said_sorted_light)
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "transparency: light %u has no map under %s (a point light without faces: "
                  "stencil volumes or none), so it lights the sorted blended draws unshadowed",
                  (unsigned)li,
                  stin_technique_name(ctx->sel.choice[STIN_FEATURE_SHADOWS].technique));
    ctx->peel->said_sorted_light = 1;
    return 0;
}
