/* SPDX-License-Identifier: MIT */
/* The framebuffer a frame draws into (desc.framebuffer, 0 = default): that
 * it is a complete framebuffer object, and its stencil and depth bits (the
 * frame decides from them whether its shadows run, frame/target.c).
 * Stencil and depth depend on the framebuffer, not the context, so they are
 * read per target: once per name, again when a frame names another one. */
#include "internal.h"

#define READ_FRAMEBUFFER 0x8CA8
#define DRAW_FRAMEBUFFER 0x8CA9
#define READ_FRAMEBUFFER_BINDING 0x8CAA
#define STENCIL_ATTACHMENT 0x8D20
#define DEPTH_ATTACHMENT 0x8D00
#define ATTACHMENT_OBJECT_TYPE 0x8CD0

/* Size of one attachment of the bound framebuffer on a core context; an
 * absent attachment has no size (asking would be a GL error). */
static int attachment_bits(const stin__gl *gl, GLenum att, GLenum pname)
{
    GLint type = GL_NONE, v = 0;
    gl->GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, att, ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_NONE)
        gl->GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, att, pname, &v);
    return v;
}

void stin__framebuffer_bits(const stin__gl *gl, int core, GLuint bound, int *stencil, int *depth)
{
    GLint v = 0;
    if (!core) {
        gl->GetIntegerv(GL_STENCIL_BITS, &v);
        *stencil = v;
        v = 0;
        gl->GetIntegerv(GL_DEPTH_BITS, &v);
        *depth = v;
    } else if (gl->GetFramebufferAttachmentParameteriv) {
        *stencil = attachment_bits(gl, bound ? STENCIL_ATTACHMENT : GL_STENCIL,
                                   GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE);
        *depth = attachment_bits(gl, bound ? DEPTH_ATTACHMENT : GL_DEPTH,
                                 GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE);
    }
}

static int has_fbo(const stin_context *ctx)
{
    return (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FBO)) != 0;
}

void stin__framebuffer_save(stin_context *ctx, GLint saved[2])
{
    saved[0] = saved[1] = 0;
    GL(ctx, GetIntegerv)(GL_DRAW_FRAMEBUFFER_BINDING, &saved[0]);
    saved[1] = saved[0];
    if (ctx->target.separate_read)
        GL(ctx, GetIntegerv)(READ_FRAMEBUFFER_BINDING, &saved[1]);
}

void stin__framebuffer_restore(stin_context *ctx, const GLint saved[2])
{
    if (saved[0] == saved[1]) {
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, (GLuint)saved[0]);
    } else {
        GL(ctx, BindFramebuffer)(DRAW_FRAMEBUFFER, (GLuint)saved[0]);
        GL(ctx, BindFramebuffer)(READ_FRAMEBUFFER, (GLuint)saved[1]);
    }
}

/* Alpha bits of `name`'s colour (bound now); on a core context those of a
 * framebuffer object's first colour attachment, and 0 for the default
 * framebuffer (a surfaceless one has no back buffer to ask about: Mesa
 * answers GL_INVALID_ENUM). */
static int alpha_bits(stin_context *ctx, GLuint name)
{
    GLint v = 0;
    if (ctx->caps.profile != STIN_GL_PROFILE_CORE) {
        GL(ctx, GetIntegerv)(GL_ALPHA_BITS, &v);
        return v;
    }
    if (!name || !ctx->gl.GetFramebufferAttachmentParameteriv)
        return 0;
    return attachment_bits(&ctx->gl, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE);
}

/* Reads the bits of `name`, bound now, into the cache. */
static void probe_bits(stin_context *ctx, GLuint name)
{
    GLint sample_buffers = 0;
    /* ES 2.0 answers no attachment query of the default framebuffer
     * (GL_INVALID_OPERATION) but GL_STENCIL_BITS of whichever is bound */
    int attachments = ctx->caps.profile == STIN_GL_PROFILE_CORE &&
                      !(ctx->caps.es && ctx->caps.gl_major < 3);
    ctx->target.name = name;
    ctx->target.stencil_bits = ctx->target.depth_bits = 0;
    stin__framebuffer_bits(&ctx->gl, attachments, name, &ctx->target.stencil_bits,
                           &ctx->target.depth_bits);
    ctx->target.alpha_bits = alpha_bits(ctx, name);
    /* GL 1.3's query; here, not per frame: a query can wait for a threaded driver */
    if (10 * ctx->caps.gl_major + ctx->caps.gl_minor >= 13)
        GL(ctx, GetIntegerv)(GL_SAMPLE_BUFFERS, &sample_buffers);
    ctx->target.multisampled = sample_buffers > 0;
}

void stin__target_init(stin_context *ctx)
{
    GLint saved[2] = {0, 0};
    int bound_stencil = ctx->caps.stencil_bits;
    uint64_t stencil = STIN_CAP_BIT(STIN_CAP_STENCIL);
    ctx->target.separate_read = ctx->caps.gl_major >= 3 ||
                                stin_query_extension(ctx, "GL_ARB_framebuffer_object") ||
                                stin_query_extension(ctx, "GL_EXT_framebuffer_blit");
    if (has_fbo(ctx)) {
        stin__framebuffer_save(ctx, saved);
        if (saved[0])
            GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, 0);
    }
    probe_bits(ctx, 0);
    if (has_fbo(ctx) && (saved[0] || saved[1]))
        stin__framebuffer_restore(ctx, saved);
    /* Selection assumes a stencil buffer where the framebuffer bound now or
     * the default one has one: a stencil-less target bound at create (an
     * earlier frame's) must not decide for every later frame. */
    if (ctx->target.stencil_bits > bound_stencil) {
        ctx->caps.stencil_bits = ctx->target.stencil_bits;
        ctx->caps.depth_bits = ctx->target.depth_bits;
    }
    if (ctx->caps.stencil_bits > 0 && !(ctx->caps.hidden & stencil))
        ctx->caps.present |= stencil;
}

stin_result stin__target_probe(stin_context *ctx, GLuint name, const char *call)
{
    GLint saved[2];
    GLenum status = GL_FRAMEBUFFER_COMPLETE;
    int rebind;
    if (!has_fbo(ctx) || (name == 0 && ctx->target.name == 0))
        return STIN_OK; /* the default framebuffer, probed before */
    if (name && !GL(ctx, IsFramebuffer)(name)) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_ARGUMENT,
                  "%s: framebuffer %u is not a framebuffer object of this context", call,
                  (unsigned)name);
        return STIN_ERROR_INVALID_ARGUMENT;
    }
    stin__framebuffer_save(ctx, saved);
    rebind = saved[0] != (GLint)name || saved[1] != (GLint)name;
    if (rebind)
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, name);
    if (name)
        status = GL(ctx, CheckFramebufferStatus)(GL_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE && name != ctx->target.name)
        probe_bits(ctx, name);
    if (rebind)
        stin__framebuffer_restore(ctx, saved);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_ARGUMENT,
                  "%s: framebuffer %u is incomplete (status 0x%x)", call, (unsigned)name,
                  (unsigned)status);
        return STIN_ERROR_INVALID_ARGUMENT;
    }
    return STIN_OK;
}

int stin__target_has_stencil(const stin_context *ctx)
{
    return (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_STENCIL)) && ctx->target.stencil_bits > 0;
}
