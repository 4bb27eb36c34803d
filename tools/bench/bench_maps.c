/* SPDX-License-Identifier: MIT */
/* The shadow-map section of stin-bench.
 *
 * GL1 tier only (the map techniques are fixed-function). Per set-up one stin
 * context with desc.techniques[STIN_FEATURE_SHADOWS] = off is created on the
 * one GL context and kept for the set-up; then per row a second one, forced to
 * the row's technique (map-depth or map-combine with desc.shadows.map_size set
 * to the row's size, or volume), each with its own copy of the scene's meshes.
 * Both draw the scene as it is (its own lights) through scene_gpu_frame:
 * warm-up, then whole frames (glFinish included) in ABBA order, shadowed
 * first. The shadowed context's frame statistics give the map size actually
 * rendered (stin may render less than asked: the texture-size limit, or the
 * viewport when there is no FBO). Per side and row the lowest set-up median
 * is kept, as in bench_run.c and bench_shadow.c. */
#include "bench_maps.h"
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
    const maps_settings *st;
    const scene *s;
    side off;
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

/* 1 made; 0 failed (err); -1 the context cannot run the technique (why). */
static int side_create(setup *u, side *sd, stin_technique shadows, uint32_t map_size,
                       char *why, size_t why_size, char *err, size_t err_size)
{
    const bench_settings *b = u->st->b;
    stin_desc desc;
    size_t bytes;
    stin_result r;
    stin_choice ch;
    bench_desc_init(b, &desc);
    desc.log = cli_log_fn;
    desc.log_user = &u->log;
    desc.tier = STIN_TIER_GL1;
    desc.caps_mask |= u->st->caps_mask;
    desc.techniques[STIN_FEATURE_SHADOWS] = shadows;
    desc.shadows.map_size = map_size;
    scene_gpu_size_desc(u->s, &desc);
    bytes = stin_memory_size(&desc);
    if (!bytes) {
        snprintf(err, err_size, "stin_memory_size: bad desc (shadows %s, map size %u)",
                 stin_technique_name(shadows), map_size);
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
        snprintf(err, err_size, "stin_create (gl1, shadows %s): %s", stin_technique_name(shadows),
                 stin_result_name(r));
        free(sd->block);
        sd->block = NULL;
        return 0;
    }
    ch = stin_query_choice(sd->ctx, STIN_FEATURE_SHADOWS);
    if (ch.technique != shadows) {
        snprintf(err, err_size, "gl1: shadows are '%s', not the forced '%s' (%s)",
                 stin_technique_name(ch.technique), stin_technique_name(shadows), ch.reason);
        return 0;
    }
    if (!scene_gpu_create(&sd->gpu, u->s, sd->ctx, err, err_size))
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
    return full_frame(p->u, which == 0 ? p->on : &p->u->off);
}

static int abba(const setup *u, const side *on, double *on_ms, double *off_ms, char *err,
                size_t err_size)
{
    abba_pair p;
    p.u = u;
    p.on = on;
    return bench_abba(u->st->frames, pair_frame, &p, "full frame ms (shadowed/off)", u->st->b->verbose,
                      on_ms, off_ms, err, err_size);
}

/* The rows in order: map-depth per size, map-combine per size, volume. */
static int plan_rows(const maps_settings *st, maps_row *rows)
{
    static const stin_technique maps[2] = {STIN_TECH_SHADOWS_MAP_DEPTH,
                                           STIN_TECH_SHADOWS_MAP_COMBINE};
    int n = 0, p, i;
    for (p = 0; p < 2; p++)
        for (i = 0; i < st->size_n; i++) {
            rows[n].technique = maps[p];
            rows[n].requested = (uint32_t)st->sizes[i];
            n++;
        }
    rows[n].technique = STIN_TECH_SHADOWS_VOLUME;
    rows[n].requested = 0;
    return n + 1;
}

