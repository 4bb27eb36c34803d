/* SPDX-License-Identifier: MIT */
/* The stage timestamps' own state (gl/stage_times.c): nothing outside
 * src/gl/ includes this header (tools/check-layers.sh). */
#ifndef STIN_GL_STAGE_TIMES_PRIVATE_H
#define STIN_GL_STAGE_TIMES_PRIVATE_H

#include "internal.h"

struct stin__stage_times {
    GLuint queries[STIN__STAGE_MARKS]; /* made at stin_create where on */
    int on;                      /* STIN_DEBUG_STAGE_TIMES and timer queries */
    unsigned char stage[STIN__STAGE_MARKS]; /* the stage each timestamp opens */
    uint32_t marks;              /* taken this frame */
    stin_stage current;
    int said_full;
};

#endif
