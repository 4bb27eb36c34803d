/* SPDX-License-Identifier: MIT */
/* stin on a headless EGL context (Mesa's surfaceless platform, or a GPU's
 * driver): the frame goes into the application's framebuffer object with a
 * depth-stencil attachment, then to the PPM named on the command line.
 *   cc egl_shadow.c $(pkg-config --cflags --libs stin) -lEGL -lm */
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

typedef void(APIENTRYP read_pixels_fn)(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format,
                                       GLenum type, void *pixels);
#define LOAD(type, name) type name; { void *p_ = get_proc(NULL, #name); memcpy(&name, &p_, sizeof p_); }

int main(int argc, char **argv)
{
    static const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                            EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLint count = 0;
    EGLConfig config;
    EGLDisplay dpy;
    EGLContext egl_ctx;
    GLuint fbo, rb[2];
    unsigned char *pixels = malloc(4u * EXAMPLE_W * EXAMPLE_H);
    int failed;
    LOAD(PFNEGLGETPLATFORMDISPLAYEXTPROC, eglGetPlatformDisplayEXT);
    if (argc != 2 || !pixels || !eglGetPlatformDisplayEXT) {
        fprintf(stderr, "usage: egl_shadow OUT.ppm (and EGL_EXT_platform_base)\n");
        return 2;
    }
    dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (!eglInitialize(dpy, NULL, NULL) || !eglBindAPI(EGL_OPENGL_API) ||
        !eglChooseConfig(dpy, config_attribs, &config, 1, &count) || count < 1 ||
        !(egl_ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL)) ||
        !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_ctx)) {
        fprintf(stderr, "egl_shadow: no surfaceless OpenGL context (0x%x)\n", eglGetError());
        return 2;
    }
    {
        LOAD(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers);
        LOAD(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer);
        LOAD(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers);
        LOAD(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer);
        LOAD(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage);
        LOAD(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer);
        LOAD(read_pixels_fn, glReadPixels);
        /* no window: the frame's target is a framebuffer object of ours,
         * with a stencil buffer so that stin may choose stencil volumes */
        glGenRenderbuffers(2, rb);
        glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, EXAMPLE_W, EXAMPLE_H);
        glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, EXAMPLE_W, EXAMPLE_H);
        glGenFramebuffers(1, &fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                  rb[1]);
        failed = example_render(get_proc, NULL, fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glReadPixels(0, 0, EXAMPLE_W, EXAMPLE_H, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    }
    failed = failed || write_ppm(argv[1], pixels);
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy, egl_ctx);
    eglTerminate(dpy);
    free(pixels);
    return failed;
}
