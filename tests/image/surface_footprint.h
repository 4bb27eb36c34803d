/* SPDX-License-Identifier: MIT */
/* The uv derivatives GL's sampler takes for a pixel (surface_test.c), for
 * the surface rows' references (surface_test.c, msaa_surface_test.c). */
#ifndef STIN_TESTS_SURFACE_FOOTPRINT_H
#define STIN_TESTS_SURFACE_FOOTPRINT_H

#include "reference_surface.h"

/* Pixel (x, y) (window, bottom-up) of a w x h frame on hit's plane: the
 * differences across its 2x2 quad (see surface_test.c); tech >= 0: the uv
 * moved by that REF_SURFACE_* technique (GL2's texture2D), < 0 unmoved
 * (GL4's textureGrad); low: the quad's lower-left pixel as its corner.
 * 0 where a quad pixel's ray runs along the plane. */
int surface_footprint(const scene *s, const reference *ref, const ref_surface *rs, int w, int h,
                      int x, int y, const ref_hit *hit, int tech, int low, ref_footprint *fp);

#endif
