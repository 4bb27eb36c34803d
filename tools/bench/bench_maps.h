/* SPDX-License-Identifier: MIT */
/* stin-bench's shadow-map section: on the GL1 tier, the frame time with the
 * fixed-function shadow maps (map-depth, map-combine) at several map sizes,
 * and with stencil shadow volumes, each as a ratio to the unshadowed stin
 * frame (shadows off) of the same scene — a scene with a spot or directional
 * light, since maps need one. */
#ifndef STIN_BENCH_MAPS_H
#define STIN_BENCH_MAPS_H

#include "bench_run.h"
#include "scene.h"
#include "stin/stin.h"

#include <stdint.h>

#define MAPS_MAX_SIZES 6
/* per path and size, plus one volume row */
#define MAPS_MAX_ROWS (2 * MAPS_MAX_SIZES + 1)

typedef struct maps_settings {
    const bench_settings *b; /* plat, gl, size, verbose; b->warmup is used too */
    int frames;              /* timed frames per side, set-up and row */
    int setups;              /* fresh shadows-off context (and per row a shadowed one) each */
    int sizes[MAPS_MAX_SIZES]; /* desc.shadows.map_size per row, powers of two */
    int size_n;
    uint64_t caps_mask;      /* desc.caps_mask of every context (e.g. hide the FBO) */
} maps_settings;

/* One row: a shadow technique (and map size) against shadows off. */
typedef struct maps_row {
    stin_technique technique;  /* map-depth, map-combine or volume */
    uint32_t requested;        /* desc.shadows.map_size; 0 for volume */
    uint32_t rendered;         /* stin_frame_stats.shadows.map_size of the shadowed frame */
    uint32_t passes, volume_triangles; /* the shadowed frame's stats */
    double off_ms, on_ms;      /* per side the lowest set-up median (glFinish included) */
    int skipped;               /* 1: the context cannot run it; why says so */
    char why[160];
} maps_row;

/* Runs every row on the GL1 tier: map-depth per size, map-combine per size,
 * then volume. *row_n gets the number of rows. Returns 1, or 0 with a message
 * in err. */
int bench_maps_run(const maps_settings *st, const scene *s, maps_row *rows, int *row_n,
                   char *err, size_t err_size);

#endif
