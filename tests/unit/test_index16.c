/* SPDX-License-Identifier: MIT */
/* 16-bit element indices (assets/mesh_chunks.c): the split of a mesh into
 * chunks of at most a given number of vertices (every triangle drawn once,
 * from the same corners, every index in its chunk's range), and on the fake
 * GL that a context without STIN_CAP_ELEMENT_INDEX_UINT never draws with
 * GL_UNSIGNED_INT on any tier and shadow technique, while one with it does. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "fake_gl.h"
#include "internal.h"

/* An n x n grid of vertices, two triangles a cell, the cells in an order
 * that jumps about (stride coprime with the cell count) so chunks meet
 * vertices again after they left them. */
static uint32_t grid_triangles(uint32_t n, uint32_t *tris)
{
    uint32_t cells = (n - 1u) * (n - 1u), c, t = 0, stride = 7919u;
    for (c = 0; c < cells; c++) {
        uint32_t k = (uint32_t)(((uint64_t)c * stride) % cells);
        uint32_t x = k % (n - 1u), y = k / (n - 1u), v = y * n + x;
        tris[t++] = v;
        tris[t++] = v + 1u;
        tris[t++] = v + n;
        tris[t++] = v + 1u;
        tris[t++] = v + n + 1u;
        tris[t++] = v + n;
    }
    return t / 3u;
}

static void check_split(uint32_t n, uint32_t limit)
{
    uint32_t nv = n * n, *tris = malloc(sizeof(uint32_t) * 6u * (n - 1u) * (n - 1u));
    uint32_t *stamp = malloc(sizeof(uint32_t) * nv), *local = malloc(sizeof(uint32_t) * nv);
    uint32_t *src = malloc(sizeof(uint32_t) * nv), max = 3u * nv, nt, count, c, t, k;
    uint32_t next_tri = 0, next_vertex = 0;
    uint16_t *idx;
    stin__index_chunk *chunks = malloc(sizeof *chunks * max);
    assert_non_null(tris);
    nt = grid_triangles(n, tris);
    idx = malloc(sizeof(uint16_t) * 3u * nt);
    count = stin__index_split(tris, nt, nv, limit, stamp, local, chunks, max);
    assert_true(count >= 1u);
    if (nv <= limit)
        assert_int_equal(count, 1);
    memset(stamp, 0, sizeof(uint32_t) * nv);
    for (c = 0; c < count; c++) {
        const stin__index_chunk *ch = &chunks[c];
        /* contiguous: the chunks cover every triangle once, in order */
        assert_int_equal(ch->first_triangle, next_tri);
        assert_int_equal(ch->first_vertex, next_vertex);
        assert_true(ch->triangle_count > 0u);
        assert_true(ch->vertex_count <= limit);
        next_tri += ch->triangle_count;
        next_vertex += ch->vertex_count;
        stin__index_chunk_fill(tris, ch, c + 1u, stamp, local, idx, src);
        for (t = 0; t < ch->triangle_count; t++)
            for (k = 0; k < 3u; k++) {
                uint16_t i = idx[3u * t + k];
                assert_true(i < ch->vertex_count); /* in the chunk's range */
                /* the same corner of the same triangle */
                assert_int_equal(src[i], tris[3u * (ch->first_triangle + t) + k]);
            }
        if (c + 1u < count) /* closed only when the next triangle did not fit */
            assert_true(ch->vertex_count + 3u > limit);
    }
    assert_int_equal(next_tri, nt);
    /* too few chunks allowed: refused, not overrun */
    if (count > 1u)
        assert_int_equal(stin__index_split(tris, nt, nv, limit, stamp, local, chunks, count - 1u),
                         0);
    free(tris);
    free(stamp);
    free(local);
    free(src);
    free(idx);
    free(chunks);
}

static void test_split_small_limits(void **state)
{
    (void)state;
    check_split(12, 3);    /* a triangle a chunk */
    check_split(40, 100);  /* many chunks, seams everywhere */
    check_split(40, 1600); /* 1,600 vertices in one chunk */
    check_split(40, 65535);
}

static void test_split_16_bit(void **state)
{
    (void)state;
    check_split(300, STIN__CHUNK_VERTICES); /* 90,000 vertices: two chunks or more */
}

static void test_chunks_max_bounds_split(void **state)
{
    /* the layout's row per mesh holds the worst split of its size */
    uint32_t n = 300, nt = 2u * (n - 1u) * (n - 1u);
    (void)state;
    assert_true(stin__index_chunks_max(nt) >= 3u * nt / STIN__CHUNK_VERTICES + 1u);
    assert_int_equal(stin__index_chunks_max(1), 1);
}

/* ---- frames on the fake GL --------------------------------------------------- */

static fake_log log_;

typedef struct frame_case {
    fake_gl_profile_id profile;
    stin_tier tier;
    stin_technique shadows;
} frame_case;

/* A context (masked or not), one 260 x 260 grid mesh (67,600 vertices)
 * drawn lit by a spot light over a small quad, one frame; returns the
 * fake's counters. */
