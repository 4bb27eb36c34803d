/* SPDX-License-Identifier: MIT */
/* CSG technique "goldfeather": Goldfeather's stencil parity method on any
 * compatibility context from GL 1.1 up. Per term of a product's normal
 * form, per primitive of the term, per layer of its candidate surface (its
 * front faces, or its back faces where it is complemented):
 *   1. the layer: depth and stencil cleared, the candidate faces drawn with
 *      depth ALWAYS and a stencil test EQUAL k - 1 that counts every
 *      fragment (fail and pass INCR), so the k-th fragment of each pixel in
 *      rasterisation order writes its depth (any order: every layer is
 *      tried). The first layer's stencil holds the depth complexity: its
 *      maximum, read back, is the number of layers (at most 255);
 *   2. parity: each other primitive of the term drawn whole with depth LESS
 *      (its faces in front of the candidate) inverting its own stencil bit,
 *      eight primitives a batch (the stencil's bits: no counter overflows,
 *      whatever the primitive count); read back, a pixel survives where
 *      every bit says inside for a plain primitive and outside for a
 *      complemented one. Past eight, where the stencil wraps both ways in
 *      one pass, convex primitives count by winding numbers instead, 255 a
 *      batch (count_others);
 *   3. the surviving depths are kept, the nearest per pixel.
 * A convex primitive's candidate surface has one layer: its depth
 * complexity is not sampled. Complemented convex candidates whose window
 * rectangles lie apart are taken together (a group): steps 1-3 run once
 * for all of them, with every literal but the members counted. Where the
 * candidates and the result are kept is csg/merge.c's: on GLSL tiers with
 * FBOs and depth textures in depth textures on the GPU, else on the CPU
 * (csg/pixels.c). Which products come here is csg/resolve.c's choice. */
#include "csg/csg_private.h"

#ifndef OFFSET_UNITS
#define OFFSET_UNITS 4.0f
#endif
#define GL_INVERT 0x150A

typedef stin__csg_pixels resolve; /* csg.h: shared with csg/scs.c */

/* ---- passes ----------------------------------------------------------------- */
/* Clears keep to the resolve's region (at most the viewport: a light's map
 * resolves a corner of a buffer it shares, csg/cast.c). */
void stin__csg_clear(stin_context *ctx, GLbitfield bits)
{
    stin__pass_state ps = stin__pass_defaults;
    ps.color_write = 0;
    stin__csg_region_keep_to(ctx, &ps);
    stin__pass_apply(ctx, &ps); /* depth and stencil writes on */
    GL(ctx, Clear)(bits);
}

/* The face a primitive does not show (culled): it shows its front faces,
 * or its back faces where it is complemented; a mirroring transform swaps
 * which winding is front. */
GLenum stin__csg_culled_face(const stin__draw *d, int complemented)
{
    int mirrored = stin__mat4_det(d->transform) < 0.0;
    return (complemented != mirrored) ? GL_FRONT : GL_BACK;
}

/* Layer k (from 1) of a candidate surface (d's faces but `culled`) into
 * the cleared depth. */
static void draw_layer(stin_context *ctx, const stin__path *path, const stin__draw *d,
                       GLenum culled, int k)
{
    stin__pass_state ps = stin__pass_defaults;
    ps.depth_test = 1;
    ps.depth_func = GL_ALWAYS;
    ps.color_write = 0;
    ps.cull = 1;
    ps.cull_face = culled;
    ps.stencil_test = 1;
    ps.front.func = GL_EQUAL;
    ps.front.ref = k - 1;
    ps.front.mask = 0xffu;
    ps.front.fail = ps.front.zfail = ps.front.zpass = GL_INCR;
    ps.back = ps.front;
    stin__csg_region_keep_to(ctx, &ps);
    stin__pass_apply(ctx, &ps);
    path->geometry(ctx, d);
    ctx->stats.passes++;
}

/* How a term's parity is counted: the faces in front of the candidate, or
 * (a primitive the near plane cuts) the faces behind it, depth-clamped
 * where the context can (csg/near.c). */
typedef struct counting {
    int behind, clamp;
} counting;

