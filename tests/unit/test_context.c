/* SPDX-License-Identifier: MIT */
/* Context creation on the fake GL: memory sizing, the caller's block,
 * defaults, tier forcing, shader fallback, and GL-object balance. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "fake_gl.h"
#include "internal.h"

/* the path's shared programs: the packed-depth one is built only without
 * depth textures, which every fake profile here has */
#define SHARED_PROGRAMS (STIN__PROG_COUNT - 1)

#define BIT(c) STIN_CAP_BIT(STIN_CAP_##c)

/* A context on the fake GL, in a heap block owned by the test. */
typedef struct fixture {
    stin_desc desc;
    fake_log log;
    void *block;
    stin_context *ctx;
} fixture;

static void fixture_init(fixture *f, const fake_gl_config *cfg)
{
    memset(f, 0, sizeof *f);
    fake_gl_reset(cfg);
    f->desc.get_proc_address = fake_gl_get_proc;
    f->desc.log = fake_log_fn;
    f->desc.log_user = &f->log;
    f->desc.max_vertices = 4096; /* small blocks keep the tests fast */
    f->desc.max_triangles = 4096;
    f->desc.max_texture_bytes = 64 * 1024;
    /* pass and object counts below are the unshadowed path's */
    f->desc.techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_OFF;
}

/* Blocks are freed by the test's teardown too, so a failed assertion leaks nothing. */
static void *blocks[8];

static void *block_alloc(size_t bytes)
{
    size_t i;
    for (i = 0; i < sizeof blocks / sizeof blocks[0]; i++)
        if (!blocks[i]) {
            blocks[i] = malloc(bytes);
            assert_non_null(blocks[i]);
            return blocks[i];
        }
    fail_msg("too many blocks");
    return NULL;
}

static void block_free(void *p)
{
    size_t i;
    for (i = 0; p && i < sizeof blocks / sizeof blocks[0]; i++)
        if (blocks[i] == p)
            blocks[i] = NULL;
    free(p);
}

static int free_blocks(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof blocks / sizeof blocks[0]; i++) {
        free(blocks[i]);
        blocks[i] = NULL;
    }
    return 0;
}

static stin_result fixture_create(fixture *f)
{
    size_t bytes = stin_memory_size(&f->desc);
    assert_true(bytes > 0);
    f->block = block_alloc(bytes);
    return stin_create(&f->desc, f->block, bytes, &f->ctx);
}

static void fixture_free(fixture *f)
{
    if (f->ctx)
        stin_destroy(f->ctx);
    block_free(f->block);
    f->ctx = NULL;
    f->block = NULL;
}

static void assert_gl_objects_balanced(void)
{
    assert_int_equal(fake_gl.buffers_created, fake_gl.buffers_deleted);
    assert_int_equal(fake_gl.vertex_arrays_created, fake_gl.vertex_arrays_deleted);
    assert_int_equal(fake_gl.textures_created, fake_gl.textures_deleted);
    assert_int_equal(fake_gl.shaders_created, fake_gl.shaders_deleted);
    assert_int_equal(fake_gl.programs_created, fake_gl.programs_deleted);
    assert_int_equal(fake_gl.transform_feedbacks_created, fake_gl.transform_feedbacks_deleted);
    assert_int_equal(fake_gl.deletes_of_zero, 0);
}

static const float quad_positions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
static const uint32_t quad_indices[] = {0, 1, 2, 0, 2, 3};

static stin_mesh make_quad(stin_context *ctx)
{
    stin_mesh_desc md;
    stin_mesh m;
    memset(&md, 0, sizeof md);
    md.positions = quad_positions;
    md.vertex_count = 4;
    md.indices = quad_indices;
    md.index_count = 6;
    assert_int_equal(stin_create_mesh(ctx, &md, &m), STIN_OK);
    return m;
}

