/* SPDX-License-Identifier: MIT */
/* DOT3 bump mapping on the fixed-function tier (src/surface/dot3.c):
 * tangent-space light vectors against hand-computed values, the
 * normalisation cube map against GL's face selection, the selection rule
 * (fixed-function lighting only), and the passes and GL objects on the fake
 * GL. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "fake_gl.h"
#include "internal.h"

#define BIT(c) STIN_CAP_BIT(STIN_CAP_##c)
#define GL11_BITS (BIT(STENCIL) | BIT(FIXED_FUNCTION))
#define GL13_BITS                                                                         \
    (GL11_BITS | BIT(MULTITEXTURE) | BIT(TEXTURE_ENV_COMBINE) | BIT(TEXTURE_ENV_DOT3) |   \
     BIT(TEXTURE_CUBE_MAP) | BIT(SEPARATE_SPECULAR))
#define GL21_BITS (GL13_BITS | BIT(DEPTH_TEXTURE) | BIT(SHADOW) | BIT(VBO) | BIT(GLSL) | BIT(FBO))

static float absf(float x) { return x < 0 ? -x : x; }

static void assert_vec(const float *got, float x, float y, float z, float tol)
{
    if (absf(got[0] - x) > tol || absf(got[1] - y) > tol || absf(got[2] - z) > tol)
        print_error("got (%f, %f, %f), expected (%f, %f, %f)\n", (double)got[0], (double)got[1],
                    (double)got[2], (double)x, (double)y, (double)z);
    assert_true(absf(got[0] - x) <= tol && absf(got[1] - y) <= tol && absf(got[2] - z) <= tol);
}

static void assert_parallel(const float *a, const float *b)
{
    float c0 = a[1] * b[2] - a[2] * b[1], c1 = a[2] * b[0] - a[0] * b[2],
          c2 = a[0] * b[1] - a[1] * b[0];
    float d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    assert_true(d > 0.0f);
    assert_true(absf(c0) + absf(c1) + absf(c2) <= 1e-4f * d);
}

/* A unit quad in z = 0 facing +z with uv = xy: T = +x, B = +y, N = +z. */
static void quad(stin__vertex v[4], float handedness)
{
    static const float p[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    int i;
    memset(v, 0, 4 * sizeof *v);
    for (i = 0; i < 4; i++) {
        v[i].position[0] = p[i][0];
        v[i].position[1] = p[i][1];
        v[i].normal[2] = 1.0f;
        v[i].uv[0] = p[i][0];
        v[i].uv[1] = p[i][1];
        v[i].tangent[0] = 1.0f;
        v[i].tangent[3] = handedness;
    }
}

static void identity(float m[16])
{
    memset(m, 0, 16 * sizeof *m);
    m[0] = m[5] = m[10] = m[15] = 1.0f;
}

static void test_light_vectors_identity(void **state)
{
    stin__vertex v[4];
    float m[16], out[24], light[4] = {1, 2, 3, 1}, sun[4] = {0.6f, 0, 0.8f, 0};
    (void)state;
    quad(v, 1.0f);
    identity(m);
    stin__dot3_light_vectors(v, 4, m, light, out);
    assert_vec(out + 0, 1, 2, 3, 1e-6f);   /* (0,0,0): L = (1,2,3) */
    assert_vec(out + 6, 0, 2, 3, 1e-6f);   /* (1,0,0) */
    assert_vec(out + 12, 0, 1, 3, 1e-6f);  /* (1,1,0) */
    assert_vec(out + 18, 1, 1, 3, 1e-6f);  /* (0,1,0) */
    assert_vec(out + 3, 1, 2, 3, 1e-6f);   /* the lighting normal points at the light */
    /* a mirrored uv layout flips B */
    quad(v, -1.0f);
    stin__dot3_light_vectors(v, 4, m, light, out);
    assert_vec(out + 0, 1, -2, 3, 1e-6f);
    /* a directional light: the same vector everywhere */
    stin__dot3_light_vectors(v, 4, m, sun, out);
    assert_vec(out + 0, 0.6f, 0, 0.8f, 1e-6f);
    assert_vec(out + 12, 0.6f, 0, 0.8f, 1e-6f);
}

/* Rotated 90 degrees about z, scaled by 2 and moved to (5,0,0): the quad's T
 * is world +y, B world -x, N world +z. A light at world (5,0,4) seen from the
 * object's origin is (0,0,4) in world space: L_ts = (0,0,4)/2 in object units
 * (the similarity path keeps object units; the direction is what counts). */
static void test_light_vectors_similarity(void **state)
{
    stin__vertex v[4];
    float m[16], out[24], light[4] = {5, 0, 4, 1}, light2[4] = {3, 3, 0, 1};
    (void)state;
    quad(v, 1.0f);
    identity(m);
    m[0] = 0; m[1] = 2; /* column 0: x -> 2y */
    m[4] = -2; m[5] = 0; /* column 1: y -> -2x */
    m[10] = 2;
    m[12] = 5;
    stin__dot3_light_vectors(v, 4, m, light, out);
    assert_vec(out + 0, 0, 0, 2, 1e-5f);
    /* vertex (1,0,0) is at world (5,2,0); the light at world (3,3,0) is
     * (-2,1,0) from it: T = +y gives 1, B = -x gives 2, N gives 0 (in half
     * units: object space is scaled by 2). */
    stin__dot3_light_vectors(v, 4, m, light2, out);
    assert_vec(out + 6, 0.5f, 1.0f, 0.0f, 1e-5f);
}

/* Non-uniform scale x2 along x: the world frame is still T = +x, N = +z, so
 * the light at world (4,0,2) from the origin is L_ts = (4,0,2), not the
 * (2,0,2) of projecting in object space. The lighting normal, moved by the
 * normal matrix, points at the light. */
static void test_light_vectors_nonuniform(void **state)
{
    stin__vertex v[4];
    float m[16], out[24], light[4] = {4, 0, 2, 1}, nm[9], n[3];
    int i;
    (void)state;
    quad(v, 1.0f);
    identity(m);
    m[0] = 2.0f;
    stin__dot3_light_vectors(v, 4, m, light, out);
    assert_vec(out + 0, 4, 0, 2, 1e-5f);
    stin__mat3_normal(nm, m);
    for (i = 0; i < 3; i++)
        n[i] = nm[i] * out[3] + nm[3 + i] * out[4] + nm[6 + i] * out[5];
    assert_parallel(n, light);
    /* a mirror (x -> -x) with non-uniform scale keeps B on the uv side: the
     * light at +y world is +B */
    m[0] = -2.0f;
    m[5] = 3.0f;
    light[0] = 0;
    light[1] = 3;
    light[2] = 0;
    stin__dot3_light_vectors(v, 1, m, light, out);
    assert_vec(out + 0, 0, 3, 0, 1e-5f);
}

/* GL 1.3 table 3.19: the face and (s, t) a direction selects. */
static int gl_face(const float r[3], float *s, float *t)
{
    float ax = absf(r[0]), ay = absf(r[1]), az = absf(r[2]), sc, tc, ma;
    int face;
    if (ax >= ay && ax >= az) {
        face = r[0] > 0 ? 0 : 1;
        sc = r[0] > 0 ? -r[2] : r[2];
        tc = -r[1];
        ma = ax;
    } else if (ay >= az) {
        face = r[1] > 0 ? 2 : 3;
        sc = r[0];
        tc = r[1] > 0 ? r[2] : -r[2];
        ma = ay;
    } else {
        face = r[2] > 0 ? 4 : 5;
        sc = r[2] > 0 ? r[0] : -r[0];
        tc = -r[1];
        ma = az;
    }
    *s = 0.5f * (sc / ma + 1.0f);
    *t = 0.5f * (tc / ma + 1.0f);
    return face;
}

static void test_cube_directions_invert_face_selection(void **state)
{
    const float axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    float d[3], s, t;
    int face, i;
    unsigned seed = 12345;
    (void)state;
    for (face = 0; face < 6; face++) { /* face centres are the axes */
        stin__dot3_cube_direction(face, 0.5f, 0.5f, d);
        assert_vec(d, axes[face][0], axes[face][1], axes[face][2], 0.0f);
        assert_int_equal(gl_face(axes[face], &s, &t), face);
    }
    for (i = 0; i < 1000; i++) { /* any direction comes back from its texel address */
        float r[3];
        int k;
        for (k = 0; k < 3; k++) {
            seed = seed * 1103515245u + 12345u;
            r[k] = (float)((seed >> 8) & 0xffff) / 32768.0f - 1.0f;
        }
        if (absf(r[0]) + absf(r[1]) + absf(r[2]) < 1e-3f)
            continue;
        face = gl_face(r, &s, &t);
        stin__dot3_cube_direction(face, s, t, d);
        assert_parallel(d, r);
    }
}

static void test_cube_faces_encode_normalised_directions(void **state)
{
    enum { N = 32 };
    static unsigned char px[4 * N * N];
    const float axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    int face, i, j, k;
    (void)state;
    for (face = 0; face < 6; face++) {
        stin__dot3_cube_face(face, N, px);
        /* every texel: 0.5 + 0.5 normalize(direction at its centre), to 1/255 */
        for (j = 0; j < N; j++)
            for (i = 0; i < N; i++) {
                float d[3], len;
                stin__dot3_cube_direction(face, (i + 0.5f) / N, (j + 0.5f) / N, d);
                len = stin__sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                for (k = 0; k < 3; k++) {
                    float want = 255.0f * (0.5f + 0.5f * d[k] / len);
                    assert_true(absf(px[4 * (j * N + i) + k] - want) <= 0.5f + 1e-3f);
                }
                assert_int_equal(px[4 * (j * N + i) + 3], 255);
            }
        /* the four texels around the face centre average to 0.5 + 0.5 axis */
        for (k = 0; k < 3; k++) {
            int c = N / 2, sum = px[4 * ((c - 1) * N + c - 1) + k] + px[4 * ((c - 1) * N + c) + k] +
                            px[4 * (c * N + c - 1) + k] + px[4 * (c * N + c) + k];
            float want = 255.0f * (0.5f + 0.5f * axes[face][k]);
            assert_true(absf(sum / 4.0f - want) <= 1.0f);
        }
    }
}

/* ---- selection ----------------------------------------------------------- */

static stin_caps caps_with(int gl, int glsl, uint64_t present)
{
    stin_caps c;
    memset(&c, 0, sizeof c);
    c.gl_major = gl / 10;
    c.gl_minor = gl % 10;
    c.glsl_major = glsl / 10;
    c.glsl_minor = glsl % 10;
    c.present = present;
    return c;
}

static void test_selection_rule(void **state)
{
    stin_caps gl11 = caps_with(11, 0, GL11_BITS), gl13 = caps_with(13, 0, GL13_BITS),
              gl21 = caps_with(21, 12, GL21_BITS);
    stin_technique forced[STIN_FEATURE_COUNT] = {STIN_TECH_NONE, STIN_TECH_NONE, STIN_TECH_NONE};
    stin__selection sel;
    char msg[256];
    (void)state;
    assert_int_equal(stin__select(&gl13, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique, STIN_TECH_SURFACE_DOT3);
    assert_int_equal(stin__select(&gl11, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique, STIN_TECH_SURFACE_PLAIN);
    assert_non_null(strstr(sel.choice[STIN_FEATURE_SURFACE].reason, "dot3 needs multitexture"));
    /* the GLSL tier has the capabilities but not the lighting path: its own
     * surface techniques come first (pom) */
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_LIGHTING].technique, STIN_TECH_LIGHTING_GLSL110);
    assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique, STIN_TECH_SURFACE_POM);
    assert_null(strstr(sel.choice[STIN_FEATURE_SURFACE].reason, "fallback"));
    /* the same context at tier gl1, or with fixed-function lighting forced */
    assert_int_equal(stin__select(&gl21, STIN_TIER_GL1, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique, STIN_TECH_SURFACE_DOT3);
    forced[STIN_FEATURE_LIGHTING] = STIN_TECH_LIGHTING_FIXED;
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.tier, STIN_TIER_GL2);
    assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique, STIN_TECH_SURFACE_DOT3);
    /* forcing dot3 under GLSL lighting is refused, naming why */
    forced[STIN_FEATURE_LIGHTING] = STIN_TECH_NONE;
    forced[STIN_FEATURE_SURFACE] = STIN_TECH_SURFACE_DOT3;
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, "fixed-function lighting"));
    assert_int_equal(stin__technique_needs(STIN_TECH_SURFACE_DOT3),
                     BIT(MULTITEXTURE) | BIT(TEXTURE_ENV_COMBINE) | BIT(TEXTURE_ENV_DOT3) |
                         BIT(TEXTURE_CUBE_MAP) | BIT(FIXED_FUNCTION));
    assert_int_equal(stin_technique_from_name("dot3"), STIN_TECH_SURFACE_DOT3);
}

