/* SPDX-License-Identifier: MIT */
/* The GL state contract of stin.h ("GL STATE"), checked on the whole state
 * the fake GL keeps (fake_gl_state.h). For every fake profile, every tier
 * it runs, every shadow and surface technique stin_create accepts there and
 * every output, a frame with a spot, a directional and a point light and
 * opaque and blended draws (one smooth and closed: volumes' terminator
 * band) must leave each field as the caller had it,
 * except the ones the header says the frame resets (to GL's defaults) or
 * overwrites. The same for stin_create (nothing changes) and for mesh and
 * texture creation (buffer and unit-0 texture bindings left at 0).
 * Every differing field is reported by name with its expected and actual
 * value, grouped over the frames it differs in; STIN_STATE_VERBOSE=1 lists
 * every frame. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fake_gl.h"
#include "internal.h"

static const struct profile {
    fake_gl_profile_id id;
    const char *name;
} profiles[] = {{FAKE_GL11, "GL11"},         {FAKE_GL13, "GL13"},
                {FAKE_GL14, "GL14"},         {FAKE_GL21, "GL21"},
                {FAKE_GL33_CORE, "GL33core"}, {FAKE_GL45_CORE, "GL45core"}};

static const stin_tier tiers[] = {STIN_TIER_GL1, STIN_TIER_GL2, STIN_TIER_GL4};
static const stin_technique shadows[] = {STIN_TECH_SHADOWS_OFF, STIN_TECH_SHADOWS_VOLUME,
                                         STIN_TECH_SHADOWS_MAP_DEPTH,
                                         STIN_TECH_SHADOWS_MAP_COMBINE,
                                         STIN_TECH_SHADOWS_MAP_PCF};
static const stin_technique surfaces[] = {STIN_TECH_SURFACE_PLAIN, STIN_TECH_SURFACE_DOT3,
                                          STIN_TECH_SURFACE_NORMAL, STIN_TECH_SURFACE_PARALLAX,
                                          STIN_TECH_SURFACE_POM};
static const struct {
    stin_output output;
    const char *name;
    stin_export export_visibility;
} outputs[] = {{STIN_OUTPUT_BEAUTY, "beauty", STIN_EXPORT_NONE},
               {STIN_OUTPUT_VISIBILITY, "visibility", STIN_EXPORT_NONE},
               {STIN_OUTPUT_NORMAL, "normal", STIN_EXPORT_NONE},
               {STIN_OUTPUT_BEAUTY, "beauty+export", STIN_EXPORT_VISIBILITY},
               {STIN_OUTPUT_BEAUTY, "export-only", STIN_EXPORT_VISIBILITY_ONLY}};

/* ---- mismatches, grouped by field ------------------------------------------ */
#define MAX_GROUPS 1024
#define WHERE_SHOWN 6

typedef struct group {
    char field[112];          /* "[setup] field" */
    char expected[96], got[96]; /* the first frame's values */
    char where[WHERE_SHOWN][72];
    unsigned count;
} group;

static group groups[MAX_GROUPS];
static unsigned group_count, mismatches, checked;
static const char *label;  /* the frame or call being checked */
static const char *setup;  /* which check: "frame", "stin_create", ... */
static int verbose;

/* The fields the same frame got wrong from GL's defaults: the run with
 * caller values reports only the others (what the caller's values add). */
#define MAX_SEEN 256
static char seen[MAX_SEEN][64];
static unsigned seen_count;
static int remember, skip_seen;

static int was_seen(const char *field)
{
    unsigned i;
    for (i = 0; i < seen_count; i++)
        if (strcmp(seen[i], field) == 0)
            return 1;
    return 0;
}

static void record(void *user, const char *field, const char *expected, const char *got)
{
    char key[112];
    unsigned i;
    (void)user;
    if (skip_seen && was_seen(field))
        return;
    if (remember && seen_count < MAX_SEEN)
        snprintf(seen[seen_count++], sizeof seen[0], "%s", field);
    mismatches++;
    snprintf(key, sizeof key, "[%s] %s", setup, field);
    if (verbose)
        print_message("  %s %s: expected %s, got %s\n", label, key, expected, got);
    for (i = 0; i < group_count && strcmp(groups[i].field, key) != 0; i++)
        ;
    if (i == group_count) {
        if (group_count == MAX_GROUPS)
            return;
        group_count++;
        memset(&groups[i], 0, sizeof groups[i]);
        snprintf(groups[i].field, sizeof groups[i].field, "%s", key);
        snprintf(groups[i].expected, sizeof groups[i].expected, "%s", expected);
        snprintf(groups[i].got, sizeof groups[i].got, "%s", got);
    }
    if (groups[i].count < WHERE_SHOWN)
        snprintf(groups[i].where[groups[i].count], sizeof groups[i].where[0], "%s", label);
    groups[i].count++;
}

/* What the fake itself could not follow counts as a mismatch too. */
static void check_fake(void)
{
    const char *fn = fake_gl_untracked_entry_point();
    if (fake_gl.untracked)
        record(NULL, "fake GL: untracked state call", "none", fake_gl.untracked_what);
    if (fake_gl.gl_errors)
        record(NULL, "fake GL: call a GL would refuse", "none", fake_gl.gl_error_what);
    if (fn)
        record(NULL, "fake GL: generated no-op that may change state", "none", fn);
    if (fake_gl.attrib_depth) { /* a push without its pop */
        char depth[16];
        snprintf(depth, sizeof depth, "%u", fake_gl.attrib_depth);
        record(NULL, "attribute stack depth", "0", depth);
        fake_gl.attrib_depth = 0;
    }
    fake_gl.untracked = fake_gl.gl_errors = 0;
}

