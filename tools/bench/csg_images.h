/* SPDX-License-Identifier: MIT */
/* The CSG section's image check (section_csg.c): a frame of each side read
 * back and compared, so a row can say whether OpenCSG's picture is the one
 * stin draws (stin's is proven against the exact reference by the image
 * tests). */
#ifndef STIN_BENCH_CSG_IMAGES_H
#define STIN_BENCH_CSG_IMAGES_H

#include "stin_platform.h"

#include <stdint.h>

/* A channel differs by more than this (of 255): the two shadings round
 * alike and differ by a few steps at most; a wrong surface differs by far
 * more. */
#define CSG_IMAGE_STEP 24

/* Two readbacks of the bound framebuffer, width x height RGBA each. */
typedef struct csg_images {
    uint8_t *a, *b;
    int width, height;
} csg_images;

int csg_images_alloc(csg_images *im, int width, int height);
void csg_images_release(csg_images *im);
/* Reads the framebuffer into a (side 0) or b (side 1); 0 on failure. */
int csg_images_read(csg_images *im, stin_platform *plat, int side);
/* Of the pixels either image covers (not the black clear colour), the
 * share in per mille where a channel differs by more than CSG_IMAGE_STEP
 * there and at the four neighbours (a wrong area; an edge rasterised a
 * pixel apart is not counted); *covered gets their count. */
double csg_images_differ(const csg_images *im, uint32_t *covered);

#endif
