/* SPDX-License-Identifier: MIT */
/* API misuse on the fake GL: inputs a hostile or careless caller passes
 * (sizes that overflow, NaN fields, handles of another context, NULL caps,
 * bad framebuffers, extreme scales) must come back as errors, never as a
 * hang, a crash or a silently wrong result. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h> /* NAN only: the test links without -lm */
#include <stdlib.h>
#include <string.h>

#include "fake_gl.h"
#include "internal.h"

static fake_log log_;

typedef struct context {
    void *block;
    size_t bytes;
    stin_context *ctx;
} context;

static stin_desc small_desc(uint32_t max_meshes)
{
    stin_desc d = fake_gl_desc(&log_);
    d.max_meshes = max_meshes;
    d.max_textures = 2;
    d.max_vertices = 64;
    d.max_triangles = 64;
    d.max_texture_bytes = 4096;
    d.techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_OFF;
    return d;
}

/* A context in c->block (allocated on first use, kept otherwise). */
static void create_in(context *c, uint32_t max_meshes)
{
    stin_desc d = small_desc(max_meshes);
    if (!c->block) {
        c->bytes = stin_memory_size(&d);
        assert_true(c->bytes > 0);
        c->block = malloc(c->bytes);
        assert_non_null(c->block);
    }
    assert_int_equal(stin_create(&d, c->block, c->bytes, &c->ctx), STIN_OK);
}

static void release(context *c)
{
    if (c->ctx)
        stin_destroy(c->ctx);
    free(c->block);
    memset(c, 0, sizeof *c);
}

static void use_profile(fake_gl_profile_id id)
{
    fake_gl_config cfg = fake_gl_profile(id);
    fake_gl_reset(&cfg);
}

static const float quad_pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
static const uint32_t quad_idx[] = {0, 1, 2, 0, 2, 3};

static stin_result mesh(stin_context *ctx, const float *pos, uint32_t vertices,
                        const uint32_t *idx, uint32_t indices, stin_mesh *out)
{
    stin_mesh_desc md = {.positions = pos, .vertex_count = vertices, .indices = idx,
                         .index_count = indices};
    return stin_create_mesh(ctx, &md, out);
}

static stin_result quad(stin_context *ctx, stin_mesh *out)
{
    return mesh(ctx, quad_pos, 4, quad_idx, 6, out);
}

/* A GL 2.1 context in c with a frame open. */
static void open_frame(context *c)
{
    stin_frame_desc fd = {.viewport = {0, 0, 64, 48}};
    stin__mat4_identity(fd.view);
    stin__mat4_identity(fd.projection);
    use_profile(FAKE_GL21);
    create_in(c, 2);
    assert_int_equal(stin_begin_frame(c->ctx, &fd), STIN_OK);
}

/* ---- items 9 and 14: the frame's framebuffer ------------------------------------ */
/* The caller's framebuffers on a GL 2.1 context whose default framebuffer
 * has a stencil buffer: 5 colour and depth only, 6 incomplete. */
static fake_gl_fbo fbos[2];

static void use_framebuffers(int default_stencil)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fake_gl_fbo colour_only = {5, 0, 24, 0}, incomplete = {6, 8, 24, 0x8CD6};
    fbos[0] = colour_only;
    fbos[1] = incomplete;
    cfg.framebuffers = fbos;
    cfg.framebuffer_count = 2;
    cfg.stencil_bits = default_stencil;
    fake_gl_reset(&cfg);
}

