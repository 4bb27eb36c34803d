/* SPDX-License-Identifier: MIT */
/* The technique sections of stin-bench (PCF shadow maps, surface techniques).
 *
 * On one GLSL tier. Per set-up one stin context forced to the baseline
 * configuration (shadows off; or shadows off and the plain surface) is
 * created on the one GL context and kept for the set-up; then per row a
 * second one, forced to the row's configuration (shadow technique,
 * desc.shadows.map_size, surface technique), each with its own copy of the
 * scene's meshes and textures. The row's context draws a copy of the scene
 * struct whose lights carry the row's pcf_kernel (the baseline draws the
 * scene as it is); both go through scene_gpu_frame: warm-up, then whole
 * frames (glFinish included) in ABBA order, row first. The bench checks that
 * stin_query_choice reports the forced techniques, and takes the row's
 * frame statistics after the warm-up (the map size actually rendered,
 * passes). Per side and row the lowest set-up median is kept, as in
 * bench_run.c, bench_shadow.c and bench_maps.c. */
#include "bench_tech.h"
#include "bench_time.h"
#include "cli_log.h"
#include "raw_gl.h"
#include "scene_gpu.h"
#include "stin_platform.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct side {
    stin_context *ctx;
    void *block;
    scene_gpu gpu;
    int made;
} side;

typedef struct setup {
    const tech_settings *st;
    const scene *s;     /* the scene as loaded: the baseline draws it */
    scene sc;           /* a copy whose lights carry the row's pcf_kernel */
    scene_light *lights;
    side base;
    cli_log log;
} setup;

static void side_destroy(side *sd)
{
    if (sd->made)
        scene_gpu_destroy(&sd->gpu, sd->ctx);
    if (sd->ctx)
        stin_destroy(sd->ctx);
    free(sd->block);
    memset(sd, 0, sizeof *sd);
}

static void config_name(const tech_config *c, char *out, size_t size)
{
    snprintf(out, size, "shadows %s, map size %u, surface %s, displacement %s, debug flags 0x%x",
             stin_technique_name(c->shadows), c->map_size,
             c->surface == STIN_TECH_NONE ? "auto" : stin_technique_name(c->surface),
             c->displacement == STIN_TECH_NONE ? "auto" : stin_technique_name(c->displacement),
             (unsigned)c->debug_flags);
}

/* 1 made; 0 failed (err); -1 the context cannot run the configuration (why). */
static int side_create(setup *u, side *sd, const tech_config *c, const scene *s, char *why,
                       size_t why_size, char *err, size_t err_size)
{
    const bench_settings *b = u->st->b;
    stin_tier tier = u->st->tier;
    stin_desc desc;
    size_t bytes;
    stin_result r;
    stin_choice ch;
    char name[160];
    int k;
    config_name(c, name, sizeof name);
    bench_desc_init(b, &desc);
    desc.log = cli_log_fn;
    desc.log_user = &u->log;
    desc.tier = tier;
    desc.techniques[STIN_FEATURE_SHADOWS] = c->shadows;
    desc.techniques[STIN_FEATURE_SURFACE] = c->surface;
    desc.techniques[STIN_FEATURE_DISPLACEMENT] = c->displacement;
    desc.techniques[STIN_FEATURE_TRANSPARENCY] = c->transparency;
    desc.shadows.map_size = c->map_size;
    desc.debug_flags = c->debug_flags;
    desc.displacement.guard_band = c->guard_band;
    desc.displacement.tess_pixels = c->tess_pixels;
    desc.displacement.tess_max = c->tess_max;
    desc.techniques[STIN_FEATURE_TRANSLUCENT_SHADOWS] = c->translucent;
    desc.translucent.deep_layers = c->deep_layers;
    desc.translucent.deep_map_size = c->deep_map_size;
    scene_gpu_size_desc(s, &desc);
    bytes = stin_memory_size(&desc);
    if (!bytes) {
        snprintf(err, err_size, "stin_memory_size: bad desc (%s)", name);
        return 0;
    }
    if (!(sd->block = malloc(bytes))) {
        snprintf(err, err_size, "cannot allocate %zu bytes for stin", bytes);
        return 0;
    }
    r = stin_create(&desc, sd->block, bytes, &sd->ctx);
    if (r == STIN_ERROR_UNSUPPORTED) {
        snprintf(why, why_size, "the context cannot run it (stin_create: %s)",
                 stin_result_name(r));
        side_destroy(sd);
        return -1;
    }
    if (r != STIN_OK) {
        snprintf(err, err_size, "stin_create (%s, %s): %s", stin_tier_name(tier), name,
                 stin_result_name(r));
        free(sd->block);
        sd->block = NULL;
        return 0;
    }
    for (k = 0; k < 4; k++) { /* every forced technique kept (shadows always forced) */
        static const stin_feature features[4] = {STIN_FEATURE_SHADOWS, STIN_FEATURE_SURFACE,
                                                 STIN_FEATURE_DISPLACEMENT,
                                                 STIN_FEATURE_TRANSLUCENT_SHADOWS};
        const stin_technique forced[4] = {c->shadows, c->surface, c->displacement, c->translucent};
        ch = stin_query_choice(sd->ctx, features[k]);
        if (forced[k] != STIN_TECH_NONE && ch.technique != forced[k]) {
            snprintf(err, err_size, "%s: %s is '%s', not the forced '%s' (%s)",
                     stin_tier_name(tier), stin_feature_name(features[k]),
                     stin_technique_name(ch.technique), stin_technique_name(forced[k]), ch.reason);
            return 0;
        }
    }
    ch = stin_query_choice(sd->ctx, STIN_FEATURE_TRANSPARENCY);
    if (c->transparency != STIN_TECH_NONE && ch.technique != c->transparency) {
        snprintf(err, err_size, "%s: transparency is '%s', not the forced '%s' (%s)",
                 stin_tier_name(tier), stin_technique_name(ch.technique),
                 stin_technique_name(c->transparency), ch.reason);
        return 0;
    }
    if (!scene_gpu_create(&sd->gpu, s, sd->ctx, err, err_size))
        return 0;
    sd->made = 1;
    return 1;
}

