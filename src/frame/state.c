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

void stin__state_save(stin_context *ctx)
{
    int fixed = uses_fixed_function(ctx);
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
        GL(ctx, PopAttrib)();
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
