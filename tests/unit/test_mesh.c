/* SPDX-License-Identifier: MIT */
/* Meshes on the fake GL: validation, adjacency and manifold status,
 * tangents and default normals, capacities, handles, and range reuse. */
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

#define NONE UINT32_MAX

static float absf(float x) { return x < 0.0f ? -x : x; }

/* ---- context ------------------------------------------------------------- */
static fake_log log_;
static void *block;
static stin_context *ctx;

static void create_context(uint32_t max_meshes, uint32_t max_vertices, uint32_t max_triangles,
                           uint32_t max_mesh_triangles)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    stin_desc d;
    size_t bytes;
    fake_gl_reset(&cfg);
    memset(&log_, 0, sizeof log_);
    memset(&d, 0, sizeof d);
    d.get_proc_address = fake_gl_get_proc;
    d.log = fake_log_fn;
    d.log_user = &log_;
    d.max_meshes = max_meshes;
    d.max_vertices = max_vertices;
    d.max_triangles = max_triangles;
    d.max_mesh_triangles = max_mesh_triangles;
    d.max_texture_bytes = 1024;
    /* the GL objects counted here are the caller's meshes' (goldfeather's
     * near-plane cap, stin's own mesh, is counted in test_context) */
    d.techniques[STIN_FEATURE_CSG] = STIN_TECH_CSG_OFF;
    bytes = stin_memory_size(&d);
    assert_true(bytes > 0);
    block = malloc(bytes);
    assert_non_null(block);
    assert_int_equal(stin_create(&d, block, bytes, &ctx), STIN_OK);
}

static int setup(void **state)
{
    (void)state;
    create_context(16, 1024, 1024, 256);
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

static void reset_log(void) { memset(&log_, 0, sizeof log_); }

static stin_mesh_desc mesh_desc(const float *pos, uint32_t nv, const uint32_t *idx, uint32_t ni)
{
    stin_mesh_desc md;
    memset(&md, 0, sizeof md);
    md.positions = pos;
    md.vertex_count = nv;
    md.indices = idx;
    md.index_count = ni;
    return md;
}

static stin_result create(const stin_mesh_desc *md, stin_mesh *m) { return stin_create_mesh(ctx, md, m); }

static stin_mesh_info info_of(stin_mesh m)
{
    stin_mesh_info info;
    assert_int_equal(stin_query_mesh_info(ctx, m, &info), STIN_OK);
    return info;
}

static void neighbours(stin_mesh m, uint32_t t, uint32_t out[3])
{
    assert_int_equal(stin_query_mesh_adjacency(ctx, m, t, out), STIN_OK);
}

static const float *vertex_normal(stin_mesh m, uint32_t v)
{
    const stin__mesh_slot *s = stin__mesh_lookup(ctx, m, NULL);
    assert_non_null(s);
    return ctx->vertices[s->first_vertex + v].normal;
}

static const float quad_pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
static const uint32_t quad_idx[] = {0, 1, 2, 0, 2, 3};

/* ---- validation ----------------------------------------------------------- */
static void test_index_out_of_range(void **state)
{
    const uint32_t idx[] = {0, 1, 2, 0, 2, 4};
    stin_mesh_desc md = mesh_desc(quad_pos, 4, idx, 6);
    stin_mesh m = {1234};
    (void)state;
    assert_int_equal(create(&md, &m), STIN_ERROR_INVALID_MESH);
    assert_int_equal(m.id, 0);
    assert_int_equal(log_.items[STIN_LOG_MESH_INDEX_RANGE], 1);
    assert_true(fake_log_has(&log_, STIN_LOG_MESH_INDEX_RANGE, "index 5"));
    assert_int_equal(fake_gl.buffers_created, 0);
}

static void test_non_finite_values(void **state)
{
    float pos[12], nrm[12], uv[8];
    stin_mesh_desc md;
    stin_mesh m;
    int i;
    (void)state;
    memcpy(pos, quad_pos, sizeof pos);
    md = mesh_desc(pos, 4, quad_idx, 6);
    pos[7] = NAN;
    assert_int_equal(create(&md, &m), STIN_ERROR_INVALID_MESH);
    assert_true(fake_log_has(&log_, STIN_LOG_MESH_NOT_FINITE, "position of vertex 2"));

    memcpy(pos, quad_pos, sizeof pos);
    for (i = 0; i < 8; i++)
        uv[i] = 0.5f;
    uv[3] = INFINITY;
    md.uvs = uv;
    assert_int_equal(create(&md, &m), STIN_ERROR_INVALID_MESH);
    assert_true(fake_log_has(&log_, STIN_LOG_MESH_NOT_FINITE, "uv of vertex 1"));

    md.uvs = NULL;
    for (i = 0; i < 12; i++)
        nrm[i] = i % 3 == 2 ? 1.0f : 0.0f;
    nrm[0] = -INFINITY;
    md.normals = nrm;
    assert_int_equal(create(&md, &m), STIN_ERROR_INVALID_MESH);
    assert_true(fake_log_has(&log_, STIN_LOG_MESH_NOT_FINITE, "normal of vertex 0"));
    assert_int_equal(log_.items[STIN_LOG_MESH_NOT_FINITE], 3);
    assert_int_equal(fake_gl.buffers_created, 0);
}

static void test_bad_arguments(void **state)
{
    stin_mesh_desc md = mesh_desc(quad_pos, 4, quad_idx, 5);
    stin_mesh m;
    (void)state;
    assert_int_equal(create(&md, &m), STIN_ERROR_INVALID_ARGUMENT); /* not a multiple of 3 */
    md.index_count = 0;
    assert_int_equal(create(&md, &m), STIN_ERROR_INVALID_ARGUMENT);
    md = mesh_desc(NULL, 4, quad_idx, 6);
    assert_int_equal(create(&md, &m), STIN_ERROR_INVALID_ARGUMENT);
    md = mesh_desc(quad_pos, 0, quad_idx, 6);
    assert_int_equal(create(&md, &m), STIN_ERROR_INVALID_ARGUMENT);
    md = mesh_desc(quad_pos, 4, NULL, 6);
    assert_int_equal(create(&md, &m), STIN_ERROR_INVALID_ARGUMENT);
    assert_int_equal(log_.items[STIN_LOG_BAD_ARGUMENT], 5);
    md = mesh_desc(quad_pos, 4, quad_idx, 6);
    assert_int_equal(stin_create_mesh(NULL, &md, &m), STIN_ERROR_INVALID_ARGUMENT);
    assert_int_equal(stin_create_mesh(ctx, NULL, &m), STIN_ERROR_INVALID_ARGUMENT);
    assert_int_equal(stin_create_mesh(ctx, &md, NULL), STIN_ERROR_INVALID_ARGUMENT);
}

static void test_all_degenerate_is_invalid(void **state)
{
    const float pos[] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 5, 0, 0};
    const uint32_t idx[] = {0, 1, 2, 0, 0, 3, 3, 3, 3};
    stin_mesh_desc md = mesh_desc(pos, 4, idx, 9);
    stin_mesh m;
    (void)state;
    assert_int_equal(create(&md, &m), STIN_ERROR_INVALID_MESH);
    assert_int_equal(log_.items[STIN_LOG_MESH_DEGENERATE], 1);
    assert_true(fake_log_has(&log_, STIN_LOG_MESH_DEGENERATE, "3"));
}