static stin_texture make_texture(stin_context *ctx)
{
    static const uint8_t pixels[4 * 4 * 4] = {255, 0, 0, 255};
    stin_texture_desc td;
    stin_texture t;
    memset(&td, 0, sizeof td);
    td.width = 4;
    td.height = 4;
    td.pixels = pixels;
    assert_int_equal(stin_create_texture(ctx, &td, &t), STIN_OK);
    return t;
}

static void run_frame(stin_context *ctx, stin_mesh m)
{
    stin_frame_desc fd;
    stin_light_desc light;
    memset(&fd, 0, sizeof fd);
    stin__mat4_identity(fd.view);
    stin__mat4_identity(fd.projection);
    fd.viewport[2] = 64;
    fd.viewport[3] = 64;
    memset(&light, 0, sizeof light);
    light.position[2] = 2.0f;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    assert_int_equal(stin_add_light(ctx, &light), STIN_OK);
    assert_int_equal(stin_draw(ctx, m, NULL, NULL), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
}

/* ---- memory size ----------------------------------------------------------- */
static void test_memory_size_grows_with_capacities(void **state)
{
    stin_desc d;
    size_t base;
    (void)state;
    memset(&d, 0, sizeof d);
    base = stin_memory_size(&d);
    assert_true(base > sizeof(stin_context));
#define GROWS(field, value)                          \
    do {                                             \
        stin_desc g = d;                             \
        g.field = (value);                           \
        assert_true(stin_memory_size(&g) > base);    \
    } while (0)
    GROWS(max_meshes, 128);
    GROWS(max_textures, 1000);
    GROWS(max_draws, 4096);
    GROWS(max_lights, 32);
    GROWS(max_vertices, 300000);
    GROWS(max_texture_bytes, 16u << 20);
#undef GROWS
    d.max_triangles = 300000;
    d.max_mesh_triangles = 100000;
    assert_true(stin_memory_size(&d) > base);
}

static void test_memory_size_is_zero_for_invalid_descs(void **state)
{
    stin_desc d;
    (void)state;
    assert_int_equal(stin_memory_size(NULL), 0);
    memset(&d, 0, sizeof d);
    d.max_lights = 33;
    assert_int_equal(stin_memory_size(&d), 0);
    d.max_lights = 32;
    assert_true(stin_memory_size(&d) > 0);
    d.max_triangles = 100;
    d.max_mesh_triangles = 101;
    assert_int_equal(stin_memory_size(&d), 0);
    d.max_mesh_triangles = 100;
    assert_true(stin_memory_size(&d) > 0);
    d.max_meshes = 65536;
    assert_int_equal(stin_memory_size(&d), 0);
}

static void test_block_one_byte_too_small(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fixture f;
    size_t need;
    char number[32];
    stin_context *ctx = (stin_context *)1;
    (void)state;
    fixture_init(&f, &cfg);
    need = stin_memory_size(&f.desc);
    f.block = block_alloc(need);
    assert_int_equal(stin_create(&f.desc, f.block, need - 1, &ctx), STIN_ERROR_OUT_OF_MEMORY);
    assert_null(ctx);
    assert_int_equal(f.log.items[STIN_LOG_ARENA_TOO_SMALL], 1);
    stin__formatf(number, sizeof number, "%zu", need);
    assert_true(fake_log_has(&f.log, STIN_LOG_ARENA_TOO_SMALL, number));
    assert_int_equal(stin_create(&f.desc, NULL, need, &ctx), STIN_ERROR_OUT_OF_MEMORY);
    assert_int_equal(fake_gl.calls[STIN_GLFN_GetString], 0); /* GL untouched */
    assert_int_equal(stin_create(&f.desc, f.block, need, &ctx), STIN_OK);
    assert_non_null(ctx);
    stin_destroy(ctx);
    block_free(f.block);
}

static void test_unaligned_blocks_work(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fixture f;
    size_t need, off;
    unsigned char *raw;
    (void)state;
    fixture_init(&f, &cfg);
    need = stin_memory_size(&f.desc);
    raw = block_alloc(need + 16);
    for (off = 1; off < 16; off++) {
        stin_context *ctx = NULL;
        stin_mesh m;
        assert_int_equal(stin_create(&f.desc, raw + off, need, &ctx), STIN_OK);
        assert_int_equal((uintptr_t)ctx % 16, 0);
        assert_true((unsigned char *)ctx >= raw + off);
        m = make_quad(ctx);
        run_frame(ctx, m);
        stin_destroy(ctx);
    }
    block_free(raw);
    assert_gl_objects_balanced();
}

/* Nothing in the caller's block is assumed zero. */
static void test_block_full_of_garbage_works(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fixture f;
    size_t need;
    stin_mesh_info info;
    stin_mesh m;
    (void)state;
    fixture_init(&f, &cfg);
    f.desc.max_meshes = 4;
    need = stin_memory_size(&f.desc);
    f.block = block_alloc(need);
    memset(f.block, 0xA5, need);
    assert_int_equal(stin_create(&f.desc, f.block, need, &f.ctx), STIN_OK);
    m = make_quad(f.ctx);
    assert_int_equal(stin_query_mesh_info(f.ctx, m, &info), STIN_OK);
    assert_int_equal(info.triangle_count, 2);
    make_texture(f.ctx);
    run_frame(f.ctx, m);
    fixture_free(&f);
    assert_int_equal(fake_gl.buffers_created, 4); /* the quad's and goldfeather's cap's */
    assert_gl_objects_balanced();
}

static void test_create_argument_errors(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fixture f;
    stin_context *ctx = (stin_context *)1;
    static unsigned char block[64];
    (void)state;
    fixture_init(&f, &cfg);
    assert_int_equal(stin_create(NULL, block, sizeof block, &ctx), STIN_ERROR_INVALID_ARGUMENT);
    assert_null(ctx);
    assert_int_equal(stin_create(&f.desc, block, sizeof block, NULL), STIN_ERROR_INVALID_ARGUMENT);
    f.desc.get_proc_address = NULL;
    assert_int_equal(stin_create(&f.desc, block, sizeof block, &ctx), STIN_ERROR_INVALID_ARGUMENT);
    assert_true(f.log.items[STIN_LOG_BAD_ARGUMENT] >= 1);
    f.desc.get_proc_address = fake_gl_get_proc;
    f.desc.max_lights = 33;
    assert_int_equal(stin_create(&f.desc, block, sizeof block, &ctx), STIN_ERROR_INVALID_ARGUMENT);
}

static void test_no_current_context(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fixture f;
    (void)state;
    cfg.version = NULL;
    fixture_init(&f, &cfg);
    assert_int_equal(fixture_create(&f), STIN_ERROR_GL);
    assert_null(f.ctx);
    assert_true(f.log.errors >= 1);
    fixture_free(&f);
}

/* ---- defaults ------------------------------------------------------------ */
static void test_query_desc_returns_documented_defaults(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    stin_desc zero, d;
    stin_context *ctx;
    void *block;
    size_t bytes;
    (void)state;
    fake_gl_reset(&cfg);
    memset(&zero, 0, sizeof zero);
    zero.get_proc_address = fake_gl_get_proc;
    bytes = stin_memory_size(&zero);
    block = block_alloc(bytes);
    assert_int_equal(stin_create(&zero, block, bytes, &ctx), STIN_OK);
    d = stin_query_desc(ctx);
    assert_int_equal(d.max_meshes, 64);
    assert_int_equal(d.max_textures, 64);
    assert_int_equal(d.max_draws, 1024);
    assert_int_equal(d.max_lights, 8);
    assert_int_equal(d.max_vertices, 262144);
    assert_int_equal(d.max_triangles, 262144);
    assert_int_equal(d.max_mesh_triangles, 65536);
    assert_int_equal(d.max_texture_bytes, 8u << 20);
    assert_int_equal(d.tier, STIN_TIER_AUTO);
    assert_int_equal(d.caps_mask, 0);
    assert_int_equal(d.max_gl_version, 0);
    assert_true(d.get_proc_address == fake_gl_get_proc);
    stin_destroy(ctx);
    block_free(block);
    d = stin_query_desc(NULL);
    assert_int_equal(d.max_meshes, 0);
}

static void test_query_desc_keeps_explicit_values(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fixture f;
    stin_desc d;
    (void)state;
    fixture_init(&f, &cfg);
    f.desc.max_meshes = 3;
    f.desc.max_lights = 32;
    f.desc.max_triangles = 1000; /* max_mesh_triangles defaults to at most this */
    assert_int_equal(fixture_create(&f), STIN_OK);
    d = stin_query_desc(f.ctx);
    assert_int_equal(d.max_meshes, 3);
    assert_int_equal(d.max_lights, 32);
    assert_int_equal(d.max_triangles, 1000);
    assert_int_equal(d.max_mesh_triangles, 1000);
    assert_int_equal(d.max_vertices, 4096);
    fixture_free(&f);
}

/* ---- tiers ---------------------------------------------------------------- */
static void test_auto_tier_per_fake_profile(void **state)
{
    static const struct {
        fake_gl_profile_id id;
        stin_tier tier;
        stin_technique lighting;
    } cases[] = {
        {FAKE_GL11, STIN_TIER_GL1, STIN_TECH_LIGHTING_FIXED},
        {FAKE_GL13, STIN_TIER_GL1, STIN_TECH_LIGHTING_FIXED},
        {FAKE_GL14, STIN_TIER_GL1, STIN_TECH_LIGHTING_FIXED},
        {FAKE_GL21, STIN_TIER_GL2, STIN_TECH_LIGHTING_GLSL110},
        {FAKE_GL33_CORE, STIN_TIER_GL4, STIN_TECH_LIGHTING_GLSL150},
        {FAKE_GL45_CORE, STIN_TIER_GL4, STIN_TECH_LIGHTING_GLSL150},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fake_gl_config cfg = fake_gl_profile(cases[i].id);
        fixture f;
        fixture_init(&f, &cfg);
        assert_int_equal(fixture_create(&f), STIN_OK);
        assert_int_equal(stin_query_tier(f.ctx), cases[i].tier);
        assert_int_equal(stin_query_choice(f.ctx, STIN_FEATURE_LIGHTING).technique,
                         cases[i].lighting);
        assert_int_equal(f.log.items[STIN_LOG_TIER_SELECTED], 1);
        assert_int_equal(f.log.errors, 0);
        fixture_free(&f);
        assert_gl_objects_balanced();
    }
}

static void test_forcing_gl4_on_gl21_is_unsupported(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fixture f;
    (void)state;
    fixture_init(&f, &cfg);
    f.desc.tier = STIN_TIER_GL4;
    assert_int_equal(fixture_create(&f), STIN_ERROR_UNSUPPORTED);
    assert_null(f.ctx);
    assert_int_equal(f.log.items[STIN_LOG_TIER_UNSUPPORTED], 1);
    assert_true(fake_log_has(&f.log, STIN_LOG_TIER_UNSUPPORTED,
                             stin_cap_name(STIN_CAP_GLSL_150)));
    assert_int_equal(fake_gl.programs_created, 0);
    fixture_free(&f);
}

/* A tier value that is not a tier is a bad argument, and logged as one. */
static void test_unknown_tier_is_a_bad_argument(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fixture f;
    (void)state;
    fixture_init(&f, &cfg);
    f.desc.tier = (stin_tier)3;
    assert_int_equal(stin_memory_size(&f.desc), 0); /* no size for what create refuses */
    f.block = block_alloc(64);
    assert_int_equal(stin_create(&f.desc, f.block, 64, &f.ctx), STIN_ERROR_INVALID_ARGUMENT);
    assert_null(f.ctx);
    assert_int_equal(f.log.items[STIN_LOG_TECHNIQUE_UNSUPPORTED], 0);
    assert_true(fake_log_has(&f.log, STIN_LOG_BAD_ARGUMENT, "tier"));
    fixture_free(&f);
}

/* displacement.tess_pixels below 1 is raised to 1 and logged (a 512-triangle
 * grid at 0.02 took minutes a frame); 1 and above stay; not above 0 is
 * still a bad desc. */
static void test_tess_pixels_floor(void **state)
{
    static const float given[3] = {0.02f, 1e-6f, 2.5f}, taken[3] = {1.0f, 1.0f, 2.5f};
    fake_gl_config cfg = fake_gl_profile(FAKE_GL45_CORE);
    fixture f;
    int i;
    (void)state;
    for (i = 0; i < 3; i++) {
        fixture_init(&f, &cfg);
        f.desc.displacement.tess_pixels = given[i];
        assert_int_equal(fixture_create(&f), STIN_OK);
        assert_true(stin_query_desc(f.ctx).displacement.tess_pixels == taken[i]);
        assert_int_equal(fake_log_has(&f.log, STIN_LOG_BAD_ARGUMENT, "tess_pixels"), i < 2);
        fixture_free(&f);
    }
    fixture_init(&f, &cfg);
    f.desc.displacement.tess_pixels = -0.5f;
    assert_int_equal(stin_memory_size(&f.desc), 0);
}

static void test_forcing_a_lower_tier(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fixture f;
    (void)state;
    fixture_init(&f, &cfg);
    f.desc.tier = STIN_TIER_GL1;
    assert_int_equal(fixture_create(&f), STIN_OK);
    assert_int_equal(stin_query_tier(f.ctx), STIN_TIER_GL1);
    assert_int_equal(stin_query_choice(f.ctx, STIN_FEATURE_LIGHTING).technique,
                     STIN_TECH_LIGHTING_FIXED);
    assert_true(fake_log_has(&f.log, STIN_LOG_TIER_SELECTED, "forced"));
    assert_int_equal(fake_gl.programs_created, 0);
    fixture_free(&f);
}

static void test_forced_technique_unsupported_is_logged(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL33_CORE);
    fixture f;
    (void)state;
    fixture_init(&f, &cfg);
    f.desc.techniques[STIN_FEATURE_LIGHTING] = STIN_TECH_LIGHTING_FIXED;
    assert_int_equal(fixture_create(&f), STIN_ERROR_UNSUPPORTED);
    assert_int_equal(f.log.items[STIN_LOG_TECHNIQUE_UNSUPPORTED], 1);
    assert_true(fake_log_has(&f.log, STIN_LOG_TECHNIQUE_UNSUPPORTED,
                             stin_cap_name(STIN_CAP_FIXED_FUNCTION)));
    fixture_free(&f);
}

