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

int caller_gl_dialect(const stin_profile *p)
{
    if (p->es)
        return p->max_gl_version > 0 && p->max_gl_version < 30 ? CALLER_GL_ES2 : CALLER_GL_ES;
    return p->core;
}

GLuint caller_gl_program(const caller_gl *gl, int core, const char *frag)
{
    /* ES fragment shaders have no default float precision; highp where the
     * stage has it (optional in ES 2.0), as a texel address needs it */
#define CALLER_GL_ES_PRECISION_                                                          \
    "#ifdef GL_FRAGMENT_PRECISION_HIGH\nprecision highp float;\n#else\n"                  \
    "precision mediump float;\n#endif\n"
    char vs_src[160];
    const char *v = vs_src, *f[3];
    GLuint p, vs, fs;
    GLint ok = 0;
    int es3 = core == CALLER_GL_ES, es2 = core == CALLER_GL_ES2, modern = core == 1 || es3;
    if (!gl->CreateProgram)
        return 0;
    snprintf(vs_src, sizeof vs_src, "#version %s\n%s vec4 p;\nvoid main() { gl_Position = p; }\n",
             es3 ? "300 es" : es2 ? "100" : modern ? "150" : "110", modern ? "in" : "attribute");
    f[0] = es3   ? "#version 300 es\n" CALLER_GL_ES_PRECISION_ "out vec4 c;\n"
         : es2   ? "#version 100\n" CALLER_GL_ES_PRECISION_ "#define c gl_FragColor\n"
         : core  ? "#version 150\nout vec4 c;\n"
                 : "#version 110\n#define c gl_FragColor\n";
#undef CALLER_GL_ES_PRECISION_
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
    if ((core == 1 || core == CALLER_GL_ES) && gl->GenVertexArrays)
        gl->GenVertexArrays(1, vao);
}

int caller_gl_read_texture(const caller_gl *gl, int core, GLuint texture, int w, int h,
                           uint8_t *into)
{
    GLint bound = 0;
    GLuint fb = 0;
    int ok;
    if (core != CALLER_GL_ES && core != CALLER_GL_ES2 && gl->GetTexImage) {
        if (gl->ActiveTexture)
            gl->ActiveTexture(GL_TEXTURE0);
        gl->BindTexture(GL_TEXTURE_2D, texture);
        gl->GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, into);
        gl->BindTexture(GL_TEXTURE_2D, 0);
        return 1;
    }
    if (!gl->GenFramebuffers || !gl->FramebufferTexture2D || !gl->ReadPixels)
        return 0;
    gl->GetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
    gl->GenFramebuffers(1, &fb);
    gl->BindFramebuffer(GL_FRAMEBUFFER, fb);
    gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    ok = gl->CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    if (ok)
        gl->ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, into);
    gl->BindFramebuffer(GL_FRAMEBUFFER, (GLuint)bound);
    gl->DeleteFramebuffers(1, &fb);
    return ok;
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
