/* SPDX-License-Identifier: MIT */
/* The shadow-volume section: per tier the shadowed frame against shadows
 * off per scene and light count, then what building the volumes costs on
 * the CPU (stin_end_frame at a tiny viewport). */
#include "bench_options.h"
#include "bench_report.h"
#include "bench_shadow.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct shadow_table {
    stin_tier tiers[3];
    int tier_n;
    shadow_row rows[3][MAX_SCENES][SHADOW_MAX_COUNTS]; /* tier index, scene, count */
    uint64_t triangles[MAX_SCENES];
    int ran[3];
    double worst, best;
    char worst_at[160], best_at[160];
} shadow_table;

/* The best and worst ratio so far, with where. */
/* A row's volume triangles, or that a geometry shader extruded them (not counted). */
static const char *volume_count(const shadow_row *r, char *out, size_t size)
{
    if (r->gpu_casters)
        snprintf(out, size, "GS-extruded");
    else
        snprintf(out, size, "%u", r->volume_triangles);
    return out;
}

static void keep_extremes(shadow_table *t, double ratio, const char *at)
{
    if (ratio > t->worst || !t->worst_at[0]) {
        t->worst = ratio;
        snprintf(t->worst_at, sizeof t->worst_at, "%s", at);
    }
    if (ratio < t->best || !t->best_at[0]) {
        t->best = ratio;
        snprintf(t->best_at, sizeof t->best_at, "%s", at);
    }
}

static int shadow_tier(const bench_env *env, const shadow_settings *st, int ti, shadow_table *t)
{
    stin_tier tier = t->tiers[ti];
    int i, c;
    printf("\n### shadows, %s (%s)\n\n", stin_tier_name(tier), tier_label(tier));
    printf("| scene | lights | volume triangles / frame | z-pass / z-fail casters | "
           "off median ms | volume median ms | volume / off |\n");
    printf("|---|---:|---:|---:|---:|---:|---:|\n");
    fflush(stdout);
    for (i = 0; i < env->o->scene_count; i++) {
        char err[1024], label[128], at[160];
        shadow_row *rows = t->rows[ti][i];
        scene_label(env->o->scenes[i], label, sizeof label);
        fprintf(stderr, "stin-bench: shadows %s %s ...\n", stin_tier_name(tier), label);
        if (!bench_shadow_run(st, tier, &env->scenes[i], rows, err, sizeof err)) {
            fprintf(stderr, "stin-bench: shadows, %s, %s: %s\n", stin_tier_name(tier), label,
                    err);
            return 0;
        }
        t->triangles[i] = scene_triangle_count(&env->scenes[i]);
        for (c = 0; c < st->count_n; c++) {
            const shadow_row *r = &rows[c];
            double ratio = r->off_ms > 0 ? r->vol_ms / r->off_ms : 0.0;
            snprintf(at, sizeof at, "%s %s, %d light(s)", stin_tier_name(tier), label,
                     r->lights);
            keep_extremes(t, ratio, at);
            char count[24];
            printf("| %s | %d | %s | %u / %u | %.2f | %.2f | %.2f |\n", label, r->lights,
                   volume_count(r, count, sizeof count), r->zpass_casters, r->zfail_casters,
                   r->off_ms, r->vol_ms, ratio);
        }
        fflush(stdout);
    }
    t->ran[ti] = 1;
    return 1;
}

