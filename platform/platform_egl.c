/* SPDX-License-Identifier: MIT */
/*
 * EGL backend: surfaceless Mesa by default, device EGL when STIN_EGL_DEVICE=1
 * or when the surfaceless platform is missing (GPU machines). Both render into
 * a pbuffer so that GL 1.x contexts, which cannot make an FBO, still have a
 * default framebuffer with depth and stencil; OpenGL ES contexts (ES profiles)
 * use the same pbuffer, from an ES2/ES3-renderable config.
 */
#include "platform_internal.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct stin_egl {
    EGLDisplay display;
    EGLSurface surface;
    EGLContext context;
    int counted;  /* holds a use of display (see display_acquire) */
    void *gl_lib; /* dlopen'd only when eglGetProcAddress misses a name */
};

#define MAX_DEVICES 16
#define DISPLAY_SLOTS 8

/* eglGetPlatformDisplayEXT hands every caller the same EGLDisplay, and
 * eglTerminate would pull it from under another live context: count users.
 * Not thread-safe, like the rest of create/destroy. */
static struct {
    EGLDisplay display;
    int users;
} displays[DISPLAY_SLOTS];

/* Returns 0 when the table is full (the display is then never terminated). */
static int display_acquire(EGLDisplay dpy)
{
    size_t i, free_slot = DISPLAY_SLOTS;
    for (i = 0; i < DISPLAY_SLOTS; i++) {
        if (displays[i].users > 0 && displays[i].display == dpy) {
            displays[i].users++;
            return 1;
        }
        if (displays[i].users == 0 && free_slot == DISPLAY_SLOTS)
            free_slot = i;
    }
    if (free_slot == DISPLAY_SLOTS)
        return 0;
    displays[free_slot].display = dpy;
    displays[free_slot].users = 1;
    return 1;
}

/* 1 when this was the last user, so the display may be terminated. */
static int display_release(EGLDisplay dpy)
{
    size_t i;
    for (i = 0; i < DISPLAY_SLOTS; i++)
        if (displays[i].users > 0 && displays[i].display == dpy)
            return --displays[i].users == 0;
    return 0;
}

static const char *egl_error_name(EGLint code)
{
    switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return "unknown EGL error";
    }
}

/* "<call> failed: EGL_BAD_xxx (0x300n)" */
static void egl_fail(char *err, size_t err_size, const char *call)
{
    EGLint code = eglGetError();
    stin_platform_errorf(err, err_size, "EGL: %s failed: %s (0x%04x)", call,
                         egl_error_name(code), (unsigned)code);
}

static void *egl_proc(const char *name)
{
    return stin_platform_fn_to_ptr((stin_platform_fn)eglGetProcAddress(name));
}

/* Returns an initialised display or EGL_NO_DISPLAY (err says why). */
static EGLDisplay init_display(PFNEGLGETPLATFORMDISPLAYEXTPROC get_display, EGLenum platform,
                               void *native, const char *what, char *err, size_t err_size)
{
    EGLint major, minor;
    EGLDisplay dpy = get_display(platform, native, NULL);
    if (dpy == EGL_NO_DISPLAY) {
        egl_fail(err, err_size, what);
        return EGL_NO_DISPLAY;
    }
    if (!eglInitialize(dpy, &major, &minor)) {
        char call[128];
        snprintf(call, sizeof call, "eglInitialize after %s", what);
        egl_fail(err, err_size, call);
        return EGL_NO_DISPLAY;
    }
    return dpy;
}

static EGLDisplay open_surfaceless(PFNEGLGETPLATFORMDISPLAYEXTPROC get_display, char *err,
                                   size_t err_size)
{
    return init_display(get_display, EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                        "eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)", err,
                        err_size);
}

/* First enumerated device that initialises (GPU drivers list theirs first). */
static EGLDisplay open_device(const char *client_exts,
                              PFNEGLGETPLATFORMDISPLAYEXTPROC get_display, char *err,
                              size_t err_size)
{
    PFNEGLQUERYDEVICESEXTPROC query_devices;
    EGLDeviceEXT devices[MAX_DEVICES];
    EGLint count = 0, i;

    if (!stin_platform_has_token(client_exts, "EGL_EXT_platform_device")) {
        stin_platform_errorf(err, err_size,
                             "EGL: neither EGL_MESA_platform_surfaceless nor "
                             "EGL_EXT_platform_device is available");
        return EGL_NO_DISPLAY;
    }
    query_devices = (PFNEGLQUERYDEVICESEXTPROC)stin_platform_ptr_to_fn(
        egl_proc("eglQueryDevicesEXT"));
    if (!query_devices) {
        stin_platform_errorf(err, err_size, "EGL: eglQueryDevicesEXT did not resolve");
        return EGL_NO_DISPLAY;
    }
    if (!query_devices(MAX_DEVICES, devices, &count)) {
        egl_fail(err, err_size, "eglQueryDevicesEXT");
        return EGL_NO_DISPLAY;
    }
    if (count == 0)
        stin_platform_errorf(err, err_size, "EGL: eglQueryDevicesEXT found no device");
    for (i = 0; i < count; i++) {
        EGLDisplay dpy = init_display(get_display, EGL_PLATFORM_DEVICE_EXT, devices[i],
                                      "eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT)",
                                      err, err_size);
        if (dpy != EGL_NO_DISPLAY)
            return dpy;
    }
    return EGL_NO_DISPLAY;
}

