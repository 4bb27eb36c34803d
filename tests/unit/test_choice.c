/* SPDX-License-Identifier: MIT */
/* The measured choice of the exact technique (shadow/choice.c) on the fake
 * GL, whose GL_TIME_ELAPSED queries return what this test says each
 * technique costs: hysteresis (no switch on a small difference, one on a
 * large one, no flip-flop), the log line, the stats, reads that never wait,
 * forcing turns it off, and frames volumes cannot draw stay on vdsm. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "fake_gl.h"
#include "internal.h"

static fake_log log_;
static void *block;
static stin_context *ctx;
static stin_mesh quad, tetra;
/* what a frame of each technique costs, by stin_shadow_choice */
static GLuint64 cost_ns[4];

static const float quad_pos[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
static const uint32_t quad_idx[] = {0, 1, 2, 0, 2, 3};
static const float tetra_pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
static const uint32_t tetra_idx[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

/* The technique of the frame ending now, from what its plan counted:
 * GPU-extruded casters, CPU-built ones, or neither (vdsm). */
static GLuint64 elapsed(void *user)
{
    const stin_shadows_stats *s = &((stin_context *)user)->stats.shadows;
    if (s->volume_gpu_casters)
        return cost_ns[STIN_SHADOW_CHOICE_VOLUME_GPU];
    if (s->zpass_casters + s->zfail_casters)
        return cost_ns[STIN_SHADOW_CHOICE_VOLUME_CPU];
    return cost_ns[STIN_SHADOW_CHOICE_VDSM];
}

static void set_costs(double vdsm_ms, double gpu_ms, double cpu_ms)
{
    cost_ns[STIN_SHADOW_CHOICE_VDSM] = (GLuint64)(vdsm_ms * 1e6);
    cost_ns[STIN_SHADOW_CHOICE_VOLUME_GPU] = (GLuint64)(gpu_ms * 1e6);
    cost_ns[STIN_SHADOW_CHOICE_VOLUME_CPU] = (GLuint64)(cpu_ms * 1e6);
}

static void destroy_context(void)
{
    if (ctx)
        stin_destroy(ctx);
    free(block);
    ctx = NULL;
    block = NULL;
}

static void mesh(const float *pos, uint32_t vertices, const uint32_t *idx, uint32_t indices,
                 stin_mesh *out)
{
    stin_mesh_desc md;
    memset(&md, 0, sizeof md);
    md.positions = pos;
    md.vertex_count = vertices;
    md.indices = idx;
    md.index_count = indices;
    assert_int_equal(stin_create_mesh(ctx, &md, out), STIN_OK);
}

/* A GL 4.5 core context on the fake, shadows on auto unless `forced`. */
static void create(stin_technique forced, uint32_t choice_frames, uint64_t debug_flags)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL45_CORE);
    stin_desc d = fake_gl_desc(&log_);
    size_t bytes;
    destroy_context();
    fake_gl_reset(&cfg);
    d.max_meshes = 4;
    d.max_vertices = 64;
    d.max_triangles = 64;
    d.techniques[STIN_FEATURE_SHADOWS] = forced;
    d.shadows.choice_frames = choice_frames;
    d.debug_flags = debug_flags;
    bytes = stin_memory_size(&d);
    assert_true(bytes > 0);
    block = malloc(bytes);
    assert_non_null(block);
    assert_int_equal(stin_create(&d, block, bytes, &ctx), STIN_OK);
    fake_gl.time_elapsed = elapsed;
    fake_gl.time_elapsed_user = ctx;
    mesh(quad_pos, 4, quad_idx, 6, &quad);
    mesh(tetra_pos, 4, tetra_idx, 12, &tetra);
}

static int teardown(void **state)
{
    (void)state;
    destroy_context();
    return 0;
}

enum { PLAIN, CSG, BLENDED, AREA };

/* near 1, far 10, 90 degrees: volumes move its far plane to infinity */
static const float perspective[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -11.0f / 9.0f, -1,
                                      0, 0, -20.0f / 9.0f, 0};

