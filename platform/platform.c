/* SPDX-License-Identifier: MIT */
/*
 * The common part of libstin_platform.a: kind names, the profile's Mesa
 * environment, backend dispatch and framebuffer readback.
 *
 * GL is reached only through the backend's get_proc_address: this library
 * never links libGL, because libOSMesa carries its own GL and the two clash.
 */
#include "platform_internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The few GL 1.1 tokens readback needs (no GL header: it would invite
 * calling libGL's symbols directly). */
#define P_GL_UNSIGNED_BYTE 0x1401
#define P_GL_FLOAT 0x1406
#define P_GL_STENCIL_INDEX 0x1901
#define P_GL_DEPTH_COMPONENT 0x1902
#define P_GL_DEPTH_STENCIL 0x84F9
#define P_GL_UNSIGNED_INT_24_8 0x84FA
#define P_GL_RGBA 0x1908
#define P_GL_VERSION 0x1F02
#define P_GL_EXTENSIONS 0x1F03
#define P_GL_NUM_EXTENSIONS 0x821D
#define P_GL_NO_ERROR 0
#define P_GL_PACK_ROW_LENGTH 0x0D02
#define P_GL_PACK_SKIP_ROWS 0x0D03
#define P_GL_PACK_SKIP_PIXELS 0x0D04
#define P_GL_PACK_ALIGNMENT 0x0D05
#define P_GL_PIXEL_PACK_BUFFER 0x88EB
#define P_GL_PIXEL_PACK_BUFFER_BINDING 0x88ED

typedef void (*p_read_pixels_fn)(int x, int y, int w, int h, unsigned format,
                                 unsigned type, void *data);
typedef void (*p_get_integerv_fn)(unsigned pname, int *data);
typedef void (*p_pixel_storei_fn)(unsigned pname, int param);
typedef const unsigned char *(*p_get_string_fn)(unsigned name);
typedef unsigned (*p_get_error_fn)(void);
typedef void (*p_bind_buffer_fn)(unsigned target, unsigned buffer);
typedef const unsigned char *(*p_get_stringi_fn)(unsigned name, unsigned i);

struct stin_platform {
    stin_platform_kind kind;
    int width, height;
    stin_egl *egl;
    stin_osmesa *osmesa;
    int has_pack_buffer; /* GL 2.1+: a bound PIXEL_PACK_BUFFER would hijack readback */
    int es;              /* OpenGL ES: depth and stencil read back packed (below) */
    p_read_pixels_fn read_pixels;
    p_get_integerv_fn get_integerv;
    p_pixel_storei_fn pixel_storei;
    p_get_error_fn get_error;
    p_bind_buffer_fn bind_buffer;
    stin_platform_msaa msaa; /* desc.samples > 1 or stin_platform_set_samples */
    stin_platform_srgb_target srgb; /* desc.srgb or stin_platform_set_srgb */
};

#define OVERRIDE_VARS 4
static const char *const override_vars[OVERRIDE_VARS] = {
    "MESA_GL_VERSION_OVERRIDE",
    "MESA_GLSL_VERSION_OVERRIDE",
    "MESA_EXTENSION_OVERRIDE",
    "MESA_GLES_VERSION_OVERRIDE",
};

/* Mesa reads the overrides once per process; a second context with other
 * overrides would silently keep the first ones. */
static int driver_loaded;

void stin_platform_errorf(char *err, size_t err_size, const char *fmt, ...)
{
    va_list ap;
    if (!err || err_size == 0)
        return;
    va_start(ap, fmt);
    vsnprintf(err, err_size, fmt, ap);
    va_end(ap);
}

void *stin_platform_fn_to_ptr(stin_platform_fn fn)
{
    void *p;
    typedef char size_check[sizeof p == sizeof fn ? 1 : -1];
    (void)sizeof(size_check);
    memcpy(&p, &fn, sizeof p);
    return p;
}

stin_platform_fn stin_platform_ptr_to_fn(void *ptr)
{
    stin_platform_fn fn;
    memcpy(&fn, &ptr, sizeof fn);
    return fn;
}

