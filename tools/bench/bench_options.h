/* SPDX-License-Identifier: MIT */
/* stin-bench's command line: one table of options (bench_options.c) that
 * gives each its argument, default, --quick value, help and setter. */
#ifndef STIN_BENCH_OPTIONS_H
#define STIN_BENCH_OPTIONS_H

#include "bench_section.h"
#include "stin/stin.h"

#include <stdio.h>

#define MAX_SCENES 16
#define LIST_MAX 8

typedef struct int_list {
    int v[LIST_MAX];
    int n;
} int_list;

/* What every section has: whether it runs, its timing, its scene. */
typedef struct section_options {
    int on;
    int frames;             /* timed frames per side (per set-up, row, light count) */
    int setups;             /* fresh set-ups; the lowest set-up median is reported */
    const char *scene;      /* its scene file; NULL: the --scenes list */
} section_options;

typedef struct options {
    const char *platform, *shader_dir;
    const char *profile;    /* NULL: the best compatibility context (every desktop tier) */
    char scene_list[2048];
    const char *scenes[MAX_SCENES];
    int scene_count;
    int width, height, warmup, quick, verbose;
    stin_tier tier;         /* AUTO: every tier */
    section_options sec[SECTION_COUNT];
    /* options of one section */
    int small_frames;       /* shadows: stin_end_frame alone at 64x36 */
    int cpu_volumes;        /* shadows: GL4's volumes built on the CPU */
    int csg_readback;       /* csg: stin resolves with read-backs (STIN_DEBUG_CSG_READBACK) */
    int_list light_counts;  /* shadows */
    int_list map_sizes;     /* maps */
    int maps_no_fbo;        /* maps */
    int_list pcf_sizes, pcf_kernels;
    int vdsm_goal;          /* vdsm: only the full chain and volumes (the goal's rows) */
    const char *displace_wall; /* displace: the coarse scene */
    int_list displace_levels;  /* displace: fixed tessellation levels on it */
    const char *deep_one, *deep_all; /* deep: point-light scenes, one face / six */
    int deep_size;             /* deep: texels a side of every map */
    const char *peers_scenes;  /* peers: comma-separated scene files */
    int peers_map_size;        /* peers: texels a side of every map, stin's and OSG's */
} options;

/* Fills o from the defaults (--quick's where it is given) and argv. Prints
 * --help and exits 0; on bad input prints why and returns 0. */
int options_parse(int argc, char **argv, options *o);
/* The usage text, from the option and section tables. */
void options_usage(FILE *f);

#endif
