/* SPDX-License-Identifier: MIT */
/* stin_update_mesh on the fake GL: every refusal leaves the mesh as it was;
 * an update uploads the block's new vertices into the same buffer (nothing
 * else), refreshes bounds and convexity, keeps the topology, follows the
 * creation's welds, and equals destroying and creating the mesh. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h> /* NAN and INFINITY only: the test links without -lm */
#include <stdlib.h>
#include <string.h>

#include "fake_gl.h"
#include "internal.h"

static fake_log log_;
static void *block;
static stin_context *ctx;

static void create_context(fake_gl_profile_id profile)
{
    fake_gl_config cfg = fake_gl_profile(profile);
    stin_desc d;
    size_t bytes;
    fake_gl_reset(&cfg);
    d = fake_gl_desc(&log_);
    d.max_meshes = 8;
    d.max_vertices = 4096;
    d.max_triangles = 4096;
    d.max_mesh_triangles = 2048;
    d.max_texture_bytes = 1024;
    d.techniques[STIN_FEATURE_CSG] = STIN_TECH_CSG_OFF; /* no mesh of stin's own */
    bytes = stin_memory_size(&d);
    assert_true(bytes > 0);
    block = malloc(bytes);
    assert_non_null(block);
    assert_int_equal(stin_create(&d, block, bytes, &ctx), STIN_OK);
}

static int setup(void **state)
{
    (void)state;
    create_context(FAKE_GL21);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    if (ctx)
        stin_destroy(ctx);
    free(block);
    ctx = NULL;
    block = NULL;
    return 0;
}

/* ---- a box of 24 vertices (4 a face: split normals and uvs, so 16 of them
 * are welded onto the first of their corner) ------------------------------ */
#define BOX_VERTICES 24u
#define BOX_INDICES 36u
typedef struct box {
    float pos[3 * BOX_VERTICES], nrm[3 * BOX_VERTICES], uv[2 * BOX_VERTICES];
} box;
static uint32_t box_idx[BOX_INDICES];

/* Face f (axis f / 2, side f % 2) of a box with the given half sizes,
 * centred at c; counter-clockwise from outside. */
static void make_box(box *b, const float half[3], const float c[3])
{
    uint32_t f, k;
    for (f = 0; f < 6; f++) {
        uint32_t axis = f / 2u, u = (axis + 1u) % 3u, v = (axis + 2u) % 3u;
        float side = f % 2u ? 1.0f : -1.0f;
        for (k = 0; k < 4; k++) {
            float su = (k == 1 || k == 2) ? 1.0f : -1.0f, sv = k >= 2 ? 1.0f : -1.0f;
            float *p = b->pos + 3u * (4u * f + k), *n = b->nrm + 3u * (4u * f + k);
            if (side < 0.0f)
                su = -su; /* keep the winding counter-clockwise from outside */
            p[axis] = c[axis] + side * half[axis];
            p[u] = c[u] + su * half[u];
            p[v] = c[v] + sv * half[v];
            n[0] = n[1] = n[2] = 0.0f;
            n[axis] = side;
            b->uv[2u * (4u * f + k)] = su > 0.0f ? 1.0f : 0.0f;
            b->uv[2u * (4u * f + k) + 1u] = sv > 0.0f ? 1.0f : 0.0f;
        }
        box_idx[6u * f + 0] = 4u * f;
        box_idx[6u * f + 1] = 4u * f + 1u;
        box_idx[6u * f + 2] = 4u * f + 2u;
        box_idx[6u * f + 3] = 4u * f;
        box_idx[6u * f + 4] = 4u * f + 2u;
        box_idx[6u * f + 5] = 4u * f + 3u;
    }
}

static const float unit_half[3] = {1, 1, 1}, origin[3] = {0, 0, 0};

