/* SPDX-License-Identifier: MIT */
/* map-depth and map-combine's own state (shadow/map_fixed.c,
 * shadow/map_facing.c): nothing outside src/shadow/ includes this header
 * (tools/check-layers.sh). */
#ifndef STIN_SHADOW_MAP_FIXED_PRIVATE_H
#define STIN_SHADOW_MAP_FIXED_PRIVATE_H

#include "internal.h"

struct stin__map_fixed_state {
    GLuint textures[STIN__MAP_SLOTS];
    GLuint ramp;          /* map-combine: 1D ramp of light depth */
    GLuint fbo;           /* with FBOs: render straight into the texture */
    GLuint depth_scratch; /* map-combine with FBOs: the depth buffer of its pass */
    GLuint face_mask;     /* 1 inside a face's 90-degree square, 0 outside */
    /* map-depth's side maps: per slot, which side of the nearest surface the
     * light sees (LUMINANCE8: 1 front, 0 back), copied from the colour of a
     * pass of their own (with FBOs: facing_fbo, RGBA8 colour and a depth) */
    GLuint facing[STIN__MAP_SLOTS];
    GLuint facing_fbo, facing_color, facing_depth;
    int facing_test;      /* 1: the lit passes test the side (a unit was spare) */
    uint32_t size;        /* allocated texels a side */
    uint32_t used;        /* rendered this frame (no FBO: bounded by the viewport) */
    int unit;             /* first texture unit of the shadow test */
    int faces;            /* point lights get six maps (needs FBOs: drawn mid-frame) */
    unsigned char valid[STIN__MAX_LIGHTS];
    float texgen[STIN__MAP_SLOTS][16];   /* world -> map texture coordinates (rows s t r q) */
    float ramp_plane[STIN__MAP_SLOTS][4]; /* world -> ramp coordinate (map-combine) */
    int said_point, said_area;
};

#endif
