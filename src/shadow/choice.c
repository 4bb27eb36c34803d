/* SPDX-License-Identifier: MIT */
/* The measured choice of the exact technique (stin.h, SHADOWS): vdsm and
 * stencil volumes (GPU-extruded or CPU-built) are both exact, and which is
 * cheaper depends on the GPU and the scene, so where the selection chose
 * vdsm on auto each frame runs the candidate that measured cheapest. A
 * GL_TIME_ELAPSED query spans each shadowed frame's plan; results are read
 * a frame or more later, once available, so no frame waits for the GPU.
 * Every desc.shadows.choice_frames frames one frame runs another candidate
 * as a trial; the choice moves only after a candidate beat the chosen one by
 * the margin on consecutive trials, so noise neither switches nor flips it.
 * Both techniques read the same shadow chunk (shadow_mask.glsl), so
 * switching the module rebuilds no program. Which frames volumes draw the
 * same is the frame's to say (frame/shadow_choice.c): it names the features
 * that decide it. */
#include "internal.h"

#define CANDIDATES 3    /* vdsm, GPU-extruded volumes, CPU-built volumes */
#define QUERIES 4       /* frames timed and not yet read back */
#define MARGIN 0.15f    /* a candidate must be this much cheaper to win a trial */
#define CONFIRM 2u      /* trials in a row it must win before the choice moves */
#define SMOOTHING 0.25f /* weight of a new frame's ms in the smoothed cost */
#define EXPLORE 3u      /* timed frames of each candidate before trials slow down
                         * (the first dropped, then CONFIRM) */
#define WARMUP 8u       /* frames before the first trial: the first frames of a
                         * context build programs and buffers, and an application
                         * that renders a few frames only keeps the selection's */

enum { VDSM, VOLUME_GPU, VOLUME_CPU };

struct stin__choice_state {
    int on;              /* the choice runs in this context */
    unsigned char present[CANDIDATES]; /* GPU extrusion only where it runs */
    int current;         /* the chosen candidate */
    int planned;         /* what this frame began on (stin__choice_begin) */
    int ran;             /* what its plan ran (stin__choice_plan) */
    int trial;           /* this frame is a trial */
    int begin_on_vdsm;   /* the last frame volumes could not draw: begin on vdsm */
    int next;            /* the candidate the next trial runs */
    int timing;          /* the query this frame's plan runs in, -1 none */
    uint32_t since_trial; /* frames volumes could draw since the last trial */
    uint32_t frames;      /* shadowed frames volumes could draw, up to WARMUP */
    float ms[CANDIDATES]; /* smoothed ms of a frame, 0 unknown */
    uint32_t timed[CANDIDATES]; /* frames read back (the first of each dropped) */
    uint32_t wins[CANDIDATES];  /* trials in a row won by the margin */
    GLuint query[QUERIES];
    unsigned char busy[QUERIES], query_candidate[QUERIES], query_trial[QUERIES];
};

size_t stin__choice_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(struct stin__choice_state);
}

static const char *candidate_name(int c)
{
    static const char *const names[CANDIDATES] = {"vdsm", "volume (GPU-extruded)",
                                                  "volume (CPU-built)"};
    return names[c];
}

static const stin__shadow_technique *module_of(int c)
{
    return c == VDSM ? &stin__shadow_vdsm : &stin__shadow_volume;
}

/* Whether stencil volumes run where the selection put vdsm: their needs,
 * the lighting, and a stencil buffer. A displaced draw keeps its frame on
 * vdsm (frame/shadow_choice.c). */
static int volumes_run(const stin_context *ctx)
{
    const stin_technique lighting = ctx->sel.choice[STIN_FEATURE_LIGHTING].technique;
    return !(stin__technique_needs(STIN_TECH_SHADOWS_VOLUME) & ~ctx->caps.present) &&
           stin__technique_runs_with(STIN_TECH_SHADOWS_VOLUME, lighting);
}

