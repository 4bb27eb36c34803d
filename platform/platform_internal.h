/* SPDX-License-Identifier: MIT */
/*
 * Private to libstin_platform.a: the two context backends and the shared
 * error helper. Each backend creates, makes current, resolves GL entry
 * points and destroys; platform.c does everything common.
 */
#ifndef STIN_PLATFORM_INTERNAL_H
#define STIN_PLATFORM_INTERNAL_H

#include "stin_platform.h"

/* Generic function pointer: what get_proc_address returns before the caller
 * casts it to the real signature. */
typedef void (*stin_platform_fn)(void);

/* Function pointer <-> void * without the ISO C object/function cast
 * (POSIX guarantees both have the same representation). */
void *stin_platform_fn_to_ptr(stin_platform_fn fn);
stin_platform_fn stin_platform_ptr_to_fn(void *ptr);

/* snprintf into err when err is not NULL. */
void stin_platform_errorf(char *err, size_t err_size, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* A multisampled target (platform_msaa.c): its framebuffer and the
 * single-sampled twin read-backs resolve into; fbo 0: none. */
typedef struct stin_platform_msaa {
    unsigned fbo, resolve_fbo;
    unsigned rb[4]; /* colour, depth-stencil; the twin's colour, depth-stencil */
    int samples;    /* what the driver allocated (>= the count asked) */
    int srgb;       /* 1: both colours GL_SRGB8_ALPHA8, GL_FRAMEBUFFER_SRGB enabled */
} stin_platform_msaa;

/* Replaces m by a target of `samples` (<= 1: none, the default framebuffer),
 * sRGB-encoded with srgb = 1 (its resolve twin too, GL_FRAMEBUFFER_SRGB
 * enabled), and leaves it bound; 0 with err when the context cannot. */
int stin_platform_msaa_create(stin_platform *p, stin_platform_msaa *m, int samples, int srgb,
                              int w, int h, char *err, size_t err_size);
void stin_platform_msaa_release(stin_platform *p, stin_platform_msaa *m);
/* Blits buffer_bit (GL_COLOR/DEPTH/STENCIL_BUFFER_BIT) into the twin and
 * binds it for reading; saved[] gets the draw and read bindings for
 * stin_platform_msaa_resolve_end. data = 1: an sRGB target's samples are
 * averaged as stored (GL_FRAMEBUFFER_SRGB off for the blit), not decoded.
 * 0: no target. */
int stin_platform_msaa_resolve(stin_platform *p, stin_platform_msaa *m, unsigned buffer_bit,
                               int data, int w, int h, int saved[2]);
void stin_platform_msaa_resolve_end(stin_platform *p, const int saved[2]);

/* Exact token match in a space-separated list (NULL: none). */
int stin_platform_has_token(const char *list, const char *token);

/* The current context's GL version as major * 10 + minor (0: unknown), and
 * whether it lists extension `name` (exact token; glGetStringi on 3.0+). */
int stin_platform_gl_version(stin_platform *p);
int stin_platform_has_extension(stin_platform *p, const char *name);

/* An sRGB colour target (platform_srgb.c); fbo 0: none. */
typedef struct stin_platform_srgb_target {
    unsigned fbo;
    unsigned rb[2]; /* SRGB8_ALPHA8 colour, depth 24 / stencil 8 */
} stin_platform_srgb_target;

/* 1 when the context renders sRGB (GL 3.0, or ARB/EXT_framebuffer_sRGB with
 * EXT_texture_sRGB); 0 with why. *encoding_query: whether GL defines the
 * attachment's colour-encoding query (GL 3.0, ARB_framebuffer_sRGB). */
int stin_platform_srgb_supported(stin_platform *p, int *encoding_query, char *why,
                                 size_t why_size);

/* Replaces s by a w x h sRGB target, left bound with GL_FRAMEBUFFER_SRGB
 * enabled; 0 with err saying what the context lacks. */
int stin_platform_srgb_create(stin_platform *p, stin_platform_srgb_target *s, int w, int h,
                              char *err, size_t err_size);
/* Deletes it, disables GL_FRAMEBUFFER_SRGB and binds framebuffer 0. */
void stin_platform_srgb_release(stin_platform *p, stin_platform_srgb_target *s);

typedef struct stin_egl stin_egl;
stin_egl *stin_egl_create(int width, int height, const stin_profile *profile,
                          char *err, size_t err_size);
void stin_egl_destroy(stin_egl *egl);
void *stin_egl_get_proc(stin_egl *egl, const char *name);

typedef struct stin_osmesa stin_osmesa;
stin_osmesa *stin_osmesa_create(int width, int height, const stin_profile *profile,
                                char *err, size_t err_size);
void stin_osmesa_destroy(stin_osmesa *osm);
void *stin_osmesa_get_proc(stin_osmesa *osm, const char *name);

#endif
