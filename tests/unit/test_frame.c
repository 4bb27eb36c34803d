/* SPDX-License-Identifier: MIT */
/* Frames and textures on the fake GL: call order, light and draw
 * validation, capacities, stats and pass counts, the GL state left behind,
 * and texture uploads (power-of-two resampling, mip chains, staging). */
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
#include "gl/stage_times_private.h" /* module state the tests read */
#include "shadow/vdsm_private.h"

static fake_log log_;
static void *block;
static stin_context *ctx;
static stin_mesh quad;
static stin_technique shadows = STIN_TECH_SHADOWS_OFF; /* of the next context */
static uint64_t caps_mask;
static uint64_t debug_flags; /* of the next context */
static stin_technique translucent = STIN_TECH_NONE; /* forced translucent-shadows, if any */

static const float quad_pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
static const uint32_t quad_idx[] = {0, 1, 2, 0, 2, 3};

/* Built with -DSTIN_GL_CHECK=1, every GL call is audited against the
 * profile; a violation is logged as STIN_LOG_GL_ERROR. */
static void destroy_context(void)
{
    assert_int_equal(log_.items[STIN_LOG_GL_ERROR], 0);
    if (ctx)
        stin_destroy(ctx);
    free(block);
    ctx = NULL;
    block = NULL;
}

/* A context on the fake `cfg`, with one quad mesh. */
static void create_context(const fake_gl_config *cfg, uint32_t max_lights, uint32_t max_draws,
                           uint32_t max_texture_bytes)
{
    stin_desc d;
    stin_mesh_desc md;
    size_t bytes;
    destroy_context();
    fake_gl_reset(cfg);
    memset(&log_, 0, sizeof log_);
    memset(&d, 0, sizeof d);
    d.get_proc_address = fake_gl_get_proc;
    d.log = fake_log_fn;
    d.log_user = &log_;
    d.max_meshes = 4;
    d.max_textures = 2;
    d.max_vertices = 64;
    d.max_triangles = 64;
    d.max_lights = max_lights;
    d.max_draws = max_draws;
    d.max_texture_bytes = max_texture_bytes;
    d.techniques[STIN_FEATURE_SHADOWS] = shadows; /* pass counts are unshadowed by default */
    d.techniques[STIN_FEATURE_TRANSLUCENT_SHADOWS] = translucent;
    d.caps_mask = caps_mask;
    d.debug_flags = debug_flags;
    bytes = stin_memory_size(&d);
    assert_true(bytes > 0);
    block = malloc(bytes);
    assert_non_null(block);
    assert_int_equal(stin_create(&d, block, bytes, &ctx), STIN_OK);
    memset(&md, 0, sizeof md);
    md.positions = quad_pos;
    md.vertex_count = 4;
    md.indices = quad_idx;
    md.index_count = 6;
    assert_int_equal(stin_create_mesh(ctx, &md, &quad), STIN_OK);
}

static void create_profile(fake_gl_profile_id id, uint32_t max_lights, uint32_t max_draws)
{
    fake_gl_config cfg = fake_gl_profile(id);
    create_context(&cfg, max_lights, max_draws, 4096);
}

static int setup(void **state)
{
    (void)state;
    create_profile(FAKE_GL21, 16, 8);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    destroy_context();
    return 0;
}

static stin_frame_desc frame_desc(void)
{
    stin_frame_desc fd;
    memset(&fd, 0, sizeof fd);
    stin__mat4_identity(fd.view);
    stin__mat4_identity(fd.projection);
    fd.viewport[2] = 64;
    fd.viewport[3] = 48;
    return fd;
}

static void begin(void)
{
    stin_frame_desc fd = frame_desc();
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
}

static stin_light_desc point_light(float x)
{
    stin_light_desc l;
    memset(&l, 0, sizeof l);
    l.position[0] = x;
    l.position[2] = 3.0f;
    return l;
}

static void add_lights(int n)
{
    int i;
    for (i = 0; i < n; i++) {
        stin_light_desc l = point_light((float)i);
        assert_int_equal(stin_add_light(ctx, &l), STIN_OK);
    }
}

/* ---- call order ------------------------------------------------------------ */
static void test_call_order_errors(void **state)
{
    stin_light_desc l = point_light(0);
    stin_frame_desc fd = frame_desc();
    (void)state;
    assert_int_equal(stin_draw(ctx, quad, NULL, NULL), STIN_ERROR_INVALID_STATE);
    assert_int_equal(stin_add_light(ctx, &l), STIN_ERROR_INVALID_STATE);
    assert_int_equal(stin_end_frame(ctx), STIN_ERROR_INVALID_STATE);
    assert_int_equal(log_.items[STIN_LOG_FRAME_STATE], 3);
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_ERROR_INVALID_STATE);
    assert_int_equal(log_.items[STIN_LOG_FRAME_STATE], 4);
    /* The open frame is still usable. */
    assert_int_equal(stin_draw(ctx, quad, NULL, NULL), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_ERROR_INVALID_STATE);
    assert_int_equal(fake_gl.draw_calls, 1);
    assert_int_equal(stin_begin_frame(NULL, &fd), STIN_ERROR_INVALID_ARGUMENT);
    assert_int_equal(stin_begin_frame(ctx, NULL), STIN_ERROR_INVALID_ARGUMENT);
}

static void test_bad_frame_descs(void **state)
{
    stin_frame_desc fd;
    (void)state;
    fd = frame_desc();
    fd.viewport[2] = 0;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
    fd = frame_desc();
    fd.view[5] = NAN;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
    fd = frame_desc();
    fd.ambient[1] = NAN;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
    fd = frame_desc();
    fd.output = (stin_output)7;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
    assert_int_equal(log_.items[STIN_LOG_BAD_ARGUMENT], 4);
    /* A rejected begin opens no frame. */
    assert_int_equal(stin_end_frame(ctx), STIN_ERROR_INVALID_STATE);

    create_profile(FAKE_GL11, 8, 8); /* no framebuffer objects */
    fd = frame_desc();
    fd.framebuffer = 3;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
}

/* A viewport past the context's limits (GL_MAX_VIEWPORT_DIMS 16384 and
 * GL_MAX_TEXTURE_SIZE 16384 on the fake's core profiles) is refused before
 * any GL call and named in the log: a huge origin aborted the driver, its
 * far corner overflowed an int in vdsm's buffers, a far corner past the
 * texture limit left GL_INVALID_VALUE pending. The largest that fits runs. */
static unsigned gl_calls(void)
{
    unsigned n = 0;
    size_t i;
    for (i = 0; i < STIN_GLFN_COUNT; i++)
        n += fake_gl.calls[i];
    return n;
}

static void test_viewport_outside_limits(void **state)
{
    static const int bad[][4] = {{0x7fff0000, 0, 64, 48},  {0, 0x7fffffc0, 64, 48},
                                 {0, 0, 100000, 100000},   {0, 0, 16385, 48},
                                 {16384 - 63, 0, 64, 48},  {0, 16384 - 47, 64, 48},
                                 {-1, 0, 64, 48},          {0, -5, 64, 48}};
    stin_frame_desc fd;
    unsigned calls;
    size_t i;
    (void)state;
    destroy_context();
    create_profile(FAKE_GL45_CORE, 8, 8);
    assert_int_equal(stin_query_caps(ctx)->max_viewport_dims[0], 16384);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fd = frame_desc();
        memcpy(fd.viewport, bad[i], sizeof fd.viewport);
        calls = gl_calls();
        assert_int_equal(stin_begin_frame(ctx, &fd), STIN_ERROR_INVALID_ARGUMENT);
        assert_int_equal(gl_calls(), calls);
        assert_int_equal(log_.items[STIN_LOG_BAD_ARGUMENT], (int)i + 1);
        assert_true(fake_log_has(&log_, STIN_LOG_BAD_ARGUMENT, "GL_MAX_VIEWPORT_DIMS"));
        assert_int_equal(stin_end_frame(ctx), STIN_ERROR_INVALID_STATE);
    }
    fd = frame_desc();
    fd.viewport[0] = 16384 - 64;
    fd.viewport[1] = 16384 - 48;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    add_lights(1);
    assert_int_equal(stin_draw(ctx, quad, NULL, NULL), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
}

