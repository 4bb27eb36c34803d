/* Texture sampling as GL does it with GL_LINEAR, GL_REPEAT and no mipmaps. */
#include <math.h>

#include "reference.h"

static int wrap(long i, int n)
{
    long m = i % n;
    return (int)(m < 0 ? m + n : m);
}

void reference_sample_texture(const scene_texture *t, float u, float v, float out_rgba[4])
{
    if (!t || !t->rgba || t->width <= 0 || t->height <= 0 || !isfinite(u) || !isfinite(v)) {
        for (int c = 0; c < 4; c++)
            out_rgba[c] = 1.0f;
        return;
    }
    /* Texel i covers [i, i+1) in texel units, its centre at i + 0.5. Reduce
     * first so a huge repeat count keeps its fraction. */
    double x = (u - floor(u)) * t->width - 0.5, y = (v - floor(v)) * t->height - 0.5;
    double x0 = floor(x), y0 = floor(y), fx = x - x0, fy = y - y0;
    int i0 = wrap((long)x0, t->width), i1 = wrap((long)x0 + 1, t->width);
    int j0 = wrap((long)y0, t->height), j1 = wrap((long)y0 + 1, t->height);
    const uint8_t *p00 = t->rgba + 4 * ((size_t)j0 * t->width + i0);
    const uint8_t *p10 = t->rgba + 4 * ((size_t)j0 * t->width + i1);
    const uint8_t *p01 = t->rgba + 4 * ((size_t)j1 * t->width + i0);
    const uint8_t *p11 = t->rgba + 4 * ((size_t)j1 * t->width + i1);
    for (int c = 0; c < 4; c++) {
        double bottom = (1.0 - fx) * p00[c] + fx * p10[c];
        double top = (1.0 - fx) * p01[c] + fx * p11[c];
        out_rgba[c] = (float)(((1.0 - fy) * bottom + fy * top) / 255.0);
    }
}
