/* SPDX-License-Identifier: MIT */
/* A CSG tree as Goldfeather's sum of products: a union of terms, each an
 * intersection of literals (a primitive or its complement). The rules, with
 * !x the complement:
 *   nf(a u b)  = nf(a) + nf(b)           nf(!(a u b)) = nf(!a) x nf(!b)
 *   nf(a n b)  = nf(a) x nf(b)           nf(!(a n b)) = nf(!a) + nf(!b)
 *   nf(a - b)  = nf(a) x nf(!b)          nf(!(a - b)) = nf(!a) + nf(b)
 * where + joins two term lists and x intersects every pair of terms. Lists
 * are built on a stack of words in the scratch (a term is its length, then
 * its sorted literals); a cross product is written above its operands and
 * moved down over them, so the scratch holds one chain of partial results,
 * never a heap. An operation on one node twice is that node (a u a = a n a
 * = a; a - a is empty): a tree doubled level by level stays one term, and a
 * term the list already holds is dropped at the end (a chain that unions the
 * same primitive in again and again is one term of it, not one per use:
 * every term costs a pass per light face when products cast). The work is
 * counted (STIN__CSG_MAX_WORK): a shared subtree is expanded at each use,
 * and a cross product of two long lists may leave nothing. */
#include "internal.h"

typedef struct nf_work {
    const stin_csg_node *nodes;
    uint32_t *w;
    uint32_t size, top, peak;
    uint64_t work;          /* steps so far (STIN__CSG_MAX_WORK) */
    stin__csg_nf_result failed;
} nf_work;

static void push(nf_work *k, uint32_t v)
{
    if (k->top >= k->size) {
        if (!k->failed)
            k->failed = STIN__CSG_NF_SCRATCH;
        return;
    }
    k->w[k->top++] = v;
    if (k->top > k->peak)
        k->peak = k->top;
}

/* Adds steps; past the limit the normalisation stops. */
static int spend(nf_work *k, uint64_t steps)
{
    k->work += steps;
    if (k->work > STIN__CSG_MAX_WORK && !k->failed)
        k->failed = STIN__CSG_NF_WORK;
    return !k->failed;
}

/* The term a n b (both sorted) at the top of the stack; nothing when it
 * holds a primitive and its complement (it is empty). */
static void push_conjunction(nf_work *k, uint32_t a, uint32_t b)
{
    uint32_t na = k->w[a], nb = k->w[b], i = 0, j = 0, len_at = k->top, last = UINT32_MAX;
    push(k, 0);
    while (!k->failed && (i < na || j < nb)) {
        uint32_t la = i < na ? k->w[a + 1 + i] : UINT32_MAX;
        uint32_t lb = j < nb ? k->w[b + 1 + j] : UINT32_MAX;
        uint32_t l = la < lb ? la : lb;
        if (la == l)
            i++;
        if (lb == l)
            j++;
        if (l == last)
            continue; /* in both terms: once */
        if (last != UINT32_MAX && STIN__CSG_PRIMITIVE_OF(l) == STIN__CSG_PRIMITIVE_OF(last)) {
            k->top = len_at; /* p and !p: the term is empty */
            return;
        }
        push(k, l);
        last = l;
    }
    if (!k->failed)
        k->w[len_at] = k->top - len_at - 1;
}

static void normal_form(nf_work *k, uint32_t node, int complement, uint32_t depth);

/* nf(x) x nf(y), left where nf(x) began. */
static void cross(nf_work *k, uint32_t x, int cx, uint32_t y, int cy, uint32_t depth)
{
    uint32_t a0 = k->top, b0, r0, a, b;
    normal_form(k, x, cx, depth);
    b0 = k->top;
    normal_form(k, y, cy, depth);
    r0 = k->top;
    for (a = a0; a < b0 && !k->failed; a += 1 + k->w[a])
        for (b = b0; b < r0 && spend(k, 1u + k->w[a] + k->w[b]); b += 1 + k->w[b])
            push_conjunction(k, a, b);
    if (k->failed)
        return;
    for (a = r0; a < k->top; a++) /* down over the operands (forward: r0 > a0) */
        k->w[a0 + (a - r0)] = k->w[a];
    k->top = a0 + (k->top - r0);
}

