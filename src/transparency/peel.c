/* SPDX-License-Identifier: MIT */
/* "depth-peel": front-to-back depth peeling of the blended draws (Everitt
 * 2001). Pass k draws them with depth LESS into a fresh depth buffer through
 * the lit programs, whose peel chunk (shaders/gl2/peel.glsl) discards what
 * lies at or in front of layer k - 1 or at or behind the opaque depth: the
 * nearest surface left per pixel is layer k. The layer is then lit as the
 * frame lights its opaque surfaces (frame/frame.c runs the lighting stages with
 * the layer standing in for the opaque draws, against the layer's depth and
 * stencil), and composited under the layers before it:
 *   C += T a c,  T *= 1 - a   (from C = 0, T = 1)
 * At the end the composite goes over the opaque image, frame = C + T frame,
 * and the first layer's depth into the frame's depth where there is one (as
 * the sorted draws leave it: the nearest surface's).
 * Peeling stops at desc.transparency.layers or at the first pass that drew
 * nothing (an occlusion query).
 * "dual-peel" (transparency/dual_peel.c) shares this file's objects and
 * entry points: each stin__peel_* call below turns to it when it is chosen. */
#include "transparency/transparency_private.h"

static int chosen(const stin_context *ctx)
{
    stin_technique t = ctx->sel.choice[STIN_FEATURE_TRANSPARENCY].technique;
    return t == STIN_TECH_TRANSPARENCY_DEPTH_PEEL || t == STIN_TECH_TRANSPARENCY_DUAL_PEEL;
}

static int dual(const stin_context *ctx)
{
    return ctx->sel.choice[STIN_FEATURE_TRANSPARENCY].technique ==
           STIN_TECH_TRANSPARENCY_DUAL_PEEL;
}

size_t stin__peel_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(stin__peel_state);
}

int stin__peel_chunks(const stin_context *ctx, int variant,
                      const char *names[STIN__FEATURE_CHUNKS])
{
    (void)variant; /* it wraps main's first call, whatever the surface */
    names[0] = !chosen(ctx) ? NULL : dual(ctx) ? "dual_peel.glsl" : "peel.glsl";
    return names[0] != NULL;
}

/* A window-sized texture of one of the peel's formats (DEPTH24_STENCIL8,
 * RGBA8, RG32F, RGBA16F), nearest texels. */
void stin__peel_screen_texture(stin_context *ctx, GLuint tex, GLenum format, int w, int h)
{
    if (format == GL_DEPTH24_STENCIL8)
        stin__rt_texture(ctx, tex, GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, w,
                         h);
    else if (format == GL_RGBA8)
        stin__rt_texture(ctx, tex, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, w, h);
    else
        stin__rt_texture(ctx, tex, format, format == GL_RG32F ? GL_RG : GL_RGBA, GL_FLOAT, w, h);
}

/* The peel's framebuffer with `color` and the depth-stencil `depth`. */
void stin__peel_attach(stin_context *ctx, GLuint color, GLuint depth)
{
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
}

/* Textures covering the viewport at its window coordinates ((x + w) x
 * (y + h), so gl_FragCoord needs no offset), grown when a frame needs more. */
