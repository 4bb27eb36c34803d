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
    /* GL 1.1 (shadow/cast_readback.c): the products' depth from the light
     * read back, tested per pixel of the frame on the CPU */
    int cpu;               /* volumes cast through read-backs */
    uint32_t cpu_cap;      /* the images' largest side (the slot was sized for it) */
    uint32_t cpu_size;     /* this light's images' side */
    int cpu_faces;         /* 1, or a point light's 6 */
    unsigned cpu_drawn;    /* bit f: face f holds products */
    float cpu_matrix[STIN__CUBE_FACES][16]; /* world -> face f's window [0, 1] cube */
    float *cpu_images;     /* after the struct in the slot: six faces' depths */
    float *cpu_corner;     /* the frame's depth under the images while they are drawn */
    unsigned char *cpu_rows; /* a band of the frame: its depth, then the decisions */
    int said_cpu_wide;     /* a viewport wider than the band was logged */
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
/* The products seen from light l (view, proj) into the depth of the frame's
 * buffer at map_vp (cleared first; scissored to it, colour writes off, the
 * light's offset); 1 if any drew. */
int stin__cast_fixed_products(stin_context *ctx, const stin_light_desc *l, const int map_vp[4],
                              const float view[16], const float proj[16]);
/* proj cropped to the rectangle the products' bounds cover in a map of
 * `size` texels a side, [n, f] narrowed to their depths (shadow/cast_map_fixed.c). */
void stin__cast_fixed_focus(const stin_context *ctx, uint32_t size, const float view[16],
                            float proj[16], float *n, float *f);

/* shadow/cast_readback.c (GL 1.1): bytes its slot part needs for desc d;
 * init places it after the state (logs the choice); draw: light li's
 * images from the light, mid-frame (1 if any product drew); mark: after
 * the count, the stencil set to 0x80 where they shadow the frame's depth. */
size_t stin__cast_readback_bytes(const stin_desc *d);
void stin__cast_readback_init(stin_context *ctx);
int stin__cast_readback_draw(stin_context *ctx, uint32_t li);
void stin__cast_readback_mark(stin_context *ctx);

#endif
