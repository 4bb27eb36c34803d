/* SPDX-License-Identifier: MIT */
/* CSG technique "scs": sequenced convex subtraction (Rappoport and Spitz;
 * Stewart, Leach and John) for products whose primitives are all convex
 * (stin_mesh_info.convex), on any context with a stencil buffer. Per term
 * of the product's normal form, in the frame's depth and stencil buffers:
 *   1. intersect: depth cleared to 0, the plain primitives' front faces
 *      drawn with depth GREATER: the farthest front face, where a convex
 *      intersection begins;
 *   2. subtract: the complemented primitives in sequence, front to back,
 *      each pushing the depth to its back face where the depth lies
 *      inside it (its front in front of the depth, its back not); the list
 *      is run at most as many times as complemented primitives can cover
 *      one pixel (from their window boxes), so every order of those is in
 *      the sequence, and a run after the first only where a check (a
 *      stencil count of the primitives the depth lies in) finds one;
 *   3. clip: a pixel survives where the depth lies in front of every plain
 *      primitive's back face, counted in the stencil 255 primitives a batch
 *      (no counter overflows), each batch read back.
 * The surviving depth is kept per pixel where nearer, in goldfeather's
 * result (csg/merge.c: on the GPU, or read back once a term), which writes
 * it into the frame's depth.
 * Faces that coincide with the depth (within 4 depth units) count as in
 * front of it: a subtracted box sharing a face's plane takes it away, one
 * touching it from outside does not, an intersected one ending there
 * leaves nothing (the exact reference's rule for crossings at one
 * distance). Passes a term: plain + 2 x complemented x runs (3 without
 * two-sided stencil) + complemented x (runs - 1) checks + plain;
 * read-backs on the CPU: the depth, one stencil a check, one each 255
 * plain primitives; on the GPU one wait a check. On the GPU the term's
 * passes keep to the rectangle of its plain primitives' overlap
 * (csg/bounds.c's region). */
#include "csg/csg_private.h"

#ifndef OFFSET_UNITS
#define OFFSET_UNITS 4.0f
#endif
#define BATCH 255u

/* Every primitive of p convex, and every term with a plain primitive. */
static const char *unfit(const stin_context *ctx, const stin__csg_product *p)
{
    const stin__csg_state *c = ctx->csg;
    uint32_t q, ti, li;
    for (q = 0; q < p->primitive_count; q++) {
        const stin__draw *d = &c->primitives[p->first_primitive + q];
        int near_cut, far_cut;
        if (!ctx->meshes[d->mesh_slot].info.convex)
            return "a primitive's mesh is not convex (stin_mesh_info.convex)";
        /* the sequence starts from the front faces the near plane would cut */
        stin__csg_planes_cut(ctx, d, &near_cut, &far_cut);
        if (near_cut)
            return "the near plane cuts a primitive (goldfeather counts from behind and caps)";
    }
    for (ti = 0; ti < p->term_count; ti++) {
        const stin__csg_term *t = &c->terms[p->first_term + ti];
        int plain = 0;
        for (li = 0; li < t->count; li++)
            plain |= !STIN__CSG_COMPLEMENTED(c->literals[t->first + li]);
        if (!plain)
            return "a term has no plain primitive";
    }
    return NULL;
}

static const stin__draw *primitive_of(const stin_context *ctx, const stin__csg_product *p,
                                      uint32_t literal)
{
    return &ctx->csg->primitives[p->first_primitive + STIN__CSG_PRIMITIVE_OF(literal)];
}

/* A pass over the depth with colour writes off; `shown` is the face kept. */
static stin__pass_state faces(const stin_context *ctx, const stin__draw *d, int back,
                              GLenum depth_func, int depth_write)
{
    stin__pass_state ps = stin__pass_defaults;
    ps.color_write = 0;
    ps.depth_test = 1;
    ps.depth_func = depth_func;
    ps.depth_write = (unsigned char)depth_write;
    ps.cull = 1;
    ps.cull_face = stin__csg_culled_face(d, back);
    stin__csg_region_keep_to(ctx, &ps);
    return ps;
}

