/* SPDX-License-Identifier: MIT */
/* The internal format a texture takes on this context. Every site names the
 * sized format it means (GL_RGBA8, GL_DEPTH_COMPONENT24, GL_DEPTH24_STENCIL8);
 * OpenGL ES 2.0 has no sized texture formats (internalformat must equal
 * format: GL_RGBA with GL_UNSIGNED_BYTE, GL_DEPTH_COMPONENT with
 * GL_UNSIGNED_INT or _SHORT by OES_depth_texture, GL_DEPTH_STENCIL_OES with
 * GL_UNSIGNED_INT_24_8_OES by OES_packed_depth_stencil) and refuses a sized
 * one with GL_INVALID_VALUE, so there the base format stands in. The
 * precision is then the implementation's (24-bit depth on Mesa). */
#include "internal.h"

#define GL_RGB8 0x8051
#define GL_LUMINANCE8 0x8040
#define GL_DEPTH_COMPONENT16 0x81A5
#define GL_DEPTH_COMPONENT32 0x81A7

/* The base format of the sized formats stin uses, or 0 for another. */
static GLenum base_format(GLenum sized)
{
    switch (sized) {
    case GL_RGBA8: return GL_RGBA;
    case GL_RGB8: return GL_RGB;
    case GL_LUMINANCE8: return GL_LUMINANCE;
    case GL_DEPTH_COMPONENT16: case GL_DEPTH_COMPONENT24: case GL_DEPTH_COMPONENT32:
        return GL_DEPTH_COMPONENT;
    case GL_DEPTH24_STENCIL8: return GL_DEPTH_STENCIL;
    default: return 0;
    }
}

int stin__sized_formats(const stin_context *ctx)
{
    return !ctx->caps.es || ctx->caps.gl_major >= 3;
}

GLenum stin__texture_format(const stin_context *ctx, GLenum sized)
{
    GLenum base = base_format(sized);
    return stin__sized_formats(ctx) || !base ? sized : base;
}

/* NPOT textures with mipmaps and repeat: core from GL 2.0 and ES 3.0; ES 2.0
 * allows NPOT only clamped to the edge and without mipmaps (sampled black
 * otherwise) unless GL_OES_texture_npot lifts that. Render targets (clamped,
 * one level) need no such rule. */
int stin__npot_textures(const stin_context *ctx)
{
    if (ctx->caps.gl_major < 2)
        return 0;
    if (ctx->caps.es && ctx->caps.gl_major < 3)
        return stin_query_extension(ctx, "GL_OES_texture_npot");
    return 1;
}
