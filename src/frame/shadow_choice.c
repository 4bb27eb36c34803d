/* SPDX-License-Identifier: MIT */
/* The measured choice of the exact technique around a frame (the choice
 * itself: shadow/choice.c). Whether volumes draw a frame the same as vdsm
 * depends on other features' work in it (CSG products, displacement,
 * peeled layers), which only the frame may name, so it is weighed here and
 * handed down as one flag. */
#include "internal.h"

/* 0 where the frame holds something only vdsm shadows as the frame should
 * look: CSG products and displaced draws (vdsm casts them exactly, volumes
 * through a map of their own), blended draws (vdsm makes each peeled
 * layer its receivers; transparent casters), an area light (vdsm shadows
 * it by 64 segments a pixel, volumes by a pass a sample: the penumbrae
 * differ), or a target without a stencil buffer. Smooth meshes, closed or
 * open, take the terminator rule under both (shadow/volume_band.c). */
static int volumes_draw(const stin_context *ctx)
{
    uint32_t i;
    if (stin__csg_product_count(ctx) || !stin__target_has_stencil(ctx))
        return 0;
    for (i = 0; i < ctx->light_count; i++)
        if (ctx->lights[i].radius > 0.0f)
            return 0;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin_material *m = &ctx->draws[i].material;
        if (m->color[3] < 1.0f || stin__displace_active(ctx, m))
            return 0;
    }
    return 1;
}

void stin__frame_choice_begin(stin_context *ctx) { ctx->shadow = stin__choice_begin(ctx); }

void stin__frame_choice_plan(stin_context *ctx) { stin__choice_plan(ctx, volumes_draw(ctx)); }

void stin__frame_choice_end(stin_context *ctx) { stin__choice_end(ctx); }
