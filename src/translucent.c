/* SPDX-License-Identifier: MIT */
/* One set of calls for the translucent-shadows feature, whichever technique
 * runs it: the frame plan, the lit programs and the shadows techniques ask
 * here, and each technique's module answers only when it is the one set up
 * (the others are no-ops). */
#include "internal.h"

const char *stin__translucent_chunk(const stin_context *ctx)
{
    const char *deep = stin__deep_chunk(ctx);
    return deep ? deep : stin__coloured_chunk(ctx);
}

void stin__translucent_locate(stin_context *ctx, stin__program *p)
{
    stin__deep_locate(ctx, p);
    stin__coloured_locate(ctx, p);
}

void stin__translucent_uniforms(stin_context *ctx, const stin__program *p)
{
    stin__deep_uniforms(ctx, p);
    stin__coloured_uniforms(ctx, p);
}

void stin__translucent_frame(stin_context *ctx)
{
    stin__deep_frame(ctx);
    stin__coloured_frame(ctx);
}

int stin__translucent_active(const stin_context *ctx)
{
    return stin__deep_active(ctx) || stin__coloured_active(ctx);
}

int stin__translucent_skips(const stin_context *ctx, const stin__draw *d)
{
    float a = d->material.color[3];
    if (a >= 1.0f)
        return 0;
    if (ctx->deep.ready || ctx->coloured.ready)
        return 1; /* it shadows through its map */
    return ctx->sel.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].technique ==
               STIN_TECH_TRANSLUCENT_OPAQUE &&
           a < ctx->desc.translucent_opaque_threshold;
}

void stin__translucent_light(stin_context *ctx, uint32_t li)
{
    stin__deep_light(ctx, li);
    stin__coloured_light(ctx, li);
}

void stin__translucent_light_done(stin_context *ctx)
{
    stin__deep_light_done(ctx);
    stin__coloured_light_done(ctx);
}