static stin_mesh create_box(const box *b, uint32_t subdivide, int with_uvs)
{
    stin_mesh_desc md;
    stin_mesh m;
    memset(&md, 0, sizeof md);
    md.positions = b->pos;
    md.normals = b->nrm;
    md.uvs = with_uvs ? b->uv : NULL;
    md.vertex_count = BOX_VERTICES;
    md.indices = box_idx;
    md.index_count = BOX_INDICES;
    md.subdivide = subdivide;
    assert_int_equal(stin_create_mesh(ctx, &md, &m), STIN_OK);
    return m;
}

static stin_mesh_update_desc update_of(const box *b)
{
    stin_mesh_update_desc u;
    memset(&u, 0, sizeof u);
    u.positions = b->pos;
    u.normals = b->nrm;
    u.vertex_count = BOX_VERTICES;
    return u;
}

static const stin__mesh_slot *slot_of(stin_mesh m)
{
    const stin__mesh_slot *s = stin__mesh_lookup(ctx, m, NULL);
    assert_non_null(s);
    return s;
}

static unsigned long long fnv(const void *data, size_t n)
{
    const unsigned char *b = (const unsigned char *)data;
    unsigned long long h = 1469598103934665603ull;
    size_t i;
    for (i = 0; i < n; i++)
        h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

/* The mesh's stored vertices and info, to show a refusal changed nothing. */
static unsigned long long fingerprint(stin_mesh m)
{
    const stin__mesh_slot *s = slot_of(m);
    return fnv(ctx->vertices + s->first_vertex, sizeof(stin__vertex) * s->vertex_count) ^
           fnv(&s->info, sizeof s->info);
}

/* ---- refusals --------------------------------------------------------------- */
static void test_refusals_leave_the_mesh(void **state)
{
    box b, moved;
    stin_mesh m, other;
    stin_mesh_update_desc u;
    unsigned long long before;
    unsigned uploads;
    (void)state;
    make_box(&b, unit_half, origin);
    make_box(&moved, unit_half, (const float[3]){2, 0, 0});
    m = create_box(&b, 0, 1);
    other = create_box(&b, 0, 1);
    stin_destroy_mesh(ctx, other); /* its handle is stale now */
    before = fingerprint(m);
    uploads = fake_gl.array_data.uploads;
    u = update_of(&moved);

    assert_int_equal(stin_update_mesh(NULL, m, &u), STIN_ERROR_INVALID_ARGUMENT);
    assert_int_equal(stin_update_mesh(ctx, m, NULL), STIN_ERROR_INVALID_ARGUMENT);
    u.positions = NULL;
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_ERROR_INVALID_ARGUMENT);
    assert_true(fake_log_has(&log_, STIN_LOG_BAD_ARGUMENT, "need positions for the mesh's 24"));
    u = update_of(&moved);
    u.vertex_count = 23;
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_ERROR_INVALID_ARGUMENT);
    assert_true(fake_log_has(&log_, STIN_LOG_BAD_ARGUMENT, "(got 23"));
    u = update_of(&moved);

    moved.pos[3 * 5 + 1] = NAN;
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_ERROR_INVALID_MESH);
    assert_true(fake_log_has(&log_, STIN_LOG_MESH_NOT_FINITE, "position of vertex 5"));
    moved.pos[3 * 5 + 1] = INFINITY;
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_ERROR_INVALID_MESH);
    moved.pos[3 * 5 + 1] = b.pos[3 * 5 + 1];
    moved.nrm[3 * 7] = -INFINITY;
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_ERROR_INVALID_MESH);
    assert_true(fake_log_has(&log_, STIN_LOG_MESH_NOT_FINITE, "normal of vertex 7"));
    moved.nrm[3 * 7] = b.nrm[3 * 7];
    {
        float tangents[4 * BOX_VERTICES] = {0};
        tangents[4 * 9 + 3] = NAN;
        u.tangents = tangents;
        assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_ERROR_INVALID_MESH);
        assert_true(fake_log_has(&log_, STIN_LOG_MESH_NOT_FINITE, "tangent of vertex 9"));
        u.tangents = NULL;
    }

    /* stale, foreign-looking and zero handles */
    assert_int_equal(stin_update_mesh(ctx, other, &u), STIN_ERROR_INVALID_HANDLE);
    assert_true(fake_log_has(&log_, STIN_LOG_BAD_HANDLE, "stin_update_mesh: stale"));
    assert_int_equal(stin_update_mesh(ctx, (stin_mesh){0}, &u), STIN_ERROR_INVALID_HANDLE);
    assert_int_equal(stin_update_mesh(ctx, (stin_mesh){m.id ^ 0x01000000u}, &u),
                     STIN_ERROR_INVALID_HANDLE);

    /* during a frame */
    {
        stin_frame_desc fd = {.viewport = {0, 0, 64, 48}};
        stin__mat4_identity(fd.view);
        stin__mat4_identity(fd.projection);
        assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
        assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_ERROR_INVALID_STATE);
        assert_true(fake_log_has(&log_, STIN_LOG_FRAME_STATE,
                                 "update it after stin_end_frame"));
        assert_int_equal(stin_end_frame(ctx), STIN_OK);
    }
    assert_int_equal(fingerprint(m), before);
    assert_int_equal(fake_gl.array_data.uploads, uploads);
    /* and it works after the frame */
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_OK);
    assert_true(fingerprint(m) != before);
}

