/* SPDX-License-Identifier: MIT */
/* CSG technique "scs": sequenced convex subtraction (Rappoport and Spitz;
 * Stewart, Leach and John) for products whose primitives are all convex
 * (stin_mesh_info.convex), on any context with a stencil buffer. Per term
 * of the product's normal form, in the frame's depth and stencil buffers:
 *   1. intersect: depth cleared to 0, the plain primitives' front faces
 *      drawn with depth GREATER: the farthest front face, where a convex
 *      intersection begins;
 *   2. subtract: the complemented primitives in sequence, each pushing the
 *      depth to its back face where the depth lies inside it (its front in
 *      front of the depth, its back behind); the list is run as many times
 *      as the most complemented primitives covering one pixel (sampled with
 *      a saturating stencil count), so every order of those is in the
 *      sequence, and stops early at a run an occlusion query finds changed
 *      nothing;
 *   3. clip: a pixel survives where the depth lies in front of every plain
 *      primitive's back face, counted in the stencil 255 primitives a batch
 *      (no counter overflows), each batch read back.
 * The surviving depth is kept per pixel where nearer, in goldfeather's
 * result (csg_merge.c: on the GPU, or read back once a term), which writes
 * it into the frame's depth.
 * Faces that coincide with the depth (within 4 depth units) count as in
 * front of it: a subtracted box sharing a face's plane takes it away, one
 * touching it from outside does not, an intersected one ending there
 * leaves nothing (the exact reference's rule for crossings at one
 * distance). Passes a term: plain + complemented (the sample) + 3 x
 * complemented x runs + plain (the clip); read-backs on the CPU: the
 * sample, the depth, one stencil each 255 plain primitives; on the GPU a
 * wait for the sample's threshold queries and none else (the early stop's
 * queries aside). */
#include "internal.h"

#ifndef OFFSET_UNITS
#define OFFSET_UNITS 4.0f
#endif
#define BATCH 255u

/* Every primitive of p convex, and every term with a plain primitive. */
static const char *unfit(const stin_context *ctx, const stin__csg_product *p)
{
    const stin__csg_state *c = &ctx->csg;
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
    return &ctx->csg.primitives[p->first_primitive + STIN__CSG_PRIMITIVE_OF(literal)];
}

/* A pass over the depth with colour writes off; `shown` is the face kept. */
static stin__pass_state faces(const stin__draw *d, int back, GLenum depth_func, int depth_write)
{
    stin__pass_state ps = stin__pass_defaults;
    ps.color_write = 0;
    ps.depth_test = 1;
    ps.depth_func = depth_func;
    ps.depth_write = (unsigned char)depth_write;
    ps.cull = 1;
    ps.cull_face = stin__csg_culled_face(d, back);
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
    GL(ctx, ClearDepth)(0.0);
    stin__csg_clear(ctx, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    GL(ctx, ClearDepth)(1.0);
    for (li = 0; li < t->count; li++) {
        uint32_t lit = ctx->csg.literals[t->first + li];
        const stin__draw *d = primitive_of(ctx, p, lit);
        stin__pass_state ps = faces(d, 0, GL_GREATER, 1);
        if (!STIN__CSG_COMPLEMENTED(lit))
            draw(ctx, path, d, &ps);
    }
}

/* The most complemented primitives of t over one pixel (saturating at 255). */
static unsigned sample_complexity(stin_context *ctx, const stin__path *path, stin__csg_pixels *r,
                                  const stin__csg_product *p, const stin__csg_term *t)
{
    unsigned any = 0, most;
    uint32_t li;
    for (li = 0; li < t->count; li++) {
        uint32_t lit = ctx->csg.literals[t->first + li];
        const stin__draw *d = primitive_of(ctx, p, lit);
        stin__pass_state ps = faces(d, 0, GL_ALWAYS, 0);
        if (!STIN__CSG_COMPLEMENTED(lit))
            continue;
        stencil(&ps, GL_ALWAYS, 0, GL_KEEP, GL_KEEP, GL_INCR);
        draw(ctx, path, d, &ps);
        any++; /* convex: each adds one at most */
    }
    if (!any)
        return 0;
    most = stin__csg_stencil_max(ctx, path, r, any < 255u ? any : 255u);
    stin__csg_clear(ctx, GL_STENCIL_BUFFER_BIT);
    return most;
}

/* Complemented d once: its front in front of the depth marks the pixel (1),
 * its back behind it too promotes the mark (2), the pixels marked 2 take
 * the back face's depth. q, where not 0, counts the pixels that moved. */
static void subtract_one(stin_context *ctx, const stin__path *path, const stin__draw *d, GLuint q)
{
    stin__pass_state ps = faces(d, 0, GL_LESS, 0);
    toward_eye(&ps);
    stencil(&ps, GL_ALWAYS, 1, GL_KEEP, GL_KEEP, GL_REPLACE);
    draw(ctx, path, d, &ps);
    if (q)
        GL_ENUM(ctx, BeginQuery, GL_SAMPLES_PASSED)(GL_SAMPLES_PASSED, q);
    ps = faces(d, 1, GL_GREATER, 0);
    toward_eye(&ps); /* a back face that near the depth ends the solid there */
    stencil(&ps, GL_EQUAL, 1, GL_ZERO, GL_ZERO, GL_INCR);
    draw(ctx, path, d, &ps);
    if (q)
        GL_ENUM(ctx, EndQuery, GL_SAMPLES_PASSED)(GL_SAMPLES_PASSED);
    ps = faces(d, 1, GL_ALWAYS, 1); /* the back face's own depth: EQUAL finds it later */
    stencil(&ps, GL_EQUAL, 2, GL_ZERO, GL_ZERO, GL_ZERO);
    draw(ctx, path, d, &ps);
}

/* The pixels query q counted (0 for no query). */
static GLuint counted(stin_context *ctx, GLuint q)
{
    GLuint n = 0;
    if (q)
        GL(ctx, GetQueryObjectuiv)(q, GL_QUERY_RESULT, &n);
    return n;
}

/* 2. the subtraction sequence: runs over the complemented primitives; the
 * moves of a run are counted in a ring of queries (a query counts from its
 * begin: the marking passes stay outside), each read before its reuse (a
 * read waits for the GPU: the ring is large enough that a run of up to 256
 * complemented primitives waits once, and the last run is not counted). */
static void subtract(stin_context *ctx, const stin__path *path, stin__csg_pixels *r,
                     const stin__csg_product *p, const stin__csg_term *t)
{
    int stop_early = ctx->csg.scs_queries[0] &&
                     !(ctx->desc.debug_flags & STIN_DEBUG_CSG_SCS_NO_EARLY_STOP);
    unsigned runs = sample_complexity(ctx, path, r, p, t), run;
    uint32_t li, k;
    if (runs == 255u && !ctx->csg.said_scs_capped) {
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "scs: 255 or more subtracted primitives cover one pixel; the subtraction "
                  "sequence stops after 255 runs");
        ctx->csg.said_scs_capped = 1;
    }
    for (run = 0; run < runs; run++) {
        GLuint moved = 0;
        int count = stop_early && run + 1 < runs; /* nothing to stop after the last run */
        for (li = 0, k = 0; li < t->count; li++) {
            uint32_t lit = ctx->csg.literals[t->first + li];
            GLuint q = count ? ctx->csg.scs_queries[k % STIN__CSG_SCS_QUERIES] : 0;
            if (!STIN__CSG_COMPLEMENTED(lit))
                continue;
            if (k >= STIN__CSG_SCS_QUERIES)
                moved += counted(ctx, q);
            subtract_one(ctx, path, primitive_of(ctx, p, lit), q);
            k++;
        }
        if (!count)
            continue;
        for (li = 0; li < k && li < STIN__CSG_SCS_QUERIES; li++)
            moved += counted(ctx, ctx->csg.scs_queries[li]);
        if (!moved) /* every later run would repeat this one */
            break;
    }
}

