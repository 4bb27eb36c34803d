/* SPDX-License-Identifier: MIT */
/* Translucent shadows' own state (translucent/deep.c, translucent/coloured.c,
 * and translucent/translucent.c, which asks both): nothing outside this
 * folder includes this header (tools/check-layers.sh). */
#ifndef STIN_TRANSLUCENT_PRIVATE_H
#define STIN_TRANSLUCENT_PRIVATE_H

#include "internal.h"

typedef struct stin__deep_state {
    /* Layer k of face f lives in layers[k % 2] at slice f * slices + k / 2
     * (RGBA32F: depth, visibility RGB): the pass drawing layer k reads layer
     * k - 1 from the other texture (ping-pong, no feedback loop). */
    GLuint layers[2];
    GLuint depth;          /* the peel passes' depth test (DEPTH_COMPONENT24) */
    GLuint fbo, program, query;
    GLuint flag;           /* GL 4.3: the early stop's storage flag (then no query) */
    int flagged;           /* the program sets the flag (deep_peel_flag.frag) */
    GLint u_model, u_view_proj, u_albedo, u_albedo_tex, u_has_albedo_tex, u_previous,
        u_previous_slice, u_mono;
    stin__displace_locs displace;
    uint32_t size;         /* texels a side of a face */
    uint32_t layer_cap;    /* desc.translucent.deep_layers */
    uint32_t slices;       /* per face and texture: ceil(layer_cap / 2) */
    int unit;              /* two texture units: even, odd layers */
    int ready;             /* set up: transparent casters leave the shadows technique */
    int frame_transparent; /* this frame has transparent draws */
    int kind;              /* the light being shaded: 0 no map, 1 one face, 2 six */
    float matrix[STIN__DEEP_FACES][16]; /* world -> [0,1] window coordinates per face */
    GLint face_layers[STIN__DEEP_FACES]; /* layers the lookup reads per face: those
                                          * peeled before an empty one, 0 for a face
                                          * no transparent caster reaches */
    float normal_offset;   /* world units per unit clip w: 1.5 texels */
    int said_area;         /* logged that area lights cast from their centre here */
} stin__deep_state;

/* Colour maps ("coloured"): faces of translucent.deep_map_size in a 3 x 2 atlas (face
 * f at column f % 3, row f / 3), RGBA8 transmittance and the nearest
 * transparent depth. */
typedef struct stin__coloured_state {
    GLuint color, depth, fbo, program;
    GLint u_model, u_view_proj, u_albedo, u_albedo_tex, u_has_albedo_tex;
    stin__displace_locs displace;
    uint32_t size;         /* texels a side of a face */
    int unit;              /* two texture units: transmittance, depth */
    int ready;             /* set up: transparent casters leave the shadows technique */
    int frame_transparent; /* this frame has transparent draws */
    int kind;              /* the light being shaded: 0 no map, 1 one face, 2 six */
    float matrix[STIN__DEEP_FACES][16]; /* world -> [0,1] window coordinates per face */
    float normal_offset;   /* world units per unit clip w: 1.5 texels */
    int said_area;         /* logged that area lights cast from their centre here */
} stin__coloured_state;

#endif