/* A pass over primitive d whole (both faces), counting where its faces lie
 * in front of the candidate's depth (behind it, counting from behind):
 * the stencil ops are the caller's. Faces that coincide with the candidate
 * count as crossed before it, whatever their rounding: a subtracted box
 * sharing the candidate's plane takes it away, an intersected one keeps it,
 * a neighbour's face touching it cancels out (the reference applies
 * crossings at one distance together). Pulled toward the eye by 4 units:
 * faces that near are the same plane (and, counted from behind, not behind
 * it). */
static stin__pass_state counting_pass(const stin_context *ctx, const counting *how)
{
    stin__pass_state ps = stin__pass_defaults;
    ps.depth_test = 1;
    ps.depth_func = how->behind ? GL_GREATER : GL_LESS;
    ps.depth_clamp = (unsigned char)how->clamp;
    ps.depth_write = 0;
    ps.color_write = 0;
    ps.stencil_test = 1;
    ps.front.func = GL_ALWAYS;
    ps.front.mask = 0xffu;
    ps.front.fail = ps.front.zfail = GL_KEEP;
    ps.polygon_offset = 1;
    ps.offset_factor = 0.0f;
    ps.offset_units = -OFFSET_UNITS;
    stin__csg_region_keep_to(ctx, &ps);
    return ps;
}

/* Primitive d whole, toggling stencil bit `bit` where its faces lie in front
 * of the candidate's depth (behind it, counting from behind). */
static void draw_parity(stin_context *ctx, const stin__path *path, const stin__draw *d, int bit,
                        const counting *how)
{
    stin__pass_state ps = counting_pass(ctx, how);
    ps.stencil_write_mask = 1u << bit;
    ps.front.zpass = GL_INVERT;
    ps.back = ps.front;
    stin__pass_apply(ctx, &ps);
    path->geometry(ctx, d);
}

/* Convex primitive d whole, adding its winding number about the
 * candidate's depth to the stencil, wrapping: +1 where its front face lies
 * in front of the depth, -1 where its back face does (from behind: the
 * other way round), 1 inside d and 0 outside; negated for a plain literal.
 * Both faces in one pass (two-sided stencil). */
static void draw_winding(stin_context *ctx, const stin__path *path, const stin__draw *d,
                         int plain, const counting *how)
{
    stin__pass_state ps = counting_pass(ctx, how);
    int front_is_gl_front = stin__csg_culled_face(d, 0) == GL_BACK; /* not mirrored */
    GLenum at_front = plain == how->behind ? GL_INCR_WRAP : GL_DECR_WRAP;
    GLenum at_back = at_front == GL_INCR_WRAP ? GL_DECR_WRAP : GL_INCR_WRAP;
    ps.two_sided = 1;
    ps.back = ps.front;
    ps.front.zpass = front_is_gl_front ? at_front : at_back;
    ps.back.zpass = front_is_gl_front ? at_back : at_front;
    stin__pass_apply(ctx, &ps);
    path->geometry(ctx, d);
}

/* The candidate's pixels that a batch of the term's other literals keeps. */
static void parity_batch(stin_context *ctx, const stin__path *path, resolve *r,
                         const stin__csg_product *p, const uint32_t *lits, uint32_t n,
                         const counting *how)
{
    unsigned char want = 0, mask = 0;
    uint32_t j;
    stin__csg_clear(ctx, GL_STENCIL_BUFFER_BIT);
    for (j = 0; j < n; j++) {
        const stin__draw *d =
            &ctx->csg->primitives[p->first_primitive + STIN__CSG_PRIMITIVE_OF(lits[j])];
        draw_parity(ctx, path, d, (int)j, how);
        mask |= (unsigned char)(1u << j);
        if (!STIN__CSG_COMPLEMENTED(lits[j]))
            want |= (unsigned char)(1u << j); /* odd: inside */
    }
    ctx->stats.passes++;
    stin__csg_candidate_keep_where(ctx, path, r, mask, want);
}

/* Where a candidate surface can lie: its window rectangle and, for a
 * literal's surface (not the near-plane cap), its world box. */
typedef struct extent {
    float rect[4], box[6];
    int has_box;
} extent;

