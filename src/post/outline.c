/* SPDX-License-Identifier: MIT */
/* The deferred outline: after the frame's lights (and the visibility
 * export), the surfaces' shading normals go into the screen mask's colour
 * over a fresh depth (the CSG products' resolved depth first, so their
 * faces draw depth EQUAL as in the frame), then one screen pass over the
 * frame's viewport reads normals and depth back through samplers and
 * blends desc.outline_color wherever outline.glsl's filter finds a
 * silhouette, a crease or a step in depth. Two passes, no memory of its
 * own beyond the mask's. */
#include "internal.h"

#define DEFAULT_NORMAL_EDGE 1.0f
#define DEFAULT_DEPTH_EDGE 0.02f

typedef struct stin__outline_state {
    GLuint program;  /* 0: the context cannot outline */
    GLint u_normal, u_depth, u_inverse_projection, u_viewport, u_texel, u_params, u_color;
} stin__outline_state;

static const stin__uniform_name outline_uniforms[] = {
    STIN__UNIFORM(stin__outline_state, u_normal, "u_normal"),
    STIN__UNIFORM(stin__outline_state, u_depth, "u_depth"),
    STIN__UNIFORM(stin__outline_state, u_inverse_projection, "u_inverse_projection"),
    STIN__UNIFORM(stin__outline_state, u_viewport, "u_viewport"),
    STIN__UNIFORM(stin__outline_state, u_texel, "u_texel"),
    STIN__UNIFORM(stin__outline_state, u_params, "u_params"),
    STIN__UNIFORM(stin__outline_state, u_color, "u_color"),
};

size_t stin__outline_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(stin__outline_state);
}

static int glsl_tier(const stin_context *ctx, int *gl4)
{
    stin_technique t = ctx->sel.choice[STIN_FEATURE_LIGHTING].technique;
    *gl4 = t == STIN_TECH_LIGHTING_GLSL150;
    return t == STIN_TECH_LIGHTING_GLSL150 || t == STIN_TECH_LIGHTING_GLSL110;
}

int stin__outline_supported(const stin_context *ctx)
{
    return ctx->outline->program != 0 && stin__mask_available(ctx);
}

void stin__outline_init(stin_context *ctx)
{
    stin__outline_state *o = ctx->outline;
    const char *chunks[2] = {NULL, NULL};
    char msg[160];
    int gl4;
    stin__memzero(o, sizeof *o);
    if (!glsl_tier(ctx, &gl4) || !stin__mask_available(ctx))
        return;
    chunks[0] = gl4 ? "gl4/outline.glsl" : "gl2/outline.glsl";
    msg[0] = '\0';
    o->program = stin__program_build(ctx, gl4 ? "gl4/screen.vert" : "gl2/screen.vert",
                                     gl4 ? "gl4/outline.frag" : "gl2/outline.frag", chunks, 0,
                                     msg, sizeof msg);
    if (!o->program) {
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "outline: its program failed to build (%s); frames asking for an outline "
                  "are refused", msg);
        return;
    }
    STIN__LOCATE(ctx, o->program, o, outline_uniforms);
}

void stin__outline_release(stin_context *ctx)
{
    if (ctx->outline->program)
        GL(ctx, DeleteProgram)(ctx->outline->program);
    ctx->outline->program = 0;
}

/* The surfaces' normals and depth in the mask: false where it cannot be
 * drawn (logged by the mask). */
static int draw_normals(stin_context *ctx, const stin__path *path)
{
    stin__pass_state ps = stin__pass_defaults;
    /* the mask clears its colour only: the depth is cleared here */
    if (!stin__mask_begin(ctx, path, STIN__OPAQUE, 0)) {
        stin__mask_frame_end(ctx);
        return 0;
    }
    stin__pass_apply(ctx, &ps);
    stin__clear_depth(ctx, 1.0);
    GL(ctx, ClearStencil)(0);
    GL(ctx, Clear)(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    ctx->draw_fbo = stin__mask_target_of(ctx).fbo;
    stin__resolved_depth_again(ctx, path);
    path->normals(ctx);
    stin__mask_frame_end(ctx); /* the mask's depth is no longer the frame's opaque one */
    ctx->draw_fbo = ctx->frame.framebuffer;
    return 1;
}

void stin__outline_stage(stin_context *ctx, const stin__path *path)
{
    stin__outline_state *o = ctx->outline;
    const stin_frame_desc *f = &ctx->frame;
    const int *vp = f->viewport;
    stin__mask_target mask;
    stin__pass_state ps = stin__pass_defaults;
    float inverse[16], viewport[4], texel[4], params[4], color[4];
    int k;
    if (!(f->outline_step > 0.0f) || f->output != STIN_OUTPUT_BEAUTY ||
        f->export_visibility == STIN_EXPORT_VISIBILITY_ONLY || !stin__outline_supported(ctx))
        return;
    if (!stin__mat4_invert(inverse, ctx->projection) || !draw_normals(ctx, path)) {
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, f->framebuffer);
        GL(ctx, Viewport)(vp[0], vp[1], vp[2], vp[3]);
        return;
    }
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, f->framebuffer);
    GL(ctx, Viewport)(vp[0], vp[1], vp[2], vp[3]);
    ps.depth_test = 0;
    ps.depth_write = 0;
    ps.blend = 1;
    ps.blend_src = GL_SRC_ALPHA;
    ps.blend_dst = GL_ONE_MINUS_SRC_ALPHA;
    stin__pass_apply(ctx, &ps);
    mask = stin__mask_target_of(ctx);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, mask.color);
    stin__bind_unit(ctx, 1, GL_TEXTURE_2D, mask.depth_stencil);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    for (k = 0; k < 4; k++) {
        viewport[k] = (float)vp[k];
        color[k] = f->outline_color[k];
    }
    if (color[0] == 0.0f && color[1] == 0.0f && color[2] == 0.0f && color[3] == 0.0f)
        color[3] = 1.0f; /* the default: opaque black */
    texel[0] = 1.0f / (float)mask.width;
    texel[1] = 1.0f / (float)mask.height;
    texel[2] = texel[3] = 0.0f;
    params[0] = f->outline_normal_edge > 0.0f ? f->outline_normal_edge : DEFAULT_NORMAL_EDGE;
    params[1] = f->outline_depth_edge > 0.0f ? f->outline_depth_edge : DEFAULT_DEPTH_EDGE;
    params[2] = f->outline_step;
    params[3] = 0.0f;
    GL(ctx, UseProgram)(o->program);
    stin__lit_program_forget(ctx);
    GL(ctx, Uniform1i)(o->u_normal, 0);
    GL(ctx, Uniform1i)(o->u_depth, 1);
    GL(ctx, UniformMatrix4fv)(o->u_inverse_projection, 1, GL_FALSE, inverse);
    GL(ctx, Uniform4fv)(o->u_viewport, 1, viewport);
    GL(ctx, Uniform4fv)(o->u_texel, 1, texel);
    GL(ctx, Uniform4fv)(o->u_params, 1, params);
    GL(ctx, Uniform4fv)(o->u_color, 1, color);
    stin__screen_quad(ctx);
    ctx->stats.passes++;
    stin__bind_unit(ctx, 1, GL_TEXTURE_2D, 0);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
}
