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

double csg_images_differ(const csg_images *im, uint32_t *covered)
{
    size_t i, n = (size_t)im->width * (size_t)im->height;
    uint32_t any = 0, off = 0;
    for (i = 0; i < n; i++) {
        const uint8_t *p = im->a + 4u * i, *q = im->b + 4u * i;
        int k, far = 0;
        if (!covers(p) && !covers(q))
            continue;
        any++;
        for (k = 0; k < 3; k++)
            far |= abs((int)p[k] - (int)q[k]) > CSG_IMAGE_STEP;
        off += (uint32_t)far;
    }
    *covered = any;
    return any ? 1000.0 * (double)off / (double)any : 0.0;
}
