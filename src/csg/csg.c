/* SPDX-License-Identifier: MIT */
/* stin_draw_csg: a product's primitives and expression checked, its
 * primitives kept like draws and its expression normalised into the
 * frame's term and literal stores (csg/normal_form.c). Nothing of a refused
 * product stays. */
#include "csg/csg_private.h"

/* Words of normalisation scratch for the desc's capacities. */
static uint32_t scratch_words(const stin_desc *d)
{
    return 2u * (d->csg.max_terms + d->csg.max_literals);
}

/* The parts behind the struct, each from a 16-byte boundary: the cast and
 * interval states, then the arrays (primitives, and their faces: two a
 * primitive and a product's near-plane cap). */
static size_t arrays_bytes(const stin_desc *d)
{
    return 4u * sizeof(stin__draw) * d->csg.max_primitives +
           (sizeof(stin__csg_product) + sizeof(stin__csg_term)) * d->csg.max_terms +
           sizeof(uint32_t) * ((size_t)d->csg.max_literals + scratch_words(d));
}

size_t stin__csg_state_bytes(const stin_desc *d)
{
    return stin__align16(sizeof(stin__csg_state)) + stin__align16(stin__csg_cast_state_bytes()) +
           stin__align16(stin__csg_interval_state_bytes()) + arrays_bytes(d);
}

void stin__csg_state_place(void *state, const stin_desc *d)
{
    stin__csg_state *c = (stin__csg_state *)state;
    unsigned char *next = (unsigned char *)state + stin__align16(sizeof *c);
    c->cast = (struct stin__csg_cast_state *)(void *)next;
    next += stin__align16(stin__csg_cast_state_bytes());
    c->interval = (struct stin__csg_interval_state *)(void *)next;
    next += stin__align16(stin__csg_interval_state_bytes());
    c->primitives = (stin__draw *)(void *)next;
    c->products = (stin__csg_product *)(void *)(c->primitives + d->csg.max_primitives);
    c->terms = (stin__csg_term *)(void *)(c->products + d->csg.max_terms);
    c->literals = (uint32_t *)(void *)(c->terms + d->csg.max_terms);
    c->scratch = c->literals + d->csg.max_literals;
    c->scratch_words = scratch_words(d);
    c->faces = (stin__draw *)(void *)(c->scratch + c->scratch_words);
}

void stin__csg_frame_begin(stin_context *ctx)
{
    stin__csg_state *c = ctx->csg;
    c->primitive_count = c->product_count = 0;
    c->term_count = c->literal_count = 0;
    c->face_count = 0;
    c->resolved = 0;
}

uint32_t stin__csg_product_count(const stin_context *ctx)
{
    return ctx->csg->product_count;
}

static stin_result refuse(stin_context *ctx, stin_result r, stin_log_item item, const char *why,
                          uint32_t index)
{
    stin__log(ctx, STIN_LOG_LEVEL_ERROR, item, "stin_draw_csg: %s (%u); product dropped", why,
              index);
    ctx->stats.csg.dropped++;
    return r;
}

static int all_zero(const float *v, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (v[i] != 0.0f)
            return 0;
    return 1;
}

/* Ops known, primitive indices in range, operands before their node: NULL,
 * or what is wrong with node *at. */
static const char *node_problem(const stin_csg_node *nodes, uint32_t node_count,
                                uint32_t primitive_count, uint32_t *at)
{
    uint32_t i;
    for (i = 0; i < node_count; i++) {
        const stin_csg_node *n = &nodes[i];
        *at = i;
        if ((unsigned)n->op > STIN_CSG_SUBTRACTION)
            return "unknown op in node";
        if (n->op == STIN_CSG_PRIMITIVE && n->primitive >= primitive_count)
            return "primitive index out of range in node";
        if (n->op != STIN_CSG_PRIMITIVE && (n->a >= i || n->b >= i))
            return "an operand must be a node before the one using it, in node";
    }
    return NULL;
}

static stin_result check_nodes(stin_context *ctx, const stin_csg_desc *desc)
{
    uint32_t at;
    const char *why = node_problem(desc->nodes, desc->node_count, desc->primitive_count, &at);
    return why ? refuse(ctx, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT, why, at) : STIN_OK;
}

/* Each primitive into the store (from ctx->csg->primitive_count on; the
 * count moves only when the whole product is accepted). */
