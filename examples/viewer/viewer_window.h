/* SPDX-License-Identifier: MIT */
/* The viewer's window and GL context (GLFW): a compatibility-profile
 * context, so that every tier can be forced (the context's version decides
 * which run), with the multisampling and sRGB encoding asked for. Changing
 * either re-creates the window: a default framebuffer's format is fixed at
 * its creation. */
#ifndef VIEWER_WINDOW_H
#define VIEWER_WINDOW_H

#include <stddef.h>
#include <stdint.h>

typedef struct GLFWwindow GLFWwindow;

typedef struct viewer_window {
    GLFWwindow *glfw;
    int samples_asked, samples; /* GL_SAMPLES of the default framebuffer */
    int srgb_asked;             /* GL_FRAMEBUFFER_SRGB enabled before each frame */
    int srgb_capable;           /* the default framebuffer encodes to sRGB */
    int visible;                /* 0: --hidden (no window on screen, the same framebuffer) */
} viewer_window;

/* Opens a width x height window titled title, its context current.
 * samples: 0 or 2, 4, 8 (GLFW_SAMPLES); srgb: ask for an sRGB-capable
 * framebuffer. What the framebuffer got is in samples and srgb_capable.
 * 0 and a message in err on failure. */
int viewer_window_open(viewer_window *w, int width, int height, int samples, int srgb,
                       int visible, const char *title, char *err, size_t err_size);
void viewer_window_close(viewer_window *w);
/* At exit, after the last window: the display connection closed. (Not
 * between windows: a display server with no client left may reset, and a
 * window opened then fails.) */
void viewer_window_shutdown(void);
/* Fits stin_desc.get_proc_address (glfwGetProcAddress; the context current). */
void *viewer_window_get_proc(void *user, const char *name);
/* The framebuffer's size in pixels. */
void viewer_window_size(const viewer_window *w, int *width, int *height);
/* Before stin's frame: GL_FRAMEBUFFER_SRGB on where asked and available. */
void viewer_window_begin_frame(const viewer_window *w);
/* The back buffer as RGBA8, rows bottom to top; 1 on success. */
int viewer_window_read(const viewer_window *w, uint8_t *rgba, int width, int height);
void viewer_window_set_title(viewer_window *w, const char *title);

#endif