static void test_tangents_refused_for_subdivided(void **state)
{
    box b;
    float tangents[4 * BOX_VERTICES] = {0};
    stin_mesh m;
    stin_mesh_update_desc u;
    (void)state;
    make_box(&b, unit_half, origin);
    m = create_box(&b, 1, 1);
    u = update_of(&b);
    u.tangents = tangents;
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_ERROR_INVALID_ARGUMENT);
    assert_true(fake_log_has(&log_, STIN_LOG_BAD_ARGUMENT, "subdivided 1 levels"));
    u.tangents = NULL;
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_OK);
}

/* ---- what an update does ------------------------------------------------------ */
static void test_uploads_into_the_same_buffer(void **state)
{
    box b, moved;
    stin_mesh m;
    stin_mesh_update_desc u;
    const stin__mesh_slot *s;
    unsigned buffers, data_calls, uploads;
    stin_mesh_info info;
    (void)state;
    make_box(&b, unit_half, origin);
    make_box(&moved, (const float[3]){0.5f, 2.0f, 1.0f}, (const float[3]){3, -1, 0.25f});
    m = create_box(&b, 0, 1);
    s = slot_of(m);
    assert_int_equal(fake_gl.array_data.usage, GL_STATIC_DRAW);
    buffers = fake_gl.buffers_created;
    data_calls = fake_gl.calls[STIN_GLFN_BufferData];
    uploads = fake_gl.array_data.uploads;
    u = update_of(&moved);
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_OK);
    /* one upload of the block's new vertices into the mesh's own buffer */
    assert_int_equal(fake_gl.calls[STIN_GLFN_BufferData], data_calls + 1);
    assert_int_equal(fake_gl.array_data.uploads, uploads + 1);
    assert_int_equal(fake_gl.buffers_created, buffers);
    assert_int_equal(fake_gl.array_data.buffer, s->vbo);
    assert_int_equal(fake_gl.array_data.size, sizeof(stin__vertex) * BOX_VERTICES);
    assert_int_equal(fake_gl.array_data.usage, GL_DYNAMIC_DRAW);
    assert_int_equal(fake_gl.array_data.hash,
                     fnv(ctx->vertices + s->first_vertex, sizeof(stin__vertex) * BOX_VERTICES));
    assert_memory_equal(ctx->vertices[s->first_vertex + 5].position, moved.pos + 15,
                        3 * sizeof(float));
    assert_int_equal(fake_gl.gl.array_buffer, 0); /* as stin_create_mesh leaves it */
    /* bounds refreshed, topology kept */
    assert_int_equal(stin_query_mesh_info(ctx, m, &info), STIN_OK);
    assert_true(info.bounds_min[0] == 2.5f && info.bounds_max[0] == 3.5f);
    assert_true(info.bounds_min[1] == -3.0f && info.bounds_max[1] == 1.0f);
    assert_true(info.bounds_min[2] == -0.75f && info.bounds_max[2] == 1.25f);
    assert_int_equal(info.closed_manifold, 1);
    assert_int_equal(info.convex, 1);
    assert_int_equal(info.welded_vertices, 0); /* bit-equal copies: none moved */
    assert_int_equal(info.triangle_count, 12);
}