static int ensure_size(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    const int *vp = ctx->frame.viewport;
    int w = vp[0] + vp[2], h = vp[1] + vp[3], i;
    GLenum status;
    if (w <= s->width && h <= s->height)
        return 1;
    if (!s->fbo) { /* the first frame with blended draws (a frame without needs none) */
        GL(ctx, GenFramebuffers)(1, &s->fbo);
        GL(ctx, GenFramebuffers)(1, &s->composite_fbo);
        GL(ctx, GenTextures)(2, s->depth);
        GL(ctx, GenTextures)(2, s->accum);
        GL(ctx, GenTextures)(1, &s->opaque);
        GL(ctx, GenTextures)(1, &s->first);
        GL(ctx, GenTextures)(1, &s->ambient);
        GL(ctx, GenTextures)(1, &s->lights);
    }
    w = w > s->width ? w : s->width;
    h = h > s->height ? h : s->height;
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    for (i = 0; i < 2; i++) { /* dual-peel: one layer depth, its own composites */
        if (i == 0 || !s->dual)
            stin__peel_screen_texture(ctx, s->depth[i], GL_DEPTH24_STENCIL8, w, h);
        if (!s->dual)
            stin__peel_screen_texture(ctx, s->accum[i], s->accum_format, w, h);
    }
    stin__peel_screen_texture(ctx, s->opaque, GL_DEPTH24_STENCIL8, w, h);
    stin__peel_screen_texture(ctx, s->first, GL_DEPTH24_STENCIL8, w, h);
    stin__peel_screen_texture(ctx, s->ambient, GL_RGBA8, w, h);
    stin__peel_screen_texture(ctx, s->lights, GL_RGBA8, w, h);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    status = stin__rt_attach(ctx, s->fbo, s->ambient, s->depth[0], s->depth[0]);
    if (s->dual && status == GL_FRAMEBUFFER_COMPLETE)
        status = stin__dual_size(ctx, w, h);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    s->width = w;
    s->height = h;
    if (status == GL_FRAMEBUFFER_COMPLETE)
        return 1;
    if (!s->said_failed)
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "%s: its framebuffer is incomplete (0x%x); blended draws are drawn "
                  "sorted", s->dual ? "dual-peel" : "depth-peel", (unsigned)status);
    s->said_failed = 1;
    s->width = s->height = 0;
    return 0;
}

static const stin__uniform_name composite_uniforms[] = {
    STIN__UNIFORM(stin__peel_state, u_ambient, "u_ambient"),
    STIN__UNIFORM(stin__peel_state, u_lights, "u_lights"),
    STIN__UNIFORM(stin__peel_state, u_accum, "u_accum"),
    STIN__UNIFORM(stin__peel_state, u_first, "u_first"),
    STIN__UNIFORM(stin__peel_state, u_params, "u_params"),
    STIN__UNIFORM(stin__peel_state, d.u_back, "u_back"),
};

void stin__peel_init(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    int gl4 = ctx->sel.choice[STIN_FEATURE_LIGHTING].technique == STIN_TECH_LIGHTING_GLSL150;
    char frag[40], msg[160], why[220];
    stin__memzero(s, sizeof *s);
    s->layer = -1;
    if (!chosen(ctx))
        return;
    s->unit = ctx->sel.transparency_unit;
    s->dual = dual(ctx);
    /* GL4: the composite in half floats, one rounding at the end instead of
     * one per layer (8 bits: up to 2/255 off after four layers) */
    s->accum_format = gl4 && (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FLOAT_TEXTURE))
                          ? GL_RGBA16F
                          : GL_RGBA8;
    stin__formatf(frag, sizeof frag, "%s/%speel_composite.frag", gl4 ? "gl4" : "gl2",
                  s->dual ? "dual_" : "");
    msg[0] = '\0';
    /* GL4 shares vdsm's full-viewport quad shader */
    s->program = stin__program_build(ctx, gl4 ? "gl4/screen.vert" : "gl2/screen.vert",
                                     frag, NULL, 0, msg, sizeof msg);
    if (!s->program || (s->dual && !stin__dual_init(ctx, msg, sizeof msg))) {
        /* dual-peel a step down to depth-peel (the lit programs built again
         * with depth-peel's chunk), depth-peel to sorted */
        int was_dual = s->dual;
        stin__formatf(why, sizeof why, "%s: its %s program failed to build (%s)",
                      was_dual ? "dual-peel" : "depth-peel", s->program ? "min-max" : "composite",
                      msg);
        stin__peel_release(ctx);
        stin__demote(ctx, STIN_FEATURE_TRANSPARENCY,
                     was_dual ? STIN_TECH_TRANSPARENCY_DEPTH_PEEL : STIN_TECH_TRANSPARENCY_SORTED, why);
        if (was_dual && stin__glsl_init(ctx, STIN_TIER_GL4, msg, sizeof msg) == STIN_OK)
            stin__peel_init(ctx);
        else if (was_dual) /* cannot happen where they built a moment ago */
            stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_SHADER_COMPILE,
                      "depth-peel: the lit programs failed to build again (%s)", msg);
        return;
    }
    STIN__LOCATE(ctx, s->program, s, composite_uniforms);
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_ANY_SAMPLES_QUERY))
        GL(ctx, GenQueries)(1, &s->query);
    s->ready = 1;
}