void stin__choice_init(stin_context *ctx)
{
    struct stin__choice_state *s = ctx->choice;
    const uint64_t timers = STIN_CAP_BIT(STIN_CAP_TIMER_QUERY) |
                            STIN_CAP_BIT(STIN_CAP_OCCLUSION_QUERY);
    stin_choice *c = &ctx->sel.choice[STIN_FEATURE_SHADOWS];
    size_t n;
    int i;
    stin__memzero(s, sizeof *s);
    s->timing = -1;
    if (ctx->desc.techniques[STIN_FEATURE_SHADOWS] != STIN_TECH_NONE ||
        c->technique != STIN_TECH_SHADOWS_VDSM || ctx->shadow != &stin__shadow_vdsm ||
        (ctx->desc.debug_flags & STIN_DEBUG_SHADOW_CHOICE_OFF) || !volumes_run(ctx))
        return;
    if ((ctx->caps.present & timers) != timers) {
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_TECHNIQUE_SELECTED,
                  "shadows: vdsm on every frame: choosing between vdsm and volumes by "
                  "measurement needs timer queries");
        return;
    }
    if (stin__shadow_volume.init && stin__shadow_volume.init(ctx) != STIN_OK)
        return;
    s->on = 1;
    s->present[VDSM] = s->present[VOLUME_CPU] = 1;
    s->present[VOLUME_GPU] = (unsigned char)stin__volume_extrude_enable(ctx, 1);
    s->current = VDSM;
    s->next = s->present[VOLUME_GPU] ? VOLUME_GPU : VOLUME_CPU;
    GL(ctx, GenQueries)(QUERIES, s->query);
    for (i = 0; i < QUERIES; i++)
        s->busy[i] = 0;
    /* what stin_query_choice says: the frames' technique is measured */
    for (n = 0; c->reason[n] && n + 1 < sizeof c->reason; n++)
        ;
    stin__formatf(c->reason + n, sizeof c->reason - n, "%s; each frame vdsm or volume by "
                  "measured cost", n ? "" : "vdsm");
    stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_TECHNIQUE_SELECTED,
              "shadows: chosen by measured GPU time per frame among %s (a trial every %u "
              "frames, switching at %d%% cheaper on %u trials in a row)",
              s->present[VOLUME_GPU] ? "vdsm, GPU-extruded and CPU-built volumes"
                                 : "vdsm and CPU-built volumes",
              ctx->desc.shadows.choice_frames, (int)(MARGIN * 100.0f + 0.5f), CONFIRM);
}

void stin__choice_release(stin_context *ctx)
{
    struct stin__choice_state *s = ctx->choice;
    if (!s->on)
        return;
    GL(ctx, DeleteQueries)(QUERIES, s->query);
    if (stin__shadow_volume.release)
        stin__shadow_volume.release(ctx);
    ctx->shadow = &stin__shadow_vdsm; /* released by the context as the selection's */
    s->on = 0;
}

/* Until every candidate has been timed EXPLORE times, one frame in two. */
static uint32_t trial_every(const stin_context *ctx)
{
    const struct stin__choice_state *s = ctx->choice;
    int c;
    for (c = 0; c < CANDIDATES; c++)
        if (s->present[c] && c != s->current && s->timed[c] < EXPLORE)
            return 1u;
    return ctx->desc.shadows.choice_frames;
}

static int free_query(const struct stin__choice_state *s)
{
    int i;
    for (i = 0; i < QUERIES; i++)
        if (!s->busy[i])
            return i;
    return -1;
}

static int other_after(const struct stin__choice_state *s, int c)
{
    do
        c = (c + 1) % CANDIDATES;
    while (c == s->current || !s->present[c]);
    return c;
}

const stin__shadow_technique *stin__choice_begin(stin_context *ctx)
{
    struct stin__choice_state *s = ctx->choice;
    if (!s->on)
        return ctx->shadow;
    s->trial = 0;
    s->planned = s->current;
    if (s->begin_on_vdsm) {
        s->planned = VDSM;
    } else if (s->frames >= WARMUP && s->since_trial >= trial_every(ctx) &&
               free_query(s) >= 0) {
        if (s->next == s->current)
            s->next = other_after(s, s->next);
        s->planned = s->next;
        s->trial = 1;
    }
    if (s->planned != VDSM)
        (void)stin__volume_extrude_enable(ctx, s->planned == VOLUME_GPU);
    return module_of(s->planned);
}

static void switch_to(stin_context *ctx, int c)
{
    struct stin__choice_state *s = ctx->choice;
    int k;
    stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_TECHNIQUE_SELECTED,
              "shadows: %s (%f ms a frame) instead of %s (%f ms): cheaper by more than "
              "%d%% on %u trials in a row",
              candidate_name(c), (double)s->ms[c], candidate_name(s->current),
              (double)s->ms[s->current], (int)(MARGIN * 100.0f + 0.5f), CONFIRM);
    s->current = c;
    for (k = 0; k < CANDIDATES; k++)
        s->wins[k] = 0;
}