/* A frame into `framebuffer` with a point light over a quad; its stats. */
static stin_frame_stats shadow_frame(context *c, stin_mesh m, uint32_t framebuffer)
{
    stin_frame_desc fd = {.viewport = {0, 0, 64, 48}};
    stin_light_desc l = {.position = {0.5f, 0.5f, 2.0f}};
    float below[16];
    stin__mat4_identity(fd.view);
    stin__mat4_identity(fd.projection);
    stin__mat4_identity(below);
    below[14] = -1.0f;
    fd.framebuffer = framebuffer;
    assert_int_equal(stin_begin_frame(c->ctx, &fd), STIN_OK);
    assert_int_equal(stin_add_light(c->ctx, &l), STIN_OK);
    assert_int_equal(stin_draw(c->ctx, m, NULL, NULL), STIN_OK);
    assert_int_equal(stin_draw(c->ctx, m, below, NULL), STIN_OK);
    assert_int_equal(stin_end_frame(c->ctx), STIN_OK);
    assert_int_equal(fake_gl.gl.draw_framebuffer, framebuffer);
    return stin_query_frame_stats(c->ctx);
}

static void create_auto(context *c)
{
    stin_desc d = small_desc(2);
    d.techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_NONE; /* the context's choice */
    d.techniques[STIN_FEATURE_SURFACE] = STIN_TECH_SURFACE_PLAIN; /* no per-draw step-downs */
    if (!c->block) {
        c->bytes = stin_memory_size(&d);
        c->block = malloc(c->bytes);
        assert_non_null(c->block);
    }
    assert_int_equal(stin_create(&d, c->block, c->bytes, &c->ctx), STIN_OK);
}

static void test_stencil_is_probed_per_frame_target(void **state)
{
    context c = {0};
    stin_mesh m;
    unsigned fallbacks;
    (void)state;
    use_framebuffers(8);
    fake_gl.gl.draw_framebuffer = fake_gl.gl.read_framebuffer = 5; /* bound at create */
    create_auto(&c);
    assert_int_equal(stin_query_choice(c.ctx, STIN_FEATURE_SHADOWS).technique,
                     STIN_TECH_SHADOWS_VOLUME);
    assert_int_equal(fake_gl.gl.draw_framebuffer, 5);
    assert_int_equal(quad(c.ctx, &m), STIN_OK);
    fallbacks = log_.items[STIN_LOG_FALLBACK];
    /* into the colour-only framebuffer: no volumes, said once */
    assert_int_equal(shadow_frame(&c, m, 5).shadows.volume_triangles, 0);
    assert_true(fake_log_has(&log_, STIN_LOG_FALLBACK, "volume falls back to off in frames "
                                                       "into framebuffer 5"));
    assert_int_equal(shadow_frame(&c, m, 5).shadows.volume_triangles, 0);
    assert_int_equal(log_.items[STIN_LOG_FALLBACK], fallbacks + 1);
    /* into the default one: volumes again; the choice never changed */
    assert_true(shadow_frame(&c, m, 0).shadows.volume_triangles > 0);
    assert_true(fake_log_has(&log_, STIN_LOG_TECHNIQUE_SELECTED, "volume again"));
    assert_int_equal(stin_query_choice(c.ctx, STIN_FEATURE_SHADOWS).technique,
                     STIN_TECH_SHADOWS_VOLUME);
    /* the frame into 5 leaves it bound: a context made now is not poisoned */
    (void)shadow_frame(&c, m, 5);
    stin_destroy(c.ctx);
    create_auto(&c);
    assert_int_equal(stin_query_choice(c.ctx, STIN_FEATURE_SHADOWS).technique,
                     STIN_TECH_SHADOWS_VOLUME);
    release(&c);
    /* no stencil anywhere: maps, as before */
    use_framebuffers(0);
    create_auto(&c);
    assert_int_equal(stin_query_choice(c.ctx, STIN_FEATURE_SHADOWS).technique,
                     STIN_TECH_SHADOWS_MAP_PCF);
    release(&c);
}