static void test_caps_mask_lowers_the_tier_and_is_logged(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fixture f;
    const stin_caps *caps;
    (void)state;
    fixture_init(&f, &cfg);
    f.desc.caps_mask = BIT(GLSL);
    assert_int_equal(fixture_create(&f), STIN_OK);
    assert_int_equal(stin_query_tier(f.ctx), STIN_TIER_GL1);
    caps = stin_query_caps(f.ctx);
    assert_true((caps->hidden & BIT(GLSL)) != 0);
    assert_true((caps->present & BIT(GLSL)) == 0);
    assert_true(fake_log_has(&f.log, STIN_LOG_CAPS, stin_cap_name(STIN_CAP_GLSL)));
    fixture_free(&f);
}

/* ---- shader failures --------------------------------------------------------- */
static void test_glsl150_compile_failure_falls_back_to_glsl110(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL45_CORE);
    fixture f;
    stin_choice c;
    stin_mesh m;
    (void)state;
    cfg.core_profile = 0; /* compatibility: GLSL 1.10 runs next to 1.50 */
    cfg.version = "4.5 (Compatibility Profile) Mesa 22.3.6";
    cfg.fail_glsl_from = 150;
    fixture_init(&f, &cfg);
    assert_int_equal(fixture_create(&f), STIN_OK);
    assert_int_equal(stin_query_tier(f.ctx), STIN_TIER_GL4);
    c = stin_query_choice(f.ctx, STIN_FEATURE_LIGHTING);
    assert_int_equal(c.technique, STIN_TECH_LIGHTING_GLSL110);
    assert_non_null(strstr(c.reason, "glsl150-per-pixel"));
    assert_true(f.log.items[STIN_LOG_SHADER_COMPILE] >= 1);
    assert_true(fake_log_has(&f.log, STIN_LOG_FALLBACK, "glsl110-per-pixel"));
    assert_true(fake_log_has(&f.log, STIN_LOG_SHADER_COMPILE, "GLSL version not supported"));
    assert_int_equal(fake_gl.shader_compile_failures, 1);
    /* the shared programs plus the lit program's normal, parallax and pom
     * variants, depth-peel's composite, the GPU CSG resolve's three and
     * the outline's */
    assert_int_equal(fake_gl.programs_created, SHARED_PROGRAMS + 3 + 1 + 3 + 1);
    m = make_quad(f.ctx);
    run_frame(f.ctx, m);
    assert_int_equal(fake_gl.draw_calls, 1);
    fixture_free(&f);
    assert_gl_objects_balanced();
}