/* One frame: a point light over the quad, and what `kind` adds. */
static stin_shadows_stats frame(int kind)
{
    stin_frame_desc fd;
    stin_light_desc l;
    memset(&fd, 0, sizeof fd);
    stin__mat4_identity(fd.view);
    fd.view[14] = -5.0f; /* the camera 5 above the quad, looking down */
    memcpy(fd.projection, perspective, sizeof perspective);
    fd.viewport[2] = 64;
    fd.viewport[3] = 48;
    memset(&l, 0, sizeof l);
    l.position[2] = 3.0f;
    l.radius = kind == AREA ? 0.5f : 0.0f;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    assert_int_equal(stin_add_light(ctx, &l), STIN_OK);
    assert_int_equal(stin_draw(ctx, quad, NULL, NULL), STIN_OK);
    if (kind == CSG) {
        stin_csg_primitive prim;
        stin_csg_node node;
        stin_csg_desc cd;
        memset(&prim, 0, sizeof prim);
        memset(&node, 0, sizeof node);
        memset(&cd, 0, sizeof cd);
        prim.mesh = tetra;
        node.op = STIN_CSG_PRIMITIVE;
        cd.primitives = &prim;
        cd.primitive_count = 1;
        cd.nodes = &node;
        cd.node_count = 1;
        assert_int_equal(stin_draw_csg(ctx, &cd), STIN_OK);
    } else if (kind == BLENDED) {
        stin_material glass;
        memset(&glass, 0, sizeof glass);
        glass.color[0] = glass.color[3] = 0.5f;
        assert_int_equal(stin_draw(ctx, tetra, NULL, &glass), STIN_OK);
    }
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    return stin_query_frame_stats(ctx).shadows;
}

/* Log lines of a switch so far. */
static unsigned switches(void)
{
    unsigned n = 0;
    const char *at = log_.text;
    while ((at = strstr(at, "a frame) instead of")) != NULL) {
        n++;
        at++;
    }
    return n;
}

/* On where the selection chose vdsm on auto: volumes set up beside it,
 * the choice's reason and log say frames are measured, and the first frame
 * runs vdsm (each candidate's cost unknown). */
static void test_on_where_vdsm_is_automatic(void **state)
{
    stin_choice c;
    stin_shadows_stats st;
    (void)state;
    set_costs(10, 4, 8);
    create(STIN_TECH_NONE, 0, 0);
    c = stin_query_choice(ctx, STIN_FEATURE_SHADOWS);
    assert_int_equal(c.technique, STIN_TECH_SHADOWS_VDSM);
    assert_non_null(strstr(c.reason, "measured cost"));
    assert_true(fake_log_has(&log_, STIN_LOG_TECHNIQUE_SELECTED, "chosen by measured GPU time"));
    assert_int_equal(stin_query_desc(ctx).shadows.choice_frames, STIN__CHOICE_FRAMES);
    st = frame(PLAIN);
    assert_int_equal(st.choice_frame, STIN_SHADOW_CHOICE_VDSM);
    assert_int_equal(st.choice_current, STIN_SHADOW_CHOICE_VDSM);
    assert_int_equal(st.choice_trial, 0);
    assert_true(st.choice_ms[0] == 0.0f && st.choice_ms[1] == 0.0f && st.choice_ms[2] == 0.0f);
    assert_int_equal(fake_gl.time_queries_begun, 1);
}

/* Candidates within the 15% margin: trials run (every candidate's frames,
 * every other frame a trial at choice_frames 1), the choice never moves. */
static void test_small_difference_never_switches(void **state)
{
    unsigned ran[4] = {0, 0, 0, 0}, trials = 0;
    int i;
    (void)state;
    set_costs(10, 9, 9.5);
    create(STIN_TECH_NONE, 1, 0);
    for (i = 0; i < 200; i++) {
        stin_shadows_stats st = frame(PLAIN);
        assert_int_equal(st.choice_current, STIN_SHADOW_CHOICE_VDSM);
        ran[st.choice_frame]++;
        trials += st.choice_trial;
        assert_true(st.choice_trial == (st.choice_frame != STIN_SHADOW_CHOICE_VDSM));
    }
    assert_int_equal(switches(), 0);
    /* 8 frames of warm-up, then one of the chosen one, one trial, ... */
    assert_int_equal(trials, 96);
    assert_int_equal(ran[STIN_SHADOW_CHOICE_VOLUME_GPU], 48);
    assert_int_equal(ran[STIN_SHADOW_CHOICE_VOLUME_CPU], 48);
}

/* A candidate well below the chosen one: one switch, logged with both
 * techniques and their ms, after two trials it won; the stats carry each
 * candidate's smoothed ms; it stays (no flip back) for hundreds of frames
 * of trials; a real change of costs moves it once more. */
