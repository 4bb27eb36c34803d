/* SPDX-License-Identifier: MIT */
/*
 * Render once, check many: capture_render's results kept for the rest of
 * the process, keyed by everything that determines them (the profile, the
 * framebuffer's size, samples and encoding, the whole scene, every option
 * and the CSG products: a new field of capture_options must be hashed too),
 * so that rows asking for the same frame (a probe of the context's
 * capabilities, the same technique checked by two files) share one render.
 * On by default; STIN_TEST_FRAME_CACHE=0 turns it off,
 * STIN_TEST_FRAME_CACHE_STATS=1 prints its hits and misses at exit
 * (docs/testing.md, "Where make check's time goes").
 */
#ifndef STIN_TESTS_CAPTURE_CACHE_H
#define STIN_TESTS_CAPTURE_CACHE_H

#include "capture.h"

typedef struct capture_key {
    uint64_t k[2];
} capture_key;

/* 1 and the key of the render these arguments ask for; 0 when the cache is off. */
int capture_cache_key(const stin_platform *plat, const stin_profile *profile, const scene *s,
                      const capture_options *o, capture_key *key);
/* 1 and a copy of the kept result (free it with capture_free), or 0. */
int capture_cache_find(const capture_key *key, capture *out);
/* Keeps a copy of a successful result (silently not, out of memory). */
void capture_cache_keep(const capture_key *key, const capture *c);

#endif
