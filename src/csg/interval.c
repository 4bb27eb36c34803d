/* SPDX-License-Identifier: MIT */
/* CSG technique "interval" on GL4: the seed's G-buffer ray-interval method
 * (one front and one back surface per operand) generalised to k layers per
 * primitive by depth peeling, so that non-convex primitives and bodies
 * behind each other along a ray resolve. Per product:
 *   1. peel: each primitive alone, k times, with depth LESS into a fresh
 *      depth layer (the frame's depth format), the peel shader discarding
 *      what lies at or in front of the layer before: layer j holds the j-th
 *      crossing of the camera ray with the primitive, an RG32F layer beside
 *      it the fragment's float depth (for exact peeling and ordering) and
 *      its side (front: the ray enters, back: it leaves). One more pass per
 *      primitive, in an occlusion query, finds whether a crossing lies past
 *      layer k (an overflow: the product goes to scs/goldfeather this
 *      frame). Where the near plane cuts a primitive, the near-plane cap is
 *      rasterised into one more layer (csg/near.c's quad);
 *   2. walk: one full-screen pass reads every primitive's crossings per
 *      pixel nearest first, keeps each primitive's in/out state (starting
 *      inside where its first crossing is a back face) and evaluates the
 *      normal form at each; the first crossing where it turns true is the
 *      surface (the cap where it holds from the start). It writes that
 *      crossing's layer into an R8 target, read back;
 *   3. keep: each layer some pixel's surface lies on is peeled once more in
 *      the frame's own depth buffer and kept where the walk chose it and it
 *      is nearer in goldfeather's result (csg/merge.c: merged on the GPU by
 *      the walk's target, or read back), which writes it into the frame's
 *      depth: its
 *      values are then those the faces drawn depth EQUAL afterwards meet
 *      (a texture's depth can differ from the frame buffer's in the last
 *      bit: Mesa rasterises into textures upside down).
 * Layer g (primitive * k + j; the cap at n k) is slice g >> 1 of array
 * g & 1: a peel reads layer g - 1 from the other array than it draws into
 * (no feedback loop). */
#include "csg/csg_private.h"

#define GL_DEPTH_COMPONENT32F 0x8CAC
#define GL_DEPTH_COMPONENT16 0x81A5
#ifndef GL_UNSIGNED_SHORT
#define GL_UNSIGNED_SHORT 0x1403
#endif
#define GL_R8 0x8229
#define GL_MAX_ARRAY_TEXTURE_LAYERS 0x88FF

/* "interval" (csg/interval.c): each primitive's crossings of the camera
 * rays peeled into k depth layers, walked per pixel by one full-screen
 * pass. Layer g (primitive * k + layer; the near-plane cap after the
 * last) lives in array g & 1 at slice g >> 1: the layer a peel reads is
 * never the texture it draws into. */
#define STIN__CSG_INTERVAL_MAX_PRIMITIVES 32u /* a product's primitives (a bit each) */
#define STIN__CSG_INTERVAL_MAX_TERMS 64u   /* a product's terms (uniform masks) */
#define STIN__CSG_INTERVAL_MAX_LAYER_INDEX 255u /* layers + cap: the walk's 8-bit answer */
typedef struct stin__csg_interval_state {
    GLuint peel_prog, walk_prog;
    GLint peel_model, peel_view_proj, peel_previous, peel_previous_slice, peel_mirrored,
        peel_tolerance;
    stin__displace_locs peel_displace;
    GLint walk_crossing[2], walk_counts, walk_terms;
    /* even and odd layers: depth (the peel's depth test; the frame's depth
     * format) and RG32F crossings (the rasteriser's float depth, for exact
     * peeling and ordering; the side) */
    GLuint depth[2], crossing[2];
    GLenum depth_format;
    GLuint result, fbo, query;  /* the walk's R8 target; the overflow's query */
    int width, height, slices;  /* grown to the largest frame and product so far */
    size_t bytes;               /* GL memory of the textures above */
    int max_slices;             /* GL_MAX_ARRAY_TEXTURE_LAYERS */
    int said_fallback, said_overflow, said_failed;
} stin__csg_interval_state;

size_t stin__csg_interval_state_bytes(void) { return sizeof(stin__csg_interval_state); }

