/* SPDX-License-Identifier: MIT */
/*
 * Whole-image reference results shared between the image-test processes
 * of one run (docs/testing.md, "The reference cache"). Off unless
 * STIN_REFERENCE_CACHE names a directory (tests/run.sh sets it and empties
 * it at start). A result is stored under a 128-bit key hashed from
 * everything that determines it: the test binary's own bytes, the
 * reference's world-space geometry and settings, the whole scene (meshes,
 * textures, materials, objects, lights, camera, CSG list, ambient,
 * background) and the call's arguments. A file is written under a
 * temporary name and renamed into place, and read back only when its
 * magic, key, size and payload hash all match: otherwise the caller
 * computes, exactly as without the cache.
 */
#ifndef STIN_TESTS_REFERENCE_CACHE_H
#define STIN_TESTS_REFERENCE_CACHE_H

#include <stddef.h>
#include <stdint.h>

typedef struct reference reference;

/* A 128-bit hash in the making: two 64-bit lanes with different mixes. */
typedef struct ref_hasher {
    uint64_t a, b, bytes;
} ref_hasher;

void ref_hash_init(ref_hasher *h);
void ref_hash_bytes(ref_hasher *h, const void *data, size_t n);
/* A length first, then the bytes (or none for NULL): arrays of different
 * lengths or a missing array never run into one another. */
void ref_hash_array(ref_hasher *h, const void *data, size_t n);
void ref_hash_u64(ref_hasher *h, uint64_t v);
/* Everything of a scene a render or a reference reads: meshes, textures,
 * materials, objects, lights, CSG list, camera, ambient, background, size
 * and shadow-map size (also the image tests' frame cache, capture_cache.h). */
struct scene;
void ref_hash_scene(ref_hasher *h, const struct scene *s);

typedef struct ref_cache_key {
    uint64_t k[2];
} ref_cache_key;

/* 1 and a key for the call named by tag on r (its geometry, settings and
 * scene at this moment); the caller hashes its arguments into h and ends
 * with ref_cache_key_end. 0 when the cache is off. */
int ref_cache_key_begin(const reference *r, const char *tag, ref_hasher *h);
void ref_cache_key_end(ref_hasher *h, ref_cache_key *key);

/* A result is one or more buffers, stored one after another. */
typedef struct ref_cache_part {
    void *data;
    size_t size;
} ref_cache_part;

/* Fills the parts from the stored result of key: 1, or 0 on a miss (the
 * parts may then hold anything: the caller computes them whole). */
int ref_cache_load(const ref_cache_key *key, const ref_cache_part *parts, int count);
/* Stores a result the caller computed successfully. Failures are silent:
 * the next process computes it again. */
void ref_cache_store(const ref_cache_key *key, const ref_cache_part *parts, int count);

/* Around a cached call's own computation (a miss): the CPU seconds of the
 * outermost one count toward STIN_REFERENCE_CACHE_STATS=1's line on
 * stderr at exit (hits, misses, seconds computing, seconds loading). */
void ref_cache_compute_begin(void);
void ref_cache_compute_end(void);

/* The hash of r's world-space snapshot, taken once by reference_create
 * when the cache is on (the snapshot never changes after). */
void ref_cache_snapshot(reference *r);

#endif
