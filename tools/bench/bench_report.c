/* SPDX-License-Identifier: MIT */
/* Labels, the machine line and tier selection for the sections (bench_report.h). */
#include "bench_report.h"
#include "bench_machine.h"
#include "bench_options.h"

#include <stdio.h>
#include <string.h>

void scene_label(const char *path, char *out, size_t size)
{
    const char *base = strrchr(path, '/');
    size_t n;
    base = base ? base + 1 : path;
    n = strcspn(base, ".");
    snprintf(out, size, "%.*s", (int)n, base);
}

const char *tier_label(stin_tier t)
{
    return t == STIN_TIER_GL1 ? "fixed-function, per-vertex lighting"
         : t == STIN_TIER_GL2 ? "GLSL 1.10, per-pixel lighting"
                              : "GLSL 1.50 + VAOs, per-pixel lighting";
}

void bench_machine_once(bench_env *env)
{
    const raw_gl *gl = env->b.gl;
    const GLubyte *renderer = gl->GetString(GL_RENDERER), *version = gl->GetString(GL_VERSION);
    char cpu[256];
    if (env->machine_printed)
        return;
    env->machine_printed = 1;
    bench_cpu_model(cpu, sizeof cpu);
    printf("\nmachine: %s; GL %s; CPU %s, %d logical cores\n",
           renderer ? (const char *)renderer : "unknown renderer",
           version ? (const char *)version : "unknown", cpu, bench_cpu_count());
}

int bench_tiers(const bench_env *env, unsigned mask, const char *what, const char *why,
                stin_tier *out)
{
    static const stin_tier all[] = {STIN_TIER_GL1, STIN_TIER_GL2, STIN_TIER_GL4};
    stin_tier forced = env->o->tier;
    int i, n = 0;
    if (forced != STIN_TIER_AUTO && !(mask & TIER_BIT(forced))) {
        printf("\n### %s: SKIP (%s; --tier %s)\n", what, why, stin_tier_name(forced));
        return 0;
    }
    for (i = 0; i < 3; i++)
        if ((mask & TIER_BIT(all[i])) && (forced == STIN_TIER_AUTO || forced == all[i]))
            out[n++] = all[i];
    return n;
}

int bench_tier_ok(const bench_env *env, stin_tier tier, const char *what, int *rc)
{
    char missing[512];
    if (stin_tier_supported(env->caps, tier, missing, sizeof missing))
        return 1;
    printf("\n### %s%s%s: SKIP (the context lacks %s)\n", what ? what : "", what ? ", " : "",
           stin_tier_name(tier), missing);
    if (env->o->tier != STIN_TIER_AUTO)
        *rc = EXIT_UNSUPPORTED;
    return 0;
}

void bench_tech_settings(const bench_env *env, int section, tech_settings *st)
{
    memset(st, 0, sizeof *st);
    st->b = &env->b;
    st->frames = env->o->sec[section].frames;
    st->setups = env->o->sec[section].setups;
    st->base.shadows = STIN_TECH_SHADOWS_OFF;
    st->base.surface = STIN_TECH_NONE;
}

const char *bench_row_timing(const bench_env *env, int setups, int frames, char *buf,
                             size_t size)
{
    snprintf(buf, size, "per side the lowest of %d set-ups' median of %d frames "
             "(ABBA-interleaved, glFinish per frame, %d warm-up per row)", setups, frames,
             env->b.warmup > 1 ? env->b.warmup : 1);
    return buf;
}

int bench_tech_tier(const bench_env *env, tech_settings *st, stin_tier tier, const char *what,
                    const scene *s, tech_row *rows, int row_n, int *rc)
{
    char err[1024], label[128];
    if (!bench_tier_ok(env, tier, what, rc))
        return 0;
    scene_label(s->path, label, sizeof label);
    st->tier = tier;
    fprintf(stderr, "stin-bench: %s %s %s ...\n", what, stin_tier_name(tier), label);
    fflush(stdout);
    if (!bench_tech_run(st, s, rows, row_n, err, sizeof err)) {
        fprintf(stderr, "stin-bench: %s, %s, %s: %s\n", what, stin_tier_name(tier), label, err);
        *rc = EXIT_FAILED;
        return 0;
    }
    return 1;
}

double tech_ratio(const tech_row *r)
{
    return r->base_ms > 0 ? r->on_ms / r->base_ms : 0.0;
}

void bench_ratio_table(const char *title, stin_tier tier, const char *base,
                       const char *const *names, const tech_row *rows, int n)
{
    int i;
    printf("\n### %s, %s (%s)\n\n", title, stin_tier_name(tier), tier_label(tier));
    printf("| row | passes | %s median ms | row median ms | row / %s | row / first row |\n", base,
           base);
    printf("|---|---:|---:|---:|---:|---:|\n");
    for (i = 0; i < n; i++) {
        const tech_row *r = &rows[i];
        if (r->skipped) {
            printf("| %s | SKIP: %s | | | | |\n", names[i], r->why);
            continue;
        }
        printf("| %s | %u | %.2f | %.2f | %.2f | %.2f |\n", names[i], r->passes, r->base_ms,
               r->on_ms, tech_ratio(r),
               !rows[0].skipped && rows[0].on_ms > 0 ? r->on_ms / rows[0].on_ms : 0.0);
    }
    fflush(stdout);
}