static stin_result take_primitives(stin_context *ctx, const stin_csg_desc *desc)
{
    uint32_t i, slot;
    for (i = 0; i < desc->primitive_count; i++) {
        const stin_csg_primitive *p = &desc->primitives[i];
        stin__draw *d = &ctx->csg->primitives[ctx->csg->primitive_count + i];
        stin__mesh_slot *m = stin__mesh_lookup(ctx, p->mesh, &slot);
        stin_result r;
        if (!m)
            return refuse(ctx, STIN_ERROR_INVALID_HANDLE, STIN_LOG_BAD_HANDLE,
                          "stale or unknown mesh handle of primitive", i);
        if (!m->info.closed_manifold)
            return refuse(ctx, STIN_ERROR_INVALID_MESH, STIN_LOG_MESH_NOT_MANIFOLD,
                          "the mesh is not a closed 2-manifold (inside and outside are "
                          "undefined), primitive", i);
        if (!stin__finite_n(p->transform, 16))
            return refuse(ctx, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT,
                          "transform must be finite, primitive", i);
        if (all_zero(p->transform, 16))
            stin__mat4_identity(d->transform);
        else if (stin__mat4_singular(p->transform))
            return refuse(ctx, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT,
                          "transform must be invertible (a flat solid has no inside), primitive",
                          i);
        else
            stin__memcopy(d->transform, p->transform, sizeof d->transform);
        if (stin__material_prepare(ctx, "stin_draw_csg", "product", &p->material, &d->material,
                                   &r) != STIN_OK) {
            ctx->stats.csg.dropped++;
            return r;
        }
        if (d->material.color[3] < 1.0f || d->material.displace)
            return refuse(ctx, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT,
                          "CSG primitives are opaque and not displaced (colour alpha 1, "
                          "displace 0), primitive", i);
        d->material.normal_map.id = d->material.height_map.id = 0; /* see stin.h */
        d->mesh_slot = slot;
        d->sort_depth = 0.0f;
        d->csg = 0;
    }
    return STIN_OK;
}

static const char *nf_failure(stin__csg_nf_result r)
{
    switch (r) {
    case STIN__CSG_NF_TERMS:
        return "its normal form has more terms than desc.csg.max_terms leaves this frame";
    case STIN__CSG_NF_LITERALS:
        return "its normal form has more literals than desc.csg.max_literals leaves this frame";
    case STIN__CSG_NF_SCRATCH:
        return "its partial normal forms outgrow the scratch of 2 (csg.max_terms + "
               "csg.max_literals) words";
    case STIN__CSG_NF_DEPTH:
        return "the expression nests deeper than 1024";
    case STIN__CSG_NF_WORK:
        return "normalising the expression takes more than 2^24 steps (a node visited, "
               "a pair of terms crossed and their literals)";
    case STIN__CSG_NF_OK:
        break;
    }
    return "";
}

static stin_result nf_result(stin__csg_nf_result nf)
{
    return nf == STIN__CSG_NF_OK      ? STIN_OK
           : nf == STIN__CSG_NF_DEPTH ? STIN_ERROR_INVALID_ARGUMENT
                                      : STIN_ERROR_CAPACITY;
}

stin_result stin_csg_measure(const stin_csg_desc *desc, uint32_t *scratch,
                             uint32_t scratch_words, stin_csg_size *size, const char **why)
{
    static const char *const empty = "empty expression: nodes and primitives are required";
    stin__csg_out out;
    stin__csg_nf_result nf;
    uint32_t at;
    const char *problem;
    if (why)
        *why = "";
    if (!desc || !scratch || !size)
        return STIN_ERROR_INVALID_ARGUMENT;
    stin__memzero(size, sizeof *size);
    problem = !desc->nodes || !desc->node_count || !desc->primitives || !desc->primitive_count
                  ? empty
              : desc->node_count > STIN__CSG_MAX_NODES ? "more than 65536 nodes"
                  : node_problem(desc->nodes, desc->node_count, desc->primitive_count, &at);
    if (problem) {
        if (why)
            *why = problem;
        return STIN_ERROR_INVALID_ARGUMENT;
    }
    stin__memzero(&out, sizeof out); /* terms NULL: counted only */
    nf = stin__csg_normal_form(desc->nodes, desc->node_count, scratch, scratch_words, &out);
    /* short of scratch: more than it had (what it needs is not known yet) */
    size->scratch_words = nf == STIN__CSG_NF_SCRATCH && scratch_words < UINT32_MAX
                              ? scratch_words + 1u
                              : out.scratch_peak;
    if (nf != STIN__CSG_NF_OK) {
        if (why)
            *why = nf_failure(nf);
        return nf_result(nf);
    }
    size->terms = out.term_count;
    size->literals = out.literal_count;
    return STIN_OK;
}