static int want_device(void)
{
    const char *v = getenv("STIN_EGL_DEVICE");
    return v && strcmp(v, "1") == 0;
}

static EGLDisplay open_display(char *err, size_t err_size)
{
    const char *client_exts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display;
    EGLDisplay dpy;
    char surfaceless_err[256] = "";

    get_display = (PFNEGLGETPLATFORMDISPLAYEXTPROC)stin_platform_ptr_to_fn(
        egl_proc("eglGetPlatformDisplayEXT"));
    if (!client_exts || !get_display ||
        !stin_platform_has_token(client_exts, "EGL_EXT_platform_base")) {
        stin_platform_errorf(err, err_size,
                             "EGL: EGL_EXT_platform_base (eglGetPlatformDisplayEXT) is missing");
        return EGL_NO_DISPLAY;
    }
    if (!want_device() && stin_platform_has_token(client_exts, "EGL_MESA_platform_surfaceless")) {
        dpy = open_surfaceless(get_display, surfaceless_err, sizeof surfaceless_err);
        if (dpy != EGL_NO_DISPLAY)
            return dpy;
    }
    dpy = open_device(client_exts, get_display, err, err_size);
    if (dpy == EGL_NO_DISPLAY && surfaceless_err[0] && err && err_size) {
        /* Say why both platforms failed. */
        char device_err[256];
        snprintf(device_err, sizeof device_err, "%s", err);
        stin_platform_errorf(err, err_size, "%s; then %s", surfaceless_err, device_err);
    }
    return dpy;
}

static EGLint config_attrib(EGLDisplay dpy, EGLConfig cfg, EGLint name)
{
    EGLint v = 0;
    eglGetConfigAttrib(dpy, cfg, name, &v);
    return v;
}

/* eglChooseConfig sorts deeper colour first, so pick exactly RGBA8 / S8 /
 * single-sampled ourselves, preferring depth 24 over deeper. */
static EGLint renderable_bit(const stin_profile *profile)
{
    if (!profile || !profile->es)
        return EGL_OPENGL_BIT;
    return profile->gl_major >= 3 ? EGL_OPENGL_ES3_BIT_KHR : EGL_OPENGL_ES2_BIT;
}

static const char *renderable_name(EGLint bit)
{
    return bit == EGL_OPENGL_BIT ? "EGL_OPENGL_BIT"
           : bit == EGL_OPENGL_ES2_BIT ? "EGL_OPENGL_ES2_BIT" : "EGL_OPENGL_ES3_BIT_KHR";
}

static int choose_config(EGLDisplay dpy, EGLint renderable, EGLConfig *out, char *err,
                         size_t err_size)
{
    const EGLint attribs[] = {
        EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
        EGL_RENDERABLE_TYPE, renderable,
        EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
        EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8,
        EGL_NONE
    };
    EGLConfig configs[256];
    EGLint count = 0, i, best = -1, best_depth = 0;

    if (!eglChooseConfig(dpy, attribs, configs, 256, &count)) {
        egl_fail(err, err_size, "eglChooseConfig");
        return 0;
    }
    for (i = 0; i < count; i++) {
        EGLint depth = config_attrib(dpy, configs[i], EGL_DEPTH_SIZE);
        if (config_attrib(dpy, configs[i], EGL_RED_SIZE) != 8 ||
            config_attrib(dpy, configs[i], EGL_GREEN_SIZE) != 8 ||
            config_attrib(dpy, configs[i], EGL_BLUE_SIZE) != 8 ||
            config_attrib(dpy, configs[i], EGL_ALPHA_SIZE) != 8 ||
            config_attrib(dpy, configs[i], EGL_STENCIL_SIZE) != 8 ||
            config_attrib(dpy, configs[i], EGL_SAMPLES) != 0)
            continue;
        if (best < 0 || (depth == 24 && best_depth != 24)) {
            best = i;
            best_depth = depth;
        }
    }
    if (best < 0) {
        stin_platform_errorf(err, err_size,
                             "EGL: no pbuffer config with RGBA8, depth 24, stencil 8 and "
                             "%s (%d candidates)", renderable_name(renderable), (int)count);
        return 0;
    }
    *out = configs[best];
    return 1;
}

/* Core (or compat >= 3.2): ask for the version and the profile. Older compat:
 * ask for nothing, Mesa gives its best compat context and
 * MESA_GL_VERSION_OVERRIDE decides what it reports. ES: ask for the version
 * (Mesa 22.3 answers every request from 2.0 up with its best, ES 3.2;
 * MESA_GLES_VERSION_OVERRIDE decides what it reports). */
