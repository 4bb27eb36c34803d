/* SPDX-License-Identifier: MIT */
/*
 * stin_platform — offscreen GL contexts for stin's tools and tests.
 *
 * Not part of libstin.a: this is libstin_platform.a, which links EGL and OSMesa
 * itself. One small API over two backends:
 *   EGL     surfaceless Mesa (EGL_MESA_platform_surfaceless) with a pbuffer
 *           surface (24-bit depth, 8-bit stencil) so that legacy contexts have a
 *           default framebuffer; device EGL (EGL_EXT_platform_device) when
 *           STIN_EGL_DEVICE=1 or when surfaceless is missing (GPU machines).
 *           OpenGL ES 2.0-3.2 contexts (the profiles with es set) come from
 *           the same display, with EGL_OPENGL_ES_API and an ES2/ES3 config.
 *   OSMesa  Mesa's software context into client memory, compatibility or core;
 *           no OpenGL ES (an ES profile there fails, saying so).
 *
 * Capability profiles emulate weaker hardware. Each profile is run in its own
 * process: stin_platform_create() applies the profile's Mesa overrides
 * (MESA_GL_VERSION_OVERRIDE or, for the OpenGL ES profiles, MESA_GLES_VERSION_OVERRIDE;
 * MESA_GLSL_VERSION_OVERRIDE, MESA_EXTENSION_OVERRIDE)
 * to the environment before the driver loads, and the profile's caps_mask and
 * max_gl_version go into stin_desc — the in-process mask is the authority, since
 * Mesa refuses to disable some extensions.
 */
#ifndef STIN_PLATFORM_H
#define STIN_PLATFORM_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum stin_platform_kind {
    STIN_PLATFORM_EGL = 0,
    STIN_PLATFORM_OSMESA
} stin_platform_kind;

typedef struct stin_profile {
    const char *name;               /* "gl11", "gl13-combine", ... */
    const char *summary;            /* one line for docs and --help */
    int gl_major, gl_minor;         /* context version to ask for / override to */
    int core;                       /* 1: core profile context */
    const char *gl_version_override;   /* MESA_GL_VERSION_OVERRIDE, NULL = none */
    const char *glsl_version_override; /* MESA_GLSL_VERSION_OVERRIDE, NULL = none */
    const char *extension_override;    /* MESA_EXTENSION_OVERRIDE, NULL = none */
    uint64_t caps_mask;             /* STIN_CAP_BIT()s hidden in-process */
    int max_gl_version;             /* stin_desc.max_gl_version (the ES version on ES) */
    /* 1: an OpenGL ES context of version gl_major.gl_minor (EGL only: OSMesa
     * has no ES); gl_version_override then goes to MESA_GLES_VERSION_OVERRIDE
     * and core is 0. */
    int es;
} stin_profile;

/* The table of named profiles (see docs/profiles.md). */
size_t stin_profile_count(void);
const stin_profile *stin_profile_at(size_t i);
const stin_profile *stin_profile_find(const char *name); /* NULL if unknown */

typedef struct stin_platform_desc {
    stin_platform_kind kind;
    int width, height;              /* default 256 x 256 */
    const stin_profile *profile;    /* NULL: best compatibility context, no overrides */
    /* 0 or 1: render into the single-sampled default framebuffer. 2, 4, 8...:
     * into a framebuffer object of that many samples (stin_platform_set_samples);
     * create fails, saying why, where the context has none. */
    int samples;
    /* 1: render into an sRGB colour target (stin_platform_set_srgb); create
     * fails, saying why, where the context has none. 0: the default
     * framebuffer (linear RGBA8). */
    int srgb;
} stin_platform_desc;

typedef struct stin_platform stin_platform;

/* Creates and makes current an offscreen context. On failure returns NULL and
 * writes a message into err.
 * With a profile, the three MESA_*_OVERRIDE variables are set to the profile's
 * values (unset where it has none) before the driver loads; a later create in
 * the same process whose profile needs other values fails, since Mesa has
 * already read them. profile = NULL leaves the environment as it is. */
stin_platform *stin_platform_create(const stin_platform_desc *desc, char *err, size_t err_size);
void stin_platform_destroy(stin_platform *p);

/* Fits stin_desc.get_proc_address; user is the stin_platform. Resolves core
 * GL 1.1 functions as well as extension functions. */
void *stin_platform_get_proc_address(void *user, const char *name);

const char *stin_platform_kind_name(stin_platform_kind kind);
int stin_platform_kind_from_name(const char *name, stin_platform_kind *out); /* 1 ok */

