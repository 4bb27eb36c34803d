/* SPDX-License-Identifier: MIT */
/* GL entry points: one table from gl_funcs.h, called through GL(ctx, Name). */
#ifndef STIN_GL_CALLS_H
#define STIN_GL_CALLS_H

#include "stin/stin.h"
#include "gl/gl_types.h"
#include "gl/gl_funcs.h"


/* ---- GL entry points ---------------------------------------------------- */
/* What an entry point or enum needs: a capability (STIN_CAP_*), GL 1.1
 * (NEED_CORE), a core GL version (NEED_GLxy) or, for the caller-state
 * calls of gl/caller_redirects.c, the version or extension that file checks
 * before it calls them (NEED_CHECKED). On OpenGL ES each NEED_GLxy reads as
 * the ES version that has the same calls (load.c); NEED_DESKTOP is GL 1.1
 * that ES never has (glClearDepth, glPolygonMode...), NEED_ES an ES 2.0
 * entry point stin calls only on ES (glClearDepthf: gl/portable_calls.c). */
enum { NEED_CORE = STIN_CAP_COUNT, NEED_GL12, NEED_GL13, NEED_GL14, NEED_GL30, NEED_GL31, NEED_GL32,
       NEED_GL33, NEED_GL42, NEED_GL43, NEED_CHECKED, NEED_DESKTOP, NEED_ES, NEED_COUNT };

typedef enum stin__glfn {
#define STIN_X_(ret, name, params, need, alt) STIN_GLFN_##name,
    STIN_GL_FUNCS(STIN_X_)
#undef STIN_X_
    STIN_GLFN_COUNT
} stin__glfn;

typedef struct stin__gl {
#define STIN_X_(ret, name, params, need, alt) ret(STIN_APIENTRY *name) params;
    STIN_GL_FUNCS(STIN_X_)
#undef STIN_X_
} stin__gl;

/* Resolves every entry point; returns the number that did not resolve.
 * loaded[i] is 1 for each entry point i that did. On an OpenGL ES context
 * (GL_VERSION "OpenGL ES ...") the desktop-only ones count as not resolved
 * and stay NULL: drivers resolve their names on ES too. */
int stin__gl_load(stin__gl *gl, stin_get_proc_fn get_proc, void *user,
                  unsigned char loaded[STIN_GLFN_COUNT]);
const char *stin__glfn_name(stin__glfn fn);
int stin__glfn_need(stin__glfn fn);
/* 1 for an entry point OpenGL ES does not have (loaded is then 0 on ES). */
int stin__glfn_desktop_only(stin__glfn fn);
/* 1 for a desktop-only entry point whose capability ES runs without it
 * (glClientActiveTexture: multitexture); 0 for glGetBufferSubData and
 * glClearBufferData, which stin's COMPUTE paths cannot do without. */
int stin__glfn_es_exempt(stin__glfn fn);
/* 1 when the current context's GL_VERSION names OpenGL ES. */
int stin__gl_is_es(const stin__gl *gl);
/* The GL version (major * 10 + minor) a NEED_GLxy names, else 0. */
int stin__need_version(int need);
/* The version a need asks of a desktop (es 0) or ES (es 1) context: 0 for a
 * capability need, -1 where that API never has it. */
int stin__need_version_in(int need, int es);
/* "GL 3.3" or the capability's name, for messages. */
const char *stin__need_name(int need);
struct stin_context;
/* 1 when entry point fn loaded and what it needs is present (after the caps
 * mask and the version cap): the test for optional calls. */
int stin__gl_available(const struct stin_context *ctx, stin__glfn fn);

/* Calls go through GL(ctx, Name)(args). The checked build first verifies that
 * the capability profile allows the entry point. */
#if defined(STIN_GL_CHECK) && STIN_GL_CHECK
void stin__gl_check_call(struct stin_context *ctx, stin__glfn fn, const char *file, int line);
void stin__gl_check_enum(struct stin_context *ctx, stin__glfn fn, GLenum e, const char *file,
                         int line);
#define GL(ctx, name) \
    (stin__gl_check_call((ctx), STIN_GLFN_##name, __FILE__, __LINE__), (ctx)->gl.name)
#define GL_ENUM(ctx, name, e) \
    (stin__gl_check_enum((ctx), STIN_GLFN_##name, (e), __FILE__, __LINE__), (ctx)->gl.name)
/* The OpenGL ES audit (gl/gl_audit.c): on an ES context, stin_create puts
 * wrappers that check each enum argument against the context's ES version
 * into ctx->gl (the driver's own pointers stay in ctx->gl_driver). */
void stin__gl_audit_at(struct stin_context *ctx, const char *file, int line);
void stin__gl_audit_enum_es(struct stin_context *ctx, stin__glfn fn, GLenum e, const char *file,
                            int line);
void stin__gl_audit_install(struct stin_context *ctx);
void stin__gl_audit_forget(struct stin_context *ctx);
/* The first ES version with enum e (20, 30, 31, 32; 0: desktop GL only);
 * *cap the capability that brings it earlier, -1 none. */
int stin__es_enum_version(GLenum e, int *cap);
#define STIN_GL_DRIVER(ctx) (&(ctx)->gl_driver)
#else
#define GL(ctx, name) ((ctx)->gl.name)
#define GL_ENUM(ctx, name, e) ((void)(e), (ctx)->gl.name)
#define stin__gl_audit_install(ctx) ((void)(ctx))
#define stin__gl_audit_forget(ctx) ((void)(ctx))
#define STIN_GL_DRIVER(ctx) (&(ctx)->gl)
#endif
/* Calls whose entry point differs on OpenGL ES (gl/portable_calls.c). */
void stin__clear_depth(struct stin_context *ctx, double depth);
void stin__depth_range(struct stin_context *ctx, double n, double f);
/* glDrawBuffer(GL_NONE) + glReadBuffer(GL_NONE) for a depth-only target. */
void stin__no_colour_buffers(struct stin_context *ctx);
/* The internal format for a texture of sized format `sized` on this context
 * (gl/texture_format.c): `sized` itself, or on OpenGL ES 2.0, which has no
 * sized formats, its base format (GL_RGBA8 -> GL_RGBA, GL_DEPTH_COMPONENT24
 * -> GL_DEPTH_COMPONENT, GL_DEPTH24_STENCIL8 -> GL_DEPTH_STENCIL). Every
 * glTexImage2D of stin's goes through it; the format and type stay the
 * caller's. stin__sized_formats says whether the context takes sized ones. */
GLenum stin__texture_format(const struct stin_context *ctx, GLenum sized);
int stin__sized_formats(const struct stin_context *ctx);
/* Whether a texture may have any size with mipmaps and GL_REPEAT (else
 * stin_create_texture resamples to powers of two). */
int stin__npot_textures(const struct stin_context *ctx);

/* glEnable/glDisable and friends take an enum whose capability is audited. */
#define GL_ENABLE(ctx, e) GL_ENUM(ctx, Enable, e)(e)
#define GL_DISABLE(ctx, e) GL_ENUM(ctx, Disable, e)(e)

#endif
