/* SPDX-License-Identifier: MIT */
/* VDSM for area lights (radius > 0, point and spot): per pixel, 64
 * segments to points of the light's disc, one bit each, instead of one
 * segment to its centre. Each casting triangle covers a screen rectangle
 * that holds its whole penumbra (vdsm_soft.geom), tested at its nearest
 * depth against the visible surface's; there the fragment stage tests the
 * pixel's segments against it (vdsm_soft.frag) and the pass ORs the bits
 * over every triangle into an RG32UI texture (glLogicOp); a screen
 * pass then multiplies the light's mask channel (the facing pass's 1 or 0)
 * by the share of the segments no triangle met (vdsm_soft_resolve.frag).
 * The disc's points turn per pixel, so the penumbra takes many levels. The
 * chain's steps decide for the centre alone and are left out (SM and DC
 * read the centre's pyramid); EP keeps the closed meshes' triangles that
 * face away from any point of the light. The programs are built at the
 * first area light; where they do not build, or the frame is tessellated,
 * the light's shadow stays hard, from its centre (logged once). */
#include "render/draw_bounds.h"
#include "shadow/vdsm_private.h"

static const stin__uniform_name soft_uniforms[] = {
    STIN__UNIFORM(stin__vdsm_soft, radius, "u_radius"),
    STIN__UNIFORM(stin__vdsm_soft, lo, "u_lo"),
    STIN__UNIFORM(stin__vdsm_soft, hi, "u_hi"),
};

void stin__vdsm_soft_release(stin_context *ctx)
{
    stin__vdsm_soft *s = &ctx->vdsm->soft;
    stin__vdsm_delete_programs(ctx, &s->prog, &s->resolve_prog, &s->resolve_prog);
    if (s->fbo)
        GL(ctx, DeleteFramebuffers)(1, &s->fbo);
    if (s->bits)
        GL(ctx, DeleteTextures)(1, &s->bits);
    s->fbo = s->bits = 0;
    s->width = s->height = 0;
    s->built = 0;
}

/* The programs, once; 0 where they do not build (logged once). */
static int build(stin_context *ctx)
{
    stin__vdsm_soft *s = &ctx->vdsm->soft;
    char msg[160];
    if (s->built)
        return s->prog != 0;
    s->built = 1;
    msg[0] = '\0';
    s->prog = stin__vdsm_program(ctx, "gl4/vdsm.vert", "gl4/vdsm_soft.geom", "gl4/vdsm_soft.frag",
                                 NULL, 0, msg, sizeof msg);
    if (s->prog)
        s->resolve_prog = stin__vdsm_program(ctx, "gl4/screen.vert", NULL,
                                             "gl4/vdsm_soft_resolve.frag", NULL, 0, msg,
                                             sizeof msg);
    if (!s->resolve_prog) {
        stin__vdsm_delete_programs(ctx, &s->prog, &s->resolve_prog, &s->resolve_prog);
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_SHADER_COMPILE,
                  "vdsm: the area lights' programs failed to build (%s): their shadows are "
                  "hard, from their centre",
                  msg);
        return 0;
    }
    stin__vdsm_polygon_locate(ctx, s->prog, &s->poly);
    STIN__LOCATE(ctx, s->prog, s, soft_uniforms);
    s->resolve_bits = GL(ctx, GetUniformLocation)(s->resolve_prog, "u_bits");
    return 1;
}

/* The bits' texture and framebuffer the size of the position buffer; 0 if
 * incomplete (logged once). */
static int ensure_target(stin_context *ctx)
{
    struct stin__vdsm_state *v = ctx->vdsm;
    stin__vdsm_soft *s = &v->soft;
    GLenum status;
    if (s->fbo && s->width == v->width && s->height == v->height)
        return 1;
    if (!s->fbo) {
        GL(ctx, GenFramebuffers)(1, &s->fbo);
        GL(ctx, GenTextures)(1, &s->bits);
    }
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    stin__rt_texture(ctx, s->bits, GL_RG32UI, GL_RG_INTEGER, GL_UNSIGNED_INT, v->width,
                     v->height);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->fbo);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, s->bits,
                                  0);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, v->depth, 0);
    status = GL(ctx, CheckFramebufferStatus)(GL_FRAMEBUFFER);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, stin__mask_target_of(ctx).fbo);
    s->width = v->width;
    s->height = v->height;
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FALLBACK,
                  "vdsm: the area lights' framebuffer is incomplete (0x%x): their shadows are "
                  "hard, from their centre",
                  (unsigned)status);
        stin__vdsm_soft_release(ctx);
        s->built = 1; /* no retry */
        return 0;
    }
    return 1;
}

