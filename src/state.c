/* Leaves GL as the public header promises after a frame: the pass state at
 * GL's defaults and the texture units the frame used unbound. */
#include "internal.h"

void stin__state_restore(stin_context *ctx)
{
    uint64_t caps = ctx->caps.present;
    stin__pass_forget(ctx); /* set every field: a module may have touched one directly */
    stin__pass_apply(ctx, &stin__pass_defaults);
    if ((caps & STIN_CAP_BIT(STIN_CAP_STENCIL_TWO_SIDE)) &&
        !(caps & STIN_CAP_BIT(STIN_CAP_SEPARATE_STENCIL)))
        GL(ctx, ActiveStencilFaceEXT)(GL_FRONT);
    if (caps & STIN_CAP_BIT(STIN_CAP_GLSL))
        GL(ctx, UseProgram)(0);
    stin__unbind_used_units(ctx);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    if (caps & STIN_CAP_BIT(STIN_CAP_VAO))
        GL(ctx, BindVertexArray)(0);
    if (caps & STIN_CAP_BIT(STIN_CAP_VBO)) {
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
        GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, 0);
    }
    stin__pass_forget(ctx); /* between frames GL is the caller's */
}