void stin__peel_release(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    GLuint tex[8];
    int i, n = 0;
    stin__dual_release(ctx);
    if (s->program)
        GL(ctx, DeleteProgram)(s->program);
    if (s->fbo)
        GL(ctx, DeleteFramebuffers)(1, &s->fbo);
    if (s->composite_fbo)
        GL(ctx, DeleteFramebuffers)(1, &s->composite_fbo);
    if (s->query)
        GL(ctx, DeleteQueries)(1, &s->query);
    for (i = 0; i < 2; i++) {
        tex[n++] = s->depth[i];
        tex[n++] = s->accum[i];
    }
    tex[n++] = s->opaque;
    tex[n++] = s->first;
    tex[n++] = s->ambient;
    tex[n++] = s->lights;
    for (i = 0; i < n; i++)
        if (tex[i])
            GL(ctx, DeleteTextures)(1, &tex[i]);
    stin__memzero(s, sizeof *s);
    s->layer = -1;
}

static const stin__uniform_name lit_uniforms[] = {
    STIN__UNIFORM(stin__program, u_peel_previous, "u_peel_previous"),
    STIN__UNIFORM(stin__program, u_peel_opaque, "u_peel_opaque"),
    STIN__UNIFORM(stin__program, u_peel_params, "u_peel_params"),
};

void stin__peel_locate(stin_context *ctx, stin__program *p)
{
    STIN__LOCATE(ctx, p->name, p, lit_uniforms);
}

void stin__peel_uniforms(stin_context *ctx, const stin__program *p)
{
    const stin__peel_state *s = ctx->peel;
    float params[4] = {0, 0, 0, 0};
    if (p->u_peel_params < 0)
        return;
    if (s->dual) {
        stin__dual_uniforms(ctx, p);
        return;
    }
    if (s->peeling) {
        params[0] = 1.0f / (float)s->width;
        params[1] = 1.0f / (float)s->height;
        params[2] = s->layer > 0 ? 1.0f : 0.0f;
        params[3] = 1.0f;
    }
    GL(ctx, Uniform1i)(p->u_peel_previous, s->unit);
    GL(ctx, Uniform1i)(p->u_peel_opaque, s->unit + 1);
    GL(ctx, Uniform4fv)(p->u_peel_params, 1, params);
}

int stin__peel_camera_set(const stin_context *ctx, const stin__draw *d)
{
    int blended = d->material.color[3] < 1.0f;
    if (ctx->peel->peeling)
        return blended ? STIN__OPAQUE : 0;
    return blended ? STIN__BLENDED : STIN__OPAQUE;
}

int stin__peel_in_layer(const stin_context *ctx) { return ctx->peel->peeling; }

static int frame_blended(const stin_context *ctx)
{
    uint32_t i;
    for (i = 0; i < ctx->draw_count; i++)
        if (ctx->draws[i].material.color[3] < 1.0f)
            return 1;
    return 0;
}

/* Clears the bound framebuffer's colour to c, and depth and stencil too. */
void stin__peel_clear(stin_context *ctx, float r, float g, float b, float a, int depth)
{
    stin__pass_state ps = stin__pass_defaults; /* writes on, no scissor */
    stin__pass_apply(ctx, &ps);
    GL(ctx, ClearColor)(r, g, b, a);
    stin__clear_depth(ctx, 1.0);
    GL(ctx, ClearStencil)(0);
    GL(ctx, Clear)(GL_COLOR_BUFFER_BIT |
                   (depth ? GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT : 0u));
}

