/* SPDX-License-Identifier: MIT */
/* The stin / raw section: per tier a table of stin's and the raw loop's
 * median frame times per scene, then the goal line over every row. */
#include "bench_options.h"
#include "bench_report.h"

#include <stdio.h>

#define GOAL_RATIO 1.15

/* The largest ratio over every row, for the goal line. */
typedef struct worst_ratio {
    double ratio;
    char at[160];
} worst_ratio;

/* One tier over every scene, as a table. 0 on failure. */
static int raw_tier(const bench_env *env, stin_tier tier, worst_ratio *w)
{
    const stin_caps *c = env->caps;
    int i;
    if (c->es) /* the same sources, run as the context's GLSL ES */
        printf("\n### %s (%s, as GLSL ES %d.%d0 on OpenGL ES %d.%d)\n\n", stin_tier_name(tier),
               tier_label(tier), c->glsl_major, c->glsl_minor, c->gl_major, c->gl_minor);
    else
        printf("\n### %s (%s)\n\n", stin_tier_name(tier), tier_label(tier));
    printf("| scene | triangles | stin median ms | raw median ms | stin / raw |\n");
    printf("|---|---:|---:|---:|---:|\n");
    fflush(stdout);
    for (i = 0; i < env->o->scene_count; i++) {
        bench_result r;
        char err[1024], label[128];
        double ratio;
        scene_label(env->o->scenes[i], label, sizeof label);
        fprintf(stderr, "stin-bench: %s %s ...\n", stin_tier_name(tier), label);
        if (!bench_run(&env->b, tier, &env->scenes[i], &r, err, sizeof err)) {
            fprintf(stderr, "stin-bench: %s, %s: %s\n", stin_tier_name(tier), label, err);
            return 0;
        }
        ratio = r.raw_ms > 0 ? r.stin_ms / r.raw_ms : 0.0;
        if (ratio > w->ratio) {
            w->ratio = ratio;
            snprintf(w->at, sizeof w->at, "%s %s", stin_tier_name(tier), label);
        }
        printf("| %s | %llu | %.2f | %.2f | %.3f |\n", label, (unsigned long long)r.triangles,
               r.stin_ms, r.raw_ms, ratio);
        fflush(stdout);
    }
    return 1;
}

int section_raw(bench_env *env, const scene *s, int *ran)
{
    const bench_settings *b = &env->b;
    stin_tier tiers[3];
    worst_ratio worst = {0.0, ""};
    int i, n = bench_tiers(env, ALL_TIERS, "stin / raw", "", tiers), rc = 0;
    (void)s;
    printf("## stin-bench: %dx%d, %s%s%s; per side the lowest of %d set-ups' median of %d frames "
           "(ABBA-interleaved, glFinish per frame, %d warm-up)\n", b->width, b->height,
           env->o->platform, env->o->profile ? ", profile " : "",
           env->o->profile ? env->o->profile : "", b->setups, b->frames, b->warmup);
    if (env->caps->es && env->caps->gl_major < 3) {
        /* its GLSL ES 1.00 programs and 16-bit indices would be another loop */
        printf("\n### stin / raw: SKIP (the raw loop needs OpenGL ES 3.0 or later)\n");
        return 0;
    }
    for (i = 0; i < n && rc == 0; i++) {
        if (!bench_tier_ok(env, tiers[i], NULL, &rc))
            continue;
        if (!raw_tier(env, tiers[i], &worst))
            return EXIT_FAILED;
        *ran = 1;
    }
    if (rc == 0 && *ran) {
        bench_machine_once(env);
        printf("goal stin / raw <= %.2f on every row: %s (worst %.3f, %s)\n", GOAL_RATIO,
               worst.ratio <= GOAL_RATIO ? "met" : "NOT met", worst.ratio, worst.at);
    }
    return rc;
}
