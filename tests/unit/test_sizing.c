/* SPDX-License-Identifier: MIT */
/* Sizing a desc from assets (issue 8 item 3): the staging a texture needs,
 * stin_desc_fit's capacities and limits, and real asset sizes (a
 * 4096x4096 texture, a 1M-triangle mesh) created with a fitted desc. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "fake_gl.h"
#include "internal.h"

static stin_texture_desc texture(stin_texture_kind kind, uint32_t w, uint32_t h)
{
    stin_texture_desc t;
    memset(&t, 0, sizeof t);
    t.kind = kind;
    t.width = w;
    t.height = h;
    return t;
}

/* Levels 1 and 2 for an albedo texture used as given; level 0 and 1 for a
 * normal map or a power-of-two resample; nothing without mipmaps. */
static void test_texture_staging_bytes(void **state)
{
    stin_texture_desc t = texture(STIN_TEXTURE_ALBEDO, 1024, 1024);
    (void)state;
    assert_int_equal(stin_texture_staging_bytes(&t), 4u * (512u * 512u + 256u * 256u));
    t.base_level_only = 1;
    assert_int_equal(stin_texture_staging_bytes(&t), 0);
    t = texture(STIN_TEXTURE_NORMAL, 1024, 1024);
    assert_int_equal(stin_texture_staging_bytes(&t), 4u * (1024u * 1024u + 512u * 512u));
    t = texture(STIN_TEXTURE_ALBEDO, 1000, 600); /* GL1 resamples to 1024 x 1024 */
    assert_int_equal(stin_texture_staging_bytes(&t), 4u * (1024u * 1024u + 512u * 512u));
    t = texture(STIN_TEXTURE_NORMAL, 1000, 600);
    t.normal_from_height = 1.0f; /* and the derived source before the resample */
    assert_int_equal(stin_texture_staging_bytes(&t),
                     4u * (1024u * 1024u + 512u * 512u) + 4u * 1000u * 600u);
    t = texture(STIN_TEXTURE_NORMAL, 8192, 8192); /* halved on a 4096 context: source kept */
    t.normal_from_height = 1.0f;
    assert_int_equal(stin_texture_staging_bytes(&t),
                     4ull * (8192u * 8192u + 4096u * 4096u) + 4ull * 8192u * 8192u);
    /* height maps: level 0 as given, and displacement's copy with the chain */
    t = texture(STIN_TEXTURE_HEIGHT, 256, 256);
    assert_int_equal(stin_texture_staging_bytes(&t), 4u * (128u * 128u + 64u * 64u));
    t.base_level_only = 1;
    assert_int_equal(stin_texture_staging_bytes(&t), 0);
    t = texture(STIN_TEXTURE_ALBEDO, 0, 16);
    assert_int_equal(stin_texture_staging_bytes(&t), 0);
    assert_int_equal(stin_texture_staging_bytes(NULL), 0);
}

/* The deep shadow maps' GPU memory: 2 ping-pong textures x 6 faces x
 * ceil(layers / 2) slices x size^2 x 16 bytes (RGBA32F) plus a size^2 x 4
 * depth buffer; the seed's 2048 x 2048 x 4 layers x 6 faces x 16 bytes is
 * 1,610,612,736 of it. Bad deep values make the desc bad. */