const char *stin_platform_kind_name(stin_platform_kind kind)
{
    switch (kind) {
    case STIN_PLATFORM_EGL: return "egl";
    case STIN_PLATFORM_OSMESA: return "osmesa";
    }
    return "unknown";
}

int stin_platform_kind_from_name(const char *name, stin_platform_kind *out)
{
    if (!name || !out)
        return 0;
    if (strcmp(name, "egl") == 0)
        *out = STIN_PLATFORM_EGL;
    else if (strcmp(name, "osmesa") == 0)
        *out = STIN_PLATFORM_OSMESA;
    else
        return 0;
    return 1;
}

/* An ES profile's version override is Mesa's ES one; the desktop one is
 * then unset, and the other way round. */
static const char *profile_value(const stin_profile *profile, int i)
{
    switch (i) {
    case 0: return profile->es ? NULL : profile->gl_version_override;
    case 1: return profile->glsl_version_override;
    case 2: return profile->extension_override;
    default: return profile->es ? profile->gl_version_override : NULL;
    }
}

static int same_value(const char *a, const char *b)
{
    return (!a && !b) || (a && b && strcmp(a, b) == 0);
}

/* Sets what the profile sets, unsets the rest. A NULL profile leaves the
 * environment alone, so a developer's own MESA_* variables still apply. */
static int apply_profile_env(const stin_profile *profile, char *err, size_t err_size)
{
    int i;
    if (!profile)
        return 1;
    for (i = 0; i < OVERRIDE_VARS; i++) {
        const char *want = profile_value(profile, i);
        if (driver_loaded && !same_value(getenv(override_vars[i]), want)) {
            stin_platform_errorf(err, err_size,
                                 "profile %s: %s must change but Mesa already read it in "
                                 "this process; run each profile in its own process",
                                 profile->name, override_vars[i]);
            return 0;
        }
    }
    for (i = 0; i < OVERRIDE_VARS; i++) {
        const char *want = profile_value(profile, i);
        int rc = want ? setenv(override_vars[i], want, 1) : unsetenv(override_vars[i]);
        if (rc != 0) {
            stin_platform_errorf(err, err_size, "profile %s: cannot set %s", profile->name,
                                 override_vars[i]);
            return 0;
        }
    }
    return 1;
}

void *stin_platform_get_proc_address(void *user, const char *name)
{
    stin_platform *p = user;
    if (!p || !name)
        return NULL;
    if (p->kind == STIN_PLATFORM_EGL)
        return stin_egl_get_proc(p->egl, name);
    return stin_osmesa_get_proc(p->osmesa, name);
}

static stin_platform_fn load(stin_platform *p, const char *name)
{
    return stin_platform_ptr_to_fn(stin_platform_get_proc_address(p, name));
}

/* "2.1 Mesa ..." or "4.5 (Core Profile) Mesa ..." -> 21, 45; "OpenGL ES 3.2
 * Mesa ..." -> 32 (is_es() tells the two apart). */
static int parse_gl_version(const unsigned char *s)
{
    int major = 0, minor = 0;
    const char *t = (const char *)s;
    if (t && strncmp(t, "OpenGL ES ", 10) == 0)
        t += 10;
    if (!t || sscanf(t, "%d.%d", &major, &minor) != 2)
        return 0;
    return major * 10 + minor;
}

static int is_es(const unsigned char *s)
{
    return s && strncmp((const char *)s, "OpenGL ES ", 10) == 0;
}

int stin_platform_has_token(const char *list, const char *token)
{
    size_t n = strlen(token);
    const char *s = list;
    while (s && (s = strstr(s, token)) != NULL) {
        if ((s == list || s[-1] == ' ') && (s[n] == '\0' || s[n] == ' '))
            return 1;
        s += n;
    }
    return 0;
}

int stin_platform_gl_version(stin_platform *p)
{
    p_get_string_fn get_string = (p_get_string_fn)load(p, "glGetString");
    return get_string ? parse_gl_version(get_string(P_GL_VERSION)) : 0;
}

