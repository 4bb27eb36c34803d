/* SPDX-License-Identifier: MIT */
/* Counters of the checked build, for tests (include/stin/stin_debug.h). */
#include "internal.h"
#include "stin/stin_debug.h"

stin_debug_counters stin_debug_query_counters(const stin_context *ctx)
{
    stin_debug_counters c;
    stin__memzero(&c, sizeof c);
#if defined(STIN_GL_CHECK) && STIN_GL_CHECK
    c.checked = 1;
#endif
    if (ctx) {
        c.gl_violations = ctx->gl_violations;
        c.gl_errors = ctx->gl_errors;
    }
    return c;
}