/* Whether literal `lit` can matter for the candidate within `own`: 0 when
 * their rectangles or their world boxes do not meet (csg/bounds.c). */
static int meets(stin_context *ctx, const stin__csg_product *p, uint32_t lit, const extent *own)
{
    const stin__draw *d = &ctx->csg->primitives[p->first_primitive + STIN__CSG_PRIMITIVE_OF(lit)];
    float rect[4], box[6];
    stin__csg_screen_rect(ctx, d, rect);
    if (!stin__csg_rects_meet(ctx, own->rect, rect))
        return 0;
    if (!own->has_box)
        return 1;
    stin__csg_world_box(ctx, d, box);
    return stin__csg_world_boxes_meet(own->box, box);
}

/* Candidates taken together: surfaces whose window rectangles lie apart (a
 * pixel's margin) share one set of passes, since no pixel holds a layer of
 * two of them; each set of passes costs llvmpipe a wait where it switches
 * framebuffers (OpenCSG batches its primitives alike). At most GROUP_MAX
 * members, picked from the next LOOKAHEAD literals of the term. */
#define GROUP_MAX 32u
#define LOOKAHEAD 64u

/* A group's members: their literal indices in the term (t->count: the
 * near-plane cap, alone), their extents, and the union of their regions
 * (each its rectangle cut to every plain literal's; normalised device). */
typedef struct group {
    uint32_t count;
    uint32_t self[GROUP_MAX];
    extent own[GROUP_MAX];
    float bound[4];
} group;

static int is_member(const group *g, uint32_t j)
{
    uint32_t i;
    for (i = 0; i < g->count; i++)
        if (g->self[i] == j)
            return 1;
    return 0;
}

/* Whether literal `lit` can matter for a member of g (meets). */
static int meets_group(stin_context *ctx, const stin__csg_product *p, uint32_t lit, const group *g)
{
    const stin__draw *d = &ctx->csg->primitives[p->first_primitive + STIN__CSG_PRIMITIVE_OF(lit)];
    float rect[4], box[6];
    uint32_t i;
    stin__csg_screen_rect(ctx, d, rect);
    stin__csg_world_box(ctx, d, box);
    for (i = 0; i < g->count; i++)
        if (stin__csg_rects_meet(ctx, g->own[i].rect, rect) &&
            (!g->own[i].has_box || stin__csg_world_boxes_meet(g->own[i].box, box)))
            return 1;
    return 0;
}

static int winds(const stin_context *ctx, const stin__csg_product *p, uint32_t lit)
{
    const stin__draw *d = &ctx->csg->primitives[p->first_primitive + STIN__CSG_PRIMITIVE_OF(lit)];
    return ctx->meshes[d->mesh_slot].info.convex;
}

/* The candidate's pixels that the next batch of the term's convex literals
 * from index `from` on (meeting `own`, not `self`) keeps: their winding
 * numbers summed, at most 2^bits - 1 of them so that the sums' values
 * differ modulo the stencil's range; a pixel lies inside every plain one
 * and no complemented one exactly where the sum is minus the plain count.
 * Returns the index after the batch's last literal; *drawn: how many. */
static uint32_t winding_batch(stin_context *ctx, const stin__path *path, resolve *r,
                              const stin__csg_product *p, const stin__csg_term *t,
                              const group *g, const counting *how, uint32_t from,
                              uint32_t *drawn)
{
    unsigned most = (1u << r->bits) - 1u;
    uint32_t j, n = 0, plain = 0;
    stin__csg_clear(ctx, GL_STENCIL_BUFFER_BIT);
    for (j = from; j < t->count && n < most; j++) {
        uint32_t lit = ctx->csg->literals[t->first + j];
        if (is_member(g, j) || !winds(ctx, p, lit) || !meets_group(ctx, p, lit, g))
            continue;
        draw_winding(ctx, path,
                     &ctx->csg->primitives[p->first_primitive + STIN__CSG_PRIMITIVE_OF(lit)],
                     !STIN__CSG_COMPLEMENTED(lit), how);
        plain += !STIN__CSG_COMPLEMENTED(lit);
        n++;
    }
    ctx->stats.passes++;
    stin__csg_candidate_keep_where(ctx, path, r, most, (0u - plain) & most);
    *drawn = n;
    return j;
}

