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

#endif
