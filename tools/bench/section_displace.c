/* SPDX-License-Identifier: MIT */
/* The displacement section (gl2, gl4; shadows off): on the 31k-vertex grid
 * (the seed's size) the surface chain against displacement - VTF with and
 * without manual bilinear filtering, and on GL4 tessellation at its default
 * target - each timed against the plain surface; then each speed-up on and
 * off where it matters (the camera moved in so the wall runs off screen:
 * the guard band; moved out: the mip levels); then the coarse stone wall
 * (825 vertices), where only tessellation shows the relief, with
 * tessellation at its default target and at fixed levels (--displace-levels).
 * Every height-mapped material is displaced in every table (the surface
 * rows force displacement off, so they draw the surface chain). */
#include "bench_options.h"
#include "bench_report.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WHAT "displacement"
#define FIXED_PIXELS 1e-3f /* a target far below every edge: each edge at the level cap */
#define NEAR_FACTOR 0.45f  /* the camera moved in: the wall reaches past the screen */
#define FAR_FACTOR 4.0f    /* moved out: the height map's upper levels */

typedef struct disp_row {
    const char *name;
    stin_technique surface, displacement;
    uint64_t flags;
    uint32_t tess_max;
    float tess_pixels;
    int gl4_only;
} disp_row;

#define OFF STIN_TECH_DISPLACEMENT_OFF
#define VTF STIN_TECH_DISPLACEMENT_VTF
#define TESS STIN_TECH_DISPLACEMENT_TESS
#define AUTO STIN_TECH_NONE

static const disp_row chain_rows[] = {
    {"plain", STIN_TECH_SURFACE_PLAIN, OFF, 0, 0, 0, 0},
    {"normal", STIN_TECH_SURFACE_NORMAL, OFF, 0, 0, 0, 0},
    {"parallax", STIN_TECH_SURFACE_PARALLAX, OFF, 0, 0, 0, 0},
    {"pom", STIN_TECH_SURFACE_POM, OFF, 0, 0, 0, 0},
    {"displace", AUTO, VTF, 0, 0, 0, 0},
    {"displace, manual bilinear", AUTO, VTF, STIN_DEBUG_DISPLACE_MANUAL_BILINEAR, 0, 0, 0},
    {"displace-tess (4 px edges)", AUTO, TESS, 0, 0, 0, 1},
};
static const disp_row guard_rows[] = {
    {"displace, guard band 1", AUTO, VTF, 0, 0, 0, 0},
    {"displace, no guard band", AUTO, VTF, STIN_DEBUG_DISPLACE_NO_GUARD, 0, 0, 0},
};
static const disp_row mip_rows[] = {
    {"displace, mip levels", AUTO, VTF, 0, 0, 0, 0},
    {"displace, level 0 only", AUTO, VTF, STIN_DEBUG_DISPLACE_NO_MIP, 0, 0, 0},
};
static const disp_row wall_rows[] = {
    {"plain", STIN_TECH_SURFACE_PLAIN, OFF, 0, 0, 0, 0},
    {"pom", STIN_TECH_SURFACE_POM, OFF, 0, 0, 0, 0},
    {"displace (the mesh's 825 vertices)", AUTO, VTF, 0, 0, 0, 0},
    {"displace-tess (4 px edges)", AUTO, TESS, 0, 0, 0, 1},
};
enum { WALL_ROWS = sizeof wall_rows / sizeof wall_rows[0] };

/* The wall's rows and one fixed-level tessellation row per --displace-levels
 * entry (names in `names`). */
static int wall_table(const int_list *levels, disp_row *out, char (*names)[48])
{
    int i, n = WALL_ROWS;
    memcpy(out, wall_rows, sizeof wall_rows);
    for (i = 0; i < levels->n; i++, n++) {
        snprintf(names[i], 48, "displace-tess, level %d", levels->v[i]);
        out[n].name = names[i];
        out[n].surface = AUTO;
        out[n].displacement = TESS;
        out[n].flags = 0;
        out[n].tess_max = (uint32_t)levels->v[i];
        out[n].tess_pixels = FIXED_PIXELS;
        out[n].gl4_only = 1;
    }
    return n;
}

/* A copy of s whose height-mapped materials are displaced and whose camera
 * is `factor` times as far from its target (materials freed by the caller). */