/* 3. each batch of plain primitives: the depth in front of every back face
 * (a face within OFFSET_UNITS counts as in front: the solid ends there). */
static void clip(stin_context *ctx, const stin__path *path, stin__csg_pixels *r,
                 const stin__csg_product *p, const stin__csg_term *t)
{
    uint32_t batch = ctx->desc.debug_flags & STIN_DEBUG_CSG_NO_BATCH ? 0xffffffffu : BATCH;
    uint32_t li = 0, n, lit;
    while (li < t->count) {
        stin__csg_clear(ctx, GL_STENCIL_BUFFER_BIT);
        for (n = 0; li < t->count && n < batch; li++) {
            const stin__draw *d;
            stin__pass_state ps;
            lit = ctx->csg.literals[t->first + li];
            if (STIN__CSG_COMPLEMENTED(lit))
                continue;
            d = primitive_of(ctx, p, lit);
            ps = faces(d, 1, GL_GREATER, 0);
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

/* The term's surface kept where nearer (csg_merge.c: a depth of 0, where
 * no plain primitive drew, is none). */
static void term(stin_context *ctx, const stin__path *path, stin__csg_pixels *r,
                 const stin__csg_product *p, const stin__csg_term *t)
{
    intersect(ctx, path, p, t);
    subtract(ctx, path, r, p, t);
    if (!stin__csg_candidate_open(ctx, r))
        return;
    clip(ctx, path, r, p, t);
    (void)stin__csg_candidate_take(ctx, path, r, NULL, 0);
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
        if (!ctx->csg.said_scs_fallback) {
            int forced = ctx->desc.techniques[STIN_FEATURE_CSG] == STIN_TECH_CSG_SCS;
            stin__log(ctx, forced ? STIN_LOG_LEVEL_WARNING : STIN_LOG_LEVEL_INFO,
                      STIN_LOG_FALLBACK, "scs: %s; goldfeather resolves the product", why);
            ctx->csg.said_scs_fallback = 1;
        }
        return 0;
    }
    for (ti = 0; ti < p->term_count; ti++)
        term(ctx, path, r, p, &ctx->csg.terms[p->first_term + ti]);
    ctx->stats.csg_scs_products++;
    return 1;
}

static void forget_queries(stin_context *ctx)
{
    uint32_t i;
    for (i = 0; i < STIN__CSG_SCS_QUERIES; i++)
        ctx->csg.scs_queries[i] = 0;
}

void stin__csg_scs_init(stin_context *ctx)
{
    forget_queries(ctx);
    if (ctx->sel.choice[STIN_FEATURE_CSG].technique == STIN_TECH_CSG_SCS &&
        (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_OCCLUSION_QUERY)))
        GL(ctx, GenQueries)(STIN__CSG_SCS_QUERIES, ctx->csg.scs_queries);
}

void stin__csg_scs_release(stin_context *ctx)
{
    if (ctx->csg.scs_queries[0])
        GL(ctx, DeleteQueries)(STIN__CSG_SCS_QUERIES, ctx->csg.scs_queries);
    forget_queries(ctx);
}
