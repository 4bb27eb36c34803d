/* SPDX-License-Identifier: MIT */
/* The reference cache (reference_cache.h): keys, and files stored by
 * rename so a reader sees a whole result or none. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "reference_cache.h"
#include "reference_internal.h"

static const char magic[8] = {'s', 't', 'i', 'n', 'r', 'e', 'f', '1'};

typedef struct file_header {
    char magic[8];
    uint64_t key[2], size, payload[2];
} file_header;

/* STIN_REFERENCE_CACHE_STATS: what the cache did in this process. */
static struct {
    int armed, depth;
    unsigned long hits, misses;
    double compute_start, compute_s, load_s, key_s;
} stats;

static double cpu_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void print_stats(void)
{
    fprintf(stderr, "reference cache: %lu hits (%.2f s loading), %lu misses (%.2f s computing), "
                    "%.2f s hashing keys\n",
            stats.hits, stats.load_s, stats.misses, stats.compute_s, stats.key_s);
}

static void arm_stats(void)
{
    const char *v = getenv("STIN_REFERENCE_CACHE_STATS");
    if (stats.armed || !v || strcmp(v, "1"))
        return;
    stats.armed = 1;
    atexit(print_stats);
}

void ref_cache_compute_begin(void)
{
    if (stats.depth++ == 0)
        stats.compute_start = cpu_seconds();
}

void ref_cache_compute_end(void)
{
    if (--stats.depth == 0) {
        stats.compute_s += cpu_seconds() - stats.compute_start;
        stats.misses++;
    }
}

void ref_hash_init(ref_hasher *h)
{
    h->a = 0x243f6a8885a308d3ull;
    h->b = 0x13198a2e03707344ull;
    h->bytes = 0;
}

/* Each lane's step is a bijection of its state for a given word, so two
 * inputs that differ in one word always differ in both lanes after it. */
static void mix_word(ref_hasher *h, uint64_t w)
{
    h->a ^= w;
    h->a *= 0x9e3779b97f4a7c15ull;
    h->a ^= h->a >> 29;
    h->b += w;
    h->b *= 0xc2b2ae3d27d4eb4full;
    h->b ^= h->b >> 31;
    h->b = (h->b << 17) | (h->b >> 47);
}

void ref_hash_bytes(ref_hasher *h, const void *data, size_t n)
{
    const unsigned char *p = (const unsigned char *)data;
    size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        uint64_t w;
        memcpy(&w, p + i, 8);
        mix_word(h, w);
    }
    if (i < n) {
        uint64_t w = 0;
        memcpy(&w, p + i, n - i);
        mix_word(h, w ^ ((uint64_t)(n - i) << 56));
    }
    h->bytes += n;
}

void ref_hash_u64(ref_hasher *h, uint64_t v) { ref_hash_bytes(h, &v, sizeof v); }

void ref_hash_array(ref_hasher *h, const void *data, size_t n)
{
    ref_hash_u64(h, data ? n : ~(uint64_t)0);
    if (data && n)
        ref_hash_bytes(h, data, n);
}

static void finish(const ref_hasher *in, uint64_t out[2])
{
    ref_hasher h = *in;
    mix_word(&h, h.bytes);
    mix_word(&h, h.a ^ h.b);
    out[0] = h.a;
    out[1] = h.b;
}

static const char *cache_dir(void)
{
    const char *d = getenv("STIN_REFERENCE_CACHE");
    return d && *d ? d : NULL;
}

/* The running binary's own bytes: a rebuilt reference (or test) never
 * meets results of another build, even in a directory nobody cleared. */
static int binary_id(uint64_t out[2])
{
    static int state; /* 0: not yet, 1: known, -1: unreadable */
    static uint64_t id[2];
    if (!state) {
        FILE *f = fopen("/proc/self/exe", "rb");
        unsigned char buf[65536];
        size_t n;
        ref_hasher h;
        ref_hash_init(&h);
        state = -1;
        if (f) {
            while ((n = fread(buf, 1, sizeof buf, f)) > 0)
                ref_hash_bytes(&h, buf, n);
            if (!ferror(f)) {
                finish(&h, id);
                state = 1;
            }
            fclose(f);
        }
    }
    memcpy(out, id, sizeof id);
    return state == 1;
}

void ref_hash_scene(ref_hasher *h, const scene *s)
{
    ref_hash_u64(h, (uint64_t)s->mesh_count);
    for (int i = 0; i < s->mesh_count; i++) {
        const scene_mesh *m = &s->meshes[i];
        size_t nv = m->vertex_count, nt = m->triangle_count;
        ref_hash_u64(h, nv);
        ref_hash_u64(h, nt);
        ref_hash_array(h, m->positions, 3 * nv * sizeof(float));
        ref_hash_array(h, m->normals, 3 * nv * sizeof(float));
        ref_hash_array(h, m->uvs, 2 * nv * sizeof(float));
        ref_hash_array(h, m->indices, 3 * nt * sizeof(uint32_t));
    }
    ref_hash_u64(h, (uint64_t)s->texture_count);
    for (int i = 0; i < s->texture_count; i++) {
        const scene_texture *t = &s->textures[i];
        ref_hash_u64(h, (uint64_t)t->kind);
        ref_hash_u64(h, (uint64_t)t->width);
        ref_hash_u64(h, (uint64_t)t->height);
        ref_hash_array(h, t->rgba,
                       t->width > 0 && t->height > 0 ? (size_t)t->width * (size_t)t->height * 4 : 0);
    }
    /* these structs hold no pointers: their bytes are their values */
    ref_hash_array(h, s->materials, (size_t)s->material_count * sizeof *s->materials);
    ref_hash_array(h, s->objects, (size_t)s->object_count * sizeof *s->objects);
    ref_hash_array(h, s->lights, (size_t)s->light_count * sizeof *s->lights);
    ref_hash_array(h, s->csg, (size_t)s->csg_count * sizeof *s->csg);
    ref_hash_bytes(h, &s->camera, sizeof s->camera);
    ref_hash_u64(h, (uint64_t)s->has_camera);
    ref_hash_bytes(h, s->ambient, sizeof s->ambient);
    ref_hash_bytes(h, s->background, sizeof s->background);
    ref_hash_u64(h, (uint64_t)s->width);
    ref_hash_u64(h, (uint64_t)s->height);
    ref_hash_u64(h, (uint64_t)s->shadow_map_size);
}