/* The world box every receiver lies in: the draws' bounds (a draw without
 * them: a box as large as a float holds comfortably). */
static void receiver_bounds(stin_context *ctx, float lo[3], float hi[3])
{
    uint32_t i;
    int k;
    for (k = 0; k < 3; k++) {
        lo[k] = 1e18f;
        hi[k] = -1e18f;
    }
    for (i = 0; i < ctx->draw_count; i++) {
        float corners[24];
        if (!stin__draw_world_corners(ctx, &ctx->draws[i], corners)) {
            for (k = 0; k < 3; k++) {
                lo[k] = -1e18f;
                hi[k] = 1e18f;
            }
            return;
        }
        for (k = 0; k < 24; k++) {
            lo[k % 3] = corners[k] < lo[k % 3] ? corners[k] : lo[k % 3];
            hi[k % 3] = corners[k] > hi[k % 3] ? corners[k] : hi[k % 3];
        }
    }
}

int stin__vdsm_soft_available(stin_context *ctx)
{
    /* the bits are ORed by glLogicOp, which OpenGL ES does not have */
    return stin__gl_available(ctx, STIN_GLFN_LogicOp) && !ctx->vdsm->tess_active &&
           build(ctx) && ensure_target(ctx);
}

void stin__vdsm_soft_draw(stin_context *ctx, const stin_light_desc *l, const float light[4],
                          int channel)
{
    stin__vdsm_soft *s = &ctx->vdsm->soft;
    const stin__pass_state before = *stin__pass_current(ctx);
    stin__pass_state ps = before;
    static const GLuint zero[4] = {0, 0, 0, 0};
    float lo[3], hi[3];
    GLuint mask_fbo = stin__mask_target_of(ctx).fbo;
    /* the bits, ORed over every casting triangle */
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->fbo);
    ps.color_only = 0;
    /* each rectangle at its nearest depth against the visible surface's
     * (the position buffer's), pulled 4 steps toward the eye against
     * rounding; clamped, as the near plane may cut the region */
    ps.depth_test = (unsigned char)stin__vdsm_depth_tested(ctx);
    ps.depth_clamp = ps.polygon_offset = ps.depth_test;
    ps.depth_write = 0;
    ps.depth_func = GL_LEQUAL;
    ps.offset_factor = 0.0f;
    ps.offset_units = -4.0f;
    stin__pass_apply(ctx, &ps);
    GL(ctx, ClearBufferuiv)(GL_COLOR, 0, zero);
    GL(ctx, Enable)(GL_COLOR_LOGIC_OP);
    GL(ctx, LogicOp)(GL_OR);
    GL(ctx, UseProgram)(s->prog);
    stin__vdsm_polygon_uniforms(ctx, &s->poly, light);
    GL(ctx, Uniform1f)(s->radius, l->radius);
    receiver_bounds(ctx, lo, hi);
    GL(ctx, Uniform3fv)(s->lo, 1, lo);
    GL(ctx, Uniform3fv)(s->hi, 1, hi);
    stin__vdsm_draw_casters(ctx, &s->poly);
    GL(ctx, Disable)(GL_COLOR_LOGIC_OP);
    ctx->stats.passes++;
    /* the mask channel times the share of segments no triangle met */
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, mask_fbo);
    ps = before;
    ps.blend = 1;
    ps.blend_src = GL_ZERO;
    ps.blend_dst = GL_SRC_COLOR;
    ps.color_only = (unsigned char)(channel + 1);
    stin__pass_apply(ctx, &ps);
    GL(ctx, UseProgram)(s->resolve_prog);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, s->bits);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, Uniform1i)(s->resolve_bits, 0);
    stin__screen_quad(ctx);
    ctx->stats.passes++;
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, ctx->vdsm->position);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    stin__pass_apply(ctx, &before);
}