static void test_some_degenerate_are_dropped(void **state)
{
    const float pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 2, 0};
    /* quad, a collinear triangle (0,2,4) and a repeated index */
    const uint32_t idx[] = {0, 1, 2, 0, 2, 4, 0, 2, 3, 1, 1, 3};
    stin_mesh_desc md = mesh_desc(pos, 5, idx, 12);
    stin_mesh_info info;
    stin_mesh m;
    (void)state;
    assert_int_equal(create(&md, &m), STIN_OK);
    info = info_of(m);
    assert_int_equal(info.triangle_count, 2);
    assert_int_equal(info.degenerate_dropped, 2);
    assert_int_equal(info.vertex_count, 5);
    assert_int_equal(log_.items[STIN_LOG_MESH_DEGENERATE], 1);
    assert_int_equal(info.open_edges, 4); /* the kept quad */
    /* The bounds cover every vertex given, used or not. */
    assert_true(info.bounds_max[0] == 2.0f && info.bounds_max[1] == 2.0f);
}

/* ---- adjacency ------------------------------------------------------------ */
/* 24 vertices (4 per face, split normals), 12 triangles, outward CCW. */
static void cube(float pos[72], float nrm[72], uint32_t idx[36])
{
    int face, c;
    for (face = 0; face < 6; face++) {
        int a = face / 2;
        float s = face % 2 ? -1.0f : 1.0f;
        int u = s > 0 ? (a + 1) % 3 : (a + 2) % 3, v = s > 0 ? (a + 2) % 3 : (a + 1) % 3;
        static const float corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (c = 0; c < 4; c++) {
            float *p = pos + 3 * (4 * face + c), *n = nrm + 3 * (4 * face + c);
            p[0] = p[1] = p[2] = 0.0f;
            n[0] = n[1] = n[2] = 0.0f;
            p[a] = s;
            p[u] = corner[c][0];
            p[v] = corner[c][1];
            n[a] = s;
        }
        idx[6 * face + 0] = 4u * face;
        idx[6 * face + 1] = 4u * face + 1;
        idx[6 * face + 2] = 4u * face + 2;
        idx[6 * face + 3] = 4u * face;
        idx[6 * face + 4] = 4u * face + 2;
        idx[6 * face + 5] = 4u * face + 3;
    }
}

