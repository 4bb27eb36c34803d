/* SPDX-License-Identifier: MIT */
/*
 * Image files through OpenImageIO, behind a C interface (image_io.cpp; the
 * in-memory half in image_buffer.c, a build without OpenImageIO in absent/).
 * Pixels are float, rows TOP to bottom (file order), channels interleaved.
 */
#ifndef STIN_TOOLS_IMAGE_IO_H
#define STIN_TOOLS_IMAGE_IO_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct image {
    int width, height, channels;
    float *pixels;               /* width * height * channels */
    char channel_names[24][16];  /* e.g. "R", "P.X", "vis.G", "T.B" */
} image;

/* Allocates pixels (zeroed) and leaves channel names empty. 1 on success. */
int image_alloc(image *img, int width, int height, int channels);
void image_free(image *img);
/* Index of a channel by name, -1 if absent. */
int image_channel(const image *img, const char *name);

/* Writes by extension: .exr keeps every channel as half or float (float for
 * P, N, Z), .png writes the first four channels (or R G B A by name) as 8-bit
 * with the linear -> sRGB transfer applied to R G B when srgb is 1.
 * Writes to a temporary name and renames, so a failure leaves no partial file. */
int image_write(const char *path, const image *img, int srgb, char *err, size_t err_size);
/* Reads any format OpenImageIO knows; 8-bit files come back in [0,1] as
 * stored (no transfer applied). */
int image_read(const char *path, image *img, char *err, size_t err_size);
/* The same for a file already in memory (an image embedded in a model);
 * format_hint is its extension ("png", "jpg") or "" to go by its signature. */
int image_read_memory(const void *data, size_t size, const char *format_hint, image *img,
                      char *err, size_t err_size);

typedef struct image_diff {
    double mean_abs, max_abs;
    long long over_threshold;    /* pixels with any channel differing by > threshold */
    long long compared;          /* pixels compared */
} image_diff;

/* Per-pixel difference of the named channels (comma separated, e.g. "R,G,B")
 * with OpenImageIO's ImageBufAlgo; pixels where mask (may be NULL, one float
 * per pixel) is 0 are skipped. 1 on success. */
int image_compare(const image *a, const image *b, const char *channels, const float *mask,
                  double threshold, image_diff *out);

#ifdef __cplusplus
}
#endif
#endif
