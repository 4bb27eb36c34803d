/* SPDX-License-Identifier: MIT */
#include "viewer_window.h"

#include <GLFW/glfw3.h>
#include <stdio.h>
#include <string.h>

#ifndef GL_FRAMEBUFFER_SRGB
#define GL_FRAMEBUFFER_SRGB 0x8DB9
#endif
#ifndef GL_FRAMEBUFFER_SRGB_CAPABLE_EXT
#define GL_FRAMEBUFFER_SRGB_CAPABLE_EXT 0x8DBA
#endif

/* The few GL calls the viewer makes itself, through the same loader as
 * stin's (the window system's libGL is GLFW's to load). */
typedef void (*gl_enum_fn)(GLenum);
typedef void (*gl_get_fn)(GLenum, GLint *);
typedef GLenum (*gl_error_fn)(void);
typedef void (*gl_store_fn)(GLenum, GLint);
typedef void (*gl_read_fn)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void *);

void *viewer_window_get_proc(void *user, const char *name)
{
    GLFWglproc fn = glfwGetProcAddress(name);
    void *p;
    (void)user;
    memcpy(&p, &fn, sizeof p); /* function to object pointer: copy the bits (ISO C) */
    return p;
}

static void glfw_error(int code, const char *text)
{
    (void)code;
    fprintf(stderr, "viewer: GLFW: %s\n", text);
}

int viewer_window_open(viewer_window *w, int width, int height, int samples, int srgb,
                       int visible, const char *title, char *err, size_t err_size)
{
    gl_get_fn get;
    gl_error_fn error;
    GLint v = 0;
    memset(w, 0, sizeof *w);
    glfwSetErrorCallback(glfw_error);
    if (!glfwInit()) { /* once: again after the first only counts */
        snprintf(err, err_size, "cannot open a display (GLFW could not start; is DISPLAY set?)");
        return 0;
    }
    glfwDefaultWindowHints();
    /* no version or profile hint: the newest compatibility context */
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    glfwWindowHint(GLFW_STENCIL_BITS, 8);
    glfwWindowHint(GLFW_SAMPLES, samples);
    glfwWindowHint(GLFW_SRGB_CAPABLE, srgb ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    w->glfw = glfwCreateWindow(width, height, title, NULL, NULL);
    if (!w->glfw) {
        snprintf(err, err_size, "cannot create a %dx%d window with an OpenGL context%s", width,
                 height, samples ? " of that many samples" : "");
        return 0;
    }
    glfwMakeContextCurrent(w->glfw);
    glfwSwapInterval(1);
    w->samples_asked = samples;
    w->srgb_asked = srgb;
    w->visible = visible;
    get = (gl_get_fn)(void (*)(void))glfwGetProcAddress("glGetIntegerv");
    error = (gl_error_fn)(void (*)(void))glfwGetProcAddress("glGetError");
    get(GL_SAMPLES, &v);
    w->samples = v;
    /* EXT_framebuffer_sRGB's query works on every GL that has sRGB framebuffers */
    v = 0;
    get(GL_FRAMEBUFFER_SRGB_CAPABLE_EXT, &v);
    w->srgb_capable = error() == GL_NO_ERROR && v;
    return 1;
}

void viewer_window_close(viewer_window *w)
{
    if (w->glfw)
        glfwDestroyWindow(w->glfw);
    w->glfw = NULL;
}

void viewer_window_shutdown(void)
{
    glfwTerminate();
}

void viewer_window_size(const viewer_window *w, int *width, int *height)
{
    glfwGetFramebufferSize(w->glfw, width, height);
}

void viewer_window_begin_frame(const viewer_window *w)
{
    gl_enum_fn set = (gl_enum_fn)(void (*)(void))glfwGetProcAddress(
        w->srgb_asked && w->srgb_capable ? "glEnable" : "glDisable");
    if (w->srgb_capable)
        set(GL_FRAMEBUFFER_SRGB);
}

int viewer_window_read(const viewer_window *w, uint8_t *rgba, int width, int height)
{
    gl_enum_fn read_buffer = (gl_enum_fn)(void (*)(void))glfwGetProcAddress("glReadBuffer");
    gl_store_fn store = (gl_store_fn)(void (*)(void))glfwGetProcAddress("glPixelStorei");
    gl_read_fn read = (gl_read_fn)(void (*)(void))glfwGetProcAddress("glReadPixels");
    gl_error_fn error = (gl_error_fn)(void (*)(void))glfwGetProcAddress("glGetError");
    (void)w;
    while (error() != GL_NO_ERROR) {
    }
    read_buffer(GL_BACK);
    store(GL_PACK_ALIGNMENT, 1);
    read(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    return error() == GL_NO_ERROR;
}

void viewer_window_set_title(viewer_window *w, const char *title)
{
    glfwSetWindowTitle(w->glfw, title);
}