/* Programs that link, then one that does not: stin_create fails on a core
 * context (nothing below GLSL) and must delete what it had built. */
static void test_failed_create_after_linked_programs_leaves_nothing(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL45_CORE);
    fixture f;
    (void)state;
    cfg.fail_link_from = 3;
    fixture_init(&f, &cfg);
    assert_int_equal(fixture_create(&f), STIN_ERROR_GL);
    assert_null(f.ctx);
    assert_true(fake_gl.programs_created >= 3); /* two linked before the failure */
    assert_gl_objects_balanced();
    fixture_free(&f);
}

/* vdsm's programs fail after lighting's linked: vdsm steps down, logged,
 * and keeps none of its objects. */
static void test_vdsm_link_failure_steps_down_and_releases(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL45_CORE);
    fixture f;
    (void)state;
    cfg.fail_link_from = SHARED_PROGRAMS + 3 + 1; /* the first program after lighting's */
    fixture_init(&f, &cfg);
    f.desc.techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_VDSM;
    assert_int_equal(fixture_create(&f), STIN_OK);
    assert_int_not_equal(stin_query_choice(f.ctx, STIN_FEATURE_SHADOWS).technique,
                         STIN_TECH_SHADOWS_VDSM);
    assert_true(fake_log_has(&f.log, STIN_LOG_FALLBACK, "vdsm"));
    fixture_free(&f);
    assert_gl_objects_balanced();
}

