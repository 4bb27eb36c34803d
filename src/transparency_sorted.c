/* SPDX-License-Identifier: MIT */
/* "sorted": the blended draws after the opaque ones, each drawn whole, far
 * to near by the eye depth of its bounds' centre (frame.c orders them), with
 * depth LESS and writes. Exact for separate convex objects; objects that
 * intersect, interleave in depth, or overlap themselves (a box's two sides)
 * show whichever surface the order or the triangle order puts last. */
#include "internal.h"

void stin__sorted_frame(stin_context *ctx)
{
    uint32_t i, blended = 0;
    if (ctx->peel.said_sorted)
        return;
    for (i = 0; i < ctx->draw_count; i++)
        blended += ctx->draws[i].material.color[3] < 1.0f;
    if (!blended)
        return;
    ctx->peel.said_sorted = 1;
    stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
              "transparency: blended draws are drawn sorted, per object far to near; "
              "intersecting or self-overlapping transparent objects are not exact");
}
