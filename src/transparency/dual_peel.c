/* SPDX-License-Identifier: MIT */
/* "dual-peel" (GL4): dual depth peeling of the blended draws (Bavoil & Myers
 * 2008), two layers per geometry pass, each lit through the frame's stages
 * as depth-peel lights one (transparency/peel.c holds the shared objects and
 * the entry points that turn here).
 * Pass k draws the blended draws once, without depth test, through the
 * min-max program (shaders/gl4/dual_peel_minmax.frag): a fragment in front
 * of the opaque depth and strictly between pass k - 1's nearest and
 * farthest writes (-z, z) with MAX blending into RG32F, so the texel ends
 * as (-near, far) of what no pass has taken yet. Layer 2k ("front k") is
 * the surface at near, layer 2k + 1 ("back k") the one at far where far is
 * not also near (one surface left: drawn once, as a front layer). A layer's
 * depth is written by drawing the blended draws again through the lit
 * programs, whose chunk (shaders/gl4/dual_peel.glsl) keeps the fragments
 * whose gl_FragCoord.z equals the recorded one: the same value, the same
 * vertex shader (invariant gl_Position), so the comparison is exact and no
 * copy of depth rounds it. The frame then lights the layer as it lights
 * opaque surfaces. Front layers composite under one another (C += T a c,
 * T *= 1 - a), back layers over one another (C = a c + (1 - a) C,
 * T *= 1 - a), into RGBA16F; at the end back goes under front and the
 * whole over the frame as depth-peel's: frame = C + T frame.
 * Peeling stops at desc.transparency.layers, at a pass that found nothing
 * (occlusion query), or after a back layer that drew nothing (no pixel had
 * a third surface left, so the next pass would find nothing): a scene of N
 * layers takes N / 2 + 1 passes (integer division). */
#include "transparency/transparency_private.h"

static const char *const minmax_uniforms[] = {"u_model", "u_view_proj", "u_previous",
                                              "u_opaque", "u_params"};

/* The min-max program, plain (0) or tessellated (1). */
static int build_minmax(stin_context *ctx, int tess, char *msg, size_t size)
{
    stin__dual_state *d = &ctx->peel->d;
    stin__program_source src;
    GLint *locs[5];
    int i;
    stin__memzero(&src, sizeof src);
    src.vert = "gl4/lit.vert"; /* the lit programs' vertex stage: the same depths */
    src.frag = "gl4/dual_peel_minmax.frag";
    src.tessellate = tess;
    d->program[tess] = stin__program_build_source(ctx, &src, msg, size);
    if (!d->program[tess])
        return 0;
    locs[0] = &d->u_model[tess];
    locs[1] = &d->u_view_proj[tess];
    locs[2] = &d->u_previous[tess];
    locs[3] = &d->u_opaque[tess];
    locs[4] = &d->u_params[tess];
    for (i = 0; i < 5; i++)
        *locs[i] = GL(ctx, GetUniformLocation)(d->program[tess], minmax_uniforms[i]);
    stin__displace_locate(ctx, d->program[tess], 1, &d->displace[tess]);
    return 1;
}

int stin__dual_init(stin_context *ctx, char *msg, size_t size)
{
    if (!build_minmax(ctx, 0, msg, size))
        return 0;
    /* displaced draws tessellated in the lit passes are so in the min-max pass */
    return !stin__displace_tessellated(ctx) || build_minmax(ctx, 1, msg, size);
}

void stin__dual_release(stin_context *ctx)
{
    stin__dual_state *d = &ctx->peel->d;
    GLuint tex[6];
    int i;
    for (i = 0; i < 2; i++) {
        if (d->program[i])
            GL(ctx, DeleteProgram)(d->program[i]);
        tex[i] = d->minmax[i];
        tex[2 + i] = d->front[i];
        tex[4 + i] = d->back[i];
    }
    for (i = 0; i < 6; i++)
        if (tex[i])
            GL(ctx, DeleteTextures)(1, &tex[i]);
    if (d->minmax_fbo)
        GL(ctx, DeleteFramebuffers)(1, &d->minmax_fbo);
    stin__memzero(d, sizeof *d);
}