static void normal_form(nf_work *k, uint32_t node, int complement, uint32_t depth)
{
    const stin_csg_node *n = &k->nodes[node];
    if (k->failed)
        return;
    if (depth >= STIN__CSG_MAX_DEPTH) {
        k->failed = STIN__CSG_NF_DEPTH;
        return;
    }
    if (!spend(k, 1))
        return;
    if (n->op != STIN_CSG_PRIMITIVE && n->a == n->b) {
        uint32_t at = k->top;
        normal_form(k, n->a, complement, depth + 1); /* a u a = a n a = a, and its complement */
        if (n->op == STIN_CSG_SUBTRACTION && !complement)
            k->top = at; /* a - a is empty (a was expanded for its checks) */
        else if (n->op == STIN_CSG_SUBTRACTION)
            normal_form(k, n->a, 0, depth + 1); /* !(a - a) = !a + a */
        return;
    }
    switch (n->op) {
    case STIN_CSG_PRIMITIVE:
        push(k, 1);
        push(k, STIN__CSG_LITERAL(n->primitive, complement));
        break;
    case STIN_CSG_UNION:
        if (complement) {
            cross(k, n->a, 1, n->b, 1, depth + 1);
        } else {
            normal_form(k, n->a, 0, depth + 1);
            normal_form(k, n->b, 0, depth + 1);
        }
        break;
    case STIN_CSG_INTERSECTION:
        if (complement) {
            normal_form(k, n->a, 1, depth + 1);
            normal_form(k, n->b, 1, depth + 1);
        } else {
            cross(k, n->a, 0, n->b, 0, depth + 1);
        }
        break;
    case STIN_CSG_SUBTRACTION:
        if (complement) {
            normal_form(k, n->a, 1, depth + 1);
            normal_form(k, n->b, 0, depth + 1);
        } else {
            cross(k, n->a, 0, n->b, 1, depth + 1);
        }
        break;
    }
}

/* 1 if the terms at a and b hold the same literals (both sorted). */
static int same_term(const uint32_t *w, uint32_t a, uint32_t b)
{
    uint32_t i;
    if (w[a] != w[b])
        return 0;
    for (i = 1; i <= w[a]; i++)
        if (w[a + i] != w[b + i])
            return 0;
    return 1;
}

/* Drops every term an earlier term repeats, moving the rest down in order.
 * Pairwise, so only for lists short enough (REPEAT_PAIRS); a longer list
 * keeps its repeats (the same union, drawn once more). */
#define REPEAT_PAIRS (1u << 22)
static void drop_repeated_terms(nf_work *k)
{
    uint32_t t, kept = 0, s, i, terms = 0;
    for (t = 0; t < k->top; t += 1 + k->w[t])
        terms++;
    if ((uint64_t)terms * terms / 2u > REPEAT_PAIRS)
        return;
    for (t = 0; t < k->top;) {
        uint32_t len = 1 + k->w[t];
        int repeated = 0;
        for (s = 0; s < kept && !repeated; s += 1 + k->w[s])
            repeated = same_term(k->w, s, t);
        if (!repeated) {
            for (i = 0; i < len; i++) /* down (kept <= t) */
                k->w[kept + i] = k->w[t + i];
            kept += len;
        }
        t += len;
    }
    k->top = kept;
}

stin__csg_nf_result stin__csg_normal_form(const stin_csg_node *nodes, uint32_t node_count,
                                          uint32_t *scratch, uint32_t scratch_words,
                                          stin__csg_out *out)
{
    nf_work k;
    uint32_t t, terms = 0, literals = 0;
    out->term_count = out->literal_count = 0;
    k.nodes = nodes;
    k.w = scratch;
    k.size = scratch_words;
    k.top = k.peak = 0;
    k.work = 0;
    k.failed = STIN__CSG_NF_OK;
    normal_form(&k, node_count - 1u, 0, 0);
    if (!k.failed)
        drop_repeated_terms(&k);
    out->scratch_peak = k.peak;
    if (k.failed)
        return k.failed;
    for (t = 0; t < k.top; t += 1 + k.w[t]) {
        terms++;
        literals += k.w[t];
    }
    if (!out->terms) { /* measured only */
        out->term_count = terms;
        out->literal_count = literals;
        return STIN__CSG_NF_OK;
    }
    if (terms > out->max_terms)
        return STIN__CSG_NF_TERMS;
    if (literals > out->max_literals)
        return STIN__CSG_NF_LITERALS;
    for (t = 0; t < k.top; t += 1 + k.w[t]) {
        stin__csg_term *term = &out->terms[out->term_count++];
        term->first = out->literal_base + out->literal_count;
        term->count = k.w[t];
        stin__memcopy(out->literals + out->literal_count, k.w + t + 1, k.w[t] * sizeof(uint32_t));
        out->literal_count += k.w[t];
    }
    return STIN__CSG_NF_OK;
}