static int same_position(const float *pos, uint32_t a, uint32_t b)
{
    return pos[3 * a] == pos[3 * b] && pos[3 * a + 1] == pos[3 * b + 1] &&
           pos[3 * a + 2] == pos[3 * b + 2];
}

/* Neighbour n of t across edge e shares that edge's two positions, reversed,
 * and names t back across that edge. */
static void assert_neighbour_consistent(stin_mesh m, const float *pos, const uint32_t *idx,
                                        uint32_t t, uint32_t e, uint32_t n)
{
    uint32_t back[3], a = idx[3 * t + e], b = idx[3 * t + (e + 1) % 3], k, found = 0;
    neighbours(m, n, back);
    for (k = 0; k < 3; k++) {
        uint32_t na = idx[3 * n + k], nb = idx[3 * n + (k + 1) % 3];
        if (same_position(pos, na, b) && same_position(pos, nb, a)) {
            assert_int_equal(back[k], t);
            found = 1;
        }
    }
    assert_true(found);
}

static void test_closed_cube_with_split_normals(void **state)
{
    float pos[72], nrm[72];
    uint32_t idx[36], t, e, nb[3];
    stin_mesh_desc md;
    stin_mesh_info info;
    stin_mesh m;
    (void)state;
    cube(pos, nrm, idx);
    md = mesh_desc(pos, 24, idx, 36);
    md.normals = nrm;
    assert_int_equal(create(&md, &m), STIN_OK);
    info = info_of(m);
    assert_int_equal(info.vertex_count, 24);
    assert_int_equal(info.triangle_count, 12);
    assert_int_equal(info.open_edges, 0);
    assert_int_equal(info.nonmanifold_edges, 0);
    assert_int_equal(info.closed_manifold, 1);
    assert_true(info.bounds_min[0] == -1.0f && info.bounds_max[2] == 1.0f);
    assert_int_equal(log_.items[STIN_LOG_MESH_NOT_MANIFOLD], 0);
    for (t = 0; t < 12; t++) {
        neighbours(m, t, nb);
        for (e = 0; e < 3; e++) {
            assert_true(nb[e] < 12);
            assert_true(nb[e] != t);
            assert_neighbour_consistent(m, pos, idx, t, e, nb[e]);
        }
    }
    assert_int_equal(stin_query_mesh_adjacency(ctx, m, 12, nb), STIN_ERROR_INVALID_ARGUMENT);
}

/* x moved by `ulps` units in the last place (no libm in this test). */
static float ulp_step(float x, int ulps)
{
    union { float f; int32_t i; } u;
    u.f = x;
    u.i += x < 0.0f ? -ulps : ulps;
    return u.f;
}

/* The cube's copies on faces 0-2 moved a few ulps, as exporters leave seams
 * and poles: welded by default (closed, positions snapped onto the first
 * copy), open with bit-equal welding, open when a face is really apart. */
static void test_weld_tolerance_closes_seams(void **state)
{
    float pos[72], nrm[72];
    uint32_t idx[36], v;
    int k;
    stin_mesh_desc md;
    stin_mesh_info info;
    stin_mesh m;
    const stin__vertex *stored;
    (void)state;
    cube(pos, nrm, idx);
    for (v = 0; v < 12; v++)
        for (k = 0; k < 3; k++)
            pos[3 * v + k] = ulp_step(pos[3 * v + k], 1 + (int)(v % 3));
    md = mesh_desc(pos, 24, idx, 36);
    assert_int_equal(create(&md, &m), STIN_OK);
    info = info_of(m);
    assert_int_equal(info.closed_manifold, 1);
    assert_int_equal(info.open_edges, 0);
    {
        uint32_t moved = 0, w; /* copies that differ from their corner's first copy */
        for (v = 0; v < 24; v++)
            for (w = 0; w < v; w++)
                if (absf(pos[3 * v] - pos[3 * w]) < 1e-4f && absf(pos[3 * v + 1] - pos[3 * w + 1]) < 1e-4f &&
                    absf(pos[3 * v + 2] - pos[3 * w + 2]) < 1e-4f) {
                    moved += memcmp(pos + 3 * v, pos + 3 * w, 3 * sizeof(float)) != 0;
                    break;
                }
        assert_true(moved > 0);
        assert_int_equal(info.welded_vertices, moved);
    }
    stored = ctx->vertices + stin__mesh_lookup(ctx, m, NULL)->first_vertex;
    for (v = 0; v < 24; v++) {
        uint32_t w;
        for (w = 0; w < 24; w++) /* every copy of a corner holds one position now */
            if (absf(stored[v].position[0] - stored[w].position[0]) < 1e-4f &&
                absf(stored[v].position[1] - stored[w].position[1]) < 1e-4f &&
                absf(stored[v].position[2] - stored[w].position[2]) < 1e-4f)
                assert_memory_equal(stored[v].position, stored[w].position, 3 * sizeof(float));
    }
    md.weld_tolerance = -1.0f; /* bit-equal only */
    assert_int_equal(create(&md, &m), STIN_OK);
    info = info_of(m);
    assert_int_equal(info.closed_manifold, 0);
    assert_true(info.open_edges > 0);
    assert_int_equal(info.welded_vertices, 0);
    /* a face 1/1000 of the cube away stays apart at the default tolerance */
    cube(pos, nrm, idx);
    for (v = 0; v < 4; v++)
        pos[3 * v] += 0.002f;
    md = mesh_desc(pos, 24, idx, 36);
    assert_int_equal(create(&md, &m), STIN_OK);
    assert_int_equal(info_of(m).open_edges, 8); /* its 4 edges and its neighbours 4 */
    md.weld_tolerance = 0.01f; /* unless the caller says so */
    assert_int_equal(create(&md, &m), STIN_OK);
    assert_int_equal(info_of(m).closed_manifold, 1);
    md.weld_tolerance = NAN;
    assert_int_equal(create(&md, &m), STIN_ERROR_INVALID_ARGUMENT);
}

