/* SPDX-License-Identifier: MIT */
/* A stin-bench section: one table of measurements (with its closing line)
 * that main runs in the order of bench_sections[]. A new section is a file
 * with its run function, a row in bench_sections.c, its index below and,
 * if it has options of its own, rows in bench_options.c. */
#ifndef STIN_BENCH_SECTION_H
#define STIN_BENCH_SECTION_H

#include "bench_run.h"
#include "scene.h"
#include "stin/stin.h"

enum { EXIT_FAILED = 1, EXIT_BAD_INPUT = 2, EXIT_UNSUPPORTED = 3 };

/* Indices into bench_sections[], in the order they run. */
enum { SEC_RAW, SEC_SHADOWS, SEC_MAPS, SEC_PCF, SEC_SURFACE, SEC_VDSM, SEC_DISPLACE, SEC_DEEP,
       SEC_CSG, SEC_PEEL, SEC_UPDATE, SEC_PEERS,
       SECTION_COUNT };

struct options;

/* What every section gets. */
typedef struct bench_env {
    bench_settings b;       /* platform, GL, size, warm-up; frames and set-ups of SEC_RAW */
    const stin_caps *caps;  /* of the one GL context */
    const struct options *o;
    scene *scenes;          /* the --scenes list, o->scene_count of them */
    int machine_printed;    /* the machine line comes once, after the first table */
} bench_env;

/* Prints the section's tables. s is its own scene (o->sec[i].scene loaded),
 * or NULL where it has none and reads env->scenes. Returns 0 or an exit
 * code; sets *ran when it printed a table rather than only SKIP lines. */
typedef int (*bench_section_fn)(bench_env *env, const scene *s, int *ran);

typedef struct bench_section {
    const char *name;       /* --NAME runs only the sections named, --no-NAME skips it */
    const char *about;      /* its heading in --help */
    bench_section_fn run;
} bench_section;

extern const bench_section bench_sections[SECTION_COUNT];

int section_raw(bench_env *env, const scene *s, int *ran);
int section_shadows(bench_env *env, const scene *s, int *ran);
int section_maps(bench_env *env, const scene *s, int *ran);
int section_pcf(bench_env *env, const scene *s, int *ran);
int section_surface(bench_env *env, const scene *s, int *ran);
int section_vdsm(bench_env *env, const scene *s, int *ran);
int section_displace(bench_env *env, const scene *s, int *ran);
int section_deep(bench_env *env, const scene *s, int *ran);
int section_csg(bench_env *env, const scene *s, int *ran);
int section_peel(bench_env *env, const scene *s, int *ran);
int section_update(bench_env *env, const scene *s, int *ran);
int section_peers(bench_env *env, const scene *s, int *ran);

#endif