static void test_glsl150_failure_on_core_has_nothing_below(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL45_CORE);
    fixture f;
    (void)state;
    cfg.fail_glsl_from = 150;
    fixture_init(&f, &cfg);
    assert_int_equal(fixture_create(&f), STIN_ERROR_GL);
    assert_null(f.ctx);
    assert_true(fake_log_has(&f.log, STIN_LOG_FALLBACK, "glsl150-per-pixel"));
    assert_gl_objects_balanced(); /* nothing left behind by the failed create */
    fixture_free(&f);
}

static void test_link_failure_on_gl21_falls_back_to_fixed_function(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fixture f;
    (void)state;
    cfg.fail_link = 1;
    fixture_init(&f, &cfg);
    assert_int_equal(fixture_create(&f), STIN_OK);
    assert_int_equal(stin_query_choice(f.ctx, STIN_FEATURE_LIGHTING).technique,
                     STIN_TECH_LIGHTING_FIXED);
    assert_int_equal(f.log.items[STIN_LOG_SHADER_LINK], 1);
    assert_true(fake_log_has(&f.log, STIN_LOG_FALLBACK, "fixed-function"));
    assert_int_equal(fake_gl.program_link_failures, 1);
    fixture_free(&f);
    assert_gl_objects_balanced();
}