/* -0 and +0 are the same position. */
static void test_negative_zero_welds(void **state)
{
    float pos[72], nrm[72];
    uint32_t idx[36], v;
    stin_mesh_desc md;
    stin_mesh m;
    (void)state;
    cube(pos, nrm, idx);
    for (v = 0; v < 72; v++)
        pos[v] *= 0.5f;
    for (v = 0; v < 72; v++)
        pos[v] -= 0.5f; /* corners at -1 and 0; flip the sign of zeros of odd vertices */
    for (v = 1; v < 24; v += 2) {
        int k;
        for (k = 0; k < 3; k++)
            if (pos[3 * v + k] == 0.0f)
                pos[3 * v + k] = -0.0f;
    }
    md = mesh_desc(pos, 24, idx, 36);
    md.normals = nrm;
    assert_int_equal(create(&md, &m), STIN_OK);
    assert_int_equal(info_of(m).closed_manifold, 1);
}

static void test_open_quad(void **state)
{
    stin_mesh_desc md = mesh_desc(quad_pos, 4, quad_idx, 6);
    stin_mesh_info info;
    uint32_t nb[3];
    stin_mesh m;
    (void)state;
    assert_int_equal(create(&md, &m), STIN_OK);
    info = info_of(m);
    assert_int_equal(info.open_edges, 4);
    assert_int_equal(info.nonmanifold_edges, 0);
    assert_int_equal(info.closed_manifold, 0);
    neighbours(m, 0, nb);
    assert_int_equal(nb[0], NONE);
    assert_int_equal(nb[1], NONE);
    assert_int_equal(nb[2], 1);
    neighbours(m, 1, nb);
    assert_int_equal(nb[0], 0);
    assert_int_equal(nb[1], NONE);
    assert_int_equal(nb[2], NONE);
    assert_int_equal(log_.items[STIN_LOG_MESH_NOT_MANIFOLD], 1);
}