GLenum stin__dual_size(stin_context *ctx, int w, int h)
{
    stin__dual_state *d = &ctx->peel->d;
    GLenum status;
    int i;
    if (!d->minmax_fbo) {
        GL(ctx, GenFramebuffers)(1, &d->minmax_fbo);
        GL(ctx, GenTextures)(2, d->minmax);
        GL(ctx, GenTextures)(2, d->front);
        GL(ctx, GenTextures)(2, d->back);
    }
    for (i = 0; i < 2; i++) {
        stin__peel_screen_texture(ctx, d->minmax[i], GL_RG32F, w, h);
        stin__peel_screen_texture(ctx, d->front[i], GL_RGBA16F, w, h);
        stin__peel_screen_texture(ctx, d->back[i], GL_RGBA16F, w, h);
    }
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    status = stin__rt_attach(ctx, d->minmax_fbo, d->minmax[0], 0, 0);
    if (status == GL_FRAMEBUFFER_COMPLETE) /* a float colour target of the composite */
        status = stin__rt_attach(ctx, ctx->peel->composite_fbo, d->front[0], 0, 0);
    return status;
}

static int front_layer(const stin__peel_state *s) { return (s->layer & 1) == 0; }

void stin__dual_uniforms(stin_context *ctx, const stin__program *p)
{
    const stin__peel_state *s = ctx->peel;
    float params[4] = {0, 0, 0, 0};
    if (s->peeling) {
        params[0] = 1.0f / (float)s->width;
        params[1] = 1.0f / (float)s->height;
        params[2] = front_layer(s) ? 1.0f : 2.0f;
        params[3] = 1.0f;
    }
    GL(ctx, Uniform1i)(p->u_peel_previous, s->unit);
    GL(ctx, Uniform4fv)(p->u_peel_params, 1, params);
}

/* Clears composite `tex` to nothing yet: C = 0, T = 1. */
static void clear_composite(stin_context *ctx, GLuint tex)
{
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    stin__peel_clear(ctx, 0, 0, 0, 1, 0);
}

void stin__dual_begin(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    stin__dual_state *d = &s->d;
    /* the first layer's depth goes into the frame at the end: none yet
     * (a frame whose first pass finds nothing begins no layer) */
    stin__peel_attach(ctx, s->ambient, s->first);
    stin__peel_clear(ctx, 0, 0, 0, 0, 1);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->composite_fbo);
    clear_composite(ctx, d->front[0]);
    clear_composite(ctx, d->back[0]);
    d->front_result = d->back_result = 0;
    d->back_empty = 0;
    d->drawn = 0;
}

/* Geometry pass k: the blended draws' (-near, far) left into minmax[k % 2];
 * returns the samples it drew (0: nothing left). */
static GLuint minmax_pass(stin_context *ctx, int k)
{
    stin__peel_state *s = ctx->peel;
    stin__dual_state *d = &s->d;
    stin__pass_state ps = stin__pass_defaults;
    int t = stin__glsl_tessellated(ctx) && d->program[1] ? 1 : 0;
    float params[4];
    GLuint samples;
    uint32_t i;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, d->minmax_fbo);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                  d->minmax[k % 2], 0);
    ps.depth_test = 0;
    stin__pass_apply(ctx, &ps);
    GL(ctx, ClearColor)(-1.0f, -1.0f, 0.0f, 0.0f); /* near 1, far -1: nothing */
    GL(ctx, Clear)(GL_COLOR_BUFFER_BIT);
    /* MAX blending; ADD again after, the equation every other pass draws
     * with (the frame set it at its start: gl/caller_state.c) */
    ps.blend = 1;
    ps.blend_src = ps.blend_dst = GL_ONE;
    stin__pass_apply(ctx, &ps);
    GL(ctx, BlendEquation)(GL_MAX);
    stin__bind_unit(ctx, s->unit, GL_TEXTURE_2D, k > 0 ? d->minmax[(k - 1) % 2] : 0);
    stin__bind_unit(ctx, s->unit + 1, GL_TEXTURE_2D, s->opaque);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, UseProgram)(d->program[t]);
    stin__lit_program_forget(ctx); /* the lit program is no longer current */
    params[0] = 1.0f / (float)s->width;
    params[1] = 1.0f / (float)s->height;
    params[2] = k > 0 ? 1.0f : 0.0f;
    params[3] = 0.0f;
    GL(ctx, UniformMatrix4fv)(d->u_view_proj[t], 1, GL_FALSE, ctx->view_proj);
    GL(ctx, Uniform1i)(d->u_previous[t], s->unit);
    GL(ctx, Uniform1i)(d->u_opaque[t], s->unit + 1);
    GL(ctx, Uniform4fv)(d->u_params[t], 1, params);
    stin__peel_count_begin(ctx);
    for (i = 0; i < ctx->draw_count; i++)
        if (ctx->draws[i].material.color[3] < 1.0f)
            stin__glsl_submit_geometry(ctx, d->u_model[t], &d->displace[t], &ctx->draws[i]);
    samples = stin__peel_count_end(ctx);
    GL(ctx, BlendEquation)(GL_FUNC_ADD);
    ctx->stats.transparency.peel_passes++;
    ctx->stats.passes++;
    return samples;
}

