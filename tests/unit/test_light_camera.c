/* SPDX-License-Identifier: MIT */
/* Light cameras for shadow maps. A directional map is fitted to the draws in
 * view, so as the camera moves the fitted square moves with the visible set;
 * snapped, it moves by whole texels only, so a static point keeps its place
 * on the texel grid and its shadow does not swim. Without snapping it lands
 * between texels. Spot maps cover the draws' depth. Fake GL: no driver. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "fake_gl.h"
#include "internal.h"

static void *block;
static stin_context *ctx;
static stin_mesh floor_mesh;

/* A 2 x 2 floor tile of two triangles around the origin, drawn on a grid. */
static const float floor_pos[] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
static const uint32_t floor_idx[] = {0, 2, 1, 0, 3, 2};

static int setup(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    stin_desc d;
    stin_mesh_desc md;
    size_t bytes;
    (void)state;
    fake_gl_reset(&cfg);
    memset(&d, 0, sizeof d);
    d.get_proc_address = fake_gl_get_proc;
    d.max_vertices = 64;
    d.max_triangles = 64;
    d.max_draws = 128;
    d.techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_OFF;
    bytes = stin_memory_size(&d);
    block = malloc(bytes);
    if (stin_create(&d, block, bytes, &ctx) != STIN_OK)
        return -1;
    memset(&md, 0, sizeof md);
    md.positions = floor_pos;
    md.vertex_count = 4;
    md.indices = floor_idx;
    md.index_count = 6;
    return stin_create_mesh(ctx, &md, &floor_mesh) == STIN_OK ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    stin_destroy(ctx);
    free(block);
    return 0;
}

/* A frame whose camera looks down at the floor from (x, 8, 8). */
static void frame_at(float x)
{
    stin_frame_desc fd;
    float proj[16] = {0};
    memset(&fd, 0, sizeof fd);
    stin__mat4_identity(fd.view);
    /* a camera turned 45 degrees down, translated: enough for the fit */
    fd.view[5] = 0.70710678f;
    fd.view[6] = 0.70710678f;
    fd.view[9] = -0.70710678f;
    fd.view[10] = 0.70710678f;
    fd.view[12] = -x;
    fd.view[13] = 0.0f;
    fd.view[14] = -11.3137f;
    proj[0] = 4.0f; /* a narrow lens: a few tiles in view */
    proj[5] = 4.0f;
    proj[10] = -1.002f;
    proj[11] = -1.0f;
    proj[14] = -0.2002f;
    memcpy(fd.projection, proj, sizeof proj);
    fd.viewport[2] = 256;
    fd.viewport[3] = 256;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    {
        int i, j;
        for (i = -4; i <= 4; i++)
            for (j = -4; j <= 4; j++) {
                float m[16];
                stin__mat4_identity(m);
                m[12] = 4.0f * (float)i + 0.37f; /* off the texel grid on purpose */
                m[14] = 4.0f * (float)j + 0.21f;
                assert_int_equal(stin_draw(ctx, floor_mesh, m, NULL), STIN_OK);
            }
    }
}

static void light_matrix(float x, uint32_t map_size, float out[16])
{
    stin_light_desc l;
    float view[16], proj[16], n, f;
    memset(&l, 0, sizeof l);
    l.type = STIN_LIGHT_DIRECTIONAL;
    l.direction[0] = 0.3f;
    l.direction[1] = -1.0f;
    l.direction[2] = 0.2f;
    {
        float len = stin__sqrtf(0.3f * 0.3f + 1.0f + 0.2f * 0.2f);
        l.direction[0] /= len;
        l.direction[1] /= len;
        l.direction[2] /= len;
    }
    frame_at(x);
    assert_int_equal(stin__light_camera(ctx, &l, view, proj, &n, &f, map_size), 1);
    assert_true(f > n);
    stin__mat4_mul(out, proj, view);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
}

/* Where a world point falls on the map's texel grid, in texels, for the
 * camera at x; returns 0 when the map's size changed (a new power of two). */