static void test_bad_frame_framebuffer_is_an_error(void **state)
{
    stin_frame_desc fd = {.viewport = {0, 0, 64, 48}};
    context c = {0};
    unsigned draws;
    (void)state;
    use_framebuffers(8);
    create_auto(&c);
    stin__mat4_identity(fd.view);
    stin__mat4_identity(fd.projection);
    fake_gl.gl.draw_framebuffer = fake_gl.gl.read_framebuffer = 0;
    memset(&log_, 0, sizeof log_);
    fd.framebuffer = 999; /* never made */
    assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
    assert_true(fake_log_has(&log_, STIN_LOG_BAD_ARGUMENT, "framebuffer 999 is not"));
    fd.framebuffer = 6; /* incomplete */
    assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
    assert_true(fake_log_has(&log_, STIN_LOG_BAD_ARGUMENT, "framebuffer 6 is incomplete"));
    assert_int_equal(log_.errors, 2); /* one line each */
    assert_int_equal(fake_gl.gl.draw_framebuffer, 0); /* the caller's binding kept */
    assert_int_equal(stin_end_frame(c.ctx), STIN_ERROR_INVALID_STATE); /* no frame opened */
    /* complete at begin, incomplete by the end: reported, nothing drawn */
    fd.framebuffer = 5;
    assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_OK);
    assert_int_equal(stin_draw(c.ctx, (stin_mesh){0}, NULL, NULL), STIN_ERROR_INVALID_HANDLE);
    fbos[0].status = 0x8CD6;
    draws = fake_gl.draw_calls;
    assert_int_equal(stin_end_frame(c.ctx), STIN_ERROR_INVALID_ARGUMENT);
    assert_true(fake_log_has(&log_, STIN_LOG_BAD_ARGUMENT, "stin_end_frame: framebuffer 5"));
    assert_int_equal(fake_gl.draw_calls, draws);
    assert_int_equal(fake_gl.gl.draw_framebuffer, 0);
    fbos[0].status = 0;
    assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_OK); /* the failed end closed it */
    assert_int_equal(stin_end_frame(c.ctx), STIN_OK);
    release(&c);
}

/* ---- item 10: texture sizes ----------------------------------------------------- */
static void test_texture_size_overflow_is_an_error(void **state)
{
    static const uint32_t sizes[][2] = {{0x80000001u, 1}, {1, 0x80000001u}, {0xffffffffu, 1},
                                        {65536, 65536}, {0x40000001u, 1}};
    static const fake_gl_profile_id profiles[] = {FAKE_GL11, FAKE_GL14, FAKE_GL21};
    uint8_t px[16] = {0};
    context c = {0};
    size_t p, i;
    unsigned made;
    (void)state;
    for (p = 0; p < sizeof profiles / sizeof profiles[0]; p++) {
        use_profile(profiles[p]);
        create_in(&c, 2);
        made = fake_gl.textures_created;
        for (i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
            stin_texture_desc td;
            stin_texture t = {7};
            memset(&td, 0, sizeof td);
            td.width = sizes[i][0];
            td.height = sizes[i][1];
            td.pixels = px; /* far too small: must not be read */
            assert_int_equal(stin_create_texture(c.ctx, &td, &t), STIN_ERROR_INVALID_ARGUMENT);
            assert_int_equal(t.id, 0);
        }
        assert_int_equal(fake_gl.textures_created, made);
        stin_destroy(c.ctx);
        c.ctx = NULL;
    }
    release(&c);
}

/* ---- item 11: light fields ------------------------------------------------------ */
static void test_non_finite_shadow_offset_is_rejected(void **state)
{
    context c = {0};
    int k;
    (void)state;
    open_frame(&c);
    for (k = 0; k < 2; k++) {
        stin_light_desc l;
        memset(&l, 0, sizeof l);
        l.position[2] = 3.0f;
        l.shadow_offset[k] = NAN;
        assert_int_equal(stin_add_light(c.ctx, &l), STIN_ERROR_INVALID_ARGUMENT);
        l.shadow_offset[k] = (float)INFINITY;
        assert_int_equal(stin_add_light(c.ctx, &l), STIN_ERROR_INVALID_ARGUMENT);
    }
    assert_int_equal(stin_end_frame(c.ctx), STIN_OK);
    assert_int_equal(stin_query_frame_stats(c.ctx).lights, 0);
    release(&c);
}