/* The candidate's pixels that the term's other literals (those meeting a
 * member of g) keep: by parity bits, a stencil bit each, or where that
 * takes fewer batches (and the stencil wraps both ways in one pass), the
 * convex ones by winding numbers, 255 a batch, and the rest by parity. A
 * literal drawn over a member it cannot matter for counts what it is
 * there (outside), so a group's members share the passes; its faces
 * within the offset of a member's depth count as crossed, as every
 * literal's do (counting_pass). */
static void count_others(stin_context *ctx, const stin__path *path, resolve *r,
                         const stin__csg_product *p, const stin__csg_term *t, const group *g,
                         const counting *how)
{
    uint32_t others[8], n = 0, j, meeting = 0, wound = 0, drawn, bits = (uint32_t)r->bits;
    int winding = stin__pass_two_sided_wrap(ctx) && bits >= 2;
    if (winding) {
        uint32_t most = (1u << bits) - 1u;
        for (j = 0; j < t->count; j++) {
            uint32_t lit = ctx->csg->literals[t->first + j];
            if (!is_member(g, j) && meets_group(ctx, p, lit, g)) {
                meeting++;
                wound += (uint32_t)winds(ctx, p, lit);
            }
        }
        winding = (wound + most - 1u) / most + (meeting - wound + bits - 1u) / bits <
                  (meeting + bits - 1u) / bits;
    }
    for (j = 0; winding && wound; wound -= drawn) {
        j = winding_batch(ctx, path, r, p, t, g, how, j, &drawn);
        if (!drawn) /* the count above saw the same literals: not reached */
            break;
    }
    for (j = 0; j < t->count; j++) {
        uint32_t lit = ctx->csg->literals[t->first + j];
        if (is_member(g, j) || (winding && winds(ctx, p, lit)) || !meets_group(ctx, p, lit, g))
            continue;
        others[n++] = lit;
        if (n == bits) {
            parity_batch(ctx, path, r, p, others, n, how);
            n = 0;
        }
    }
    if (n)
        parity_batch(ctx, path, r, p, others, n, how);
}

/* The layer count of the surface just drawn as layer 1 (its stencil holds
 * every pixel's fragment count), or a bound above it. */
static int depth_complexity(stin_context *ctx, const stin__path *path, resolve *r)
{
    unsigned most = stin__csg_stencil_max(ctx, path, r, 255u);
    if (most == 255u && !ctx->csg->said_layers && !ctx->csg->no_readback) {
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "goldfeather: a primitive is 255 or more layers deep; layers past "
                  "255 are not drawn");
        ctx->csg->said_layers = 1;
    }
    return (int)most;
}

/* Whether the surface of the term's literal `self` (t->count: the cap's,
 * d) can hold a pixel of the term: off its rectangle or box a plain
 * literal leaves nothing there (a complemented one is outside: no pass).
 * Its extent into *own, its region (its rectangle cut to every plain
 * literal's: the surface lies inside each) into region. */
static int admit(stin_context *ctx, const stin__csg_product *p, const stin__csg_term *t,
                 uint32_t self, const stin__draw *d, extent *own, float region[4])
{
    uint32_t j;
    int box[4];
    stin__csg_screen_rect(ctx, d, own->rect);
    own->has_box = self < t->count;
    if (own->has_box)
        stin__csg_world_box(ctx, d, own->box);
    stin__memcopy(region, own->rect, 4 * sizeof *region);
    for (j = 0; j < t->count; j++) {
        uint32_t lit = ctx->csg->literals[t->first + j];
        float rect[4];
        if (j == self || STIN__CSG_COMPLEMENTED(lit))
            continue;
        if (!meets(ctx, p, lit, own))
            return 0;
        stin__csg_screen_rect(ctx, &ctx->csg->primitives[p->first_primitive +
                                                        STIN__CSG_PRIMITIVE_OF(lit)], rect);
        stin__csg_rect_cut(region, rect);
    }
    return stin__csg_window_box(ctx, region, box);
}