/* ---- on the fake GL ------------------------------------------------------ */

static fake_log log_;
static void *block;
static stin_context *ctx;

static stin_result create(const fake_gl_config *cfg, stin_technique surface)
{
    stin_desc d;
    size_t bytes;
    stin_result r;
    fake_gl_reset(cfg);
    memset(&log_, 0, sizeof log_);
    memset(&d, 0, sizeof d);
    d.get_proc_address = fake_gl_get_proc;
    d.log = fake_log_fn;
    d.log_user = &log_;
    d.max_meshes = 4;
    d.max_textures = 4;
    d.max_vertices = 64;
    d.max_triangles = 64;
    d.max_texture_bytes = 4096;
    d.techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_OFF;
    d.techniques[STIN_FEATURE_SURFACE] = surface;
    bytes = stin_memory_size(&d);
    block = malloc(bytes);
    assert_non_null(block);
    r = stin_create(&d, block, bytes, &ctx);
    if (r != STIN_OK) {
        free(block);
        block = NULL;
        ctx = NULL;
    }
    return r;
}

static void destroy(void)
{
    if (ctx)
        stin_destroy(ctx);
    free(block);
    ctx = NULL;
    block = NULL;
}

static void test_context_creates_and_deletes_the_cube_map(void **state)
{
    fake_gl_config gl13 = fake_gl_profile(FAKE_GL13), gl11 = fake_gl_profile(FAKE_GL11);
    (void)state;
    assert_int_equal(create(&gl13, STIN_TECH_NONE), STIN_OK);
    assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_SURFACE).technique, STIN_TECH_SURFACE_DOT3);
    assert_int_equal(fake_gl.textures_created, 1);
    assert_int_equal(fake_gl.tex_images, 6); /* one level per face */
    assert_int_equal(fake_gl.tex_level_width[0], 32);
    destroy();
    assert_int_equal(fake_gl.textures_deleted, 1);

    assert_int_equal(create(&gl11, STIN_TECH_NONE), STIN_OK);
    assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_SURFACE).technique, STIN_TECH_SURFACE_PLAIN);
    assert_int_equal(fake_gl.textures_created, 0);
    destroy();

    /* two texture units: plain, and the reason says so; forced: refused */
    gl13.max_texture_units = 2;
    assert_int_equal(create(&gl13, STIN_TECH_NONE), STIN_OK);
    assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_SURFACE).technique, STIN_TECH_SURFACE_PLAIN);
    assert_non_null(strstr(stin_query_choice(ctx, STIN_FEATURE_SURFACE).reason, "3 texture units"));
    assert_int_equal(fake_gl.textures_created, 0);
    destroy();
    assert_int_equal(create(&gl13, STIN_TECH_SURFACE_DOT3), STIN_ERROR_UNSUPPORTED);
    assert_true(fake_log_has(&log_, STIN_LOG_TECHNIQUE_UNSUPPORTED, "3 texture units"));
}

