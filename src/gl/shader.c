/* SPDX-License-Identifier: MIT */
/* GLSL compile and link with the driver's info log in a stack buffer. */
#include "internal.h"

#define MAX_CHUNKS 8
/* the ES preamble (version line, derivatives, frag depth, precision) or a
 * tessellation version line, the context's defines, defines, main text,
 * chunks, the main text after the chunks */
#define MAX_PARTS (MAX_CHUNKS + 8)
#define CHUNK_MARKER "// @chunks"

/* Where the marker line starts in src, or NULL. */
static const char *find_marker(const char *src)
{
    const char *p = src;
    for (; *p; p++) {
        const char *a = p, *b = CHUNK_MARKER;
        while (*b && *a == *b) {
            a++;
            b++;
        }
        if (!*b)
            return p;
    }
    return NULL;
}

/* A chunk of the gl4 directory, or the gl2 one it shares (GLSL 1.10 names,
 * mapped by a #define in the gl4 main files) when gl4 has none of its own. */
static const char *shared_chunk(const char *name)
{
    const char *src = stin__shader_source(name);
    char gl2[64];
    size_t i;
    if (src || name[0] != 'g' || name[1] != 'l' || name[2] != '4')
        return src;
    for (i = 0; name[i] && i + 1 < sizeof gl2; i++)
        gl2[i] = name[i];
    gl2[i] = '\0';
    gl2[2] = '2';
    return stin__shader_source(gl2);
}

/* OpenGL ES: the same sources under a version and precision preamble that
 * replaces the file's #version line. On ES 2.0 shaders/gl2 runs as GLSL ES
 * 1.00, gl_FragDepth mapped to GL_EXT_frag_depth's name where the driver
 * has it; on ES 3.x every source runs as the context's GLSL ES 3.x0 (GLSL
 * ES 1.00 has no shadow samplers), shaders/gl2 with its GLSL 1.10 names
 * mapped, as the gl4 main files map them for the chunks they share. Fragment stages get highp where the ES 2.0 part has it
 * (GL_FRAGMENT_PRECISION_HIGH; ES 3.x always has), and the sampler types
 * without a default precision get one. STIN_ES marks the few differences
 * in the sources. */
/* GLSL ES 1.00's samplers default to lowp, and a lowp lookup is what Mesa
 * then returns: 10 bits of a depth texture (the outline's depth steps banded
 * the floor); highp where the stage has it. #extension lines come before
 * any statement, so the precision lines come last. */
static const char es100_version[] = "#version 100\n#define STIN_ES 1\n";
static const char es100_vertex[] = "precision highp sampler2D;\nprecision highp samplerCube;\n";
/* fragment derivatives where the context has them (STIN_CAP_DERIVATIVES) */
static const char es100_derivatives[] = "#extension GL_OES_standard_derivatives : enable\n";
/* gl_FragDepth (STIN_CAP_FRAG_DEPTH; programs that write it are built only
 * where the capability is) */
static const char es100_frag_depth[] =
    "#ifdef GL_EXT_frag_depth\n#extension GL_EXT_frag_depth : enable\n"
    "#define gl_FragDepth gl_FragDepthEXT\n#endif\n";
static const char es100_fragment[] =
    "#ifdef GL_FRAGMENT_PRECISION_HIGH\n"
    "precision highp float;\nprecision highp int;\n"
    "precision highp sampler2D;\nprecision highp samplerCube;\n"
    "#else\n"
    "precision mediump float;\nprecision mediump int;\n"
    "#endif\n";
static const char es3_precision[] =
    "#define STIN_ES 1\n"
    "precision highp float;\nprecision highp int;\n"
    "precision highp sampler2D;\nprecision highp sampler2DShadow;\n"
    "precision highp sampler2DArray;\nprecision highp sampler2DArrayShadow;\n"
    "precision highp sampler3D;\nprecision highp samplerCube;\n"
    "precision highp usampler2D;\nprecision highp isampler2D;\n";
