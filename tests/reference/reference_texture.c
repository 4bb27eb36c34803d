/* SPDX-License-Identifier: MIT */
/* Texture sampling as GL does it with GL_LINEAR and GL_REPEAT, without and
 * with the mip chain stin builds (GL_LINEAR_MIPMAP_LINEAR). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

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

/* ---- mipmaps: the chain stin builds, sampled as GL filters it ----------- */

struct reference_mips {
    int count;
    scene_texture *levels;
};

/* One texel of the next level from its four sources (a side of 1 repeats). */
typedef void (*reduce4)(const uint8_t *const src[4], uint8_t out[4]);

static void box4(const uint8_t *const src[4], uint8_t out[4])
{
    for (int c = 0; c < 4; c++)
        out[c] = (uint8_t)((src[0][c] + src[1][c] + src[2][c] + src[3][c] + 2u) / 4u);
}

static uint8_t to_byte(float x)
{
    float b = x + 0.5f;
    return (uint8_t)(b < 0.0f ? 0.0f : b > 255.0f ? 255.0f : b);
}

/* The alpha-weighted mean of four unit normals: its direction in RGB, its
 * length in A (a short mean normal widens the highlight, Toksvig). */
static void normals4(const uint8_t *const src[4], uint8_t out[4])
{
    float mean[3] = {0, 0, 0}, len;
    for (int i = 0; i < 4; i++) {
        float n[3], l;
        for (int c = 0; c < 3; c++)
            n[c] = ((float)src[i][c] - 128.0f) / 127.0f;
        l = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int c = 0; l > 0.0f && c < 3; c++)
            mean[c] += 0.25f * n[c] / l * ((float)src[i][3] / 255.0f);
    }
    len = sqrtf(mean[0] * mean[0] + mean[1] * mean[1] + mean[2] * mean[2]);
    if (!(len > 1e-6f)) { /* the normals cancel: straight up, length ~0 */
        mean[0] = mean[1] = 0.0f;
        mean[2] = len = 1e-6f;
    }
    for (int c = 0; c < 3; c++)
        out[c] = to_byte(128.0f + 127.0f * mean[c] / len);
    out[3] = to_byte(255.0f * (len < 1.0f ? len : 1.0f));
}

static int next_level(const scene_texture *a, scene_texture *b, reduce4 reduce)
{
    b->width = a->width > 1 ? a->width / 2 : 1;
    b->height = a->height > 1 ? a->height / 2 : 1;
    b->rgba = malloc(4 * (size_t)b->width * b->height);
    if (!b->rgba)
        return 0;
    for (int y = 0; y < b->height; y++)
        for (int x = 0; x < b->width; x++) {
            int x0 = a->width > 1 ? 2 * x : 0, y0 = a->height > 1 ? 2 * y : 0;
            int x1 = a->width > 1 ? x0 + 1 : 0, y1 = a->height > 1 ? y0 + 1 : 0;
            const uint8_t *const src[4] = {
                a->rgba + 4 * ((size_t)y0 * a->width + x0), a->rgba + 4 * ((size_t)y0 * a->width + x1),
                a->rgba + 4 * ((size_t)y1 * a->width + x0), a->rgba + 4 * ((size_t)y1 * a->width + x1)};
            reduce(src, b->rgba + 4 * ((size_t)y * b->width + x));
        }
    return 1;
}

reference_mips *reference_mips_create(const scene_texture *t, int normal_map)
{
    if (!t || !t->rgba || t->width <= 0 || t->height <= 0)
        return NULL;
    int count = 1;
    for (int w = t->width, h = t->height; w > 1 || h > 1; count++) {
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
    }
    reference_mips *m = calloc(1, sizeof *m);
    if (!m || !(m->levels = calloc((size_t)count, sizeof *m->levels))) {
        free(m);
        return NULL;
    }
    size_t bytes = 4 * (size_t)t->width * t->height;
    m->levels[0] = *t;
    m->levels[0].rgba = malloc(bytes);
    m->count = 1;
    if (!m->levels[0].rgba) {
        reference_mips_destroy(m);
        return NULL;
    }
    memcpy(m->levels[0].rgba, t->rgba, bytes);
    for (size_t i = 0; normal_map && i < bytes / 4; i++)
        m->levels[0].rgba[4 * i + 3] = 255; /* stin's level 0 of a normal map */
    for (; m->count < count; m->count++)
        if (!next_level(&m->levels[m->count - 1], &m->levels[m->count], normal_map ? normals4 : box4)) {
            reference_mips_destroy(m);
            return NULL;
        }
    return m;
}

void reference_mips_destroy(reference_mips *m)
{
    if (!m)
        return;
    for (int i = 0; i < m->count; i++)
        free(m->levels[i].rgba);
    free(m->levels);
    free(m);
}

int reference_mips_levels(const reference_mips *m) { return m ? m->count : 0; }

const scene_texture *reference_mips_level(const reference_mips *m, int i)
{
    return m && i >= 0 && i < m->count ? &m->levels[i] : NULL;
}

double reference_mip_lambda(const double duv_dx[2], const double duv_dy[2], int width, int height)
{
    double x = hypot(duv_dx[0] * width, duv_dx[1] * height);
    double y = hypot(duv_dy[0] * width, duv_dy[1] * height);
    double rho = x > y ? x : y;
    return rho > 0.0 ? log2(rho) : -HUGE_VAL;
}

void reference_sample_mips(const reference_mips *m, float u, float v, double lambda,
                           float out_rgba[4])
{
    if (!m || !(lambda > 0.0)) { /* magnification (or no chain): level 0 */
        reference_sample_texture(m ? &m->levels[0] : NULL, u, v, out_rgba);
        return;
    }
    int last = m->count - 1;
    if (lambda >= last) {
        reference_sample_texture(&m->levels[last], u, v, out_rgba);
        return;
    }
    int d1 = (int)floor(lambda);
    float a[4], b[4], f = (float)(lambda - d1);
    reference_sample_texture(&m->levels[d1], u, v, a);
    reference_sample_texture(&m->levels[d1 + 1], u, v, b);
    for (int c = 0; c < 4; c++)
        out_rgba[c] = (1.0f - f) * a[c] + f * b[c];
}
