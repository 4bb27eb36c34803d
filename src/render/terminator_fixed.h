/* SPDX-License-Identifier: MIT */
/* The fixed-function path's terminator band (render/terminator_fixed.c). */
#ifndef STIN_RENDER_TERMINATOR_FIXED_H
#define STIN_RENDER_TERMINATOR_FIXED_H

#include "render/path.h"

struct stin_context;

/* path->terminator_band without a fragment shader (path.h says what it
 * draws): each triangle is kept or left out on the CPU, its band
 * fragments told by the alpha test. */
void stin__fixed_terminator_band(struct stin_context *ctx, const stin__draw *d,
                                 const float light[4], const uint32_t *tris, uint32_t n);

/* What a band triangle's facts need of the frame and draw: the eye and the
 * normal matrix (0 where the view does not invert). */
typedef struct stin__band_view {
    float eye[3];
    float normal_matrix[9];
} stin__band_view;
int stin__band_view_init(const struct stin_context *ctx, const stin__draw *d,
                         stin__band_view *bv);

/* Whether triangle tri (3 indices of d's mesh) may hold band fragments for
 * light (w 0: a direction): the facet turned from the light on the side
 * the eye sees, every corner's normal on that side, the curved surface
 * above the facet, some corner's normal toward the light. The GLSL band
 * without derivatives draws only these (terminator_band.frag). */
int stin__band_triangle(const struct stin_context *ctx, const stin__band_view *bv,
                        const stin__draw *d, const float light[4], const uint32_t *tri);

#endif
