/* SPDX-License-Identifier: MIT */
/* Textures of a scene file: image files, or procedural patterns generated
 * here so tests and demos need no binary assets. All results are RGBA8 with
 * rows bottom to top; height maps keep the height in R (copied to G, B). */
#include "scene_internal.h"
#include "image_io.h"
#include "isolate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TEXTURE_SIZE_MAX SCENE_TEXTURE_SIZE_MAX

static uint8_t to_byte(float x)
{
    x = x > 0 ? (x < 1 ? x : 1) : 0; /* also NaN -> 0 */
    return (uint8_t)lrintf(x * 255.0f);
}

static void put_rgb(scene_texture *t, int x, int y, const float c[3])
{
    uint8_t *px = t->rgba + 4 * ((size_t)y * (size_t)t->width + (size_t)x);
    px[0] = to_byte(c[0]);
    px[1] = to_byte(c[1]);
    px[2] = to_byte(c[2]);
    px[3] = 255;
}

static void put_grey(scene_texture *t, int x, int y, float h)
{
    const float c[3] = { h, h, h };
    put_rgb(t, x, y, c);
}

/* Integer hash (murmur3 finaliser) of a few lattice coordinates: the same
 * seed always gives the same bricks and noise, on every machine. */
static uint32_t hash3(uint32_t a, uint32_t b, uint32_t c)
{
    uint32_t h = a * 0x9e3779b1u ^ (b + 0x7f4a7c15u) * 0x85ebca6bu ^ (c + 0x165667b1u) * 0xc2b2ae35u;
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    return h;
}

static float hash_unit(uint32_t a, uint32_t b, uint32_t c)
{
    return (float)(hash3(a, b, c) >> 8) / 16777216.0f; /* [0, 1) */
}

typedef struct brick_layout {
    int rows, cols;
    float mortar; /* mortar width in brick heights */
    float bevel;  /* rounded edge width in brick heights */
} brick_layout;

/* Running bond: odd rows shift by half a brick. Returns the distance from
 * texel (x, y) to the nearest brick edge in brick heights, and the brick. */
static float brick_at(const brick_layout *b, const scene_texture *t, int x, int y,
                      int *row, int *col)
{
    float u = (x + 0.5f) / t->width, v = (y + 0.5f) / t->height;
    float bw = (float)t->width / b->cols, bh = (float)t->height / b->rows;
    float fu, fv, dx, dy;
    *row = (int)floorf(v * b->rows);
    if (*row & 1)
        u += 0.5f / b->cols;
    fu = u * b->cols;
    *col = (int)floorf(fu) % b->cols;
    fu -= floorf(fu);
    fv = v * b->rows - (float)*row;
    dx = fminf(fu, 1 - fu) * bw;
    dy = fminf(fv, 1 - fv) * bh;
    return fminf(dx, dy) / bh;
}

static void gen_checker(scene_texture *t, const int cells[2], const float a[3], const float b[3])
{
    int x, y;
    for (y = 0; y < t->height; y++)
        for (x = 0; x < t->width; x++) {
            int cx = x * cells[0] / t->width, cy = y * cells[1] / t->height;
            put_rgb(t, x, y, (cx + cy) & 1 ? b : a);
        }
}

static void gen_bricks(scene_texture *t, const brick_layout *b, const float brick[3],
                       const float mortar[3], float variation, uint32_t seed)
{
    int x, y, row, col, k;
    for (y = 0; y < t->height; y++)
        for (x = 0; x < t->width; x++) {
            float d = brick_at(b, t, x, y, &row, &col), c[3];
            float s = 1 + variation * (2 * hash_unit(seed, (uint32_t)row, (uint32_t)col) - 1);
            for (k = 0; k < 3; k++)
                c[k] = d < 0.5f * b->mortar ? mortar[k] : brick[k] * s;
            put_rgb(t, x, y, c);
        }
}

static void gen_bricks_height(scene_texture *t, const brick_layout *b)
{
    int x, y, row, col;
    for (y = 0; y < t->height; y++)
        for (x = 0; x < t->width; x++) {
            float d = brick_at(b, t, x, y, &row, &col) - 0.5f * b->mortar, h = 0;
            if (d >= 0) {
                /* Quarter-circle profile over the bevel: rounded edges. */
                float e = b->bevel > 0 ? fminf(d / b->bevel, 1.0f) : 1.0f;
                h = sqrtf(1 - (1 - e) * (1 - e));
            }
            put_grey(t, x, y, h);
        }
}

