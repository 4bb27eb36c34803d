/* SPDX-License-Identifier: MIT */
/* The renderers the peers section compares, behind one interface: a stin
 * context forced to one shadow technique, or an osgShadow technique
 * (osgshadow_shim.h, where stin-bench is built with it), each drawing one
 * scene into the bench's framebuffer. */
#ifndef STIN_BENCH_PEERS_ROWS_H
#define STIN_BENCH_PEERS_ROWS_H

#include "bench_section.h"
#include "peers_vis.h"
#include "scene_gpu.h"

/* What a frame draws: the row's shadows, the row without its casters, with
 * everything it can shadow in shadow (osgShadow), or stin's visibility
 * output. */
enum { PEER_SHADOWED, PEER_UNSHADOWED, PEER_FULL, PEER_VISIBILITY };

typedef struct peer_row {
    char name[48];
    int osg;                 /* 0: stin, `technique` a stin_technique; 1: OSGS_* */
    int technique;
    uint64_t debug_flags;    /* stin's desc.debug_flags */
    stin_context *ctx;
    void *block;
    scene_gpu gpu;
    struct osgs_peer *peer;
    double ms;               /* median frame, glFinish included */
    int failed;              /* 1: no times; why says so */
    char why[256];
    peers_mismatch mm;       /* against the reference */
    long disagree;           /* stin rows: classified against its visibility output */
    int staged;              /* stage_ms holds stin's GPU time per stage (medians) */
    double stage_ms[STIN_STAGE_COUNT];
    char note[160];          /* the default row: what its measured choice settled on */
} peer_row;

/* Creates the row's renderer for s at the bench's size (rows are memset
 * first, name/osg/technique set by the caller); a failure sets failed and
 * why. map_size: texels a side of every map. */
void peer_row_create(peer_row *r, const bench_env *env, scene *s, int map_size);
/* One frame of `mode` (the caller's scene lights: stin reads them per frame)
 * and glFinish: its milliseconds, or -1 with why set. */
double peer_row_frame(peer_row *r, const bench_env *env, int mode);
void peer_row_destroy(peer_row *r);
/* stin rows: stage_ms from a second context with STIN_DEBUG_STAGE_TIMES
 * (peers_stages.c); staged stays 0 without timer queries. */
void peer_row_stages(peer_row *r, const bench_env *env, scene *s, int map_size, int frames);

/* The default row, after its timed frames: note says which technique the
 * measured choice settled on and each candidate's smoothed ms. */
void peer_row_settled(peer_row *r);

/* Why osgShadow does not run here, or NULL where it does. */
const char *peer_osg_absent(const bench_env *env);

#endif
