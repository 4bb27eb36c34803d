/* SPDX-License-Identifier: MIT */
/*
 * sRGB colour targets for either backend: a framebuffer object with a
 * GL_SRGB8_ALPHA8 colour and a packed depth-stencil renderbuffer, and
 * GL_FRAMEBUFFER_SRGB enabled as an application that wants encoded output
 * enables it. Neither a Mesa pbuffer nor an OSMesa buffer offers an sRGB
 * default framebuffer here, so this is the one way the platform gives one.
 * Needs framebuffer objects (GL 3.0, ARB_framebuffer_object, or
 * EXT_framebuffer_object + EXT_packed_depth_stencil) and sRGB rendering
 * (GL 3.0, or ARB/EXT_framebuffer_sRGB with EXT_texture_sRGB).
 */
#include "platform_internal.h"

#include <stdio.h>
#include <string.h>

#define S_GL_FRAMEBUFFER 0x8D40
#define S_GL_RENDERBUFFER 0x8D41
#define S_GL_COLOR_ATTACHMENT0 0x8CE0
#define S_GL_DEPTH_ATTACHMENT 0x8D00
#define S_GL_STENCIL_ATTACHMENT 0x8D20
#define S_GL_SRGB8_ALPHA8 0x8C43
#define S_GL_DEPTH24_STENCIL8 0x88F0
#define S_GL_FRAMEBUFFER_COMPLETE 0x8CD5
#define S_GL_FRAMEBUFFER_SRGB 0x8DB9
#define S_GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING 0x8210
#define S_GL_SRGB 0x8C40

typedef void (*s_gen_fn)(int n, unsigned *names);
typedef void (*s_delete_fn)(int n, const unsigned *names);
typedef void (*s_bind_fn)(unsigned target, unsigned name);
typedef void (*s_storage_fn)(unsigned target, unsigned format, int w, int h);
typedef void (*s_attach_rb_fn)(unsigned target, unsigned attachment, unsigned rb_target,
                               unsigned rb);
typedef unsigned (*s_status_fn)(unsigned target);
typedef void (*s_get_attachment_fn)(unsigned target, unsigned attachment, unsigned pname,
                                    int *out);
typedef void (*s_cap_fn)(unsigned cap);

typedef struct srgb_gl {
    s_gen_fn gen_framebuffers, gen_renderbuffers;
    s_delete_fn delete_framebuffers, delete_renderbuffers;
    s_bind_fn bind_framebuffer, bind_renderbuffer;
    s_storage_fn storage;
    s_attach_rb_fn attach;
    s_status_fn status;
    s_get_attachment_fn get_attachment; /* GL 3.0 / ARB_framebuffer_sRGB only */
    s_cap_fn enable, disable;
} srgb_gl;

static stin_platform_fn load(stin_platform *p, const char *name, const char *suffix)
{
    char full[64];
    snprintf(full, sizeof full, "%s%s", name, suffix);
    return stin_platform_ptr_to_fn(stin_platform_get_proc_address(p, full));
}

int stin_platform_srgb_supported(stin_platform *p, int *encoding_query, char *why,
                                 size_t why_size)
{
    int version = stin_platform_gl_version(p);
    *encoding_query = version >= 30 || stin_platform_has_extension(p, "GL_ARB_framebuffer_sRGB");
    if (version >= 30 || ((stin_platform_has_extension(p, "GL_ARB_framebuffer_sRGB") ||
                           stin_platform_has_extension(p, "GL_EXT_framebuffer_sRGB")) &&
                          stin_platform_has_extension(p, "GL_EXT_texture_sRGB")))
        return 1;
    snprintf(why, why_size, "GL %d.%d has no sRGB rendering (GL 3.0, or "
                            "GL_ARB/EXT_framebuffer_sRGB with GL_EXT_texture_sRGB)",
             version / 10, version % 10);
    return 0;
}

/* The entry-point suffix the context promises framebuffer objects with
 * ("" or "EXT") where it renders sRGB too, or NULL with why. */
static const char *fbo_suffix(stin_platform *p, int *encoding_query, char *why,
                              size_t why_size)
{
    int version = stin_platform_gl_version(p);
    if (!stin_platform_srgb_supported(p, encoding_query, why, why_size))
        return NULL;
    if (version >= 30 || stin_platform_has_extension(p, "GL_ARB_framebuffer_object"))
        return "";
    if (stin_platform_has_extension(p, "GL_EXT_framebuffer_object") &&
        stin_platform_has_extension(p, "GL_EXT_packed_depth_stencil"))
        return "EXT";
    snprintf(why, why_size, "GL %d.%d has no framebuffer objects (GL 3.0, "
                            "GL_ARB_framebuffer_object or GL_EXT_framebuffer_object + "
                            "GL_EXT_packed_depth_stencil)", version / 10, version % 10);
    return NULL;
}

