/* SPDX-License-Identifier: MIT */
/* A headless EGL context (Mesa's surfaceless platform, or a GPU's driver),
 * desktop OpenGL or OpenGL ES 2.0 / 3.0 (--es 2|3), with the application's
 * framebuffer object (RGBA8 and depth-stencil
 * renderbuffers) for the EGL examples. */
#ifndef EXAMPLE_EGL_H
#define EXAMPLE_EGL_H

#include "example_scene.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

/* Every GL call here and in stin goes through eglGetProcAddress (EGL 1.5
 * resolves core functions too). Function pointers do not convert to
 * void * in ISO C: copy the bits. */
static void *get_proc(void *user, const char *name)
{
    void (*fn)(void) = eglGetProcAddress(name);
    void *p;
    (void)user;
    memcpy(&p, &fn, sizeof p);
    return p;
}

#define LOAD(type, name) type name; { void *p_ = get_proc(NULL, #name); memcpy(&name, &p_, sizeof p_); }

typedef void(APIENTRYP read_pixels_fn)(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format,
                                       GLenum type, void *pixels);

typedef struct example_egl {
    EGLDisplay dpy;
    EGLContext ctx;
    GLuint fbo;
    int es; /* 0: desktop OpenGL; 2 or 3: the OpenGL ES major version */
} example_egl;

/* The examples' command line, "[--es 2|3] OUT.ppm": the context's API into
 * e->es and the picture's path into *out. 0 on success, else the usage is
 * printed. */
static int example_egl_args(example_egl *e, int argc, char **argv, const char **out)
{
    e->es = 0;
    if (argc == 4 && !strcmp(argv[1], "--es") && (!strcmp(argv[2], "2") || !strcmp(argv[2], "3"))) {
        e->es = argv[2][0] - '0';
        *out = argv[3];
        return 0;
    }
    if (argc == 2 && argv[1][0] != '-') {
        *out = argv[1];
        return 0;
    }
    fprintf(stderr, "usage: %s [--es 2|3] OUT.ppm\n", argv[0]);
    return 1;
}

/* The context (desktop OpenGL, or OpenGL ES e->es.0), current, and the
 * framebuffer object, bound. 0 on success. */
static int example_egl_open(example_egl *e, const char *program)
{
    EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                               EGL_OPENGL_BIT, EGL_NONE};
    const EGLint es_attribs[] = {EGL_CONTEXT_CLIENT_VERSION, e->es, EGL_NONE};
    EGLint count = 0;
    EGLConfig config;
    GLuint rb[2];
    LOAD(PFNEGLGETPLATFORMDISPLAYEXTPROC, eglGetPlatformDisplayEXT);
    if (!eglGetPlatformDisplayEXT) {
        fprintf(stderr, "%s: needs EGL_EXT_platform_base\n", program);
        return 1;
    }
    if (e->es) /* EGL_OPENGL_ES3_BIT is EGL 1.5's (and KHR_create_context's) */
        config_attribs[3] = e->es == 3 ? 0x0040 : EGL_OPENGL_ES2_BIT;
    e->dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (!eglInitialize(e->dpy, NULL, NULL) ||
        !eglBindAPI(e->es ? EGL_OPENGL_ES_API : EGL_OPENGL_API) ||
        !eglChooseConfig(e->dpy, config_attribs, &config, 1, &count) || count < 1 ||
        !(e->ctx = eglCreateContext(e->dpy, config, EGL_NO_CONTEXT, e->es ? es_attribs : NULL)) ||
        !eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, e->ctx)) {
        fprintf(stderr, "%s: no surfaceless OpenGL%s context (0x%x)\n", program,
                e->es == 3 ? " ES 3.0" : e->es ? " ES 2.0" : "", eglGetError());
        return 1;
    }
    {
        LOAD(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers);
        LOAD(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer);
        LOAD(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers);
        LOAD(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer);
        LOAD(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage);
        LOAD(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer);
        /* no window: the frame's target is a framebuffer object of ours,
         * with a stencil buffer so that stin may choose stencil volumes.
         * On ES 2.0 these formats are OES_rgb8_rgba8's and
         * OES_packed_depth_stencil's; depth and stencil are attached one
         * by one, as ES 2.0 has no GL_DEPTH_STENCIL_ATTACHMENT. */
        glGenRenderbuffers(2, rb);
        glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, EXAMPLE_W, EXAMPLE_H);
        glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, EXAMPLE_W, EXAMPLE_H);
        glGenFramebuffers(1, &e->fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, e->fbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    }
    { /* a driver may give a later version than asked (Mesa: ES 3.2 for 2) */
        typedef const GLubyte *(APIENTRYP get_string_fn)(GLenum name);
        LOAD(get_string_fn, glGetString);
        printf("context: %s\n", (const char *)glGetString(GL_VERSION));
    }
    return 0;
}

/* The framebuffer's pixels into the PPM at path, and the context closed.
 * 0 on success. */
static int example_egl_close(example_egl *e, const char *path)
{
    unsigned char *pixels = malloc(4u * EXAMPLE_W * EXAMPLE_H);
    int failed = !pixels;
    LOAD(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer);
    LOAD(read_pixels_fn, glReadPixels);
    if (pixels) {
        glBindFramebuffer(GL_FRAMEBUFFER, e->fbo);
        glReadPixels(0, 0, EXAMPLE_W, EXAMPLE_H, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
        failed = write_ppm(path, pixels);
    }
    eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(e->dpy, e->ctx);
    eglTerminate(e->dpy);
    free(pixels);
    return failed;
}

#endif