static int chosen(const stin_context *ctx)
{
    return ctx->sel.choice[STIN_FEATURE_CSG].technique == STIN_TECH_CSG_INTERVAL;
}

/* The seed's one interval per primitive: its nearest front and nearest
 * back face as two layers, nothing peeled, no overflow. */
static int one_interval(const stin_context *ctx)
{
    return (ctx->desc.debug_flags & STIN_DEBUG_CSG_INTERVAL_ONE_LAYER) != 0;
}

/* k: layers kept per primitive. */
static int layers_of(const stin_context *ctx)
{
    if (one_interval(ctx) || (ctx->desc.debug_flags & STIN_DEBUG_CSG_INTERVAL_TWO_LAYERS))
        return 2;
    return (int)ctx->desc.csg.interval_layers;
}

void stin__csg_interval_release(stin_context *ctx)
{
    stin__csg_interval_state *s = ctx->csg->interval;
    if (s->depth[0])
        GL(ctx, DeleteTextures)(2, s->depth);
    if (s->crossing[0])
        GL(ctx, DeleteTextures)(2, s->crossing);
    if (s->result)
        GL(ctx, DeleteTextures)(1, &s->result);
    if (s->fbo)
        GL(ctx, DeleteFramebuffers)(1, &s->fbo);
    if (s->query)
        GL(ctx, DeleteQueries)(1, &s->query);
    if (s->peel_prog)
        GL(ctx, DeleteProgram)(s->peel_prog);
    if (s->walk_prog)
        GL(ctx, DeleteProgram)(s->walk_prog);
    stin__memzero(s, sizeof *s);
}

static const stin__uniform_name peel_uniforms[] = {
    STIN__UNIFORM(stin__csg_interval_state, peel_model, "u_model"),
    STIN__UNIFORM(stin__csg_interval_state, peel_view_proj, "u_view_proj"),
    STIN__UNIFORM(stin__csg_interval_state, peel_previous, "u_previous"),
    STIN__UNIFORM(stin__csg_interval_state, peel_previous_slice, "u_previous_slice"),
    STIN__UNIFORM(stin__csg_interval_state, peel_mirrored, "u_mirrored"),
    STIN__UNIFORM(stin__csg_interval_state, peel_tolerance, "u_tolerance"),
};

static const stin__uniform_name walk_uniforms[] = {
    STIN__UNIFORM(stin__csg_interval_state, walk_crossing[0], "u_crossing_even"),
    STIN__UNIFORM(stin__csg_interval_state, walk_crossing[1], "u_crossing_odd"),
    STIN__UNIFORM(stin__csg_interval_state, walk_counts, "u_counts"),
    STIN__UNIFORM(stin__csg_interval_state, walk_terms, "u_terms"),
};

/* The peel program draws meshes as the volume program does (volume.vert:
 * its position is invariant with the lit passes'); the walk is a screen
 * quad. 0 with msg when one does not build. */
static int make_programs(stin_context *ctx, char *msg, size_t size)
{
    stin__csg_interval_state *s = ctx->csg->interval;
    s->peel_prog = stin__program_build(ctx, "gl4/volume.vert", "gl4/csg_interval_peel.frag", NULL,
                                       0, msg, size);
    if (!s->peel_prog)
        return 0;
    s->walk_prog = stin__program_build(ctx, "gl4/screen.vert", "gl4/csg_interval.frag",
                                       NULL, 0, msg, size);
    if (!s->walk_prog)
        return 0;
    STIN__LOCATE(ctx, s->peel_prog, s, peel_uniforms);
    STIN__LOCATE(ctx, s->walk_prog, s, walk_uniforms);
    stin__displace_locate(ctx, s->peel_prog, 1, &s->peel_displace);
    return 1;
}

void stin__csg_interval_init(stin_context *ctx)
{
    stin__csg_interval_state *s = ctx->csg->interval;
    char msg[160], why[220];
    GLint most = 0;
    stin__memzero(s, sizeof *s);
    if (!chosen(ctx))
        return;
    msg[0] = '\0';
    if (!make_programs(ctx, msg, sizeof msg)) {
        stin__csg_interval_release(ctx);
        stin__formatf(why, sizeof why, "its programs failed to build (%s)", msg);
        stin__demote(ctx, STIN_FEATURE_CSG, STIN_TECH_CSG_SCS, why);
        return;
    }
    GL(ctx, GetIntegerv)(GL_MAX_ARRAY_TEXTURE_LAYERS, &most);
    s->max_slices = most > 256 ? most : 256; /* GL 3.0's least */
    GL(ctx, GenQueries)(1, &s->query);
}