int stin_platform_has_extension(stin_platform *p, const char *name)
{
    p_get_string_fn get_string = (p_get_string_fn)load(p, "glGetString");
    p_get_stringi_fn get_stringi = (p_get_stringi_fn)load(p, "glGetStringi");
    int count = 0, i;
    if (stin_platform_gl_version(p) >= 30 && get_stringi && p->get_integerv) {
        /* (ES 3.0 has glGetStringi too) */
        /* a core context has no GL_EXTENSIONS string */
        p->get_integerv(P_GL_NUM_EXTENSIONS, &count);
        for (i = 0; i < count; i++)
            if (!strcmp((const char *)get_stringi(P_GL_EXTENSIONS, (unsigned)i), name))
                return 1;
        return 0;
    }
    return get_string && stin_platform_has_token((const char *)get_string(P_GL_EXTENSIONS),
                                                 name);
}

static int load_readback(stin_platform *p, char *err, size_t err_size)
{
    p_get_string_fn get_string = (p_get_string_fn)load(p, "glGetString");
    p->read_pixels = (p_read_pixels_fn)load(p, "glReadPixels");
    p->get_integerv = (p_get_integerv_fn)load(p, "glGetIntegerv");
    p->pixel_storei = (p_pixel_storei_fn)load(p, "glPixelStorei");
    p->get_error = (p_get_error_fn)load(p, "glGetError");
    if (!get_string || !p->read_pixels || !p->get_integerv || !p->pixel_storei ||
        !p->get_error) {
        stin_platform_errorf(err, err_size,
                             "%s: GL 1.1 entry points (glReadPixels, glGetIntegerv, "
                             "glPixelStorei, glGetString, glGetError) did not resolve",
                             stin_platform_kind_name(p->kind));
        return 0;
    }
    p->es = is_es(get_string(P_GL_VERSION));
    /* pack buffers: desktop GL 2.1, OpenGL ES 3.0 */
    if (parse_gl_version(get_string(P_GL_VERSION)) >= (is_es(get_string(P_GL_VERSION)) ? 30 : 21)) {
        p->bind_buffer = (p_bind_buffer_fn)load(p, "glBindBuffer");
        p->has_pack_buffer = p->bind_buffer != NULL;
    }
    return 1;
}

stin_platform *stin_platform_create(const stin_platform_desc *desc, char *err, size_t err_size)
{
    stin_platform *p;
    if (err && err_size)
        err[0] = '\0';
    if (!desc) {
        stin_platform_errorf(err, err_size, "stin_platform_create: desc is NULL");
        return NULL;
    }
    if (desc->width < 0 || desc->height < 0 ||
        (desc->kind != STIN_PLATFORM_EGL && desc->kind != STIN_PLATFORM_OSMESA)) {
        stin_platform_errorf(err, err_size,
                             "stin_platform_create: bad desc (kind %d, size %dx%d)",
                             (int)desc->kind, desc->width, desc->height);
        return NULL;
    }
    if (desc->profile && desc->profile->es && desc->kind != STIN_PLATFORM_EGL) {
        stin_platform_errorf(err, err_size,
                             "profile %s is OpenGL ES, which %s does not offer; run it on egl",
                             desc->profile->name, stin_platform_kind_name(desc->kind));
        return NULL;
    }
    if (!apply_profile_env(desc->profile, err, err_size))
        return NULL;
    p = calloc(1, sizeof *p);
    if (!p) {
        stin_platform_errorf(err, err_size, "stin_platform_create: out of memory");
        return NULL;
    }
    p->kind = desc->kind;
    p->width = desc->width ? desc->width : 256;
    p->height = desc->height ? desc->height : 256;
    driver_loaded = 1;
    if (p->kind == STIN_PLATFORM_EGL)
        p->egl = stin_egl_create(p->width, p->height, desc->profile, err, err_size);
    else
        p->osmesa = stin_osmesa_create(p->width, p->height, desc->profile, err, err_size);
    if ((!p->egl && !p->osmesa) || !load_readback(p, err, err_size) ||
        !stin_platform_set_samples(p, desc->samples, err, err_size) ||
        (desc->srgb && !stin_platform_set_srgb(p, 1, err, err_size))) {
        stin_platform_destroy(p);
        return NULL;
    }
    return p;
}