static void compare(const fake_gl_glstate *expected)
{
    checked++;
    fake_gl_state_diff(expected, &fake_gl.gl, record, NULL);
    check_fake();
}

static void reset_report(void)
{
    group_count = mismatches = checked = 0;
    verbose = getenv("STIN_STATE_VERBOSE") && getenv("STIN_STATE_VERBOSE")[0] == '1';
}

/* Prints the groups and fails the test if there are any. */
static void finish_report(const char *what)
{
    unsigned i, k;
    for (i = 0; i < group_count; i++) {
        const group *g = &groups[i];
        print_message("%s: expected %s, got %s, in %u: ", g->field, g->expected, g->got, g->count);
        for (k = 0; k < g->count && k < WHERE_SHOWN; k++)
            print_message("%s%s", k ? ", " : "", g->where[k]);
        print_message("%s\n", g->count > WHERE_SHOWN ? ", ..." : "");
    }
    if (mismatches)
        fail_msg("%s: %u fields differ (%u kinds) over %u checks", what, mismatches, group_count,
                 checked);
    assert_true(checked > 0);
}

/* ---- the scene ----------------------------------------------------------------- */
static fake_log log_;
static stin_context *ctx;
static void *block;
static stin_mesh cube, ball;
static stin_texture albedo, normal_map, height_map;

static void create_mesh(const float *pos, const float *nrm, const float *uv, uint32_t vertices,
                        const uint32_t *idx, uint32_t indices, stin_mesh *out)
{
    stin_mesh_desc md = {.positions = pos, .normals = nrm, .uvs = uv, .vertex_count = vertices,
                         .indices = idx, .index_count = indices};
    assert_int_equal(stin_create_mesh(ctx, &md, out), STIN_OK);
}

/* A unit cube, four vertices a face so that every face has its own normal
 * and uvs (tangents come from the uvs). */