/* A whole frame, glFinish included; negative on failure. */
static double full_frame(const setup *u, const side *sd)
{
    const bench_settings *b = u->st->b;
    double t0 = bench_now_ms();
    stin_result r = scene_gpu_frame(&sd->gpu, sd->ctx, b->width, b->height, STIN_OUTPUT_BEAUTY,
                                    stin_platform_framebuffer(b->plat));
    b->gl->Finish();
    return r == STIN_OK ? bench_now_ms() - t0 : -1.0;
}

/* The pair bench_abba alternates: side 0 the row's context, side 1 the baseline. */
typedef struct abba_pair {
    const setup *u;
    const side *on;
} abba_pair;

static double pair_frame(void *user, int which)
{
    const abba_pair *p = (const abba_pair *)user;
    return full_frame(p->u, which == 0 ? p->on : &p->u->base);
}

static int abba(const setup *u, const side *on, double *on_ms, double *base_ms, char *err,
                size_t err_size)
{
    abba_pair p;
    p.u = u;
    p.on = on;
    return bench_abba(u->st->frames, pair_frame, &p, "full frame ms (row/baseline)", u->st->b->verbose,
                      on_ms, base_ms, err, err_size);
}

static int is_map(stin_technique t)
{
    return t == STIN_TECH_SHADOWS_MAP_PCF || t == STIN_TECH_SHADOWS_MAP_DEPTH ||
           t == STIN_TECH_SHADOWS_MAP_COMBINE;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

#define STAGED_FRAMES 64

/* The row's GPU time per stage: a context of its configuration with
 * STIN_DEBUG_STAGE_TIMES (and its counted_flags), one warm-up frame, then
 * the settings' frames (at most STAGED_FRAMES), the median per stage.
 * Leaves row->staged 0 where the context has no timer queries; with
 * counted_flags the warm-up frame's primitives are the row's. */
static int staged_row(setup *u, tech_row *row, char *err, size_t err_size)
{
    static double ms[STIN_STAGE_COUNT][STAGED_FRAMES];
    tech_config cfg = row->cfg;
    side timed;
    char why[160];
    int k, i, n = u->st->frames < STAGED_FRAMES ? u->st->frames : STAGED_FRAMES, ok = 0;
    memset(&timed, 0, sizeof timed);
    cfg.debug_flags |= STIN_DEBUG_STAGE_TIMES | cfg.counted_flags;
    if (side_create(u, &timed, &cfg, &u->sc, why, sizeof why, err, err_size) <= 0)
        goto done;
    for (k = -1; k < n; k++) {
        stin_frame_stats fs;
        if (full_frame(u, &timed) < 0) {
            snprintf(err, err_size, "stin frame failed (stage times)");
            goto done;
        }
        fs = stin_query_frame_stats(timed.ctx);
        if (k < 0 && cfg.counted_flags)
            row->primitives = fs.shadows.vdsm_primitives;
        if (!fs.stage_times) {
            ok = 1; /* no timer queries: no stage column */
            goto done;
        }
        for (i = 0; k >= 0 && i < STIN_STAGE_COUNT; i++)
            ms[i][k] = fs.stage_ns[i] / 1e6;
    }
    for (i = 0; i < STIN_STAGE_COUNT; i++) {
        qsort(ms[i], (size_t)n, sizeof ms[i][0], by_value);
        row->stage_ms[i] = ms[i][n / 2];
    }
    row->staged = 1;
    ok = 1;
done:
    side_destroy(&timed);
    return ok;
}

static int one_row(setup *u, tech_row *row, int first, char *err, size_t err_size)
{
    const bench_settings *b = u->st->b;
    side on;
    stin_frame_stats fs;
    double on_ms, base_ms;
    unsigned errors_before = u->log.errors;
    int i, k, ok = 0, made;
    memset(&on, 0, sizeof on);
    for (i = 0; i < u->sc.light_count; i++) {
        u->lights[i] = u->s->lights[i];
        if (row->cfg.pcf_kernel)
            u->lights[i].pcf_kernel = row->cfg.pcf_kernel;
    }
    made = side_create(u, &on, &row->cfg, &u->sc, row->why, sizeof row->why, err, err_size);
    if (made < 0) {
        /* the forced technique's error line is the expected answer here */
        u->log.errors = errors_before;
        row->skipped = 1;
        return 1;
    }
    if (!made)
        goto done;
    for (k = 0; k < (b->warmup > 1 ? b->warmup : 1); k++)
        if (full_frame(u, &on) < 0 || full_frame(u, &u->base) < 0) {
            snprintf(err, err_size, "stin frame failed");
            goto done;
        }
    /* the last warm-up frame's statistics: the same every frame */
    fs = stin_query_frame_stats(on.ctx);
    if (is_map(row->cfg.shadows) && fs.shadows.map_size == 0) {
        snprintf(err, err_size, "the %s frame rendered no shadow map",
                 stin_technique_name(row->cfg.shadows));
        goto done;
    }
    if (!abba(u, &on, &on_ms, &base_ms, err, err_size))
        goto done;
    if (b->verbose)
        fprintf(stderr, "stin-bench: %s shadows %s %u (rendered %u) kernel %d surface %s: "
                "medians row %.2f baseline %.2f ms\n", stin_tier_name(u->st->tier),
                stin_technique_name(row->cfg.shadows), row->cfg.map_size, fs.shadows.map_size,
                row->cfg.pcf_kernel, stin_technique_name(row->cfg.surface), on_ms, base_ms);
    row->rendered = fs.shadows.map_size;
    row->passes = fs.passes;
    if (!row->cfg.counted_flags)
        row->primitives = fs.shadows.vdsm_primitives;
    row->peel_passes = fs.transparency.peel_passes;
    bench_keep_min(&row->on_ms, on_ms, first);
    bench_keep_min(&row->base_ms, base_ms, first);
    if (first && u->st->stages && !staged_row(u, row, err, err_size))
        goto done;
    ok = 1;
done:
    side_destroy(&on);
    return ok;
}

static int one_setup(const tech_settings *st, const scene *s, int first, tech_row *rows,
                     int row_n, char *err, size_t err_size)
{
    const bench_settings *b = st->b;
    setup *u = calloc(1, sizeof *u);
    char why[160];
    int i, ok = 0, made;
    GLenum e;
    if (!u) {
        snprintf(err, err_size, "out of memory");
        return 0;
    }
    u->st = st;
    u->s = s;
    u->sc = *s;
    u->lights = calloc((size_t)s->light_count + 1, sizeof *u->lights);
    if (!u->lights) {
        snprintf(err, err_size, "out of memory");
        goto done;
    }
    u->sc.lights = u->lights;
    u->log.program = "stin-bench";
    u->log.verbose = b->verbose;
    made = side_create(u, &u->base, &st->base, s, why, sizeof why, err, err_size);
    if (made < 0)
        snprintf(err, err_size, "%s, baseline: %s", stin_tier_name(st->tier), why);
    if (made <= 0)
        goto done;
    for (i = 0; i < row_n; i++) {
        if (rows[i].skipped)
            continue; /* known from the first set-up */
        if (!one_row(u, &rows[i], first, err, err_size))
            goto done;
        if (!first && rows[i].skipped) {
            snprintf(err, err_size, "%s / %s ran in one set-up and not in another",
                     stin_technique_name(rows[i].cfg.shadows),
                     stin_technique_name(rows[i].cfg.surface));
            goto done;
        }
    }
    if ((e = b->gl->GetError()) != 0) {
        snprintf(err, err_size, "GL error 0x%x during the frames", e);
        goto done;
    }
    if (u->log.errors) {
        snprintf(err, err_size, "stin logged %u error(s)", u->log.errors);
        goto done;
    }
    ok = 1;
done:
    side_destroy(&u->base);
    free(u->lights);
    free(u);
    return ok;
}

int bench_tech_run(const tech_settings *st, const scene *s, tech_row *rows, int row_n,
                   char *err, size_t err_size)
{
    int i, j;
    for (i = 0; i < row_n; i++) {
        rows[i].rendered = rows[i].passes = rows[i].primitives = 0;
        rows[i].base_ms = rows[i].on_ms = 0.0;
        rows[i].skipped = rows[i].staged = 0;
        rows[i].why[0] = 0;
        if (rows[i].cfg.pcf_kernel != 0 && rows[i].cfg.pcf_kernel != 1 &&
            rows[i].cfg.pcf_kernel != 3 && rows[i].cfg.pcf_kernel != 5) {
            snprintf(err, err_size, "PCF kernels are 1, 3 or 5");
            return 0;
        }
    }
    if (row_n < 1 || row_n > TECH_MAX_ROWS) {
        snprintf(err, err_size, "1..%d rows", TECH_MAX_ROWS);
        return 0;
    }
    for (j = 0; j < st->setups; j++)
        if (!one_setup(st, s, j == 0, rows, row_n, err, err_size))
            return 0;
    return 1;
}