static void test_tetrahedron(void **state)
{
    const float pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const uint32_t idx[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    stin_mesh_desc md = mesh_desc(pos, 4, idx, 12);
    uint32_t t, nb[3];
    stin_mesh m;
    (void)state;
    assert_int_equal(create(&md, &m), STIN_OK);
    assert_int_equal(info_of(m).closed_manifold, 1);
    for (t = 0; t < 4; t++) {
        neighbours(m, t, nb);
        /* each face touches the three others, once each */
        assert_true(nb[0] != t && nb[1] != t && nb[2] != t);
        assert_true(nb[0] != nb[1] && nb[1] != nb[2] && nb[0] != nb[2]);
        assert_true(nb[0] < 4 && nb[1] < 4 && nb[2] < 4);
        assert_neighbour_consistent(m, pos, idx, t, 0, nb[0]);
    }
}

static void test_three_triangles_on_one_edge(void **state)
{
    const float pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
    const uint32_t idx[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    stin_mesh_desc md = mesh_desc(pos, 5, idx, 9);
    stin_mesh_info info;
    uint32_t nb[3];
    stin_mesh m;
    (void)state;
    assert_int_equal(create(&md, &m), STIN_OK);
    info = info_of(m);
    assert_int_equal(info.nonmanifold_edges, 1);
    assert_int_equal(info.open_edges, 6);
    assert_int_equal(info.closed_manifold, 0);
    neighbours(m, 0, nb);
    assert_int_equal(nb[0], NONE);
    neighbours(m, 1, nb);
    assert_int_equal(nb[0], NONE);
    assert_true(fake_log_has(&log_, STIN_LOG_MESH_NOT_MANIFOLD, "1 non-manifold"));
}

static void test_inconsistently_oriented_pair(void **state)
{
    const float pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0};
    const uint32_t idx[] = {0, 1, 2, 0, 1, 3}; /* both run 0 -> 1 along the shared edge */
    stin_mesh_desc md = mesh_desc(pos, 4, idx, 6);
    stin_mesh_info info;
    uint32_t nb[3];
    stin_mesh m;
    (void)state;
    assert_int_equal(create(&md, &m), STIN_OK);
    info = info_of(m);
    assert_int_equal(info.nonmanifold_edges, 1);
    assert_int_equal(info.open_edges, 4);
    assert_int_equal(info.closed_manifold, 0);
    neighbours(m, 0, nb);
    assert_int_equal(nb[0], NONE);
    neighbours(m, 1, nb);
    assert_int_equal(nb[0], NONE);
}

/* ---- tangents and normals ---------------------------------------------------- */
static void tangent(stin_mesh m, uint32_t v, float t[4])
{
    assert_int_equal(stin_query_mesh_tangent(ctx, m, v, t), STIN_OK);
}

static void assert_unit_and_orthogonal(const float t[4], const float n[3])
{
    float len2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
    assert_true(absf(len2 - 1.0f) < 2e-5f);
    assert_true(absf(t[0] * n[0] + t[1] * n[1] + t[2] * n[2]) < 1e-5f);
    assert_true(t[3] == 1.0f || t[3] == -1.0f);
}

static void test_tangent_follows_u(void **state)
{
    const float uv[] = {0, 0, 1, 0, 1, 1, 0, 1};
    stin_mesh_desc md = mesh_desc(quad_pos, 4, quad_idx, 6);
    float t[4];
    uint32_t v;
    stin_mesh m;
    (void)state;
    md.uvs = uv;
    assert_int_equal(create(&md, &m), STIN_OK);
    for (v = 0; v < 4; v++) {
        tangent(m, v, t);
        assert_true(absf(t[0] - 1.0f) < 1e-5f);
        assert_true(absf(t[1]) < 1e-5f && absf(t[2]) < 1e-5f);
        assert_true(t[3] == 1.0f);
        assert_unit_and_orthogonal(t, vertex_normal(m, v));
    }
    assert_int_equal(stin_query_mesh_tangent(ctx, m, 4, t), STIN_ERROR_INVALID_ARGUMENT);
}

static void test_mirrored_uvs_flip_handedness(void **state)
{
    const float uv[] = {1, 0, 0, 0, 0, 1, 1, 1};
    stin_mesh_desc md = mesh_desc(quad_pos, 4, quad_idx, 6);
    float t[4];
    uint32_t v;
    stin_mesh m;
    (void)state;
    md.uvs = uv;
    assert_int_equal(create(&md, &m), STIN_OK);
    for (v = 0; v < 4; v++) {
        tangent(m, v, t);
        assert_true(absf(t[0] + 1.0f) < 1e-5f);
        assert_true(t[3] == -1.0f);
        assert_unit_and_orthogonal(t, vertex_normal(m, v));
    }
}

/* A quad facing +y with uv = (x, -z) and a tilted normal: Gram-Schmidt keeps
 * the tangent orthogonal to the given normal. */
static void test_tangent_is_orthogonalised_against_the_normal(void **state)
{
    const float pos[] = {0, 0, 0, 1, 0, 0, 1, 0, -1, 0, 0, -1};
    const float uv[] = {0, 0, 1, 0, 1, 1, 0, 1};
    const float nrm[] = {0.3f, 1, 0, 0.3f, 1, 0, 0.3f, 1, 0, 0.3f, 1, 0};
    stin_mesh_desc md = mesh_desc(pos, 4, quad_idx, 6);
    const float *n;
    float t[4];
    stin_mesh m;
    (void)state;
    md.uvs = uv;
    md.normals = nrm;
    assert_int_equal(create(&md, &m), STIN_OK);
    n = vertex_normal(m, 0);
    assert_true(absf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0f) < 1e-5f); /* normalised */
    tangent(m, 0, t);
    assert_unit_and_orthogonal(t, n);
    assert_true(t[0] > 0.9f);
    assert_true(t[3] == 1.0f);
}

static void test_no_uvs_gives_some_perpendicular_tangent(void **state)
{
    stin_mesh_desc md = mesh_desc(quad_pos, 4, quad_idx, 6);
    float t[4];
    stin_mesh m;
    (void)state;
    assert_int_equal(create(&md, &m), STIN_OK);
    tangent(m, 2, t);
    assert_unit_and_orthogonal(t, vertex_normal(m, 2));
}

