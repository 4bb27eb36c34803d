/* SPDX-License-Identifier: MIT */
#include "caller_gl.h"

#include <string.h>

void caller_gl_load(caller_gl *gl, stin_platform *plat)
{
#define CALLER_GL_X_(ret, name, params)                                                   \
    {                                                                                     \
        void *p = stin_platform_get_proc_address(plat, "gl" #name);                      \
        memcpy(&gl->name, &p, sizeof p); /* object to function pointer: copy the bits */ \
    }
    CALLER_GL_FUNCS(CALLER_GL_X_)
#undef CALLER_GL_X_
}