/* ---- destroy ------------------------------------------------------------- */
/* per_context: the GL4 path's VAO for shadow volumes with its two
 * streaming buffers (vertices, indices: 2 per_context buffers), and on GL4
 * goldfeather's depth texture; the meshes: the caller's three and
 * goldfeather's near-plane cap (stin's own) */
static void check_destroy_balances(fake_gl_profile_id id, unsigned buffers_per_mesh,
                                   unsigned vaos_per_mesh, unsigned programs, unsigned per_context)
{
    fake_gl_config cfg = fake_gl_profile(id);
    fixture f;
    stin_mesh a, b;
    fixture_init(&f, &cfg);
    assert_int_equal(fixture_create(&f), STIN_OK);
    a = make_quad(f.ctx);
    b = make_quad(f.ctx);
    make_texture(f.ctx);
    stin_destroy_texture(f.ctx, make_texture(f.ctx));
    run_frame(f.ctx, a);
    stin_destroy_mesh(f.ctx, b);
    make_quad(f.ctx);
    assert_int_equal(fake_gl.buffers_created, 4 * buffers_per_mesh + 2 * per_context);
    assert_int_equal(fake_gl.vertex_arrays_created, 4 * vaos_per_mesh + per_context);
    assert_int_equal(fake_gl.textures_created, 2 + per_context);
    assert_int_equal(fake_gl.programs_created, programs);
    assert_int_equal(fake_gl.textures_deleted, 1);
    assert_int_equal(fake_gl.programs_deleted, 0);
    fixture_free(&f);
    assert_gl_objects_balanced();
}