/* Octahedron: every vertex is in four equal faces, so its area-weighted
 * normal points away from the centre. */
static void octahedron(float pos[18], uint32_t idx[24])
{
    int v, f = 0, sx, sy, sz;
    for (v = 0; v < 18; v++)
        pos[v] = 0.0f;
    for (v = 0; v < 6; v++)
        pos[3 * v + v / 2] = v % 2 ? -1.0f : 1.0f; /* +x -x +y -y +z -z */
    for (sx = 0; sx < 2; sx++)
        for (sy = 0; sy < 2; sy++)
            for (sz = 0; sz < 2; sz++) {
                uint32_t a = (uint32_t)sx, b = 2u + (uint32_t)sy, c = 4u + (uint32_t)sz;
                int outward = (sx + sy + sz) % 2 == 0; /* even number of negative axes */
                idx[f++] = a;
                idx[f++] = outward ? b : c;
                idx[f++] = outward ? c : b;
            }
}

/* Subdivision at creation: per level V + E vertices and 4 T triangles (E by
 * vertex indices: the cube's split faces share no index, so its 24-vertex
 * faces stay apart but welded), still closed; midpoints on the flat
 * faces, uv means; too many levels for the capacities is CAPACITY, more
 * than 6 INVALID_ARGUMENT. */
static void test_subdivide(void **state)
{
    float pos[72], nrm[72], uv[48];
    uint32_t idx[36], i;
    stin_mesh_desc md;
    stin_mesh_info info;
    stin_mesh m;
    (void)state;
    cube(pos, nrm, idx);
    for (i = 0; i < 24; i++) {
        uv[2 * i] = (float)(i % 2);
        uv[2 * i + 1] = (float)((i / 2) % 2);
    }
    md = mesh_desc(pos, 24, idx, 36);
    md.normals = nrm;
    md.uvs = uv;
    md.subdivide = 1;
    assert_int_equal(create(&md, &m), STIN_OK);
    info = info_of(m);
    /* 6 faces of 4 vertices, 5 edges each (4 sides and a diagonal) */
    assert_int_equal(info.vertex_count, 24 + 30);
    assert_int_equal(info.triangle_count, 48);
    assert_int_equal(info.closed_manifold, 1);
    assert_true(info.bounds_min[0] == -1.0f && info.bounds_max[1] == 1.0f);
    md.subdivide = 2; /* 54 + E1, E1 = 2 * 30 + 3 * 12 */
    assert_int_equal(create(&md, &m), STIN_OK);
    info = info_of(m);
    assert_int_equal(info.vertex_count, 54 + 96);
    assert_int_equal(info.triangle_count, 192);
    assert_int_equal(info.closed_manifold, 1);
    md.subdivide = 3; /* 768 triangles: over max_mesh_triangles (256) */
    assert_int_equal(create(&md, &m), STIN_ERROR_CAPACITY);
    md.subdivide = 7;
    assert_int_equal(create(&md, &m), STIN_ERROR_INVALID_ARGUMENT);
}

static void test_default_normals(void **state)
{
    float pos[18];
    uint32_t idx[24], v;
    stin_mesh_desc md = mesh_desc(quad_pos, 4, quad_idx, 6);
    const float *n;
    stin_mesh m;
    int k;
    (void)state;
    assert_int_equal(create(&md, &m), STIN_OK);
    for (v = 0; v < 4; v++) {
        n = vertex_normal(m, v);
        assert_true(absf(n[0]) < 1e-6f && absf(n[1]) < 1e-6f && absf(n[2] - 1.0f) < 1e-6f);
    }
    octahedron(pos, idx);
    md = mesh_desc(pos, 6, idx, 24);
    assert_int_equal(create(&md, &m), STIN_OK);
    assert_int_equal(info_of(m).closed_manifold, 1);
    for (v = 0; v < 6; v++) {
        n = vertex_normal(m, v);
        for (k = 0; k < 3; k++)
            assert_true(absf(n[k] - pos[3 * v + k]) < 1e-5f);
    }
}

/* A given zero normal is replaced by the face-derived one; others are normalised. */
static void test_given_normals_are_normalised(void **state)
{
    const float nrm[] = {0, 0, 5, 0, 0, 0, 0, 0, 2, 0, 0, 1};
    stin_mesh_desc md = mesh_desc(quad_pos, 4, quad_idx, 6);
    stin_mesh m;
    uint32_t v;
    (void)state;
    md.normals = nrm;
    assert_int_equal(create(&md, &m), STIN_OK);
    for (v = 0; v < 4; v++)
        assert_true(absf(vertex_normal(m, v)[2] - 1.0f) < 1e-6f);
}

