/* SPDX-License-Identifier: MIT */
/* The VDSM section (gl4): per --scenes scene the seed's optimisation chain
 * one step set a row - SP alone, + EP, + SM, + DC, + DT (the shadow faces
 * depth-tested against the visible surface: the full chain, its steps in
 * a culling pass of their own), the full chain in one geometry shader
 * (STIN_DEBUG_VDSM_ONE_PASS) - and
 * stencil volumes, each timed against shadows off. The vdsm rows count the
 * primitives their geometry shader emits (STIN_DEBUG_VDSM_COUNT, the seed's
 * P_c) in their stage-times context, so its waits for the GPU stay out of
 * the timed frames. --vdsm-goal runs only the full chain and the volumes
 * (a scene in a minute, not in several). Where the
 * context has timer queries each row's shadow work is timed on the GPU too
 * (STIN_DEBUG_STAGE_TIMES, a context of its own: the prepass and shadow
 * stages - vdsm's position buffer, facing pass, pyramid and polygons; the
 * volumes' stencil counts - without the lit passes and the rest). */
#include "bench_options.h"
#include "bench_report.h"

#include <stdio.h>
#include <string.h>

#define WHAT "VDSM"
#define COUNT STIN_DEBUG_VDSM_COUNT
#define NO_DT STIN_DEBUG_VDSM_NO_DEPTH_TEST

static const struct step_set {
    const char *name;
    stin_technique shadows;
    uint64_t flags;
    int goal; /* one of the two rows the 1.5x goal compares (--vdsm-goal) */
} sets[] = {
    {"SP", STIN_TECH_SHADOWS_VDSM,
     NO_DT | STIN_DEBUG_VDSM_NO_EP | STIN_DEBUG_VDSM_NO_SM | STIN_DEBUG_VDSM_NO_DC, 0},
    {"SP+EP", STIN_TECH_SHADOWS_VDSM,
     NO_DT | STIN_DEBUG_VDSM_NO_SM | STIN_DEBUG_VDSM_NO_DC, 0},
    {"SP+EP+SM", STIN_TECH_SHADOWS_VDSM, NO_DT | STIN_DEBUG_VDSM_NO_DC, 0},
    {"SP+EP+SM+DC", STIN_TECH_SHADOWS_VDSM, NO_DT, 0},
    {"SP+EP+SM+DC+DT", STIN_TECH_SHADOWS_VDSM, 0, 1},
    {"the same in one pass", STIN_TECH_SHADOWS_VDSM, STIN_DEBUG_VDSM_ONE_PASS, 0},
    {"volume", STIN_TECH_SHADOWS_VOLUME, 0, 1},
};
enum { N = sizeof sets / sizeof sets[0], SP = 0, VOLUME = N - 1 };

/* The row's shadow work on the GPU (ms): its prepass and shadow stages. */
static double shadow_work(const tech_row *r)
{
    return r->staged ? r->stage_ms[STIN_STAGE_PREPASS] + r->stage_ms[STIN_STAGE_SHADOW] : 0.0;
}

/* A ratio's cell: empty where the row it divides by did not run (not
 * asked, or skipped). */
static void ratio_cell(double of, const tech_row *by, int by_ran, double by_value,
                       const char *fmt)
{
    if (!by_ran || by->skipped || by_value <= 0)
        printf(" |");
    else
        printf(fmt, of / by_value);
}

static void print_scene(const char *label, const tech_row *rows, const int *ran)
{
    const tech_row *sp = &rows[SP], *vol = &rows[VOLUME];
    int i;
    printf("\n### " WHAT ", %s\n\n", label);
    printf("| step set | P_c | P_c / SP | off median ms | median ms | / off | / SP | "
           "/ volume | shadow GPU ms | / volume's |\n");
    printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (i = 0; i < N; i++) {
        const tech_row *r = &rows[i];
        if (!ran[i])
            continue; /* not asked (--vdsm-goal) */
        if (r->skipped) {
            printf("| %s | SKIP: %s | | | | | | | | |\n", sets[i].name, r->why);
            continue;
        }
        if (i == VOLUME) {
            printf("| %s | | |", sets[i].name);
        } else {
            printf("| %s | %u |", sets[i].name, r->primitives);
            ratio_cell(r->primitives, sp, ran[SP], sp->primitives, " %.3f |");
        }
        printf(" %.2f | %.2f | %.2f |", r->base_ms, r->on_ms, tech_ratio(r));
        ratio_cell(r->on_ms, sp, ran[SP], sp->on_ms, " %.2f |");
        ratio_cell(r->on_ms, vol, ran[VOLUME], vol->on_ms, " %.2f |");
        if (r->staged) {
            printf(" %.3f |", shadow_work(r));
            ratio_cell(shadow_work(r), vol, ran[VOLUME], shadow_work(vol), " %.2f |");
            printf("\n");
        } else {
            printf(" not timed | |\n");
        }
    }
    fflush(stdout);
}

int section_vdsm(bench_env *env, const scene *s, int *ran)
{
    tech_row rows[N], asked[N];
    int pick[N], asked_set[N], n = 0;
    stin_tier tier;
    tech_settings st;
    char label[128], timing[160];
    int i, k, rc = 0;
    (void)s;
    bench_tech_settings(env, SEC_VDSM, &st);
    st.stages = 1;
    printf("\n## VDSM step sets (gl4) against shadows off, SP alone and stencil volumes, "
           "%dx%d, the scenes' lights; %s\n", env->b.width, env->b.height,
           bench_row_timing(env, st.setups, st.frames, timing, sizeof timing));
    if (!bench_tiers(env, TIER_BIT(STIN_TIER_GL4), WHAT, "gl4 only", &tier))
        return 0;
    for (k = 0; k < N; k++) {
        asked_set[k] = !env->o->vdsm_goal || sets[k].goal;
        if (asked_set[k])
            pick[n++] = k;
    }
    for (i = 0; i < env->o->scene_count; i++) {
        memset(asked, 0, sizeof asked);
        for (k = 0; k < n; k++) {
            const struct step_set *set = &sets[pick[k]];
            asked[k].cfg.shadows = set->shadows;
            asked[k].cfg.surface = STIN_TECH_NONE;
            asked[k].cfg.debug_flags = set->flags;
            asked[k].cfg.counted_flags = set->shadows == STIN_TECH_SHADOWS_VDSM ? COUNT : 0;
        }
        scene_label(env->o->scenes[i], label, sizeof label);
        if (!bench_tech_tier(env, &st, tier, WHAT, &env->scenes[i], asked, n, &rc))
            return rc;
        *ran = 1;
        memset(rows, 0, sizeof rows);
        for (k = 0; k < n; k++)
            rows[pick[k]] = asked[k];
        print_scene(label, rows, asked_set);
    }
    return 0;
}