static void array_texture(stin_context *ctx, GLuint tex, GLint format, GLenum layout,
                          GLenum type, int w, int h, int slices)
{
    GL(ctx, BindTexture)(GL_TEXTURE_2D_ARRAY, tex);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    GL(ctx, TexImage3D)(GL_TEXTURE_2D_ARRAY, 0, format, w, h, slices, 0, layout, type, NULL);
}

/* The peel's depth test in the frame's depth format (the nearest fragment
 * it keeps is the one the frame's buffer would keep). */
static void depth_format(const stin_context *ctx, GLenum *format, GLenum *layout, GLenum *type)
{
    int bits = ctx->target.depth_bits;
    *format = bits > 24 ? GL_DEPTH_COMPONENT32F
              : bits > 16 ? GL_DEPTH_COMPONENT24
                          : GL_DEPTH_COMPONENT16;
    *layout = GL_DEPTH_COMPONENT;
    *type = bits > 24 ? GL_FLOAT : bits > 16 ? GL_UNSIGNED_INT : GL_UNSIGNED_SHORT;
}

/* Layers for `slices` slices an array at the viewport's window size (x + w
 * by y + h: gl_FragCoord needs no offset), grown when a frame needs more;
 * 0 when the framebuffer is incomplete (logged once). */
static int ensure_targets(stin_context *ctx, int slices)
{
    stin__csg_interval_state *s = ctx->csg->interval;
    const int *vp = ctx->frame.viewport;
    int w = vp[0] + vp[2], h = vp[1] + vp[3], i;
    GLenum status, format, layout, type;
    depth_format(ctx, &format, &layout, &type);
    if (w <= s->width && h <= s->height && slices <= s->slices && format == s->depth_format)
        return 1;
    if (!s->fbo) { /* the first frame with a product */
        GL(ctx, GenFramebuffers)(1, &s->fbo);
        GL(ctx, GenTextures)(2, s->depth);
        GL(ctx, GenTextures)(2, s->crossing);
        GL(ctx, GenTextures)(1, &s->result);
    }
    w = w > s->width ? w : s->width;
    h = h > s->height ? h : s->height;
    slices = slices > s->slices ? slices : s->slices;
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    for (i = 0; i < 2; i++) {
        array_texture(ctx, s->depth[i], (GLint)format, layout, type, w, h, slices);
        array_texture(ctx, s->crossing[i], GL_RG32F, GL_RG, GL_FLOAT, w, h, slices);
    }
    GL(ctx, BindTexture)(GL_TEXTURE_2D_ARRAY, 0);
    stin__rt_texture(ctx, s->result, GL_R8, GL_RED, GL_UNSIGNED_BYTE, w, h);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->fbo);
    GL(ctx, FramebufferTextureLayer)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, s->crossing[0], 0, 0);
    GL(ctx, FramebufferTextureLayer)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, s->depth[0], 0, 0);
    status = GL(ctx, CheckFramebufferStatus)(GL_FRAMEBUFFER);
    s->width = w;
    s->height = h;
    s->slices = slices;
    s->depth_format = format;
    s->bytes = (size_t)w * (size_t)h * ((size_t)slices * 2u * 12u + 1u);
    if (status == GL_FRAMEBUFFER_COMPLETE)
        return 1;
    if (!s->said_failed)
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "interval: its layer framebuffer is incomplete (0x%x); scs/goldfeather "
                  "resolve the products", (unsigned)status);
    s->said_failed = 1;
    return 0;
}

/* Why product p cannot go through the walk (NULL: it can). */
static const char *unfit(const stin_context *ctx, const stin__csg_product *p, int k)
{
    const stin__csg_interval_state *s = ctx->csg->interval;
    if (p->primitive_count > STIN__CSG_INTERVAL_MAX_PRIMITIVES)
        return "the product has more than 32 primitives (the walk's in/out bits)";
    if (p->term_count > STIN__CSG_INTERVAL_MAX_TERMS)
        return "the product has more than 64 terms (the walk's uniforms)";
    if (p->primitive_count * (uint32_t)k + 1u > STIN__CSG_INTERVAL_MAX_LAYER_INDEX)
        return "its primitives x layers pass 254 (the walk's 8-bit layer index)";
    if ((p->primitive_count * (uint32_t)k + 2u) / 2u > (uint32_t)s->max_slices)
        return "its primitives x layers pass GL_MAX_ARRAY_TEXTURE_LAYERS";
    if (s->said_failed)
        return "its layer framebuffer is incomplete";
    return NULL;
}