/* ---- embedding item 6: the frame's matrices ---------------------------------------- */
/* The outline's fields: a step outside 0..64, a non-finite colour or a
 * negative edge is an argument error; a context without GLSL lighting
 * refuses an outline as unsupported, saying why. */
static void test_outline_fields_are_checked(void **state)
{
    context c = {0};
    stin_frame_desc fd = {.viewport = {0, 0, 64, 48}};
    (void)state;
    use_profile(FAKE_GL21);
    create_in(&c, 2);
    stin__mat4_identity(fd.view);
    stin__mat4_identity(fd.projection);
    fd.outline_step = 65.0f;
    assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
    assert_true(fake_log_has(&log_, STIN_LOG_BAD_ARGUMENT, "outline_step"));
    fd.outline_step = -1.0f;
    assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
    fd.outline_step = 1.0f;
    fd.outline_color[1] = NAN;
    assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
    fd.outline_color[1] = 0.0f;
    fd.outline_depth_edge = -0.5f;
    assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
    release(&c);
    use_profile(FAKE_GL11);
    create_in(&c, 2);
    fd.outline_depth_edge = 0.0f;
    assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_ERROR_UNSUPPORTED);
    assert_true(fake_log_has(&log_, STIN_LOG_FALLBACK, "outline needs GLSL"));
    fd.outline_step = 0.0f; /* no outline: the same frame is fine */
    assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_OK);
    assert_int_equal(stin_end_frame(c.ctx), STIN_OK);
    release(&c);
}

/* All-zero (a forgotten matrix) or singular view and projection are refused
 * with a message; far translations, tiny and huge scales and orthographic
 * projections are fine. */
static void test_singular_frame_matrices_are_rejected(void **state)
{
    context c = {0};
    stin_frame_desc fd = {.viewport = {0, 0, 64, 48}};
    static const float scales[] = {1e-18f, 1e-6f, 1.0f, 1e6f, 1e18f};
    size_t i;
    (void)state;
    use_profile(FAKE_GL21);
    create_in(&c, 2);
    stin__mat4_identity(fd.view);
    memset(fd.projection, 0, sizeof fd.projection);
    assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
    assert_true(fake_log_has(&log_, STIN_LOG_BAD_ARGUMENT, "invertible"));
    stin__mat4_identity(fd.projection);
    fd.view[10] = 0.0f; /* flattens z */
    assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
    fd.view[10] = 1.0f;
    fd.view[4] = 1.0f; /* column 1 = column 0 */
    fd.view[5] = 0.0f;
    assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
    for (i = 0; i < sizeof scales / sizeof scales[0]; i++) {
        stin__mat4_identity(fd.view);
        fd.view[0] = fd.view[5] = fd.view[10] = scales[i];
        fd.view[12] = 1e6f; /* far from the origin */
        assert_int_equal(stin_begin_frame(c.ctx, &fd), STIN_OK);
        assert_int_equal(stin_end_frame(c.ctx), STIN_OK);
    }
    release(&c);
}

/* ---- issue 8 item 2: the visibility map ----------------------------------------- */
static stin_result export_frame(context *c, stin_mesh m, stin_export ex, int check_open)
{
    stin_frame_desc fd = {.viewport = {2, 1, 64, 48}};
    stin_light_desc l = {.position = {0.5f, 0.5f, 2.0f}};
    stin_visibility_map map;
    stin_result r;
    stin__mat4_identity(fd.view);
    stin__mat4_identity(fd.projection);
    fd.export_visibility = ex;
    if ((r = stin_begin_frame(c->ctx, &fd)) != STIN_OK)
        return r;
    assert_int_equal(stin_add_light(c->ctx, &l), STIN_OK);
    assert_int_equal(stin_draw(c->ctx, m, NULL, NULL), STIN_OK);
    if (check_open) /* nothing to hand out while a frame is open */
        assert_int_equal(stin_query_visibility_map(c->ctx, &map), STIN_ERROR_INVALID_STATE);
    return stin_end_frame(c->ctx);
}

