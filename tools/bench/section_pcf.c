/* SPDX-License-Identifier: MIT */
/* The PCF section (gl2, gl4): map-pcf per map size and kernel against
 * shadows off, a table per tier, then the ratios as one grid. */
#include "bench_options.h"
#include "bench_report.h"

#include <stdio.h>
#include <string.h>

#define WHAT "PCF shadow maps"

typedef struct pcf_run {
    stin_tier tiers[2];
    int tier_n, done[2];
    tech_row rows[2][TECH_MAX_ROWS];
    const tech_row *best, *worst;
    stin_tier best_tier, worst_tier;
} pcf_run;

static int plan_rows(const options *o, tech_row *rows)
{
    int i, k, n = 0;
    for (i = 0; i < o->pcf_sizes.n; i++)
        for (k = 0; k < o->pcf_kernels.n; k++, n++) {
            tech_config *c = &rows[n].cfg;
            c->shadows = STIN_TECH_SHADOWS_MAP_PCF;
            c->surface = STIN_TECH_NONE;
            c->map_size = (uint32_t)o->pcf_sizes.v[i];
            c->pcf_kernel = o->pcf_kernels.v[k];
        }
    return n;
}

static void print_tier(pcf_run *p, int t, int row_n)
{
    int i;
    printf("\n### " WHAT ", %s (%s)\n\n", stin_tier_name(p->tiers[t]), tier_label(p->tiers[t]));
    printf("| map size asked | map size rendered | kernel | passes | off median ms | "
           "map-pcf median ms | map-pcf / off |\n");
    printf("|---:|---:|---:|---:|---:|---:|---:|\n");
    for (i = 0; i < row_n; i++) {
        const tech_row *r = &p->rows[t][i];
        if (r->skipped) {
            printf("| %u | SKIP: %s | %d | | | | |\n", r->cfg.map_size, r->why,
                   r->cfg.pcf_kernel);
            continue;
        }
        printf("| %u | %u | %d | %u | %.2f | %.2f | %.2f |\n", r->cfg.map_size, r->rendered,
               r->cfg.pcf_kernel, r->passes, r->base_ms, r->on_ms, tech_ratio(r));
        if (!p->best || tech_ratio(r) < tech_ratio(p->best))
            p->best = r, p->best_tier = p->tiers[t];
        if (!p->worst || tech_ratio(r) > tech_ratio(p->worst))
            p->worst = r, p->worst_tier = p->tiers[t];
    }
    fflush(stdout);
}

/* The ratios again as one grid: a line per tier and map size, a column per kernel. */
static void print_grid(const pcf_run *p, const options *o)
{
    int t, i, k;
    printf("\n### " WHAT ": map-pcf / off\n\n| tier | map size |");
    for (k = 0; k < o->pcf_kernels.n; k++)
        printf(" kernel %d |", o->pcf_kernels.v[k]);
    printf("\n|---|---:|");
    for (k = 0; k < o->pcf_kernels.n; k++)
        printf("---:|");
    printf("\n");
    for (t = 0; t < p->tier_n; t++)
        for (i = 0; p->done[t] && i < o->pcf_sizes.n; i++) {
            printf("| %s | %d |", stin_tier_name(p->tiers[t]), o->pcf_sizes.v[i]);
            for (k = 0; k < o->pcf_kernels.n; k++) {
                const tech_row *r = &p->rows[t][i * o->pcf_kernels.n + k];
                if (r->skipped)
                    printf(" SKIP |");
                else
                    printf(" %.2f |", tech_ratio(r));
            }
            printf("\n");
        }
    if (p->best && p->worst)
        printf("\nmap-pcf / shadows off: from %.2f (%s %u, kernel %d) to %.2f (%s %u, kernel "
               "%d)\n", tech_ratio(p->best), stin_tier_name(p->best_tier), p->best->rendered,
               p->best->cfg.pcf_kernel, tech_ratio(p->worst), stin_tier_name(p->worst_tier),
               p->worst->rendered, p->worst->cfg.pcf_kernel);
}

int section_pcf(bench_env *env, const scene *s, int *ran)
{
    static pcf_run p; /* rows too large for the stack */
    const options *o = env->o;
    tech_settings st;
    char label[128], timing[160];
    int t, row_n = 0, rc = 0;
    memset(&p, 0, sizeof p);
    bench_tech_settings(env, SEC_PCF, &st);
    scene_label(s->path, label, sizeof label);
    printf("\n## PCF shadow maps (map-pcf, gl2/gl4): %s, %dx%d, the scene's %d light(s); %s\n",
           label, env->b.width, env->b.height, s->light_count,
           bench_row_timing(env, st.setups, st.frames, timing, sizeof timing));
    p.tier_n = bench_tiers(env, GLSL_TIERS, WHAT, "gl2 and gl4 only", p.tiers);
    for (t = 0; t < p.tier_n; t++) {
        row_n = plan_rows(o, p.rows[t]);
        if (!bench_tech_tier(env, &st, p.tiers[t], WHAT, s, p.rows[t], row_n, &rc)) {
            if (rc)
                return rc;
            continue;
        }
        p.done[t] = *ran = 1;
        print_tier(&p, t, row_n);
    }
    if (*ran) {
        print_grid(&p, o);
        fflush(stdout);
    }
    return 0;
}