static void run_frame(const frame_case *fc, int masked, unsigned *uint_draws,
                      unsigned *ushort_draws, uint32_t *chunks)
{
    fake_gl_config cfg = fake_gl_profile(fc->profile);
    const uint32_t n = 260, nv = n * n, nt = 2u * (n - 1u) * (n - 1u);
    stin_desc d;
    stin_context *ctx = NULL;
    stin_mesh mesh;
    stin_mesh_desc md;
    stin_frame_desc fd;
    stin_light_desc l;
    stin_material mat;
    float *pos = malloc(sizeof(float) * 3u * nv);
    uint32_t *tris = malloc(sizeof(uint32_t) * 3u * nt), i, slot = 0;
    void *block;
    size_t bytes;
    fake_gl_reset(&cfg);
    memset(&log_, 0, sizeof log_);
    for (i = 0; i < nv; i++) {
        pos[3u * i] = (float)(i % n) / (float)n - 0.5f;
        pos[3u * i + 1] = (float)(i / n) / (float)n - 0.5f;
        pos[3u * i + 2] = 0.0f;
    }
    (void)grid_triangles(n, tris);
    memset(&d, 0, sizeof d);
    d.get_proc_address = fake_gl_get_proc;
    d.log = fake_log_fn;
    d.log_user = &log_;
    d.max_meshes = 2;
    d.max_vertices = nv;
    d.max_triangles = nt;
    d.max_mesh_triangles = nt;
    d.max_texture_bytes = 1024;
    d.tier = fc->tier;
    d.techniques[STIN_FEATURE_SHADOWS] = fc->shadows;
    d.techniques[STIN_FEATURE_CSG] = STIN_TECH_CSG_OFF;
    d.caps_mask = masked ? STIN_CAP_BIT(STIN_CAP_ELEMENT_INDEX_UINT) : 0;
    bytes = stin_memory_size(&d);
    block = malloc(bytes);
    assert_int_equal(stin_create(&d, block, bytes, &ctx), STIN_OK);
    memset(&md, 0, sizeof md);
    md.positions = pos;
    md.vertex_count = nv;
    md.indices = tris;
    md.index_count = 3u * nt;
    assert_int_equal(stin_create_mesh(ctx, &md, &mesh), STIN_OK);
    assert_non_null(stin__mesh_lookup(ctx, mesh, &slot));
    *chunks = ctx->meshes[slot].chunk_count;
    memset(&fd, 0, sizeof fd);
    stin__mat4_identity(fd.view);
    stin__mat4_identity(fd.projection);
    fd.viewport[2] = 64;
    fd.viewport[3] = 48;
    memset(&l, 0, sizeof l);
    l.type = STIN_LIGHT_SPOT;
    l.position[2] = 3.0f;
    l.direction[2] = -1.0f;
    l.spot_cutoff_deg = 60.0f;
    memset(&mat, 0, sizeof mat);
    mat.color[0] = mat.color[1] = mat.color[2] = mat.color[3] = 1.0f;
    fake_gl.uint_index_draws = fake_gl.ushort_index_draws = 0;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    assert_int_equal(stin_add_light(ctx, &l), STIN_OK);
    assert_int_equal(stin_draw(ctx, mesh, NULL, &mat), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    *uint_draws = fake_gl.uint_index_draws;
    *ushort_draws = fake_gl.ushort_index_draws;
    assert_int_equal(log_.errors, 0);
    stin_destroy(ctx);
    free(block);
    free(pos);
    free(tris);
}

static const frame_case cases[] = {
    {FAKE_GL21, STIN_TIER_GL2, STIN_TECH_SHADOWS_MAP_PCF},
    {FAKE_GL21, STIN_TIER_GL2, STIN_TECH_SHADOWS_VOLUME},
    {FAKE_GL21, STIN_TIER_GL1, STIN_TECH_SHADOWS_MAP_DEPTH},
    {FAKE_GL45_CORE, STIN_TIER_GL4, STIN_TECH_SHADOWS_VDSM},
    {FAKE_GL45_CORE, STIN_TIER_GL4, STIN_TECH_SHADOWS_MAP_PCF},
};

static void test_masked_frames_draw_16_bit(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        unsigned u32, u16;
        uint32_t chunks;
        run_frame(&cases[i], 1, &u32, &u16, &chunks);
        print_message("case %zu masked: %u 32-bit, %u 16-bit draws, %u chunks\n", i, u32, u16,
                      chunks);
        assert_int_equal(u32, 0);
        assert_true(u16 >= chunks);
        assert_true(chunks >= 2u); /* 67,600 vertices: split */
        run_frame(&cases[i], 0, &u32, &u16, &chunks);
        assert_true(u32 > 0u); /* the same frame with the bit draws 32-bit */
        assert_int_equal(u16, 0);
        assert_int_equal(chunks, 1);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_split_small_limits),
        cmocka_unit_test(test_split_16_bit),
        cmocka_unit_test(test_chunks_max_bounds_split),
        cmocka_unit_test(test_masked_frames_draw_16_bit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
