/* SPDX-License-Identifier: MIT */
/* VDSM for area lights (radius > 0, point and spot): per pixel, 64
 * segments to points of the light's disc, one bit each, instead of one
 * segment to its centre. Each casting triangle covers a screen rectangle
 * that holds its whole penumbra (vdsm_soft.geom), tested at its nearest
 * depth against the visible surface's; there the fragment stage tests the
 * pixel's segments against it (vdsm_soft.frag) and the pass ORs the bits
 * over every triangle into an RG32UI texture (glLogicOp; OpenGL ES has
 * none, so there ES 3.2's image atomics OR them into an R32UI image, a
 * pixel's two words side by side); a screen
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
    if (s->depth_fbo)
        GL(ctx, DeleteFramebuffers)(1, &s->depth_fbo);
    if (s->bits)
        GL(ctx, DeleteTextures)(1, &s->bits);
    s->fbo = s->bits = s->depth_fbo = 0;
    s->width = s->height = 0;
    s->built = 0;
}

/* Whether the bits can be ORed: by glLogicOp, or where OpenGL ES lacks it
 * by GLSL ES 3.20's imageAtomicOr on r32ui images (ES 3.1 has it only with
 * OES_shader_image_atomic, not asked for). */
static int can_or(stin_context *ctx)
{
    if (stin__gl_available(ctx, STIN_GLFN_LogicOp))
        return 1;
    return ctx->caps.es && ctx->caps.glsl_major * 10 + ctx->caps.glsl_minor >= 32 &&
           stin__gl_available(ctx, STIN_GLFN_TexStorage2D) &&
           stin__gl_available(ctx, STIN_GLFN_BindImageTexture) &&
           stin__gl_available(ctx, STIN_GLFN_MemoryBarrier);
}

/* One of the programs, its fragment stage told where the bits are ORed
 * by image atomics. */
static GLuint program(stin_context *ctx, const char *vert, const char *geom, const char *frag,
                      char *msg, size_t size)
{
    stin__program_source src;
    stin__memzero(&src, sizeof src);
    src.vert = vert;
    src.geom = geom;
    src.frag = frag;
    src.frag_defines = ctx->vdsm->soft.image ? "#define STIN_SOFT_IMAGE 1\n" : NULL;
    return stin__program_build_source(ctx, &src, msg, size);
}

/* The programs, once; 0 where they do not build (logged once). */
static int build(stin_context *ctx)
{
    stin__vdsm_soft *s = &ctx->vdsm->soft;
    char msg[160];
    if (s->built)
        return s->prog != 0;
    s->built = 1;
    s->image = !stin__gl_available(ctx, STIN_GLFN_LogicOp);
    msg[0] = '\0';
    s->prog = program(ctx, "gl4/vdsm.vert", "gl4/vdsm_soft.geom", "gl4/vdsm_soft.frag", msg,
                      sizeof msg);
    if (s->prog)
        s->resolve_prog = program(ctx, "gl4/screen.vert", NULL, "gl4/vdsm_soft_resolve.frag",
                                  msg, sizeof msg);
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

/* OpenGL ES: the bits' image, immutable (ES binds no other texture as an
 * image), so a new one at each size; fbo clears it, depth_fbo (the position
 * buffer's depth alone: the image is twice as wide) takes the pass that ORs
 * into it. */
static GLenum image_target(stin_context *ctx)
{
    struct stin__vdsm_state *v = ctx->vdsm;
    stin__vdsm_soft *s = &v->soft;
    GLenum status;
    GL(ctx, DeleteTextures)(1, &s->bits);
    GL(ctx, GenTextures)(1, &s->bits);
    if (!s->depth_fbo)
        GL(ctx, GenFramebuffers)(1, &s->depth_fbo);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, s->bits);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    GL(ctx, TexStorage2D)(GL_TEXTURE_2D, 1, GL_R32UI, 2 * v->width, v->height);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    status = stin__rt_attach(ctx, s->fbo, s->bits, 0, 0);
    return status == GL_FRAMEBUFFER_COMPLETE
               ? stin__rt_attach_depth_only(ctx, s->depth_fbo, v->depth, 0)
               : status;
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
    if (s->image) {
        status = image_target(ctx);
    } else {
        stin__rt_texture(ctx, s->bits, GL_RG32UI, GL_RG_INTEGER, GL_UNSIGNED_INT, v->width,
                         v->height);
        GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
        status = stin__rt_attach(ctx, s->fbo, s->bits, v->depth, 0);
    }
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
    return can_or(ctx) && !ctx->vdsm->tess_active && build(ctx) && ensure_target(ctx);
}

/* The OR over the triangles begins: glLogicOp, or the bits' image bound
 * for the atomics, the depth test against the position buffer's depth. */
static void or_begin(stin_context *ctx)
{
    stin__vdsm_soft *s = &ctx->vdsm->soft;
    if (!s->image) {
        GL(ctx, Enable)(GL_COLOR_LOGIC_OP);
        GL(ctx, LogicOp)(GL_OR);
        return;
    }
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->depth_fbo);
    GL(ctx, BindImageTexture)(0, s->bits, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
}

/* The OR ends: the atomics' writes made visible to the resolve's fetches
 * and to the next light's clear. */
static void or_end(stin_context *ctx)
{
    if (!ctx->vdsm->soft.image) {
        GL(ctx, Disable)(GL_COLOR_LOGIC_OP);
        return;
    }
    GL(ctx, MemoryBarrier)(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    GL(ctx, BindImageTexture)(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
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
    if (s->image)
        ps.scissor = 0; /* the clear reaches both words of every pixel */
    stin__pass_apply(ctx, &ps);
    GL(ctx, ClearBufferuiv)(GL_COLOR, 0, zero);
    or_begin(ctx);
    GL(ctx, UseProgram)(s->prog);
    stin__vdsm_polygon_uniforms(ctx, &s->poly, light);
    GL(ctx, Uniform1f)(s->radius, l->radius);
    receiver_bounds(ctx, lo, hi);
    GL(ctx, Uniform3fv)(s->lo, 1, lo);
    GL(ctx, Uniform3fv)(s->hi, 1, hi);
    stin__vdsm_draw_casters(ctx, &s->poly);
    or_end(ctx);
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
