/* SPDX-License-Identifier: MIT */
/*
 * Multisampled targets for either backend: a framebuffer object with an RGBA8
 * and a packed depth-stencil renderbuffer of N samples, and a single-sampled
 * twin that read-backs resolve into with one blit (glReadPixels cannot read
 * a multisampled buffer). A pbuffer or an OSMesa buffer has no samples of
 * its own, so this is the one way either platform offers them. Needs GL 3.0,
 * ARB_framebuffer_object, or EXT_framebuffer_object with
 * EXT_framebuffer_multisample and EXT_framebuffer_blit (the EXT entry
 * points are used then). An sRGB one has GL_SRGB8_ALPHA8 colour in both
 * framebuffers and GL_FRAMEBUFFER_SRGB on, as an application enables it:
 * writes are encoded, blending and the resolve's average are in linear
 * space (GL 4.4's blit rule; Mesa does so).
 */
#include "platform_internal.h"

#include <stdio.h>
#include <string.h>

#define M_GL_FRAMEBUFFER 0x8D40
#define M_GL_RENDERBUFFER 0x8D41
#define M_GL_READ_FRAMEBUFFER 0x8CA8
#define M_GL_DRAW_FRAMEBUFFER 0x8CA9
#define M_GL_DRAW_FRAMEBUFFER_BINDING 0x8CA6
#define M_GL_READ_FRAMEBUFFER_BINDING 0x8CAA
#define M_GL_COLOR_ATTACHMENT0 0x8CE0
#define M_GL_DEPTH_ATTACHMENT 0x8D00
#define M_GL_STENCIL_ATTACHMENT 0x8D20
#define M_GL_RGBA8 0x8058
#define M_GL_SRGB8_ALPHA8 0x8C43
#define M_GL_FRAMEBUFFER_SRGB 0x8DB9
#define M_GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING 0x8210
#define M_GL_SRGB 0x8C40
#define M_GL_DEPTH24_STENCIL8 0x88F0
#define M_GL_FRAMEBUFFER_COMPLETE 0x8CD5
#define M_GL_MAX_SAMPLES 0x8D57
#define M_GL_RENDERBUFFER_SAMPLES 0x8CAB
#define M_GL_NEAREST 0x2600
#define M_GL_SCISSOR_TEST 0x0C11
#define M_GL_VERSION 0x1F02
#define M_GL_EXTENSIONS 0x1F03

typedef void (*m_gen_fn)(int n, unsigned *names);
typedef void (*m_delete_fn)(int n, const unsigned *names);
typedef void (*m_bind_fn)(unsigned target, unsigned name);
typedef void (*m_storage_ms_fn)(unsigned target, int samples, unsigned format, int w, int h);
typedef void (*m_attach_rb_fn)(unsigned target, unsigned attachment, unsigned rb_target,
                               unsigned rb);
typedef unsigned (*m_status_fn)(unsigned target);
typedef void (*m_blit_fn)(int sx0, int sy0, int sx1, int sy1, int dx0, int dy0, int dx1,
                          int dy1, unsigned mask, unsigned filter);
typedef void (*m_get_integerv_fn)(unsigned pname, int *data);
typedef void (*m_get_rb_param_fn)(unsigned target, unsigned pname, int *data);
typedef unsigned char (*m_is_enabled_fn)(unsigned cap);
typedef void (*m_cap_fn)(unsigned cap);
typedef const unsigned char *(*m_get_string_fn)(unsigned name);
typedef void (*m_get_attachment_fn)(unsigned target, unsigned attachment, unsigned pname,
                                    int *out);

typedef struct msaa_gl {
    m_gen_fn gen_framebuffers, gen_renderbuffers;
    m_delete_fn delete_framebuffers, delete_renderbuffers;
    m_bind_fn bind_framebuffer, bind_renderbuffer;
    m_storage_ms_fn storage_ms;
    m_attach_rb_fn attach;
    m_status_fn status;
    m_blit_fn blit;
    m_get_integerv_fn get_integerv;
    m_get_rb_param_fn get_rb_param;
    m_is_enabled_fn is_enabled;
    m_cap_fn enable, disable;
    m_get_attachment_fn get_attachment;
} msaa_gl;