static void make_cube(void)
{
    static const float n[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    float pos[72], nrm[72], uv[48];
    uint32_t idx[36];
    int f, v, k;
    for (f = 0; f < 6; f++) {
        /* two axes spanning the face, u x v = n */
        float u[3] = {n[f][1], n[f][2], n[f][0]}, w[3];
        w[0] = n[f][1] * u[2] - n[f][2] * u[1];
        w[1] = n[f][2] * u[0] - n[f][0] * u[2];
        w[2] = n[f][0] * u[1] - n[f][1] * u[0];
        for (v = 0; v < 4; v++) {
            float su = (v == 1 || v == 2) ? 0.5f : -0.5f, sv = v >= 2 ? 0.5f : -0.5f;
            for (k = 0; k < 3; k++) {
                pos[12 * f + 3 * v + k] = 0.5f * n[f][k] + su * u[k] + sv * w[k];
                nrm[12 * f + 3 * v + k] = n[f][k];
            }
            uv[8 * f + 2 * v] = su + 0.5f;
            uv[8 * f + 2 * v + 1] = sv + 0.5f;
        }
        idx[6 * f + 0] = (uint32_t)(4 * f);
        idx[6 * f + 1] = (uint32_t)(4 * f + 1);
        idx[6 * f + 2] = (uint32_t)(4 * f + 2);
        idx[6 * f + 3] = (uint32_t)(4 * f);
        idx[6 * f + 4] = (uint32_t)(4 * f + 2);
        idx[6 * f + 5] = (uint32_t)(4 * f + 3);
    }
    create_mesh(pos, nrm, uv, 24, idx, 36, &cube);
}

/* An octahedron with its corners' normals pointing out of the centre: a
 * closed smooth mesh, so volumes draw their terminator band; updated once. */
static void make_ball(void)
{
    static const float pos[18] = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    static const uint32_t idx[24] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                     2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    stin_mesh_update_desc ud = {.positions = pos, .normals = pos, .vertex_count = 6};
    create_mesh(pos, pos, NULL, 6, idx, 24, &ball);
    /* the same shape again: the update's GL state is held with creation's */
    assert_int_equal(stin_update_mesh(ctx, ball, &ud), STIN_OK);
}

static stin_texture make_texture(stin_texture_kind kind, const uint8_t rgba[4])
{
    uint8_t px[4 * 4 * 4];
    stin_texture_desc td;
    stin_texture t;
    int i;
    for (i = 0; i < 16; i++)
        memcpy(px + 4 * i, rgba, 4);
    memset(&td, 0, sizeof td);
    td.kind = kind;
    td.width = td.height = 4;
    td.pixels = px;
    assert_int_equal(stin_create_texture(ctx, &td, &t), STIN_OK);
    return t;
}

static void destroy_context(void)
{
    if (ctx)
        stin_destroy(ctx);
    free(block);
    ctx = NULL;
    block = NULL;
}

/* 1 if stin_create accepts the combination on cfg (the fake's state is
 * reset first). */
static int create_context_on(const fake_gl_config *cfg, stin_tier tier, stin_technique shadow,
                             stin_technique surface)
{
    stin_desc d = fake_gl_desc(&log_);
    size_t bytes;
    destroy_context();
    fake_gl_reset(cfg);
    d.tier = tier;
    d.techniques[STIN_FEATURE_SHADOWS] = shadow;
    d.techniques[STIN_FEATURE_SURFACE] = surface;
    d.max_meshes = 2;
    d.max_textures = 4;
    d.max_vertices = 64;
    d.max_triangles = 64;
    d.max_mesh_triangles = 64;
    d.max_draws = 8;
    d.max_lights = 4;
    d.shadows.map_size = 256;
    d.shadows.soft_samples = 2;
    bytes = stin_memory_size(&d);
    assert_true(bytes > 0);
    block = malloc(bytes);
    assert_non_null(block);
    if (stin_create(&d, block, bytes, &ctx) != STIN_OK) {
        ctx = NULL;
        return 0;
    }
    return 1;
}

static int create_context(fake_gl_profile_id id, stin_tier tier, stin_technique shadow,
                          stin_technique surface)
{
    fake_gl_config cfg = fake_gl_profile(id);
    return create_context_on(&cfg, tier, shadow, surface);
}

static void perspective(float m[16], float near, float far)
{
    const float f = 1.7320508f; /* cot(30 degrees): 60 degrees vertical */
    memset(m, 0, 16 * sizeof *m);
    m[0] = f / (64.0f / 48.0f);
    m[5] = f;
    m[10] = (far + near) / (near - far);
    m[11] = -1.0f;
    m[14] = 2.0f * far * near / (near - far);
}

static stin_frame_desc frame_desc(stin_output output, stin_export ex)
{
    stin_frame_desc fd = {.viewport = {3, 2, 64, 48}, .clear_color = {0.1f, 0, 0, 0},
                          .ambient = {0.2f, 0.2f, 0.2f}};
    fd.output = output;
    fd.export_visibility = ex;
    stin__mat4_identity(fd.view);
    fd.view[12] = 0.3f;
    fd.view[14] = -6.0f;
    perspective(fd.projection, 0.5f, 50.0f);
    return fd;
}

/* Spot, directional and point light (the point light takes the six-face
 * map paths), a textured and a plain opaque cube, a blended one. */
/* 0 when the frame was refused as documented (an export without FBOs):
 * nothing drawn, no GL touched. */
static int run_frame(stin_output output, stin_export ex)
{
    static const stin_light_desc lights[3] = {
        {.type = STIN_LIGHT_SPOT, .position = {0, 4, 3}, .direction = {0, -4, -3},
         .spot_cutoff_deg = 40.0f},
        {.type = STIN_LIGHT_DIRECTIONAL, .direction = {-0.3f, -1.0f, -0.2f}, .intensity = 0.5f},
        /* brighter than 1 near it: DOT3's scaled pass */
        {.type = STIN_LIGHT_POINT, .position = {2.0f, 2.5f, 1.0f}, .attenuation = {0.5f, 0, 0}}};
    stin_frame_desc fd = frame_desc(output, ex);
    uint64_t fbo = STIN_CAP_BIT(STIN_CAP_FBO) | STIN_CAP_BIT(STIN_CAP_PACKED_DEPTH_STENCIL);
    stin_material tex = {.color = {0.8f, 0.6f, 0.4f, 1.0f}, .specular = {0.3f, 0.3f, 0.3f},
                         .self_shadow = 1},
                  plain = {.shininess = 0} /* every default */,
                  glass = {.color = {0.5f, 0.5f, 0.5f, 0.5f}};
    float xf[16];
    int i;
    if (ex && (stin_query_caps(ctx)->present & fbo) != fbo) { /* refused, nothing drawn */
        unsigned errors = log_.errors;
        assert_int_equal(stin_begin_frame(ctx, &fd), STIN_ERROR_UNSUPPORTED);
        assert_int_equal(log_.errors, errors + 1); /* said, and expected */
        log_.errors = errors;
        return 0;
    }
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    for (i = 0; i < 3; i++)
        assert_int_equal(stin_add_light(ctx, &lights[i]), STIN_OK);
    tex.albedo = albedo;
    tex.normal_map = normal_map;
    tex.height_map = height_map;
    stin__mat4_identity(xf);
    assert_int_equal(stin_draw(ctx, cube, xf, &tex), STIN_OK);
    xf[12] = 1.5f;
    xf[13] = -0.5f;
    assert_int_equal(stin_draw(ctx, cube, xf, &plain), STIN_OK);
    xf[12] = -0.5f;
    xf[13] = 0.2f;
    xf[14] = 1.2f;
    assert_int_equal(stin_draw(ctx, cube, xf, &glass), STIN_OK);
    /* displaced where the context displaces (GL 4.5: the tessellated
     * programs and GL_PATCH_VERTICES, which the caller gets back) */
    tex.displace = 1;
    xf[14] = -1.2f;
    assert_int_equal(stin_draw(ctx, cube, xf, &tex), STIN_OK);
    tex.displace = 0;
    stin__mat4_identity(xf);
    xf[12] = -1.5f;
    xf[13] = 0.5f;
    assert_int_equal(stin_draw(ctx, ball, xf, &plain), STIN_OK);
    fake_gl.patch_draws = 0;
    fake_gl.calls[STIN_GLFN_Begin] = 0;
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    /* fixed function's terminator band (render/terminator_fixed.c) ran */
    if (stin_query_choice(ctx, STIN_FEATURE_SHADOWS).technique == STIN_TECH_SHADOWS_VOLUME &&
        stin_query_choice(ctx, STIN_FEATURE_LIGHTING).technique == STIN_TECH_LIGHTING_FIXED &&
        output == STIN_OUTPUT_BEAUTY)
        assert_true(fake_gl.calls[STIN_GLFN_Begin] > 0);
    /* tessellated: that draw's passes, where it has its height map (and
     * only frames with one: test_frame) */
    if (stin_query_choice(ctx, STIN_FEATURE_DISPLACEMENT).technique ==
            STIN_TECH_DISPLACEMENT_TESS &&
        height_map.id)
        assert_true(fake_gl.patch_draws > 0);
    return 1;
}

/* ---- what the caller had, and what the header says comes back ------------------ */
static int has(stin_cap c) { return (stin_query_caps(ctx)->present & STIN_CAP_BIT(c)) != 0; }

static int gl_version(void)
{
    const stin_caps *c = stin_query_caps(ctx);
    return c->gl_major * 10 + c->gl_minor;
}

/* Caller state no pass sets, by the GL version that has it (issue 13 item
 * 19): the caller leaves it on, the frame turns it off and leaves it off. */
static const struct {
    int cap, version;
} hostile_caps[] = {
    {FAKE_GL_COLOR_LOGIC_OP, 11},  {FAKE_GL_POLYGON_SMOOTH, 11},     {FAKE_GL_CLIP_PLANE2, 11},
    {FAKE_GL_CLIP_PLANE7, 11},     {FAKE_GL_SAMPLE_ALPHA_TO_COVERAGE, 13},
    {FAKE_GL_SAMPLE_COVERAGE, 13}, {FAKE_GL_RASTERIZER_DISCARD, 30}, {FAKE_GL_PRIMITIVE_RESTART, 31},
    {FAKE_GL_SAMPLE_MASK, 32},     {FAKE_GL_PRIMITIVE_RESTART_FIXED_INDEX, 43}};
#define HOSTILE_SAMPLER 77

/* The caller's hostile state (non_default frames): everything above, a
 * blend equation, polygon mode, depth range and sampler objects, and on
 * compatibility contexts what the fixed pipeline would mix in. */
static void hostile_values(fake_gl_glstate *s)
{
    size_t i;
    for (i = 0; i < sizeof hostile_caps / sizeof hostile_caps[0]; i++)
        if (gl_version() >= hostile_caps[i].version)
            s->enabled[hostile_caps[i].cap] = 1;
    if (gl_version() >= 14)
        s->blend_equation = 0x8008; /* GL_MAX */
    if (gl_version() >= 40)
        s->patch_vertices = 4; /* kept: stin gives it back */
    s->polygon_mode[0] = s->polygon_mode[1] = 0x1B01; /* GL_LINE */
    s->depth_range[0] = 0.25f;
    s->depth_range[1] = 0.75f;
    if (gl_version() >= 33) {
        s->units[3].sampler = HOSTILE_SAMPLER;
        s->units[FAKE_GL_UNITS - 1].sampler = HOSTILE_SAMPLER; /* past stin's units: kept */
    }
    if (!has(STIN_CAP_FIXED_FUNCTION))
        return;
    s->enabled[FAKE_GL_ALPHA_TEST] = 1;
    s->enabled[FAKE_GL_POLYGON_STIPPLE] = 1;
    s->enabled[FAKE_GL_FOG] = 1;
    s->enabled[FAKE_GL_COLOR_MATERIAL] = 1;
    s->units[0].enabled[FAKE_GL_TEXTURE_2D] = 1;
    s->units[0].enabled[FAKE_GL_TEXTURE_GEN_S] = 1;
    s->units[0].matrix[0][0] = 2.0f;
    s->color_array = s->edge_flag_array = 1;
    s->pixel_transfer[FAKE_GL_DEPTH_SCALE] = 0.5f;
    if (has(STIN_CAP_MULTITEXTURE)) {
        s->units[1].enabled[FAKE_GL_TEXTURE_1D] = 1;
        s->units[1].matrix[0][5] = 3.0f;
        s->units[1].texcoord_array = 1;
    }
    if (gl_version() >= 14)
        s->fog_coord_array = s->secondary_color_array = 1;
}

/* What the frame leaves of hostile_values: GL's defaults for the state of
 * every tier (and alpha test and stipple on compatibility contexts). */
static void hostile_after(fake_gl_glstate *e, const fake_gl_glstate *def)
{
    size_t i;
    int u, units = stin_query_caps(ctx)->max_texture_image_units;
    for (i = 0; i < sizeof hostile_caps / sizeof hostile_caps[0]; i++)
        e->enabled[hostile_caps[i].cap] = 0;
    e->blend_equation = def->blend_equation;
    memcpy(e->polygon_mode, def->polygon_mode, sizeof e->polygon_mode);
    memcpy(e->depth_range, def->depth_range, sizeof e->depth_range);
    for (u = 0; u < units && u < 16; u++)
        e->units[u].sampler = 0;
    e->enabled[FAKE_GL_ALPHA_TEST] = e->enabled[FAKE_GL_POLYGON_STIPPLE] = 0;
}

static void translation(GLfloat *m, float x, float y, float z)
{
    stin__mat4_identity(m);
    m[12] = x;
    m[13] = y;
    m[14] = z;
}

/* Caller values. "defaults": GL's initial pixel store after creation (the
 * header: UNPACK_ALIGNMENT 4 is the caller's). "caller": also values the
 * frame must reset (depth, blend, cull, colour mask, scissor, program, active
 * unit) and values it must keep (shade model, normalize, two-sided lighting,
 * matrix mode and matrices, current colour, pack/unpack alignment). */
static void caller_values(int non_default)
{
    fake_gl_glstate *s = &fake_gl.gl;
    s->pixel_store[FAKE_GL_UNPACK_ALIGNMENT] = 4;
    if (!non_default)
        return;
    s->enabled[FAKE_GL_DEPTH_TEST] = 1;
    s->depth_func = GL_LEQUAL;
    s->enabled[FAKE_GL_BLEND] = 1;
    s->blend_src_rgb = s->blend_src_alpha = GL_SRC_ALPHA;
    s->blend_dst_rgb = s->blend_dst_alpha = GL_ONE_MINUS_SRC_ALPHA;
    s->enabled[FAKE_GL_CULL_FACE] = 1;
    s->cull_face = GL_FRONT;
    s->front_face = GL_CW;
    s->color_mask[3] = GL_FALSE;
    s->enabled[FAKE_GL_SCISSOR_TEST] = 1;
    s->pixel_store[FAKE_GL_UNPACK_ALIGNMENT] = 2;
    s->pixel_store[FAKE_GL_PACK_ALIGNMENT] = 8;
    if (has(STIN_CAP_GLSL))
        s->program = 4242;
    if (has(STIN_CAP_MULTITEXTURE))
        s->active_texture = GL_TEXTURE0 + 1;
    if (gl_version() >= 30) /* an sRGB target's encoding: kept, though data outputs set it aside */
        s->enabled[FAKE_GL_FRAMEBUFFER_SRGB] = 1;
    hostile_values(s);
    if (has(STIN_CAP_FIXED_FUNCTION)) {
        s->shade_model = 0x1D00; /* GL_FLAT */
        s->enabled[FAKE_GL_NORMALIZE] = 1;
        s->light_model_two_side = 1;
        s->matrix_mode = GL_PROJECTION;
        translation(s->modelview[0], 0.0f, 0.0f, -2.0f);
        translation(s->projection[0], 0.25f, 0.0f, 0.0f);
        s->current_color[0] = 0.25f;
        s->current_color[2] = 0.75f;
    }
}

/* The snapshot with what stin_end_frame documents applied. */
static void expected_after_frame(fake_gl_glstate *e, const stin_frame_desc *fd)
{
    fake_gl_glstate def;
    const fake_gl_glstate *got = &fake_gl.gl;
    stin_technique surface = stin_query_choice(ctx, STIN_FEATURE_SURFACE).technique;
    int gl1 = stin_query_tier(ctx) == STIN_TIER_GL1, u;
    fake_gl_state_init(&def);
    /* left at GL's defaults: the header's list, item by item */
    hostile_after(e, &def);
    e->enabled[FAKE_GL_DEPTH_TEST] = 0;
    e->depth_mask = GL_TRUE;
    e->depth_func = GL_LESS;
    e->enabled[FAKE_GL_BLEND] = 0;
    e->blend_src_rgb = def.blend_src_rgb;
    e->blend_dst_rgb = def.blend_dst_rgb;
    e->blend_src_alpha = def.blend_src_alpha;
    e->blend_dst_alpha = def.blend_dst_alpha;
    e->enabled[FAKE_GL_STENCIL_TEST] = 0;
    e->stencil[0] = def.stencil[0];
    e->stencil[1] = def.stencil[1];
    e->front_face = GL_CCW;
    e->cull_face = GL_BACK;
    e->enabled[FAKE_GL_CULL_FACE] = 0;
    memcpy(e->color_mask, def.color_mask, sizeof e->color_mask);
    e->enabled[FAKE_GL_SCISSOR_TEST] = 0;
    e->program = 0;
    e->active_texture = GL_TEXTURE0;
    memset(e->units[0].binding, 0, sizeof e->units[0].binding);
    e->array_buffer = 0;
    if (gl1) { /* the rest of the fixed-function state is the caller's */
        e->alpha_func = def.alpha_func;
        e->alpha_ref = def.alpha_ref;
        e->vertex_array = e->normal_array = e->color_array = 0;
        e->index_array = e->edge_flag_array = e->fog_coord_array = e->secondary_color_array = 0;
        for (u = 0; u < FAKE_GL_UNITS; u++)
            e->units[u].texcoord_array = 0;
        e->client_active_texture = GL_TEXTURE0;
    }
    /* set by the frame */
    memcpy(e->viewport, fd->viewport, sizeof e->viewport);
    if (has(STIN_CAP_FBO))
        e->draw_framebuffer = e->read_framebuffer = fd->framebuffer;
    /* overwritten */
    memcpy(e->clear_color, got->clear_color, sizeof e->clear_color);
    e->clear_depth = got->clear_depth;
    e->polygon_offset_factor = got->polygon_offset_factor;
    e->polygon_offset_units = got->polygon_offset_units;
    memcpy(e->scissor, got->scissor, sizeof e->scissor);
    /* the GLSL surface technique's units */
    if (surface == STIN_TECH_SURFACE_NORMAL || surface == STIN_TECH_SURFACE_PARALLAX ||
        surface == STIN_TECH_SURFACE_POM) {
        e->units[1].binding[FAKE_GL_TARGET_2D] = 0;
        e->units[2].binding[FAKE_GL_TARGET_2D] = 0;
    }
}

/* ---- the checks --------------------------------------------------------------- */
static const char *tier_name(stin_tier t)
{
    return t == STIN_TIER_GL1 ? "gl1" : t == STIN_TIER_GL2 ? "gl2" : "gl4";
}

/* stin_create must leave GL as it found it (GL's initial state here). */
static void check_create(void)
{
    fake_gl_glstate def;
    setup = "stin_create";
    fake_gl_state_init(&def);
    compare(&def);
}

/* Mesh and texture creation: buffer bindings and unit 0's texture
 * bindings are left at 0, everything else (UNPACK_ALIGNMENT too) as the
 * caller had it. */
static void create_scene(void)
{
    static const uint8_t white[4] = {200, 180, 160, 255}, flat[4] = {128, 128, 255, 255},
                         mid[4] = {128, 0, 0, 255};
    fake_gl_glstate e;
    setup = "create_mesh/texture";
    fake_gl_state_init(&fake_gl.gl); /* what stin_create left is checked on its own */
    e = fake_gl.gl;
    make_cube();
    make_ball();
    albedo = make_texture(STIN_TEXTURE_ALBEDO, white);
    normal_map = make_texture(STIN_TEXTURE_NORMAL, flat);
    height_map = make_texture(STIN_TEXTURE_HEIGHT, mid);
    e.array_buffer = 0;
    e.vao0.element_buffer = 0;
    memset(e.units[0].binding, 0, sizeof e.units[0].binding);
    compare(&e);
}

/* Each output from the same caller state: the state after creation plus
 * GL's defaults, then plus the caller's other values. */
static void check_frames(const fake_gl_glstate *created, const char *prefix)
{
    char where[72];
    size_t o;
    int non_default;
    for (o = 0; o < sizeof outputs / sizeof outputs[0]; o++)
        for (non_default = 0; non_default < 2; non_default++) {
            stin_frame_desc fd = frame_desc(outputs[o].output, outputs[o].export_visibility);
            fake_gl_glstate e;
            snprintf(where, sizeof where, "%s/%s", prefix, outputs[o].name);
            label = where;
            setup = non_default ? "frame, caller values" : "frame";
            fake_gl.gl = *created;
            caller_values(non_default);
            e = fake_gl.gl;
            if (run_frame(outputs[o].output, outputs[o].export_visibility))
                expected_after_frame(&e, &fd);
            if (!non_default)
                seen_count = 0;
            remember = !non_default;
            skip_seen = non_default;
            compare(&e);
            remember = skip_seen = 0;
        }
}

static void test_profile(void **state)
{
    const struct profile *p = (const struct profile *)*state;
    size_t t, s, f;
    unsigned combos = 0;
    char prefix[64];
    reset_report();
    for (t = 0; t < sizeof tiers / sizeof tiers[0]; t++)
        for (s = 0; s < sizeof shadows / sizeof shadows[0]; s++)
            for (f = 0; f < sizeof surfaces / sizeof surfaces[0]; f++) {
                fake_gl_glstate created;
                if (!create_context(p->id, tiers[t], shadows[s], surfaces[f]))
                    continue; /* refused: not a combination this profile runs */
                combos++;
                snprintf(prefix, sizeof prefix, "%s/%s/%s/%s", p->name, tier_name(tiers[t]),
                         stin_technique_name(shadows[s]), stin_technique_name(surfaces[f]));
                label = prefix;
                check_create();
                create_scene();
                created = fake_gl.gl;
                check_frames(&created, prefix);
                assert_int_equal(log_.errors, 0);
            }
    destroy_context();
    print_message("%s: %u technique combinations, %u checks\n", p->name, combos, checked);
    assert_true(combos > 0);
    finish_report(p->name);
}

/* GL_UNPACK_ALIGNMENT is the caller's after texture creation, whatever it
 * was (4 is GL's default). */
static void test_texture_creation_keeps_unpack_alignment(void **state)
{
    static const GLint alignments[] = {4, 2, 8};
    static const uint8_t grey[4] = {100, 100, 100, 255};
    char where[64];
    size_t p, a;
    (void)state;
    reset_report();
    setup = "create_texture";
    for (p = 0; p < sizeof profiles / sizeof profiles[0]; p++) {
        assert_true(create_context(profiles[p].id, STIN_TIER_AUTO, STIN_TECH_NONE, STIN_TECH_NONE));
        for (a = 0; a < sizeof alignments / sizeof alignments[0]; a++) {
            char expected[16], got[16];
            snprintf(where, sizeof where, "%s/alignment %d", profiles[p].name, alignments[a]);
            label = where;
            fake_gl.gl.pixel_store[FAKE_GL_UNPACK_ALIGNMENT] = alignments[a];
            (void)make_texture(STIN_TEXTURE_ALBEDO, grey);
            checked++;
            if (fake_gl.gl.pixel_store[FAKE_GL_UNPACK_ALIGNMENT] != alignments[a]) {
                snprintf(expected, sizeof expected, "%d", alignments[a]);
                snprintf(got, sizeof got, "%d", fake_gl.gl.pixel_store[FAKE_GL_UNPACK_ALIGNMENT]);
                record(NULL, "GL_UNPACK_ALIGNMENT", expected, got);
            }
        }
    }
    destroy_context();
    finish_report("texture creation");
}

/* Texture creation reads tightly packed client rows whatever the caller's
 * unpack state (row length, skips, a bound pixel unpack buffer) and gives
 * every piece of state back, the active unit's 2D binding included. */
static void test_texture_creation_ignores_and_keeps_unpack_state(void **state)
{
    static const uint8_t grey[4] = {100, 100, 100, 255};
    char where[64];
    size_t p;
    (void)state;
    reset_report();
    setup = "create_texture, caller unpack state";
    for (p = 0; p < sizeof profiles / sizeof profiles[0]; p++) {
        fake_gl_glstate before;
        assert_true(create_context(profiles[p].id, STIN_TIER_AUTO, STIN_TECH_NONE, STIN_TECH_NONE));
        snprintf(where, sizeof where, "%s", profiles[p].name);
        label = where;
        fake_gl.gl.pixel_store[FAKE_GL_UNPACK_ROW_LENGTH] = 7;
        fake_gl.gl.pixel_store[FAKE_GL_UNPACK_SKIP_ROWS] = 2;
        fake_gl.gl.pixel_store[FAKE_GL_UNPACK_SKIP_PIXELS] = 3;
        if (has(STIN_CAP_VBO) &&
            stin_query_caps(ctx)->gl_major * 10 + stin_query_caps(ctx)->gl_minor >= 21)
            fake_gl.gl.pixel_unpack_buffer = 99;
        if (has(STIN_CAP_MULTITEXTURE))
            fake_gl.gl.active_texture = GL_TEXTURE0 + 2;
        fake_gl.gl.units[has(STIN_CAP_MULTITEXTURE) ? 2 : 0].binding[FAKE_GL_TARGET_2D] = 55;
        before = fake_gl.gl;
        fake_gl.tex_images_loose = 0;
        (void)make_texture(STIN_TEXTURE_ALBEDO, grey);
        checked++;
        if (fake_gl.tex_images_loose) {
            char got[16];
            snprintf(got, sizeof got, "%u", fake_gl.tex_images_loose);
            record(NULL, "uploads with the caller's row length, skips or unpack buffer", "0", got);
        }
        compare(&before);
    }
    destroy_context();
    finish_report("texture creation, caller unpack state");
}

/* The fake's state of vertex array object `name` (bound once to make it). */
static fake_gl_vao vao_state(GLuint name)
{
    int i;
    for (i = 0; i < FAKE_GL_MAX_VAOS; i++)
        if (fake_gl.vaos[i].name == name)
            return fake_gl.vaos[i].state;
    fail_msg("vertex array %u unknown to the fake", name);
    return fake_gl.gl.vao0;
}

/* A caller's vertex array object (element buffer 55, attribute 5 on) and
 * array buffer 66 bound: mesh creation and every frame, on every tier of
 * a context with VAOs, leave the caller's VAO bound and as it was, and
 * make no call a GL would refuse (client pointers into a bound VAO). */
static void test_caller_vertex_array_is_left_alone(void **state)
{
    static const struct {
        fake_gl_profile_id id;
        const char *name;
    } bases[] = {{FAKE_GL21, "GL21+ARB_vao"}, {FAKE_GL45_CORE, "GL45core"}};
    size_t b, t, s, o;
    char where[96];
    (void)state;
    reset_report();
    for (b = 0; b < sizeof bases / sizeof bases[0]; b++)
        for (t = 0; t < sizeof tiers / sizeof tiers[0]; t++)
            for (s = 0; s < sizeof shadows / sizeof shadows[0]; s++) {
                fake_gl_config cfg = fake_gl_profile(bases[b].id);
                stin__gl gl;
                unsigned char loaded[STIN_GLFN_COUNT];
                fake_gl_vao caller;
                if (bases[b].id == FAKE_GL21)
                    cfg.extensions = "GL_ARB_multitexture GL_ARB_texture_env_combine "
                                     "GL_ARB_depth_texture GL_ARB_shadow GL_EXT_stencil_wrap "
                                     "GL_ARB_framebuffer_object GL_ARB_vertex_array_object";
                if (!create_context_on(&cfg, tiers[t], shadows[s], STIN_TECH_NONE))
                    continue;
                assert_true(has(STIN_CAP_VAO));
                snprintf(where, sizeof where, "%s/%s/%s", bases[b].name, tier_name(tiers[t]),
                         stin_technique_name(shadows[s]));
                label = where;
                stin__gl_load(&gl, fake_gl_get_proc, NULL, loaded);
                gl.BindVertexArray(77);
                gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 55);
                gl.EnableVertexAttribArray(5);
                gl.BindBuffer(GL_ARRAY_BUFFER, 66);
                caller = vao_state(77);
                setup = "create_mesh, caller VAO";
                make_cube();
                make_ball();
                for (o = 0; o <= sizeof outputs / sizeof outputs[0]; o++) {
                    fake_gl_vao now;
                    char got[16];
                    checked++;
                    if (fake_gl.gl.vertex_array_binding != 77) {
                        snprintf(got, sizeof got, "%u", fake_gl.gl.vertex_array_binding);
                        record(NULL, "vertex_array_binding", "77", got);
                    }
                    now = vao_state(77);
                    if (memcmp(&now, &caller, sizeof now) != 0) {
                        snprintf(got, sizeof got, "%u", now.element_buffer);
                        record(NULL, "caller VAO (element buffer, attributes)", "55, attrib 5 on",
                               got);
                    }
                    check_fake();
                    if (o == sizeof outputs / sizeof outputs[0])
                        break;
                    setup = "frame, caller VAO";
                    gl.BindBuffer(GL_ARRAY_BUFFER, 66);
                    run_frame(outputs[o].output, outputs[o].export_visibility);
                }
            }
    destroy_context();
    finish_report("caller vertex array");
}

