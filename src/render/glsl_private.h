/* SPDX-License-Identifier: MIT */
/* The GLSL path's own state (render/path_glsl.c, render/lit_specialise.c):
 * its lit programs, the per-frame lit uniforms they share, the specialised
 * ones and the tessellated twins. Nothing outside src/render/ includes this
 * header (tools/check-layers.sh); other folders go through render/path.h. */
#ifndef STIN_RENDER_GLSL_PRIVATE_H
#define STIN_RENDER_GLSL_PRIVATE_H

#include "internal.h"

/* Lit programs specialised to a light batch and a material (render/lit_specialise.c):
 * lit.frag with the batch's light count as its loop bound and only the parts
 * of the equation the batch and material use, built when a pass first needs
 * one and kept across frames, STIN__LIT_CACHE of them (no heap). */
typedef struct stin__lit_cache {
    stin__program programs[STIN__LIT_CACHE]; /* name 0: its build failed (the general one) */
    uint32_t keys[STIN__LIT_CACHE];
    uint32_t used[STIN__LIT_CACHE]; /* the frame it last served */
    uint32_t count, frame;
    int said_full;            /* a frame found every slot in use (logged once) */
} stin__lit_cache;

struct stin__glsl_state {
    /* lit programs per surface variant; [STIN__SURF_PLAIN] is unused (the
     * plain one is programs[STIN__PROG_LIT]) */
    stin__program lit[STIN__SURF_COUNT];
    int best;             /* best variant built (STIN__SURF_*) */
    const stin__program *current; /* lit program in use this pass, NULL = other */
    uint32_t serial;      /* bumped when the per-frame lit uniforms change */
    float packed[4 * 4 * STIN__LIGHTS_PER_PASS]; /* the lights last uploaded */
    int light_n, with_ambient;
    uint32_t light_key;   /* their stin__lit_lights_key */
    stin__lit_cache lit_cache; /* lit programs per light batch and material */
    struct {              /* "displace-tess": the programs above, tessellated,
                           * swapped in for frames with displaced draws */
        stin__program programs[STIN__PROG_COUNT];
        stin__program lit[STIN__SURF_COUNT];
        int active;       /* they are in ctx->programs and lit now */
    } tess;
};

#endif
