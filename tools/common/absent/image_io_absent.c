/* SPDX-License-Identifier: MIT */
/*
 * image_io.h's file half in a build made with OIIO=no (a bench-only build for
 * a machine without OpenImageIO): every file operation fails and says why.
 * Scenes without texture files, and the bench, need none of them.
 */
#include "image_io.h"

#include <stdio.h>

static int absent(const char *what, char *err, size_t err_size)
{
    snprintf(err, err_size, "%s: this build has no OpenImageIO (made with OIIO=no)", what);
    return 0;
}

int image_write(const char *path, const image *img, int srgb, char *err, size_t err_size)
{
    (void)img;
    (void)srgb;
    return absent(path, err, err_size);
}

int image_read(const char *path, image *img, char *err, size_t err_size)
{
    (void)img;
    return absent(path, err, err_size);
}

int image_read_memory(const void *data, size_t size, const char *format_hint, image *img,
                      char *err, size_t err_size)
{
    (void)data;
    (void)size;
    (void)img;
    return absent(format_hint[0] ? format_hint : "embedded image", err, err_size);
}

int image_compare(const image *a, const image *b, const char *channels, const float *mask,
                  double threshold, image_diff *out)
{
    (void)a;
    (void)b;
    (void)channels;
    (void)mask;
    (void)threshold;
    (void)out;
    return 0;
}
