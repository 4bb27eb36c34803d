/* GL entry points: one table from gl_funcs.h, called through GL(ctx, Name). */
#ifndef STIN_GL_CALLS_H
#define STIN_GL_CALLS_H

#include "stin/stin.h"
#include "gl_types.h"
#include "gl_funcs.h"


/* ---- GL entry points ---------------------------------------------------- */
enum { NEED_CORE = STIN_CAP_COUNT, NEED_GL30, NEED_COUNT };

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
 * loaded[i] is 1 for each entry point i that did. */
int stin__gl_load(stin__gl *gl, stin_get_proc_fn get_proc, void *user,
                  unsigned char loaded[STIN_GLFN_COUNT]);
const char *stin__glfn_name(stin__glfn fn);
int stin__glfn_need(stin__glfn fn);

/* Calls go through GL(ctx, Name)(args). The checked build first verifies that
 * the capability profile allows the entry point. */
#if defined(STIN_GL_CHECK) && STIN_GL_CHECK
void stin__gl_check_call(struct stin_context *ctx, stin__glfn fn);
void stin__gl_check_enum(struct stin_context *ctx, stin__glfn fn, GLenum e);
#define GL(ctx, name) (stin__gl_check_call((ctx), STIN_GLFN_##name), (ctx)->gl.name)
#define GL_ENUM(ctx, name, e) (stin__gl_check_enum((ctx), STIN_GLFN_##name, (e)), (ctx)->gl.name)
#else
#define GL(ctx, name) ((ctx)->gl.name)
#define GL_ENUM(ctx, name, e) ((void)(e), (ctx)->gl.name)
#endif
/* glEnable/glDisable and friends take an enum whose capability is audited. */
#define GL_ENABLE(ctx, e) GL_ENUM(ctx, Enable, e)(e)
#define GL_DISABLE(ctx, e) GL_ENUM(ctx, Disable, e)(e)
/* In checked builds, GL errors after a pass are logged and counted. */
void stin__gl_check_errors(struct stin_context *ctx, const char *where);

#endif
