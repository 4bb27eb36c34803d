/* SPDX-License-Identifier: MIT */
/* The deep section: translucent shadows' cost, each row timed against
 * shadows off on the same scene.
 *   layers     (gl2, gl4; --deep-scene, a spot light over stacked panes)
 *              map-pcf of --deep-size with the panes cast solid, then
 *              the same map with deep maps of that size a face and 1, 2, 4
 *              layers (gl4), and with coloured maps (gl2, gl4);
 *   early stop (gl4; a point light, --deep-one with transparency in one
 *              cube face, --deep-all in all six) deep with 4 layers: early
 *              stop by the storage flag where GL 4.3 has it, by the
 *              occlusion query, and none; and coloured - the seed's graph.
 * The goal lines (each row's time over its shadows-off frames, one row over
 * another): one-layer deep at most 2x the plain map of the same size; the
 * early stop at least 2x faster when transparency sits in one face, on the
 * whole frame and on the deep maps' own GPU time (the translucent stage of
 * STIN_DEBUG_STAGE_TIMES, where the context has timer queries). */
#include "bench_options.h"
#include "bench_report.h"

#include <stdio.h>
#include <string.h>

#define WHAT "deep shadow maps"
#define MAP STIN_TECH_SHADOWS_MAP_PCF
#define SOLID STIN_TECH_TRANSLUCENT_SOLID
#define DEEP STIN_TECH_TRANSLUCENT_DEEP
#define COLOURED STIN_TECH_TRANSLUCENT_COLOURED

typedef struct deep_row {
    const char *name;
    stin_technique translucent;
    uint32_t layers;
    uint64_t flags;
    int gl4_only;
} deep_row;

static const deep_row layer_rows[] = {
    {"map-pcf, panes solid", SOLID, 0, 0, 0},
    {"deep, 1 layer", DEEP, 1, 0, 1},
    {"deep, 2 layers", DEEP, 2, 0, 1},
    {"deep, 4 layers", DEEP, 4, 0, 1},
    {"coloured", COLOURED, 0, 0, 0},
};
enum { LAYER_ROWS = sizeof layer_rows / sizeof layer_rows[0] };

static const deep_row stop_rows[] = {
    {"deep 4, early stop (storage flag on GL 4.3)", DEEP, 4, 0, 1},
    {"deep 4, early stop by occlusion query", DEEP, 4, STIN_DEBUG_DEEP_QUERY_STOP, 1},
    {"deep 4, no early stop", DEEP, 4, STIN_DEBUG_DEEP_NO_EARLY_STOP, 1},
    {"coloured", COLOURED, 0, 0, 1},
};
enum { STOP_ROWS = sizeof stop_rows / sizeof stop_rows[0], STOP = 0, NO_STOP = 2 };

/* One table of defs on s (gl4-only rows left out below gl4), measured into
 * rows. Returns the count, 0 when the tier was skipped or failed. */
static int run_table(bench_env *env, tech_settings *st, stin_tier tier, const char *title,
                     const scene *s, const deep_row *defs, int n, tech_row *rows, int *rc)
{
    const char *names[TECH_MAX_ROWS];
    uint32_t size = (uint32_t)env->o->deep_size;
    int i, m = 0;
    memset(rows, 0, sizeof *rows * (size_t)n);
    for (i = 0; i < n; i++) {
        if (defs[i].gl4_only && tier != STIN_TIER_GL4)
            continue;
        names[m] = defs[i].name;
        rows[m].cfg.shadows = MAP;
        rows[m].cfg.surface = STIN_TECH_NONE;
        rows[m].cfg.map_size = size;
        rows[m].cfg.translucent = defs[i].translucent;
        rows[m].cfg.deep_layers = defs[i].layers;
        rows[m].cfg.deep_map_size = size;
        rows[m].cfg.debug_flags = defs[i].flags;
        m++;
    }
    if (!m || !bench_tech_tier(env, st, tier, WHAT, s, rows, m, rc))
        return 0;
    bench_ratio_table(title, tier, "off", names, rows, m);
    return m;
}

/* Row a over row b, each as its time over its own interleaved shadows-off
 * frames (rows run minutes apart on a shared machine: their off times
 * drift, their ratios to off do not). */
static double ratio(const tech_row *a, const tech_row *b)
{
    return !a->skipped && !b->skipped && tech_ratio(b) > 0 ? tech_ratio(a) / tech_ratio(b) : 0.0;
}

/* Each row's GPU time per stage (medians, ms), and the translucent
 * stage's no-stop / stop ratio (0 where a row has no stage times). */
