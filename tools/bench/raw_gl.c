/* SPDX-License-Identifier: MIT */
/* Run-time resolution of the raw loop's GL entry points. */
#include "raw_gl.h"

#include <stdio.h>
#include <string.h>

static void *resolve(void *(*get_proc)(void *, const char *), void *user, const char *name)
{
    char full[80];
    void *p;
    snprintf(full, sizeof full, "gl%s", name);
    p = get_proc(user, full);
    if (!p) {
        /* GL 1.4 drivers expose buffer objects only under their ARB names. */
        snprintf(full, sizeof full, "gl%sARB", name);
        p = get_proc(user, full);
    }
    return p;
}

void raw_gl_load(raw_gl *gl, void *(*get_proc)(void *user, const char *name), void *user)
{
    void *p;
    memset(gl, 0, sizeof *gl);
    /* memcpy: ISO C has no cast from an object pointer to a function pointer. */
#define RAW_X_(ret, name, params, need)                \
    p = resolve(get_proc, user, #name);                \
    memcpy(&gl->name, &p, sizeof p);
    RAW_GL_FUNCS(RAW_X_)
#undef RAW_X_
}

const char *raw_gl_missing(const raw_gl *gl, int need)
{
#define RAW_X_(ret, name, params, n)                   \
    if (((n) & need) && !gl->name)                     \
        return "gl" #name;
    RAW_GL_FUNCS(RAW_X_)
#undef RAW_X_
    return NULL;
}