/* ---- lights ------------------------------------------------------------------ */
static void test_bad_lights_are_rejected(void **state)
{
    stin_light_desc l;
    stin_frame_stats st;
    (void)state;
    begin();
    l = point_light(0);
    l.position[1] = NAN;
    assert_int_equal(stin_add_light(ctx, &l), STIN_ERROR_INVALID_ARGUMENT);
    l = point_light(0);
    l.type = STIN_LIGHT_SPOT;
    l.direction[2] = -1.0f;
    l.spot_cutoff_deg = 120.0f;
    assert_int_equal(stin_add_light(ctx, &l), STIN_ERROR_INVALID_ARGUMENT);
    l.spot_cutoff_deg = 90.0f; /* the upper bound is allowed */
    assert_int_equal(stin_add_light(ctx, &l), STIN_OK);
    l = point_light(0);
    l.type = STIN_LIGHT_DIRECTIONAL; /* zero direction */
    assert_int_equal(stin_add_light(ctx, &l), STIN_ERROR_INVALID_ARGUMENT);
    l = point_light(0);
    l.attenuation[1] = -1.0f;
    assert_int_equal(stin_add_light(ctx, &l), STIN_ERROR_INVALID_ARGUMENT);
    l = point_light(0);
    l.spot_exponent = 200.0f;
    assert_int_equal(stin_add_light(ctx, &l), STIN_ERROR_INVALID_ARGUMENT);
    l = point_light(0);
    l.type = (stin_light_type)9;
    assert_int_equal(stin_add_light(ctx, &l), STIN_ERROR_INVALID_ARGUMENT);
    assert_int_equal(stin_add_light(ctx, NULL), STIN_ERROR_INVALID_ARGUMENT);
    assert_int_equal(log_.items[STIN_LOG_BAD_ARGUMENT], 6);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    st = stin_query_frame_stats(ctx);
    assert_int_equal(st.lights, 1);
    assert_int_equal(st.dropped_lights, 0);
}

static void test_light_defaults_and_direction_normalised(void **state)
{
    stin_light_desc l;
    const stin_light_desc *kept;
    (void)state;
    begin();
    memset(&l, 0, sizeof l);
    l.type = STIN_LIGHT_DIRECTIONAL;
    l.direction[1] = -4.0f;
    assert_int_equal(stin_add_light(ctx, &l), STIN_OK);
    kept = &ctx->lights[0];
    assert_true(kept->direction[1] == -1.0f);
    assert_true(kept->color[0] == 1.0f && kept->color[1] == 1.0f && kept->color[2] == 1.0f);
    assert_true(kept->intensity == 1.0f);
    assert_true(kept->attenuation[0] == 1.0f && kept->attenuation[1] == 0.0f);
    assert_true(kept->spot_cutoff_deg == 45.0f);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
}

