/* SPDX-License-Identifier: MIT */
/* The few calls whose entry point differs between desktop GL and OpenGL ES:
 * every feature calls these, so that no desktop-only function runs on ES. */
#include "internal.h"

void stin__clear_depth(stin_context *ctx, double depth)
{
    if (ctx->caps.es)
        GL(ctx, ClearDepthf)((GLfloat)depth);
    else
        GL(ctx, ClearDepth)(depth);
}

void stin__depth_range(stin_context *ctx, double n, double f)
{
    if (ctx->caps.es)
        GL(ctx, DepthRangef)((GLfloat)n, (GLfloat)f);
    else
        GL(ctx, DepthRange)(n, f);
}

/* A depth-only framebuffer object: no colour drawn or read. ES 2.0 has
 * neither call (an FBO without a colour attachment is complete there);
 * ES 3.0 has glReadBuffer and glDrawBuffers, not glDrawBuffer. */
void stin__no_colour_buffers(stin_context *ctx)
{
    if (ctx->caps.es) {
        if (ctx->caps.gl_major >= 3) {
            static const GLenum none = GL_NONE;
            GL(ctx, DrawBuffers)(1, &none);
            GL(ctx, ReadBuffer)(GL_NONE);
        }
        return;
    }
    GL(ctx, DrawBuffer)(GL_NONE);
    GL(ctx, ReadBuffer)(GL_NONE);
}