static void stencil(stin__pass_state *ps, GLenum func, GLint ref, GLenum fail, GLenum zfail,
                    GLenum zpass)
{
    ps->stencil_test = 1;
    ps->front.func = func;
    ps->front.ref = ref;
    ps->front.mask = 0xffu;
    ps->front.fail = fail;
    ps->front.zfail = zfail;
    ps->front.zpass = zpass;
    ps->back = ps->front;
}

/* Faces within OFFSET_UNITS of the depth count as in front of it. */
static void toward_eye(stin__pass_state *ps)
{
    ps->polygon_offset = 1;
    ps->offset_factor = 0.0f;
    ps->offset_units = -OFFSET_UNITS;
}

static void draw(stin_context *ctx, const stin__path *path, const stin__draw *d,
                 const stin__pass_state *ps)
{
    stin__pass_apply(ctx, ps);
    path->geometry(ctx, d);
    ctx->stats.passes++;
}

/* 1. the farthest front face of the term's plain primitives. */
static void intersect(stin_context *ctx, const stin__path *path, const stin__csg_product *p,
                      const stin__csg_term *t)
{
    uint32_t li;
    stin__clear_depth(ctx, 0.0);
    stin__csg_clear(ctx, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    stin__clear_depth(ctx, 1.0);
    for (li = 0; li < t->count; li++) {
        uint32_t lit = ctx->csg->literals[t->first + li];
        const stin__draw *d = primitive_of(ctx, p, lit);
        stin__pass_state ps = faces(ctx, d, 0, GL_GREATER, 1);
        if (!STIN__CSG_COMPLEMENTED(lit))
            draw(ctx, path, d, &ps);
    }
}

/* Which complemented literals of t can move the depth: those whose window
 * box meets the region. Their boxes go into the csg scratch (idle during
 * the resolve), 2 words a literal: x and y spans as 16-bit offsets from the
 * region's corner, an empty span where the literal is plain or off the
 * region. Returns how many, and in *bound how many runs the sequence
 * takes at most: 1 where every two whose boxes meet lie apart in the world,
 * else how many can cover one pixel, 1 + the most others one's box meets
 * (255 at most; past PAIRWISE listed literals, whose pairs would cost more
 * than they save, their count: the check ends the sequence where it is
 * done either way). */
#define OFF_REGION 0x0000ffffu /* first 0xffff, last 0: empty */
#define WHOLE_REGION 0xffff0000u
#define PAIRWISE 1024u

static int listed(const uint32_t *box, uint32_t li) { return box[2u * li] != OFF_REGION; }

static int boxes_meet(const uint32_t *a, const uint32_t *b)
{
    int k;
    for (k = 0; k < 2; k++)
        if ((a[k] & 0xffffu) > (b[k] >> 16) || (b[k] & 0xffffu) > (a[k] >> 16))
            return 0;
    return 1;
}

/* Literal li's box into box[2 li], box[2 li + 1]; 0 where it is off the
 * region. Spans past 65536 pixels (no GL has such viewports) are whole. */
static int box_of(const stin_context *ctx, const stin__draw *d, uint32_t *box)
{
    const int *region = ctx->csg->region;
    float rect[4];
    int b[4], k;
    if (region[2] > 0x10000 || region[3] > 0x10000) {
        box[0] = box[1] = WHOLE_REGION;
        return 1;
    }
    stin__csg_screen_rect(ctx, d, rect);
    if (!stin__csg_window_box(ctx, rect, b))
        return 0;
    for (k = 0; k < 2; k++) {
        int lo = b[k] - region[k], hi = b[k] + b[2 + k] - region[k];
        lo = lo < 0 ? 0 : lo;
        hi = hi > region[2 + k] ? region[2 + k] : hi;
        if (hi <= lo)
            return 0;
        box[k] = (uint32_t)lo | (uint32_t)(hi - 1) << 16;
    }
    return 1;
}

/* Whether two listed literals lie apart in the world (csg/bounds.c), by
 * more than the offset that lets a face count as in front of the depth:
 * their solids share no point, nor does a face of the one come within
 * reach of a face of the other. */
static int apart(stin_context *ctx, const stin__csg_product *p, const stin__csg_term *t,
                 uint32_t li, uint32_t lj)
{
    float a[6], b[6];
    stin__csg_world_box(ctx, primitive_of(ctx, p, ctx->csg->literals[t->first + li]), a);
    stin__csg_world_box(ctx, primitive_of(ctx, p, ctx->csg->literals[t->first + lj]), b);
    return stin__csg_world_boxes_apart(ctx, a, b, 2.0f * OFFSET_UNITS);
}

/* Whether every two listed literals whose boxes meet lie apart: then a
 * pixel's depth, pushed out of one, lies inside no other, and one run in
 * any order takes it out of all (a drilled plate's holes). Each pair's
 * world test costs 32 corner transforms: past APART_TESTS of them (a long
 * row of primitives along the view, whose boxes all meet) the answer is
 * no, and the sequence keeps its bound and its checks. */
#define APART_TESTS 16384u

static int untangled(stin_context *ctx, const stin__csg_product *p, const stin__csg_term *t,
                     const uint32_t *box)
{
    uint32_t li, lj, tests = 0;
    for (li = 0; li < t->count; li++) {
        if (!listed(box, li))
            continue;
        for (lj = li + 1u; lj < t->count; lj++)
            if (listed(box, lj) && boxes_meet(&box[2u * li], &box[2u * lj]) &&
                (++tests > APART_TESTS || !apart(ctx, p, t, li, lj)))
                return 0;
    }
    return 1;
}

static uint32_t list_complemented(stin_context *ctx, const stin__csg_product *p,
                                  const stin__csg_term *t, unsigned *bound)
{
    uint32_t *box = ctx->csg->scratch, li, lj, n = 0, most = 0;
    for (li = 0; li < t->count; li++) {
        uint32_t lit = ctx->csg->literals[t->first + li];
        if (!STIN__CSG_COMPLEMENTED(lit) || !box_of(ctx, primitive_of(ctx, p, lit), &box[2u * li]))
            box[2u * li] = box[2u * li + 1u] = OFF_REGION;
        else
            n++;
    }
    if (n > PAIRWISE) {
        most = n;
    } else if (n > 1u && untangled(ctx, p, t, box)) {
        *bound = 1u;
        return n;
    }
    for (li = 0; li < t->count && most < 255u; li++) {
        uint32_t meets = 1;
        if (!listed(box, li))
            continue;
        for (lj = 0; lj < t->count && meets < 255u; lj++)
            meets += lj != li && listed(box, lj) && boxes_meet(&box[2u * li], &box[2u * lj]);
        most = meets > most ? meets : most;
    }
    *bound = most < 255u ? most : 255u;
    return n;
}

/* The listed literals front to back, over the boxes in the scratch: pairs
 * of the key's bits and the literal, returned as the start of the scratch.
 * The key is the eye's power with respect to each world box's sphere
 * (csg/bounds.c; orthographic cameras: the nearest corner's w). For spheres that is
 * the order the rays meet them in, intersecting ones too, so a sequence in
 * that order pushes every pixel through every sphere in its first run (the
 * bench's grids and row), and the check below ends it. Any order is exact:
 * the runs' count is what makes it so. */
static uint32_t *order_front_to_back(stin_context *ctx, const stin__csg_product *p,
                                     const stin__csg_term *t, uint32_t n)
{
    uint32_t *pair = ctx->csg->scratch, li, k = 0, gap, i, j;
    float eye[3];
    int perspective = stin__csg_eye(ctx, eye);
    for (li = 0; li < t->count; li++) {
        const stin__draw *d;
        float key;
        if (!listed(pair, li))
            continue;
        /* entry k <= li overwrites boxes already read */
        d = primitive_of(ctx, p, ctx->csg->literals[t->first + li]);
        key = perspective ? stin__csg_power(ctx, d, eye) : stin__csg_nearest_w(ctx, d);
        stin__memcopy(&pair[2u * k], &key, sizeof key);
        pair[2u * k + 1u] = li;
        k++;
    }
    for (gap = n / 2u; gap > 0; gap /= 2u) /* Shell's sort: no heap, n up to the literals */
        for (i = gap; i < n; i++) {
            uint32_t moving[2];
            float key, other;
            moving[0] = pair[2u * i];
            moving[1] = pair[2u * i + 1u];
            stin__memcopy(&key, &moving[0], sizeof key);
            for (j = i; j >= gap; j -= gap) {
                stin__memcopy(&other, &pair[2u * (j - gap)], sizeof other);
                if (!(other > key))
                    break;
                pair[2u * j] = pair[2u * (j - gap)];
                pair[2u * j + 1u] = pair[2u * (j - gap) + 1u];
            }
            pair[2u * j] = moving[0];
            pair[2u * j + 1u] = moving[1];
        }
    return pair;
}

/* Complemented d once: the pixels where the depth lies inside d (its front
 * in front of the depth and its back not: goldfeather's parity rule,
 * crossed faces are those in front, coincident ones included) take its
 * back face's depth. Marking them takes one pass over both faces with
 * two-sided stencil (depth LESS: a front face passing counts 1, a back face
 * failing 1 more), else two (the front faces mark 1, the back faces
 * promote it to 2); the depth is written in a pass of its own, since the
 * marks test with the coplanar rule's offset and an offset moves what a
 * pass writes too. */
static void subtract_one(stin_context *ctx, const stin__path *path, const stin__draw *d)
{
    stin__pass_state ps = faces(ctx, d, 0, GL_LESS, 0);
    toward_eye(&ps);
    if (stin__pass_two_sided(ctx)) {
        int front_is_gl_front = stin__csg_culled_face(d, 0) == GL_BACK; /* not mirrored */
        stencil(&ps, GL_ALWAYS, 0, GL_KEEP, GL_KEEP, GL_INCR); /* front faces: zpass */
        ps.cull = 0;
        ps.two_sided = 1;
        ps.back = ps.front;
        ps.back.zfail = GL_INCR; /* back faces: zfail */
        ps.back.zpass = GL_KEEP;
        if (!front_is_gl_front) {
            stin__stencil_face swap = ps.front;
            ps.front = ps.back;
            ps.back = swap;
        }
        draw(ctx, path, d, &ps);
    } else {
        stencil(&ps, GL_ALWAYS, 1, GL_KEEP, GL_KEEP, GL_REPLACE);
        draw(ctx, path, d, &ps);
        ps = faces(ctx, d, 1, GL_GEQUAL, 0);
        toward_eye(&ps); /* a back face that near the depth ends the solid there */
        stencil(&ps, GL_EQUAL, 1, GL_ZERO, GL_ZERO, GL_INCR);
        draw(ctx, path, d, &ps);
    }
    ps = faces(ctx, d, 1, GL_ALWAYS, 1); /* the back face's own depth: EQUAL finds it later */
    stencil(&ps, GL_EQUAL, 2, GL_ZERO, GL_ZERO, GL_ZERO);
    draw(ctx, path, d, &ps);
}

/* Whether the depth still lies inside a listed primitive anywhere: each
 * counts +1 where its front lies in front of the depth and -1 where its
 * back does (subtract_one's rule, so a pixel counted is one another run
 * moves), in one pass per primitive with two-sided stencil and wrapping
 * counts, else front faces then back faces (increments first: a clamped
 * count never goes below 0); batches of 255 (no count overflows); the
 * stencil's largest value read as csg/merge.c reads it (a query on the
 * GPU). */
static int still_inside(stin_context *ctx, const stin__path *path, stin__csg_pixels *r,
                        const stin__csg_product *p, const stin__csg_term *t,
                        const uint32_t *order, uint32_t n)
{
    int two_sided = stin__pass_two_sided_wrap(ctx);
    GLenum incr = two_sided ? GL_INCR_WRAP : GL_INCR, decr = two_sided ? GL_DECR_WRAP : GL_DECR;
    uint32_t i = 0, batch;
    ctx->stats.csg.scs_checks++;
    while (i < n) {
        stin__csg_clear(ctx, GL_STENCIL_BUFFER_BIT);
        for (batch = 0; i < n && batch < 255u; i++, batch++) {
            uint32_t lit = ctx->csg->literals[t->first + order[2u * i + 1u]];
            const stin__draw *d = primitive_of(ctx, p, lit);
            stin__pass_state ps = faces(ctx, d, 0, GL_LESS, 0);
            int front_is_gl_front = stin__csg_culled_face(d, 0) == GL_BACK; /* not mirrored */
            toward_eye(&ps);
            stencil(&ps, GL_ALWAYS, 0, GL_KEEP, GL_KEEP, incr); /* ps.cull_face: the back */
            if (two_sided) {
                ps.cull = 0;
                ps.two_sided = 1;
                ps.back = ps.front;
                (front_is_gl_front ? &ps.back : &ps.front)->zpass = decr;
                draw(ctx, path, d, &ps);
                continue;
            }
            draw(ctx, path, d, &ps);
            ps.cull_face = ps.cull_face == GL_BACK ? GL_FRONT : GL_BACK;
            ps.front.zpass = ps.back.zpass = decr;
            draw(ctx, path, d, &ps);
        }
        if (stin__csg_stencil_max(ctx, path, r, 1u))
            return 1;
    }
    return 0;
}

/* 2. the subtraction sequence: runs over the listed complemented
 * primitives front to back, as many as one pixel's most covering ones (the
 * boxes' bound), each after the first only where the check finds the
 * depth still inside one (STIN_DEBUG_CSG_SCS_NO_EARLY_STOP: every run). */
static void subtract(stin_context *ctx, const stin__path *path, stin__csg_pixels *r,
                     const stin__csg_product *p, const stin__csg_term *t)
{
    int check = !(ctx->desc.debug_flags & STIN_DEBUG_CSG_SCS_NO_EARLY_STOP);
    unsigned runs, run;
    uint32_t n = list_complemented(ctx, p, t, &runs), i;
    const uint32_t *order = order_front_to_back(ctx, p, t, n);
    for (run = 0; run < runs; run++) {
        if (run > 0 && check) {
            if (!still_inside(ctx, path, r, p, t, order, n))
                return;
            stin__csg_clear(ctx, GL_STENCIL_BUFFER_BIT); /* its counts: subtract_one's start at 0 */
        }
        ctx->stats.csg.scs_runs++;
        for (i = 0; i < n; i++)
            subtract_one(ctx, path,
                         primitive_of(ctx, p, ctx->csg->literals[t->first + order[2u * i + 1u]]));
    }
    if (runs == 255u && check && still_inside(ctx, path, r, p, t, order, n) &&
        !ctx->csg->said_scs_capped) {
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "scs: 255 or more subtracted primitives cover one pixel; the subtraction "
                  "sequence stops after 255 runs");
        ctx->csg->said_scs_capped = 1;
    }
}