static float smooth(float f)
{
    return f * f * (3 - 2 * f);
}

/* Value noise that tiles: the lattice wraps with the texture. */
static void gen_noise(scene_texture *t, int cells, int octaves, uint32_t seed)
{
    int x, y, o;
    for (y = 0; y < t->height; y++)
        for (x = 0; x < t->width; x++) {
            float sum = 0, amp = 1, total = 0;
            for (o = 0; o < octaves; o++) {
                int n = cells << o;
                float fx = (x + 0.5f) * n / t->width, fy = (y + 0.5f) * n / t->height;
                int ix = (int)floorf(fx), iy = (int)floorf(fy);
                float sx = smooth(fx - ix), sy = smooth(fy - iy);
                uint32_t x0 = (uint32_t)(ix % n), x1 = (uint32_t)((ix + 1) % n);
                uint32_t y0 = (uint32_t)(iy % n), y1 = (uint32_t)((iy + 1) % n);
                uint32_t s = seed * 131u + (uint32_t)o;
                float a = hash_unit(s, x0, y0), b = hash_unit(s, x1, y0);
                float c = hash_unit(s, x0, y1), d = hash_unit(s, x1, y1);
                sum += amp * ((a + (b - a) * sx) * (1 - sy) + (c + (d - c) * sx) * sy);
                total += amp;
                amp *= 0.5f;
            }
            put_grey(t, x, y, sum / total);
        }
}

static float height_at(const scene_texture *h, int x, int y)
{
    x = (x % h->width + h->width) % h->width;
    y = (y % h->height + h->height) % h->height;
    return h->rgba[4 * ((size_t)y * (size_t)h->width + (size_t)x)] / 255.0f;
}

static void gen_normals(scene_texture *t, const scene_texture *h, float strength)
{
    int x, y;
    for (y = 0; y < t->height; y++)
        for (x = 0; x < t->width; x++) {
            float du = 0.5f * (height_at(h, x + 1, y) - height_at(h, x - 1, y));
            float dv = 0.5f * (height_at(h, x, y + 1) - height_at(h, x, y - 1));
            float n[3] = { -strength * du, -strength * dv, 1 };
            float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            int k;
            for (k = 0; k < 3; k++)
                n[k] = 0.5f + 0.5f * n[k] / len;
            put_rgb(t, x, y, n);
        }
}

static int alloc_pixels(scene_parser *p, const char *where, scene_texture *t, int w, int h)
{
    t->width = w;
    t->height = h;
    t->rgba = calloc((size_t)w * (size_t)h, 4);
    return t->rgba ? 1 : scene_fail(p, where, "out of memory for a %d x %d texture", w, h);
}

static float srgb_to_linear(float x)
{
    return x <= 0.04045f ? x / 12.92f : powf((x + 0.055f) / 1.055f, 2.4f);
}

void scene_image_to_rgba8(const image *img, int linearise, uint8_t *out)
{
    int x, y, k;
    for (y = 0; y < img->height; y++)
        for (x = 0; x < img->width; x++) {
            const float *s = img->pixels + ((size_t)y * (size_t)img->width + (size_t)x) * (size_t)img->channels;
            uint8_t *d = out + 4 * ((size_t)(img->height - 1 - y) * (size_t)img->width + (size_t)x);
            int grey = img->channels < 3;
            float c[3];
            c[0] = s[0];
            c[1] = grey ? s[0] : s[1];
            c[2] = grey ? s[0] : s[2];
            for (k = 0; k < 3; k++)
                d[k] = to_byte(linearise ? srgb_to_linear(c[k] < 0 ? 0 : c[k]) : c[k]);
            d[3] = img->channels == 2 ? to_byte(s[1]) : img->channels >= 4 ? to_byte(s[3]) : 255;
        }
}

/* Child side: image file -> width, height and RGBA8 rows bottom to top. */
static int decode_work(void *arg, int fd, char *why, size_t why_size)
{
    image img;
    int size[2], ok;
    uint8_t *rgba;
    if (!image_read((const char *)arg, &img, why, why_size))
        return 0;
    if (img.width > TEXTURE_SIZE_MAX || img.height > TEXTURE_SIZE_MAX) {
        snprintf(why, why_size, "larger than %d texels", TEXTURE_SIZE_MAX);
        image_free(&img);
        return 0;
    }
    size[0] = img.width;
    size[1] = img.height;
    rgba = malloc(4 * (size_t)img.width * (size_t)img.height);
    if (rgba)
        scene_image_to_rgba8(&img, 0, rgba);
    ok = rgba && isolate_write(fd, size, sizeof size) &&
         isolate_write(fd, rgba, 4 * (size_t)img.width * (size_t)img.height);
    if (!ok)
        snprintf(why, why_size, "out of memory");
    free(rgba);
    image_free(&img);
    return ok;
}