stin_result stin_draw_csg(stin_context *ctx, const stin_csg_desc *desc)
{
    stin__csg_state *c;
    stin__csg_product *p;
    stin__csg_out out;
    stin__csg_nf_result nf;
    stin_result r;
    if (!ctx)
        return STIN_ERROR_INVALID_ARGUMENT;
    if (ctx->state != STIN__IN_FRAME) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FRAME_STATE,
                  "stin_draw_csg: no frame is open");
        return STIN_ERROR_INVALID_STATE;
    }
    if (!desc)
        return refuse(ctx, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT, "desc is NULL", 0);
    /* the CPU resolve reads the frame's depth and stencil back, which a
     * multisampled framebuffer object does not allow: it resolves through a
     * single-sampled copy (csg/resolve_msaa.c) where the context has what
     * that needs; else no product rather than a wrong one. The GPU resolve
     * snaps the faces' own samples (csg/merge.c). */
    if (ctx->target.multisampled && !stin__csg_merge_ready(ctx) &&
        !stin__csg_msaa_readback_ready(ctx) &&
        ctx->sel.choice[STIN_FEATURE_CSG].technique != STIN_TECH_CSG_OFF)
        return refuse(ctx, STIN_ERROR_UNSUPPORTED, STIN_LOG_TECHNIQUE_UNSUPPORTED,
                      "the frame's target is multisampled, and the CSG read-back resolve "
                      "(GL1 tiers, STIN_DEBUG_CSG_READBACK) reads it through a single-sampled "
                      "copy only with framebuffer objects, packed depth-stencil, depth "
                      "textures, a framebuffer blit and glDrawPixels; products drawn so far",
                      ctx->csg->product_count);
    if (!desc->nodes || !desc->node_count || !desc->primitives || !desc->primitive_count)
        return refuse(ctx, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT,
                      "empty expression: nodes and primitives are required, node count",
                      desc->node_count);
    if (desc->node_count > STIN__CSG_MAX_NODES)
        return refuse(ctx, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT,
                      "more than 65536 nodes", desc->node_count);
    r = check_nodes(ctx, desc);
    if (r != STIN_OK)
        return r;
    c = ctx->csg;
    if (desc->primitive_count > ctx->desc.csg.max_primitives - c->primitive_count)
        return refuse(ctx, STIN_ERROR_CAPACITY, STIN_LOG_POOL_FULL,
                      "more primitives than desc.csg.max_primitives leaves this frame, primitives",
                      desc->primitive_count);
    r = take_primitives(ctx, desc);
    if (r != STIN_OK)
        return r;
    out.terms = c->terms + c->term_count;
    out.max_terms = ctx->desc.csg.max_terms - c->term_count;
    out.literals = c->literals + c->literal_count;
    out.max_literals = ctx->desc.csg.max_literals - c->literal_count;
    out.literal_base = c->literal_count;
    nf = stin__csg_normal_form(desc->nodes, desc->node_count, c->scratch, c->scratch_words, &out);
    if (nf != STIN__CSG_NF_OK)
        return refuse(ctx, nf_result(nf),
                      nf == STIN__CSG_NF_DEPTH ? STIN_LOG_BAD_ARGUMENT : STIN_LOG_POOL_FULL,
                      nf_failure(nf), desc->node_count);
    if (out.term_count == 0) {
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_BAD_ARGUMENT,
                  "stin_draw_csg: every term of the expression is empty (a primitive and its "
                  "complement); nothing to draw");
        return STIN_OK;
    }
    p = &c->products[c->product_count++];
    p->first_primitive = c->primitive_count;
    p->primitive_count = desc->primitive_count;
    p->first_term = c->term_count;
    p->term_count = out.term_count;
    c->primitive_count += desc->primitive_count;
    c->term_count += out.term_count;
    c->literal_count += out.literal_count;
    ctx->stats.csg.products++;
    ctx->stats.csg.terms += out.term_count;
    return STIN_OK;
}

