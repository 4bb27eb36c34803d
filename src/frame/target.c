/* SPDX-License-Identifier: MIT */
/* Whether the context's shadows choice can run into the framebuffer a
 * frame draws into: the probe (gl/framebuffer_probe.c) reads the target's
 * bits, and the frame weighs them against the chosen technique's needs
 * (select/technique_table.c), which the probe sits below. */
#include "internal.h"

/* Whether the chosen shadows technique runs into the target; says so when
 * the answer changes (a target without a stencil buffer turns volumes off
 * for its frames, and the context's choice stays). */
static void decide_shadows(stin_context *ctx)
{
    stin_technique t = ctx->sel.choice[STIN_FEATURE_SHADOWS].technique;
    int off = (stin__technique_needs(t) & STIN_CAP_BIT(STIN_CAP_STENCIL)) &&
              ctx->target.stencil_bits <= 0;
    if (off != ctx->target.shadows_off)
        stin__log(ctx, off ? STIN_LOG_LEVEL_WARNING : STIN_LOG_LEVEL_INFO,
                  off ? STIN_LOG_FALLBACK : STIN_LOG_TECHNIQUE_SELECTED,
                  off ? "shadows: %s falls back to off in frames into framebuffer %u: it has "
                        "no stencil buffer"
                      : "shadows: %s again in frames into framebuffer %u (%d stencil bits)",
                  stin_technique_name(t), (unsigned)ctx->target.name, ctx->target.stencil_bits);
    ctx->target.shadows_off = off;
}

stin_result stin__target_check(stin_context *ctx, GLuint name, const char *call)
{
    stin_result r = stin__target_probe(ctx, name, call);
    if (r == STIN_OK)
        decide_shadows(ctx);
    return r;
}
