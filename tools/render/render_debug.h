/* SPDX-License-Identifier: MIT */
/* stin-render --debug: pictures of what the shadows are made of
 * (render_debug.c). */
#ifndef STIN_RENDER_DEBUG_H
#define STIN_RENDER_DEBUG_H

#include "scene_gpu.h"
#include "stin_platform.h"

enum {
    RENDER_DEBUG_SHADOW_MAP = 1, /* each light's shadow map, <output>-shadow-map-<i>.png */
    RENDER_DEBUG_VOLUMES = 2,    /* the volumes over the beauty (STIN_DEBUG_VOLUME_SHOW) */
    RENDER_DEBUG_MASKS = 4       /* the lights' visibility map, <output>-masks.png */
};

/* A --debug value's bit, 0 if unknown. */
unsigned render_debug_parse(const char *name);
/* After the outputs' frames: the images of `kinds` next to `output`, one
 * "wrote" line each (or a line saying why a light has none). 1 on success. */
int render_debug_write(unsigned kinds, const char *output, const scene_gpu *g,
                       stin_context *ctx, stin_platform *p, char *err, size_t err_size);

#endif