static double stage_table(const char *title, const deep_row *defs, const tech_row *rows, int n)
{
    int i, k;
    printf("\n### %s: GPU time per stage (median ms, STIN_DEBUG_STAGE_TIMES)\n\n| row |", title);
    for (k = 0; k < STIN_STAGE_COUNT; k++)
        printf(" %s |", stin_stage_name((stin_stage)k));
    printf("\n|---|");
    for (k = 0; k < STIN_STAGE_COUNT; k++)
        printf("---:|");
    printf("\n");
    for (i = 0; i < n; i++) {
        if (!rows[i].staged) {
            printf("| %s | not timed (no timer queries, or skipped) |\n", defs[i].name);
            continue;
        }
        printf("| %s |", defs[i].name);
        for (k = 0; k < STIN_STAGE_COUNT; k++)
            printf(" %.3f |", rows[i].stage_ms[k]);
        printf("\n");
    }
    fflush(stdout);
    return rows[NO_STOP].staged && rows[STOP].staged && rows[STOP].stage_ms[STIN_STAGE_TRANSLUCENT] > 0
               ? rows[NO_STOP].stage_ms[STIN_STAGE_TRANSLUCENT] /
                     rows[STOP].stage_ms[STIN_STAGE_TRANSLUCENT]
               : 0.0;
}

/* The early-stop table on one point-light scene; its no-stop / stop ratio
 * of frames, and in *maps of the deep maps' GPU time. */
static double stop_table(bench_env *env, tech_settings *st, const char *path, double *maps,
                         int *rc)
{
    tech_row rows[STOP_ROWS];
    scene s;
    char err[512], label[128], title[192];
    double r = 0.0;
    if (!scene_load(path, &s, err, sizeof err)) {
        fprintf(stderr, "stin-bench: %s: %s\n", path, err);
        *rc = EXIT_BAD_INPUT;
        return 0.0;
    }
    scene_label(path, label, sizeof label);
    snprintf(title, sizeof title, "early stop, %s (point light, 4 layers, %d a face)", label,
             env->o->deep_size);
    *maps = 0.0;
    st->stages = 1;
    if (run_table(env, st, STIN_TIER_GL4, title, &s, stop_rows, STOP_ROWS, rows, rc) ==
        STOP_ROWS) {
        r = ratio(&rows[NO_STOP], &rows[STOP]);
        *maps = stage_table(title, stop_rows, rows, STOP_ROWS);
    }
    st->stages = 0;
    scene_free(&s);
    return r;
}

int section_deep(bench_env *env, const scene *s, int *ran)
{
    tech_row rows[LAYER_ROWS];
    stin_tier tiers[2];
    tech_settings st;
    char timing[160];
    int tier_n, t, rc = 0;
    double one_layer = 0.0, one_face, all_faces, one_face_maps, all_faces_maps = 0.0;
    bench_tech_settings(env, SEC_DEEP, &st);
    st.base.translucent = SOLID; /* shadows off: nothing for deep to shadow */
    printf("\n## Translucent shadows (deep, coloured) against shadows off, %dx%d; %s\n",
           env->b.width, env->b.height,
           bench_row_timing(env, st.setups, st.frames, timing, sizeof timing));
    tier_n = bench_tiers(env, GLSL_TIERS, WHAT, "gl2 and gl4 only", tiers);
    for (t = 0; t < tier_n && !rc; t++) {
        int n = run_table(env, &st, tiers[t], "map-pcf, deep layers and coloured", s, layer_rows,
                          LAYER_ROWS, rows, &rc);
        if (!n)
            continue;
        *ran = 1;
        if (tiers[t] == STIN_TIER_GL4 && n == LAYER_ROWS)
            one_layer = ratio(&rows[1], &rows[0]);
    }
    if (rc || !bench_tier_ok(env, STIN_TIER_GL4, WHAT, &rc) ||
        !bench_tiers(env, TIER_BIT(STIN_TIER_GL4), WHAT, "gl4 only", tiers))
        return rc;
    one_face = stop_table(env, &st, env->o->deep_one, &one_face_maps, &rc);
    all_faces = rc ? 0.0 : stop_table(env, &st, env->o->deep_all, &all_faces_maps, &rc);
    if (one_layer > 0.0)
        printf("\ndeep goal: one-layer deep / map-pcf of the same size %.2f, each over shadows off "
               "(goal <= 2: %s)\n",
               one_layer, one_layer <= 2.0 ? "met" : "missed");
    if (one_face > 0.0)
        printf("deep goal: no early stop / early stop %.2f with transparency in one face "
               "(goal >= 2: %s), %.2f in all six\n", one_face, one_face >= 2.0 ? "met" : "missed",
               all_faces);
    if (one_face_maps > 0.0)
        printf("deep goal, the deep maps' GPU time (translucent stage): no early stop / early "
               "stop %.2f with transparency in one face (goal >= 2: %s), %.2f in all six\n",
               one_face_maps, one_face_maps >= 2.0 ? "met" : "missed", all_faces_maps);
    return rc;
}
