/* SPDX-License-Identifier: MIT */
/* The peers section's mismatch against the exact reference: per pixel the
 * visibility of light 0 that a frame shows, either read from stin's
 * visibility output or classified from a renderer's shadowed, unshadowed
 * and full-shadow frames, compared with the Embree reference's. */
#ifndef STIN_BENCH_PEERS_VIS_H
#define STIN_BENCH_PEERS_VIS_H

#include "scene.h"

#include <stdint.h>

/* A channel step under which the light's share of a pixel is too small to
 * tell lit from shadowed (of 255, the largest channel of stin's unshadowed
 * frame minus its ambient-only frame). */
#define PEERS_VIS_MIN_SHARE 8

/* The reference of one scene at one size, and which pixels are judged. */
typedef struct peers_ref {
    int width, height;
    float *image;     /* reference_render: REFERENCE_CHANNELS per pixel */
    void *hits;       /* ref_hit per pixel */
    uint8_t *judged;  /* 1: hit, light 0 reaches the side seen, and its share of
                       * the pixel is at least PEERS_VIS_MIN_SHARE */
    long judged_n;
} peers_ref;

/* Mismatch of one frame's visibility on the judged pixels. */
typedef struct peers_mismatch {
    long wrong;       /* judged pixels whose visibility is not the reference's */
    long far;         /* of those, more than one pixel from a shadow edge */
    double wrong_pct, far_pct; /* of the image's pixels */
} peers_mismatch;

/* Builds the reference of s (light 0) at width x height; `unshadowed` and
 * `ambient` are stin's frames (RGBA8, rows bottom to top) without shadows
 * and without the light. 0 with the reason in err. */
int peers_ref_create(peers_ref *r, const scene *s, int width, int height,
                     const uint8_t *unshadowed, const uint8_t *ambient, char *err,
                     size_t err_size);
void peers_ref_release(peers_ref *r);

/* Visibility per pixel (1 lit, 0 shadowed) from three frames of one
 * renderer: `frame` is nearer its unshadowed frame than its full-shadow
 * frame; where those two agree the renderer cannot shadow the pixel (lit). */
void peers_classify(const uint8_t *frame, const uint8_t *unshadowed, const uint8_t *full,
                    int n, uint8_t *vis);
/* Visibility per pixel from stin's STIN_OUTPUT_VISIBILITY frame. */
void peers_vis_output(const uint8_t *output, int n, uint8_t *vis);

/* vis against the reference on the judged pixels. */
void peers_mismatch_of(const peers_ref *r, const uint8_t *vis, peers_mismatch *out);
/* Judged pixels where a and b differ (the classifier against stin's own
 * answer). */
long peers_disagree(const peers_ref *r, const uint8_t *a, const uint8_t *b);

#endif