static void test_deep_memory(void **state)
{
    stin_desc d;
    (void)state;
    memset(&d, 0, sizeof d);
    assert_int_equal(stin_deep_memory_bytes(&d), 2ull * 6 * 2 * 512 * 512 * 16 + 512ull * 512 * 4);
    d.translucent.deep_map_size = 2048;
    assert_int_equal(stin_deep_memory_bytes(&d), 1610612736ull + 2048ull * 2048 * 4);
    d.translucent.deep_layers = 3; /* three layers take two slices of the even texture, one of the odd */
    assert_int_equal(stin_deep_memory_bytes(&d), 1610612736ull + 2048ull * 2048 * 4);
    d.translucent.deep_layers = 1;
    assert_int_equal(stin_deep_memory_bytes(&d), 1610612736ull / 2 + 2048ull * 2048 * 4);
    d.translucent.deep_layers = 17;
    assert_int_equal(stin_deep_memory_bytes(&d), 0);
    assert_int_equal(stin_memory_size(&d), 0);
    d.translucent.deep_layers = 4;
    d.translucent.deep_map_size = 3000; /* not a power of two */
    assert_int_equal(stin_deep_memory_bytes(&d), 0);
    d.translucent.deep_map_size = 8192; /* above 4096 */
    assert_int_equal(stin_deep_memory_bytes(&d), 0);
    d.translucent.deep_map_size = 0;
    d.translucent.deep_mono = 2;
    assert_int_equal(stin_memory_size(&d), 0);
    assert_int_equal(stin_deep_memory_bytes(NULL), 0);
}

/* A desc stin_create refuses for its enum values (an unknown tier, an
 * unknown technique, a technique forced on another feature) has no size
 * either: stin_memory_size and stin_deep_memory_bytes are 0, and
 * stin_create names the value (the same check, select/select.c). */
static void test_bad_enums_have_no_size(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fake_log log;
    stin_desc d;
    stin_context *ctx = NULL;
    static unsigned char block[64];
    int i;
    (void)state;
    for (i = 0; i < 4; i++) {
        fake_gl_reset(&cfg);
        d = fake_gl_desc(&log);
        if (i == 0)
            d.tier = (stin_tier)3;
        else if (i == 1)
            d.techniques[STIN_FEATURE_SHADOWS] = (stin_technique)STIN_TECH_COUNT;
        else if (i == 2)
            d.techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_SURFACE_NORMAL;
        else
            d.techniques[STIN_FEATURE_CSG] = (stin_technique)-7;
        assert_int_equal(stin_memory_size(&d), 0);
        assert_int_equal(stin_deep_memory_bytes(&d), 0);
        assert_int_equal(stin_create(&d, block, sizeof block, &ctx), STIN_ERROR_INVALID_ARGUMENT);
        assert_true(fake_log_has(&log, STIN_LOG_BAD_ARGUMENT, i ? "is not a" : "unknown tier 3"));
        assert_null(ctx);
    }
    d = fake_gl_desc(&log);
    d.techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_VOLUME;
    assert_true(stin_memory_size(&d) > 0);
}

static void test_desc_fit_raises_and_limits(void **state)
{
    stin_desc d;
    stin_asset_summary a;
    const char *field = "x";
    (void)state;
    memset(&d, 0, sizeof d);
    memset(&a, 0, sizeof a);
    d.max_draws = 5000; /* larger values stay */
    a.meshes = 3;
    a.vertices = 600000;
    a.triangles = 1200000;
    a.largest_mesh_triangles = 1000000;
    a.largest_texture_staging = 20u << 20;
    a.draws = 10;
    a.lights = 4;
    assert_int_equal(stin_desc_fit(&d, &a, &field), STIN_OK);
    assert_null(field);
    assert_int_equal(d.max_meshes, 3);
    assert_int_equal(d.max_vertices, 600000);
    assert_int_equal(d.max_triangles, 1200000);
    assert_int_equal(d.max_mesh_triangles, 1000000);
    assert_int_equal(d.max_texture_bytes, 20u << 20);
    assert_int_equal(d.max_draws, 5000);
    assert_int_equal(d.max_lights, 4);
    assert_int_equal(d.max_textures, 0); /* 0 in the summary: the default stays */
    a.lights = 33;
    d.max_lights = 0;
    assert_int_equal(stin_desc_fit(&d, &a, &field), STIN_ERROR_CAPACITY);
    assert_string_equal(field, "max_lights");
    assert_int_equal(d.max_lights, 0); /* unchanged */
    a.lights = 1;
    a.vertices = 1ull << 30;
    assert_int_equal(stin_desc_fit(&d, &a, &field), STIN_ERROR_CAPACITY);
    assert_string_equal(field, "max_vertices");
    /* only the largest mesh given: all meshes hold at least it */
    memset(&d, 0, sizeof d);
    memset(&a, 0, sizeof a);
    a.largest_mesh_triangles = 300000;
    assert_int_equal(stin_desc_fit(&d, &a, NULL), STIN_OK);
    assert_int_equal(d.max_triangles, 300000);
}