/* Asked below GL 3.0 only, where GL_EXTENSIONS is one string (asking
 * GL_NUM_EXTENSIONS there would raise an error the read-backs then see). */
static int has_extension(stin_platform *p, const char *name)
{
    m_get_string_fn get_string =
        (m_get_string_fn)stin_platform_ptr_to_fn(stin_platform_get_proc_address(p, "glGetString"));
    return get_string &&
           stin_platform_has_token((const char *)get_string(M_GL_EXTENSIONS), name);
}

/* The entry point `name` + suffix ("" or "EXT"). */
static stin_platform_fn load(stin_platform *p, const char *name, const char *suffix)
{
    char full[64];
    snprintf(full, sizeof full, "%s%s", name, suffix);
    return stin_platform_ptr_to_fn(stin_platform_get_proc_address(p, full));
}

/* Which entry points the context's version or extensions promise: "" for
 * GL 3.0 / ARB_framebuffer_object, "EXT" for the three EXT extensions,
 * NULL for none (why says what is missing). */
static const char *entry_suffix(stin_platform *p, char *why, size_t why_size)
{
    m_get_string_fn get_string =
        (m_get_string_fn)stin_platform_ptr_to_fn(stin_platform_get_proc_address(p, "glGetString"));
    const char *version = get_string ? (const char *)get_string(M_GL_VERSION) : NULL;
    int major = 0, minor = 0;
    if (version && sscanf(version, "%d.%d", &major, &minor) == 2 && major >= 3)
        return "";
    if (has_extension(p, "GL_ARB_framebuffer_object"))
        return "";
    if (has_extension(p, "GL_EXT_framebuffer_object") &&
        has_extension(p, "GL_EXT_framebuffer_multisample") &&
        has_extension(p, "GL_EXT_framebuffer_blit"))
        return "EXT";
    snprintf(why, why_size,
             "GL %s has neither GL 3.0, GL_ARB_framebuffer_object nor "
             "GL_EXT_framebuffer_object + _multisample + _blit",
             version ? version : "(unknown)");
    return NULL;
}

static int load_gl(stin_platform *p, msaa_gl *gl, char *why, size_t why_size)
{
    const char *x = entry_suffix(p, why, why_size);
    if (!x)
        return 0;
    gl->gen_framebuffers = (m_gen_fn)load(p, "glGenFramebuffers", x);
    gl->gen_renderbuffers = (m_gen_fn)load(p, "glGenRenderbuffers", x);
    gl->delete_framebuffers = (m_delete_fn)load(p, "glDeleteFramebuffers", x);
    gl->delete_renderbuffers = (m_delete_fn)load(p, "glDeleteRenderbuffers", x);
    gl->bind_framebuffer = (m_bind_fn)load(p, "glBindFramebuffer", x);
    gl->bind_renderbuffer = (m_bind_fn)load(p, "glBindRenderbuffer", x);
    gl->storage_ms = (m_storage_ms_fn)load(p, "glRenderbufferStorageMultisample", x);
    gl->attach = (m_attach_rb_fn)load(p, "glFramebufferRenderbuffer", x);
    gl->status = (m_status_fn)load(p, "glCheckFramebufferStatus", x);
    gl->blit = (m_blit_fn)load(p, "glBlitFramebuffer", x);
    gl->get_rb_param = (m_get_rb_param_fn)load(p, "glGetRenderbufferParameteriv", x);
    gl->get_integerv = (m_get_integerv_fn)load(p, "glGetIntegerv", "");
    gl->is_enabled = (m_is_enabled_fn)load(p, "glIsEnabled", "");
    gl->enable = (m_cap_fn)load(p, "glEnable", "");
    gl->disable = (m_cap_fn)load(p, "glDisable", "");
    gl->get_attachment =
        (m_get_attachment_fn)load(p, "glGetFramebufferAttachmentParameteriv", x);
    if (!gl->gen_framebuffers || !gl->gen_renderbuffers || !gl->delete_framebuffers ||
        !gl->delete_renderbuffers || !gl->bind_framebuffer || !gl->bind_renderbuffer ||
        !gl->storage_ms || !gl->attach || !gl->status || !gl->blit || !gl->get_rb_param ||
        !gl->get_integerv || !gl->is_enabled || !gl->enable || !gl->disable || !gl->get_attachment) {
        snprintf(why, why_size, "an entry point of multisampled framebuffers (suffix '%s') "
                                "did not resolve", x);
        return 0;
    }
    return 1;
}