/* 3. each batch of plain primitives: the depth in front of every back face
 * (a face within OFFSET_UNITS counts as in front: the solid ends there). */
static void clip(stin_context *ctx, const stin__path *path, stin__csg_pixels *r,
                 const stin__csg_product *p, const stin__csg_term *t)
{
    uint32_t batch = ctx->desc.debug_flags & STIN_DEBUG_CSG_SCS_NO_BATCH ? 0xffffffffu : BATCH;
    uint32_t li = 0, n, lit;
    while (li < t->count) {
        stin__csg_clear(ctx, GL_STENCIL_BUFFER_BIT);
        for (n = 0; li < t->count && n < batch; li++) {
            const stin__draw *d;
            stin__pass_state ps;
            lit = ctx->csg->literals[t->first + li];
            if (STIN__CSG_COMPLEMENTED(lit))
                continue;
            d = primitive_of(ctx, p, lit);
            ps = faces(ctx, d, 1, GL_GREATER, 0);
            toward_eye(&ps);
            /* counts only where every earlier one of the batch counted */
            stencil(&ps, GL_EQUAL, (GLint)(n & 0xffu), GL_KEEP, GL_KEEP, GL_INCR);
            draw(ctx, path, d, &ps);
            n++;
        }
        if (!n)
            break;
        stin__csg_candidate_keep_where(ctx, path, r, 0xffu, n > 255u ? 255u : n);
    }
}

