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
     * light sees, copied from the colour of a pass of their own (with FBOs:
     * facing_fbo, RGBA8 colour and a depth): facing, lit where the eye sees
     * a front face (LUMINANCE8, INTENSITY8 with the terminator test: 1
     * front or no surface, 0 back), and facing_back, lit where it sees a
     * back face (LUMINANCE8: 1 back or no surface, 0 front) */
    GLuint facing[STIN__MAP_SLOTS];
    GLuint facing_back[STIN__MAP_SLOTS];
    GLuint facing_fbo, facing_color, facing_depth;
    int facing_test;      /* 1: the lit passes test the side (a unit was spare) */
    /* 1: the terminator test (shadow/map_terminator.c; FBOs, and a unit
     * spare after the side test's and the faces' mask): second-depth maps
     * for closed solids, a side map of their shading normals */
    int terminator;
    float lift[STIN__MAP_SLOTS]; /* its far-side margin, in the map's depth */
    /* the margin in the world, at the far plane: a solid thinner than it
     * keeps the facet (its lit side would compare with its own far side
     * within the margin) */
    float solid_min[STIN__MAP_SLOTS];
    uint32_t slot; /* the map the lit pass tests */
    int eye_back;                /* the lit pass draws the faces the eye sees from behind */
    int receiver;                /* the rule the units hold: 1 a solid's, 0 the facet */
    uint32_t size;        /* allocated texels a side */
    uint32_t used;        /* rendered this frame (no FBO: bounded by the viewport) */
    int unit;             /* first texture unit of the shadow test */
    int faces;            /* point lights get six maps (needs FBOs: drawn mid-frame) */
    unsigned char valid[STIN__MAX_LIGHTS];
    float texgen[STIN__MAP_SLOTS][16];   /* world -> map texture coordinates (rows s t r q) */
    float ramp_plane[STIN__MAP_SLOTS][4]; /* world -> ramp coordinate (map-combine) */
    int said_point, said_area;
};


/* map-depth's terminator test (shadow/map_terminator.c). units: the units
 * it takes after the side map's; lift stores slot's margins; side_draw
 * draws the side pass's casters (open ones in the side colours set, solids
 * by light l's shading normal); bind / unbind put slot's test on its units;
 * side sets the units for the eye's side (1: back faces) and each receiver
 * after. */
int stin__map_terminator_units(void);
/* Whether the test runs (units: those the map takes from its first on, the
 * side test's and the faces' mask among them); logged where it does not. */
void stin__map_terminator_init(stin_context *ctx, int units);
void stin__map_terminator_lift(stin_context *ctx, uint32_t slot, const float proj[16], float n,
                               float f, float units);
void stin__map_terminator_side_draw(stin_context *ctx, uint32_t slot, const stin_light_desc *l,
                                    const float view[16], const float proj[16]);
void stin__map_terminator_bind(stin_context *ctx, uint32_t slot);
void stin__map_terminator_side(stin_context *ctx, int back);
void stin__map_terminator_unbind(stin_context *ctx);

#endif