static void fall_back(stin_context *ctx, const char *why)
{
    int forced = ctx->desc.techniques[STIN_FEATURE_CSG] == STIN_TECH_CSG_INTERVAL;
    if (ctx->csg->interval->said_fallback)
        return;
    stin__log(ctx, forced ? STIN_LOG_LEVEL_WARNING : STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
              "interval: %s; scs or goldfeather resolves the product", why);
    ctx->csg->interval->said_fallback = 1;
}

/* Layer g as the framebuffer's depth and colour. */
static void attach_layer(stin_context *ctx, int g)
{
    const stin__csg_interval_state *s = ctx->csg->interval;
    GL(ctx, FramebufferTextureLayer)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, s->crossing[g & 1], 0,
                                     g >> 1);
    GL(ctx, FramebufferTextureLayer)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, s->depth[g & 1], 0,
                                     g >> 1);
}

/* The peel's unit for the layer before: not the height map's (a sampler
 * of another type on one unit is an error at the draw). */
static int previous_unit(const stin_context *ctx) { return ctx->sel.displace_unit == 1 ? 2 : 1; }

/* Draw d through the peel program against layer `previous` (< 0: none),
 * with the pass state ps. */
static void peel_draw(stin_context *ctx, const stin__draw *d, int previous,
                      const stin__pass_state *ps)
{
    const stin__csg_interval_state *s = ctx->csg->interval;
    stin__pass_apply(ctx, ps);
    stin__bind_unit(ctx, previous_unit(ctx), GL_TEXTURE_2D_ARRAY,
                    previous < 0 ? 0 : s->crossing[previous & 1]);
    GL(ctx, Uniform1i)(s->peel_previous_slice, previous < 0 ? -1 : previous >> 1);
    GL(ctx, Uniform1i)(s->peel_mirrored,
                       d->csg != STIN__CSG_CAP && stin__mat4_det(d->transform) < 0.0);
    stin__glsl_submit_geometry(ctx, s->peel_model, &s->peel_displace, d);
    ctx->stats.passes++;
}

/* Layer g of d: cleared, then its nearest crossing behind layer `previous`
 * (culling `culled`, 0: none). */