/* ---- capacities ------------------------------------------------------------- */
static void test_max_meshes_full(void **state)
{
    stin_mesh_desc md = mesh_desc(quad_pos, 4, quad_idx, 6);
    stin_mesh a, b, c;
    (void)state;
    teardown(NULL);
    create_context(2, 1024, 1024, 256);
    assert_int_equal(create(&md, &a), STIN_OK);
    assert_int_equal(create(&md, &b), STIN_OK);
    assert_int_equal(create(&md, &c), STIN_ERROR_CAPACITY);
    assert_int_equal(c.id, 0);
    assert_int_equal(log_.items[STIN_LOG_POOL_FULL], 1);
    assert_true(fake_log_has(&log_, STIN_LOG_POOL_FULL, "max_meshes"));
    assert_int_equal(fake_gl.buffers_created, 4);
    stin_destroy_mesh(ctx, a);
    assert_int_equal(create(&md, &c), STIN_OK);
}

static void test_max_mesh_triangles_exceeded(void **state)
{
    float pos[72], nrm[72];
    uint32_t idx[36];
    stin_mesh_desc md;
    stin_mesh m;
    (void)state;
    teardown(NULL);
    create_context(4, 1024, 1024, 11);
    cube(pos, nrm, idx);
    md = mesh_desc(pos, 24, idx, 36);
    assert_int_equal(create(&md, &m), STIN_ERROR_CAPACITY);
    assert_true(fake_log_has(&log_, STIN_LOG_POOL_FULL, "max_mesh_triangles"));
    md.index_count = 33; /* 11 triangles fit */
    assert_int_equal(create(&md, &m), STIN_OK);
    assert_int_equal(info_of(m).triangle_count, 11);
}

static void test_max_vertices_and_triangles_exceeded(void **state)
{
    stin_mesh_desc md = mesh_desc(quad_pos, 4, quad_idx, 6);
    stin_mesh a, b;
    (void)state;
    teardown(NULL);
    create_context(8, 6, 100, 2); /* room for one quad's vertices */
    assert_int_equal(create(&md, &a), STIN_OK);
    assert_int_equal(create(&md, &b), STIN_ERROR_CAPACITY);
    assert_true(fake_log_has(&log_, STIN_LOG_POOL_FULL, "max_vertices"));
    teardown(NULL);
    create_context(8, 100, 3, 2); /* room for one quad's triangles */
    assert_int_equal(create(&md, &a), STIN_OK);
    assert_int_equal(create(&md, &b), STIN_ERROR_CAPACITY);
    assert_true(fake_log_has(&log_, STIN_LOG_POOL_FULL, "max_triangles"));
    /* The vertex range taken before the triangle range failed was given back. */
    assert_int_equal(ctx->vertex_ranges.used_count, 1);
    assert_int_equal(fake_gl.buffers_created, 2);
}