/* Framebuffer name to render into: 0, the default framebuffer, or the
 * framebuffer object of stin_platform_set_samples and stin_platform_set_srgb
 * (the two combine: a multisampled sRGB target). */
uint32_t stin_platform_framebuffer(const stin_platform *p);

/* Renders into a framebuffer object of `samples` samples from now on (an
 * RGBA8 and a depth 24 / stencil 8 renderbuffer of the platform's size,
 * left bound), replacing an earlier one; 0 or 1 goes back to the default
 * framebuffer. Needs GL 3.0, GL_ARB_framebuffer_object, or
 * GL_EXT_framebuffer_object with GL_EXT_framebuffer_multisample and
 * GL_EXT_framebuffer_blit, on either backend, and samples <= GL_MAX_SAMPLES.
 * Returns 1, or 0 with err saying which is missing (the target is then the
 * one before, or the default framebuffer where that cannot be made again).
 * The read-backs below resolve it first: one blit into a single-sampled twin
 * (colour averaged over the samples; depth and stencil one sample's, the
 * driver's choice), the caller's framebuffer bindings kept. With
 * stin_platform_set_srgb on, both colours are GL_SRGB8_ALPHA8 and
 * GL_FRAMEBUFFER_SRGB is on: the samples are written encoded and the resolve
 * averages them in linear space and encodes the mean (GL 4.4's blit rule,
 * which Mesa follows). */
int stin_platform_set_samples(stin_platform *p, int samples, char *err, size_t err_size);
/* The samples of the current target as the driver allocated them (it may
 * round the count up); 0 for the default framebuffer. */
int stin_platform_samples(const stin_platform *p);

/* on = 1: renders into an sRGB colour target from now on: a framebuffer
 * object of the platform's size with a GL_SRGB8_ALPHA8 colour and a depth
 * 24 / stencil 8 renderbuffer, left bound, and GL_FRAMEBUFFER_SRGB enabled
 * (the application's part: GL then encodes every colour written to it with
 * the sRGB transfer function and blends in linear space). Needs framebuffer
 * objects (GL 3.0, GL_ARB_framebuffer_object, or GL_EXT_framebuffer_object
 * with GL_EXT_packed_depth_stencil) and sRGB rendering (GL 3.0, or
 * GL_ARB_framebuffer_sRGB or GL_EXT_framebuffer_sRGB with
 * GL_EXT_texture_sRGB), on either backend. Returns 1, or 0 with err saying
 * what is missing (the target is then the one before). Into a multisampled
 * target (stin_platform_set_samples, before or after) the multisampled
 * colour and its resolve twin are the sRGB ones.
 * on = 0: deletes it, disables GL_FRAMEBUFFER_SRGB and binds framebuffer 0
 * (the linear multisampled target, where the samples are still set).
 * stin_platform_read_color returns its stored, encoded bytes. */
int stin_platform_set_srgb(stin_platform *p, int on, char *err, size_t err_size);
/* 1 while the target is the sRGB one. */
int stin_platform_srgb(const stin_platform *p);
int stin_platform_width(const stin_platform *p);
int stin_platform_height(const stin_platform *p);

/* Readback of the current framebuffer, rows bottom to top.
 * color: 4 bytes per pixel RGBA8; depth: window-space depth in [0,1];
 * stencil: one byte per pixel. Return 1 on success.
 * Reads width x height from (0,0) of the bound read framebuffer. The pack
 * state (alignment, row length, skips, and on GL 2.1+ the PIXEL_PACK_BUFFER
 * binding) is set for a tight read and restored. Returns 0 if GL reports an
 * error afterwards; errors pending before the call count too and are
 * consumed. */
int stin_platform_read_color(stin_platform *p, uint8_t *rgba);
/* read_color for a data frame (STIN_OUTPUT_NORMAL, STIN_OUTPUT_VISIBILITY):
 * the same bytes, except that a multisampled sRGB target's samples are
 * averaged as stored (GL_FRAMEBUFFER_SRGB off for the resolve), since stin
 * writes data there unencoded; read_color would decode, average and encode
 * them as colour, moving silhouette pixels. */
int stin_platform_read_data(stin_platform *p, uint8_t *rgba);
int stin_platform_read_depth(stin_platform *p, float *depth);
int stin_platform_read_stencil(stin_platform *p, uint8_t *stencil);

#ifdef __cplusplus
}
#endif
#endif