static void test_destroy_deletes_every_gl_object(void **state)
{
    (void)state;
    check_destroy_balances(FAKE_GL11, 0, 0, 0, 0);
    /* GLSL tiers: depth-peel's composite program too (its textures come with
     * the first frame with blended draws), and the GPU CSG resolve's merge,
     * kill and snap programs (its textures come with the first product),
     * and the outline's; the frame's one lit program specialised to its
     * light batch (render/lit_specialise.c) */
    check_destroy_balances(FAKE_GL21, 2, 0, SHARED_PROGRAMS + 3 + 1 + 3 + 1 + 1, 0);
    /* GL 4.5: each program again, tessellated ("displace-tess"), dual-peel's
     * composite and its min-max programs (plain and tessellated), on core
     * goldfeather's depth program (compatibility contexts use glDrawPixels;
     * interval, not the default, builds its two where chosen), and the GPU
     * resolve's three, the outline's, and the specialised lit program */
    check_destroy_balances(FAKE_GL45_CORE, 2, 1,
                           2 * (SHARED_PROGRAMS + 3) + 1 + 2 + 1 + 3 + 1 + 1, 1);
}

/* ---- entry points and extensions ------------------------------------------ */
static void test_missing_glsl_entry_point_lowers_the_tier(void **state)
{
    static const char *const missing[] = {"glUniform3fv", NULL};
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fixture f;
    (void)state;
    cfg.missing = missing;
    fixture_init(&f, &cfg);
    assert_int_equal(fixture_create(&f), STIN_OK);
    assert_int_equal(stin_query_tier(f.ctx), STIN_TIER_GL1);
    assert_int_equal(f.log.items[STIN_LOG_MISSING_ENTRY_POINT], 1);
    assert_true((stin_query_caps(f.ctx)->present & BIT(GLSL)) == 0);
    fixture_free(&f);
}

/* A GL 1.1 entry point has no capability to turn off: the context cannot be
 * used, and stin_create must say so rather than call a NULL pointer later. */
