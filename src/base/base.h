/* SPDX-License-Identifier: MIT */
/* The library's own small runtime: logging and formatting without the heap,
 * the arena, range allocation and math. */
#ifndef STIN_BASE_H
#define STIN_BASE_H

#include "stin/stin.h"

#include <stdarg.h>


/* ---- logging ------------------------------------------------------------ */
void stin__log(struct stin_context *ctx, stin_log_level level, stin_log_item item,
               const char *fmt, ...);
void stin__logv(stin_log_fn fn, void *user, stin_log_level level, stin_log_item item,
                const char *fmt, va_list ap);
/* A small formatter (%s %d %u %x %lu %zu %f %%) that never touches the heap. */
size_t stin__format(char *buf, size_t size, const char *fmt, va_list ap);
size_t stin__formatf(char *buf, size_t size, const char *fmt, ...);

/* ---- memory ------------------------------------------------------------- */
typedef struct stin__arena {
    unsigned char *base;
    size_t size, used;
} stin__arena;
/* Bump allocation aligned to 16 bytes; NULL when the arena is exhausted. */
void *stin__arena_alloc(stin__arena *a, size_t bytes);
size_t stin__align16(size_t n);
void stin__memzero(void *p, size_t n);
void stin__memcopy(void *dst, const void *src, size_t n);

/* First-fit allocator of element ranges in a fixed store (vertices, triangles). */
typedef struct stin__range {
    uint32_t offset, count;
} stin__range;
typedef struct stin__range_alloc {
    stin__range *used; /* sorted by offset */
    uint32_t used_count, max_ranges;
    uint32_t capacity;
} stin__range_alloc;
void stin__range_init(stin__range_alloc *r, stin__range *storage, uint32_t max_ranges,
                      uint32_t capacity);
/* Returns 1 and the offset on success, 0 when no gap is large enough. */
int stin__range_take(stin__range_alloc *r, uint32_t count, uint32_t *offset);
void stin__range_give(stin__range_alloc *r, uint32_t offset);


/* ---- math --------------------------------------------------------------- */
void stin__mat4_identity(float m[16]);
void stin__mat4_mul(float out[16], const float a[16], const float b[16]);
int stin__mat4_invert(float out[16], const float m[16]);
double stin__mat4_det(const float m[16]);
/* 1 when m is singular for any practical purpose, whatever its scale. */
int stin__mat4_singular(const float m[16]);
/* Upper 3x3 of the inverse transpose, for normals. */
void stin__mat3_normal(float out[9], const float m[16]);
void stin__mat4_transform_point(const float m[16], const float p[3], float out[3]);
float stin__sqrtf(float x);
float stin__cos_deg(float degrees);
int stin__isfinite(float x);
/* The largest power of two not above n (1 for n < 2). */
uint32_t stin__pow2_at_most(uint32_t n);
/* 1 when the n values are all finite. */
int stin__finite_n(const float *v, int n);
/* Scales v to unit length at any magnitude; 0 (v unchanged or scaled) for a
 * zero or non-finite vector. */
int stin__normalize3(float v[3]);
/* The share of an area light's intensity and visibility sample i of n
 * carries: a whole number of 255ths, 255 / n rounded up or down so that the
 * n shares sum to exactly 1 (8-bit targets add them without a step short
 * of full light). n <= 1: 1. */
float stin__light_sample_weight(uint32_t i, uint32_t n);

#endif