static int load_gl(stin_platform *p, srgb_gl *gl, char *why, size_t why_size)
{
    int encoding_query = 0;
    const char *x = fbo_suffix(p, &encoding_query, why, why_size);
    if (!x)
        return 0;
    gl->gen_framebuffers = (s_gen_fn)load(p, "glGenFramebuffers", x);
    gl->gen_renderbuffers = (s_gen_fn)load(p, "glGenRenderbuffers", x);
    gl->delete_framebuffers = (s_delete_fn)load(p, "glDeleteFramebuffers", x);
    gl->delete_renderbuffers = (s_delete_fn)load(p, "glDeleteRenderbuffers", x);
    gl->bind_framebuffer = (s_bind_fn)load(p, "glBindFramebuffer", x);
    gl->bind_renderbuffer = (s_bind_fn)load(p, "glBindRenderbuffer", x);
    gl->storage = (s_storage_fn)load(p, "glRenderbufferStorage", x);
    gl->attach = (s_attach_rb_fn)load(p, "glFramebufferRenderbuffer", x);
    gl->status = (s_status_fn)load(p, "glCheckFramebufferStatus", x);
    gl->get_attachment = encoding_query ? (s_get_attachment_fn)load(
                                              p, "glGetFramebufferAttachmentParameteriv", x)
                                        : NULL;
    gl->enable = (s_cap_fn)load(p, "glEnable", "");
    gl->disable = (s_cap_fn)load(p, "glDisable", "");
    if (!gl->gen_framebuffers || !gl->gen_renderbuffers || !gl->delete_framebuffers ||
        !gl->delete_renderbuffers || !gl->bind_framebuffer || !gl->bind_renderbuffer ||
        !gl->storage || !gl->attach || !gl->status || !gl->enable || !gl->disable) {
        snprintf(why, why_size, "an entry point of framebuffer objects (suffix '%s') did "
                                "not resolve", x);
        return 0;
    }
    return 1;
}

void stin_platform_srgb_release(stin_platform *p, stin_platform_srgb_target *s)
{
    srgb_gl gl;
    char why[8];
    if (!s->fbo)
        return;
    if (load_gl(p, &gl, why, sizeof why)) {
        gl.disable(S_GL_FRAMEBUFFER_SRGB); /* the enable is the platform's, as it set it */
        gl.bind_framebuffer(S_GL_FRAMEBUFFER, 0);
        gl.delete_framebuffers(1, &s->fbo);
        gl.delete_renderbuffers(2, s->rb);
    }
    memset(s, 0, sizeof *s);
}

int stin_platform_srgb_create(stin_platform *p, stin_platform_srgb_target *s, int w, int h,
                              char *err, size_t err_size)
{
    srgb_gl gl;
    char why[300];
    int encoding = S_GL_SRGB, complete;
    stin_platform_srgb_release(p, s);
    if (!load_gl(p, &gl, why, sizeof why)) {
        stin_platform_errorf(err, err_size, "no sRGB target: %s", why);
        return 0;
    }
    gl.gen_framebuffers(1, &s->fbo);
    gl.gen_renderbuffers(2, s->rb);
    gl.bind_renderbuffer(S_GL_RENDERBUFFER, s->rb[0]);
    gl.storage(S_GL_RENDERBUFFER, S_GL_SRGB8_ALPHA8, w, h);
    gl.bind_renderbuffer(S_GL_RENDERBUFFER, s->rb[1]);
    gl.storage(S_GL_RENDERBUFFER, S_GL_DEPTH24_STENCIL8, w, h);
    gl.bind_renderbuffer(S_GL_RENDERBUFFER, 0);
    gl.bind_framebuffer(S_GL_FRAMEBUFFER, s->fbo);
    gl.attach(S_GL_FRAMEBUFFER, S_GL_COLOR_ATTACHMENT0, S_GL_RENDERBUFFER, s->rb[0]);
    gl.attach(S_GL_FRAMEBUFFER, S_GL_DEPTH_ATTACHMENT, S_GL_RENDERBUFFER, s->rb[1]);
    gl.attach(S_GL_FRAMEBUFFER, S_GL_STENCIL_ATTACHMENT, S_GL_RENDERBUFFER, s->rb[1]);
    complete = gl.status(S_GL_FRAMEBUFFER) == S_GL_FRAMEBUFFER_COMPLETE;
    if (complete && gl.get_attachment)
        gl.get_attachment(S_GL_FRAMEBUFFER, S_GL_COLOR_ATTACHMENT0,
                          S_GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, &encoding);
    if (!complete || encoding != S_GL_SRGB) {
        stin_platform_srgb_release(p, s);
        stin_platform_errorf(err, err_size, "no sRGB target: %s",
                             complete ? "the driver stores GL_SRGB8_ALPHA8 linear"
                                      : "an GL_SRGB8_ALPHA8 + depth 24 / stencil 8 "
                                        "framebuffer is incomplete");
        return 0;
    }
    gl.enable(S_GL_FRAMEBUFFER_SRGB); /* the caller's part: encode on write */
    return 1; /* the sRGB framebuffer stays bound */
}
