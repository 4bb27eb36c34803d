/* SPDX-License-Identifier: MIT */
/* stin-bench's shadow-volume section: per tier and scene, the frame time with
 * stencil shadow volumes as a ratio to the unshadowed stin frame (shadows
 * off) for several point-light counts, and an estimate of the per-frame CPU
 * cost of building the volumes (silhouette extraction) from the outside. */
#ifndef STIN_BENCH_SHADOW_H
#define STIN_BENCH_SHADOW_H

#include "bench_run.h"
#include "scene.h"
#include "stin/stin.h"

#include <stdint.h>

#define SHADOW_MAX_COUNTS 4   /* light counts per run */
#define SHADOW_MAX_LIGHTS 8   /* most lights in one count (one unshadowed pass) */

typedef struct shadow_settings {
    const bench_settings *b; /* plat, gl, size, verbose; b->warmup is used too */
    int frames;              /* timed frames per side, set-up and light count */
    int setups;              /* fresh pair of stin contexts each, >= 1 */
    int small_w, small_h;    /* viewport of the extraction estimate (64x36) */
    int small_frames;        /* timed frames per side there */
    int cpu_volumes;         /* STIN_DEBUG_VOLUME_CPU on the volume side */
    int light_counts[SHADOW_MAX_COUNTS];
    int count_n;
} shadow_settings;

/* One light count of one scene on one tier. */
typedef struct shadow_row {
    int lights;
    /* full size: per side the lowest set-up median frame time (glFinish included) */
    double off_ms, vol_ms;
    /* from the shadowed context's last frame */
    uint32_t volume_triangles, passes, zpass_casters, zfail_casters;
    uint32_t gpu_casters; /* casters a geometry shader extruded (triangles not counted) */
    /* small viewport: per side the lowest set-up median of stin_end_frame's wall
     * time (no glFinish), and of the part of it spent outside the GL draw and
     * upload calls (glDrawArrays, glDrawElements, glBufferData, glClear) */
    double off_end_ms, vol_end_ms;
    double off_cpu_ms, vol_cpu_ms;
} shadow_row;

/* Runs every light count of one scene on one tier; rows[i] for
 * light_counts[i]. Returns 1, or 0 with a message in err. */
int bench_shadow_run(const shadow_settings *st, stin_tier tier, const scene *s,
                     shadow_row *rows, char *err, size_t err_size);

/* The get_proc_address the shadow section hands stin: the platform's, with
 * the GL draw and upload calls wrapped so that the time spent in them can be
 * read (see bench_shadow.c). user is the stin_platform. */
void *bench_shadow_get_proc(void *user, const char *name);

#endif