/* The term's surface kept where nearer (csg/merge.c: a depth of 0, where
 * no plain primitive drew, is none). */
static void term(stin_context *ctx, const stin__path *path, stin__csg_pixels *r,
                 const stin__csg_product *p, const stin__csg_term *t)
{
    float region[4] = {-1e30f, -1e30f, 1e30f, 1e30f}, rect[4];
    uint32_t li;
    stin__csg_surface surface; /* every literal's shown side */
    /* the term's surface lies inside every plain primitive's rectangle: on
     * the GPU (nothing outside read back) its passes keep to their overlap */
    for (li = 0; li < t->count; li++) {
        uint32_t lit = ctx->csg->literals[t->first + li];
        if (STIN__CSG_COMPLEMENTED(lit))
            continue;
        stin__csg_screen_rect(ctx, primitive_of(ctx, p, lit), rect);
        stin__csg_rect_cut(region, rect);
    }
    stin__csg_region_reset(ctx);
    if (!stin__csg_region_narrow(ctx, region))
        return;
    intersect(ctx, path, p, t);
    subtract(ctx, path, r, p, t);
    if (!stin__csg_candidate_open(ctx, r))
        return;
    clip(ctx, path, r, p, t);
    surface.p = p;
    surface.t = t;
    surface.list = NULL;
    surface.first = 0;
    surface.count = t->count;
    surface.cap = NULL;
    surface.cap_culled = GL_BACK;
    (void)stin__csg_candidate_take(ctx, path, r, NULL, &surface, 0);
}