void ref_cache_snapshot(reference *r)
{
    ref_hasher h;
    if (!cache_dir())
        return;
    ref_hash_init(&h);
    ref_hash_u64(&h, (uint64_t)r->object_count);
    for (int i = 0; i < r->object_count; i++) {
        const ref_object *o = &r->objects[i];
        size_t nv = o->vertex_count, nt = o->triangle_count;
        ref_hash_u64(&h, nv);
        ref_hash_u64(&h, nt);
        ref_hash_array(&h, o->positions, 3 * nv * sizeof(float));
        ref_hash_array(&h, o->normals, 3 * nv * sizeof(float));
        ref_hash_array(&h, o->uvs, 2 * nv * sizeof(float));
        ref_hash_array(&h, o->indices, 3 * nt * sizeof(uint32_t));
        ref_hash_u64(&h, (uint64_t)o->closed);
    }
    finish(&h, r->snapshot_hash);
    r->snapshot_hashed = 1;
}

int ref_cache_key_begin(const reference *r, const char *tag, ref_hasher *h)
{
    uint64_t id[2];
    double start = cpu_seconds();
    if (!cache_dir() || !r || !r->snapshot_hashed || !binary_id(id))
        return 0;
    ref_hash_init(h);
    ref_hash_bytes(h, id, sizeof id);
    ref_hash_array(h, tag, strlen(tag));
    ref_hash_bytes(h, r->snapshot_hash, sizeof r->snapshot_hash);
    ref_hash_bytes(h, &r->eps, sizeof r->eps);
    ref_hash_u64(h, r->area_samples);
    ref_hash_u64(h, (uint64_t)r->facet_terminator);
    ref_csg_hash_state(r, h);
    ref_hash_scene(h, r->s);
    stats.key_s += cpu_seconds() - start;
    return 1;
}

void ref_cache_key_end(ref_hasher *h, ref_cache_key *key) { finish(h, key->k); }

static void path_of(const ref_cache_key *key, char *path, size_t n)
{
    snprintf(path, n, "%s/%016llx%016llx", cache_dir(), (unsigned long long)key->k[0],
             (unsigned long long)key->k[1]);
}

static void payload_hash(const ref_cache_part *parts, int count, uint64_t out[2])
{
    ref_hasher h;
    ref_hash_init(&h);
    for (int i = 0; i < count; i++)
        ref_hash_array(&h, parts[i].data, parts[i].size);
    finish(&h, out);
}

static uint64_t payload_size(const ref_cache_part *parts, int count)
{
    uint64_t n = 0;
    for (int i = 0; i < count; i++)
        n += parts[i].size;
    return n;
}

int ref_cache_load(const ref_cache_key *key, const ref_cache_part *parts, int count)
{
    char path[4096];
    file_header fh;
    uint64_t check[2];
    FILE *f;
    int ok;
    double start = cpu_seconds();
    if (!cache_dir())
        return 0;
    arm_stats();
    path_of(key, path, sizeof path);
    f = fopen(path, "rb");
    if (!f)
        return 0;
    ok = fread(&fh, sizeof fh, 1, f) == 1 && !memcmp(fh.magic, magic, sizeof magic) &&
         fh.key[0] == key->k[0] && fh.key[1] == key->k[1] && fh.size == payload_size(parts, count);
    for (int i = 0; ok && i < count; i++)
        ok = !parts[i].size || fread(parts[i].data, 1, parts[i].size, f) == parts[i].size;
    ok = ok && fgetc(f) == EOF;
    fclose(f);
    if (!ok)
        return 0;
    payload_hash(parts, count, check);
    if (check[0] != fh.payload[0] || check[1] != fh.payload[1])
        return 0;
    stats.hits++;
    stats.load_s += cpu_seconds() - start;
    return 1;
}

void ref_cache_store(const ref_cache_key *key, const ref_cache_part *parts, int count)
{
    char path[4096], tmp[4200];
    file_header fh;
    FILE *f;
    int ok;
    if (!cache_dir())
        return;
    path_of(key, path, sizeof path);
    snprintf(tmp, sizeof tmp, "%s.%ld.tmp", path, (long)getpid());
    memcpy(fh.magic, magic, sizeof magic);
    fh.key[0] = key->k[0];
    fh.key[1] = key->k[1];
    fh.size = payload_size(parts, count);
    payload_hash(parts, count, fh.payload);
    f = fopen(tmp, "wb");
    if (!f)
        return;
    ok = fwrite(&fh, sizeof fh, 1, f) == 1;
    for (int i = 0; ok && i < count; i++)
        ok = !parts[i].size || fwrite(parts[i].data, 1, parts[i].size, f) == parts[i].size;
    ok = fclose(f) == 0 && ok;
    if (!ok || rename(tmp, path) != 0)
        remove(tmp);
}