static void peel(stin_context *ctx, const stin__draw *d, int g, int previous, GLenum culled)
{
    stin__pass_state ps = stin__pass_defaults;
    attach_layer(ctx, g);
    ps.depth_write = 1;
    stin__pass_apply(ctx, &ps);
    GL(ctx, ClearColor)(0.0f, 0.0f, 0.0f, 0.0f);
    stin__clear_depth(ctx, 1.0);
    GL(ctx, Clear)(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    ps.depth_test = 1;
    ps.depth_func = GL_LESS;
    ps.cull = culled != 0;
    ps.cull_face = culled ? culled : GL_BACK;
    peel_draw(ctx, d, previous, &ps);
}

/* Whether any primitive of p has a crossing past layer k: each drawn once
 * more against its last layer, nothing written, in one occlusion query. */
static int overflows(stin_context *ctx, const stin__csg_product *p, int k)
{
    stin__csg_interval_state *s = ctx->csg->interval;
    stin__pass_state ps = stin__pass_defaults;
    uint32_t q;
    ps.depth_write = 0;
    ps.color_write = 0;
    if (!stin__any_samples_begin(ctx, s->query))
        return 1; /* a caller's samples query: taken as an overflow */
    for (q = 0; q < p->primitive_count; q++) {
        int last = (int)q * k + k - 1;
        attach_layer(ctx, last + 1); /* not the array it reads; nothing is written */
        peel_draw(ctx, &ctx->csg->primitives[p->first_primitive + q], last, &ps);
    }
    return stin__any_samples_end(ctx, s->query);
}

/* Every layer of p's primitives (and the cap's, where the near plane may
 * lie inside it); 0 when a primitive overflows k. */
static int peel_product(stin_context *ctx, const stin__csg_product *p, int k, int *cap)
{
    stin__csg_interval_state *s = ctx->csg->interval;
    uint32_t q;
    int j;
    GL(ctx, UseProgram)(s->peel_prog);
    stin__lit_program_forget(ctx);
    ctx->bound_mesh = 0xffffffffu;
    GL(ctx, UniformMatrix4fv)(s->peel_view_proj, 1, GL_FALSE, ctx->view_proj);
    GL(ctx, Uniform1i)(s->peel_previous, previous_unit(ctx));
    if (s->peel_displace.map >= 0) /* undisplaced draws leave it at its unit too */
        GL(ctx, Uniform1i)(s->peel_displace.map, ctx->sel.displace_unit);
    *cap = 0;
    for (q = 0; q < p->primitive_count; q++) {
        const stin__draw *d = &ctx->csg->primitives[p->first_primitive + q];
        int g = (int)q * k, near_cut, far_cut;
        stin__csg_planes_cut(ctx, d, &near_cut, &far_cut);
        *cap |= near_cut;
        if (one_interval(ctx)) { /* the seed's G-buffer: nearest front, nearest back */
            peel(ctx, d, g, -1, stin__csg_culled_face(d, 0));
            peel(ctx, d, g + 1, -1, stin__csg_culled_face(d, 1));
            continue;
        }
        for (j = 0; j < k; j++)
            peel(ctx, d, g + j, j ? g + j - 1 : -1, 0);
    }
    if (!one_interval(ctx) && overflows(ctx, p, k)) {
        if (!s->said_overflow) {
            stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                      "interval: a primitive crosses a camera ray more than %d times "
                      "(desc.csg.interval_layers), or a query of the caller's holds the "
                      "occlusion count; scs or goldfeather resolves that product this frame",
                      k);
            s->said_overflow = 1;
        }
        return 0;
    }
    *cap = *cap && ctx->csg->cap_usable;
    if (*cap) {
        stin__draw d = ctx->csg->primitives[p->first_primitive];
        d.mesh_slot = ctx->csg->cap_slot;
        d.csg = STIN__CSG_CAP;
        stin__memcopy(d.transform, ctx->csg->cap_transform, sizeof d.transform);
        peel(ctx, &d, (int)p->primitive_count * k, -1, 0);
    }
    return 1;
}

/* The walk into the R8 target: per pixel the surface's layer + 1 (0:
 * none), read back into r->stencil. */
static void walk(stin_context *ctx, stin__csg_pixels *r, const stin__csg_product *p, int k,
                 int cap)
{
    stin__csg_interval_state *s = ctx->csg->interval;
    stin__pass_state ps = stin__pass_defaults;
    GLuint terms[2 * STIN__CSG_INTERVAL_MAX_TERMS];
    GLint counts[4];
    uint32_t ti, li;
    int i;
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, s->result,
                                  0);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
    for (ti = 0; ti < p->term_count; ti++) {
        const stin__csg_term *t = &ctx->csg->terms[p->first_term + ti];
        terms[2 * ti] = terms[2 * ti + 1] = 0;
        for (li = 0; li < t->count; li++) {
            uint32_t lit = ctx->csg->literals[t->first + li];
            terms[2 * ti + STIN__CSG_COMPLEMENTED(lit)] |= 1u << STIN__CSG_PRIMITIVE_OF(lit);
        }
    }
    counts[0] = (GLint)p->primitive_count;
    counts[1] = k;
    counts[2] = (GLint)p->term_count;
    counts[3] = cap;
    ps.depth_test = 0;
    stin__pass_apply(ctx, &ps);
    GL(ctx, UseProgram)(s->walk_prog);
    for (i = 0; i < 2; i++) {
        stin__bind_unit(ctx, i, GL_TEXTURE_2D_ARRAY, s->crossing[i]);
        GL(ctx, Uniform1i)(s->walk_crossing[i], i);
    }
    GL(ctx, Uniform4iv)(s->walk_counts, 1, counts);
    GL(ctx, Uniform2uiv)(s->walk_terms, (GLsizei)p->term_count, terms);
    stin__screen_quad(ctx);
    ctx->stats.passes++;
    GL(ctx, ReadPixels)(r->x, r->y, r->w, r->h, GL_RED, GL_UNSIGNED_BYTE, r->stencil);
    for (i = 0; i < 2; i++)
        stin__bind_unit(ctx, i, GL_TEXTURE_2D_ARRAY, 0);
    stin__bind_unit(ctx, previous_unit(ctx), GL_TEXTURE_2D_ARRAY, 0);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
}