int stin__peel_begin(stin_context *ctx, const stin__path *path)
{
    stin__peel_state *s = ctx->peel;
    if (!s->ready || !frame_blended(ctx) || !ensure_size(ctx))
        return 0;
    s->frame_fbo = ctx->draw_fbo;
    s->path = path;
    /* the opaque depth, drawn again as the target's (the mask's way) */
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->fbo);
    stin__peel_attach(ctx, s->ambient, s->opaque);
    stin__peel_clear(ctx, 0, 0, 0, 0, 1);
    path->ambient(ctx, STIN__OPAQUE, 1);
    stin__resolved_depth_again(ctx, path);
    if (s->dual) {
        s->layer = -1;
        ctx->draw_fbo = s->fbo;
        stin__dual_begin(ctx);
        return 1;
    }
    /* nothing in front yet: C = 0, T = 1 */
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->composite_fbo);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                  s->accum[0], 0);
    stin__peel_clear(ctx, 0, 0, 0, 1, 0);
    s->result = 0;
    s->layer = -1;
    ctx->draw_fbo = s->fbo; /* the lighting stages come back to the layer */
    return 1;
}

static GLuint layer_depth(const stin__peel_state *s, int k)
{
    return k == 0 ? s->first : s->depth[k % 2];
}

int stin__peel_layer_begin(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    int k = s->layer + 1;
    if (s->dual)
        return stin__dual_layer_begin(ctx);
    if ((uint32_t)k >= ctx->desc.transparency.layers)
        return 0;
    s->layer = k;
    s->peeling = 1;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->fbo);
    stin__peel_attach(ctx, s->ambient, layer_depth(s, k));
    stin__peel_clear(ctx, 0, 0, 0, 0, 1);
    stin__bind_unit(ctx, s->unit, GL_TEXTURE_2D, k > 0 ? layer_depth(s, k - 1) : 0);
    stin__bind_unit(ctx, s->unit + 1, GL_TEXTURE_2D, s->opaque);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    stin__lit_uniforms_stale(ctx); /* every lit program's peel uniforms are stale */
    ctx->stats.transparency.peel_passes++;
    stin__peel_count_begin(ctx);
    return 1;
}

/* Under a caller's samples query the peeling runs to its layer limit. */
void stin__peel_count_begin(stin_context *ctx)
{
    ctx->peel->counting = ctx->peel->query && stin__any_samples_begin(ctx, ctx->peel->query);
}

GLuint stin__peel_count_end(stin_context *ctx)
{
    return ctx->peel->counting ? (GLuint)stin__any_samples_end(ctx, ctx->peel->query) : 1u;
}

int stin__peel_layer_lights(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    GLuint samples;
    if (s->dual)
        return stin__dual_layer_lights(ctx);
    samples = stin__peel_count_end(ctx);
    if (!samples && !(ctx->desc.debug_flags & STIN_DEBUG_PEEL_NO_EARLY_STOP)) {
        s->layer = (int)ctx->desc.transparency.layers; /* the last: nothing is left */
        return 0;
    }
    if (samples)
        ctx->stats.transparency.peel_layers++;
    stin__peel_lights_target(ctx);
    return 1;
}

void stin__peel_lights_target(stin_context *ctx)
{
    stin__pass_state ps = stin__pass_defaults;
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                  ctx->peel->lights, 0);
    ps.depth_test = 1; /* keep the layer's depth: only the colour is cleared */
    ps.depth_write = 0;
    stin__pass_apply(ctx, &ps);
    GL(ctx, ClearColor)(0.0f, 0.0f, 0.0f, 0.0f);
    GL(ctx, Clear)(GL_COLOR_BUFFER_BIT);
}