static void test_more_lights_than_max_lights(void **state)
{
    stin_light_desc l = point_light(0);
    stin_frame_stats st;
    (void)state;
    create_profile(FAKE_GL21, 2, 8);
    begin();
    add_lights(2);
    assert_int_equal(stin_add_light(ctx, &l), STIN_ERROR_CAPACITY);
    assert_int_equal(stin_add_light(ctx, &l), STIN_ERROR_CAPACITY);
    assert_int_equal(log_.items[STIN_LOG_POOL_FULL], 2);
    assert_true(fake_log_has(&log_, STIN_LOG_POOL_FULL, "max_lights"));
    assert_int_equal(stin_draw(ctx, quad, NULL, NULL), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    st = stin_query_frame_stats(ctx);
    assert_int_equal(st.lights, 2);
    assert_int_equal(st.dropped_lights, 2);
    /* The next frame starts counting from zero. */
    begin();
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    st = stin_query_frame_stats(ctx);
    assert_int_equal(st.dropped_lights, 0);
    assert_int_equal(st.lights, 0);
}

/* ---- draws ------------------------------------------------------------------- */
static void test_more_draws_than_max_draws(void **state)
{
    stin_frame_stats st;
    int i;
    (void)state;
    begin();
    for (i = 0; i < 8; i++)
        assert_int_equal(stin_draw(ctx, quad, NULL, NULL), STIN_OK);
    assert_int_equal(stin_draw(ctx, quad, NULL, NULL), STIN_ERROR_CAPACITY);
    assert_true(fake_log_has(&log_, STIN_LOG_POOL_FULL, "max_draws"));
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    st = stin_query_frame_stats(ctx);
    assert_int_equal(st.draws, 8);
    assert_int_equal(st.dropped_draws, 1);
    assert_int_equal(st.triangles, 16);
    assert_int_equal(fake_gl.draw_calls, 8);
    assert_int_equal(fake_gl.drawn_indices, 48);
}

static void test_stale_mesh_handle_in_a_draw(void **state)
{
    stin_mesh stale = quad, foreign = {0x7fff0003u};
    stin_frame_stats st;
    (void)state;
    stin_destroy_mesh(ctx, quad);
    begin();
    assert_int_equal(stin_draw(ctx, stale, NULL, NULL), STIN_ERROR_INVALID_HANDLE);
    assert_int_equal(stin_draw(ctx, foreign, NULL, NULL), STIN_ERROR_INVALID_HANDLE);
    assert_int_equal(log_.items[STIN_LOG_BAD_HANDLE], 2);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    st = stin_query_frame_stats(ctx);
    assert_int_equal(st.draws, 0);
    assert_int_equal(st.dropped_draws, 2);
    assert_int_equal(fake_gl.draw_calls, 0);
}

/* A mesh or texture a queued draw may use is not destroyed mid-frame: the
 * call is refused and logged, and the frame still draws it. */
static void test_destroy_inside_a_frame_is_refused(void **state)
{
    static const uint8_t white[4] = {255, 255, 255, 255};
    stin_texture_desc td;
    stin_texture tex;
    stin_material m;
    (void)state;
    memset(&td, 0, sizeof td);
    td.width = td.height = 1;
    td.pixels = white;
    assert_int_equal(stin_create_texture(ctx, &td, &tex), STIN_OK);
    memset(&m, 0, sizeof m);
    m.albedo = tex;
    begin();
    assert_int_equal(stin_draw(ctx, quad, NULL, &m), STIN_OK);
    stin_destroy_mesh(ctx, quad);
    stin_destroy_texture(ctx, tex);
    assert_int_equal(log_.items[STIN_LOG_FRAME_STATE], 2);
    assert_true(fake_log_has(&log_, STIN_LOG_FRAME_STATE, "after stin_end_frame"));
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    assert_int_equal(stin_query_frame_stats(ctx).draws, 1);
    assert_int_equal(fake_gl.textures_deleted, 0);
    stin_destroy_texture(ctx, tex); /* between frames: fine */
    stin_destroy_mesh(ctx, quad);
    assert_int_equal(fake_gl.textures_deleted, 1);
    assert_int_equal(log_.items[STIN_LOG_FRAME_STATE], 2);
}

static void test_bad_draw_arguments(void **state)
{
    float xf[16];
    stin_material mat;
    (void)state;
    begin();
    stin__mat4_identity(xf);
    xf[12] = NAN;
    assert_int_equal(stin_draw(ctx, quad, xf, NULL), STIN_ERROR_INVALID_ARGUMENT);
    memset(&mat, 0, sizeof mat);
    mat.shininess = NAN;
    assert_int_equal(stin_draw(ctx, quad, NULL, &mat), STIN_ERROR_INVALID_ARGUMENT);
    memset(&mat, 0, sizeof mat);
    mat.albedo.id = 0x00010002u; /* no such texture */
    assert_int_equal(stin_draw(ctx, quad, NULL, &mat), STIN_ERROR_INVALID_HANDLE);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    assert_int_equal(stin_query_frame_stats(ctx).draws, 0);
}

/* ---- passes ------------------------------------------------------------------ */
static stin_frame_stats frame_with(int lights, int opaque_draws, int blended_draws, stin_output out)
{
    stin_frame_desc fd = frame_desc();
    stin_material glass;
    int i;
    memset(&glass, 0, sizeof glass);
    glass.color[0] = glass.color[3] = 0.5f;
    fd.output = out;
    fake_gl.draw_calls = 0;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    add_lights(lights);
    for (i = 0; i < opaque_draws; i++)
        assert_int_equal(stin_draw(ctx, quad, NULL, NULL), STIN_OK);
    for (i = 0; i < blended_draws; i++)
        assert_int_equal(stin_draw(ctx, quad, NULL, &glass), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    return stin_query_frame_stats(ctx);
}

/* GLSL paths: 8 lights per pass. */
static void test_glsl_passes_per_eight_lights(void **state)
{
    static const struct {
        int lights;
        uint32_t passes;
    } cases[] = {{0, 1}, {1, 1}, {8, 1}, {9, 2}, {16, 2}};
    size_t i;
    int p;
    static const fake_gl_profile_id profiles[] = {FAKE_GL21, FAKE_GL45_CORE};
    (void)state;
    for (p = 0; p < 2; p++) {
        create_profile(profiles[p], 16, 8);
        for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            stin_frame_stats st = frame_with(cases[i].lights, 2, 0, STIN_OUTPUT_BEAUTY);
            assert_int_equal(st.passes, cases[i].passes);
            assert_int_equal(st.lights, (uint32_t)cases[i].lights);
            assert_int_equal(st.draws, 2);
            assert_int_equal(st.triangles, 4);
            assert_int_equal(fake_gl.draw_calls, 2 * cases[i].passes);
        }
    }
}

/* ---- lit programs specialised per light batch and material -------------- */

/* A frame of two opaque quads under n lights of one type (attenuated: a
 * linear term); its stats. */
static stin_frame_stats lit_frame(int n, stin_light_type type, int attenuated)
{
    stin_frame_desc fd = frame_desc();
    int i;
    fake_gl.draw_calls = 0;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    for (i = 0; i < n; i++) {
        stin_light_desc l = point_light((float)i);
        l.type = type;
        l.direction[2] = -1.0f;
        l.spot_cutoff_deg = 30.0f;
        l.attenuation[1] = attenuated ? 0.1f : 0.0f;
        assert_int_equal(stin_add_light(ctx, &l), STIN_OK);
    }
    for (i = 0; i < 2; i++)
        assert_int_equal(stin_draw(ctx, quad, NULL, NULL), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    return stin_query_frame_stats(ctx);
}

/* A batch's program is built in the first frame that needs it and kept. */
static void test_lit_programs_specialised_once_and_kept(void **state)
{
    static const fake_gl_profile_id profiles[] = {FAKE_GL21, FAKE_GL45_CORE};
    int p;
    (void)state;
    for (p = 0; p < 2; p++) {
        unsigned made;
        stin_frame_stats st;
        create_profile(profiles[p], 16, 8);
        made = fake_gl.programs_created;
        st = lit_frame(1, STIN_LIGHT_POINT, 0);
        assert_int_equal(st.lighting.programs_built, 1);
        assert_int_equal(st.lighting.specialised, 2);
        assert_int_equal(fake_gl.programs_created, made + 1);
        st = lit_frame(1, STIN_LIGHT_POINT, 0); /* the same batch: kept */
        assert_int_equal(st.lighting.programs_built, 0);
        assert_int_equal(st.lighting.specialised, 2);
        st = lit_frame(9, STIN_LIGHT_POINT, 0); /* batches of 8 (new) and 1 (kept) */
        assert_int_equal(st.lighting.programs_built, 1);
        assert_int_equal(st.lighting.specialised, 4);
        st = lit_frame(1, STIN_LIGHT_POINT, 1); /* attenuated: another program */
        assert_int_equal(st.lighting.programs_built, 1);
        assert_int_equal(fake_gl.programs_created, made + 3);
        assert_int_equal(fake_gl.draw_calls, 2);
    }
}

/* More batches over the frames than slots: the ones that served the oldest
 * frames give way, so the GL programs stay bounded. */
static void test_lit_programs_bounded(void **state)
{
    /* directional lights have no attenuation: five kinds of batch */
    static const stin_light_type types[] = {STIN_LIGHT_POINT, STIN_LIGHT_SPOT,
                                            STIN_LIGHT_DIRECTIONAL, STIN_LIGHT_POINT,
                                            STIN_LIGHT_SPOT};
    unsigned made;
    int f;
    (void)state;
    create_profile(FAKE_GL21, 16, 8);
    made = fake_gl.programs_created - fake_gl.programs_deleted;
    for (f = 0; f < 40; f++) { /* 40 batches: counts 1-8 of each kind */
        stin_frame_stats st = lit_frame(1 + f % 8, types[f / 8], f >= 24);
        assert_int_equal(st.lighting.programs_built, 1);
        assert_int_equal(st.lighting.specialised, 2);
    }
    assert_int_equal(fake_gl.programs_created - fake_gl.programs_deleted, made + STIN__LIT_CACHE);
    destroy_context(); /* and stin_destroy deletes them all */
    assert_int_equal(fake_gl.programs_created, fake_gl.programs_deleted);
}

/* A frame that needs more programs than there are slots: the general one
 * draws the rest (no slot this frame used is replaced), said once. */
static void test_lit_programs_full_frame(void **state)
{
    const stin__program *general;
    uint32_t key;
    unsigned said;
    (void)state;
    create_profile(FAKE_GL21, 16, 8);
    begin();
    said = log_.items[STIN_LOG_FALLBACK]; /* the context's own choices */
    general = &ctx->programs[STIN__PROG_LIT];
    for (key = 1; key <= STIN__LIT_CACHE; key++) /* 32 keys, no albedo map */
        assert_ptr_not_equal(stin__lit_specialised(ctx, general, 0, key, 0), general);
    assert_ptr_equal(stin__lit_specialised(ctx, general, 0, 0x10u | 1u, 1), general);
    assert_ptr_equal(stin__lit_specialised(ctx, general, 0, 0x10u | 2u, 1), general);
    assert_true(fake_log_has(&log_, STIN_LOG_FALLBACK, "more than 32 specialised"));
    assert_int_equal(log_.items[STIN_LOG_FALLBACK], said + 1);
    assert_ptr_not_equal(stin__lit_specialised(ctx, general, 0, 1u, 0), general); /* kept */
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
}

/* STIN_DEBUG_LIGHTING_GENERAL: the general programs only. */
static void test_lit_general_flag(void **state)
{
    unsigned made;
    stin_frame_stats st;
    (void)state;
    debug_flags = STIN_DEBUG_LIGHTING_GENERAL;
    create_profile(FAKE_GL45_CORE, 16, 8);
    debug_flags = 0;
    made = fake_gl.programs_created;
    st = lit_frame(3, STIN_LIGHT_SPOT, 1);
    assert_int_equal(st.lighting.programs_built, 0);
    assert_int_equal(st.lighting.specialised, 0);
    assert_int_equal(fake_gl.programs_created, made);
    assert_int_equal(fake_gl.draw_calls, 2);
}

/* A specialised program that does not build: the general one draws, with
 * one warning, and the build is not tried again. */
static void test_lit_failed_build_falls_back(void **state)
{
    unsigned made;
    stin_frame_stats st;
    (void)state;
    create_profile(FAKE_GL21, 16, 8);
    made = fake_gl.programs_created;
    fake_gl.config.fail_link_from = made + 1;
    st = lit_frame(1, STIN_LIGHT_POINT, 0);
    assert_int_equal(st.lighting.programs_built, 0);
    assert_int_equal(st.lighting.specialised, 0);
    assert_int_equal(fake_gl.draw_calls, 2);
    assert_true(fake_log_has(&log_, STIN_LOG_SHADER_COMPILE, "the general one serves"));
    st = lit_frame(1, STIN_LIGHT_POINT, 0);
    assert_int_equal(fake_gl.programs_created, made + 1);
    assert_int_equal(fake_gl.draw_calls, 2);
}

/* The frame's projection is known at stin_begin_frame, before any light,
 * and does not depend on the lights (the application draws its own geometry
 * with it): volumes move a perspective far plane to infinity in every
 * frame; shadows off keep the caller's. */
static void test_frame_projection_is_known_at_begin(void **state)
{
    stin_frame_desc fd = frame_desc();
    float p[16], n = 0.5f, f = 20.0f;
    (void)state;
    memset(fd.projection, 0, sizeof fd.projection);
    fd.projection[0] = fd.projection[5] = 1.0f;
    fd.projection[10] = -(f + n) / (f - n);
    fd.projection[11] = -1.0f;
    fd.projection[14] = -2.0f * f * n / (f - n);
    shadows = STIN_TECH_SHADOWS_VOLUME;
    create_profile(FAKE_GL21, 16, 8);
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    stin_query_frame_projection(ctx, p);
    assert_true(p[10] > -1.0f && p[10] < -0.999999f); /* eps - 1 */
    assert_true(p[14] < -1.999f * n && p[14] > -2.001f * n);  /* (eps - 2) n */
    assert_int_equal(stin_end_frame(ctx), STIN_OK); /* no lights: the same projection */
    {
        float after[16];
        stin_query_frame_projection(ctx, after);
        assert_memory_equal(p, after, sizeof p);
    }
    shadows = STIN_TECH_SHADOWS_OFF;
    create_profile(FAKE_GL21, 16, 8);
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    stin_query_frame_projection(ctx, p);
    assert_memory_equal(p, fd.projection, sizeof p);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
}

/* A driver that refuses the mask's framebuffer: the lights go back to a lit
 * pass each, drawn into the frame's own target (a caller framebuffer here),
 * with a warning. */
#define TARGET_FBO 900u
static void test_incomplete_mask_falls_back_into_the_target(void **state)
{
    static fake_gl_fbo target = {TARGET_FBO, 8, 24, 0};
    fake_gl_config cfg = fake_gl_profile(FAKE_GL45_CORE);
    stin_frame_desc fd = frame_desc();
    stin_frame_stats st;
    (void)state;
    cfg.framebuffers = &target;
    cfg.framebuffer_count = 1;
    cfg.generated_framebuffer_status = 0x8CD6; /* GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT */
    shadows = STIN_TECH_SHADOWS_VOLUME;
    create_context(&cfg, 16, 8, 4096);
    fd.framebuffer = TARGET_FBO;
    fake_gl.draws_into_default = 0;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    add_lights(8);
    assert_int_equal(stin_draw(ctx, quad, NULL, NULL), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    st = stin_query_frame_stats(ctx);
    assert_int_equal(st.passes, 1 + 8 + 8); /* as without masks */
    assert_true(fake_log_has(&log_, STIN_LOG_FALLBACK, "mask framebuffer incomplete"));
    assert_int_equal(fake_gl.draws_into_default, 0);
    assert_int_equal(fake_gl.gl.draw_framebuffer, TARGET_FBO);
    shadows = STIN_TECH_SHADOWS_OFF;
    create_profile(FAKE_GL21, 16, 8);
}

/* Volumes on GLSL tiers with FBOs and packed depth-stencil: each light's
 * visibility goes into a channel of the screen mask and one lit pass shades
 * four lights; without the mask every light gets its own lit pass. */
static void test_volume_lights_share_lit_passes_through_masks(void **state)
{
    stin_frame_stats st;
    (void)state;
    shadows = STIN_TECH_SHADOWS_VOLUME;
    create_profile(FAKE_GL45_CORE, 16, 8);
    st = frame_with(8, 1, 0, STIN_OUTPUT_BEAUTY);
    /* ambient, the mask's copy of the depth, 8 stencil counts, 2 lit passes */
    assert_int_equal(st.passes, 1 + 1 + 8 + 2);
    /* light 0 only: no mask, whose depth would be a geometry pass of its
     * own; counted in the frame's stencil: ambient, count, flat pass */
    st = frame_with(8, 1, 0, STIN_OUTPUT_VISIBILITY);
    assert_int_equal(st.passes, 1 + 1 + 1);
    caps_mask = STIN_CAP_BIT(STIN_CAP_PACKED_DEPTH_STENCIL);
    create_profile(FAKE_GL45_CORE, 16, 8);
    st = frame_with(8, 1, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(st.passes, 1 + 8 + 8);
    caps_mask = 0;
    shadows = STIN_TECH_SHADOWS_OFF;
    create_profile(FAKE_GL21, 16, 8);
}

/* Volumes are cut past the visible receivers and culled where they cannot
 * reach the view: a quad in view casts a cut volume; one at x = 5, far
 * outside the orthographic view (x in -1..1) and lit from z = 3, casts one
 * that only spreads away from it: skipped. STIN_DEBUG_VOLUME_UNBOUNDED
 * draws both to infinity. */
static void test_volumes_cut_and_culled(void **state)
{
    static const float aside[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1};
    stin_frame_desc fd = frame_desc();
    stin_frame_stats st;
    int unbounded;
    (void)state;
    shadows = STIN_TECH_SHADOWS_VOLUME;
    for (unbounded = 0; unbounded < 2; unbounded++) {
        debug_flags = unbounded ? STIN_DEBUG_VOLUME_UNBOUNDED : 0;
        create_profile(FAKE_GL21, 16, 8);
        assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
        add_lights(1);
        assert_int_equal(stin_draw(ctx, quad, NULL, NULL), STIN_OK);
        assert_int_equal(stin_draw(ctx, quad, aside, NULL), STIN_OK);
        assert_int_equal(stin_end_frame(ctx), STIN_OK);
        st = stin_query_frame_stats(ctx);
        assert_int_equal(st.shadows.volume_cut_casters, unbounded ? 0 : 1);
        assert_int_equal(st.shadows.volume_culled_casters, unbounded ? 0 : 1);
        assert_int_equal(st.shadows.zpass_casters + st.shadows.zfail_casters, unbounded ? 2 : 1);
    }
    debug_flags = 0;
    shadows = STIN_TECH_SHADOWS_OFF;
    create_profile(FAKE_GL21, 16, 8);
}

/* sorted: blended draws are drawn once per light batch each, after the
 * opaque ones (no packed depth-stencil: no depth-peel). */
static void test_blended_draws_once_per_batch(void **state)
{
    stin_frame_stats st;
    (void)state;
    caps_mask = STIN_CAP_BIT(STIN_CAP_PACKED_DEPTH_STENCIL);
    create_profile(FAKE_GL21, 16, 8);
    assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_TRANSPARENCY).technique,
                     STIN_TECH_TRANSPARENCY_SORTED);
    st = frame_with(9, 1, 2, STIN_OUTPUT_BEAUTY);
    assert_int_equal(st.passes, 2);
    assert_int_equal(st.draws, 3);
    assert_int_equal(fake_gl.draw_calls, 2 * 1 + 2 * 2);
    caps_mask = 0;
    create_profile(FAKE_GL21, 16, 8);
}

/* Fixed function: GL_MAX_LIGHTS lights per pass (at most 8). */
static void test_fixed_function_passes_per_max_lights(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL11);
    stin_frame_stats st;
    (void)state;
    cfg.max_lights = 2;
    create_context(&cfg, 16, 8, 4096);
    st = frame_with(5, 1, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(st.passes, 3);
    assert_int_equal(fake_gl.draw_calls, 3);
    st = frame_with(0, 1, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(st.passes, 1);

    create_profile(FAKE_GL14, 16, 8); /* GL_MAX_LIGHTS 8 */
    st = frame_with(9, 1, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(st.passes, 2);
    assert_int_equal(fake_gl.draw_calls, 2);
}

static void test_output_pass_counts(void **state)
{
    stin_frame_stats st;
    (void)state;
    st = frame_with(9, 2, 0, STIN_OUTPUT_NORMAL);
    assert_int_equal(st.passes, 1);
    assert_int_equal(fake_gl.draw_calls, 2);
    st = frame_with(9, 2, 0, STIN_OUTPUT_VISIBILITY); /* depth, then white where visible */
    assert_int_equal(st.passes, 2);
    assert_int_equal(fake_gl.draw_calls, 4);
    create_profile(FAKE_GL11, 8, 8);
    st = frame_with(1, 2, 0, STIN_OUTPUT_NORMAL); /* two multiplicative passes without shaders */
    assert_int_equal(st.passes, 2);
    assert_int_equal(fake_gl.draw_calls, 4);
}

/* stin.h: after a frame, depth/blend/stencil/cull/scissor are off, lighting too. */
static void test_frame_leaves_documented_state(void **state)
{
    static const fake_gl_profile_id profiles[] = {FAKE_GL11, FAKE_GL21, FAKE_GL45_CORE};
    static const GLenum off[] = {GL_DEPTH_TEST, GL_BLEND,    GL_STENCIL_TEST, GL_CULL_FACE,
                                 GL_SCISSOR_TEST, GL_LIGHTING, GL_LIGHT0,      GL_TEXTURE_2D};
    size_t p, i;
    (void)state;
    for (p = 0; p < sizeof profiles / sizeof profiles[0]; p++) {
        create_profile(profiles[p], 16, 8);
        frame_with(9, 1, 1, STIN_OUTPUT_BEAUTY);
        assert_true(fake_gl.calls[STIN_GLFN_Enable] > 0);
        for (i = 0; i < sizeof off / sizeof off[0]; i++)
            assert_false(fake_gl_is_enabled(off[i]));
    }
}

/* ---- textures ---------------------------------------------------------------- */
static stin_texture_desc texture_desc(uint32_t w, uint32_t h, const uint8_t *pixels)
{
    stin_texture_desc td;
    memset(&td, 0, sizeof td);
    td.width = w;
    td.height = h;
    td.pixels = pixels;
    return td;
}

static void fill(uint8_t *px, uint32_t n, const uint8_t rgba[4])
{
    uint32_t i;
    for (i = 0; i < n; i++)
        memcpy(px + 4 * i, rgba, 4);
}

static void test_npot_texture_on_gl11_is_resampled_with_mips(void **state)
{
    static const uint8_t rgba[4] = {10, 20, 30, 40};
    static const int expect[4][2] = {{4, 8}, {2, 4}, {1, 2}, {1, 1}};
    uint8_t px[3 * 5 * 4] = {0};
    stin_texture_desc td = texture_desc(3, 5, px);
    stin_texture t;
    unsigned level;
    (void)state;
    create_profile(FAKE_GL11, 8, 8);
    fill(px, 15, rgba);
    assert_int_equal(stin_create_texture(ctx, &td, &t), STIN_OK);
    assert_true(t.id != 0);
    assert_int_equal(fake_gl.textures_created, 1);
    assert_int_equal(fake_gl.tex_levels, 4);
    assert_int_equal(fake_gl.tex_images, 4);
    for (level = 0; level < 4; level++) {
        assert_int_equal(fake_gl.tex_level_width[level], expect[level][0]);
        assert_int_equal(fake_gl.tex_level_height[level], expect[level][1]);
        /* a uniform image stays uniform through the resample and the box filter */
        assert_memory_equal(fake_gl.tex_level_first_texel[level], rgba, 4);
    }
}

static void test_texture_without_mips(void **state)
{
    uint8_t px[3 * 5 * 4] = {0};
    stin_texture_desc td = texture_desc(3, 5, px);
    stin_texture t;
    (void)state;
    create_profile(FAKE_GL11, 8, 8);
    td.base_level_only = 1;
    assert_int_equal(stin_create_texture(ctx, &td, &t), STIN_OK);
    assert_int_equal(fake_gl.tex_levels, 1);
    assert_int_equal(fake_gl.tex_level_width[0], 4);
    assert_int_equal(fake_gl.tex_level_height[0], 8);
}

/* GL 2.0+ takes any size: no resample, a 3x5 chain. */
static void test_npot_texture_on_gl21_keeps_its_size(void **state)
{
    static const uint8_t rgba[4] = {200, 100, 50, 255};
    uint8_t px[3 * 5 * 4] = {0};
    stin_texture_desc td = texture_desc(3, 5, px);
    stin_texture t;
    (void)state;
    fill(px, 15, rgba);
    assert_int_equal(stin_create_texture(ctx, &td, &t), STIN_OK);
    assert_int_equal(fake_gl.tex_levels, 3);
    assert_int_equal(fake_gl.tex_level_width[0], 3);
    assert_int_equal(fake_gl.tex_level_height[0], 5);
    assert_int_equal(fake_gl.tex_level_width[2], 1);
    assert_int_equal(fake_gl.tex_level_height[2], 1);
    assert_memory_equal(fake_gl.tex_level_first_texel[2], rgba, 4);
}

static void test_texture_is_clamped_to_max_texture_size(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL11);
    uint8_t px[16 * 3 * 4] = {0};
    stin_texture_desc td = texture_desc(16, 3, px);
    stin_texture t;
    (void)state;
    cfg.max_texture_size = 4;
    create_context(&cfg, 8, 8, 4096);
    assert_int_equal(stin_create_texture(ctx, &td, &t), STIN_OK);
    assert_int_equal(fake_gl.tex_level_width[0], 4);
    assert_int_equal(fake_gl.tex_level_height[0], 4);
}

static void test_texture_staging_too_small(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL11);
    uint8_t px[8 * 8 * 4] = {0};
    stin_texture_desc td = texture_desc(8, 8, px);
    stin_texture t = {99};
    (void)state;
    /* level 0 is uploaded as given; levels 1 and 2 (4x4 and 2x2) need 80 bytes */
    create_context(&cfg, 8, 8, 4 * (4 * 4 + 2 * 2) - 1);
    assert_int_equal(stin_create_texture(ctx, &td, &t), STIN_ERROR_CAPACITY);
    assert_int_equal(t.id, 0);
    assert_true(fake_log_has(&log_, STIN_LOG_POOL_FULL, "max_texture_bytes"));
    assert_int_equal(fake_gl.textures_created, 0);
    td.base_level_only = 1;
    assert_int_equal(stin_create_texture(ctx, &td, &t), STIN_OK);
}

static void test_texture_pool_and_handles(void **state)
{
    uint8_t px[4 * 4 * 4] = {0};
    stin_texture_desc td = texture_desc(4, 4, px);
    stin_texture a, b, c;
    stin_material mat;
    (void)state;
    assert_int_equal(stin_create_texture(ctx, &td, &a), STIN_OK);
    assert_int_equal(stin_create_texture(ctx, &td, &b), STIN_OK);
    assert_int_equal(stin_create_texture(ctx, &td, &c), STIN_ERROR_CAPACITY); /* max_textures 2 */
    assert_true(fake_log_has(&log_, STIN_LOG_POOL_FULL, "max_textures"));
    stin_destroy_texture(ctx, a);
    assert_int_equal(fake_gl.textures_deleted, 1);
    assert_int_equal(stin_create_texture(ctx, &td, &c), STIN_OK);
    assert_true(c.id != a.id);
    memset(&mat, 0, sizeof mat);
    mat.albedo = a; /* stale */
    begin();
    assert_int_equal(stin_draw(ctx, quad, NULL, &mat), STIN_ERROR_INVALID_HANDLE);
    mat.albedo = c;
    assert_int_equal(stin_draw(ctx, quad, NULL, &mat), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    stin_destroy_texture(ctx, a); /* stale: logged, nothing deleted */
    assert_int_equal(fake_gl.textures_deleted, 1);
    assert_true(log_.items[STIN_LOG_BAD_HANDLE] >= 2);
}

static void test_texture_bad_arguments(void **state)
{
    uint8_t px[16] = {0};
    stin_texture_desc td = texture_desc(2, 2, px);
    stin_texture t;
    (void)state;
    td.width = 0;
    assert_int_equal(stin_create_texture(ctx, &td, &t), STIN_ERROR_INVALID_ARGUMENT);
    td = texture_desc(2, 2, NULL);
    assert_int_equal(stin_create_texture(ctx, &td, &t), STIN_ERROR_INVALID_ARGUMENT);
    td = texture_desc(2, 2, px);
    td.kind = (stin_texture_kind)5;
    assert_int_equal(stin_create_texture(ctx, &td, &t), STIN_ERROR_INVALID_ARGUMENT);
    assert_int_equal(fake_gl.textures_created, 0);
}

/* STIN_DEBUG_STAGE_TIMES: a timestamp at each change of the frame plan's
 * stage (volumes through the screen mask, 8 lights: two groups of four,
 * each its stencil counts and one lit pass; no CSG product, so no csg
 * stage), one more at the end, each read
 * back once; none without the flag, none where the context has no timer
 * queries (logged once); a frame changing stage more often than the pool
 * holds goes on, its rest untimed (logged once). */
static void test_stage_times_follow_the_plan(void **state)
{
    static const stin_stage plan[] = {
        STIN_STAGE_PREPASS, STIN_STAGE_BASE,     STIN_STAGE_SHADOW,  STIN_STAGE_LIGHTING,
        STIN_STAGE_SHADOW,  STIN_STAGE_LIGHTING, STIN_STAGE_SHADOW,  STIN_STAGE_BASE,
        STIN_STAGE_BLENDED, STIN_STAGE_BASE,     STIN_STAGE_EXPORT};
    const uint32_t marks = sizeof plan / sizeof plan[0];
    stin_frame_stats st;
    uint32_t i;
    (void)state;
    shadows = STIN_TECH_SHADOWS_VOLUME;
    debug_flags = STIN_DEBUG_STAGE_TIMES;
    create_profile(FAKE_GL45_CORE, 16, 8);
    st = frame_with(8, 1, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(st.stage_times, 1);
    assert_int_equal(ctx->times->marks, marks);
    for (i = 0; i < marks; i++)
        assert_int_equal(ctx->times->stage[i], plan[i]);
    assert_int_equal(fake_gl.calls[STIN_GLFN_QueryCounter], marks + 1);
    assert_int_equal(fake_gl.calls[STIN_GLFN_GetQueryObjectui64v], marks + 1);

    create_profile(FAKE_GL21, 16, 8); /* no timer queries */
    st = frame_with(8, 1, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(st.stage_times, 0);
    assert_int_equal(fake_gl.calls[STIN_GLFN_QueryCounter], 0);
    assert_true(fake_log_has(&log_, STIN_LOG_FALLBACK, "no timer queries"));

    /* sorted blended draws under map-pcf: per draw and light a shadow and
     * a lighting stage, 8 x 16 x 2 changes and more */
    shadows = STIN_TECH_SHADOWS_MAP_PCF;
    caps_mask = STIN_CAP_BIT(STIN_CAP_PACKED_DEPTH_STENCIL); /* no peeling: sorted */
    create_profile(FAKE_GL45_CORE, 16, 8);
    st = frame_with(16, 1, 7, STIN_OUTPUT_BEAUTY);
    assert_int_equal(st.stage_times, 1);
    assert_int_equal(ctx->times->marks, STIN__STAGE_MARKS - 1u);
    assert_int_equal(fake_gl.calls[STIN_GLFN_QueryCounter], STIN__STAGE_MARKS);
    assert_true(fake_log_has(&log_, STIN_LOG_FALLBACK, "changed stage more than"));

    debug_flags = 0;
    create_profile(FAKE_GL45_CORE, 16, 8);
    st = frame_with(8, 1, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(st.stage_times, 0);
    assert_int_equal(fake_gl.calls[STIN_GLFN_QueryCounter], 0);
    caps_mask = 0;
    shadows = STIN_TECH_SHADOWS_OFF;
}

/* vdsm on a context with tessellation shaders draws triangles, as the lit
 * programs do, in frames with nothing displaced: its tessellated programs
 * are for frames with displaced draws (test_state draws one). Built
 * tessellated for every frame, a peeled layer's points missed pixels of
 * the layer the lit programs drew (docs/testing.md, "Viewport origins"). */
static void test_vdsm_tessellates_only_displaced_frames(void **state)
{
    stin_frame_stats st;
    (void)state;
    shadows = STIN_TECH_SHADOWS_VDSM;
    create_profile(FAKE_GL45_CORE, 16, 8);
    assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_SHADOWS).technique,
                     STIN_TECH_SHADOWS_VDSM);
    assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_DISPLACEMENT).technique,
                     STIN_TECH_DISPLACEMENT_TESS);
    fake_gl.patch_draws = 0;
    st = frame_with(2, 2, 1, STIN_OUTPUT_BEAUTY); /* a blended draw: peeled layers */
    assert_true(st.passes > 0);
    assert_true(fake_gl.draw_calls > 10);
    /* and culls first: its triangle count is known without tessellation */
    assert_true(st.shadows.vdsm_cull_passes >= 2);
    shadows = STIN_TECH_SHADOWS_OFF;
    assert_int_equal(fake_gl.patch_draws, 0);
}

/* vdsm's deepest receivers per light texel: by storage-buffer atomics
 * where the context has GL 4.3's (one quad, shadow/vdsm_receivers.c), else
 * as one point per pixel; a frame with SM and DC either way. */
static void test_vdsm_receivers_by_atomics_on_gl43(void **state)
{
    stin_frame_stats st;
    (void)state;
    shadows = STIN_TECH_SHADOWS_VDSM;
    create_profile(FAKE_GL45_CORE, 16, 8);
    assert_true(ctx->vdsm->pyramid.usable);
    assert_true(ctx->vdsm->pyramid.atomic_prog != 0 && ctx->vdsm->pyramid.first_prog != 0);
    assert_int_equal(ctx->vdsm->pyramid.deepest, 0); /* made in the first frame */
    assert_int_equal(fake_gl.calls[STIN_GLFN_BindBufferBase], 0);
    assert_int_equal(frame_with(1, 2, 0, STIN_OUTPUT_BEAUTY).shadows.vdsm_atomic_receivers, 1);
    assert_true(ctx->vdsm->pyramid.deepest != 0);
    assert_true(fake_gl.calls[STIN_GLFN_BindBufferBase] >= 4); /* bound, unbound, twice */
    create_profile(FAKE_GL33_CORE, 16, 8);
    assert_true(ctx->vdsm->pyramid.usable);
    assert_int_equal(ctx->vdsm->pyramid.atomic_prog, 0);
    st = frame_with(1, 2, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(st.shadows.vdsm_atomic_receivers, 0);
    /* only the culling pass's feedback buffer: bound and unbound */
    assert_int_equal(fake_gl.calls[STIN_GLFN_BindBufferBase], 2 * st.shadows.vdsm_cull_passes);
    shadows = STIN_TECH_SHADOWS_OFF;
}

/* vdsm's culling buffer: grown to a frame's casters (4 parts a triangle
 * and a quarter more), kept while a light's pass needs over a quarter of
 * it, given back at the 60th pass in a row that needs less, grown again at
 * once. */
static void test_vdsm_cull_buffer_given_back(void **state)
{
    const stin__vdsm_cull *c;
    int i;
    (void)state;
    shadows = STIN_TECH_SHADOWS_VDSM;
    create_profile(FAKE_GL45_CORE, 16, 640);
    c = &ctx->vdsm->culling;
    frame_with(1, 600, 0, STIN_OUTPUT_BEAUTY); /* 600 quads: 4800 parts */
    assert_int_equal(c->capacity, 6000);
    for (i = 0; i < 70; i++) /* 2000 parts: over a quarter */
        frame_with(1, 250, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(c->capacity, 6000);
    for (i = 0; i < 29; i++) /* 16 parts, two lights a frame: 58 passes */
        frame_with(2, 2, 0, STIN_OUTPUT_BEAUTY);
    frame_with(1, 2, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(c->capacity, 6000);
    frame_with(1, 2, 0, STIN_OUTPUT_BEAUTY); /* the 60th */
    assert_int_equal(c->capacity, 1024);     /* the floor: 48 KB */
    frame_with(1, 600, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(c->capacity, 6000);
    shadows = STIN_TECH_SHADOWS_OFF;
}

/* vdsm culls first: per light one transform-feedback pass, its kept
 * triangles drawn in one draw - from the feedback object on GL 4.0+, by a
 * query's count before it - and the one-pass program under
 * STIN_DEBUG_VDSM_ONE_PASS. */
static void test_vdsm_culls_into_feedback_then_draws_once(void **state)
{
    stin_frame_stats st;
    (void)state;
    shadows = STIN_TECH_SHADOWS_VDSM;
    create_profile(FAKE_GL45_CORE, 16, 8);
    assert_true(ctx->vdsm->culling.usable && ctx->vdsm->culling.feedback != 0);
    assert_int_equal(ctx->vdsm->culling.query, 0); /* no wait without STIN_DEBUG_VDSM_COUNT */
    st = frame_with(2, 3, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(st.shadows.vdsm_cull_passes, 2);
    assert_int_equal(fake_gl.calls[STIN_GLFN_BeginTransformFeedback], 2);
    assert_int_equal(fake_gl.calls[STIN_GLFN_EndTransformFeedback], 2);
    assert_int_equal(fake_gl.calls[STIN_GLFN_DrawTransformFeedback], 2);
    assert_true(ctx->vdsm->culling.capacity >= 4 * 3 * 2); /* three quads' triangles' parts */
    /* the pyramid allocated at the map size, drawn at the 64 x 48 viewport's
     * (the power of two nearest 32, at least 256) */
    assert_int_equal(ctx->vdsm->pyramid.alloc, 1024);
    assert_int_equal(ctx->vdsm->pyramid.size, 256);
    assert_int_equal(ctx->vdsm->pyramid.top, 8);
    create_profile(FAKE_GL33_CORE, 16, 8);
    assert_true(ctx->vdsm->culling.usable);
    assert_int_equal(ctx->vdsm->culling.feedback, 0); /* counted by a query instead */
    st = frame_with(1, 2, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(st.shadows.vdsm_cull_passes, 1);
    assert_int_equal(fake_gl.calls[STIN_GLFN_BeginTransformFeedback], 1);
    assert_int_equal(fake_gl.calls[STIN_GLFN_DrawTransformFeedback], 0);
    debug_flags = STIN_DEBUG_VDSM_ONE_PASS;
    create_profile(FAKE_GL45_CORE, 16, 8);
    st = frame_with(2, 3, 0, STIN_OUTPUT_BEAUTY);
    assert_int_equal(st.shadows.vdsm_cull_passes, 0);
    assert_int_equal(fake_gl.calls[STIN_GLFN_BeginTransformFeedback], 0);
    debug_flags = 0;
    shadows = STIN_TECH_SHADOWS_OFF;
}

/* The screen mask's depth: volumes count against the frame's depth, so
 * the mask's first light group draws it there (a geometry pass with depth
 * written), and with one light they use no mask (the frame's own stencil
 * is a pass cheaper); vdsm's polygons test the position buffer's depth, so
 * its mask gets no such pass, with one light or five (two groups). */
static void test_mask_depth_pass_only_where_read(void **state)
{
    static const stin_technique techs[] = {STIN_TECH_SHADOWS_VOLUME, STIN_TECH_SHADOWS_VDSM};
    int t, lights;
    (void)state;
    for (t = 0; t < 2; t++)
        for (lights = 1; lights <= 5; lights += 4) {
            shadows = techs[t];
            create_profile(FAKE_GL45_CORE, 16, 8);
            (void)frame_with(lights, 3, 0, STIN_OUTPUT_BEAUTY); /* makes the mask */
            if (techs[t] == STIN_TECH_SHADOWS_VOLUME && lights == 1) {
                assert_int_equal(stin__mask_target_of(ctx).fbo, 0);
                continue;
            }
            assert_true(stin__mask_target_of(ctx).fbo != 0);
            fake_gl.watched_framebuffer = stin__mask_target_of(ctx).fbo;
            fake_gl.draws_into_watched = fake_gl.depth_draws_into_watched = 0;
            (void)frame_with(lights, 3, 0, STIN_OUTPUT_BEAUTY);
            assert_true(fake_gl.draws_into_watched > 0); /* the masks were drawn */
            if (techs[t] == STIN_TECH_SHADOWS_VOLUME)
                assert_int_equal(fake_gl.depth_draws_into_watched, 3); /* once, not per group */
            else
                assert_int_equal(fake_gl.depth_draws_into_watched, 0);
            fake_gl.watched_framebuffer = 0;
        }
    shadows = STIN_TECH_SHADOWS_OFF;
}

/* The visibility export with deep maps: two lights want one visibility
 * tile and two transmittance tiles (64 x 48 each, two a row); a largest
 * texture of 100 holds one, so the map keeps both lights' visibility and no
 * transmittance, saying so once; 200 holds all three. */
static void test_export_without_room_for_transmittance(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL45_CORE);
    stin_frame_desc fd = frame_desc();
    stin_visibility_map map;
    stin_material glass;
    int round;
    (void)state;
    memset(&glass, 0, sizeof glass);
    glass.color[0] = glass.color[3] = 0.5f;
    fd.export_visibility = STIN_EXPORT_VISIBILITY;
    shadows = STIN_TECH_SHADOWS_VOLUME;
    for (round = 0; round < 2; round++) {
        cfg.max_texture_size = round == 0 ? 100 : 200;
        create_context(&cfg, 16, 8, 4096);
        assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_TRANSLUCENT_SHADOWS).technique,
                         STIN_TECH_TRANSLUCENT_DEEP);
        assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
        add_lights(2);
        assert_int_equal(stin_draw(ctx, quad, NULL, NULL), STIN_OK);
        assert_int_equal(stin_draw(ctx, quad, NULL, &glass), STIN_OK);
        assert_int_equal(stin_end_frame(ctx), STIN_OK);
        assert_int_equal(stin_query_visibility_map(ctx, &map), STIN_OK);
        assert_int_equal(map.lights, 2);
        assert_int_equal(map.transmittance_tile, round == 0 ? 0u : 1u);
        assert_int_equal(fake_log_has(&log_, STIN_LOG_FALLBACK, "transmittance tiles do not fit"),
                         round == 0);
    }
    shadows = STIN_TECH_SHADOWS_OFF;
}

/* Deep maps the driver cannot make (its proxy array refuses them) step
 * down to the largest size it takes, logged; none of 64 or more and deep
 * falls back to translucent-solid. Before, maps of deep_map_size 4096 were
 * allocated as asked: GL_OUT_OF_MEMORY pending, no log, no maps. */
static void test_deep_maps_step_down_to_what_the_driver_takes(void **state)
{
    static const unsigned long long most[3] = {0, 16ull * 256 * 256 * 12, 16ull * 32 * 32 * 12};
    static const GLsizei width[3] = {512, 256, 0};
    fake_gl_config cfg = fake_gl_profile(FAKE_GL45_CORE);
    int round;
    (void)state;
    shadows = STIN_TECH_SHADOWS_VOLUME;
    for (round = 0; round < 3; round++) {
        cfg.max_array_bytes = most[round]; /* the default 512 x 512, 2 slices x 6 faces */
        create_context(&cfg, 4, 8, 4096);
        assert_int_equal(fake_gl.array_width, width[round]);
        assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_TRANSLUCENT_SHADOWS).technique,
                         round < 2 ? STIN_TECH_TRANSLUCENT_DEEP : STIN_TECH_TRANSLUCENT_SOLID);
        assert_int_equal(fake_log_has(&log_, STIN_LOG_FALLBACK, "the maps are 256 x 256"),
                         round == 1);
        assert_int_equal(fake_log_has(&log_, STIN_LOG_FALLBACK, "takes none"), round == 2);
    }
    shadows = STIN_TECH_SHADOWS_OFF;
}

/* With shadows off no light has a map, so deep (the GL4 default) falls
 * back: said as INFO when it was only the default (the caller's own
 * choice rules it out), as a WARNING when the caller forced it. */
static void test_translucent_fallback_without_shadows(void **state)
{
    int forced;
    (void)state;
    for (forced = 0; forced < 2; forced++) {
        translucent = forced ? STIN_TECH_TRANSLUCENT_DEEP : STIN_TECH_NONE;
        create_profile(FAKE_GL45_CORE, 4, 8);
        assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_TRANSLUCENT_SHADOWS).technique,
                         STIN_TECH_TRANSLUCENT_SOLID);
        assert_true(fake_log_has(&log_, STIN_LOG_FALLBACK, "shadows are off"));
        assert_int_equal(log_.warnings, (unsigned)forced);
    }
    translucent = STIN_TECH_NONE;
}

/* One frame of map-pcf: a point light at the origin and the quad (0.2 a
 * side) at each of n corners, under the identity camera (its view the
 * cube [-1, 1]^3). */
static stin_frame_stats pcf_point_frame(const float (*at)[3], int n)
{
    stin_light_desc l;
    int i;
    memset(&l, 0, sizeof l);
    begin();
    assert_int_equal(stin_add_light(ctx, &l), STIN_OK);
    for (i = 0; i < n; i++) {
        float m[16];
        stin__mat4_identity(m);
        m[0] = m[5] = m[10] = 0.2f;
        m[12] = at[i][0];
        m[13] = at[i][1];
        m[14] = at[i][2];
        assert_int_equal(stin_draw(ctx, quad, m, NULL), STIN_OK);
    }
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    return stin_query_frame_stats(ctx);
}

/* map-pcf under a point light (issue 36): its six faces share one atlas,
 * each drawn with only the casters whose bounds meet its frustum, and a
 * face no visible draw reaches is not drawn at all. A quad on each side
 * of the light, all in view: six faces of one caster each (36 before).
 * The +x one moved out of view: its face is skipped (no visible point
 * picks it), the five others drawn. A visible receiver on +x again with
 * the out-of-view quad beyond it: that face holds both, since a caster
 * the camera does not see still shadows what it does. */
static void test_pcf_point_faces_culled(void **state)
{
    float at[7][3] = {{0.5f, -0.1f, 0.0f},  {-0.7f, -0.1f, 0.0f}, {-0.1f, 0.5f, 0.0f},
                      {-0.1f, -0.7f, 0.0f}, {-0.1f, -0.1f, 0.6f}, {-0.1f, -0.1f, -0.6f},
                      {2.0f, -0.1f, 0.0f}};
    stin_frame_stats st;
    (void)state;
    shadows = STIN_TECH_SHADOWS_MAP_PCF;
    create_profile(FAKE_GL45_CORE, 4, 8);
    assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_SHADOWS).technique,
                     STIN_TECH_SHADOWS_MAP_PCF);
    st = pcf_point_frame((const float(*)[3])at, 6);
    assert_int_equal(st.shadows.map_faces, 6);
    assert_int_equal(st.shadows.map_face_casters, 6);
    /* the +x quad out of view: nothing visible reads +x */
    st = pcf_point_frame((const float(*)[3])at + 1, 6);
    assert_int_equal(st.shadows.map_faces, 5);
    assert_int_equal(st.shadows.map_face_casters, 5);
    /* a visible receiver on +x and the out-of-view caster beyond it */
    st = pcf_point_frame((const float(*)[3])at, 7);
    assert_int_equal(st.shadows.map_faces, 6);
    assert_int_equal(st.shadows.map_face_casters, 7);
    shadows = STIN_TECH_SHADOWS_OFF;
}

