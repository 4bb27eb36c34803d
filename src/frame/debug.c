/* SPDX-License-Identifier: MIT */
/* Counters of the checked build, for tests, and the shadow maps for
 * looking at (include/stin/stin_debug.h). */
#include "internal.h"
#include "stin/stin_debug.h"

stin_debug_counters stin_debug_query_counters(const stin_context *ctx)
{
    stin_debug_counters c;
    stin__memzero(&c, sizeof c);
#if defined(STIN_GL_CHECK) && STIN_GL_CHECK
    c.checked = 1;
#endif
    if (ctx)
        c.gl_violations = ctx->gl_violations;
    return c;
}

stin_result stin_debug_query_shadow_map(const stin_context *ctx, uint32_t light,
                                        stin_debug_map *out)
{
    if (!ctx || !out)
        return STIN_ERROR_INVALID_ARGUMENT;
    if (ctx->state != STIN__IDLE)
        return STIN_ERROR_INVALID_STATE;
    if (light >= ctx->light_count || light >= STIN__MAX_LIGHTS)
        return STIN_ERROR_INVALID_ARGUMENT;
    stin__memzero(out, sizeof *out);
    if (!ctx->shadow->debug_map)
        return STIN_ERROR_UNSUPPORTED; /* the technique keeps no maps */
    return ctx->shadow->debug_map(ctx, light, out);
}