/* A 4096x4096 albedo texture and a 1M-triangle mesh, created with a desc
 * fitted to them; the 4 MiB staging of the old default refuses the texture. */
static void test_real_asset_sizes_load(void **state)
{
    enum { N = 4096, GRID = 708 }; /* 707 x 707 x 2 = 999,698 triangles */
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    stin_desc d;
    stin_asset_summary a;
    stin_texture_desc td = texture(STIN_TEXTURE_ALBEDO, N, N);
    stin_mesh_desc md;
    stin_texture t;
    stin_mesh m;
    stin_context *ctx = NULL;
    float *pos = malloc(sizeof(float) * 3u * GRID * GRID);
    uint32_t *idx = malloc(sizeof(uint32_t) * 6u * (GRID - 1) * (GRID - 1)), i, j, k = 0;
    uint8_t *px = calloc((size_t)N * N, 4);
    void *block;
    size_t bytes;
    (void)state;
    assert_non_null(pos);
    assert_non_null(idx);
    assert_non_null(px);
    for (j = 0; j < GRID; j++)
        for (i = 0; i < GRID; i++) {
            pos[3 * (j * GRID + i)] = (float)i;
            pos[3 * (j * GRID + i) + 1] = (float)j;
            pos[3 * (j * GRID + i) + 2] = 0.0f;
        }
    for (j = 0; j + 1 < GRID; j++)
        for (i = 0; i + 1 < GRID; i++) {
            uint32_t v = j * GRID + i;
            uint32_t q[6] = {v, v + 1, v + GRID + 1, v, v + GRID + 1, v + GRID};
            memcpy(idx + k, q, sizeof q);
            k += 6;
        }
    memset(&md, 0, sizeof md);
    md.positions = pos;
    md.vertex_count = GRID * GRID;
    md.indices = idx;
    md.index_count = k;
    td.pixels = px;
    cfg.max_texture_size = N;
    fake_gl_reset(&cfg);
    d = fake_gl_desc(NULL);
    memset(&a, 0, sizeof a);
    a.meshes = a.textures = 1;
    a.vertices = md.vertex_count;
    a.triangles = a.largest_mesh_triangles = k / 3u;
    a.largest_texture_staging = stin_texture_staging_bytes(&td);
    assert_int_equal(stin_desc_fit(&d, &a, NULL), STIN_OK);
    bytes = stin_memory_size(&d);
    assert_true(bytes > 0);
    block = malloc(bytes);
    assert_non_null(block);
    assert_int_equal(stin_create(&d, block, bytes, &ctx), STIN_OK);
    assert_int_equal(stin_create_texture(ctx, &td, &t), STIN_OK);
    assert_int_equal(fake_gl.tex_levels, 13); /* 4096 down to 1 */
    assert_int_equal(stin_create_mesh(ctx, &md, &m), STIN_OK);
    stin_destroy(ctx);
    d.max_texture_bytes = 4u << 20;
    assert_int_equal(stin_create(&d, block, bytes, &ctx), STIN_OK);
    assert_int_equal(stin_create_texture(ctx, &td, &t), STIN_ERROR_CAPACITY);
    stin_destroy(ctx);
    free(block);
    free(px);
    free(idx);
    free(pos);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_texture_staging_bytes),
        cmocka_unit_test(test_deep_memory),
        cmocka_unit_test(test_bad_enums_have_no_size),
        cmocka_unit_test(test_desc_fit_raises_and_limits),
        cmocka_unit_test(test_real_asset_sizes_load),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
