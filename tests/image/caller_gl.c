/* SPDX-License-Identifier: MIT */
#include "caller_gl.h"

#include <stdio.h>
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

GLuint caller_gl_flat_program(const caller_gl *gl, int core, float r, float g, float b)
{
    char vs_src[160], fs_src[200];
    const char *v = vs_src, *f = fs_src;
    GLuint p, vs, fs;
    GLint ok = 0;
    if (!gl->CreateProgram)
        return 0;
    snprintf(vs_src, sizeof vs_src, "#version %s\n%s vec4 p;\nvoid main() { gl_Position = p; }\n",
             core ? "150" : "110", core ? "in" : "attribute");
    snprintf(fs_src, sizeof fs_src,
             core ? "#version 150\nout vec4 c;\nvoid main() { c = vec4(%g, %g, %g, 1.0); }\n"
                  : "#version 110\nvoid main() { gl_FragColor = vec4(%g, %g, %g, 1.0); }\n",
             r, g, b);
    p = gl->CreateProgram();
    vs = gl->CreateShader(GL_VERTEX_SHADER);
    fs = gl->CreateShader(GL_FRAGMENT_SHADER);
    gl->ShaderSource(vs, 1, &v, NULL);
    gl->ShaderSource(fs, 1, &f, NULL);
    gl->CompileShader(vs);
    gl->CompileShader(fs);
    gl->AttachShader(p, vs);
    gl->AttachShader(p, fs);
    gl->BindAttribLocation(p, 0, "p");
    gl->LinkProgram(p);
    gl->DeleteShader(vs);
    gl->DeleteShader(fs);
    gl->GetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        gl->DeleteProgram(p);
        return 0;
    }
    return p;
}