static void test_large_difference_switches_once(void **state)
{
    stin_shadows_stats st;
    int i, switched_at = -1;
    (void)state;
    set_costs(10, 4, 8);
    create(STIN_TECH_NONE, 1, 0);
    for (i = 0; i < 40; i++) {
        st = frame(PLAIN);
        if (switched_at < 0 && st.choice_current == STIN_SHADOW_CHOICE_VOLUME_GPU)
            switched_at = i;
    }
    /* after 8 frames of warm-up GPU volumes' trials fall on frames 8, 12,
     * 16: the first one's time is dropped (its buffers), the next two win,
     * the last read back a frame later */
    assert_int_equal(switched_at, 17);
    assert_int_equal(switches(), 1);
    assert_true(fake_log_has(
        &log_, STIN_LOG_TECHNIQUE_SELECTED,
        "volume (GPU-extruded) (4.000 ms a frame) instead of vdsm (10.000 ms)"));
    assert_true(st.choice_ms[0] > 9.99f && st.choice_ms[0] < 10.01f);
    assert_true(st.choice_ms[1] > 3.99f && st.choice_ms[1] < 4.01f);
    assert_true(st.choice_ms[2] > 7.99f && st.choice_ms[2] < 8.01f);
    for (i = 0; i < 300; i++) {
        st = frame(PLAIN);
        assert_int_equal(st.choice_current, STIN_SHADOW_CHOICE_VOLUME_GPU);
    }
    assert_int_equal(switches(), 1);
    set_costs(2, 4, 8); /* vdsm got cheap: the choice follows, once */
    for (i = 0; i < 300; i++)
        st = frame(PLAIN);
    assert_int_equal(st.choice_current, STIN_SHADOW_CHOICE_VDSM);
    assert_int_equal(switches(), 2);
}

/* The default pace: no trial in the first 8 frames, then one frame in two
 * until each candidate has been timed three times, then a trial after
 * every 30 frames of the chosen one. */
static void test_trials_every_choice_frames(void **state)
{
    unsigned trials = 0;
    int i;
    (void)state;
    set_costs(10, 9, 9.5);
    create(STIN_TECH_NONE, 0, 0);
    for (i = 0; i < 8; i++)
        trials += frame(PLAIN).choice_trial;
    assert_int_equal(trials, 0);
    for (i = 0; i < 12; i++) /* the exploration: 6 trials */
        trials += frame(PLAIN).choice_trial;
    assert_int_equal(trials, 6);
    trials = 0;
    for (i = 0; i < 310; i++)
        trials += frame(PLAIN).choice_trial;
    assert_int_equal(trials, 10);
}

/* Results are read only once available: while the GPU holds them, no
 * result is read and four frames at most are timed; once there, they are
 * read back. No switch program is built either: the lit programs are the
 * same for every candidate. */
static void test_reads_never_wait_and_build_nothing(void **state)
{
    unsigned programs;
    int i;
    (void)state;
    set_costs(10, 4, 8);
    create(STIN_TECH_NONE, 1, 0);
    fake_gl.queries_unavailable = 1;
    for (i = 0; i < 10; i++)
        (void)frame(PLAIN);
    assert_int_equal(fake_gl.time_queries_begun, 4);
    assert_int_equal(fake_gl.calls[STIN_GLFN_GetQueryObjectui64v], 0);
    fake_gl.queries_unavailable = 0;
    for (i = 0; i < 4; i++) /* each candidate's first frames made their buffers */
        (void)frame(PLAIN);
    assert_true(fake_gl.time_results_read >= 4);
    programs = fake_gl.programs_created;
    for (i = 0; i < 60; i++)
        (void)frame(PLAIN);
    assert_int_equal(switches(), 1);
    assert_int_equal(fake_gl.programs_created, programs);
}

/* Forcing a technique (vdsm itself too), or the debug flag: no queries,
 * no trials, every frame the selection's technique, stats OFF. */