int stin__dual_layer_begin(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    stin__dual_state *d = &s->d;
    int j = s->layer + 1, all = (ctx->desc.debug_flags & STIN_DEBUG_DUAL_PEEL_NO_EARLY_STOP) != 0;
    if ((uint32_t)j >= ctx->desc.transparency.layers)
        return 0;
    if ((j & 1) == 0) { /* a front layer: its pass first */
        if (d->back_empty && !all)
            return 0;
        if (!minmax_pass(ctx, j / 2) && !all)
            return 0;
    }
    s->layer = j;
    s->peeling = 1;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->fbo);
    stin__peel_attach(ctx, s->ambient, j == 0 ? s->first : s->depth[0]);
    stin__peel_clear(ctx, 0, 0, 0, 0, 1);
    stin__bind_unit(ctx, s->unit, GL_TEXTURE_2D, d->minmax[(j / 2) % 2]);
    stin__bind_unit(ctx, s->unit + 1, GL_TEXTURE_2D, 0);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    stin__lit_uniforms_stale(ctx); /* every lit program's peel uniforms are stale */
    stin__peel_count_begin(ctx);
    return 1;
}

int stin__dual_layer_lights(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    GLuint samples = stin__peel_count_end(ctx);
    s->d.drawn = samples != 0;
    if (!samples) {
        if (!front_layer(s)) /* every pixel had one surface left at most */
            s->d.back_empty = 1;
        return 0;
    }
    ctx->stats.transparency.peel_layers++;
    stin__peel_lights_target(ctx);
    return 1;
}

/* The composite program with the layer's textures on units 0-1, the
 * composite `accum` on 2, `first` (depth) on 3, `back` on 4, and mode 0
 * (a front layer under), 1 (a back layer over) or 2 (back under front,
 * over the frame). */
static void composite_program(stin_context *ctx, int mode, GLuint accum, GLuint first,
                              GLuint back)
{
    stin__peel_state *s = ctx->peel;
    float params[4];
    params[0] = 1.0f / (float)s->width;
    params[1] = 1.0f / (float)s->height;
    params[2] = (float)mode;
    params[3] = mode == 2 ? (float)s->coverage : 0.0f;
    GL(ctx, UseProgram)(s->program);
    stin__lit_program_forget(ctx);
    GL(ctx, Uniform1i)(s->u_ambient, 0);
    GL(ctx, Uniform1i)(s->u_lights, 1);
    GL(ctx, Uniform1i)(s->u_accum, 2);
    GL(ctx, Uniform1i)(s->u_first, 3);
    GL(ctx, Uniform1i)(s->d.u_back, 4);
    GL(ctx, Uniform4fv)(s->u_params, 1, params);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, s->ambient);
    stin__bind_unit(ctx, 1, GL_TEXTURE_2D, s->lights);
    stin__bind_unit(ctx, 2, GL_TEXTURE_2D, accum);
    stin__bind_unit(ctx, 3, GL_TEXTURE_2D, first);
    stin__bind_unit(ctx, 4, GL_TEXTURE_2D, back);
}

static void composite_done(stin_context *ctx)
{
    stin__bind_unit(ctx, 4, GL_TEXTURE_2D, 0);
    stin__peel_composite_done(ctx);
}

void stin__dual_layer_end(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    stin__dual_state *d = &s->d;
    stin__pass_state ps = stin__pass_defaults;
    int front = front_layer(s);
    int *result = front ? &d->front_result : &d->back_result;
    GLuint *pair = front ? d->front : d->back;
    s->peeling = 0; /* the composite and whatever follows are no layer's */
    stin__lit_uniforms_stale(ctx);
    if (!d->drawn)
        return;
    stin__bind_unit(ctx, s->unit, GL_TEXTURE_2D, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->composite_fbo);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                  pair[1 - *result], 0);
    ps.depth_test = 0;
    stin__pass_apply(ctx, &ps);
    composite_program(ctx, front ? 0 : 1, pair[*result], 0, 0);
    stin__screen_quad(ctx);
    composite_done(ctx);
    *result = 1 - *result;
    ctx->stats.passes++;
}

void stin__dual_end(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    stin__dual_state *d = &s->d;
    stin__peel_over_frame(ctx); /* depth-peel's rule */
    composite_program(ctx, 2, d->front[d->front_result], s->first, d->back[d->back_result]);
    stin__screen_quad(ctx);
    composite_done(ctx);
    ctx->stats.passes++;
}