static const stin__draw *member_draw(const stin_context *ctx, const stin__csg_product *p,
                                     const stin__csg_term *t, uint32_t self, GLenum *culled)
{
    uint32_t lit = ctx->csg->literals[t->first + self];
    const stin__draw *d = &ctx->csg->primitives[p->first_primitive + STIN__CSG_PRIMITIVE_OF(lit)];
    *culled = stin__csg_culled_face(d, (int)STIN__CSG_COMPLEMENTED(lit));
    return d;
}

/* The candidate surfaces of group g of term t (or, where cap is not NULL,
 * the cap's, g's one member): every layer, tested against the term's
 * other literals, kept where nearer. Returns whether it kept any pixel
 * (where want_kept asks: csg/merge.c's take). Nothing outside the union
 * of the members' regions is read (on the GPU) or read back: the passes
 * keep to it. */
static int take_group(stin_context *ctx, const stin__path *path, resolve *r,
                      const stin__csg_product *p, const stin__csg_term *t, const group *g,
                      const stin__draw *cap, const counting *how, int want_kept)
{
    uint32_t i;
    int layers = 1, k, kept = 0, one_layer = 1;
    stin__csg_surface surface;
    GLenum culled = GL_BACK; /* the cap's quad faces the window whatever the camera mirrors */
    const stin__draw *d = cap;
    if (!cap) { /* a convex surface shows one layer a pixel; a group's members are convex */
        d = member_draw(ctx, p, t, g->self[0], &culled);
        one_layer = g->count > 1 || ctx->meshes[d->mesh_slot].info.convex;
    }
    surface.p = p;
    surface.t = t;
    surface.list = cap ? NULL : g->self;
    surface.first = 0;
    surface.count = cap ? 0 : g->count;
    surface.cap = cap;
    surface.cap_culled = culled;
    stin__csg_region_reset(ctx);
    if (!stin__csg_region_narrow(ctx, g->bound))
        return 0;
    for (k = 1; k <= layers; k++) {
        stin__csg_clear(ctx, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        for (i = 0; i < g->count; i++) {
            if (!cap)
                d = member_draw(ctx, p, t, g->self[i], &culled);
            draw_layer(ctx, path, d, culled, k);
        }
        if (k == 1 && !one_layer) /* every fragment counted: the depth complexity */
            layers = depth_complexity(ctx, path, r);
        if (!stin__csg_candidate_open(ctx, r)) /* no layer, or none nearer */
            continue;
        count_others(ctx, path, r, p, t, g, how);
        kept |= stin__csg_candidate_take(ctx, path, r, NULL, &surface, want_kept);
    }
    if (g->count > 1)
        ctx->stats.csg.grouped += g->count;
    return kept;
}

/* Whether literal `li` of the term may share a group: a complemented
 * convex one (one layer). Two admitted members lie apart, and a plain one
 * apart from another member would leave that one nothing (admit), so
 * only complemented literals gain from sharing. */
static int groups(const stin_context *ctx, const stin__csg_product *p, const stin__csg_term *t,
                  uint32_t li)
{
    uint32_t lit = ctx->csg->literals[t->first + li];
    return STIN__CSG_COMPLEMENTED(lit) && winds(ctx, p, lit);
}

/* Whether rectangle rect lies apart from every member of g. */
static int apart(const stin_context *ctx, const group *g, const float rect[4])
{
    uint32_t i;
    for (i = 0; i < g->count; i++)
        if (stin__csg_rects_meet(ctx, g->own[i].rect, rect))
            return 0;
    return 1;
}

/* The next group of term t from the pending literals (pending[0..*n)): the
 * first admitted one, and where it groups, every later admitted one that
 * groups and lies apart from those taken, up to GROUP_MAX; literals not
 * admitted are dropped, the rest stay pending (compacted in place). */
static void next_group(stin_context *ctx, const stin__csg_product *p, const stin__csg_term *t,
                       uint32_t *pending, uint32_t *n, group *g)
{
    uint32_t i, kept = 0;
    int open = 1;
    g->count = 0;
    g->bound[0] = g->bound[1] = 1e30f;
    g->bound[2] = g->bound[3] = -1e30f;
    for (i = 0; i < *n; i++) {
        uint32_t li = pending[i];
        GLenum culled;
        const stin__draw *d = member_draw(ctx, p, t, li, &culled);
        extent own;
        float region[4];
        int k;
        if (!open || (g->count && !groups(ctx, p, t, li))) {
            pending[kept++] = li;
            continue;
        }
        stin__csg_screen_rect(ctx, d, own.rect);
        if (g->count && !apart(ctx, g, own.rect)) {
            pending[kept++] = li;
            continue;
        }
        if (!admit(ctx, p, t, li, d, &own, region))
            continue; /* its surface holds no pixel of the term */
        g->self[g->count] = li;
        g->own[g->count++] = own;
        for (k = 0; k < 2; k++) {
            g->bound[k] = region[k] < g->bound[k] ? region[k] : g->bound[k];
            g->bound[2 + k] = region[2 + k] > g->bound[2 + k] ? region[2 + k] : g->bound[2 + k];
        }
        open = g->count < GROUP_MAX && groups(ctx, p, t, li);
    }
    *n = kept;
}

/* How term t counts, and whether the near plane may lie inside it (every
 * plain literal's box cut by the near plane): then it has a cap candidate.
 * Counting from behind needs the far plane to cut nothing, or depth
 * clamping; where the near plane and the far plane both cut and there is
 * none, the term counts from the front (logged once). */
static int term_counting(stin_context *ctx, const stin__csg_product *p, const stin__csg_term *t,
                         counting *how)
{
    int any_near = 0, any_far = 0, plain_all_near = 1;
    uint32_t j;
    how->behind = how->clamp = 0;
    for (j = 0; j < t->count; j++) {
        uint32_t lit = ctx->csg->literals[t->first + j];
        int near_cut, far_cut;
        stin__csg_planes_cut(ctx, &ctx->csg->primitives[p->first_primitive +
                                                         STIN__CSG_PRIMITIVE_OF(lit)],
                             &near_cut, &far_cut);
        any_near |= near_cut;
        any_far |= far_cut;
        if (!STIN__CSG_COMPLEMENTED(lit) && !near_cut)
            plain_all_near = 0;
    }
    if (!any_near)
        return 0;
    how->clamp = any_far && (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_DEPTH_CLAMP)) != 0;
    if (any_far && !how->clamp) {
        if (!ctx->csg->said_planes) {
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                      "goldfeather: the near and the far plane both cut a product's primitive "
                      "and the context has no depth clamp; where the eye is inside it the "
                      "product is wrong (move the far plane out)");
            ctx->csg->said_planes = 1;
        }
        return 0;
    }
    how->behind = 1;
    return plain_all_near && ctx->csg->cap_usable;
}

