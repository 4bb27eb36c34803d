/* SPDX-License-Identifier: MIT */
/* The GL state contract of the public header ("GL STATE"): what a frame
 * gives back as the caller had it and what it leaves at GL's defaults. */
#include "internal.h"

/* The fixed-function state the GL1 tier changes (lights, materials, the
 * light model, shade model, enables, matrix mode, current colour, every
 * texture unit's bindings, environment and texgen) goes back with one
 * level of GL's own attribute stack. */
#define FIXED_FUNCTION_BITS \
    (GL_CURRENT_BIT | GL_LIGHTING_BIT | GL_TRANSFORM_BIT | GL_ENABLE_BIT | GL_TEXTURE_BIT | \
     GL_PIXEL_MODE_BIT)

static int uses_fixed_function(const stin_context *ctx)
{
    return stin__path_of(ctx) == stin__fixed_path();
}

static int has_fbo(const stin_context *ctx)
{
    return (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FBO)) != 0;
}

/* GL_PIXEL_MODE_BIT's read buffer is the bound read framebuffer's: the pop
 * sets the pushed one on whatever is bound then. Popped on the frame's
 * target it would be the caller's binding's (GL_FRONT or GL_BACK into a
 * framebuffer object: GL_INVALID_OPERATION, the target's read buffer
 * lost), so it is popped on the bindings it was pushed on. */
static void pop_attrib(stin_context *ctx)
{
    GLint frame[2];
    if (!has_fbo(ctx)) {
        GL(ctx, PopAttrib)();
        return;
    }
    stin__framebuffer_save(ctx, frame);
    stin__framebuffer_restore(ctx, ctx->caller.pushed_fbo);
    GL(ctx, PopAttrib)();
    stin__framebuffer_restore(ctx, frame); /* the header: the frame's binding stays */
}

void stin__state_save(stin_context *ctx)
{
    int fixed = uses_fixed_function(ctx);
    if (fixed && has_fbo(ctx))
        stin__framebuffer_save(ctx, ctx->caller.pushed_fbo);
    if (fixed)
        GL(ctx, PushAttrib)(FIXED_FUNCTION_BITS);
    stin__caller_frame_begin(ctx, &ctx->caller);
    ctx->caller_vao = stin__vao_begin(ctx);
    stin__caller_state_defaults(ctx);
    if (fixed)
        stin__caller_state_fixed_begin(ctx);
    stin__displace_frame_begin(ctx);
}

void stin__state_restore(stin_context *ctx)
{
    uint64_t caps = ctx->caps.present;
    int fixed = uses_fixed_function(ctx);
    stin__displace_frame_end(ctx);
    if (fixed) {
        stin__caller_state_fixed_end(ctx);
        pop_attrib(ctx);
        GL(ctx, AlphaFunc)(GL_ALWAYS, 0.0f); /* colour-buffer group: not pushed */
        stin__caller_state_defaults(ctx); /* the pop gave back the caller's enables */
    }
    stin__pass_forget(ctx); /* set every field: a module may have touched one directly */
    stin__pass_apply(ctx, &stin__pass_defaults);
    if ((caps & STIN_CAP_BIT(STIN_CAP_STENCIL_TWO_SIDE)) &&
        !(caps & STIN_CAP_BIT(STIN_CAP_SEPARATE_STENCIL)))
        GL(ctx, ActiveStencilFaceEXT)(GL_FRONT);
    if (caps & STIN_CAP_BIT(STIN_CAP_GLSL))
        GL(ctx, UseProgram)(0);
    if (fixed) { /* the pop gave back the caller's units; unit 0 is left empty */
        ctx->units_used = 0;
        stin__unbind_units(ctx, 1u);
    } else {
        stin__unbind_used_units(ctx);
        GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    }
    if (caps & STIN_CAP_BIT(STIN_CAP_VAO))
        GL(ctx, BindVertexArray)(0);
    if (caps & STIN_CAP_BIT(STIN_CAP_VBO)) {
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
        GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, 0); /* vertex array 0's */
    }
    stin__vao_end(ctx, ctx->caller_vao);
    stin__caller_frame_end(ctx, &ctx->caller);
    stin__pass_forget(ctx); /* between frames GL is the caller's */
}
