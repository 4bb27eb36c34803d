/* SPDX-License-Identifier: MIT */
/* The pass-state cache: compare with what GL holds, send the differences. */
#include "internal.h"

#define STENCIL_DEFAULT {GL_ALWAYS, 0, 0xffffffffu, GL_KEEP, GL_KEEP, GL_KEEP}

const stin__pass_state stin__pass_defaults = {
    0, 1, 1, 0, 0, 0, 0, 0, 0, 0,
    GL_LESS, GL_ONE, GL_ZERO, GL_BACK, GL_CCW,
    0.0f, 0.0f,
    {0, 0, 0, 0},
    0xffffffffu,
    STENCIL_DEFAULT, STENCIL_DEFAULT,
    0,
};

static void toggle(stin_context *ctx, GLenum cap, unsigned char on)
{
    if (on)
        GL_ENABLE(ctx, cap);
    else
        GL_DISABLE(ctx, cap);
}

static int same_face(const stin__stencil_face *a, const stin__stencil_face *b)
{
    return a->func == b->func && a->ref == b->ref && a->mask == b->mask && a->fail == b->fail &&
           a->zfail == b->zfail && a->zpass == b->zpass;
}

static void stencil_op(stin_context *ctx, const stin__stencil_face *f)
{
    GLenum audited = f->zfail != GL_KEEP ? f->zfail : f->zpass; /* WRAP needs its extension */
    GL_ENUM(ctx, StencilOp, audited)(f->fail, f->zfail, f->zpass);
}

/* Both faces' stencil. Separate stencil (GL 2.0) sets the operations per
 * face (one function for both: the volumes never differ there); EXT
 * two-side switches the active face. */
static void apply_stencil(stin_context *ctx, const stin__pass_state *s, const stin__pass_state *c,
                          int force)
{
    uint64_t caps = ctx->caps.present;
    int separate = (caps & STIN_CAP_BIT(STIN_CAP_SEPARATE_STENCIL)) != 0;
    int ext = !separate && (caps & STIN_CAP_BIT(STIN_CAP_STENCIL_TWO_SIDE));
    const stin__stencil_face *back = s->two_sided ? &s->back : &s->front;
    if (!force && s->two_sided == c->two_sided && same_face(&s->front, &c->front) &&
        (!s->two_sided || same_face(&s->back, &c->back)))
        return;
    if (ext && (force || s->two_sided != c->two_sided))
        toggle(ctx, GL_STENCIL_TEST_TWO_SIDE_EXT, s->two_sided);
    if (ext && (s->two_sided || force)) { /* forced: the back face to the front's */
        GL(ctx, ActiveStencilFaceEXT)(GL_BACK);
        stencil_op(ctx, back);
        GL(ctx, StencilFunc)(back->func, back->ref, back->mask);
        GL(ctx, ActiveStencilFaceEXT)(GL_FRONT);
    }
    GL(ctx, StencilFunc)(s->front.func, s->front.ref, s->front.mask);
    if (separate && s->two_sided) {
        GL(ctx, StencilOpSeparate)(GL_BACK, back->fail, back->zfail, back->zpass);
        GL(ctx, StencilOpSeparate)(GL_FRONT, s->front.fail, s->front.zfail, s->front.zpass);
    } else {
        stencil_op(ctx, &s->front);
    }
}

int stin__pass_two_sided(const stin_context *ctx)
{
    return (ctx->caps.present & (STIN_CAP_BIT(STIN_CAP_STENCIL_TWO_SIDE) |
                                 STIN_CAP_BIT(STIN_CAP_SEPARATE_STENCIL))) != 0;
}

int stin__pass_two_sided_wrap(const stin_context *ctx)
{
    return (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_STENCIL_WRAP)) && stin__pass_two_sided(ctx);
}

