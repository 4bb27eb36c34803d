/* SPDX-License-Identifier: MIT */
/* Camera transparency's own state (transparency/peel.c, dual_peel.c,
 * sorted.c): nothing outside this folder includes this header
 * (tools/check-layers.sh). */
#ifndef STIN_TRANSPARENCY_PRIVATE_H
#define STIN_TRANSPARENCY_PRIVATE_H

#include "internal.h"

/* dual-peel's own objects; the layer's depth, ambient and lights, the
 * opaque depth, the framebuffers and the query are depth-peel's. */
typedef struct stin__dual_state {
    GLuint minmax[2];      /* pass k's (-near, far) per pixel (RG32F) is minmax[k % 2] */
    GLuint front[2];       /* front layers' composite (C, T), under, ping-pong (RGBA16F) */
    GLuint back[2];        /* back layers' composite (C, T), over, ping-pong (RGBA16F) */
    GLuint minmax_fbo;
    GLuint program[2];     /* the min-max pass: plain, tessellated (0: not built) */
    stin__displace_locs displace[2];
    GLint u_model[2], u_view_proj[2], u_previous[2], u_opaque[2], u_params[2];
    GLint u_back;          /* the composite program's back composite */
    int front_result, back_result; /* front[front_result], back[back_result] hold them */
    int drawn;             /* the layer begun last drew something */
    int back_empty;        /* the last back layer drew nothing: no pass would find more */
} stin__dual_state;

typedef struct stin__peel_state {
    /* Layer k's depth (and stencil, for volumes) is depth[k % 2] (layer 0's:
     * first, kept for the frame's depth at the end): its pass reads layer
     * k - 1's from another texture (no feedback loop). */
    GLuint depth[2], first;
    GLuint opaque;         /* the opaque draws' depth: layers lie in front of it */
    GLuint ambient;        /* a layer's ambient colour and opacity (RGBA8) */
    GLuint lights;         /* a layer's lights added up (RGBA8) */
    GLuint accum[2];       /* the composite so far, (C, T) front to back, ping-pong */
    GLenum accum_format;   /* accum's: RGBA16F on GL4 (with float textures), else RGBA8 */
    GLuint fbo, composite_fbo, program, query;
    int counting;          /* the layer's query began (not under a caller's) */
    GLint u_ambient, u_lights, u_accum, u_first, u_params;
    int width, height;     /* allocated texels (0: not yet) */
    int unit;              /* two units: the previous layer's depth, the opaque depth */
    int ready;             /* set up: depth-peel runs */
    int layer;             /* the layer drawn last (-1: none yet) */
    int peeling;           /* 1 while a layer is drawn: camera passes draw it */
    int result;            /* accum[result] holds the composite */
    GLuint frame_fbo;      /* the frame's target, bound back at the end */
    const stin__path *path; /* the frame's path (the coverage pass draws through it) */
    int coverage;          /* the last quad colours the covered samples alone (peel_coverage.c) */
    int said_failed;
    int said_sorted, said_sorted_unshadowed, said_sorted_light; /* "sorted": what was said */
    int dual;              /* the technique is dual-peel (its state below) */
    stin__dual_state d;
} stin__peel_state;

#endif