static void test_missing_core_entry_point_fails_create(void **state)
{
    static const char *const missing[] = {"glDrawElements", NULL};
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    fixture f;
    (void)state;
    cfg.missing = missing;
    fixture_init(&f, &cfg);
    assert_int_equal(fixture_create(&f), STIN_ERROR_GL);
    assert_null(f.ctx);
    assert_true(fake_log_has(&f.log, STIN_LOG_MISSING_ENTRY_POINT, "glDrawElements"));
    fixture_free(&f);
}

static void test_has_extension_is_an_exact_match(void **state)
{
    static const char *const exts[] = {"GL_ARB_shadow_ambient", "GL_EXT_stencil_two_side"};
    fake_gl_config cfg = fake_gl_profile(FAKE_GL14);
    fixture f;
    (void)state;
    cfg.extensions = "GL_ARB_shadow_ambient GL_EXT_stencil_wrap";
    fixture_init(&f, &cfg);
    f.desc.caps_mask = BIT(STENCIL_WRAP); /* has_extension reports the driver, before the mask */
    assert_int_equal(fixture_create(&f), STIN_OK);
    assert_true(stin_query_extension(f.ctx, "GL_EXT_stencil_wrap"));
    assert_true(stin_query_extension(f.ctx, "GL_ARB_shadow_ambient"));
    assert_false(stin_query_extension(f.ctx, "GL_ARB_shadow"));
    assert_false(stin_query_extension(f.ctx, "GL_EXT_stencil"));
    assert_false(stin_query_extension(f.ctx, ""));
    assert_false(stin_query_extension(f.ctx, NULL));
    fixture_free(&f);

    cfg = fake_gl_profile(FAKE_GL33_CORE);
    cfg.extension_list = exts;
    cfg.extension_count = 2;
    fixture_init(&f, &cfg);
    assert_int_equal(fixture_create(&f), STIN_OK);
    assert_true(stin_query_extension(f.ctx, "GL_EXT_stencil_two_side"));
    assert_false(stin_query_extension(f.ctx, "GL_ARB_shadow"));
    assert_false(stin_query_extension(f.ctx, "GL_EXT_stencil_two_side_x"));
    fixture_free(&f);
}

#define TEST(f) cmocka_unit_test_teardown(f, free_blocks)

int main(void)
{
    const struct CMUnitTest tests[] = {
        TEST(test_memory_size_grows_with_capacities),
        TEST(test_memory_size_is_zero_for_invalid_descs),
        TEST(test_block_one_byte_too_small),
        TEST(test_unaligned_blocks_work),
        TEST(test_block_full_of_garbage_works),
        TEST(test_create_argument_errors),
        TEST(test_no_current_context),
        TEST(test_query_desc_returns_documented_defaults),
        TEST(test_query_desc_keeps_explicit_values),
        TEST(test_auto_tier_per_fake_profile),
        TEST(test_forcing_gl4_on_gl21_is_unsupported),
        TEST(test_unknown_tier_is_a_bad_argument),
        TEST(test_forcing_a_lower_tier),
        TEST(test_tess_pixels_floor),
        TEST(test_forced_technique_unsupported_is_logged),
        TEST(test_caps_mask_lowers_the_tier_and_is_logged),
        TEST(test_glsl150_compile_failure_falls_back_to_glsl110),
        TEST(test_glsl150_failure_on_core_has_nothing_below),
        TEST(test_failed_create_after_linked_programs_leaves_nothing),
        TEST(test_vdsm_link_failure_steps_down_and_releases),
        TEST(test_link_failure_on_gl21_falls_back_to_fixed_function),
        TEST(test_destroy_deletes_every_gl_object),
        TEST(test_missing_glsl_entry_point_lowers_the_tier),
        TEST(test_missing_core_entry_point_fails_create),
        TEST(test_has_extension_is_an_exact_match),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