static int displaced_copy(const scene *s, float factor, scene *out)
{
    int i, k;
    *out = *s;
    out->materials = malloc(sizeof *out->materials * (size_t)(s->material_count + 1));
    if (!out->materials)
        return 0; /* NULL: nothing to free */
    memcpy(out->materials, s->materials, sizeof *out->materials * (size_t)s->material_count);
    for (i = 0; i < s->material_count; i++)
        out->materials[i].displace |= out->materials[i].height >= 0;
    for (k = 0; k < 3; k++)
        out->camera.eye[k] = s->camera.target[k] + factor * (s->camera.eye[k] - s->camera.target[k]);
    return 1;
}

/* One table: defs on scene s (tier's rows; gl4-only rows skipped on gl2). */
static int run_table(bench_env *env, tech_settings *st, stin_tier tier, const char *title,
                     const scene *s, const disp_row *defs, int n, int *rc)
{
    tech_row rows[TECH_MAX_ROWS];
    const char *names[TECH_MAX_ROWS];
    int i, m = 0;
    memset(rows, 0, sizeof rows);
    for (i = 0; i < n; i++) {
        if (defs[i].gl4_only && tier != STIN_TIER_GL4)
            continue;
        names[m] = defs[i].name;
        rows[m].cfg.shadows = STIN_TECH_SHADOWS_OFF;
        rows[m].cfg.surface = defs[i].surface;
        rows[m].cfg.displacement = defs[i].displacement;
        rows[m].cfg.debug_flags = defs[i].flags;
        rows[m].cfg.tess_max = defs[i].tess_max;
        rows[m].cfg.tess_pixels = defs[i].tess_pixels;
        m++;
    }
    if (!bench_tech_tier(env, st, tier, WHAT, s, rows, m, rc))
        return 0;
    bench_ratio_table(title, tier, "plain", names, rows, m);
    return 1;
}

int section_displace(bench_env *env, const scene *s, int *ran)
{
    scene grid, near, far, wall_src, wall;
    stin_tier tiers[2];
    tech_settings st;
    char timing[160], err[512];
    int tier_n, t, rc = 0, have_wall;
    memset(&grid, 0, sizeof grid);
    near = far = wall = grid;
    bench_tech_settings(env, SEC_DISPLACE, &st);
    st.base.surface = STIN_TECH_SURFACE_PLAIN;
    st.base.displacement = OFF;
    printf("\n## Displacement (gl2/gl4, shadows off) against the plain surface, %dx%d; %s\n",
           env->b.width, env->b.height,
           bench_row_timing(env, st.setups, st.frames, timing, sizeof timing));
    tier_n = bench_tiers(env, GLSL_TIERS, WHAT, "gl2 and gl4 only", tiers);
    if (!tier_n)
        return 0;
    have_wall = scene_load(env->o->displace_wall, &wall_src, err, sizeof err);
    if (!have_wall)
        fprintf(stderr, "stin-bench: %s: %s\n", env->o->displace_wall, err);
    if (!displaced_copy(s, 1.0f, &grid) || !displaced_copy(s, NEAR_FACTOR, &near) ||
        !displaced_copy(s, FAR_FACTOR, &far) || (have_wall && !displaced_copy(&wall_src, 1.0f, &wall))) {
        fprintf(stderr, "stin-bench: out of memory\n");
        rc = EXIT_FAILED;
    }
    for (t = 0; t < tier_n && !rc; t++) {
        if (!run_table(env, &st, tiers[t], "surface chain and displacement, 31k-vertex grid",
                       &grid, chain_rows, sizeof chain_rows / sizeof chain_rows[0], &rc))
            continue;
        *ran = 1;
        if (!run_table(env, &st, tiers[t], "guard band, camera moved in (the wall off screen)",
                       &near, guard_rows, 2, &rc) ||
            !run_table(env, &st, tiers[t], "mip levels, camera 4x as far", &far, mip_rows, 2, &rc))
            continue;
        if (have_wall) {
            disp_row rows[WALL_ROWS + LIST_MAX];
            char names[LIST_MAX][48];
            int n = wall_table(&env->o->displace_levels, rows, names);
            (void)run_table(env, &st, tiers[t], "the coarse stone wall", &wall, rows, n, &rc);
        }
    }
    free(grid.materials);
    free(near.materials);
    free(far.materials);
    if (have_wall) {
        free(wall.materials);
        scene_free(&wall_src);
    }
    return rc;
}