int stin__csg_scs_takes(const stin_context *ctx, const stin__csg_product *p)
{
    return ctx->sel.choice[STIN_FEATURE_CSG].technique == STIN_TECH_CSG_SCS && !unfit(ctx, p);
}

int stin__csg_scs_product(stin_context *ctx, const stin__path *path, stin__csg_pixels *r,
                          const stin__csg_product *p)
{
    const char *why;
    uint32_t ti;
    stin_technique chosen = ctx->sel.choice[STIN_FEATURE_CSG].technique;
    if (chosen != STIN_TECH_CSG_SCS && chosen != STIN_TECH_CSG_INTERVAL) /* interval's spill */
        return 0;
    why = unfit(ctx, p);
    if (why) {
        if (!ctx->csg->said_scs_fallback) {
            int forced = ctx->desc.techniques[STIN_FEATURE_CSG] == STIN_TECH_CSG_SCS;
            stin__log(ctx, forced ? STIN_LOG_LEVEL_WARNING : STIN_LOG_LEVEL_INFO,
                      STIN_LOG_FALLBACK, "scs: %s; goldfeather resolves the product", why);
            ctx->csg->said_scs_fallback = 1;
        }
        return 0;
    }
    for (ti = 0; ti < p->term_count; ti++)
        term(ctx, path, r, p, &ctx->csg->terms[p->first_term + ti]);
    ctx->stats.csg.scs_products++;
    return 1;
}
