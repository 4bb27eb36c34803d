/* SPDX-License-Identifier: MIT */
/* stin-bench's technique sections on the GLSL tiers: rows of one forced
 * technique configuration each (a shadow technique with a map size and a PCF
 * kernel, or a surface technique), each timed as a ratio to a baseline
 * configuration of the same tier and scene (shadows off, or the plain
 * surface, or shadows off and a debug flag set). Used by the "PCF shadow
 * maps", "Surface techniques", "VDSM" and "Displacement" sections. */
#ifndef STIN_BENCH_TECH_H
#define STIN_BENCH_TECH_H

#include "bench_run.h"
#include "scene.h"
#include "stin/stin.h"

#include <stdint.h>

#define TECH_MAX_ROWS 40

/* What one stin context is forced to. */
typedef struct tech_config {
    stin_technique shadows;  /* desc.techniques[STIN_FEATURE_SHADOWS] (never NONE here) */
    stin_technique surface;  /* desc.techniques[STIN_FEATURE_SURFACE]; NONE = the tier's */
    uint32_t map_size;       /* desc.shadows.map_size; 0 = stin's default */
    int pcf_kernel;          /* every scene light's pcf_kernel; 0 = as the scene has it */
    uint64_t debug_flags;    /* desc.debug_flags (vdsm's steps) */
    /* flags the row's stage-times context adds (vdsm's counter, whose waits
     * stay out of the timed frames); its first frame gives `primitives` */
    uint64_t counted_flags;
    stin_technique displacement; /* desc.techniques[STIN_FEATURE_DISPLACEMENT]; NONE = auto */
    float guard_band, tess_pixels; /* desc.displacement.guard_band, displacement.tess_pixels (0: default) */
    uint32_t tess_max;       /* desc.displacement.tess_max (0: default) */
    stin_technique translucent; /* desc.techniques[STIN_FEATURE_TRANSLUCENT_SHADOWS]; NONE = auto */
    uint32_t deep_layers, deep_map_size; /* desc's (0: default) */
    stin_technique transparency; /* desc.techniques[STIN_FEATURE_TRANSPARENCY]; NONE = auto */
} tech_config;

typedef struct tech_settings {
    const bench_settings *b; /* plat, gl, size, verbose; b->warmup is used too */
    stin_tier tier;
    int frames;              /* timed frames per side, set-up and row */
    int setups;              /* fresh baseline context per set-up, fresh row context per row */
    tech_config base;        /* the baseline every row is timed against */
    int stages;              /* also each row's GPU time per stage: after its ABBA frames,
                              * a second context with STIN_DEBUG_STAGE_TIMES, `frames`
                              * frames, the median per stage (1 set-up: the first) */
} tech_settings;

/* One row: its configuration (set by the caller) and what was measured. */
typedef struct tech_row {
    tech_config cfg;
    uint32_t rendered;       /* stin_frame_stats.shadows.map_size of the row's frame */
    uint32_t passes;         /* stin_frame_stats.passes of the row's frame */
    uint32_t primitives;     /* stin_frame_stats.shadows.vdsm_primitives of the row's frame */
    uint32_t peel_passes;    /* stin_frame_stats.transparency.peel_passes of the row's frame */
    double base_ms, on_ms;   /* per side the lowest set-up median (glFinish included) */
    int staged;              /* stage_ms holds the row's stage medians (timer queries) */
    double stage_ms[STIN_STAGE_COUNT];
    int skipped;             /* 1: the context cannot run it; why says so */
    char why[160];
} tech_row;

/* Runs every row (rows[i].cfg set by the caller) on st->tier: per set-up one
 * baseline context kept for the set-up, per row a fresh context forced to the
 * row's configuration, ABBA frames. Returns 1, or 0 with a message in err. */
int bench_tech_run(const tech_settings *st, const scene *s, tech_row *rows, int row_n,
                   char *err, size_t err_size);

#endif