static void test_visibility_map_contract(void **state)
{
    context c = {0};
    stin_mesh m;
    stin_visibility_map map;
    (void)state;
    use_profile(FAKE_GL21);
    create_auto(&c);
    assert_int_equal(quad(c.ctx, &m), STIN_OK);
    assert_int_equal(stin_query_visibility_map(c.ctx, &map), STIN_ERROR_INVALID_STATE);
    assert_int_equal(stin_bind_visibility(c.ctx, 0), STIN_ERROR_INVALID_STATE);
    assert_int_equal(export_frame(&c, m, (stin_export)7, 0), STIN_ERROR_INVALID_ARGUMENT);
    assert_int_equal(export_frame(&c, m, STIN_EXPORT_VISIBILITY, 1), STIN_OK);
    assert_int_equal(stin_query_visibility_map(c.ctx, &map), STIN_OK);
    assert_true(map.texture != 0);
    assert_int_equal(map.lights, 1);
    assert_int_equal(map.tile_width, 66); /* the viewport's far corner */
    assert_int_equal(map.tile_height, 49);
    assert_true(map.width >= 66 && map.height >= 49);
    /* the application's program must be current; units are the context's */
    assert_int_equal(stin_bind_visibility(c.ctx, 0), STIN_ERROR_INVALID_STATE);
    assert_int_equal(stin_bind_visibility(c.ctx, -1), STIN_ERROR_INVALID_ARGUMENT);
    assert_int_equal(stin_bind_visibility(c.ctx, 1 << 20), STIN_ERROR_INVALID_ARGUMENT);
    /* a frame without the export leaves nothing to hand out */
    assert_int_equal(export_frame(&c, m, STIN_EXPORT_NONE, 0), STIN_OK);
    assert_int_equal(stin_query_visibility_map(c.ctx, &map), STIN_ERROR_INVALID_STATE);
    release(&c);
    /* no framebuffer objects: refused, said */
    use_profile(FAKE_GL14);
    create_auto(&c);
    assert_int_equal(quad(c.ctx, &m), STIN_OK);
    assert_int_equal(export_frame(&c, m, STIN_EXPORT_VISIBILITY_ONLY, 0), STIN_ERROR_UNSUPPORTED);
    assert_true(fake_log_has(&log_, STIN_LOG_FALLBACK, "packed depth-stencil"));
    release(&c);
}

/* ---- item 12: handles ----------------------------------------------------------- */
static void test_handles_of_another_context_are_foreign(void **state)
{
    context a = {0}, b = {0};
    stin_mesh ma, mb;
    stin_mesh_info info;
    (void)state;
    use_profile(FAKE_GL21);
    create_in(&a, 4);
    create_in(&b, 4);
    assert_int_equal(quad(a.ctx, &ma), STIN_OK);
    assert_int_equal(quad(b.ctx, &mb), STIN_OK);
    /* two blocks: tags from their addresses (1 in 256 alike; these two differ) */
    if (a.ctx->handle_tag != b.ctx->handle_tag) {
        assert_true(ma.id != mb.id);
        assert_int_equal(stin_query_mesh_info(b.ctx, ma, &info), STIN_ERROR_INVALID_HANDLE);
        assert_int_equal(stin_query_mesh_info(a.ctx, mb, &info), STIN_ERROR_INVALID_HANDLE);
    }
    /* the same block: a new context never takes the old one's handles */
    stin_destroy(a.ctx);
    create_in(&a, 4);
    assert_int_equal(stin_query_mesh_info(a.ctx, ma, &info), STIN_ERROR_INVALID_HANDLE);
    assert_int_equal(quad(a.ctx, &mb), STIN_OK); /* the same slot, generation 1 again */
    assert_true(mb.id != ma.id);
    assert_int_equal(stin_query_mesh_info(a.ctx, ma, &info), STIN_ERROR_INVALID_HANDLE);
    assert_int_equal(stin_query_mesh_info(a.ctx, mb, &info), STIN_OK);
    release(&a);
    release(&b);
}

