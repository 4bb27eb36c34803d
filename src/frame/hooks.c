/* SPDX-License-Identifier: MIT */
/* The services the frame lends the layers below it, pointing at the
 * features that give them: the frame is the one layer that names
 * features, so the shadow techniques, passes and post stages reach the
 * CSG products only through these (render/casters.h, render/resolved.h). */
#include "internal.h"

static const stin__casters csg_casters = {
    stin__csg_cast_wanted,
    stin__csg_cast,
    stin__csg_cast_again,
    stin__csg_cast_none,
};

static const stin__resolved csg_resolved = {
    stin__csg_face_begin,
    stin__csg_face_end,
    stin__csg_depth_again,
    stin__csg_depth_texture,
};

void stin__hooks_install(stin_context *ctx)
{
    /* csg-off is final once stin__csg_init has run: no products are ever
     * resolved or cast, which the hooks' absence says too */
    int csg = ctx->sel.choice[STIN_FEATURE_CSG].technique != STIN_TECH_CSG_OFF;
    ctx->casters.hooks = csg ? &csg_casters : NULL;
    ctx->casters.drew = 0;
    ctx->resolved = csg ? &csg_resolved : NULL;
}
