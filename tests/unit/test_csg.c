/* SPDX-License-Identifier: MIT */
/* CSG products: the normal form (Goldfeather's rules, empty terms dropped,
 * literals merged, random trees against their normal forms at every
 * inside/outside assignment, the limits) and stin_draw_csg's checks on the
 * fake GL (call order, bad input, capacities; nothing of a refused product
 * stays). */
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
#include "csg/csg_private.h" /* the frame's products, read back */
#include "gl/stage_times_private.h" /* the stage marks, read back */

#define P(i) {STIN_CSG_PRIMITIVE, (i), 0, 0}
#define U(a, b) {STIN_CSG_UNION, 0, (a), (b)}
#define I(a, b) {STIN_CSG_INTERSECTION, 0, (a), (b)}
#define S(a, b) {STIN_CSG_SUBTRACTION, 0, (a), (b)}
#define L(p) STIN__CSG_LITERAL(p, 0)
#define NOT(p) STIN__CSG_LITERAL(p, 1)
#define END UINT32_MAX

enum { WORDS = 4096, TERMS = 256, LITERALS = 1024 };
static uint32_t scratch[WORDS];
static stin__csg_term terms[TERMS];
static uint32_t literals[LITERALS];

static stin__csg_nf_result normalise(const stin_csg_node *nodes, uint32_t n, stin__csg_out *out,
                                     uint32_t words)
{
    memset(out, 0, sizeof *out);
    out->terms = terms;
    out->max_terms = TERMS;
    out->literals = literals;
    out->max_literals = LITERALS;
    return stin__csg_normal_form(nodes, n, scratch, words, out);
}

/* expected: the terms' literals, each term ended by END, the list by a second END. */
static void expect_terms(const stin_csg_node *nodes, uint32_t n, const uint32_t *expected)
{
    stin__csg_out out;
    uint32_t t = 0, i;
    assert_int_equal(normalise(nodes, n, &out, WORDS), STIN__CSG_NF_OK);
    while (expected[0] != END) {
        assert_true(t < out.term_count);
        for (i = 0; expected[i] != END; i++) {
            assert_true(i < terms[t].count);
            assert_int_equal(literals[terms[t].first + i], expected[i]);
        }
        assert_int_equal(terms[t].count, i);
        expected += i + 1;
        t++;
    }
    assert_int_equal(out.term_count, t);
}

static void test_goldfeather_rules(void **state)
{
    static const stin_csg_node sub[] = {P(0), P(1), S(0, 1)};
    static const uint32_t sub_nf[] = {L(0), NOT(1), END, END};
    static const stin_csg_node union_minus[] = {P(0), P(1), P(2), U(0, 1), S(3, 2)};
    static const uint32_t union_minus_nf[] = {L(0), NOT(2), END, L(1), NOT(2), END, END};
    static const stin_csg_node minus_union[] = {P(0), P(1), P(2), U(1, 2), S(0, 3)};
    static const uint32_t minus_union_nf[] = {L(0), NOT(1), NOT(2), END, END};
    static const stin_csg_node minus_inter[] = {P(0), P(1), P(2), I(1, 2), S(0, 3)};
    static const uint32_t minus_inter_nf[] = {L(0), NOT(1), END, L(0), NOT(2), END, END};
    static const stin_csg_node minus_minus[] = {P(0), P(1), P(2), S(1, 2), S(0, 3)};
    static const uint32_t minus_minus_nf[] = {L(0), NOT(1), END, L(0), L(2), END, END};
    static const stin_csg_node inter_union[] = {P(0), P(1), P(2), U(1, 2), I(0, 3)};
    static const uint32_t inter_union_nf[] = {L(0), L(1), END, L(0), L(2), END, END};
    /* literals come out sorted by primitive, whatever the tree's order */
    static const stin_csg_node sorted[] = {P(2), P(0), P(1), S(0, 1), I(3, 2)};
    static const uint32_t sorted_nf[] = {NOT(0), L(1), L(2), END, END};
    (void)state;
    expect_terms(sub, 3, sub_nf);
    expect_terms(union_minus, 5, union_minus_nf);
    expect_terms(minus_union, 5, minus_union_nf);
    expect_terms(minus_inter, 5, minus_inter_nf);
    expect_terms(minus_minus, 5, minus_minus_nf);
    expect_terms(inter_union, 5, inter_union_nf);
    expect_terms(sorted, 5, sorted_nf);
}

static void test_empty_terms_dropped_and_repeats_merged(void **state)
{
    static const stin_csg_node self_minus[] = {P(0), S(0, 0)};
    static const uint32_t none[] = {END};
    static const stin_csg_node self_inter[] = {P(0), I(0, 0)};
    static const uint32_t one[] = {L(0), END, END};
    /* (a u b) - a = b !a: the term a !a is empty */
    static const stin_csg_node half[] = {P(0), P(1), U(0, 1), S(2, 0)};
    static const uint32_t half_nf[] = {NOT(0), L(1), END, END};
    /* a leaf used twice through a shared node */
    static const stin_csg_node shared[] = {P(0), P(1), S(0, 1), I(2, 2)};
    static const uint32_t shared_nf[] = {L(0), NOT(1), END, END};
    /* a chain that unions the same primitive in again, and a union of two
     * nodes with the same terms: each term once, in first-use order */
    static const stin_csg_node chain[] = {P(0), P(1), U(0, 1), U(2, 1), U(3, 1), U(4, 1)};
    static const stin_csg_node twice[] = {P(0), P(1), U(0, 1), U(1, 0), U(2, 3)};
    static const uint32_t a_b[] = {L(0), END, L(1), END, END};
    (void)state;
    expect_terms(self_minus, 2, none);
    expect_terms(self_inter, 2, one);
    expect_terms(half, 4, half_nf);
    expect_terms(shared, 4, shared_nf);
    expect_terms(chain, 6, a_b);
    expect_terms(twice, 5, a_b);
}