static void test_forcing_turns_it_off(void **state)
{
    static const stin_technique forced[] = {STIN_TECH_SHADOWS_VDSM, STIN_TECH_SHADOWS_VOLUME,
                                            STIN_TECH_NONE};
    size_t k;
    int i;
    (void)state;
    set_costs(10, 4, 8);
    for (k = 0; k < sizeof forced / sizeof forced[0]; k++) {
        create(forced[k], 1, forced[k] == STIN_TECH_NONE ? STIN_DEBUG_SHADOW_CHOICE_OFF : 0);
        assert_false(fake_log_has(&log_, STIN_LOG_TECHNIQUE_SELECTED, "measured"));
        for (i = 0; i < 30; i++) {
            stin_shadows_stats st = frame(PLAIN);
            assert_int_equal(st.choice_frame, STIN_SHADOW_CHOICE_OFF);
            assert_int_equal(st.choice_current, STIN_SHADOW_CHOICE_OFF);
            assert_int_equal(st.choice_trial, 0);
        }
        assert_int_equal(fake_gl.time_queries_begun, 0);
        assert_int_equal(switches(), 0);
        assert_int_equal(ctx->shadow, stin__shadow_technique_of(forced[k] == STIN_TECH_NONE
                                                                    ? STIN_TECH_SHADOWS_VDSM
                                                                    : forced[k]));
    }
}

/* Frames volumes would not draw the same - a CSG product (vdsm casts it),
 * a blended draw, an area light - run vdsm under a choice of volumes, are
 * not trials and not timed; the next frame begins on vdsm (its projection
 * the caller's) and the one after goes back to the choice. */
static void test_vdsm_only_frames_stay_on_vdsm(void **state)
{
    static const int kinds[] = {CSG, BLENDED, AREA};
    float proj[16];
    size_t k;
    int i;
    (void)state;
    set_costs(10, 4, 8);
    create(STIN_TECH_NONE, 1, 0);
    for (i = 0; i < 40; i++)
        (void)frame(PLAIN);
    assert_int_equal(frame(PLAIN).choice_current, STIN_SHADOW_CHOICE_VOLUME_GPU);
    for (k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        unsigned timed = fake_gl.time_queries_begun;
        stin_shadows_stats st = frame(kinds[k]);
        assert_int_equal(st.choice_frame, STIN_SHADOW_CHOICE_VDSM);
        assert_int_equal(st.choice_current, STIN_SHADOW_CHOICE_VOLUME_GPU);
        assert_int_equal(st.choice_trial, 0);
        assert_int_equal(fake_gl.time_queries_begun, timed);
        st = frame(kinds[k]); /* begun on vdsm: the caller's projection */
        stin_query_frame_projection(ctx, proj);
        assert_true(proj[10] == perspective[10] && proj[14] == perspective[14]);
        assert_int_equal(st.choice_frame, STIN_SHADOW_CHOICE_VDSM);
        st = frame(PLAIN); /* begun on vdsm still, volumes could draw it */
        assert_int_equal(st.choice_frame, STIN_SHADOW_CHOICE_VDSM);
        assert_int_equal(st.choice_trial, 0);
        st = frame(PLAIN);
        assert_true(st.choice_frame != STIN_SHADOW_CHOICE_VDSM || st.choice_trial);
    }
    assert_int_equal(switches(), 1);
}

/* Each end of a frame's query stands in a submission of its own, two
 * flushes each: llvmpipe stamps every query end in a scene when the scene
 * is done, so without them a frame drawn without a framebuffer switch
 * measured 0.03 ms (stin-bench --peers). A frame the choice does not time
 * flushes nothing. */
static void test_query_ends_stand_alone(void **state)
{
    unsigned begun, flushes;
    (void)state;
    set_costs(10, 4, 8);
    create(STIN_TECH_NONE, 1, 0);
    begun = fake_gl.time_queries_begun;
    flushes = fake_gl.calls[STIN_GLFN_Flush];
    (void)frame(PLAIN);
    assert_int_equal(fake_gl.time_queries_begun, begun + 1);
    assert_int_equal(fake_gl.calls[STIN_GLFN_Flush], flushes + 4);
    create(STIN_TECH_SHADOWS_VOLUME, 1, 0); /* forced: no choice, no query */
    flushes = fake_gl.calls[STIN_GLFN_Flush];
    (void)frame(PLAIN);
    assert_int_equal(fake_gl.calls[STIN_GLFN_Flush], flushes);
}

#define TEST(f) cmocka_unit_test_teardown(f, teardown)

int main(void)
{
    const struct CMUnitTest tests[] = {
        TEST(test_on_where_vdsm_is_automatic),
        TEST(test_small_difference_never_switches),
        TEST(test_large_difference_switches_once),
        TEST(test_trials_every_choice_frames),
        TEST(test_reads_never_wait_and_build_nothing),
        TEST(test_forcing_turns_it_off),
        TEST(test_vdsm_only_frames_stay_on_vdsm),
        TEST(test_query_ends_stand_alone),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