/* A map-pcf frame of n opaque quads under `spots` spot lights above them
 * (output out); its stats, the draw calls counted from begin. */
static stin_frame_stats pcf_spot_frame(int n, int spots, stin_output out)
{
    stin_frame_desc fd = frame_desc();
    int i;
    fd.output = out;
    fake_gl.draw_calls = 0;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    for (i = 0; i < spots; i++) {
        stin_light_desc l = point_light(0.1f * (float)i);
        l.type = STIN_LIGHT_SPOT;
        l.direction[2] = -1.0f;
        assert_int_equal(stin_add_light(ctx, &l), STIN_OK);
    }
    for (i = 0; i < n; i++)
        assert_int_equal(stin_draw(ctx, quad, NULL, NULL), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    return stin_query_frame_stats(ctx);
}

/* map-pcf's one forward pass (issue 36): the lit program samples the map,
 * so the ambient light and the first light share one pass with depth
 * writes: each of N meshes drawn once into the map and once from the
 * camera (2 passes, 2N draws; an ambient and a lit pass made it 3 and
 * 3N). A second light adds its own map and lit pass; the visibility
 * output keeps its ambient pass before the flat one. */
static void test_pcf_forward_pass(void **state)
{
    static const fake_gl_profile_id profiles[] = {FAKE_GL21, FAKE_GL45_CORE};
    const int n = 3;
    stin_frame_stats st;
    int p;
    (void)state;
    shadows = STIN_TECH_SHADOWS_MAP_PCF;
    for (p = 0; p < 2; p++) {
        create_profile(profiles[p], 16, 8);
        assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_SHADOWS).technique,
                         STIN_TECH_SHADOWS_MAP_PCF);
        st = pcf_spot_frame(n, 1, STIN_OUTPUT_BEAUTY);
        assert_int_equal(st.passes, 1 + 1); /* the map, the forward pass */
        assert_int_equal(fake_gl.draw_calls, n + n);
        st = pcf_spot_frame(n, 2, STIN_OUTPUT_BEAUTY);
        assert_int_equal(st.passes, 2 + 1 + 1); /* two maps, forward, light 1's */
        assert_int_equal(fake_gl.draw_calls, 2 * n + n + n);
        st = pcf_spot_frame(n, 1, STIN_OUTPUT_VISIBILITY);
        assert_int_equal(st.passes, 1 + 1 + 1); /* the map, ambient, flat */
        assert_int_equal(fake_gl.draw_calls, 3 * n);
    }
    shadows = STIN_TECH_SHADOWS_OFF;
}

