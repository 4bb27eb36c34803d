/* Leaves GL as the public header promises after a frame. */
#include "internal.h"

void stin__state_restore(stin_context *ctx)
{
    uint64_t caps = ctx->caps.present;
    GL_DISABLE(ctx, GL_DEPTH_TEST);
    GL_DISABLE(ctx, GL_BLEND);
    GL_DISABLE(ctx, GL_STENCIL_TEST);
    GL_DISABLE(ctx, GL_CULL_FACE);
    GL_DISABLE(ctx, GL_SCISSOR_TEST);
    GL(ctx, DepthMask)(GL_TRUE);
    GL(ctx, DepthFunc)(GL_LESS);
    GL(ctx, BlendFunc)(GL_ONE, GL_ZERO);
    GL(ctx, ColorMask)(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    GL(ctx, StencilMask)(0xffffffffu);
    GL(ctx, StencilFunc)(GL_ALWAYS, 0, 0xffffffffu);
    GL(ctx, StencilOp)(GL_KEEP, GL_KEEP, GL_KEEP);
    GL(ctx, CullFace)(GL_BACK);
    GL(ctx, FrontFace)(GL_CCW);
    if (caps & STIN_CAP_BIT(STIN_CAP_GLSL))
        GL(ctx, UseProgram)(0);
    if (caps & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    if (caps & STIN_CAP_BIT(STIN_CAP_VAO))
        GL(ctx, BindVertexArray)(0);
    if (caps & STIN_CAP_BIT(STIN_CAP_VBO)) {
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
        GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, 0);
    }
}
