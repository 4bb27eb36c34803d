/* SPDX-License-Identifier: MIT */
/* capture_render's results kept by key, the least recently used given up
 * first (capture_cache.h). */
#include "capture_cache.h"
#include "reference_cache.h"
#include "scene_gpu.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Rows that share a frame ask for it within a scene's tests of one tier, so
 * a few dozen frames are enough (at 256x192, 3.3 MB each). */
#define KEPT_MAX 32

typedef struct kept {
    capture_key key;
    capture cap;
    size_t room;        /* floats cap.img.pixels holds: a slot keeps its block */
    unsigned long used; /* the clock at the last hit or keep; 0: empty */
} kept;

static kept slots[KEPT_MAX];
static unsigned long clock_now, hits, misses;

static void print_stats(void)
{
    fprintf(stderr, "frame cache: %lu hits, %lu misses\n", hits, misses);
}

static int cache_on(void)
{
    static int on = -1;
    if (on < 0) {
        const char *v = getenv("STIN_TEST_FRAME_CACHE"), *st = getenv("STIN_TEST_FRAME_CACHE_STATS");
        on = !v || strcmp(v, "0") != 0;
        if (on && st && strcmp(st, "0") != 0)
            atexit(print_stats);
    }
    return on;
}

int capture_cache_key(const stin_platform *plat, const stin_profile *profile, const scene *s,
                      const capture_options *o, capture_key *key)
{
    ref_hasher h;
    ref_cache_key k;
    int i;
    if (!cache_on())
        return 0;
    ref_hash_init(&h);
    ref_hash_array(&h, profile->name, strlen(profile->name));
    ref_hash_u64(&h, (uint64_t)stin_platform_width(plat));
    ref_hash_u64(&h, (uint64_t)stin_platform_height(plat));
    ref_hash_u64(&h, (uint64_t)stin_platform_samples(plat));
    ref_hash_u64(&h, (uint64_t)stin_platform_srgb(plat));
    /* the options field by field: the struct has padding and a pointer */
    ref_hash_u64(&h, (uint64_t)o->tier);
    ref_hash_u64(&h, (uint64_t)o->shadows);
    ref_hash_u64(&h, o->debug_flags);
    ref_hash_u64(&h, o->extra_mask);
    ref_hash_u64(&h, o->shadow_map_size);
    ref_hash_u64(&h, (uint64_t)o->surface);
    ref_hash_u64(&h, (uint64_t)o->displacement);
    ref_hash_bytes(&h, &o->guard_band, sizeof o->guard_band);
    ref_hash_bytes(&h, &o->tess_pixels, sizeof o->tess_pixels);
    ref_hash_u64(&h, (uint64_t)o->csg_technique);
    ref_hash_u64(&h, o->csg_capacity);
    ref_hash_u64(&h, (uint64_t)o->translucent);
    ref_hash_u64(&h, o->deep_layers);
    ref_hash_u64(&h, o->deep_map_size);
    ref_hash_u64(&h, (uint64_t)o->deep_mono);
    ref_hash_bytes(&h, &o->opaque_threshold, sizeof o->opaque_threshold);
    ref_hash_u64(&h, (uint64_t)o->visibility_only);
    ref_hash_u64(&h, (uint64_t)(o->csg ? o->csg_count : 0));
    for (i = 0; o->csg && i < o->csg_count; i++) {
        const scene_gpu_csg *p = &o->csg[i];
        ref_hash_array(&h, p->objects, (size_t)p->primitive_count * sizeof *p->objects);
        ref_hash_array(&h, p->nodes, (size_t)p->node_count * sizeof *p->nodes);
    }
    ref_hash_scene(&h, s);
    ref_cache_key_end(&h, &k);
    memcpy(key->k, k.k, sizeof key->k);
    return 1;
}

/* A copy that owns its pixels: 1, or 0 out of memory. */
static int copy_capture(const capture *from, capture *to)
{
    size_t n = (size_t)from->img.width * from->img.height * from->img.channels;
    *to = *from;
    to->img.pixels = malloc(n * sizeof(float));
    if (!to->img.pixels)
        return 0;
    memcpy(to->img.pixels, from->img.pixels, n * sizeof(float));
    return 1;
}

int capture_cache_find(const capture_key *key, capture *out)
{
    int i;
    for (i = 0; i < KEPT_MAX; i++)
        if (slots[i].used && !memcmp(&slots[i].key, key, sizeof *key) &&
            copy_capture(&slots[i].cap, out)) {
            slots[i].used = ++clock_now;
            hits++;
            return 1;
        }
    misses++;
    return 0;
}

/* A slot's block is allocated once and written over after, so the cache
 * frees and allocates no large block between the driver's (with a block a
 * render, a whole gl45-core suite peaked at 5.5 GB against 3.9 without the
 * cache; not measured again since). */
void capture_cache_keep(const capture_key *key, const capture *c)
{
    int i, oldest = 0;
    kept *k;
    size_t n = (size_t)c->img.width * c->img.height * c->img.channels;
    float *pixels;
    for (i = 1; i < KEPT_MAX; i++)
        if (slots[i].used < slots[oldest].used)
            oldest = i;
    k = &slots[oldest];
    k->used = 0;
    if (k->room < n) {
        free(k->cap.img.pixels);
        k->cap.img.pixels = malloc(n * sizeof(float));
        k->room = k->cap.img.pixels ? n : 0;
        if (!k->cap.img.pixels)
            return;
    }
    pixels = k->cap.img.pixels;
    k->cap = *c;
    k->cap.img.pixels = pixels;
    memcpy(pixels, c->img.pixels, n * sizeof(float));
    k->key = *key;
    k->used = ++clock_now;
}