/* Image decoders are not ours: they run in a child (isolate.h). */
static int load_file(scene_parser *p, const cJSON *json, const char *where, scene_texture *t)
{
    char rel[512] = "", full[1024], why[512], path[256];
    unsigned char *bytes;
    size_t size;
    int wh[2];
    scene_join(path, sizeof path, where, "file");
    if (!scene_get_string(p, json, "file", where, rel, sizeof rel))
        return 0;
    if (!scene_resolve_path(p->file, rel, full, sizeof full))
        return scene_fail(p, path, "path too long");
    if (!scene_check_regular_file(full, why, sizeof why) ||
        !scene_import(decode_work, full, &bytes, &size, why, sizeof why))
        return scene_fail(p, path, "cannot read '%s': %s", rel, why);
    if (size >= sizeof wh)
        memcpy(wh, bytes, sizeof wh);
    if (size < sizeof wh || wh[0] < 1 || wh[1] < 1 || wh[0] > TEXTURE_SIZE_MAX ||
        wh[1] > TEXTURE_SIZE_MAX || size != sizeof wh + 4 * (size_t)wh[0] * (size_t)wh[1]) {
        free(bytes);
        return scene_fail(p, path, "cannot read '%s': the decoder returned a malformed image", rel);
    }
    if (!alloc_pixels(p, path, t, wh[0], wh[1])) {
        free(bytes);
        return 0;
    }
    memcpy(t->rgba, bytes + sizeof wh, size - sizeof wh);
    free(bytes);
    return 1;
}

static int get_size(scene_parser *p, const cJSON *json, const char *key, const char *where,
                    int lo, int hi, int out[2])
{
    float v[2] = { (float)out[0], (float)out[1] };
    char path[256];
    int i;
    if (!scene_get_vector(p, json, key, where, 2, SCENE_POSITIVE, v))
        return 0;
    scene_join(path, sizeof path, where, key);
    for (i = 0; i < 2; i++) {
        if (v[i] != floorf(v[i]) || v[i] < lo || v[i] > hi)
            return scene_fail(p, path, "expected two integers in [%d, %d]", lo, hi);
        out[i] = (int)v[i];
    }
    return 1;
}

static int get_layout(scene_parser *p, const cJSON *json, const char *where, brick_layout *b)
{
    b->rows = 8;
    b->cols = 4;
    b->mortar = 0.08f;
    b->bevel = 0.1f;
    return scene_get_int(p, json, "rows", where, 1, 1024, &b->rows) &&
           scene_get_int(p, json, "cols", where, 1, 1024, &b->cols) &&
           scene_get_number(p, json, "mortar_width", where, SCENE_UNIT, &b->mortar) &&
           scene_get_number(p, json, "bevel", where, SCENE_UNIT, &b->bevel);
}