/* The composite program with its textures on units 0-3 and mode 0 (a layer
 * under the composite) or 1 (the composite over the frame). */
static void composite_program(stin_context *ctx, int mode)
{
    stin__peel_state *s = ctx->peel;
    float params[4];
    params[0] = 1.0f / (float)s->width;
    params[1] = 1.0f / (float)s->height;
    params[2] = (float)mode;
    params[3] = mode ? (float)s->coverage : 0.0f;
    GL(ctx, UseProgram)(s->program);
    stin__lit_program_forget(ctx); /* the lit program is no longer current */
    GL(ctx, Uniform1i)(s->u_ambient, 0);
    GL(ctx, Uniform1i)(s->u_lights, 1);
    GL(ctx, Uniform1i)(s->u_accum, 2);
    GL(ctx, Uniform1i)(s->u_first, 3);
    GL(ctx, Uniform4fv)(s->u_params, 1, params);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, s->ambient);
    stin__bind_unit(ctx, 1, GL_TEXTURE_2D, s->lights);
    stin__bind_unit(ctx, 2, GL_TEXTURE_2D, s->accum[s->result]);
    stin__bind_unit(ctx, 3, GL_TEXTURE_2D, mode ? s->first : 0);
}

void stin__peel_composite_done(stin_context *ctx)
{
    int i;
    for (i = 3; i >= 0; i--)
        stin__bind_unit(ctx, i, GL_TEXTURE_2D, 0);
    stin__peel_coverage_done(ctx);
}

void stin__peel_layer_end(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    stin__pass_state ps = stin__pass_defaults;
    if (s->dual) {
        stin__dual_layer_end(ctx);
        return;
    }
    s->peeling = 0; /* the composite and whatever follows are no layer's */
    stin__lit_uniforms_stale(ctx);
    if (s->layer >= (int)ctx->desc.transparency.layers)
        return; /* stopped early: nothing to add */
    stin__bind_unit(ctx, s->unit, GL_TEXTURE_2D, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->composite_fbo);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                  s->accum[1 - s->result], 0);
    ps.depth_test = 0;
    stin__pass_apply(ctx, &ps);
    composite_program(ctx, 0);
    stin__screen_quad(ctx);
    stin__peel_composite_done(ctx);
    s->result = 1 - s->result;
    ctx->stats.passes++;
}

/* The frame's framebuffer bound for the last quad, the peel's units
 * freed: over the opaque image as premultiplied colour with coverage 1 - T
 * (frame = C + T frame, alpha = 1 - T + T alpha) and the first layer's
 * depth where it has a surface (its depth, cleared to 1, passes LESS there
 * only; elsewhere C = 0 and T = 1 leave the frame as it is). Into a
 * multisampled target with a stencil the samples the blended draws cover
 * are marked first and the quad colours those alone (peel_coverage.c).
 * Both peels. */
void stin__peel_over_frame(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    stin__pass_state ps = stin__pass_defaults;
    stin__bind_unit(ctx, s->unit, GL_TEXTURE_2D, 0);
    stin__bind_unit(ctx, s->unit + 1, GL_TEXTURE_2D, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    if (stin__peel_coverage(ctx))
        return;
    ps.depth_test = 1;
    ps.depth_func = GL_LESS;
    ps.depth_write = 1;
    ps.blend = 1;
    ps.blend_src = GL_ONE;
    ps.blend_dst = GL_ONE_MINUS_SRC_ALPHA;
    stin__pass_apply(ctx, &ps);
}

void stin__peel_end(stin_context *ctx)
{
    stin__peel_state *s = ctx->peel;
    s->peeling = 0;
    stin__lit_uniforms_stale(ctx);
    ctx->draw_fbo = s->frame_fbo;
    if (s->dual) {
        stin__dual_end(ctx);
        return;
    }
    stin__peel_over_frame(ctx);
    composite_program(ctx, 1);
    stin__screen_quad(ctx);
    stin__peel_composite_done(ctx);
    ctx->stats.passes++;
}
