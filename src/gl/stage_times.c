/* SPDX-License-Identifier: MIT */
/* GPU time per frame stage. A timestamp (glQueryCounter) is written where
 * the frame plan changes stage; a stage's time is the gap to the next
 * timestamp, summed over its visits (the per-light stages come back light
 * by light). Timestamps, not GL_TIME_ELAPSED: those cannot nest, and the
 * stages' own occlusion and primitive queries stay free to run. The reads
 * wait for the GPU at the frame's end, so timing is a debug flag. */
#include "gl/stage_times_private.h"

size_t stin__times_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(struct stin__stage_times);
}

void stin__times_init(stin_context *ctx)
{
    struct stin__stage_times *t = ctx->times;
    const uint64_t need = STIN_CAP_BIT(STIN_CAP_TIMER_QUERY) |
                          STIN_CAP_BIT(STIN_CAP_OCCLUSION_QUERY);
    stin__memzero(t, sizeof *t);
    if (!(ctx->desc.debug_flags & STIN_DEBUG_STAGE_TIMES))
        return;
    if ((ctx->caps.present & need) != need) {
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                  "STIN_DEBUG_STAGE_TIMES: the context has no timer queries (GL 3.3 or "
                  "GL_ARB_timer_query); frames are not timed");
        return;
    }
    GL(ctx, GenQueries)((GLsizei)STIN__STAGE_MARKS, t->queries);
    t->on = 1;
}

void stin__times_release(stin_context *ctx)
{
    struct stin__stage_times *t = ctx->times;
    if (t->on)
        GL(ctx, DeleteQueries)((GLsizei)STIN__STAGE_MARKS, t->queries);
    stin__memzero(t, sizeof *t);
}

static void mark(stin_context *ctx, stin_stage s)
{
    struct stin__stage_times *t = ctx->times;
    t->current = s;
    if (t->marks + 1u >= STIN__STAGE_MARKS) { /* the last one ends the frame */
        if (!t->said_full)
            stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                      "STIN_DEBUG_STAGE_TIMES: a frame changed stage more than %u times; "
                      "the rest of its time goes to the stage before",
                      STIN__STAGE_MARKS - 2u);
        t->said_full = 1;
        return;
    }
    /* Each counter in a submission of its own: a renderer that defers
     * drawing to the flush (llvmpipe bins a whole scene and stamps every
     * counter in it when the scene is done) would otherwise stamp a stage's
     * start when the work after it is done. */
    GL(ctx, Flush)();
    GL(ctx, QueryCounter)(t->queries[t->marks], GL_TIMESTAMP);
    GL(ctx, Flush)();
    t->stage[t->marks++] = (unsigned char)s;
}

void stin__times_begin(stin_context *ctx, stin_stage s)
{
    ctx->times->marks = 0;
    if (ctx->times->on)
        mark(ctx, s);
}

stin_stage stin__times_enter(stin_context *ctx, stin_stage s)
{
    stin_stage was = ctx->times->current;
    if (ctx->times->on && s != was)
        mark(ctx, s);
    return was;
}

void stin__times_end(stin_context *ctx)
{
    struct stin__stage_times *t = ctx->times;
    GLuint64 at[STIN__STAGE_MARKS];
    uint32_t i;
    if (!t->on || !t->marks)
        return;
    GL(ctx, QueryCounter)(t->queries[t->marks], GL_TIMESTAMP);
    for (i = 0; i <= t->marks; i++) { /* the first read waits; the rest are done */
        at[i] = 0;
        GL(ctx, GetQueryObjectui64v)(t->queries[i], GL_QUERY_RESULT, &at[i]);
    }
    for (i = 0; i < t->marks; i++)
        if (at[i + 1] > at[i]) /* timestamps are monotonic; a driver's that is not counts 0 */
            ctx->stats.stage_ns[t->stage[i]] += at[i + 1] - at[i];
    ctx->stats.stage_times = 1;
}