/* Every candidate of product p: each literal's surface of each term, and
 * the near-plane cap where a term may hold the near plane. */
void stin__csg_goldfeather_product(stin_context *ctx, const stin__path *path, resolve *r,
                                  stin__csg_product *p)
{
    uint32_t ti, li;
    p->capped = 0;
    for (ti = 0; ti < p->term_count; ti++) {
        const stin__csg_term *t = &ctx->csg->terms[p->first_term + ti];
        counting how;
        int cap = term_counting(ctx, p, t, &how);
        uint32_t pending[LOOKAHEAD], n = 0;
        group g;
        li = 0;
        while (li < t->count || n) {
            while (n < LOOKAHEAD && li < t->count)
                pending[n++] = li++;
            next_group(ctx, p, t, pending, &n, &g);
            if (g.count)
                (void)take_group(ctx, path, r, p, t, &g, NULL, &how, 0);
        }
        if (cap) {
            stin__draw d = ctx->csg->primitives[p->first_primitive];
            float region[4];
            d.mesh_slot = ctx->csg->cap_slot;
            stin__memcopy(d.transform, ctx->csg->cap_transform, sizeof d.transform);
            g.count = 1;
            g.self[0] = t->count;
            if (admit(ctx, p, t, t->count, &d, &g.own[0], region)) {
                stin__memcopy(g.bound, region, sizeof g.bound);
                p->capped |= take_group(ctx, path, r, p, t, &g, &d, &how, 1);
            }
        }
    }
}