/* ---- random trees: the normal form holds exactly where the tree does ---- */
static uint32_t rng = 12345u;
static uint32_t next(void)
{
    rng = rng * 1664525u + 1013904223u;
    return rng >> 8;
}

static int eval_tree(const stin_csg_node *nodes, uint32_t i, uint32_t inside)
{
    const stin_csg_node *n = &nodes[i];
    switch (n->op) {
    case STIN_CSG_PRIMITIVE: return (int)((inside >> n->primitive) & 1u);
    case STIN_CSG_UNION: return eval_tree(nodes, n->a, inside) || eval_tree(nodes, n->b, inside);
    case STIN_CSG_INTERSECTION:
        return eval_tree(nodes, n->a, inside) && eval_tree(nodes, n->b, inside);
    case STIN_CSG_SUBTRACTION:
        return eval_tree(nodes, n->a, inside) && !eval_tree(nodes, n->b, inside);
    }
    return -1;
}

static int eval_terms(const stin__csg_out *out, uint32_t inside)
{
    uint32_t t, i;
    for (t = 0; t < out->term_count; t++) {
        int all = 1, positive = 0;
        for (i = 0; i < terms[t].count; i++) {
            uint32_t l = literals[terms[t].first + i];
            uint32_t in = (inside >> STIN__CSG_PRIMITIVE_OF(l)) & 1u;
            if (!STIN__CSG_COMPLEMENTED(l))
                positive = 1;
            if (i > 0)
                assert_true(l > literals[terms[t].first + i - 1]); /* sorted, once each */
            if (in == STIN__CSG_COMPLEMENTED(l))
                all = 0;
        }
        assert_true(positive); /* Goldfeather draws a term from its plain primitives */
        if (all)
            return 1;
    }
    return 0;
}

static void test_random_trees_match_their_normal_forms(void **state)
{
    enum { PRIMS = 6, NODES = 12 };
    int round;
    (void)state;
    for (round = 0; round < 2000; round++) {
        stin_csg_node nodes[NODES];
        stin__csg_out out;
        uint32_t n = 0, inside, leaves = 1 + next() % PRIMS, i;
        for (i = 0; i < leaves; i++) {
            stin_csg_node leaf = P(0);
            leaf.primitive = next() % PRIMS;
            nodes[n++] = leaf;
        }
        while (n < NODES) {
            stin_csg_node op = U(0, 0);
            op.op = (stin_csg_op)(1 + next() % 3);
            op.a = next() % n;
            op.b = next() % n;
            nodes[n++] = op;
        }
        assert_int_equal(normalise(nodes, n, &out, WORDS), STIN__CSG_NF_OK);
        for (inside = 0; inside < (1u << PRIMS); inside++)
            assert_int_equal(eval_terms(&out, inside), eval_tree(nodes, n - 1, inside));
    }
}

static void test_limits(void **state)
{
    static stin_csg_node chain[STIN__CSG_MAX_DEPTH + 2];
    stin_csg_node cross[9];
    stin__csg_out out;
    uint32_t i;
    (void)state;
    /* a union of 1025 leaves nested 1025 deep */
    chain[0] = (stin_csg_node)P(0);
    for (i = 1; i < STIN__CSG_MAX_DEPTH + 2; i++) {
        stin_csg_node u = U(0, 0);
        u.a = i - 1;
        chain[i] = u;
    }
    assert_int_equal(normalise(chain, STIN__CSG_MAX_DEPTH + 2, &out, WORDS), STIN__CSG_NF_DEPTH);
    assert_int_equal(out.term_count, 0);
    /* 1023 deep is fine: 1024 terms [0], merged into one */
    assert_int_equal(normalise(chain, STIN__CSG_MAX_DEPTH, &out, WORDS), STIN__CSG_NF_OK);
    assert_int_equal(out.term_count, 1);
    /* (a u b) n (c u d) n (e u f) n (g u h): 16 terms of 4 */
    for (i = 0; i < 8; i++) {
        stin_csg_node leaf = P(0);
        leaf.primitive = i;
        cross[i] = leaf;
    }
    {
        stin_csg_node nodes[15];
        memcpy(nodes, cross, 8 * sizeof nodes[0]);
        nodes[8] = (stin_csg_node)U(0, 1);
        nodes[9] = (stin_csg_node)U(2, 3);
        nodes[10] = (stin_csg_node)U(4, 5);
        nodes[11] = (stin_csg_node)U(6, 7);
        nodes[12] = (stin_csg_node)I(8, 9);
        nodes[13] = (stin_csg_node)I(12, 10);
        nodes[14] = (stin_csg_node)I(13, 11);
        assert_int_equal(normalise(nodes, 15, &out, WORDS), STIN__CSG_NF_OK);
        assert_int_equal(out.term_count, 16);
        assert_int_equal(out.literal_count, 64);
        assert_int_equal(normalise(nodes, 15, &out, 60), STIN__CSG_NF_SCRATCH);
        assert_int_equal(out.term_count, 0);
        memset(&out, 0, sizeof out);
        out.terms = terms;
        out.max_terms = 16;
        out.literals = literals;
        out.max_literals = 63;
        assert_int_equal(stin__csg_normal_form(nodes, 15, scratch, WORDS, &out),
                         STIN__CSG_NF_LITERALS);
        out.max_terms = 15;
        out.max_literals = 64;
        assert_int_equal(stin__csg_normal_form(nodes, 15, scratch, WORDS, &out),
                         STIN__CSG_NF_TERMS);
    }
    /* x_i = x_{i-1} - x_{i-1}: one node twice, empty at once */
    for (i = 1; i < 40; i++) {
        stin_csg_node s = S(0, 0);
        s.a = s.b = i - 1;
        chain[i] = s;
    }
    assert_int_equal(normalise(chain, 40, &out, WORDS), STIN__CSG_NF_OK);
    assert_int_equal(out.term_count, 0);
    /* x_i = x_{i-1} - (x_{i-1} n x_{i-1}): x_{i-1} expanded twice a level */
    for (i = 1; i < 80; i += 2) {
        stin_csg_node n = I(0, 0), s = S(0, 0);
        n.a = n.b = i - 1;
        s.a = i - 1;
        s.b = i;
        chain[i] = n;
        chain[i + 1] = s;
    }
    assert_int_equal(normalise(chain, 81, &out, WORDS), STIN__CSG_NF_WORK);
}

