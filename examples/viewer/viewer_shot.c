/* SPDX-License-Identifier: MIT */
#include "viewer_shot.h"
#include "image_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A framebuffer that encodes (sRGB on) holds display values: linear again
 * for the file, which encodes them itself where it is a PNG. */
static float to_linear(uint8_t v, int encoded)
{
    float c = v / 255.0f;
    if (!encoded)
        return c;
    return c <= 0.04045f ? c / 12.92f : powf((c + 0.055f) / 1.055f, 2.4f);
}

int viewer_shot_write(const viewer_window *w, const char *path, char *err, size_t err_size)
{
    int width, height, x, y, c, ok = 0;
    int encoded = w->srgb_asked && w->srgb_capable;
    const char *dot = strrchr(path, '.');
    uint8_t *rgba;
    image img;
    memset(&img, 0, sizeof img);
    viewer_window_size(w, &width, &height);
    rgba = malloc((size_t)width * height * 4);
    if (!rgba || !image_alloc(&img, width, height, 4)) {
        snprintf(err, err_size, "%s: out of memory", path);
        goto done;
    }
    if (!viewer_window_read(w, rgba, width, height)) {
        snprintf(err, err_size, "%s: the window's read-back failed", path);
        goto done;
    }
    for (c = 0; c < 4; c++)
        snprintf(img.channel_names[c], sizeof img.channel_names[c], "%c", "RGBA"[c]);
    for (y = 0; y < height; y++) /* GL rows bottom to top, files top to bottom */
        for (x = 0; x < width; x++)
            for (c = 0; c < 4; c++)
                img.pixels[((size_t)(height - 1 - y) * width + x) * 4 + c] =
                    to_linear(rgba[((size_t)y * width + x) * 4 + c], encoded && c < 3);
    ok = image_write(path, &img, dot && !strcmp(dot, ".png"), err, err_size);
done:
    image_free(&img);
    free(rgba);
    return ok;
}
