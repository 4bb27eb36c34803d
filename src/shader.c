/* GLSL compile and link with the driver's info log in a stack buffer. */
#include "internal.h"

static GLuint compile(stin_context *ctx, GLenum type, const char *name, char *msg, size_t size)
{
    const char *src = stin__shader_source(name);
    GLuint s;
    GLint ok = 0;
    char log[1024];
    if (!src) {
        stin__formatf(msg, size, "shader %s is not embedded", name);
        return 0;
    }
    s = GL(ctx, CreateShader)(type);
    GL(ctx, ShaderSource)(s, 1, &src, NULL);
    GL(ctx, CompileShader)(s);
    GL(ctx, GetShaderiv)(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        log[0] = '\0';
        GL(ctx, GetShaderInfoLog)(s, (GLsizei)sizeof log, NULL, log);
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_SHADER_COMPILE, "%s: %s", name, log);
        stin__formatf(msg, size, "%s did not compile", name);
        GL(ctx, DeleteShader)(s);
        return 0;
    }
    return s;
}

/* Attribute locations are fixed so that one vertex layout (and one VAO per
 * mesh) serves every program. */
GLuint stin__program_build(stin_context *ctx, const char *vert, const char *frag, char *msg,
                           size_t size)
{
    GLuint vs = compile(ctx, GL_VERTEX_SHADER, vert, msg, size), fs, p;
    GLint ok = 0;
    char log[1024];
    if (!vs)
        return 0;
    fs = compile(ctx, GL_FRAGMENT_SHADER, frag, msg, size);
    if (!fs) {
        GL(ctx, DeleteShader)(vs);
        return 0;
    }
    p = GL(ctx, CreateProgram)();
    GL(ctx, AttachShader)(p, vs);
    GL(ctx, AttachShader)(p, fs);
    GL(ctx, BindAttribLocation)(p, 0, "a_position");
    GL(ctx, BindAttribLocation)(p, 1, "a_normal");
    GL(ctx, BindAttribLocation)(p, 2, "a_uv");
    GL(ctx, BindAttribLocation)(p, 3, "a_tangent");
    GL(ctx, LinkProgram)(p);
    GL(ctx, DeleteShader)(vs); /* flagged; freed with the program */
    GL(ctx, DeleteShader)(fs);
    GL(ctx, GetProgramiv)(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        log[0] = '\0';
        GL(ctx, GetProgramInfoLog)(p, (GLsizei)sizeof log, NULL, log);
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_SHADER_LINK, "%s + %s: %s", vert, frag, log);
        stin__formatf(msg, size, "%s + %s did not link", vert, frag);
        GL(ctx, DeleteProgram)(p);
        return 0;
    }
    return p;
}