/* ---- bounded work --------------------------------------------------------- */
enum { BIG_WORDS = 1 << 18 };
static uint32_t big_scratch[BIG_WORDS];
static stin_csg_node big[4 * STIN__CSG_MAX_DEPTH];

/* A union of primitive doubled `levels` times from big[at] on: through one
 * shared node (x u x), or through a second node (x u (x n x)). The index
 * of its root. */
static uint32_t doubled(uint32_t at, uint32_t primitive, uint32_t levels, int second)
{
    uint32_t i, x = at;
    big[at] = (stin_csg_node)P(0);
    big[at].primitive = primitive;
    for (i = 0; i < levels; i++) {
        stin_csg_node u = U(0, 0), n = I(0, 0);
        u.a = u.b = n.a = n.b = x;
        if (second) {
            big[x + 1] = n;
            u.b = x + 1;
            x++;
        }
        big[++x] = u;
    }
    return x;
}

/* X n (Y - p), X a union of p and Y one of q, each doubled L times: every
 * one of X's terms [p] crossed with Y's [q !p] is empty. */
static uint32_t doubled_product(uint32_t levels, int second)
{
    uint32_t x = doubled(0, 0, levels, second), y = doubled(x + 1, 1, levels, second);
    big[y + 1] = (stin_csg_node)S(0, 0);
    big[y + 1].a = y;
    big[y + 2] = (stin_csg_node)I(0, 0);
    big[y + 2].a = x;
    big[y + 2].b = y + 1;
    return y + 3;
}

static void test_work_is_bounded(void **state)
{
    stin__csg_out out;
    uint32_t n;
    (void)state;
    /* one shared node doubled 20 times is one term (it was 2^20), and the
     * product with its complement is empty at once (it was 4^20 crossings) */
    n = doubled(0, 0, 20, 0);
    assert_int_equal(normalise(big, n + 1, &out, WORDS), STIN__CSG_NF_OK);
    assert_int_equal(out.term_count, 1);
    assert_int_equal(literals[terms[0].first], L(0));
    n = doubled_product(20, 0);
    assert_int_equal(normalise(big, n, &out, WORDS), STIN__CSG_NF_OK);
    assert_int_equal(out.term_count, 0);
    /* through a second node: 2^13 x 2^13 crossings, each empty, with room
     * for them all: refused for the steps, not run for seconds */
    n = doubled_product(13, 1);
    memset(&out, 0, sizeof out);
    out.terms = terms;
    out.max_terms = TERMS;
    out.literals = literals;
    out.max_literals = LITERALS;
    assert_int_equal(stin__csg_normal_form(big, n, big_scratch, BIG_WORDS, &out),
                     STIN__CSG_NF_WORK);
    assert_int_equal(out.term_count, 0);
    /* 2^6 x 2^6 is within it */
    n = doubled_product(6, 1);
    assert_int_equal(stin__csg_normal_form(big, n, big_scratch, BIG_WORDS, &out),
                     STIN__CSG_NF_OK);
    assert_int_equal(out.term_count, 0);
}

static void test_measure(void **state)
{
    static stin_csg_primitive one;
    stin_csg_desc d;
    stin_csg_size size;
    const char *why = NULL;
    uint32_t i, n;
    (void)state;
    memset(&d, 0, sizeof d);
    d.primitives = &one;
    d.nodes = big;
    /* a union of 257 primitives: 257 terms of one */
    for (i = 0; i < 257; i++) {
        big[i] = (stin_csg_node)P(0);
        big[i].primitive = i;
    }
    big[257] = (stin_csg_node)U(0, 1);
    for (n = 258, i = 2; i < 257; i++, n++) {
        big[n] = (stin_csg_node)U(0, 0);
        big[n].a = n - 1;
        big[n].b = i;
    }
    d.primitive_count = 257;
    d.node_count = n;
    assert_int_equal(stin_csg_measure(&d, scratch, WORDS, &size, &why), STIN_OK);
    assert_int_equal(size.terms, 257);
    assert_int_equal(size.literals, 257);
    assert_true(size.scratch_words >= 2 * 257 && size.scratch_words <= WORDS);
    assert_int_equal(stin_csg_measure(&d, scratch, 100, &size, &why), STIN_ERROR_CAPACITY);
    assert_non_null(strstr(why, "scratch"));
    assert_int_equal(size.scratch_words, 101); /* short: more than it had */
    d.primitive_count = 256; /* node 256 names primitive 256 */
    assert_int_equal(stin_csg_measure(&d, scratch, WORDS, &size, &why),
                     STIN_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(why, "out of range"));
    /* the doubled tree: one term; through a second node: past the steps */
    d.primitive_count = 2;
    d.node_count = doubled_product(28, 0);
    assert_int_equal(stin_csg_measure(&d, scratch, WORDS, &size, &why), STIN_OK);
    assert_int_equal(size.terms, 0);
    d.node_count = doubled(0, 0, 28, 0) + 1;
    assert_int_equal(stin_csg_measure(&d, scratch, WORDS, &size, &why), STIN_OK);
    assert_int_equal(size.terms, 1);
    d.node_count = doubled_product(13, 1);
    assert_int_equal(stin_csg_measure(&d, big_scratch, BIG_WORDS, &size, &why),
                     STIN_ERROR_CAPACITY);
    assert_non_null(strstr(why, "2^24 steps"));
    assert_true(size.scratch_words <= BIG_WORDS);
    /* 1025 deep */
    d.node_count = doubled(0, 0, STIN__CSG_MAX_DEPTH + 1, 0) + 1;
    assert_int_equal(stin_csg_measure(&d, scratch, WORDS, &size, &why),
                     STIN_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(why, "1024"));
    d.node_count = doubled(0, 0, STIN__CSG_MAX_DEPTH - 1, 0) + 1;
    assert_int_equal(stin_csg_measure(&d, scratch, WORDS, &size, &why), STIN_OK);
}

