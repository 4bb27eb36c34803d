/* SPDX-License-Identifier: MIT */
/* What the multisampled-target tests share (msaa_common.c) beside
 * msaa_shared.h's target and frame: the exact reference shaded at them and box-filtered as
 * the resolve averages them, and the comparison that separates the
 * silhouette band (pixels within one of a change of object among the
 * samples) from the rest. */
#ifndef STIN_TESTS_MSAA_COMMON_H
#define STIN_TESTS_MSAA_COMMON_H

#include "image_test.h"
#include "msaa_shared.h"
#include "reference.h"
#include "scene.h"

#include <stdint.h>

typedef struct msaa_ref {
    int w, h, n;
    ref_hit *hits;   /* n images of w x h, bottom row first */
    float *colour;   /* w x h x 3: the samples' mean */
    float *vis;      /* n x w x h: every light's visibility at each sample */
    unsigned char *centre_differs; /* w x h: a sample's surface, taken on to the pixel
                                    * centre, has another visibility there */
    int unshadowed; /* set before shading: the lights unshadowed (shadows off) */
} msaa_ref;

/* m emptied, sized to the scene (no arrays yet). */
void msaa_ref_init(msaa_ref *m, const scene *s);
/* m->w, m->h set: the arrays for n samples (1, or 0 out of memory). */
int msaa_ref_alloc(msaa_ref *m, int n);
/* m->hits filled (sample k's image at hits + k w h): each sample shaded
 * into colour, vis and centre_differs; at_centre: where multisampling
 * shades, its surface taken on to the pixel centre (one fragment a surface
 * a pixel); MSAA_AT_CENTRE_INSIDE: so where that point lies on the
 * sample's triangle, else at the sample (a CSG product's faces: the point
 * beyond a triangle's edge lies inside the solid, whose rays it shadows,
 * where stin's map lookup is biased). */
#define MSAA_AT_CENTRE_INSIDE 2
void msaa_ref_shade(const scene *s, const reference *ref, int per_vertex, int at_centre,
                    msaa_ref *m);
void msaa_ref_free(msaa_ref *m);
/* m sized (msaa_ref_init): the reference of s (facets: reference.h's
 * terminator rule) cast and shaded (at_centre 1) at the n sample positions;
 * an area light integrated over 64 directions, enough to tell the
 * penumbra (left out of the band) from umbra and light at an eighth of
 * the default's cost. 1, or 0 (err). */
int msaa_ref_build(const scene *s, int facets, int per_vertex, const float pos[][2], int n,
                   msaa_ref *m, char *err, size_t err_size);

typedef struct msaa_band {
    long band, over, compared, compared_over;
    double band_max, compared_max;
} msaa_band;

/* rgba: the resolved frame, w x h rows bottom first, stride pixels a row;
 * pixels by a shadow edge left out (the shadow tests' business). */
void msaa_compare_band(const msaa_ref *m, const uint8_t *rgba, int stride, double tolerance,
                       msaa_band *b);

/* A row's bounds: a pixel is over beyond tolerance (max channel); at most
 * max_band_over of the band (which must hold more than 100) and
 * max_over_fraction of the rest. */
typedef struct msaa_bounds {
    double tolerance;
    int max_band_over;
    double max_over_fraction;
} msaa_bounds;

/* The frame against m under bd: one PASS/FAIL line as `name`, the pair
 * saved on failure. */
void msaa_report_band(run *r, const char *name, const msaa_ref *m, const uint8_t *rgba,
                      const msaa_bounds *bd);

/* Builds a row's reference into m (sized, m->n set): 1, or 0 (err). */
typedef int (*msaa_ref_fn)(const void *ctx, msaa_ref *m, char *err, size_t err_size);
/* One row as `name`: the frame of t (SKIP or FAIL where it did not
 * render), its reference from build over n samples, compared under bd. */
void msaa_row(run *r, const scene *s, const msaa_techniques *t, const char *name, int n,
              msaa_ref_fn build, const void *ctx, const msaa_bounds *bd);

#endif
