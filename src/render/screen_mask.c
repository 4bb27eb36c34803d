/* SPDX-License-Identifier: MIT */
/* Per-light visibility as data: a shadow technique writes each light's
 * visibility into one channel of a screen mask (drawn in its own
 * framebuffer with a copy of the frame's depth), and one lit pass then
 * shades four lights reading their channels (shaders/gl2/shadow_mask.glsl).
 * N shadowed lights cost N visibility passes and N/4 lit passes instead of
 * N lit passes. Needs GLSL lighting, FBOs, packed depth-stencil textures
 * and one texture unit beyond the surface's.
 * The mask is single-sampled: one surface a pixel, the one at its centre.
 * Into a multisampled target the lit pass also reads the depth the mask
 * was drawn against (one more unit, after displacement's) and, where the
 * fragment's surface is not the centre's, takes the neighbouring texel of
 * its own surface (shadow_mask.glsl), so no sample gets the visibility of
 * the surface behind or in front of it. */
#include "internal.h"

struct stin__mask_state {
    GLuint fbo, color, depth_stencil;
    int width, height;    /* allocated texels (0: not yet) */
    int unit;             /* the texture unit the lit pass reads it on */
    int drawable;         /* the context can draw masks (set at stin_create) */
    int usable;           /* and the lit passes can read them (a unit for it) */
    int active;           /* lights of the current lit pass read from it */
    int depth_done;       /* the frame's depth is in the mask's buffer */
    int depth_unit;       /* where the lit pass reads depth_source; -1: no unit spare */
    GLuint depth_source;  /* the depth the mask was drawn against (this group's) */
};

/* Window depth the mask's depth may lie from the fragment's and still be
 * its surface: a few steps of 24 bits (the two are rasterised alike, or by
 * another program of the same transform: vdsm's position buffer). */
#define MASK_SAME_SURFACE (16.0f / 16777216.0f)

/* The lit pass takes the fragment's own surface's texel (file comment):
 * into the frame's multisampled target, where a unit is spare. */
static int lookup_by_depth(const stin_context *ctx)
{
    return ctx->target.multisampled && ctx->draw_fbo == ctx->frame.framebuffer &&
           ctx->mask->depth_unit >= 0 && ctx->mask->depth_source != 0;
}

size_t stin__mask_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(struct stin__mask_state);
}

int stin__mask_drawable(const stin_context *ctx)
{
    uint64_t need = STIN_CAP_BIT(STIN_CAP_FBO) | STIN_CAP_BIT(STIN_CAP_PACKED_DEPTH_STENCIL);
    return (ctx->caps.present & need) == need;
}

int stin__mask_available(const stin_context *ctx)
{
    return ctx->mask->drawable;
}

int stin__mask_usable(const stin_context *ctx)
{
    return ctx->mask->usable;
}

stin__mask_target stin__mask_target_of(const stin_context *ctx)
{
    stin__mask_target t;
    t.fbo = ctx->mask->fbo;
    t.color = ctx->mask->color;
    t.depth_stencil = ctx->mask->depth_stencil;
    t.width = ctx->mask->width;
    t.height = ctx->mask->height;
    return t;
}

void stin__mask_init(stin_context *ctx)
{
    uint64_t need = STIN_CAP_BIT(STIN_CAP_GLSL) | STIN_CAP_BIT(STIN_CAP_FBO) |
                    STIN_CAP_BIT(STIN_CAP_PACKED_DEPTH_STENCIL);
    const stin__technique_row *r =
        stin__technique_row_of(ctx->sel.choice[STIN_FEATURE_SHADOWS].technique);
    stin__memzero(ctx->mask, sizeof *ctx->mask);
    ctx->mask->unit = ctx->sel.shadow_unit;
    ctx->mask->depth_unit =
        ctx->sel.displace_unit + 1 < ctx->sel.unit_limit ? ctx->sel.displace_unit + 1 : -1;
    ctx->mask->drawable = stin__mask_drawable(ctx);
    if ((ctx->caps.present & need) != need ||
        ctx->sel.choice[STIN_FEATURE_LIGHTING].technique == STIN_TECH_LIGHTING_FIXED)
        return;
    /* the unit is the technique's own (vdsm) or a spare selection granted */
    if (!(r && r->fragment_units > 0) && ctx->sel.shadow_spare_units < 1) {
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                  "shadow masks need texture unit %d of %d: each shadowed light gets its own "
                  "lit pass", ctx->mask->unit, ctx->sel.unit_limit);
        return;
    }
    ctx->mask->usable = 1;
}

void stin__mask_release(stin_context *ctx)
{
    if (ctx->mask->fbo)
        GL(ctx, DeleteFramebuffers)(1, &ctx->mask->fbo);
    if (ctx->mask->color)
        GL(ctx, DeleteTextures)(1, &ctx->mask->color);
    if (ctx->mask->depth_stencil)
        GL(ctx, DeleteTextures)(1, &ctx->mask->depth_stencil);
    ctx->mask->fbo = ctx->mask->color = ctx->mask->depth_stencil = 0;
    ctx->mask->width = ctx->mask->height = 0;
}

/* The mask covers the viewport's pixels at the same window coordinates (so
 * scissor boxes and gl_FragCoord need no offset): (x + w) x (y + h). */