static int texel_of(float x, uint32_t size, float out[2], float *scale)
{
    static const float p[4] = {0.123f, 0.0f, -0.456f, 1.0f};
    float m[16];
    int k;
    light_matrix(x, size, m);
    for (k = 0; k < 2; k++) /* NDC -> texels */
        out[k] = (m[k] * p[0] + m[4 + k] * p[1] + m[8 + k] * p[2] + m[12 + k]) * 0.5f *
                 (float)(size ? size : 1024);
    *scale = m[0];
    return 1;
}

static float fraction(float v)
{
    float f = v - (float)(long)v;
    if (f < 0)
        f += 1.0f;
    return f > 0.5f ? 1.0f - f : f;
}

/* Moving the camera changes the tiles in view and so the fitted square;
 * snapped, a static point moves by whole texels. */
static void test_directional_map_moves_by_whole_texels(void **state)
{
    float a[2], b[2], sa, sb;
    (void)state;
    texel_of(0.0f, 1024, a, &sa);
    texel_of(6.3f, 1024, b, &sb);
    assert_true(sa == sb); /* the same power-of-two square */
    assert_true(a[0] != b[0] || a[1] != b[1]); /* it did move */
    assert_true(fraction(b[0] - a[0]) < 1e-2f);
    assert_true(fraction(b[1] - a[1]) < 1e-2f);
}

/* Without snapping the same move lands between texels: the test above can fail. */
static void test_unsnapped_map_swims(void **state)
{
    float a[2], b[2], sa, sb;
    (void)state;
    texel_of(0.0f, 0, a, &sa);
    texel_of(6.3f, 0, b, &sb);
    assert_true(fraction(b[0] - a[0]) > 1e-2f || fraction(b[1] - a[1]) > 1e-2f || sa != sb);
}

/* A spot light's depth range brackets the floor. */
static void test_spot_fits_the_draws(void **state)
{
    stin_light_desc l;
    float view[16], proj[16], n, f;
    (void)state;
    memset(&l, 0, sizeof l);
    l.type = STIN_LIGHT_SPOT;
    l.position[1] = 5.0f;
    l.direction[1] = -1.0f;
    l.spot_cutoff_deg = 30.0f;
    frame_at(0.0f);
    assert_int_equal(stin__light_camera(ctx, &l, view, proj, &n, &f, 1024), 1);
    assert_true(n > 0.0f && n <= 5.0f);
    assert_true(f >= 5.0f);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
}

/* The map passes' polygon offset: (0, 0) means the default unless the light
 * asks for its offset exactly, where (0, 0) turns it off and other values
 * are used as given; its units are 24-bit depth's steps, scaled where the
 * maps' depth textures measured other bits (OpenGL ES 2.0: Mesa's 32). */
static void test_map_offset_default_and_exact(void **state)
{
    stin_light_desc l;
    float factor, units;
    (void)state;
    memset(&l, 0, sizeof l);
    assert_int_equal(stin__map_offset(ctx, &l, &factor, &units), 1);
    assert_true(factor == 1.1f && units == 4.0f);
    l.shadow_offset[0] = 2.0f;
    l.shadow_offset[1] = 3.0f;
    assert_int_equal(stin__map_offset(ctx, &l, &factor, &units), 1);
    assert_true(factor == 2.0f && units == 3.0f);
    ctx->depth_texture_unit = 1.0f / 4294967296.0f; /* 32-bit maps: 256 steps a 24-bit one */
    assert_int_equal(stin__map_offset(ctx, &l, &factor, &units), 1);
    assert_true(factor == 2.0f && units == 768.0f);
    assert_true(stin__rt_depth_unit(ctx) == 1.0f / 4294967296.0f);
    ctx->depth_texture_unit = 0.0f;
    assert_true(stin__rt_depth_unit(ctx) == STIN__DEPTH24_UNIT);
    l.shadow_offset_exact = 1;
    assert_int_equal(stin__map_offset(ctx, &l, &factor, &units), 1);
    assert_true(factor == 2.0f && units == 3.0f);
    l.shadow_offset[0] = l.shadow_offset[1] = 0.0f;
    assert_int_equal(stin__map_offset(ctx, &l, &factor, &units), 0);
    assert_true(factor == 0.0f && units == 0.0f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_directional_map_moves_by_whole_texels),
        cmocka_unit_test(test_unsnapped_map_swims),
        cmocka_unit_test(test_spot_fits_the_draws),
        cmocka_unit_test(test_map_offset_default_and_exact),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