static void test_no_buffers_on_gl11(void **state)
{
    box b, moved;
    stin_mesh m;
    stin_mesh_update_desc u;
    stin_mesh_info info;
    (void)state;
    teardown(state);
    create_context(FAKE_GL11);
    make_box(&b, unit_half, origin);
    make_box(&moved, unit_half, (const float[3]){0, 5, 0});
    m = create_box(&b, 0, 0);
    u = update_of(&moved);
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_OK);
    assert_int_equal(fake_gl.calls[STIN_GLFN_BufferData], 0); /* client arrays from the block */
    assert_int_equal(stin_query_mesh_info(ctx, m, &info), STIN_OK);
    assert_true(info.bounds_min[1] == 4.0f && info.bounds_max[1] == 6.0f);
}

/* Welded copies take their first vertex's new position, whatever they get. */
static void test_welds_follow_the_first_vertex(void **state)
{
    box b, moved;
    stin_mesh m;
    stin_mesh_update_desc u;
    const stin__mesh_slot *s;
    uint32_t i, j, stray = 0;
    (void)state;
    make_box(&b, unit_half, origin);
    m = create_box(&b, 0, 1);
    s = slot_of(m);
    moved = b;
    for (i = 0; i < 3 * BOX_VERTICES; i++)
        moved.pos[i] = b.pos[i] * 1.5f + (float)(i / 3u) * 1e-3f; /* every copy apart */
    u = update_of(&moved);
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_OK);
    for (i = 0; i < BOX_VERTICES; i++) {
        uint32_t first = i;
        for (j = 0; j < i; j++)
            if (!memcmp(b.pos + 3 * j, b.pos + 3 * i, 3 * sizeof(float))) {
                first = j;
                break;
            }
        stray += first != i;
        assert_memory_equal(ctx->vertices[s->first_vertex + i].position, moved.pos + 3 * first,
                            3 * sizeof(float));
    }
    assert_int_equal(stray, 16);
}

/* A dent makes a convex box concave, and undoing it convex again. */
static void test_convex_follows_the_shape(void **state)
{
    box b, dented;
    stin_mesh m;
    stin_mesh_update_desc u;
    stin_mesh_info info;
    uint32_t i;
    (void)state;
    make_box(&b, unit_half, origin);
    m = create_box(&b, 0, 1);
    dented = b;
    /* corner (1, 1, 1) pushed inside the other seven's hull: a dimple */
    for (i = 0; i < BOX_VERTICES; i++)
        if (b.pos[3 * i] > 0.0f && b.pos[3 * i + 1] > 0.0f && b.pos[3 * i + 2] > 0.0f)
            dented.pos[3 * i] = dented.pos[3 * i + 1] = dented.pos[3 * i + 2] = 0.2f;
    u = update_of(&dented);
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_OK);
    assert_int_equal(stin_query_mesh_info(ctx, m, &info), STIN_OK);
    assert_int_equal(info.convex, 0);
    assert_int_equal(info.closed_manifold, 1);
    u = update_of(&b);
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_OK);
    assert_int_equal(stin_query_mesh_info(ctx, m, &info), STIN_OK);
    assert_int_equal(info.convex, 1);
}

