/* SPDX-License-Identifier: MIT */
/* The extra shadow casters' hooks called for the shadow techniques, with
 * "nothing to cast" where the frame lent none (render/casters.h). */
#include "internal.h"

int stin__casters_wanted(const stin_context *ctx)
{
    return ctx->casters.hooks ? ctx->casters.hooks->wanted(ctx) : 0;
}

int stin__casters_cast(stin_context *ctx, const stin__path *path, const float view[16],
                       const float proj[16], const int map_vp[4], GLuint map_fbo, int in_place,
                       float factor, float units)
{
    const stin__casters *h = ctx->casters.hooks;
    ctx->casters.drew =
        h ? h->cast(ctx, path, view, proj, map_vp, map_fbo, in_place, factor, units) : 0;
    return ctx->casters.drew;
}

void stin__casters_again(stin_context *ctx, const int map_vp[4], GLuint target, int in_place)
{
    if (ctx->casters.hooks)
        ctx->casters.hooks->again(ctx, map_vp, target, in_place);
}

void stin__casters_none(stin_context *ctx, const char *why)
{
    if (ctx->casters.hooks)
        ctx->casters.hooks->none(ctx, why);
}

int stin__casters_product(const stin_context *ctx, uint32_t i, stin__caster_product *out)
{
    return ctx->casters.hooks ? ctx->casters.hooks->product(ctx, i, out) : 0;
}

const uint32_t *stin__casters_term(const stin_context *ctx, const stin__caster_product *p,
                                   uint32_t t, uint32_t *count)
{
    return ctx->casters.hooks->term(ctx, p, t, count); /* p came from product(): lent */
}

int stin__casters_drew(const stin_context *ctx)
{
    return ctx->casters.drew;
}