void stin__pass_apply(stin_context *ctx, const stin__pass_state *s)
{
    stin__pass_state *c = &ctx->pass;
    int f = !ctx->pass_known;
#define CHANGED(field) (f || s->field != c->field)
    if (CHANGED(depth_test))
        toggle(ctx, GL_DEPTH_TEST, s->depth_test);
    if (CHANGED(depth_func))
        GL(ctx, DepthFunc)(s->depth_func);
    if (CHANGED(depth_write))
        GL(ctx, DepthMask)(s->depth_write ? GL_TRUE : GL_FALSE);
    if (CHANGED(color_write) || CHANGED(color_only)) {
        GLboolean w[4];
        int k;
        for (k = 0; k < 4; k++)
            w[k] = s->color_write && (!s->color_only || s->color_only == k + 1) ? GL_TRUE : GL_FALSE;
        GL(ctx, ColorMask)(w[0], w[1], w[2], w[3]);
    }
    if (CHANGED(blend))
        toggle(ctx, GL_BLEND, s->blend);
    if (CHANGED(blend_src) || CHANGED(blend_dst))
        GL(ctx, BlendFunc)(s->blend_src, s->blend_dst);
    if (CHANGED(cull))
        toggle(ctx, GL_CULL_FACE, s->cull);
    if (CHANGED(cull_face))
        GL(ctx, CullFace)(s->cull_face);
    if (CHANGED(front_face))
        GL(ctx, FrontFace)(s->front_face);
    if (CHANGED(polygon_offset))
        toggle(ctx, GL_POLYGON_OFFSET_FILL, s->polygon_offset);
    if (s->polygon_offset && (CHANGED(offset_factor) || CHANGED(offset_units)))
        GL(ctx, PolygonOffset)(s->offset_factor, s->offset_units);
    if (CHANGED(scissor))
        toggle(ctx, GL_SCISSOR_TEST, s->scissor);
    if (s->scissor && (f || s->scissor_box[0] != c->scissor_box[0] ||
                       s->scissor_box[1] != c->scissor_box[1] ||
                       s->scissor_box[2] != c->scissor_box[2] ||
                       s->scissor_box[3] != c->scissor_box[3]))
        GL(ctx, Scissor)(s->scissor_box[0], s->scissor_box[1], s->scissor_box[2],
                         s->scissor_box[3]);
    if ((ctx->caps.present & STIN_CAP_BIT(STIN_CAP_DEPTH_CLAMP)) && CHANGED(depth_clamp))
        toggle(ctx, GL_DEPTH_CLAMP, s->depth_clamp);
    if (CHANGED(stencil_test))
        toggle(ctx, GL_STENCIL_TEST, s->stencil_test);
    if (CHANGED(stencil_write_mask))
        GL(ctx, StencilMask)(s->stencil_write_mask);
    apply_stencil(ctx, s, c, f);
#undef CHANGED
    {
        /* offsets and the box are sent only while on: the cache keeps what GL
         * holds (unknown after a forget: a box no pass asks for) */
        float factor = f ? -1e30f : c->offset_factor, units = f ? -1e30f : c->offset_units;
        int box[4], k;
        for (k = 0; k < 4; k++)
            box[k] = f ? -1 : c->scissor_box[k];
        *c = *s;
        if (!s->polygon_offset) {
            c->offset_factor = factor;
            c->offset_units = units;
        }
        if (!s->scissor)
            for (k = 0; k < 4; k++)
                c->scissor_box[k] = box[k];
    }
    ctx->pass_known = 1;
}

const stin__pass_state *stin__pass_current(const stin_context *ctx)
{
    return ctx->pass_known ? &ctx->pass : &stin__pass_defaults;
}

void stin__pass_forget(stin_context *ctx) { ctx->pass_known = 0; }

stin__pass_state stin__pass_draw(const stin_context *ctx, int additive, int blend_alpha)
{
    stin__pass_state s = *stin__pass_current(ctx);
    s.depth_test = 1;
    s.depth_func = additive ? GL_EQUAL : GL_LESS;
    s.depth_write = !additive;
    s.color_write = 1;
    s.color_only = ctx->pass_channel;
    s.blend = additive || blend_alpha;
    s.blend_src = blend_alpha ? GL_SRC_ALPHA : GL_ONE;
    s.blend_dst = additive ? GL_ONE : blend_alpha ? GL_ONE_MINUS_SRC_ALPHA : GL_ZERO;
    if (ctx->pass_blend[0]) {
        s.blend = 1;
        s.blend_src = ctx->pass_blend[0];
        s.blend_dst = ctx->pass_blend[1];
    }
    if (!s.blend) { /* keep the cached function: nothing to send */
        s.blend_src = ctx->pass_known ? ctx->pass.blend_src : GL_ONE;
        s.blend_dst = ctx->pass_known ? ctx->pass.blend_dst : GL_ZERO;
    }
    s.polygon_offset = 0;
    s.cull = ctx->lit_cull != 0; /* a shadow test that differs by side draws one at a time */
    if (s.cull)
        s.cull_face = ctx->lit_cull;
    return s;
}

void stin__bind_unit(stin_context *ctx, int unit, GLenum target, GLuint name)
{
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + unit));
    GL(ctx, BindTexture)(target, name);
    if (unit < 32)
        ctx->units_used |= 1u << unit;
}

void stin__unbind_units(stin_context *ctx, uint32_t units)
{
    int u;
    int cube = (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_TEXTURE_CUBE_MAP)) != 0;
    int core = ctx->caps.profile == STIN_GL_PROFILE_CORE;
    for (u = 31; u >= 0; u--) {
        if (!(units & (1u << u)))
            continue;
        if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE))
            GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + u));
        GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
        if (!core)
            GL(ctx, BindTexture)(GL_TEXTURE_1D, 0);
        if (cube)
            GL(ctx, BindTexture)(GL_TEXTURE_CUBE_MAP, 0);
    }
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    ctx->units_used &= ~units;
}

void stin__unbind_used_units(stin_context *ctx) { stin__unbind_units(ctx, ctx->units_used); }
