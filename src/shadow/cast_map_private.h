/* SPDX-License-Identifier: MIT */
/* The casters' map's own state (shadow/cast_map.c, and its GL1 passes in
 * shadow/cast_map_fixed.c): nothing outside src/shadow/ includes this
 * header (tools/check-layers.sh). */
#ifndef STIN_SHADOW_CAST_MAP_PRIVATE_H
#define STIN_SHADOW_CAST_MAP_PRIVATE_H

#include "internal.h"

/* A program with the map test (cast_test.glsl): the marking pass's (its
 * model and camera) or vdsm's mask pass's (its position buffer). */
typedef struct stin__mark_program {
    GLuint name;
    GLint u_model, u_view_proj, u_position, u_matrix, u_params, u_light, u_faces, u_map;
    stin__displace_locs displace;
} stin__mark_program;

/* A light's map as GL1's marking pass reads it: with FBOs the shared atlas
 * (drawn just before the light's count), without them a texture per face
 * of its own, copied out of the frame's buffer in the light pre-pass. */
typedef struct stin__cast_light {
    GLuint copies[STIN__CUBE_FACES]; /* without FBOs: each face's map (0: none made yet) */
    uint32_t copy_size;              /* their texels a side */
    int copy_faces;                  /* how many of them have an image */
    int faces;                       /* 1, or a point light's 6 */
    unsigned drawn;                  /* bit f: face f holds products */
    float matrix[STIN__CUBE_FACES][16]; /* world -> its map's texture coordinates */
    float window[STIN__CUBE_FACES][16]; /* world -> the face's own [0, 1] window */
    float ramp[STIN__CUBE_FACES][4];    /* map-combine: a receiver's own ramp coordinate */
} stin__cast_light;

struct stin__cast_map_state {
    GLuint texture, fbo;
    stin__mark_program mark, mark_tess; /* the pass, and its tessellated twin (displace-tess) */
    stin__mark_program mask;            /* vdsm's: the test into its screen mask */
    uint32_t size;         /* a cell's texels a side */
    int fixed;             /* volumes' marking pass is the fixed-function path's (GL1) */
    int copied;            /* GL1 without FBOs: the maps drawn before the frame's clear */
    int ramp;              /* ... as map-combine's ramp of depths (no depth textures) */
    int drawn;             /* the map holds the casters of the light being counted */
    int displaced;         /* it casts the displaced draws too (volumes', not vdsm's) */
    int faces;             /* its cells: 1, or a point light's 6 */
    float matrix[STIN__CUBE_FACES][16]; /* world -> [0,1] atlas space, per cell */
    float light[3];        /* a point light's position */
    uint32_t kernel;       /* its light's pcf_kernel */
    uint32_t said_light;   /* bit li: what casts light li's products was logged */
    /* GL1 (shadow/cast_map_fixed.c) */
    GLuint face_mask;      /* 1 inside a face's square, 0 around it */
    GLuint front;          /* 1D: 0 behind a face's plane, 1 in front of it */
    GLuint ramp_texture;   /* map-combine's ramp */
    int face_units;        /* the units a point light's faces need are there */
    uint32_t copy_size;    /* without FBOs: this frame's face size (the viewport bounds it) */
    uint32_t current;      /* the light being counted */
    stin__cast_light lights[STIN__MAX_LIGHTS];
};

/* shadow/cast_map.c: the frame's surfaces (its opaque draws and the
 * products' faces) through program p, or the fixed-function path (NULL). */
void stin__cast_map_receivers(stin_context *ctx, const stin__mark_program *p);

/* shadow/cast_map_fixed.c: init makes the GL1 textures (the faces' tests,
 * map-combine's ramp); release deletes them and the copies. prepass: the
 * light pre-pass without FBOs, every light's map drawn and copied. cell:
 * with FBOs, what draw_cell drew into cell `cell` for the light being
 * counted (window: its [0, 1] window matrix, into: the atlas's). mark:
 * the marking pass of the light being counted, face by face. */
void stin__cast_fixed_init(stin_context *ctx);
void stin__cast_fixed_release(stin_context *ctx);
void stin__cast_fixed_cell(stin_context *ctx, int cell, const float window[16],
                           const float into[16], int drew);
void stin__cast_fixed_mark(stin_context *ctx);

#endif