void stin_platform_destroy(stin_platform *p)
{
    if (!p)
        return;
    if (p->read_pixels) { /* the context is current: its objects can go */
        stin_platform_msaa_release(p, &p->msaa);
        stin_platform_srgb_release(p, &p->srgb);
    }
    stin_egl_destroy(p->egl);
    stin_osmesa_destroy(p->osmesa);
    free(p);
}

uint32_t stin_platform_framebuffer(const stin_platform *p)
{
    if (!p)
        return 0;
    return p->msaa.fbo ? p->msaa.fbo : p->srgb.fbo;
}

/* The target of `samples` (<= 1: single-sampled), sRGB or not: one
 * framebuffer object of platform_msaa.c or platform_srgb.c, or none. */
static int make_target(stin_platform *p, int samples, int srgb, char *err, size_t err_size)
{
    stin_platform_msaa_release(p, &p->msaa);
    stin_platform_srgb_release(p, &p->srgb);
    if (samples > 1)
        return stin_platform_msaa_create(p, &p->msaa, samples, srgb, p->width, p->height, err,
                                         err_size);
    return !srgb || stin_platform_srgb_create(p, &p->srgb, p->width, p->height, err, err_size);
}

/* make_target, or on failure the target as it was (err kept). */
static int change_target(stin_platform *p, int samples, int srgb, char *err, size_t err_size)
{
    int was_samples = p->msaa.fbo ? p->msaa.samples : 0, was_srgb = stin_platform_srgb(p);
    char why[400];
    if (make_target(p, samples, srgb, err, err_size))
        return 1;
    snprintf(why, sizeof why, "%s", err ? err : "");
    if (!make_target(p, was_samples, was_srgb, NULL, 0))
        make_target(p, 0, 0, NULL, 0);
    stin_platform_errorf(err, err_size, "%s: %s%s", stin_platform_kind_name(p->kind),
                         samples > 1 ? "no multisampled target: " : "", why);
    return 0;
}

int stin_platform_set_samples(stin_platform *p, int samples, char *err, size_t err_size)
{
    if (!p || samples < 0 || samples > 64) {
        stin_platform_errorf(err, err_size, "stin_platform_set_samples: bad samples %d",
                             samples);
        return 0;
    }
    return change_target(p, samples, stin_platform_srgb(p), err, err_size);
}

int stin_platform_set_srgb(stin_platform *p, int on, char *err, size_t err_size)
{
    if (!p) {
        stin_platform_errorf(err, err_size, "stin_platform_set_srgb: platform is NULL");
        return 0;
    }
    return change_target(p, p->msaa.fbo ? p->msaa.samples : 0, on, err, err_size);
}

int stin_platform_samples(const stin_platform *p)
{
    return p && p->msaa.fbo ? p->msaa.samples : 0;
}

int stin_platform_srgb(const stin_platform *p)
{
    return p && (p->srgb.fbo || (p->msaa.fbo && p->msaa.srgb));
}

int stin_platform_width(const stin_platform *p)
{
    return p ? p->width : 0;
}

int stin_platform_height(const stin_platform *p)
{
    return p ? p->height : 0;
}

/* Pack state readback overrides, so tight rows come back whatever the
 * caller left set; restored afterwards. */
typedef struct pack_state {
    int alignment, row_length, skip_rows, skip_pixels, buffer;
} pack_state;

static void pack_begin(stin_platform *p, pack_state *s)
{
    p->get_integerv(P_GL_PACK_ALIGNMENT, &s->alignment);
    p->get_integerv(P_GL_PACK_ROW_LENGTH, &s->row_length);
    p->get_integerv(P_GL_PACK_SKIP_ROWS, &s->skip_rows);
    p->get_integerv(P_GL_PACK_SKIP_PIXELS, &s->skip_pixels);
    s->buffer = 0;
    if (p->has_pack_buffer) {
        p->get_integerv(P_GL_PIXEL_PACK_BUFFER_BINDING, &s->buffer);
        if (s->buffer)
            p->bind_buffer(P_GL_PIXEL_PACK_BUFFER, 0);
    }
    p->pixel_storei(P_GL_PACK_ALIGNMENT, 1);
    p->pixel_storei(P_GL_PACK_ROW_LENGTH, 0);
    p->pixel_storei(P_GL_PACK_SKIP_ROWS, 0);
    p->pixel_storei(P_GL_PACK_SKIP_PIXELS, 0);
}