/* Each layer some pixel's surface lies on, peeled once more in the
 * frame's depth buffer - its depth there is what the face draws' depth
 * EQUAL meets; a texture's may differ in the last bit (Mesa rasterises
 * into textures flipped) - against the layer before within TOLERANCE (the
 * two rasterisations differ far less; crossings of one primitive closer
 * than that are one), read back and kept where nearer (goldfeather's
 * read of the frame's depth). */
#define TOLERANCE (16.0f / 16777216.0f)
static void keep_layers(stin_context *ctx, stin__csg_pixels *r, stin__csg_product *p, int k,
                        int cap)
{
    stin__csg_interval_state *s = ctx->csg->interval;
    stin__pass_state clear = stin__pass_defaults, ps = stin__pass_defaults;
    int cap_layer = (int)p->primitive_count * k, g;
    unsigned char used[STIN__CSG_INTERVAL_MAX_LAYER_INDEX + 1];
    stin__csg_select select;
    size_t i;
    select.texture = s->result;
    p->capped = 0;
    stin__memzero(used, sizeof used);
    for (i = 0; i < r->pixels; i++)
        used[r->stencil[i]] = 1;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->csg->resolve_fbo);
    GL(ctx, UseProgram)(s->peel_prog);
    GL(ctx, Uniform1f)(s->peel_tolerance, TOLERANCE);
    ctx->bound_mesh = 0xffffffffu;
    clear.depth_write = 1;
    clear.color_write = 0;
    ps.depth_test = 1;
    ps.color_write = 0;
    for (g = 0; g <= cap_layer; g++) {
        const stin__draw *d = &ctx->csg->primitives[p->first_primitive + g / k];
        stin__draw cap_draw;
        if (!used[g + 1])
            continue;
        if (g == cap_layer) {
            if (!cap)
                break;
            cap_draw = ctx->csg->primitives[p->first_primitive];
            cap_draw.mesh_slot = ctx->csg->cap_slot;
            cap_draw.csg = STIN__CSG_CAP;
            stin__memcopy(cap_draw.transform, ctx->csg->cap_transform,
                          sizeof cap_draw.transform);
            d = &cap_draw;
        }
        stin__pass_apply(ctx, &clear);
        stin__clear_depth(ctx, 1.0);
        GL(ctx, Clear)(GL_DEPTH_BUFFER_BIT);
        peel_draw(ctx, d, g % k && g != cap_layer ? g - 1 : -1, &ps);
        select.id = g + 1;
        if (stin__csg_candidate_open(ctx, r) &&
            stin__csg_candidate_take(ctx, NULL, r, &select, NULL, g == cap_layer))
            p->capped |= g == cap_layer;
        GL(ctx, UseProgram)(s->peel_prog); /* the GPU's merge took the program */
    }
    GL(ctx, Uniform1f)(s->peel_tolerance, 0.0f);
    stin__bind_unit(ctx, previous_unit(ctx), GL_TEXTURE_2D_ARRAY, 0);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
}

int stin__csg_interval_product(stin_context *ctx, const stin__path *path, stin__csg_pixels *r,
                               stin__csg_product *p)
{
    stin__csg_interval_state *s = ctx->csg->interval;
    int k = layers_of(ctx), cap = 0, done;
    const char *why;
    if (!chosen(ctx))
        return 0;
    why = unfit(ctx, p, k);
    if (why) {
        fall_back(ctx, why);
        return 0;
    }
    if (!ensure_targets(ctx, ((int)p->primitive_count * k + 2) / 2)) {
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->csg->resolve_fbo);
        return 0;
    }
    ctx->stats.csg.interval_bytes = s->bytes;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->fbo);
    done = peel_product(ctx, p, k, &cap);
    if (done) {
        walk(ctx, r, p, k, cap);
        keep_layers(ctx, r, p, k, cap);
    }
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->csg->resolve_fbo);
    path->geometry_begin(ctx); /* the resolve's program again, for the products after */
    if (!done)
        return 0;
    ctx->stats.csg.interval_products++;
    return 1;
}