/* 70,000 re-creations in one slot: the first id never comes back (16-bit
 * generations wrapped into it after 65,535). */
static void test_generations_never_revive_a_stale_id(void **state)
{
    context c = {0};
    stin_mesh first, m;
    stin_mesh_info info;
    uint32_t i;
    (void)state;
    use_profile(FAKE_GL11);
    create_in(&c, 2);
    assert_int_equal(quad(c.ctx, &first), STIN_OK);
    stin_destroy_mesh(c.ctx, first);
    for (i = 0; i < 70000u; i++) {
        assert_int_equal(quad(c.ctx, &m), STIN_OK);
        if (m.id == first.id)
            fail_msg("re-creation %u issued the first id 0x%x again", i, first.id);
        stin_destroy_mesh(c.ctx, m);
    }
    assert_int_equal(stin_query_mesh_info(c.ctx, first, &info), STIN_ERROR_INVALID_HANDLE);
    release(&c);
}

/* A slot whose generation reached the top is retired: the next mesh takes
 * another slot and every old id stays stale (65,535 slots leave 8 bits). */
static void test_slot_at_top_generation_is_retired(void **state)
{
    static uint32_t ids[300];
    context c = {0};
    stin_mesh m;
    stin_mesh_info info;
    uint32_t i, n = 0;
    (void)state;
    use_profile(FAKE_GL11);
    create_in(&c, 65535);
    for (i = 0; i < 300u; i++) {
        assert_int_equal(quad(c.ctx, &m), STIN_OK);
        ids[n++] = m.id;
        stin_destroy_mesh(c.ctx, m);
    }
    assert_true(c.ctx->meshes[0].handle.retired);
    assert_int_equal(ids[255] & 0xffffu, 2u); /* after 255 generations: slot 1 */
    for (i = 0; i < n; i++) {
        uint32_t k;
        m.id = ids[i];
        assert_int_equal(stin_query_mesh_info(c.ctx, m, &info), STIN_ERROR_INVALID_HANDLE);
        for (k = 0; k < i; k++)
            assert_true(ids[k] != ids[i]);
    }
    release(&c);
}

/* ---- item 13: NULL caps --------------------------------------------------------- */
static void test_tier_queries_take_null_caps(void **state)
{
    char missing[64] = "unchanged";
    (void)state;
    assert_int_equal(stin_tier_supported(NULL, STIN_TIER_GL1, missing, sizeof missing), 0);
    assert_string_equal(missing, "");
    assert_int_equal(stin_tier_supported(NULL, STIN_TIER_GL4, NULL, 0), 0);
    assert_int_equal(stin_best_tier(NULL), STIN_TIER_AUTO);
}

