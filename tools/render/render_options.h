/* SPDX-License-Identifier: MIT */
/* stin-render's command line (render_options.c). */
#ifndef STIN_RENDER_OPTIONS_H
#define STIN_RENDER_OPTIONS_H

#include "stin/stin.h"

#include <stdint.h>
#include <stdio.h>

enum { EXIT_FAILED = 1, EXIT_BAD_INPUT = 2, EXIT_UNSUPPORTED = 3 };

/* Triangles one frame may draw (instances x triangles, summed over the
 * objects) unless --max-triangles says otherwise: about 20 s a frame of
 * shadow volumes on a software rasteriser, and the tool renders three. */
#define RENDER_MAX_TRIANGLES_DEFAULT (16u << 20)

/* Scenes one run renders in turn (--no-output only beyond the first). */
#define RENDER_MAX_SCENES 64

typedef struct options {
    const char *scenes[RENDER_MAX_SCENES]; /* the scene files given, in order */
    int scene_count;
    const char *scene_path, *output, *profile, *platform, *shadows, *surface, *csg;
    uint64_t debug_flags;
    unsigned debug_outputs;     /* RENDER_DEBUG_* (render_debug.h) */
    uint32_t shadow_map_size;   /* 0: the scene's, else stin's default */
    uint64_t max_triangles;     /* work limit; 0 = none */
    stin_tier tier;
    int width, height, caps, verbose;
    int samples;                /* --samples: the target's samples (0: single-sampled) */
    int no_output;              /* --no-output: render and print statistics only */
    int progress;               /* --progress: progress lines even when stderr is no terminal */
    int frame;                  /* --frame: fit the camera to the scene's bounds */
    int srgb;                   /* --srgb: render into an sRGB colour target */
    float outline;              /* --outline: the filter's step in pixels (0: none) */
} options;

void render_usage(FILE *f);
/* Parses argv into *o; on a bad option prints one line to stderr and returns 0. */
int render_parse_args(int argc, char **argv, options *o);
/* --shadows/--surface/--csg: a technique name of that feature, or "auto". */
int render_parse_technique(const char *name, stin_feature f, stin_technique *out);

#endif
