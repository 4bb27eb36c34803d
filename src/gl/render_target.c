/* SPDX-License-Identifier: MIT */
/* Render targets: the texture and framebuffer set-up the passes share. */
#include "internal.h"

/* Binds tex, filtered by `filter` both ways, edges clamped. */
static void bind_clamped(stin_context *ctx, GLuint tex, GLint filter)
{
    GL(ctx, BindTexture)(GL_TEXTURE_2D, tex);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

/* The bound texture's level 0, w x h of `internal`, no data. */
static void level0(stin_context *ctx, GLenum internal, GLenum format, GLenum type, int w, int h)
{
    GLenum f = stin__texture_format(ctx, internal);
    GL_ENUM(ctx, TexImage2D, f)(GL_TEXTURE_2D, 0, (GLint)f, w, h, 0, format, type, NULL);
}

void stin__rt_texture(stin_context *ctx, GLuint tex, GLenum internal, GLenum format,
                      GLenum type, int w, int h)
{
    bind_clamped(ctx, tex, GL_NEAREST);
    level0(ctx, internal, format, type, w, h);
}

void stin__rt_shadow_map(stin_context *ctx, GLuint tex, int w, int h)
{
    bind_clamped(ctx, tex, GL_LINEAR);
    GL_ENUM(ctx, TexParameteri, GL_TEXTURE_COMPARE_MODE)(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE,
                                                         GL_COMPARE_R_TO_TEXTURE);
    GL_ENUM(ctx, TexParameteri, GL_TEXTURE_COMPARE_FUNC)(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC,
                                                         GL_LEQUAL);
    level0(ctx, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, w, h);
}

void stin__rt_depth_measure(stin_context *ctx)
{
    GLint bits = 0;
    float unit = 1.0f;
    if (ctx->depth_texture_unit > 0.0f || !ctx->caps.es || ctx->caps.gl_major >= 3)
        return; /* no query of core profiles; ES 3.0's depth textures are sized */
    GL(ctx, GetIntegerv)(GL_DEPTH_BITS, &bits);
    if (bits < 8 || bits > 32)
        bits = 24;
    while (bits-- > 0)
        unit *= 0.5f;
    ctx->depth_texture_unit = unit;
}

float stin__rt_depth_unit(const stin_context *ctx)
{
    return ctx->depth_texture_unit > 0.0f ? ctx->depth_texture_unit : STIN__DEPTH24_UNIT;
}

GLuint stin__rt_depth_renderbuffer(stin_context *ctx, int w, int h)
{
    GLuint rb = 0;
    /* ES 2.0 renders depth in 16 bits (24 only by OES_depth24) */
    GLenum internal =
        ctx->caps.es && ctx->caps.gl_major < 3 ? GL_DEPTH_COMPONENT16 : GL_DEPTH_COMPONENT24;
    GL(ctx, GenRenderbuffers)(1, &rb);
    GL(ctx, BindRenderbuffer)(GL_RENDERBUFFER, rb);
    GL(ctx, RenderbufferStorage)(GL_RENDERBUFFER, internal, w, h);
    GL(ctx, BindRenderbuffer)(GL_RENDERBUFFER, 0);
    return rb;
}

/* Binds fbo and attaches the textures that are not 0. */
static void attach(stin_context *ctx, GLuint fbo, GLuint color, GLuint depth, GLuint stencil)
{
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, fbo);
    if (color)
        GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color,
                                      0);
    if (depth)
        GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth,
                                      0);
    if (stencil)
        GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                                      stencil, 0);
}

GLenum stin__rt_attach(stin_context *ctx, GLuint fbo, GLuint color, GLuint depth,
                       GLuint stencil)
{
    attach(ctx, fbo, color, depth, stencil);
    return GL(ctx, CheckFramebufferStatus)(GL_FRAMEBUFFER);
}

GLenum stin__rt_attach_depth_only(stin_context *ctx, GLuint fbo, GLuint depth, GLuint stencil)
{
    attach(ctx, fbo, 0, depth, stencil);
    stin__no_colour_buffers(ctx);
    return GL(ctx, CheckFramebufferStatus)(GL_FRAMEBUFFER);
}