static void pack_end(stin_platform *p, const pack_state *s)
{
    p->pixel_storei(P_GL_PACK_ALIGNMENT, s->alignment);
    p->pixel_storei(P_GL_PACK_ROW_LENGTH, s->row_length);
    p->pixel_storei(P_GL_PACK_SKIP_ROWS, s->skip_rows);
    p->pixel_storei(P_GL_PACK_SKIP_PIXELS, s->skip_pixels);
    if (s->buffer)
        p->bind_buffer(P_GL_PIXEL_PACK_BUFFER, (unsigned)s->buffer);
}

/* The buffer a read of `format` needs resolved from a multisampled target:
 * colour is averaged over the samples, depth and stencil take one sample. */
static unsigned resolve_bit(unsigned format)
{
    return format == P_GL_DEPTH_STENCIL ? 0x500u      /* both */
           : format == P_GL_DEPTH_COMPONENT ? 0x100u   /* GL_DEPTH_BUFFER_BIT */
           : format == P_GL_STENCIL_INDEX ? 0x400u   /* GL_STENCIL_BUFFER_BIT */
                                          : 0x4000u; /* GL_COLOR_BUFFER_BIT */
}

/* Any GL error (pending ones included, which this consumes) fails the read. */
static int read_pixels(stin_platform *p, unsigned format, unsigned type, int data, void *out)
{
    pack_state s;
    int ok = 1, i, saved[2];
    int resolved;
    if (!p || !out)
        return 0;
    resolved = stin_platform_msaa_resolve(p, &p->msaa, resolve_bit(format), data, p->width,
                                          p->height, saved);
    pack_begin(p, &s);
    p->read_pixels(0, 0, p->width, p->height, format, type, out);
    pack_end(p, &s);
    if (resolved)
        stin_platform_msaa_resolve_end(p, saved);
    for (i = 0; i < 32 && p->get_error() != P_GL_NO_ERROR; i++)
        ok = 0; /* bounded: a lost context can report errors forever */
    return ok;
}

int stin_platform_read_color(stin_platform *p, uint8_t *rgba)
{
    return read_pixels(p, P_GL_RGBA, P_GL_UNSIGNED_BYTE, 0, rgba);
}

int stin_platform_read_data(stin_platform *p, uint8_t *rgba)
{
    return read_pixels(p, P_GL_RGBA, P_GL_UNSIGNED_BYTE, 1, rgba);
}

/* OpenGL ES reads neither GL_FLOAT depth nor, on ES 2.0, stencil indices;
 * Mesa's NV_read_depth_stencil reads both as one 24/8 word on every ES
 * version: depth in the top 24 bits (exact: the buffer has 24), stencil in
 * the low 8. */
static int read_es_depth_stencil(stin_platform *p, float *depth, uint8_t *stencil)
{
    size_t i, n = (size_t)p->width * (size_t)p->height;
    uint32_t *words = malloc(n * sizeof *words);
    int ok = words && read_pixels(p, P_GL_DEPTH_STENCIL, P_GL_UNSIGNED_INT_24_8, 1, words);
    for (i = 0; ok && i < n; i++) {
        if (depth)
            depth[i] = (float)((double)(words[i] >> 8) / 16777215.0);
        if (stencil)
            stencil[i] = (uint8_t)(words[i] & 0xffu);
    }
    free(words);
    return ok;
}

int stin_platform_read_depth(stin_platform *p, float *depth)
{
    if (p && p->es)
        return depth && read_es_depth_stencil(p, depth, NULL);
    return read_pixels(p, P_GL_DEPTH_COMPONENT, P_GL_FLOAT, 1, depth);
}

int stin_platform_read_stencil(stin_platform *p, uint8_t *stencil)
{
    if (p && p->es)
        return stencil && read_es_depth_stencil(p, NULL, stencil);
    return read_pixels(p, P_GL_STENCIL_INDEX, P_GL_UNSIGNED_BYTE, 1, stencil);
}