/* The CPU estimate of volume building, one row per tier, scene and count. */
static void shadow_cpu_table(const bench_env *env, const shadow_settings *st,
                             const shadow_table *t)
{
    int ti, i, c;
    printf("\n### shadows: stin_end_frame at %dx%d (volume building on the CPU)\n\n", st->small_w,
           st->small_h);
    printf("| tier | scene | lights | volume triangles / frame | end_frame off / volume ms | "
           "difference ms | outside GL draws off / volume ms | difference ms | "
           "ns per scene triangle and light | ns per volume triangle |\n");
    printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (ti = 0; ti < t->tier_n; ti++) {
        if (!t->ran[ti])
            continue;
        for (i = 0; i < env->o->scene_count; i++) {
            char label[128];
            scene_label(env->o->scenes[i], label, sizeof label);
            for (c = 0; c < st->count_n; c++) {
                const shadow_row *r = &t->rows[ti][i][c];
                double cpu = r->vol_cpu_ms - r->off_cpu_ms;
                double per_tri = t->triangles[i] ? 1e6 * cpu / ((double)t->triangles[i] *
                                                                (double)r->lights) : 0.0;
                char per_vol[24] = "-", count[24];
                if (r->volume_triangles)
                    snprintf(per_vol, sizeof per_vol, "%.1f",
                             1e6 * cpu / (double)r->volume_triangles);
                printf("| %s | %s | %d | %s | %.3f / %.3f | %.3f | %.3f / %.3f | %.3f | %.2f | "
                       "%s |\n", stin_tier_name(t->tiers[ti]), label, r->lights,
                       volume_count(r, count, sizeof count), r->off_end_ms, r->vol_end_ms,
                       r->vol_end_ms - r->off_end_ms, r->off_cpu_ms, r->vol_cpu_ms, cpu, per_tri,
                       per_vol);
            }
        }
    }
    fflush(stdout);
}

static void settings(const bench_env *env, shadow_settings *st, char *counts, size_t size)
{
    const options *o = env->o;
    int i;
    memset(st, 0, sizeof *st);
    st->b = &env->b;
    st->frames = o->sec[SEC_SHADOWS].frames;
    st->setups = o->sec[SEC_SHADOWS].setups;
    st->small_w = 64;
    st->small_h = 36;
    st->small_frames = o->small_frames;
    st->cpu_volumes = o->cpu_volumes;
    st->count_n = o->light_counts.n;
    counts[0] = '\0';
    for (i = 0; i < st->count_n; i++) {
        size_t len = strlen(counts);
        st->light_counts[i] = o->light_counts.v[i];
        snprintf(counts + len, size - len, "%s%d", i ? ", " : "", st->light_counts[i]);
    }
}

int section_shadows(bench_env *env, const scene *s, int *ran)
{
    const bench_settings *b = &env->b;
    shadow_settings st;
    shadow_table *t = calloc(1, sizeof *t);
    char counts[64];
    int i, rc = 0;
    (void)s;
    if (!t) {
        fprintf(stderr, "stin-bench: out of memory\n");
        return EXIT_FAILED;
    }
    settings(env, &st, counts, sizeof counts);
    printf("\n## Shadow volumes: %dx%d, %s point light(s); per side the lowest of %d set-ups' "
           "median of %d frames (ABBA-interleaved, glFinish per frame, %d warm-up, 1 per later "
           "light count); stin_end_frame alone at %dx%d: %d frames\n",
           b->width, b->height, counts, st.setups, st.frames, b->warmup > 1 ? b->warmup : 1,
           st.small_w, st.small_h, st.small_frames);
    t->tier_n = bench_tiers(env, ALL_TIERS, "shadows", "", t->tiers);
    for (i = 0; i < t->tier_n && rc == 0; i++) {
        if (!bench_tier_ok(env, t->tiers[i], "shadows", &rc))
            continue;
        if (!(env->caps->present & STIN_CAP_BIT(STIN_CAP_STENCIL))) {
            printf("\n### shadows, %s: SKIP (no stencil buffer)\n", stin_tier_name(t->tiers[i]));
            continue;
        }
        if (!shadow_tier(env, &st, i, t))
            rc = EXIT_FAILED;
        else
            *ran = 1;
    }
    if (rc == 0 && *ran) {
        shadow_cpu_table(env, &st, t);
        printf("\nshadow volumes / shadows off: from %.2f (%s) to %.2f (%s)\n", t->best,
               t->best_at, t->worst, t->worst_at);
    }
    free(t);
    return rc;
}