/* GLSL 1.10's names in GLSL ES 3.x0, for shaders/gl2 */
static const char es3_gl2_vertex[] =
    "#define attribute in\n#define varying out\n"
    "#define texture2D texture\n#define texture2DLod textureLod\n";
static const char es3_gl2_fragment[] =
    "#define varying in\n"
    "#define texture2D texture\n#define texture2DLod textureLod\n"
    "#define textureCube texture\n#define shadow2D(s, c) vec4(texture(s, c))\n"
    "out vec4 stin_frag_color;\n#define gl_FragColor stin_frag_color\n";

/* The ES version line of the context's GLSL ES 3.x. */
static const char *es3_version(const stin_context *ctx)
{
    int v = ctx->caps.glsl_major * 10 + ctx->caps.glsl_minor;
    return v >= 32 ? "#version 320 es\n" : v == 31 ? "#version 310 es\n" : "#version 300 es\n";
}

static int has_derivatives(const stin_context *ctx)
{
    return (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_DERIVATIVES)) != 0;
}

/* The parts that replace the #version line of `name` on ES (count, at most 4). */
static int es_preamble(const stin_context *ctx, GLenum type, const char *name,
                       const GLchar **parts)
{
    int fragment = type == GL_FRAGMENT_SHADER, n = 1;
    if (ctx->caps.gl_major < 3) {
        parts[0] = es100_version;
        if (!fragment) {
            parts[n++] = es100_vertex;
            return n;
        }
        if (has_derivatives(ctx))
            parts[n++] = es100_derivatives;
        parts[n++] = es100_frag_depth;
        parts[n++] = es100_fragment;
        return n;
    }
    parts[0] = es3_version(ctx);
    parts[1] = es3_precision;
    if (name[2] != '2')
        return 2;
    parts[2] = fragment ? es3_gl2_fragment : es3_gl2_vertex;
    return 3;
}

/* The first lines of a tessellation stage: GLSL 4.00, or 1.50 with the
 * ARB extension (no `precise` there: the blend is written so that a shared
 * edge's two patches evaluate it in the same order); GLSL ES 3.20 has
 * tessellation and `precise` in core. */
static const char *tess_version(const stin_context *ctx)
{
    if (ctx->caps.es)
        return "#define STIN_PRECISE precise\n";
    if (ctx->caps.glsl_major * 100 + ctx->caps.glsl_minor >= 400)
        return "#version 400 core\n#define STIN_PRECISE precise\n";
    return "#version 150\n#extension GL_ARB_tessellation_shader : require\n#define STIN_PRECISE\n";
}

/* A fragment stage without derivatives takes the sources' derivative-free
 * paths (stin.h, DERIVATIVES), and without depth textures reads maps packed
 * into colour (pcf_tap_depth.glsl); NULL where nothing is defined. */
static const char *context_defines(const stin_context *ctx, GLenum type)
{
    static const char *const lines[4] = {
        NULL, "#define STIN_NO_DERIVATIVES 1\n", "#define STIN_NO_DEPTH_TEXTURE 1\n",
        "#define STIN_NO_DERIVATIVES 1\n#define STIN_NO_DEPTH_TEXTURE 1\n"};
    int depth = (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE)) != 0;
    if (type != GL_FRAGMENT_SHADER)
        return NULL;
    return lines[(has_derivatives(ctx) ? 0 : 1) + (depth ? 0 : 2)];
}

/* The main file's text up to its "// @chunks" line, then each chunk, then
 * the rest: one shader from several embedded files, without copying (GL
 * takes the pieces with their lengths); the context's defines and then
 * defines (or NULL) go in after the #version line. */
