/* SPDX-License-Identifier: MIT */
/* The surface section (gl2, gl4, shadows off): each GLSL surface technique
 * against the plain surface, a table per tier. */
#include "bench_options.h"
#include "bench_report.h"

#include <stdio.h>
#include <string.h>

#define WHAT "surface techniques"

static const stin_technique surfaces[] = {STIN_TECH_SURFACE_PLAIN, STIN_TECH_SURFACE_NORMAL,
                                          STIN_TECH_SURFACE_PARALLAX, STIN_TECH_SURFACE_POM};
enum { N = sizeof surfaces / sizeof surfaces[0] };

static void print_tier(stin_tier tier, const tech_row *rows)
{
    const tech_row *worst = NULL;
    int i;
    printf("\n### " WHAT ", %s (%s)\n\n", stin_tier_name(tier), tier_label(tier));
    printf("| surface | passes | plain median ms | surface median ms | surface / plain |\n");
    printf("|---|---:|---:|---:|---:|\n");
    for (i = 0; i < N; i++) {
        const tech_row *r = &rows[i];
        if (r->skipped) {
            printf("| %s | SKIP: %s | | | |\n", stin_technique_name(r->cfg.surface), r->why);
            continue;
        }
        printf("| %s | %u | %.2f | %.2f | %.2f |\n", stin_technique_name(r->cfg.surface),
               r->passes, r->base_ms, r->on_ms, tech_ratio(r));
        if (!worst || tech_ratio(r) > tech_ratio(worst))
            worst = r;
    }
    if (worst)
        printf("\n%s: surface / plain at most %.2f (%s)\n", stin_tier_name(tier),
               tech_ratio(worst), stin_technique_name(worst->cfg.surface));
    fflush(stdout);
}

int section_surface(bench_env *env, const scene *s, int *ran)
{
    tech_row rows[N];
    stin_tier tiers[2];
    tech_settings st;
    char label[128], timing[160];
    int tier_n, t, i, rc = 0;
    bench_tech_settings(env, SEC_SURFACE, &st);
    st.base.surface = STIN_TECH_SURFACE_PLAIN;
    scene_label(s->path, label, sizeof label);
    printf("\n## Surface techniques (gl2/gl4, shadows off): %s, %dx%d; %s; the plain row is a "
           "second plain context against the first\n", label, env->b.width, env->b.height,
           bench_row_timing(env, st.setups, st.frames, timing, sizeof timing));
    tier_n = bench_tiers(env, GLSL_TIERS, WHAT, "gl2 and gl4 only", tiers);
    for (t = 0; t < tier_n; t++) {
        memset(rows, 0, sizeof rows);
        for (i = 0; i < N; i++) {
            rows[i].cfg.shadows = STIN_TECH_SHADOWS_OFF;
            rows[i].cfg.surface = surfaces[i];
        }
        if (!bench_tech_tier(env, &st, tiers[t], WHAT, s, rows, N, &rc)) {
            if (rc)
                return rc;
            continue;
        }
        *ran = 1;
        print_tier(tiers[t], rows);
    }
    return 0;
}