/* Stores sized for exactly two quads: create/destroy/create succeeds at the limit. */
static void test_ranges_are_reused_after_destroy(void **state)
{
    const float pos8[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0, 0, 3, 0, 0, 3, 1, 0, 2, 1, 0};
    const uint32_t idx8[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    stin_mesh_desc quad = mesh_desc(quad_pos, 4, quad_idx, 6), two = mesh_desc(pos8, 8, idx8, 12);
    stin_mesh a, b, c;
    int round;
    (void)state;
    teardown(NULL);
    create_context(4, 8, 4, 4);
    for (round = 0; round < 3; round++) {
        assert_int_equal(create(&quad, &a), STIN_OK);
        assert_int_equal(create(&quad, &b), STIN_OK);
        assert_int_equal(create(&quad, &c), STIN_ERROR_CAPACITY);
        stin_destroy_mesh(ctx, a);
        assert_int_equal(create(&two, &c), STIN_ERROR_CAPACITY); /* 4 + 4 free, not contiguous */
        assert_int_equal(create(&quad, &c), STIN_OK);           /* the hole a left */
        stin_destroy_mesh(ctx, b);
        stin_destroy_mesh(ctx, c);
        assert_int_equal(create(&two, &a), STIN_OK);
        stin_destroy_mesh(ctx, a);
    }
    assert_int_equal(ctx->vertex_ranges.used_count, 0);
    assert_int_equal(ctx->triangle_ranges.used_count, 0);
    assert_int_equal(fake_gl.buffers_created, fake_gl.buffers_deleted);
}

static void test_range_allocator_first_fit(void **state)
{
    stin__range store[4];
    stin__range_alloc r;
    uint32_t a, b, c, d;
    (void)state;
    stin__range_init(&r, store, 3, 10);
    assert_true(stin__range_take(&r, 4, &a));
    assert_true(stin__range_take(&r, 3, &b));
    assert_true(stin__range_take(&r, 3, &c));
    assert_int_equal(a, 0);
    assert_int_equal(b, 4);
    assert_int_equal(c, 7);
    assert_false(stin__range_take(&r, 1, &d)); /* full, and out of range records */
    stin__range_give(&r, b);
    assert_false(stin__range_take(&r, 4, &d));
    assert_true(stin__range_take(&r, 2, &d));
    assert_int_equal(d, 4);
    assert_false(stin__range_take(&r, 0, &d));
    stin__range_give(&r, 12345); /* unknown offset: no effect */
    assert_int_equal(r.used_count, 3);
}

/* ---- handles ----------------------------------------------------------------- */
static void test_destroyed_handle_is_stale(void **state)
{
    stin_mesh_desc md = mesh_desc(quad_pos, 4, quad_idx, 6);
    stin_mesh_info info;
    stin_mesh a, b;
    uint32_t nb[3];
    float t[4];
    (void)state;
    assert_int_equal(create(&md, &a), STIN_OK);
    assert_true(a.id != 0);
    stin_destroy_mesh(ctx, a);
    assert_int_equal(fake_gl.buffers_deleted, 2);
    assert_int_equal(stin_query_mesh_info(ctx, a, &info), STIN_ERROR_INVALID_HANDLE);
    assert_int_equal(stin_query_mesh_adjacency(ctx, a, 0, nb), STIN_ERROR_INVALID_HANDLE);
    assert_int_equal(stin_query_mesh_tangent(ctx, a, 0, t), STIN_ERROR_INVALID_HANDLE);
    reset_log();
    stin_destroy_mesh(ctx, a); /* twice: logged, nothing deleted */
    assert_int_equal(log_.items[STIN_LOG_BAD_HANDLE], 1);
    assert_int_equal(fake_gl.buffers_deleted, 2);

    assert_int_equal(create(&md, &b), STIN_OK); /* reuses the slot */
    assert_int_equal(b.id & 0x1fu, a.id & 0x1fu); /* slot + 1: 5 bits for 16 meshes */
    assert_true(b.id != a.id);
    assert_int_equal(stin_query_mesh_info(ctx, a, &info), STIN_ERROR_INVALID_HANDLE);
    assert_int_equal(stin_query_mesh_info(ctx, b, &info), STIN_OK);
}

static void test_foreign_handles(void **state)
{
    stin_mesh_desc md = mesh_desc(quad_pos, 4, quad_idx, 6);
    stin_mesh_info info;
    stin_mesh a, zero = {0}, far_slot;
    (void)state;
    assert_int_equal(create(&md, &a), STIN_OK);
    far_slot.id = (a.id & ~0x1fu) | 17u; /* slot 16 of 16 meshes */
    assert_int_equal(stin_query_mesh_info(ctx, zero, &info), STIN_ERROR_INVALID_HANDLE);
    assert_int_equal(stin_query_mesh_info(ctx, far_slot, &info), STIN_ERROR_INVALID_HANDLE);
    assert_int_equal(stin_query_mesh_info(NULL, a, &info), STIN_ERROR_INVALID_HANDLE);
    assert_int_equal(stin_query_mesh_info(ctx, a, NULL), STIN_ERROR_INVALID_ARGUMENT);
    reset_log();
    stin_destroy_mesh(ctx, zero); /* the zero handle is silently nothing */
    assert_int_equal(log_.items[STIN_LOG_BAD_HANDLE], 0);
    stin_destroy_mesh(NULL, a);
    assert_int_equal(stin_query_mesh_info(ctx, a, &info), STIN_OK);
}

#define TEST(f) cmocka_unit_test_setup_teardown(f, setup, teardown)

int main(void)
{
    const struct CMUnitTest tests[] = {
        TEST(test_index_out_of_range),
        TEST(test_non_finite_values),
        TEST(test_bad_arguments),
        TEST(test_all_degenerate_is_invalid),
        TEST(test_some_degenerate_are_dropped),
        TEST(test_closed_cube_with_split_normals),
        TEST(test_weld_tolerance_closes_seams),
        TEST(test_negative_zero_welds),
        TEST(test_open_quad),
        TEST(test_tetrahedron),
        TEST(test_three_triangles_on_one_edge),
        TEST(test_inconsistently_oriented_pair),
        TEST(test_tangent_follows_u),
        TEST(test_mirrored_uvs_flip_handedness),
        TEST(test_tangent_is_orthogonalised_against_the_normal),
        TEST(test_no_uvs_gives_some_perpendicular_tangent),
        TEST(test_default_normals),
        TEST(test_subdivide),
        TEST(test_given_normals_are_normalised),
        TEST(test_max_meshes_full),
        TEST(test_max_mesh_triangles_exceeded),
        TEST(test_max_vertices_and_triangles_exceeded),
        TEST(test_ranges_are_reused_after_destroy),
        TEST(test_range_allocator_first_fit),
        TEST(test_destroyed_handle_is_stale),
        TEST(test_foreign_handles),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
