/* SPDX-License-Identifier: MIT */
/* The camera transparency section (gl2, gl4; shadows off, so the layers'
 * cost is the peel's own): on the panes scene with 0, 2 and 4 transparent
 * layers on screen (its opaque objects and that many copies of its first
 * pane stacked 0.3 apart), depth-peel's and dual-peel's (gl4) passes and
 * frame times against sorted's; on gl4 then the same layers shadowed, vdsm
 * against volume. */
#include "bench_options.h"
#include "bench_report.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WHAT "camera transparency"
#define LAYER_CASES 3
#define PEELS 2 /* depth-peel, dual-peel */

static int blended(const scene *s, const scene_object *o)
{
    return s->materials[o->material].color[3] < 1.0f;
}

/* A copy of s with its opaque objects and `panes` copies of its first
 * transparent one, each 0.3 above the one before; objects freed by the
 * caller. 0 when s has no transparent object or memory ran out. */
static int with_panes(const scene *s, int panes, scene *out)
{
    int i, n = 0, first = -1;
    *out = *s;
    out->objects = malloc(sizeof *out->objects * (size_t)(s->object_count + panes));
    if (!out->objects)
        return 0;
    for (i = 0; i < s->object_count; i++) {
        if (!blended(s, &s->objects[i]))
            out->objects[n++] = s->objects[i];
        else if (first < 0)
            first = i;
    }
    for (i = 0; i < panes && first >= 0; i++) {
        out->objects[n] = s->objects[first];
        out->objects[n].transform[13] += 0.3f * (float)i; /* column-major: the y translation */
        n++;
    }
    out->object_count = n;
    return first >= 0;
}

/* gl4: the layers shadowed, vdsm (its position buffer made again per
 * layer) against volumes, and vdsm with the layers unshadowed
 * (STIN_DEBUG_PEEL_VDSM_UNSHADOWED): the last two differ by what the
 * per-layer masks cost. */
static int shadowed_layers(bench_env *env, const scene *s, const tech_settings *section, int *rc)
{
    static const int layers[LAYER_CASES] = {0, 2, 4};
    tech_settings st = *section;
    int i, ok = 1;
    st.base.shadows = STIN_TECH_SHADOWS_VOLUME;
    st.base.transparency = STIN_TECH_TRANSPARENCY_DEPTH_PEEL;
    printf("\n### gl4, depth-peel with shadows: vdsm against volume\n\n"
           "| layers on screen | volume median ms | vdsm median ms | vdsm / volume "
           "| vdsm, layers unshadowed, median ms | vdsm layer masks ms |\n"
           "|---:|---:|---:|---:|---:|---:|\n");
    for (i = 0; i < LAYER_CASES && ok && !*rc; i++) {
        tech_row rows[2];
        scene copy;
        memset(rows, 0, sizeof rows);
        rows[0].cfg = st.base;
        rows[0].cfg.shadows = STIN_TECH_SHADOWS_VDSM;
        rows[1].cfg = rows[0].cfg;
        rows[1].cfg.debug_flags |= STIN_DEBUG_PEEL_VDSM_UNSHADOWED;
        if (!with_panes(s, layers[i], &copy)) {
            free(copy.objects);
            return 0; /* said by the first table */
        }
        ok = bench_tech_tier(env, &st, STIN_TIER_GL4, WHAT, &copy, rows, 2, rc);
        free(copy.objects);
        if (!ok)
            break;
        if (rows[0].skipped || rows[1].skipped)
            printf("| %d | SKIP: %s | | | | |\n", layers[i],
                   rows[0].skipped ? rows[0].why : rows[1].why);
        else
            printf("| %d | %.2f | %.2f | %.2f | %.2f | %.2f |\n", layers[i], rows[0].base_ms,
                   rows[0].on_ms, tech_ratio(&rows[0]), rows[1].on_ms,
                   rows[0].on_ms - rows[1].on_ms);
        fflush(stdout);
    }
    return ok;
}

int section_peel(bench_env *env, const scene *s, int *ran)
{
    static const int layers[LAYER_CASES] = {0, 2, 4};
    stin_tier tiers[2];
    tech_settings st;
    char timing[160];
    int tier_n, t, i, rc = 0;
    bench_tech_settings(env, SEC_PEEL, &st);
    st.base.transparency = STIN_TECH_TRANSPARENCY_SORTED;
    printf("\n## Camera transparency (gl2/gl4, shadows off): depth-peel and dual-peel against "
           "sorted, %dx%d; "
           "%s\n", env->b.width, env->b.height,
           bench_row_timing(env, st.setups, st.frames, timing, sizeof timing));
    tier_n = bench_tiers(env, GLSL_TIERS, WHAT, "gl2 and gl4 only", tiers);
    for (t = 0; t < tier_n && !rc; t++) {
        tech_row rows[PEELS];
        int ok = 1;
        printf("\n### %s (%s)\n\n", stin_tier_name(tiers[t]), tier_label(tiers[t]));
        printf("| layers on screen | depth-peel passes | dual-peel passes | sorted median ms "
               "| depth-peel median ms | dual-peel median ms | depth-peel / sorted "
               "| dual-peel / depth-peel |\n|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        for (i = 0; i < LAYER_CASES && ok && !rc; i++) {
            scene copy;
            memset(rows, 0, sizeof rows);
            rows[0].cfg = rows[1].cfg = st.base;
            rows[0].cfg.transparency = STIN_TECH_TRANSPARENCY_DEPTH_PEEL;
            rows[1].cfg.transparency = STIN_TECH_TRANSPARENCY_DUAL_PEEL;
            if (!with_panes(s, layers[i], &copy)) {
                fprintf(stderr, "stin-bench: the peel scene has too few transparent objects\n");
                free(copy.objects);
                rc = EXIT_BAD_INPUT;
                break;
            }
            ok = bench_tech_tier(env, &st, tiers[t], WHAT, &copy, rows, PEELS, &rc);
            free(copy.objects);
            if (!ok)
                break;
            if (rows[0].skipped)
                printf("| %d | SKIP: %s | | | | | | |\n", layers[i], rows[0].why);
            else if (rows[1].skipped) /* gl2: dual-peel is GL4 only */
                printf("| %d | %u | SKIP: %s | %.2f | %.2f | | %.2f | |\n", layers[i],
                       rows[0].peel_passes, rows[1].why, rows[0].base_ms, rows[0].on_ms,
                       tech_ratio(&rows[0]));
            else
                printf("| %d | %u | %u | %.2f | %.2f | %.2f | %.2f | %.2f |\n", layers[i],
                       rows[0].peel_passes, rows[1].peel_passes, rows[0].base_ms,
                       rows[0].on_ms, rows[1].on_ms, tech_ratio(&rows[0]),
                       rows[0].on_ms > 0 ? rows[1].on_ms / rows[0].on_ms : 0.0);
            fflush(stdout);
        }
        if (ok && !rc)
            *ran = 1;
        if (ok && !rc && tiers[t] == STIN_TIER_GL4)
            (void)shadowed_layers(env, s, &st, &rc);
    }
    return rc;
}