uint32_t stin_query_csg_terms(const stin_context *ctx, uint32_t product, uint32_t term,
                              uint32_t *literals, uint32_t capacity, uint32_t *count)
{
    const stin__csg_product *p;
    const stin__csg_term *t;
    uint32_t i;
    if (count)
        *count = 0;
    if (!ctx || product >= ctx->csg->product_count)
        return 0;
    p = &ctx->csg->products[product];
    if (literals && term < p->term_count) {
        t = &ctx->csg->terms[p->first_term + term];
        for (i = 0; i < t->count && i < capacity; i++)
            literals[i] = ctx->csg->literals[t->first + i];
        if (count)
            *count = i;
    }
    return p->term_count;
}

int stin__csg_caster_product(const stin_context *ctx, uint32_t i, stin__caster_product *out)
{
    const stin__csg_state *c = ctx->csg;
    const stin__csg_product *p;
    if (i >= c->product_count)
        return 0;
    p = &c->products[i];
    out->primitives = c->primitives + p->first_primitive;
    out->primitive_count = p->primitive_count;
    out->term_count = p->term_count;
    out->index = i;
    return 1;
}

const uint32_t *stin__csg_caster_term(const stin_context *ctx, const stin__caster_product *p,
                                      uint32_t t, uint32_t *count)
{
    const stin__csg_state *c = ctx->csg;
    const stin__csg_term *term = &c->terms[c->products[p->index].first_term + t];
    *count = term->count;
    return c->literals + term->first;
}

/* Each primitive's faces that a term shows: front where it is plain in a
 * term, back where it is complemented (both when both); and the product's
 * near-plane cap where the resolve kept it (3 csg.max_primitives faces at
 * most: a product has a primitive at least). */
void stin__csg_faces(stin_context *ctx)
{
    stin__csg_state *c = ctx->csg;
    uint32_t pi, ti, li;
    c->face_count = 0;
    if (!c->resolved)
        return;
    for (pi = 0; pi < c->product_count; pi++) {
        const stin__csg_product *p = &c->products[pi];
        uint32_t q;
        for (q = 0; q < p->primitive_count; q++) {
            int front = 0, back = 0;
            for (ti = 0; ti < p->term_count; ti++) {
                const stin__csg_term *t = &c->terms[p->first_term + ti];
                for (li = 0; li < t->count; li++) {
                    uint32_t l = c->literals[t->first + li];
                    if (STIN__CSG_PRIMITIVE_OF(l) != q)
                        continue;
                    if (STIN__CSG_COMPLEMENTED(l))
                        back = 1;
                    else
                        front = 1;
                }
            }
            if (front) {
                c->faces[c->face_count] = c->primitives[p->first_primitive + q];
                c->faces[c->face_count++].csg = STIN__CSG_FRONT;
            }
            if (back) {
                c->faces[c->face_count] = c->primitives[p->first_primitive + q];
                c->faces[c->face_count++].csg = STIN__CSG_BACK;
            }
        }
        if (p->capped) {
            /* the near plane's cut, in the first primitive's material */
            stin__draw *cap = &c->faces[c->face_count++];
            *cap = c->primitives[p->first_primitive];
            cap->mesh_slot = c->cap_slot;
            stin__memcopy(cap->transform, c->cap_transform, sizeof cap->transform);
            cap->csg = STIN__CSG_CAP;
        }
    }
}

const stin__draw *stin__csg_face_list(const stin_context *ctx, uint32_t *count)
{
    *count = ctx->csg->face_count;
    return ctx->csg->faces;
}

GLenum stin__csg_face_hidden(const stin__draw *d)
{
    int mirrored = stin__mat4_det(d->transform) < 0.0 && d->csg != STIN__CSG_CAP;
    return ((d->csg == STIN__CSG_BACK) != mirrored) ? GL_FRONT : GL_BACK;
}

int stin__csg_face_begin(stin_context *ctx, const stin__draw *d, stin__pass_state *saved)
{
    stin__pass_state ps = *stin__pass_current(ctx);
    GLenum hidden = stin__csg_face_hidden(d);
    *saved = ps;
    /* map-depth's side test draws the lit pass once per side the eye sees:
     * a product's surface always shows its outside to the eye (a cavity's
     * wall too), so it goes with the front sides' pass */
    if (ps.cull && ps.cull_face != GL_BACK)
        return 0;
    if (ps.depth_func == GL_LESS)
        ps.depth_func = GL_EQUAL; /* on the resolved depth only */
    ps.cull = 1;
    ps.cull_face = hidden;
    stin__pass_apply(ctx, &ps);
    return 1;
}

void stin__csg_face_end(stin_context *ctx, const stin__pass_state *saved)
{
    stin__pass_apply(ctx, saved);
}