/* ---- stin_draw_csg on the fake GL ---------------------------------------- */
static fake_log log_;
static void *block;
static stin_context *ctx;
static stin_mesh tetra, quad;

static const float tetra_pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
static const uint32_t tetra_idx[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
static const float quad_pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
static const uint32_t quad_idx[] = {0, 1, 2, 0, 2, 3};

static void add_mesh(const float *pos, uint32_t nv, const uint32_t *idx, uint32_t ni,
                     stin_mesh *out)
{
    stin_mesh_desc md;
    memset(&md, 0, sizeof md);
    md.positions = pos;
    md.vertex_count = nv;
    md.indices = idx;
    md.index_count = ni;
    assert_int_equal(stin_create_mesh(ctx, &md, out), STIN_OK);
}

/* A context on the fake profile with the tetrahedron and the quad; small
 * CSG capacities (8 primitives, 4 terms, 8 literals) unless `defaults`. */
static stin_technique forced_csg = STIN_TECH_NONE; /* make_context's desc.techniques */
static uint64_t debug_flags_;                       /* and desc.debug_flags */

static int sample_buffers_; /* the next contexts' framebuffers are multisampled */

static void make_context(fake_gl_profile_id id, uint64_t caps_mask, int defaults)
{
    fake_gl_config cfg = fake_gl_profile(id);
    stin_desc d;
    size_t bytes;
    cfg.sample_buffers = sample_buffers_;
    fake_gl_reset(&cfg);
    d = fake_gl_desc(&log_);
    d.max_meshes = 4;
    d.max_textures = 1;
    d.max_vertices = 64;
    d.max_triangles = 64;
    d.caps_mask = caps_mask;
    d.techniques[STIN_FEATURE_CSG] = forced_csg;
    d.debug_flags = debug_flags_;
    if (!defaults) {
        d.csg.max_primitives = 8;
        d.csg.max_terms = 4;
        d.csg.max_literals = 8;
    }
    bytes = stin_memory_size(&d);
    block = malloc(bytes);
    assert_int_equal(stin_create(&d, block, bytes, &ctx), STIN_OK);
    add_mesh(tetra_pos, 4, tetra_idx, 12, &tetra);
    add_mesh(quad_pos, 4, quad_idx, 6, &quad);
}

static int setup(void **state)
{
    (void)state;
    make_context(FAKE_GL11, 0, 0);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    stin_destroy(ctx);
    free(block);
    return 0;
}

static int no_clear_; /* the next frames keep the framebuffer's contents */

static void begin(void)
{
    stin_frame_desc fd;
    memset(&fd, 0, sizeof fd);
    fd.keep_contents = no_clear_;
    stin__mat4_identity(fd.view);
    stin__mat4_identity(fd.projection);
    fd.viewport[2] = 16;
    fd.viewport[3] = 16;
    assert_int_equal(stin_begin_frame(ctx, &fd), STIN_OK);
}

static stin_csg_primitive prims[8];
static stin_csg_node nodes[8];

/* The product of prims[0..primitives) and nodes[0..node_count). */
static stin_csg_desc product_of(uint32_t primitives, uint32_t node_count)
{
    stin_csg_desc d;
    memset(&d, 0, sizeof d);
    d.primitives = prims;
    d.primitive_count = primitives;
    d.nodes = nodes;
    d.node_count = node_count;
    return d;
}

/* a - b of two tetrahedra (the second moved by x) */
static stin_csg_desc subtraction(void)
{
    memset(prims, 0, sizeof prims);
    prims[0].mesh = tetra;
    prims[1].mesh = tetra;
    stin__mat4_identity(prims[1].transform);
    prims[1].transform[12] = 0.25f;
    nodes[0] = (stin_csg_node)P(0);
    nodes[1] = (stin_csg_node)P(1);
    nodes[2] = (stin_csg_node)S(0, 1);
    return product_of(2, 3);
}

static void refused(stin_csg_desc *d, stin_result r, stin_log_item item, const char *text)
{
    stin_frame_stats before = stin_query_frame_stats(ctx);
    log_.items[item] = 0;
    assert_int_equal(stin_draw_csg(ctx, d), r);
    assert_int_equal(log_.items[item], 1);
    assert_true(fake_log_has(&log_, item, text));
    assert_int_equal(stin_query_frame_stats(ctx).csg.dropped, before.csg.dropped + 1);
    assert_int_equal(stin_query_frame_stats(ctx).csg.products, before.csg.products);
    assert_int_equal(ctx->csg->primitive_count, before.csg.products ? 2u : 0u);
}

static void test_draw_csg_accepts_and_reads_back(void **state)
{
    stin_csg_desc d = subtraction();
    uint32_t lits[4], count = 9;
    (void)state;
    assert_int_equal(stin_draw_csg(ctx, &d), STIN_ERROR_INVALID_STATE);
    begin();
    assert_int_equal(stin_draw_csg(ctx, &d), STIN_OK);
    assert_int_equal(stin_query_csg_terms(ctx, 0, 0, lits, 4, &count), 1);
    assert_int_equal(count, 2);
    assert_int_equal(lits[0], L(0));
    assert_int_equal(lits[1], NOT(1));
    assert_int_equal(stin_query_csg_terms(ctx, 1, 0, lits, 4, &count), 0);
    assert_int_equal(count, 0);
    assert_int_equal(stin_query_frame_stats(ctx).csg.products, 1);
    assert_int_equal(stin_query_frame_stats(ctx).csg.terms, 1);
    /* the zero transform is the identity; the material got its defaults */
    assert_true(ctx->csg->primitives[0].transform[0] == 1.0f);
    assert_true(ctx->csg->primitives[0].material.color[3] == 1.0f);
    /* a - a is empty: accepted, nothing kept */
    nodes[2] = (stin_csg_node)S(0, 0);
    assert_int_equal(stin_draw_csg(ctx, &d), STIN_OK);
    assert_int_equal(stin_query_frame_stats(ctx).csg.products, 1);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    begin(); /* a new frame starts empty */
    assert_int_equal(stin_query_csg_terms(ctx, 0, 0, NULL, 0, NULL), 0);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
}

static void test_draw_csg_refuses_bad_input(void **state)
{
    stin_csg_desc d;
    stin_mesh stale;
    (void)state;
    begin();
    assert_int_equal(stin_draw_csg(NULL, NULL), STIN_ERROR_INVALID_ARGUMENT);
    refused(NULL, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT, "desc is NULL");
    d = subtraction();
    d.node_count = 0;
    refused(&d, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT, "empty expression");
    d = subtraction();
    d.primitive_count = 0;
    refused(&d, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT, "empty expression");
    d = subtraction();
    nodes[1].op = (stin_csg_op)7;
    refused(&d, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT, "unknown op in node (1)");
    d = subtraction();
    nodes[1].primitive = 2;
    refused(&d, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT,
            "primitive index out of range in node (1)");
    d = subtraction();
    nodes[2].b = 2; /* itself: a cycle */
    refused(&d, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT, "before the one using it");
    d = subtraction();
    prims[1].transform[5] = NAN;
    refused(&d, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT, "transform must be finite");
    d = subtraction();
    prims[1].transform[5] = 0.0f; /* flat */
    refused(&d, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT, "invertible");
    d = subtraction();
    prims[0].mesh = quad;
    refused(&d, STIN_ERROR_INVALID_MESH, STIN_LOG_MESH_NOT_MANIFOLD, "closed 2-manifold");
    d = subtraction();
    stale.id = tetra.id ^ 0x10000u;
    prims[1].mesh = stale;
    refused(&d, STIN_ERROR_INVALID_HANDLE, STIN_LOG_BAD_HANDLE, "stale or unknown mesh");
    d = subtraction();
    prims[1].material.color[0] = 0.5f;
    prims[1].material.color[3] = 0.5f;
    refused(&d, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT, "opaque");
    d = subtraction();
    prims[1].material.shininess = NAN;
    refused(&d, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT, "material values");
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
}

/* csg.max_primitives 8, terms 4, literals 8 */
static void test_draw_csg_capacities(void **state)
{
    stin_csg_desc d = subtraction();
    (void)state;
    begin();
    assert_int_equal(stin_draw_csg(ctx, &d), STIN_OK); /* 2 primitives, 1 term, 2 literals */
    d.primitive_count = 4;
    prims[2] = prims[3] = prims[0];
    /* (0 u 1) n (2 u 3): 4 terms of 2, more than the 3 terms left */
    nodes[0] = (stin_csg_node)P(0);
    nodes[1] = (stin_csg_node)P(1);
    nodes[2] = (stin_csg_node)P(2);
    nodes[3] = (stin_csg_node)P(3);
    nodes[4] = (stin_csg_node)U(0, 1);
    nodes[5] = (stin_csg_node)U(2, 3);
    nodes[6] = (stin_csg_node)I(4, 5);
    d.node_count = 7;
    refused(&d, STIN_ERROR_CAPACITY, STIN_LOG_POOL_FULL, "csg.max_terms");
    /* two terms of 4 literals, more than the 6 left */
    {
        /* (0 n 1) n ((2 - 3) u (3 - 2)): two terms of 4 */
        stin_csg_node all[9] = {P(0), P(1), P(2), P(3), I(0, 1), S(2, 3), S(3, 2), U(5, 6),
                                I(4, 7)};
        d.nodes = all;
        d.node_count = 9;
        refused(&d, STIN_ERROR_CAPACITY, STIN_LOG_POOL_FULL, "csg.max_literals");
        d.nodes = nodes;
    }
    /* 7 primitives: more than the 6 left */
    d = subtraction();
    prims[2] = prims[3] = prims[4] = prims[5] = prims[6] = prims[0];
    d.primitive_count = 7;
    refused(&d, STIN_ERROR_CAPACITY, STIN_LOG_POOL_FULL, "csg.max_primitives");
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
}

static void test_memory_counts_the_capacities(void **state)
{
    stin_desc d = fake_gl_desc(NULL), more;
    size_t base;
    (void)state;
    base = stin_memory_size(&d);
    more = d;
    more.csg.max_literals = 4096u + 1000u;
    assert_true(stin_memory_size(&more) >= base + 3u * 4u * 1000u); /* store + scratch */
    more = d;
    more.csg.max_primitives = 256u + 100u;
    assert_true(stin_memory_size(&more) >= base + 100u * sizeof(stin__draw));
    more.csg.max_terms = 1u << 24;
    assert_int_equal(stin_memory_size(&more), 0);
    assert_int_equal(stin_query_desc(ctx).csg.max_primitives, 8);
    d = fake_gl_desc(NULL);
    d = stin__desc_defaults(&d);
    assert_int_equal(d.csg.max_primitives, 256);
    assert_int_equal(d.csg.max_terms, 256);
    assert_int_equal(d.csg.max_literals, 4096);
}

static void recreate(fake_gl_profile_id id, uint64_t caps_mask)
{
    teardown(NULL);
    make_context(id, caps_mask, 1);
    log_.items[STIN_LOG_FALLBACK] = 0; /* what stin_create logged */
}

/* stin_draw_csg into a multisampled target where the resolve reads back:
 * refused, dropped, nothing resolved (stin.h, MULTISAMPLED TARGETS). */
static void refused_frame(void)
{
    stin_csg_desc d = subtraction();
    begin();
    assert_int_equal(stin_draw_csg(ctx, &d), STIN_ERROR_UNSUPPORTED);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    assert_int_equal(ctx->stats.csg.dropped, 1);
    assert_int_equal(ctx->stats.csg.gpu_resolves, 0);
}

static void one_frame(void)
{
    stin_csg_desc d = subtraction();
    begin();
    assert_int_equal(stin_draw_csg(ctx, &d), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
}

/* one_frame on a fresh 3.3 core context made with debug flags `flags` */
static void flagged_frame(uint64_t flags)
{
    debug_flags_ = flags;
    recreate(FAKE_GL33_CORE, 0);
    debug_flags_ = 0;
    one_frame();
}

/* A frame with a product on the fake GL: GL 1.1 resolves it (depth read,
 * written once by glDrawPixels, faces drawn with the passes) by scs (two
 * convex tetrahedra; GL 1.1 has no occlusion queries); a core profile
 * resolves it by scs too on the GPU (no read-back: the faces snapped onto
 * the result), with STIN_DEBUG_CSG_READBACK by read-backs written through
 * the R32F texture, or by interval where forced (its layers and walk made at
 * the first frame with a product; its walk read back); without a stencil
 * buffer the choice is csg-off and the frames say once that products are
 * not drawn. */
static void test_frames_with_a_product(void **state)
{
    (void)state;
    recreate(FAKE_GL11, 0);
    assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_CSG).technique, STIN_TECH_CSG_SCS);
    one_frame();
    assert_int_equal(ctx->stats.csg.scs_products, 1);
    assert_true(ctx->csg->resolved);
    assert_int_equal(ctx->csg->face_count, 2); /* 0's front faces, 1's back faces */
    assert_true(fake_gl.calls[STIN_GLFN_ReadPixels] >= 2);
    assert_int_equal(fake_gl.calls[STIN_GLFN_DrawPixels], 1);
    assert_int_equal(log_.items[STIN_LOG_FALLBACK], 0);

    recreate(FAKE_GL33_CORE, 0);
    assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_CSG).technique, STIN_TECH_CSG_SCS);
    one_frame();
    assert_int_equal(ctx->stats.csg.scs_products, 1);
    assert_true(ctx->csg->resolved);
    assert_int_equal(ctx->stats.csg.gpu_resolves, 1);
    assert_true(ctx->stats.csg.gpu_bytes > 0);
    /* none: one subtracted primitive takes one run, with no check after
     * it; no depth, no clip count */
    assert_int_equal(fake_gl.calls[STIN_GLFN_ReadPixels], 0);
    assert_int_equal(ctx->stats.csg.scs_runs, 1);
    assert_int_equal(fake_gl.calls[STIN_GLFN_TexSubImage2D], 0);

    flagged_frame(STIN_DEBUG_STAGE_TIMES); /* the resolve timed as its own stage */
    assert_int_equal(ctx->stats.stage_times, 1);
    assert_true(ctx->times->marks >= 4);
    assert_int_equal(ctx->times->stage[2], STIN_STAGE_CSG); /* after prepass and base */
    assert_int_equal(ctx->times->stage[3], STIN_STAGE_BASE);

    flagged_frame(STIN_DEBUG_CSG_READBACK);
    assert_int_equal(ctx->stats.csg.scs_products, 1);
    assert_int_equal(ctx->stats.csg.gpu_resolves, 0);
    assert_true(fake_gl.calls[STIN_GLFN_ReadPixels] >= 2); /* depth, clip count */
    assert_int_equal(fake_gl.calls[STIN_GLFN_TexSubImage2D], 1);

    forced_csg = STIN_TECH_CSG_INTERVAL; /* not the default: slower than scs on llvmpipe */
    recreate(FAKE_GL33_CORE, 0);
    forced_csg = STIN_TECH_NONE;
    assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_CSG).technique,
                     STIN_TECH_CSG_INTERVAL);
    one_frame();
    assert_int_equal(ctx->stats.csg.interval_products, 1);
    assert_true(ctx->stats.csg.interval_bytes > 0);
    assert_int_equal(ctx->stats.csg.scs_products, 0);
    assert_true(ctx->csg->resolved);
    assert_int_equal(fake_gl.calls[STIN_GLFN_DrawPixels], 0);
    assert_int_equal(fake_gl.calls[STIN_GLFN_ReadPixels], 1); /* the walk */
    assert_int_equal(fake_gl.calls[STIN_GLFN_TexSubImage2D], 0);

    recreate(FAKE_GL11, STIN_CAP_BIT(STIN_CAP_STENCIL));
    assert_int_equal(stin_query_choice(ctx, STIN_FEATURE_CSG).technique, STIN_TECH_CSG_OFF);
    one_frame(); /* accepted, not drawn */
    one_frame();
    assert_false(ctx->csg->resolved);
    assert_int_equal(fake_gl.calls[STIN_GLFN_DrawPixels], 0);
    assert_int_equal(log_.items[STIN_LOG_FALLBACK], 1);
    assert_true(fake_log_has(&log_, STIN_LOG_FALLBACK, "CSG products are not drawn"));
}

