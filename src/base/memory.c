/* SPDX-License-Identifier: MIT */
/* The caller's block carved by a bump allocator, and a first-fit range
 * allocator for the shared vertex and triangle stores. */
#include "internal.h"

size_t stin__align16(size_t n) { return (n + 15u) & ~(size_t)15u; }

void *stin__arena_alloc(stin__arena *a, size_t bytes)
{
    size_t start = stin__align16(a->used);
    if (start > a->size || bytes > a->size - start)
        return NULL;
    a->used = start + bytes;
    return a->base ? a->base + start : NULL;
}

void stin__memzero(void *p, size_t n)
{
    unsigned char *c = (unsigned char *)p;
    while (n--)
        *c++ = 0;
}

void stin__memcopy(void *dst, const void *src, size_t n)
{
    unsigned char *d = (unsigned char *)dst;
    const unsigned char *s = (const unsigned char *)src;
    while (n--)
        *d++ = *s++;
}

void stin__range_init(stin__range_alloc *r, stin__range *storage, uint32_t max_ranges,
                      uint32_t capacity)
{
    r->used = storage;
    r->used_count = 0;
    r->max_ranges = max_ranges;
    r->capacity = capacity;
}

int stin__range_take(stin__range_alloc *r, uint32_t count, uint32_t *offset)
{
    uint32_t i, start = 0, j;
    if (r->used_count >= r->max_ranges || count == 0)
        return 0;
    for (i = 0; i <= r->used_count; i++) {
        uint32_t end = i < r->used_count ? r->used[i].offset : r->capacity;
        if (end >= start && end - start >= count) {
            for (j = r->used_count; j > i; j--)
                r->used[j] = r->used[j - 1];
            r->used[i].offset = start;
            r->used[i].count = count;
            r->used_count++;
            *offset = start;
            return 1;
        }
        if (i < r->used_count)
            start = r->used[i].offset + r->used[i].count;
    }
    return 0;
}

void stin__range_give(stin__range_alloc *r, uint32_t offset)
{
    uint32_t i, j;
    for (i = 0; i < r->used_count; i++) {
        if (r->used[i].offset == offset) {
            for (j = i; j + 1 < r->used_count; j++)
                r->used[j] = r->used[j + 1];
            r->used_count--;
            return;
        }
    }
}