/* ---- item 15: scale invariance -------------------------------------------------- */
static void make_cube(float scale, float pos[24], uint32_t idx[36])
{
    static const uint32_t faces[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                       2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
    int v;
    for (v = 0; v < 8; v++) {
        pos[3 * v] = (v & 1) ^ ((v >> 1) & 1) ? scale : -scale;
        pos[3 * v + 1] = (v & 2) ? scale : -scale;
        pos[3 * v + 2] = (v & 4) ? scale : -scale;
    }
    memcpy(idx, faces, sizeof faces);
}

static void test_meshes_at_extreme_scales(void **state)
{
    static const float scales[] = {1.0f, 1e15f, 1e30f, 1e-12f, 1e-18f};
    context c = {0};
    size_t s;
    (void)state;
    use_profile(FAKE_GL21);
    create_in(&c, 8);
    for (s = 0; s < sizeof scales / sizeof scales[0]; s++) {
        float pos[24];
        uint32_t idx[36];
        stin_mesh m;
        stin_mesh_info info;
        const float *n;
        make_cube(scales[s], pos, idx);
        if (mesh(c.ctx, pos, 8, idx, 36, &m) != STIN_OK)
            fail_msg("a cube of half-size %g was rejected", (double)scales[s]);
        assert_int_equal(stin_query_mesh_info(c.ctx, m, &info), STIN_OK);
        assert_int_equal(info.triangle_count, 12);
        assert_int_equal(info.degenerate_dropped, 0);
        assert_true(info.closed_manifold);
        /* default normals: the corner's diagonal at any scale */
        n = c.ctx->vertices[stin__mesh_lookup(c.ctx, m, NULL)->first_vertex].normal;
        if (!(n[0] < -0.577f && n[0] > -0.578f && n[2] < -0.577f && n[2] > -0.578f))
            fail_msg("scale %g: corner normal (%g, %g, %g)", (double)scales[s], (double)n[0],
                     (double)n[1], (double)n[2]);
        stin_destroy_mesh(c.ctx, m);
    }
    /* a sliver stays degenerate at every scale */
    for (s = 0; s < sizeof scales / sizeof scales[0]; s++) {
        const float k = scales[s];
        const float sliver[9] = {0, 0, 0, k, 0, 0, 2 * k, 1e-9f * k, 0};
        const uint32_t tri[3] = {0, 1, 2};
        stin_mesh m;
        assert_int_equal(mesh(c.ctx, sliver, 3, tri, 3, &m), STIN_ERROR_INVALID_MESH);
    }
    release(&c);
}

static void test_light_directions_at_extreme_scales(void **state)
{
    static const float lengths[] = {1e-30f, 1e-40f /* subnormal */, 1e-20f, 1e20f, 3e38f};
    context c = {0};
    size_t i;
    (void)state;
    open_frame(&c);
    for (i = 0; i < sizeof lengths / sizeof lengths[0]; i++) {
        stin_light_desc l;
        const float *d;
        memset(&l, 0, sizeof l);
        l.type = STIN_LIGHT_DIRECTIONAL;
        l.direction[0] = lengths[i];
        l.direction[1] = -lengths[i];
        if (stin_add_light(c.ctx, &l) != STIN_OK)
            fail_msg("direction (%g, %g, 0) was rejected", (double)lengths[i], (double)-lengths[i]);
        d = c.ctx->lights[c.ctx->light_count - 1].direction;
        assert_true(d[0] > 0.7070f && d[0] < 0.7072f && d[1] < -0.7070f && d[1] > -0.7072f);
    }
    {
        stin_light_desc l;
        memset(&l, 0, sizeof l);
        l.type = STIN_LIGHT_SPOT;
        assert_int_equal(stin_add_light(c.ctx, &l), STIN_ERROR_INVALID_ARGUMENT);
    }
    assert_int_equal(stin_end_frame(c.ctx), STIN_OK);
    release(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stencil_is_probed_per_frame_target),
        cmocka_unit_test(test_bad_frame_framebuffer_is_an_error),
        cmocka_unit_test(test_texture_size_overflow_is_an_error),
        cmocka_unit_test(test_non_finite_shadow_offset_is_rejected),
        cmocka_unit_test(test_singular_frame_matrices_are_rejected),
        cmocka_unit_test(test_outline_fields_are_checked),
        cmocka_unit_test(test_handles_of_another_context_are_foreign),
        cmocka_unit_test(test_generations_never_revive_a_stale_id),
        cmocka_unit_test(test_slot_at_top_generation_is_retired),
        cmocka_unit_test(test_tier_queries_take_null_caps),
        cmocka_unit_test(test_meshes_at_extreme_scales),
        cmocka_unit_test(test_light_directions_at_extreme_scales),
        cmocka_unit_test(test_visibility_map_contract),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