/* scs's GPU resolve in place: a frame whose one product has one term
 * resolves it in the frame's own buffers (no work framebuffer bound, no
 * merge, no snap), and copies its depth into the result texture only when
 * a pass asks for it, once; not with STIN_DEBUG_CSG_NO_IN_PLACE, not in a
 * frame that keeps the framebuffer's contents, not into a multisampled
 * framebuffer, not with two products. */
static void test_scs_in_place(void **state)
{
    stin_csg_desc d;
    int origin[2];
    (void)state;
    recreate(FAKE_GL33_CORE, 0);
    one_frame();
    assert_int_equal(ctx->stats.csg.in_place, 1);
    assert_int_equal(ctx->stats.csg.direct, 0);
    assert_int_equal(ctx->stats.csg.gpu_resolves, 1);
    assert_int_equal(ctx->stats.csg.scs_products, 1);
    assert_int_equal(fake_gl.calls[STIN_GLFN_ReadPixels], 0);
    assert_int_equal(fake_gl.calls[STIN_GLFN_CopyTexSubImage2D], 0);
    assert_int_equal(fake_gl.draws_into_default, /* every draw into the frame */
                     fake_gl.calls[STIN_GLFN_DrawElements] + fake_gl.calls[STIN_GLFN_DrawArrays]);
    assert_true(stin__csg_depth_texture(ctx, origin) != 0); /* a pass asks: copied once */
    assert_true(stin__csg_depth_texture(ctx, origin) != 0);
    assert_int_equal(fake_gl.calls[STIN_GLFN_CopyTexSubImage2D], 1);

    flagged_frame(STIN_DEBUG_CSG_NO_IN_PLACE);
    assert_int_equal(ctx->stats.csg.in_place, 0);
    assert_int_equal(ctx->stats.csg.direct, 0);
    assert_int_equal(ctx->stats.csg.gpu_resolves, 1);
    assert_true(fake_gl.draws_into_default <
                fake_gl.calls[STIN_GLFN_DrawElements] + fake_gl.calls[STIN_GLFN_DrawArrays]);

    recreate(FAKE_GL33_CORE, 0);
    no_clear_ = 1;
    one_frame();
    no_clear_ = 0;
    assert_int_equal(ctx->stats.csg.in_place, 0);
    assert_int_equal(ctx->stats.csg.direct, 1); /* it draws into the frame's depth only */
    assert_int_equal(ctx->stats.csg.gpu_resolves, 1);

    sample_buffers_ = 1; /* probed with the framebuffer's bits, not every frame */
    recreate(FAKE_GL33_CORE, 0);
    one_frame(); /* a multisampled target: merged, never in place or direct */
    assert_int_equal(ctx->stats.csg.in_place, 0);
    assert_int_equal(ctx->stats.csg.direct, 0);
    assert_int_equal(ctx->stats.csg.gpu_resolves, 1);
    /* the snap's id pass: its texture counted beside the work and result */
    assert_true(ctx->stats.csg.gpu_bytes > ctx->csg->merge.bytes);
    flagged_frame(STIN_DEBUG_CSG_SNAP_AT_CENTRE); /* no id pass */
    assert_int_equal(ctx->stats.csg.gpu_bytes, ctx->csg->merge.bytes);
    debug_flags_ = STIN_DEBUG_CSG_READBACK;
    recreate(FAKE_GL33_CORE, 0);
    debug_flags_ = 0;
    sample_buffers_ = 0;
    refused_frame(); /* the read-back resolve takes no product into it */

    recreate(FAKE_GL33_CORE, 0); /* single-sampled again, for the tests after */

    recreate(FAKE_GL33_CORE, 0);
    d = subtraction(); /* the new context's mesh */
    begin();
    assert_int_equal(stin_draw_csg(ctx, &d), STIN_OK);
    assert_int_equal(stin_draw_csg(ctx, &d), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    assert_int_equal(ctx->stats.csg.scs_products, 2);
    assert_int_equal(ctx->stats.csg.in_place, 0);
    assert_int_equal(ctx->stats.csg.direct, 1);
}

/* A big tetrahedron minus three small ones, each of those moved by `step`
 * in x from the last (apart in the window where step is large). */
static stin_csg_desc minus_three(float step)
{
    int i, k;
    memset(prims, 0, sizeof prims);
    for (i = 0; i < 4; i++) {
        prims[i].mesh = tetra;
        stin__mat4_identity(prims[i].transform);
        for (k = 0; k < 2; k++)
            prims[i].transform[5 * k] = i ? 0.2f : 2.0f;
        prims[i].transform[12] = i ? -0.8f + step * (float)(i - 1) : -1.0f;
        prims[i].transform[13] = i ? -0.8f : -1.0f;
        prims[i].transform[14] = i ? -0.2f : -0.5f;
        nodes[i] = (stin_csg_node)P(i);
    }
    nodes[4] = (stin_csg_node)U(1, 2);
    nodes[5] = (stin_csg_node)U(4, 3);
    nodes[6] = (stin_csg_node)S(0, 5);
    return product_of(4, 7);
}

/* glClear calls of a goldfeather frame of minus_three(step). */
static unsigned clears_of(float step)
{
    stin_csg_desc d;
    forced_csg = STIN_TECH_CSG_GOLDFEATHER;
    recreate(FAKE_GL33_CORE, 0);
    forced_csg = STIN_TECH_NONE;
    d = minus_three(step);
    begin();
    assert_int_equal(stin_draw_csg(ctx, &d), STIN_OK);
    assert_int_equal(stin_end_frame(ctx), STIN_OK);
    assert_int_equal(ctx->stats.csg.terms, 1);
    return fake_gl.calls[STIN_GLFN_Clear];
}

/* goldfeather takes complemented convex candidates whose window rectangles
 * lie apart in one set of passes: three small tetrahedra 0.5 apart (4
 * pixels of 16 a side each way) share one layer clear and one count clear,
 * where the same three on top of each other take three of each. */
static void test_goldfeather_groups_apart_candidates(void **state)
{
    unsigned apart, stacked;
    (void)state;
    apart = clears_of(0.5f);
    assert_int_equal(ctx->stats.csg.grouped, 3);
    stacked = clears_of(0.0f);
    assert_int_equal(ctx->stats.csg.grouped, 0);
    assert_int_equal(apart + 4u, stacked);
}

/* A second frame on a context made with forced_csg and `flags`, counting
 * the draws into the GPU resolve's result framebuffer (made in the first). */
static void watched_frame(uint64_t flags)
{
    flagged_frame(flags);
    fake_gl.watched_framebuffer = ctx->csg->merge.fbo[STIN__CSG_MERGE_RESULT];
    fake_gl.draws_into_watched = 0;
    fake_gl.calls[STIN_GLFN_CopyTexSubImage2D] = 0;
    one_frame();
}

/* The direct GPU resolve: goldfeather's candidates are each snapped into
 * the frame's depth, so the result framebuffer is never drawn into (no
 * clear, merge quad or final snap) and the result texture is copied from
 * the frame only when a pass asks, once; with STIN_DEBUG_CSG_NO_IN_PLACE
 * the merge runs; under interval (its walk's layers are no one face set)
 * it does not run (into a multisampled framebuffer no product does). */
static void test_direct(void **state)
{
    int origin[2];
    (void)state;
    forced_csg = STIN_TECH_CSG_GOLDFEATHER;
    watched_frame(0);
    assert_int_equal(ctx->stats.csg.direct, 1);
    assert_int_equal(ctx->stats.csg.in_place, 0);
    assert_int_equal(ctx->stats.csg.gpu_resolves, 1);
    assert_int_equal(ctx->stats.csg.scs_products, 0);
    assert_int_equal(fake_gl.draws_into_watched, 0);
    assert_int_equal(fake_gl.calls[STIN_GLFN_ReadPixels], 0);
    assert_int_equal(fake_gl.calls[STIN_GLFN_CopyTexSubImage2D], 0);
    assert_true(stin__csg_depth_texture(ctx, origin) != 0);
    assert_true(stin__csg_depth_texture(ctx, origin) != 0);
    assert_int_equal(fake_gl.calls[STIN_GLFN_CopyTexSubImage2D], 1);

    watched_frame(STIN_DEBUG_CSG_NO_IN_PLACE);
    assert_int_equal(ctx->stats.csg.direct, 0);
    assert_int_equal(ctx->stats.csg.gpu_resolves, 1);
    assert_true(fake_gl.draws_into_watched > 0); /* the merge quads */


    forced_csg = STIN_TECH_CSG_INTERVAL;
    flagged_frame(0);
    forced_csg = STIN_TECH_NONE;
    assert_int_equal(ctx->stats.csg.interval_products, 1);
    assert_int_equal(ctx->stats.csg.direct, 0);
}

/* A projection of fovy 90 (square) from near n to far f into ctx (view
 * identity: the eye at the origin looking down -z). */
static void perspective(float n, float f)
{
    float *p = ctx->projection;
    memset(p, 0, 16 * sizeof *p);
    p[0] = p[5] = 1.0f;
    p[10] = -(f + n) / (f - n);
    p[11] = -1.0f;
    p[14] = -2.0f * f * n / (f - n);
    memcpy(ctx->view_proj, p, sizeof ctx->view_proj);
}

static int apart(float ax0, float ax1, float bx0, float bx1, float z0, float z1)
{
    const float a[6] = {ax0, -0.5f, z0, ax1, 0.5f, z1}, b[6] = {bx0, -0.5f, z0, bx1, 0.5f, z1};
    return stin__csg_world_boxes_apart(ctx, a, b, 8.0f);
}

/* scs's world rule (csg/bounds.c): boxes apart by more than 8 depth steps
 * along every ray through both, at the far side's distance, with the
 * target's depth precision; unsure (0) for oblique projections and boxes
 * reaching behind the eye. */
static void test_world_boxes_apart(void **state)
{
    (void)state;
    ctx->target.depth_bits = 24;
    perspective(1.0f, 100.0f);
    assert_true(apart(-1.0f, -0.1f, 0.1f, 1.0f, -6.0f, -5.0f));   /* 0.2 apart */
    assert_false(apart(-1.0f, 0.1f, -0.1f, 1.0f, -6.0f, -5.0f));  /* overlapping */
    assert_false(apart(-1.0f, 0.0f, 1e-5f, 1.0f, -6.0f, -5.0f));  /* within the 1e-3 margin */
    assert_false(apart(-1.0f, -0.1f, 0.1f, 1.0f, -1.0f, 1.0f));   /* behind the eye */
    /* 0.1 apart at w 10 with near 0.1: 5.8e-5 of depth, 8 steps of 24 bits
     * are 4.8e-7 and of 16 bits 1.2e-4 */
    perspective(0.1f, 100.0f);
    assert_true(apart(-1.0f, -0.05f, 0.05f, 1.0f, -10.0f, -9.0f));
    ctx->target.depth_bits = 16;
    assert_false(apart(-1.0f, -0.05f, 0.05f, 1.0f, -10.0f, -9.0f));
    ctx->target.depth_bits = 24;
    ctx->projection[3] = 0.1f; /* oblique: no plain form */
    memcpy(ctx->view_proj, ctx->projection, sizeof ctx->view_proj);
    assert_false(apart(-1.0f, -0.1f, 0.1f, 1.0f, -6.0f, -5.0f));
    memset(ctx->projection, 0, sizeof ctx->projection); /* orthographic, depth 0..99 */
    ctx->projection[0] = ctx->projection[5] = ctx->projection[15] = 1.0f;
    ctx->projection[10] = -2.0f / 99.0f;
    ctx->projection[14] = -101.0f / 99.0f;
    memcpy(ctx->view_proj, ctx->projection, sizeof ctx->view_proj);
    assert_true(apart(-1.0f, -0.1f, 0.1f, 1.0f, -6.0f, -5.0f));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_goldfeather_rules),
        cmocka_unit_test(test_empty_terms_dropped_and_repeats_merged),
        cmocka_unit_test(test_random_trees_match_their_normal_forms),
        cmocka_unit_test(test_limits),
        cmocka_unit_test(test_work_is_bounded),
        cmocka_unit_test(test_measure),
        cmocka_unit_test_setup_teardown(test_draw_csg_accepts_and_reads_back, setup, teardown),
        cmocka_unit_test_setup_teardown(test_draw_csg_refuses_bad_input, setup, teardown),
        cmocka_unit_test_setup_teardown(test_draw_csg_capacities, setup, teardown),
        cmocka_unit_test_setup_teardown(test_memory_counts_the_capacities, setup, teardown),
        cmocka_unit_test_setup_teardown(test_frames_with_a_product, setup, teardown),
        cmocka_unit_test_setup_teardown(test_direct, setup, teardown),
        cmocka_unit_test_setup_teardown(test_goldfeather_groups_apart_candidates, setup,
                                        teardown),
        cmocka_unit_test_setup_teardown(test_scs_in_place, setup, teardown),
        cmocka_unit_test_setup_teardown(test_world_boxes_apart, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