static void test_given_tangents_are_kept(void **state)
{
    box b;
    float tangents[4 * BOX_VERTICES];
    stin_mesh m;
    stin_mesh_update_desc u;
    float t[4];
    uint32_t i;
    (void)state;
    make_box(&b, unit_half, origin);
    m = create_box(&b, 0, 1);
    for (i = 0; i < BOX_VERTICES; i++) {
        tangents[4 * i] = 0.0f;
        tangents[4 * i + 1] = 1.0f;
        tangents[4 * i + 2] = 0.0f;
        tangents[4 * i + 3] = i % 2 ? -0.5f : 3.0f;
    }
    u = update_of(&b);
    u.tangents = tangents;
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_OK);
    assert_int_equal(stin_query_mesh_tangent(ctx, m, 3, t), STIN_OK);
    assert_true(t[0] == 0.0f && t[1] == 1.0f && t[2] == 0.0f && t[3] == -1.0f);
    assert_int_equal(stin_query_mesh_tangent(ctx, m, 4, t), STIN_OK);
    assert_true(t[3] == 1.0f);
}

/* An update equals destroying and creating the mesh from the new data:
 * every stored vertex, the info, the adjacency and what is derived. */
static void check_equals_create(uint32_t subdivide, int with_uvs, int with_normals)
{
    box b, moved;
    stin_mesh m, fresh;
    stin_mesh_update_desc u;
    const stin__mesh_slot *s, *f;
    uint32_t i;
    make_box(&b, unit_half, origin);
    make_box(&moved, (const float[3]){0.5f, 2.0f, 1.0f}, (const float[3]){3, -1, 0.25f});
    for (i = 0; i < BOX_VERTICES; i++) /* a twist: not a box any more, normals tilt */
        moved.pos[3 * i] += 0.3f * moved.pos[3 * i + 1] * moved.pos[3 * i + 2];
    m = create_box(&b, subdivide, with_uvs);
    u = update_of(&moved);
    if (!with_normals)
        u.normals = NULL;
    assert_int_equal(stin_update_mesh(ctx, m, &u), STIN_OK);
    if (!with_normals)
        memset(moved.nrm, 0, sizeof moved.nrm);
    {
        stin_mesh_desc md;
        memset(&md, 0, sizeof md);
        md.positions = moved.pos;
        md.normals = with_normals ? moved.nrm : NULL;
        md.uvs = with_uvs ? b.uv : NULL;
        md.vertex_count = BOX_VERTICES;
        md.indices = box_idx;
        md.index_count = BOX_INDICES;
        md.subdivide = subdivide;
        assert_int_equal(stin_create_mesh(ctx, &md, &fresh), STIN_OK);
    }
    s = slot_of(m);
    f = slot_of(fresh);
    assert_int_equal(s->vertex_count, f->vertex_count);
    assert_memory_equal(ctx->vertices + s->first_vertex, ctx->vertices + f->first_vertex,
                        sizeof(stin__vertex) * s->vertex_count);
    assert_memory_equal(&s->info, &f->info, sizeof s->info);
    assert_memory_equal(ctx->adjacency + 3 * s->first_triangle,
                        ctx->adjacency + 3 * f->first_triangle,
                        3 * sizeof(uint32_t) * s->triangle_count);
    assert_true(s->smooth == f->smooth && s->edge == f->edge && s->uv_edge == f->uv_edge);
    stin_destroy_mesh(ctx, m);
    stin_destroy_mesh(ctx, fresh);
}

static void test_equals_destroy_and_create(void **state)
{
    (void)state;
    check_equals_create(0, 1, 1);
    check_equals_create(0, 0, 0);
    check_equals_create(0, 1, 0);
    check_equals_create(1, 1, 1);
    check_equals_create(2, 0, 1);
}

#define TEST(f) cmocka_unit_test_setup_teardown(f, setup, teardown)
int main(void)
{
    const struct CMUnitTest tests[] = {
        TEST(test_refusals_leave_the_mesh),
        TEST(test_tangents_refused_for_subdivided),
        TEST(test_uploads_into_the_same_buffer),
        TEST(test_no_buffers_on_gl11),
        TEST(test_welds_follow_the_first_vertex),
        TEST(test_convex_follows_the_shape),
        TEST(test_given_tangents_are_kept),
        TEST(test_equals_destroy_and_create),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