static int ensure_size(stin_context *ctx)
{
    const int *vp = ctx->frame.viewport;
    int w = vp[0] + vp[2], h = vp[1] + vp[3];
    GLenum status;
    if (ctx->mask->fbo && w <= ctx->mask->width && h <= ctx->mask->height)
        return 1;
    if (!ctx->mask->fbo) {
        GL(ctx, GenFramebuffers)(1, &ctx->mask->fbo);
        GL(ctx, GenTextures)(1, &ctx->mask->color);
        GL(ctx, GenTextures)(1, &ctx->mask->depth_stencil);
    }
    if (w < ctx->mask->width)
        w = ctx->mask->width;
    if (h < ctx->mask->height)
        h = ctx->mask->height;
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    stin__rt_texture(ctx, ctx->mask->color, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, w, h);
    stin__rt_texture(ctx, ctx->mask->depth_stencil, GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL,
                     GL_UNSIGNED_INT_24_8, w, h);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    status = stin__rt_attach(ctx, ctx->mask->fbo, ctx->mask->color, ctx->mask->depth_stencil,
                             ctx->mask->depth_stencil);
    ctx->mask->width = w;
    ctx->mask->height = h;
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "shadow mask framebuffer incomplete (0x%x): each shadowed light gets its own "
                  "lit pass", (unsigned)status);
        stin__mask_release(ctx);
        ctx->mask->usable = ctx->mask->drawable = 0;
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo); /* lights go on there */
        return 0;
    }
    return 1;
}

int stin__mask_begin(stin_context *ctx, const stin__path *path, int which, int depth)
{
    stin__pass_state ps = stin__pass_defaults;
    if (!ctx->mask->drawable || !ensure_size(ctx))
        return 0;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->mask->fbo);
    ctx->mask->depth_source = depth ? ctx->mask->depth_stencil : 0; /* else the technique names its own */
    stin__pass_apply(ctx, &ps); /* writes on, no scissor: the clear covers the mask */
    GL(ctx, ClearColor)(0.0f, 0.0f, 0.0f, 0.0f);
    if (depth && !ctx->mask->depth_done) {
        stin__clear_depth(ctx, 1.0);
        GL(ctx, ClearStencil)(0);
        GL(ctx, Clear)(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        /* the same program and draws as the target's ambient pass: equal depths */
        path->ambient(ctx, which, 1);
        stin__resolved_depth_again(ctx, path); /* the CSG products' surfaces too */
        ctx->mask->depth_done = 1;
    } else {
        GL(ctx, Clear)(GL_COLOR_BUFFER_BIT);
    }
    return 1;
}

void stin__mask_write(stin_context *ctx, const stin__path *path, int channel, float share)
{
    /* on the far plane, depth GREATER: only where a surface is (the
     * visibility export hands out 0 elsewhere) */
    static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const float value[4] = {share, share, share, share};
    const stin__program *p = &ctx->programs[STIN__PROG_VOLUME];
    stin__pass_state ps = *stin__pass_current(ctx);
    ps.depth_test = 1;
    ps.depth_func = GL_GREATER;
    ps.depth_write = 0;
    ps.depth_clamp = 0;
    ps.color_write = 1;
    ps.color_only = (unsigned char)(channel + 1);
    ps.blend = share < 1.0f; /* a sample's share adds up in the channel */
    ps.blend_src = ps.blend_dst = GL_ONE;
    stin__pass_apply(ctx, &ps);
    path->volume_begin(ctx);
    GL(ctx, UniformMatrix4fv)(p->u_view_proj, 1, GL_FALSE, identity);
    GL(ctx, Uniform4fv)(p->u_color, 1, value);
    path->volume_draw(ctx, identity, stin__screen_quad_vertices(1), 6);
    path->volume_end(ctx);
}

void stin__mask_end(stin_context *ctx)
{
    const int *vp = ctx->frame.viewport;
    stin__pass_state ps = *stin__pass_current(ctx);
    ps.color_only = 0;
    stin__pass_apply(ctx, &ps);
    /* the pass's target: the frame's, or a peeled layer's (depth-peel) */
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    GL(ctx, Viewport)(vp[0], vp[1], vp[2], vp[3]);
    stin__bind_unit(ctx, ctx->mask->unit, GL_TEXTURE_2D, ctx->mask->color);
    if (lookup_by_depth(ctx))
        stin__bind_unit(ctx, ctx->mask->depth_unit, GL_TEXTURE_2D, ctx->mask->depth_source);
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    ctx->mask->active = 1;
    stin__lit_uniforms_stale(ctx); /* the lit programs' mask uniforms change */
}

void stin__mask_depth_from(stin_context *ctx, GLuint depth)
{
    ctx->mask->depth_source = depth;
}

void stin__mask_read_done(stin_context *ctx)
{
    ctx->mask->active = 0;
    stin__lit_uniforms_stale(ctx);
}

void stin__mask_frame_end(stin_context *ctx)
{
    ctx->mask->active = 0;
    ctx->mask->depth_done = 0;
}

void stin__mask_uniforms(stin_context *ctx, const stin__program *p)
{
    float params[4];
    GL(ctx, Uniform1i)(p->u_shadow_kind, ctx->mask->active);
    if (!ctx->mask->active)
        return;
    params[0] = 1.0f / (float)ctx->mask->width;
    params[1] = 1.0f / (float)ctx->mask->height;
    params[2] = lookup_by_depth(ctx) ? 1.0f : 0.0f;
    params[3] = MASK_SAME_SURFACE;
    GL(ctx, Uniform4fv)(p->u_shadow_params, 1, params);
    GL(ctx, Uniform1i)(p->u_shadow_map, ctx->mask->unit);
    if (params[2] != 0.0f)
        GL(ctx, Uniform1i)(p->u_shadow_depth, ctx->mask->depth_unit);
}
