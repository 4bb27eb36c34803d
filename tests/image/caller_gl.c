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

GLuint caller_gl_program(const caller_gl *gl, int core, const char *frag)
{
    char vs_src[160];
    const char *v = vs_src, *f[3];
    GLuint p, vs, fs;
    GLint ok = 0;
    if (!gl->CreateProgram)
        return 0;
    snprintf(vs_src, sizeof vs_src, "#version %s\n%s vec4 p;\nvoid main() { gl_Position = p; }\n",
             core == CALLER_GL_ES ? "300 es" : core ? "150" : "110", core ? "in" : "attribute");
    f[0] = core == CALLER_GL_ES ? "#version 300 es\nprecision mediump float;\nout vec4 c;\n"
         : core                 ? "#version 150\nout vec4 c;\n"
                                : "#version 110\n#define c gl_FragColor\n";
    f[1] = frag;
    p = gl->CreateProgram();
    vs = gl->CreateShader(GL_VERTEX_SHADER);
    fs = gl->CreateShader(GL_FRAGMENT_SHADER);
    gl->ShaderSource(vs, 1, &v, NULL);
    gl->ShaderSource(fs, 2, f, NULL);
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

GLuint caller_gl_flat_program(const caller_gl *gl, int core, float r, float g, float b)
{
    char fs_src[96];
    snprintf(fs_src, sizeof fs_src, "void main() { c = vec4(%g, %g, %g, 1.0); }\n", r, g, b);
    return caller_gl_program(gl, core, fs_src);
}

void caller_gl_buffers(const caller_gl *gl, int core, GLuint *vbo, GLuint *vao)
{
    *vbo = *vao = 0;
    gl->GenBuffers(1, vbo);
    if (core && gl->GenVertexArrays)
        gl->GenVertexArrays(1, vao);
}

void caller_gl_delete(const caller_gl *gl, GLuint *program, GLuint *vbo, GLuint *vao)
{
    if (*vao)
        gl->DeleteVertexArrays(1, vao);
    if (*vbo)
        gl->DeleteBuffers(1, vbo);
    if (*program)
        gl->DeleteProgram(*program);
    *program = *vbo = *vao = 0;
}