static GLuint compile(stin_context *ctx, GLenum type, const char *name,
                      const char *const *chunks, const char *defines, char *msg, size_t size)
{
    const char *own = context_defines(ctx, type);
    const char *src = stin__shader_source(name), *marker;
    const GLchar *parts[MAX_PARTS];
    GLint lengths[MAX_PARTS];
    GLsizei count = 0;
    GLuint s;
    GLint ok = 0;
    char log[1024];
    int i;
    if (!src) {
        stin__formatf(msg, size, "shader %s is not embedded", name);
        return 0;
    }
    marker = chunks && chunks[0] ? find_marker(src) : NULL;
    if (chunks && chunks[0] && !marker) {
        stin__formatf(msg, size, "shader %s has no %s line for its chunks", name, CHUNK_MARKER);
        return 0;
    }
    if (ctx->caps.es) {
        /* the file's #version line gives way to the ES preamble */
        int n = es_preamble(ctx, type, name, parts);
        while (count < n)
            lengths[count++] = -1;
    }
    if (type == GL_TESS_CONTROL_SHADER || type == GL_TESS_EVALUATION_SHADER) {
        /* the file's #version line gives way to the tessellation one */
        parts[count] = tess_version(ctx);
        lengths[count++] = -1;
    }
    if (count) {
        while (*src && *src != '\n')
            src++;
    }
    if (!count && (own || defines)) { /* after the file's #version line, which comes first */
        const char *line = src;
        while (*src && *src != '\n')
            src++;
        if (*src)
            src++;
        parts[count] = line;
        lengths[count++] = (GLint)(src - line);
    }
    if (own) {
        parts[count] = own;
        lengths[count++] = -1;
    }
    if (defines) {
        parts[count] = defines;
        lengths[count++] = -1;
    }
    parts[count] = src;
    lengths[count++] = marker ? (GLint)(marker - src) : -1;
    for (i = 0; marker && chunks[i] && i < MAX_CHUNKS; i++) {
        const char *c = shared_chunk(chunks[i]);
        if (!c) {
            stin__formatf(msg, size, "shader chunk %s is not embedded", chunks[i]);
            return 0;
        }
        parts[count] = c;
        lengths[count++] = -1;
    }
    if (marker) {
        parts[count] = marker;
        lengths[count++] = -1;
    }
    s = GL(ctx, CreateShader)(type);
    GL(ctx, ShaderSource)(s, count, parts, lengths);
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

/* Vertex shaders that draw meshes have a chunk line: on gl4 the attributes
 * (or, built as a tessellation evaluation stage, tess_eval.glsl), then the
 * context's displacement chunk of the shader's directory ("gl2/", "gl4/"). */
static const char *const *vertex_chunks(const stin_context *ctx, const char *vert, int tess,
                                        char name[40], const char *list[3])
{
    const char *src = stin__shader_source(vert);
    int n = 0;
    if (!src || !find_marker(src))
        return NULL;
    if (vert[2] == '4')
        list[n++] = tess ? "gl4/tess_eval.glsl" : "gl4/vertex_attributes.glsl";
    stin__formatf(name, 40, "gl2/%s",
                  ctx->vertex_chunk.displace ? "displace.glsl" : "displace_none.glsl");
    name[2] = vert[2]; /* the vertex shader's directory: gl2/ or gl4/ */
    list[n++] = name;
    list[n] = NULL;
    return list;
}

GLuint stin__program_build(stin_context *ctx, const char *vert, const char *frag,
                           const char *const *frag_chunks, int tessellate, char *msg,
                           size_t size)
{
    stin__program_source src;
    stin__memzero(&src, sizeof src);
    src.vert = vert;
    src.frag = frag;
    src.frag_chunks = frag_chunks;
    src.tessellate = tessellate;
    return stin__program_build_source(ctx, &src, msg, size);
}

/* Attribute locations are fixed so that one vertex layout (and one VAO per
 * mesh) serves every program; a program fed from elsewhere names its own. */
static void bind_attributes(stin_context *ctx, GLuint p, const char *const *names)
{
    static const char *const mesh[] = {"a_position", "a_normal", "a_uv", "a_tangent", NULL};
    GLuint i;
    if (!names)
        names = mesh;
    for (i = 0; names[i]; i++)
        GL(ctx, BindAttribLocation)(p, i, names[i]);
}

static void delete_stages(stin_context *ctx, const GLuint *stages, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (stages[i])
            GL(ctx, DeleteShader)(stages[i]); /* flagged; freed with the program */
}

GLuint stin__program_build_source(stin_context *ctx, const stin__program_source *src, char *msg,
                                  size_t size)
{
    /* vertex, tessellation control and evaluation, geometry, fragment */
    GLuint stages[5] = {0, 0, 0, 0, 0}, p;
    GLint ok = 0;
    char log[1024], vname[40];
    const char *vlist[3], *last;
    int i, tess = src->tessellate && ctx->vertex_chunk.tessellate, ok_so_far;
    if (tess) { /* the program's vertex shader displaces the tessellated points */
        stages[0] = compile(ctx, GL_VERTEX_SHADER, "gl4/tess.vert", NULL, NULL, msg, size);
        if (stages[0])
            stages[1] =
                compile(ctx, GL_TESS_CONTROL_SHADER, "gl4/tess.tesc", NULL, NULL, msg, size);
        if (stages[1])
            stages[2] = compile(ctx, GL_TESS_EVALUATION_SHADER, src->vert,
                                vertex_chunks(ctx, src->vert, 1, vname, vlist), NULL, msg, size);
        ok_so_far = stages[2] != 0;
    } else {
        stages[0] = compile(ctx, GL_VERTEX_SHADER, src->vert,
                            vertex_chunks(ctx, src->vert, 0, vname, vlist), NULL, msg, size);
        ok_so_far = stages[0] != 0;
    }
    if (ok_so_far && src->geom)
        ok_so_far = (stages[3] = compile(ctx, GL_GEOMETRY_SHADER, src->geom, src->geom_chunks,
                                         NULL, msg, size)) != 0;
    if (ok_so_far && src->frag)
        ok_so_far = (stages[4] = compile(ctx, GL_FRAGMENT_SHADER, src->frag, src->frag_chunks,
                                         src->frag_defines, msg, size)) != 0;
    else if (ok_so_far && ctx->caps.es) /* ES links no program without one */
        ok_so_far = (stages[4] = compile(ctx, GL_FRAGMENT_SHADER, "gl4/empty.frag", NULL, NULL,
                                         msg, size)) != 0;
    if (!ok_so_far) {
        delete_stages(ctx, stages, 5);
        return 0;
    }
    p = GL(ctx, CreateProgram)();
    for (i = 0; i < 5; i++)
        if (stages[i])
            GL(ctx, AttachShader)(p, stages[i]);
    bind_attributes(ctx, p, src->attributes);
    /* ES has no glBindFragDataLocation: a single output takes location 0,
     * several need layout(location) in the source (STIN_ES) */
    for (i = 0; !ctx->caps.es && i < STIN__MAX_FRAG_OUTPUTS && src->frag_outputs[i]; i++)
        GL(ctx, BindFragDataLocation)(p, (GLuint)i, src->frag_outputs[i]);
    if (src->feedback) {
        GLsizei n = 0;
        while (src->feedback[n])
            n++;
        GL(ctx, TransformFeedbackVaryings)(p, n, src->feedback, GL_INTERLEAVED_ATTRIBS);
    }
    GL(ctx, LinkProgram)(p);
    delete_stages(ctx, stages, 5);
    GL(ctx, GetProgramiv)(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        log[0] = '\0';
        GL(ctx, GetProgramInfoLog)(p, (GLsizei)sizeof log, NULL, log);
        last = src->frag ? src->frag : src->geom ? src->geom : "no fragment stage";
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_SHADER_LINK, "%s + %s: %s", src->vert,
                  last, log);
        stin__formatf(msg, size, "%s + %s did not link", src->vert, last);
        GL(ctx, DeleteProgram)(p);
        return 0;
    }
    return p;
}

void stin__uniform_locations(stin_context *ctx, GLuint prog, void *locs,
                             const stin__uniform_name *names, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        GLint *field = (GLint *)(void *)((unsigned char *)locs + names[i].offset);
        *field = GL(ctx, GetUniformLocation)(prog, names[i].name);
    }
}