/* The fake itself: defaults, the two stencil models, eye-space lights and
 * planes, deletion unbinding, and the diff naming fields. */
static void test_fake_gl_tracks_state(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL14);
    stin__gl gl;
    unsigned char loaded[STIN_GLFN_COUNT];
    fake_gl_glstate before;
    const GLfloat half[4] = {0.5f, 0.5f, 0.5f, 1.0f}, plane[4] = {0, 0, 1, 0};
    GLfloat shift[16];
    GLuint tex = 0;
    (void)state;
    fake_gl_reset(&cfg);
    stin__gl_load(&gl, fake_gl_get_proc, NULL, loaded);
    before = fake_gl.gl;
    assert_int_equal(fake_gl.gl.pixel_store[FAKE_GL_UNPACK_ALIGNMENT], 4);
    assert_true(fake_gl_is_enabled(0x0BD0)); /* GL_DITHER starts on */
    /* GL 1.4 + EXT_stencil_two_side: glStencilOp sets the active face only */
    gl.ActiveStencilFaceEXT(GL_BACK);
    gl.StencilOp(GL_KEEP, GL_INCR_WRAP, GL_KEEP);
    gl.ActiveStencilFaceEXT(GL_FRONT);
    gl.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    assert_int_equal(fake_gl.gl.stencil[1].zfail, GL_INCR_WRAP);
    assert_int_equal(fake_gl.gl.stencil[0].zfail, GL_KEEP);
    /* lights and eye planes are stored in eye space */
    translation(shift, 0.0f, 0.0f, -3.0f);
    gl.LoadMatrixf(shift);
    gl.Lightfv(GL_LIGHT0 + 1, GL_POSITION, (const GLfloat[4]){0, 0, 1, 1});
    assert_true(fake_gl.gl.lights[1].position[2] == -2.0f);
    gl.TexGenfv(GL_R, GL_EYE_PLANE, plane);
    assert_true(fake_gl.gl.units[0].eye_plane[2][3] == 3.0f); /* p M^-1 */
    gl.ActiveTexture(GL_TEXTURE0 + 2);
    gl.GenTextures(1, &tex);
    gl.BindTexture(GL_TEXTURE_2D, tex);
    gl.Enable(GL_TEXTURE_2D);
    gl.TexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    gl.Materialfv(GL_FRONT, GL_DIFFUSE, half);
    assert_true(fake_gl_is_enabled(GL_TEXTURE_2D));
    reset_report();
    setup = "self-test";
    label = "GL14";
    compare(&before);
    assert_int_equal(mismatches, 9);
    {
        static const char *const fields[] = {
            "stencil back.zfail", "light1.position", "modelview[0]", "active_texture",
            "unit0.texgen R eye plane", "unit2.env.mode", "unit2.enable GL_TEXTURE_2D",
            "unit2.binding GL_TEXTURE_2D", "material front.diffuse"};
        size_t i, k;
        for (i = 0; i < sizeof fields / sizeof fields[0]; i++) {
            for (k = 0; k < group_count && !strstr(groups[k].field, fields[i]); k++)
                ;
            if (k == group_count)
                fail_msg("the diff did not name %s", fields[i]);
        }
    }
    gl.DeleteTextures(1, &tex); /* deleting a bound texture unbinds it */
    assert_int_equal(fake_gl.gl.units[2].binding[FAKE_GL_TARGET_2D], 0);
    gl.PixelStorei(0x9999, 1);
    assert_int_equal(fake_gl.untracked, 1);
}

int main(void)
{
    struct CMUnitTest tests[sizeof profiles / sizeof profiles[0] + 4];
    size_t i, n = 0;
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_fake_gl_tracks_state);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_texture_creation_keeps_unpack_alignment);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_texture_creation_ignores_and_keeps_unpack_state);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_caller_vertex_array_is_left_alone);
    for (i = 0; i < sizeof profiles / sizeof profiles[0]; i++) {
        struct CMUnitTest t = cmocka_unit_test_prestate(test_profile, (void *)&profiles[i]);
        t.name = profiles[i].name;
        tests[n++] = t;
    }
    return cmocka_run_group_tests(tests, NULL, NULL);
}