static int one_row(setup *u, maps_row *row, int first, char *err, size_t err_size)
{
    const bench_settings *b = u->st->b;
    side on;
    stin_frame_stats fs;
    double on_ms, off_ms;
    unsigned errors_before = u->log.errors;
    int k, ok = 0, made;
    memset(&on, 0, sizeof on);
    made = side_create(u, &on, row->technique, row->requested, row->why, sizeof row->why, err,
                       err_size);
    if (made < 0) {
        /* the forced technique's error line is the expected answer here */
        u->log.errors = errors_before;
        row->skipped = 1;
        return 1;
    }
    if (!made)
        goto done;
    for (k = 0; k < (b->warmup > 1 ? b->warmup : 1); k++)
        if (full_frame(u, &on) < 0 || full_frame(u, &u->off) < 0) {
            snprintf(err, err_size, "stin frame failed");
            goto done;
        }
    /* the last warm-up frame's statistics: the same every frame */
    fs = stin_query_frame_stats(on.ctx);
    if (row->technique == STIN_TECH_SHADOWS_VOLUME ? fs.shadows.volume_triangles == 0
                                                   : fs.shadows.map_size == 0) {
        snprintf(err, err_size, "the %s frame rendered no %s", stin_technique_name(row->technique),
                 row->technique == STIN_TECH_SHADOWS_VOLUME ? "volume triangles" : "shadow map");
        goto done;
    }
    if (!abba(u, &on, &on_ms, &off_ms, err, err_size))
        goto done;
    if (b->verbose)
        fprintf(stderr, "stin-bench: maps %s %u (rendered %u): medians shadowed %.2f off %.2f ms\n",
                stin_technique_name(row->technique), row->requested, fs.shadows.map_size, on_ms,
                off_ms);
    row->rendered = fs.shadows.map_size;
    row->passes = fs.passes;
    row->volume_triangles = fs.shadows.volume_triangles;
    bench_keep_min(&row->on_ms, on_ms, first);
    bench_keep_min(&row->off_ms, off_ms, first);
    ok = 1;
done:
    side_destroy(&on);
    return ok;
}

static int one_setup(const maps_settings *st, const scene *s, int first, maps_row *rows,
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
    u->log.program = "stin-bench";
    u->log.verbose = b->verbose;
    made = side_create(u, &u->off, STIN_TECH_SHADOWS_OFF, 0, why, sizeof why, err, err_size);
    if (made < 0)
        snprintf(err, err_size, "gl1, shadows off: %s", why);
    if (made <= 0)
        goto done;
    for (i = 0; i < row_n; i++) {
        if (rows[i].skipped)
            continue; /* known from the first set-up */
        if (!one_row(u, &rows[i], first, err, err_size))
            goto done;
        if (!first && rows[i].skipped) {
            snprintf(err, err_size, "%s ran in one set-up and not in another",
                     stin_technique_name(rows[i].technique));
            goto done;
        }
    }
    if ((e = b->gl->GetError()) != 0) {
        snprintf(err, err_size, "GL error 0x%x during the shadow-map frames", e);
        goto done;
    }
    if (u->log.errors) {
        snprintf(err, err_size, "stin logged %u error(s)", u->log.errors);
        goto done;
    }
    ok = 1;
done:
    side_destroy(&u->off);
    free(u);
    return ok;
}

int bench_maps_run(const maps_settings *st, const scene *s, maps_row *rows, int *row_n,
                   char *err, size_t err_size)
{
    int i, j, has_map_light = 0;
    *row_n = 0;
    memset(rows, 0, MAPS_MAX_ROWS * sizeof *rows);
    for (i = 0; i < s->light_count; i++)
        if (s->lights[i].type == SCENE_LIGHT_SPOT || s->lights[i].type == SCENE_LIGHT_DIRECTIONAL)
            has_map_light = 1;
    if (!has_map_light) {
        snprintf(err, err_size,
                 "%s: no spot or directional light (every map path and size needs one)",
                 s->path);
        return 0;
    }
    if (st->size_n < 1 || st->size_n > MAPS_MAX_SIZES) {
        snprintf(err, err_size, "1..%d map sizes", MAPS_MAX_SIZES);
        return 0;
    }
    *row_n = plan_rows(st, rows);
    for (j = 0; j < st->setups; j++)
        if (!one_setup(st, s, j == 0, rows, *row_n, err, err_size))
            return 0;
    return 1;
}