static void context_attribs(const stin_profile *profile, EGLint *a)
{
    int n = 0;
    int versioned = profile && (profile->core || profile->gl_major * 10 + profile->gl_minor >= 32);
    if (profile && profile->es) {
        a[n++] = EGL_CONTEXT_MAJOR_VERSION;
        a[n++] = profile->gl_major;
        a[n++] = EGL_CONTEXT_MINOR_VERSION;
        a[n++] = profile->gl_minor;
    } else if (versioned) {
        a[n++] = EGL_CONTEXT_MAJOR_VERSION;
        a[n++] = profile->gl_major;
        a[n++] = EGL_CONTEXT_MINOR_VERSION;
        a[n++] = profile->gl_minor;
        a[n++] = EGL_CONTEXT_OPENGL_PROFILE_MASK;
        a[n++] = profile->core ? EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT
                               : EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT;
    }
    a[n] = EGL_NONE;
}

static int create_context(stin_egl *egl, EGLConfig cfg, int width, int height,
                          const stin_profile *profile, char *err, size_t err_size)
{
    EGLint ctx_attribs[8];
    const EGLint surf_attribs[] = { EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE };

    egl->surface = eglCreatePbufferSurface(egl->display, cfg, surf_attribs);
    if (egl->surface == EGL_NO_SURFACE) {
        egl_fail(err, err_size, "eglCreatePbufferSurface");
        return 0;
    }
    context_attribs(profile, ctx_attribs);
    egl->context = eglCreateContext(egl->display, cfg, EGL_NO_CONTEXT, ctx_attribs);
    if (egl->context == EGL_NO_CONTEXT) {
        EGLint code = eglGetError();
        stin_platform_errorf(err, err_size,
                             "EGL: eglCreateContext failed for a %s %d.%d context "
                             "(profile %s): %s (0x%04x)",
                             profile && profile->es     ? "OpenGL ES"
                             : profile && profile->core ? "core"
                                                        : "compatibility",
                             profile ? profile->gl_major : 0, profile ? profile->gl_minor : 0,
                             profile ? profile->name : "none", egl_error_name(code),
                             (unsigned)code);
        return 0;
    }
    if (!eglMakeCurrent(egl->display, egl->surface, egl->surface, egl->context)) {
        egl_fail(err, err_size, "eglMakeCurrent");
        return 0;
    }
    return 1;
}

void stin_egl_destroy(stin_egl *egl)
{
    if (!egl)
        return;
    if (egl->display != EGL_NO_DISPLAY) {
        /* Unbind only our own context; another platform's may be current. */
        if (egl->context != EGL_NO_CONTEXT && eglGetCurrentContext() == egl->context)
            eglMakeCurrent(egl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (egl->context != EGL_NO_CONTEXT)
            eglDestroyContext(egl->display, egl->context);
        if (egl->surface != EGL_NO_SURFACE)
            eglDestroySurface(egl->display, egl->surface);
        if (egl->counted && display_release(egl->display)) {
            eglTerminate(egl->display);
            if (eglGetCurrentContext() == EGL_NO_CONTEXT)
                eglReleaseThread();
        }
    }
    if (egl->gl_lib)
        dlclose(egl->gl_lib);
    free(egl);
}

stin_egl *stin_egl_create(int width, int height, const stin_profile *profile, char *err,
                          size_t err_size)
{
    EGLConfig cfg;
    stin_egl *egl = calloc(1, sizeof *egl);
    if (!egl) {
        stin_platform_errorf(err, err_size, "EGL: out of memory");
        return NULL;
    }
    egl->surface = EGL_NO_SURFACE;
    egl->context = EGL_NO_CONTEXT;
    egl->display = open_display(err, err_size);
    if (egl->display == EGL_NO_DISPLAY)
        goto fail;
    egl->counted = display_acquire(egl->display);
    if (!eglBindAPI(profile && profile->es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) {
        egl_fail(err, err_size, profile && profile->es ? "eglBindAPI(EGL_OPENGL_ES_API)"
                                                       : "eglBindAPI(EGL_OPENGL_API)");
        goto fail;
    }
    if (!choose_config(egl->display, renderable_bit(profile), &cfg, err, err_size) ||
        !create_context(egl, cfg, width, height, profile, err, err_size))
        goto fail;
    return egl;
fail:
    stin_egl_destroy(egl);
    return NULL;
}

/* Mesa resolves core functions too (EGL_KHR_get_all_proc_addresses); the
 * libGL fallback is for EGLs that do not. */
void *stin_egl_get_proc(stin_egl *egl, const char *name)
{
    static const char *const libs[] = { "libGL.so.1", "libOpenGL.so.0" };
    void *p = egl_proc(name);
    size_t i;
    if (p || !egl)
        return p;
    for (i = 0; !egl->gl_lib && i < sizeof libs / sizeof libs[0]; i++)
        egl->gl_lib = dlopen(libs[i], RTLD_NOW | RTLD_LOCAL);
    return egl->gl_lib ? dlsym(egl->gl_lib, name) : NULL;
}