/* A framebuffer of colour (`colour`: RGBA8 or SRGB8_ALPHA8) + depth-stencil
 * renderbuffers with `samples` (0: single-sampled); 1 when complete. rb[0],
 * rb[1] get the renderbuffers. */
static int make_target(const msaa_gl *gl, int samples, unsigned colour, int w, int h,
                       unsigned *fbo, unsigned rb[2])
{
    gl->gen_framebuffers(1, fbo);
    gl->gen_renderbuffers(2, rb);
    gl->bind_renderbuffer(M_GL_RENDERBUFFER, rb[0]);
    gl->storage_ms(M_GL_RENDERBUFFER, samples, colour, w, h);
    gl->bind_renderbuffer(M_GL_RENDERBUFFER, rb[1]);
    gl->storage_ms(M_GL_RENDERBUFFER, samples, M_GL_DEPTH24_STENCIL8, w, h);
    gl->bind_renderbuffer(M_GL_RENDERBUFFER, 0);
    gl->bind_framebuffer(M_GL_FRAMEBUFFER, *fbo);
    gl->attach(M_GL_FRAMEBUFFER, M_GL_COLOR_ATTACHMENT0, M_GL_RENDERBUFFER, rb[0]);
    gl->attach(M_GL_FRAMEBUFFER, M_GL_DEPTH_ATTACHMENT, M_GL_RENDERBUFFER, rb[1]);
    gl->attach(M_GL_FRAMEBUFFER, M_GL_STENCIL_ATTACHMENT, M_GL_RENDERBUFFER, rb[1]);
    return gl->status(M_GL_FRAMEBUFFER) == M_GL_FRAMEBUFFER_COMPLETE;
}

void stin_platform_msaa_release(stin_platform *p, stin_platform_msaa *m)
{
    msaa_gl gl;
    char why[8];
    if (!m->fbo)
        return;
    if (load_gl(p, &gl, why, sizeof why)) {
        unsigned fbos[2];
        fbos[0] = m->fbo;
        fbos[1] = m->resolve_fbo;
        if (m->srgb) /* the enable is the platform's, as it set it */
            gl.disable(M_GL_FRAMEBUFFER_SRGB);
        gl.bind_framebuffer(M_GL_FRAMEBUFFER, 0);
        gl.delete_framebuffers(2, fbos);
        gl.delete_renderbuffers(4, m->rb);
    }
    memset(m, 0, sizeof *m);
}

/* 1 when the bound framebuffer's colour is stored encoded (asked where GL
 * defines the query). */
static int stores_srgb(const msaa_gl *gl)
{
    int encoding = 0;
    gl->get_attachment(M_GL_FRAMEBUFFER, M_GL_COLOR_ATTACHMENT0,
                       M_GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, &encoding);
    return encoding == M_GL_SRGB;
}

