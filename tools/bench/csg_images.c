/* SPDX-License-Identifier: MIT */
/* Reading back and comparing the CSG section's two pictures. */
#include "csg_images.h"

#include <stdlib.h>

int csg_images_alloc(csg_images *im, int width, int height)
{
    size_t bytes = (size_t)width * (size_t)height * 4u;
    im->width = width;
    im->height = height;
    im->a = (uint8_t *)malloc(bytes);
    im->b = (uint8_t *)malloc(bytes);
    if (im->a && im->b)
        return 1;
    csg_images_release(im);
    return 0;
}

void csg_images_release(csg_images *im)
{
    free(im->a);
    free(im->b);
    im->a = im->b = NULL;
}

int csg_images_read(csg_images *im, stin_platform *plat, int side)
{
    return stin_platform_read_color(plat, side ? im->b : im->a);
}

static int covers(const uint8_t *p) { return p[0] | p[1] | p[2]; }

static int differs(const csg_images *im, size_t i)
{
    const uint8_t *p = im->a + 4u * i, *q = im->b + 4u * i;
    int k;
    for (k = 0; k < 3; k++)
        if (abs((int)p[k] - (int)q[k]) > CSG_IMAGE_STEP)
            return 1;
    return 0;
}

double csg_images_differ(const csg_images *im, uint32_t *covered)
{
    int w = im->width, h = im->height, x, y;
    uint32_t any = 0, off = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t i = (size_t)y * (size_t)w + (size_t)x;
            if (!covers(im->a + 4u * i) && !covers(im->b + 4u * i))
                continue;
            any++;
            /* off with its four neighbours: a wrong area, not an edge the
             * two rasterise a pixel apart (an edge pixel off at the border
             * counts, its outside neighbours taken as off) */
            off += (uint32_t)(differs(im, i) && (x == 0 || differs(im, i - 1u)) &&
                              (x == w - 1 || differs(im, i + 1u)) &&
                              (y == 0 || differs(im, i - (size_t)w)) &&
                              (y == h - 1 || differs(im, i + (size_t)w)));
        }
    *covered = any;
    return any ? 1000.0 * (double)off / (double)any : 0.0;
}