#define TEST(f) cmocka_unit_test_setup_teardown(f, setup, teardown)

int main(void)
{
    const struct CMUnitTest tests[] = {
        TEST(test_call_order_errors),
        TEST(test_pcf_point_faces_culled),
        TEST(test_pcf_forward_pass),
        TEST(test_deep_maps_step_down_to_what_the_driver_takes),
        TEST(test_translucent_fallback_without_shadows),
        TEST(test_bad_frame_descs),
        TEST(test_viewport_outside_limits),
        TEST(test_bad_lights_are_rejected),
        TEST(test_light_defaults_and_direction_normalised),
        TEST(test_more_lights_than_max_lights),
        TEST(test_more_draws_than_max_draws),
        TEST(test_stale_mesh_handle_in_a_draw),
        TEST(test_destroy_inside_a_frame_is_refused),
        TEST(test_bad_draw_arguments),
        TEST(test_glsl_passes_per_eight_lights),
        TEST(test_blended_draws_once_per_batch),
        TEST(test_lit_programs_specialised_once_and_kept),
        TEST(test_lit_programs_bounded),
        TEST(test_lit_programs_full_frame),
        TEST(test_lit_general_flag),
        TEST(test_lit_failed_build_falls_back),
        TEST(test_volume_lights_share_lit_passes_through_masks),
        TEST(test_volumes_cut_and_culled),
        TEST(test_incomplete_mask_falls_back_into_the_target),
        TEST(test_frame_projection_is_known_at_begin),
        TEST(test_fixed_function_passes_per_max_lights),
        TEST(test_output_pass_counts),
        TEST(test_stage_times_follow_the_plan),
        TEST(test_export_without_room_for_transmittance),
        TEST(test_vdsm_tessellates_only_displaced_frames),
        TEST(test_vdsm_receivers_by_atomics_on_gl43),
        TEST(test_vdsm_culls_into_feedback_then_draws_once),
        TEST(test_vdsm_cull_buffer_given_back),
        TEST(test_mask_depth_pass_only_where_read),
        TEST(test_frame_leaves_documented_state),
        TEST(test_npot_texture_on_gl11_is_resampled_with_mips),
        TEST(test_texture_without_mips),
        TEST(test_npot_texture_on_gl21_keeps_its_size),
        TEST(test_texture_is_clamped_to_max_texture_size),
        TEST(test_texture_staging_too_small),
        TEST(test_texture_pool_and_handles),
        TEST(test_texture_bad_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
