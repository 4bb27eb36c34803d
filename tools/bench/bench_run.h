/* SPDX-License-Identifier: MIT */
/* One measurement of stin-bench: a scene on one tier, drawn by libstin and
 * by the raw-GL loop on the same context, interleaved frame by frame, over
 * several independent set-ups. */
#ifndef STIN_BENCH_RUN_H
#define STIN_BENCH_RUN_H

#include "raw_gl.h"
#include "scene.h"
#include "stin/stin.h"
#include "stin_platform.h"

#include <stdint.h>

typedef struct bench_settings {
    stin_platform *plat;
    const raw_gl *gl;
    int width, height;       /* the platform's framebuffer size */
    int frames;              /* timed frames per side and set-up */
    int warmup;              /* untimed frames per side first, per set-up */
    int setups;              /* fresh stin context + raw loop each, >= 1 */
    int verbose;             /* per-run details on stderr */
    const char *shader_dir;  /* for the raw loop's GLSL */
    uint64_t caps_mask;      /* the --profile's: every stin_desc of the run gets them */
    int max_gl_version;
} bench_settings;

typedef struct bench_result {
    uint64_t triangles;
    double stin_ms, raw_ms;  /* per side: the lowest of the set-ups' median frame times */
    double mismatch;         /* worst set-up: fraction of pixels where the images differ */
    int max_diff;            /* worst set-up: largest channel difference, 0..255 */
} bench_result;

/* A zeroed desc that resolves GL through the run's platform, with the
 * profile's caps mask and GL version cap (stin_platform.h: the in-process
 * half of a profile). Every context the bench makes starts from it. */
void bench_desc_init(const bench_settings *b, stin_desc *desc);

/* Runs the measurement. Returns 1, or 0 with a message in err. */
int bench_run(const bench_settings *b, stin_tier tier, const scene *s, bench_result *out,
              char *err, size_t err_size);

#endif
