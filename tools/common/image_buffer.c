/* SPDX-License-Identifier: MIT */
/*
 * image_io.h's in-memory half: allocation and channel lookup, the same
 * whichever file backend (OpenImageIO, or none) the build links.
 */
#include "image_io.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define IMAGE_MAX_CHANNELS ((int)(sizeof(((image *)0)->channel_names) / sizeof(((image *)0)->channel_names[0])))

int image_alloc(image *img, int width, int height, int channels)
{
    memset(img, 0, sizeof *img);
    if (width <= 0 || height <= 0 || channels <= 0 || channels > IMAGE_MAX_CHANNELS ||
        (size_t)width > SIZE_MAX / sizeof(float) / (size_t)height / (size_t)channels)
        return 0;
    img->pixels = calloc((size_t)width * (size_t)height * (size_t)channels, sizeof(float));
    if (!img->pixels)
        return 0;
    img->width = width;
    img->height = height;
    img->channels = channels;
    return 1;
}

void image_free(image *img)
{
    free(img->pixels);
    memset(img, 0, sizeof *img);
}

int image_channel(const image *img, const char *name)
{
    for (int c = 0; c < img->channels && c < IMAGE_MAX_CHANNELS; c++)
        if (strcmp(img->channel_names[c], name) == 0)
            return c;
    return -1;
}
