/* SPDX-License-Identifier: MIT */
/* The GL1 shadow-map section: map-depth and map-combine per map size, and
 * stencil volumes, each against shadows off on one scene. */
#include "bench_maps.h"
#include "bench_options.h"
#include "bench_report.h"

#include <stdio.h>
#include <string.h>

static double on_off(const maps_row *r)
{
    return r->off_ms > 0 ? r->on_ms / r->off_ms : 0.0;
}

/* One table row; the volume row is the one without a map size. */
static void print_row(const maps_row *r)
{
    char asked[32], rendered[48];
    if (r->technique == STIN_TECH_SHADOWS_VOLUME) {
        snprintf(asked, sizeof asked, "-");
        snprintf(rendered, sizeof rendered, "- (%u volume triangles)", r->volume_triangles);
    } else {
        snprintf(asked, sizeof asked, "%u", r->requested);
        snprintf(rendered, sizeof rendered, "%u", r->rendered);
    }
    if (r->skipped)
        printf("| %s | %s | SKIP: %s | | | | |\n", stin_technique_name(r->technique), asked,
               r->why);
    else
        printf("| %s | %s | %s | %u | %.2f | %.2f | %.2f |\n",
               stin_technique_name(r->technique), asked, rendered, r->passes, r->off_ms,
               r->on_ms, on_off(r));
}

static void print_table(const maps_row *rows, int row_n)
{
    const maps_row *best = NULL, *worst = NULL, *vol = NULL;
    int i;
    printf("\n| shadows | map size asked | map size rendered | passes | off median ms | "
           "shadowed median ms | shadowed / off |\n");
    printf("|---|---:|---:|---:|---:|---:|---:|\n");
    for (i = 0; i < row_n; i++) {
        const maps_row *r = &rows[i];
        print_row(r);
        if (r->skipped)
            continue;
        if (r->technique == STIN_TECH_SHADOWS_VOLUME)
            vol = r;
        if (r->technique != STIN_TECH_SHADOWS_VOLUME && (!best || on_off(r) < on_off(best)))
            best = r;
        if (r->technique != STIN_TECH_SHADOWS_VOLUME && (!worst || on_off(r) > on_off(worst)))
            worst = r;
    }
    if (best && worst)
        printf("\nshadow maps / shadows off: from %.2f (%s %u) to %.2f (%s %u)", on_off(best),
               stin_technique_name(best->technique), best->rendered, on_off(worst),
               stin_technique_name(worst->technique), worst->rendered);
    if (vol)
        printf("%sshadow volumes / shadows off: %.2f", best && worst ? "; " : "\n", on_off(vol));
    printf("\n");
}

int section_maps(bench_env *env, const scene *s, int *ran)
{
    const bench_settings *b = &env->b;
    const options *o = env->o;
    maps_settings st;
    maps_row rows[MAPS_MAX_ROWS];
    char err[1024], label[128], timing[160];
    stin_tier tier;
    int i, row_n = 0, rc = 0;
    memset(&st, 0, sizeof st);
    st.b = b;
    st.frames = o->sec[SEC_MAPS].frames;
    st.setups = o->sec[SEC_MAPS].setups;
    st.size_n = o->map_sizes.n;
    for (i = 0; i < st.size_n; i++)
        st.sizes[i] = o->map_sizes.v[i];
    st.caps_mask = o->maps_no_fbo ? STIN_CAP_BIT(STIN_CAP_FBO) : 0;
    scene_label(s->path, label, sizeof label);
    printf("\n## Shadow maps (gl1, %s): %s, %dx%d, the scene's %d light(s)%s; %s\n",
           tier_label(STIN_TIER_GL1), label, b->width, b->height, s->light_count,
           o->maps_no_fbo ? ", FBO hidden from stin" : "",
           bench_row_timing(env, st.setups, st.frames, timing, sizeof timing));
    if (!bench_tiers(env, TIER_BIT(STIN_TIER_GL1), "shadow maps",
                     "the map techniques are gl1 only", &tier) ||
        !bench_tier_ok(env, tier, "shadow maps", &rc))
        return rc;
    fprintf(stderr, "stin-bench: shadow maps gl1 %s ...\n", label);
    fflush(stdout);
    if (!bench_maps_run(&st, s, rows, &row_n, err, sizeof err)) {
        fprintf(stderr, "stin-bench: shadow maps, gl1, %s: %s\n", label, err);
        return EXIT_FAILED;
    }
    print_table(rows, row_n);
    fflush(stdout);
    *ran = 1;
    return 0;
}