/* One frame's time read back: the candidate's smoothed cost, and on a trial
 * whether it beat the chosen one. */
static void record(stin_context *ctx, int c, int trial, GLuint64 ns)
{
    struct stin__choice_state *s = ctx->choice;
    float ms = (float)((double)ns * 1e-6);
    if (s->timed[c]++ == 0)
        return; /* its first frame made its buffers */
    s->ms[c] = s->ms[c] > 0.0f ? s->ms[c] + SMOOTHING * (ms - s->ms[c]) : ms;
    if (!trial || c == s->current || s->ms[s->current] <= 0.0f)
        return;
    if (s->ms[c] * (1.0f + MARGIN) < s->ms[s->current])
        s->wins[c]++;
    else
        s->wins[c] = 0;
    if (s->wins[c] >= CONFIRM)
        switch_to(ctx, c);
}

/* The frames whose results are there, oldest first; none waits. */
static void read_back(stin_context *ctx)
{
    struct stin__choice_state *s = ctx->choice;
    int i;
    for (i = 0; i < QUERIES; i++) {
        GLuint available = 0;
        GLuint64 ns = 0;
        if (!s->busy[i])
            continue;
        GL(ctx, GetQueryObjectuiv)(s->query[i], GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available)
            continue;
        GL(ctx, GetQueryObjectui64v)(s->query[i], GL_QUERY_RESULT, &ns);
        s->busy[i] = 0;
        record(ctx, s->query_candidate[i], s->query_trial[i], ns);
    }
}

void stin__choice_plan(stin_context *ctx, int volumes_draw)
{
    struct stin__choice_state *s = ctx->choice;
    int shadowed = ctx->light_count > 0 && ctx->frame.output != STIN_OUTPUT_NORMAL;
    if (!s->on)
        return;
    read_back(ctx);
    s->ran = s->planned;
    s->timing = -1;
    if (!volumes_draw) { /* vdsm's, and not a trial: the next frames begin on vdsm */
        s->ran = VDSM;
        s->trial = 0;
        s->begin_on_vdsm = 1;
        ctx->shadow = &stin__shadow_vdsm;
        return;
    }
    s->begin_on_vdsm = 0;
    if (!shadowed) {
        s->trial = 0; /* nothing to time: the trial waits for a shadowed frame */
        return;
    }
    if (s->frames < WARMUP)
        s->frames++;
    if (s->trial) {
        s->since_trial = 0;
        s->next = other_after(s, s->ran);
    } else {
        s->since_trial++;
    }
    /* a caller's time query: this frame goes untimed */
    s->timing = ctx->queries_busy & STIN__QUERY_TIME ? -1 : free_query(s);
    if (s->timing < 0)
        return;
    s->busy[s->timing] = 1;
    s->query_candidate[s->timing] = (unsigned char)s->ran;
    s->query_trial[s->timing] = (unsigned char)s->trial;
    /* Each end of the query in a submission of its own: a renderer that
     * defers drawing to the flush (llvmpipe stamps every query end in a
     * scene when the scene is done) measured a frame drawn without a
     * framebuffer switch as 0.03 ms. On a GPU a few flushes a frame cost
     * nothing measurable. */
    GL(ctx, Flush)();
    GL_ENUM(ctx, BeginQuery, GL_TIME_ELAPSED)(GL_TIME_ELAPSED, s->query[s->timing]);
    GL(ctx, Flush)();
}

void stin__choice_end(stin_context *ctx)
{
    struct stin__choice_state *s = ctx->choice;
    stin_shadows_stats *st = &ctx->stats.shadows;
    int c;
    if (!s->on)
        return;
    if (s->timing >= 0) { /* in a submission of its own, as the begin */
        GL(ctx, Flush)();
        GL(ctx, EndQuery)(GL_TIME_ELAPSED);
        GL(ctx, Flush)();
    }
    s->timing = -1;
    st->choice_frame = (uint32_t)s->ran + 1u;
    st->choice_current = (uint32_t)s->current + 1u;
    st->choice_trial = (uint32_t)s->trial;
    for (c = 0; c < CANDIDATES; c++)
        st->choice_ms[c] = s->ms[c];
}