int stin_platform_msaa_create(stin_platform *p, stin_platform_msaa *m, int samples, int srgb,
                              int w, int h, char *err, size_t err_size)
{
    msaa_gl gl;
    char why[200];
    int max_samples = 0, got = 0, encoding_query = 0;
    unsigned colour = srgb ? M_GL_SRGB8_ALPHA8 : M_GL_RGBA8;
    stin_platform_msaa_release(p, m);
    if (samples <= 1)
        return 1;
    if (!load_gl(p, &gl, why, sizeof why) ||
        (srgb && !stin_platform_srgb_supported(p, &encoding_query, why, sizeof why))) {
        stin_platform_errorf(err, err_size, "%d samples%s: %s", samples, srgb ? ", sRGB" : "",
                             why);
        return 0;
    }
    gl.get_integerv(M_GL_MAX_SAMPLES, &max_samples);
    if (samples > max_samples) {
        stin_platform_errorf(err, err_size, "%d samples: the context has at most %d "
                             "(GL_MAX_SAMPLES)", samples, max_samples);
        return 0;
    }
    if (!make_target(&gl, 0, colour, w, h, &m->resolve_fbo, m->rb + 2) ||
        (encoding_query && !stores_srgb(&gl)) ||
        !make_target(&gl, samples, colour, w, h, &m->fbo, m->rb) ||
        (encoding_query && !stores_srgb(&gl))) {
        stin_platform_msaa_release(p, m);
        stin_platform_errorf(err, err_size, "%d samples%s: the framebuffer is incomplete%s",
                             samples, srgb ? ", sRGB" : "",
                             srgb ? " or the driver stores GL_SRGB8_ALPHA8 linear" : "");
        return 0;
    }
    gl.bind_renderbuffer(M_GL_RENDERBUFFER, m->rb[0]);
    gl.get_rb_param(M_GL_RENDERBUFFER, M_GL_RENDERBUFFER_SAMPLES, &got);
    gl.bind_renderbuffer(M_GL_RENDERBUFFER, 0);
    m->samples = got;
    m->srgb = srgb;
    if (srgb)
        gl.enable(M_GL_FRAMEBUFFER_SRGB); /* the caller's part: encode on write */
    return 1; /* the multisampled framebuffer stays bound */
}

int stin_platform_msaa_resolve(stin_platform *p, stin_platform_msaa *m, unsigned buffer_bit,
                               int data, int w, int h, int saved[2])
{
    msaa_gl gl;
    char why[8];
    int scissor;
    if (!m->fbo || !load_gl(p, &gl, why, sizeof why))
        return 0;
    gl.get_integerv(M_GL_DRAW_FRAMEBUFFER_BINDING, &saved[0]);
    gl.get_integerv(M_GL_READ_FRAMEBUFFER_BINDING, &saved[1]);
    scissor = gl.is_enabled(M_GL_SCISSOR_TEST); /* the one state a blit obeys */
    if (scissor)
        gl.disable(M_GL_SCISSOR_TEST);
    gl.bind_framebuffer(M_GL_READ_FRAMEBUFFER, m->fbo);
    gl.bind_framebuffer(M_GL_DRAW_FRAMEBUFFER, m->resolve_fbo);
    if (data && m->srgb) /* data bytes, not colour: no decode, no encode */
        gl.disable(M_GL_FRAMEBUFFER_SRGB);
    gl.blit(0, 0, w, h, 0, 0, w, h, buffer_bit, M_GL_NEAREST);
    if (data && m->srgb)
        gl.enable(M_GL_FRAMEBUFFER_SRGB);
    if (scissor)
        gl.enable(M_GL_SCISSOR_TEST);
    gl.bind_framebuffer(M_GL_READ_FRAMEBUFFER, m->resolve_fbo);
    return 1;
}

void stin_platform_msaa_resolve_end(stin_platform *p, const int saved[2])
{
    msaa_gl gl;
    char why[8];
    if (!load_gl(p, &gl, why, sizeof why))
        return;
    gl.bind_framebuffer(M_GL_DRAW_FRAMEBUFFER, (unsigned)saved[0]);
    gl.bind_framebuffer(M_GL_READ_FRAMEBUFFER, (unsigned)saved[1]);
}