int scene_texture_build(scene_parser *p, const cJSON *json, const char *where,
                        const scene_texture *done, int done_count, scene_texture *out)
{
    static const char *const file_keys[] = { "file", NULL };
    static const char *const checker_keys[] = { "procedural", "size", "cells", "color_a", "color_b", NULL };
    static const char *const bricks_keys[] = { "procedural", "size", "rows", "cols", "mortar_width",
                                               "color", "mortar_color", "variation", "seed", NULL };
    static const char *const bh_keys[] = { "procedural", "size", "rows", "cols", "mortar_width", "bevel", NULL };
    static const char *const noise_keys[] = { "procedural", "size", "cells", "octaves", "seed", NULL };
    static const char *const normal_keys[] = { "procedural", "from", "strength", NULL };
    char kind[32] = "", path[256];
    int size[2] = { 256, 256 };

    if (!cJSON_IsObject(json))
        return scene_fail(p, where, "expected an object");
    if (cJSON_GetObjectItemCaseSensitive(json, "file")) {
        out->kind = SCENE_TEXTURE_ALBEDO;
        return scene_check_object(p, json, where, file_keys) && load_file(p, json, where, out);
    }
    if (!scene_require(p, json, "procedural", where) ||
        !scene_get_string(p, json, "procedural", where, kind, sizeof kind))
        return 0;
    scene_join(path, sizeof path, where, "procedural");

    if (strcmp(kind, "checker") == 0) {
        int cells[2] = { 8, 8 };
        float a[3] = { 0.9f, 0.9f, 0.9f }, b[3] = { 0.2f, 0.2f, 0.2f };
        if (!scene_check_object(p, json, where, checker_keys) ||
            !get_size(p, json, "size", where, 1, TEXTURE_SIZE_MAX, size) ||
            !get_size(p, json, "cells", where, 1, TEXTURE_SIZE_MAX, cells) ||
            !scene_get_vector(p, json, "color_a", where, 3, SCENE_UNIT, a) ||
            !scene_get_vector(p, json, "color_b", where, 3, SCENE_UNIT, b) ||
            !alloc_pixels(p, where, out, size[0], size[1]))
            return 0;
        out->kind = SCENE_TEXTURE_ALBEDO;
        gen_checker(out, cells, a, b);
        return 1;
    }
    if (strcmp(kind, "bricks") == 0 || strcmp(kind, "bricks_height") == 0) {
        int height = strcmp(kind, "bricks_height") == 0, seed = 1;
        float brick[3] = { 0.55f, 0.22f, 0.15f }, mortar[3] = { 0.75f, 0.73f, 0.68f }, var = 0.15f;
        brick_layout b;
        size[0] = size[1] = 512;
        if (!scene_check_object(p, json, where, height ? bh_keys : bricks_keys) ||
            !get_size(p, json, "size", where, 1, TEXTURE_SIZE_MAX, size) ||
            !get_layout(p, json, where, &b) ||
            !scene_get_vector(p, json, "color", where, 3, SCENE_UNIT, brick) ||
            !scene_get_vector(p, json, "mortar_color", where, 3, SCENE_UNIT, mortar) ||
            !scene_get_number(p, json, "variation", where, SCENE_UNIT, &var) ||
            !scene_get_int(p, json, "seed", where, 0, 1 << 30, &seed) ||
            !alloc_pixels(p, where, out, size[0], size[1]))
            return 0;
        out->kind = height ? SCENE_TEXTURE_HEIGHT : SCENE_TEXTURE_ALBEDO;
        if (height)
            gen_bricks_height(out, &b);
        else
            gen_bricks(out, &b, brick, mortar, var, (uint32_t)seed);
        return 1;
    }
    if (strcmp(kind, "noise_height") == 0) {
        int cells = 8, octaves = 4, seed = 1;
        if (!scene_check_object(p, json, where, noise_keys) ||
            !get_size(p, json, "size", where, 1, TEXTURE_SIZE_MAX, size) ||
            !scene_get_int(p, json, "cells", where, 1, 256, &cells) ||
            !scene_get_int(p, json, "octaves", where, 1, 8, &octaves) ||
            !scene_get_int(p, json, "seed", where, 0, 1 << 30, &seed) ||
            !alloc_pixels(p, where, out, size[0], size[1]))
            return 0;
        out->kind = SCENE_TEXTURE_HEIGHT;
        gen_noise(out, cells, octaves, (uint32_t)seed);
        return 1;
    }
    if (strcmp(kind, "normal_from_height") == 0) {
        char from[SCENE_NAME_MAX] = "", fpath[256];
        float strength = 1;
        int i;
        scene_join(fpath, sizeof fpath, where, "from");
        if (!scene_check_object(p, json, where, normal_keys) || !scene_require(p, json, "from", where) ||
            !scene_get_string(p, json, "from", where, from, sizeof from) ||
            !scene_get_number(p, json, "strength", where, SCENE_NONNEGATIVE, &strength))
            return 0;
        for (i = 0; i < done_count && strcmp(done[i].name, from) != 0; i++)
            ;
        if (i == done_count)
            return scene_fail(p, fpath, "unknown texture '%s' (it must be defined earlier)", from);
        if (!alloc_pixels(p, where, out, done[i].width, done[i].height))
            return 0;
        out->kind = SCENE_TEXTURE_NORMAL;
        gen_normals(out, &done[i], strength);
        return 1;
    }
    return scene_fail(p, path, "unknown procedural texture '%s' (checker, bricks, bricks_height, "
                      "noise_height, normal_from_height)", kind);
}