/* Unshadowed: ambient + lights in one batch for everything, then one DOT3
 * pass per light for the bumped draw. */
static void test_passes_per_light(void **state)
{
    static const float pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    static const float uv[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const uint32_t idx[] = {0, 1, 2, 0, 2, 3};
    static const uint8_t flat[4 * 4] = {128, 128, 255, 255, 128, 128, 255, 255,
                                        128, 128, 255, 255, 128, 128, 255, 255};
    fake_gl_config gl13 = fake_gl_profile(FAKE_GL13);
    stin_mesh_desc md;
    stin_texture_desc td;
    stin_frame_desc fd;
    stin_light_desc l;
    stin_material bumped, plain;
    stin_mesh m;
    stin_texture nmap;
    unsigned draws_before;
    (void)state;
    assert_int_equal(create(&gl13, STIN_TECH_NONE), STIN_OK);
    memset(&md, 0, sizeof md);
    md.positions = pos;
    md.uvs = uv;
    md.vertex_count = 4;
    md.indices = idx;
    md.index_count = 6;
    assert_int_equal(stin_create_mesh(ctx, &md, &m), STIN_OK);
    memset(&td, 0, sizeof td);
    td.kind = STIN_TEXTURE_NORMAL;
    td.width = td.height = 2;
    td.pixels = flat;
    assert_int_equal(stin_create_texture(ctx, &td, &nmap), STIN_OK);
    memset(&bumped, 0, sizeof bumped);
    bumped.normal_map = nmap;
    memset(&plain, 0, sizeof plain);
    memset(&fd, 0, sizeof fd);
    fd.view[0] = fd.view[5] = fd.view[10] = fd.view[15] = 1;
    fd.projection[0] = fd.projection[5] = fd.projection[10] = fd.projection[15] = 1;
    fd.viewport[2] = fd.viewport[3] = 16;
    memset(&l, 0, sizeof l);
    l.position[2] = 2;

    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    assert_int_equal(stin_add_light(ctx, &l), STIN_OK);
    assert_int_equal(stin_add_light(ctx, &l), STIN_OK);
    assert_int_equal(stin_draw(ctx, m, NULL, &bumped), STIN_OK);
    assert_int_equal(stin_draw(ctx, m, NULL, &plain), STIN_OK);
    draws_before = fake_gl.draw_calls;
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    /* one batch of both draws + a DOT3 pass per light of the bumped one */
    assert_int_equal(fake_gl.draw_calls - draws_before, 2 + 2);
    assert_int_equal(stin_query_frame_stats(ctx).passes, 1 + 2);
    assert_true(fake_gl.calls[STIN_GLFN_TexEnvi] > 0);
    /* GL state as the header promises */
    assert_false(fake_gl_is_enabled(GL_TEXTURE_CUBE_MAP));
    assert_false(fake_gl_is_enabled(GL_TEXTURE_2D));
    assert_int_equal(log_.errors, 0);

    /* no bumped draw: no DOT3 pass, no combiner touched */
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
    assert_int_equal(stin_add_light(ctx, &l), STIN_OK);
    assert_int_equal(stin_draw(ctx, m, NULL, &plain), STIN_OK);
    fake_gl.calls[STIN_GLFN_TexEnvi] = 0;
    draws_before = fake_gl.draw_calls;
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    assert_int_equal(fake_gl.draw_calls - draws_before, 1);
    assert_int_equal(fake_gl.calls[STIN_GLFN_TexEnvi], 0);
    stin_destroy_texture(ctx, nmap);
    stin_destroy_mesh(ctx, m);
    destroy();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_light_vectors_identity),
        cmocka_unit_test(test_light_vectors_similarity),
        cmocka_unit_test(test_light_vectors_nonuniform),
        cmocka_unit_test(test_cube_directions_invert_face_selection),
        cmocka_unit_test(test_cube_faces_encode_normalised_directions),
        cmocka_unit_test(test_selection_rule),
        cmocka_unit_test(test_context_creates_and_deletes_the_cube_map),
        cmocka_unit_test(test_passes_per_light),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
