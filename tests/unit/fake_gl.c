/* SPDX-License-Identifier: MIT */
/* The fake GL of fake_gl.h. Entry points that need behaviour (strings,
 * integers, object names, shader status, counters) are written out here,
 * the ones that change GL state in fake_gl_state.c; every other one is a
 * counted no-op generated from the STIN_GL_FUNCS list, so the fake follows
 * the library's table and every stub has the exact signature. */
#define FAKE_GL_STUBS
#include "fake_gl.h"

#include <string.h>

fake_gl_state fake_gl;

/* ---- generated no-op stubs -------------------------------------------------
 * FAKE_CUSTOM_<Name> marks an entry point written out by hand below,
 * FAKE_STATE_<Name> (fake_gl_state.h) one written out in fake_gl_state.c;
 * the probes turn "is it marked?" into 0 or 1 so the X-macro can skip them.
 * A non-void entry point left unmarked fails to compile (no return value). */
#define FAKE_CUSTOM_GetString ~, 1
#define FAKE_CUSTOM_GetStringi ~, 1
#define FAKE_CUSTOM_GetIntegerv ~, 1
#define FAKE_CUSTOM_DrawElements ~, 1
#define FAKE_CUSTOM_GenTextures ~, 1
#define FAKE_CUSTOM_DeleteTextures ~, 1
#define FAKE_CUSTOM_TexImage2D ~, 1
#define FAKE_CUSTOM_GenBuffers ~, 1
#define FAKE_CUSTOM_BufferData ~, 1
#define FAKE_CUSTOM_DeleteBuffers ~, 1
#define FAKE_CUSTOM_GenVertexArrays ~, 1
#define FAKE_CUSTOM_DeleteVertexArrays ~, 1
#define FAKE_CUSTOM_GenFramebuffers ~, 1
#define FAKE_CUSTOM_GenTransformFeedbacks ~, 1
#define FAKE_CUSTOM_DeleteTransformFeedbacks ~, 1
#define FAKE_CUSTOM_DeleteFramebuffers ~, 1
#define FAKE_CUSTOM_CreateShader ~, 1
#define FAKE_CUSTOM_ShaderSource ~, 1
#define FAKE_CUSTOM_GetShaderiv ~, 1
#define FAKE_CUSTOM_GetShaderInfoLog ~, 1
#define FAKE_CUSTOM_DeleteShader ~, 1
#define FAKE_CUSTOM_CreateProgram ~, 1
#define FAKE_CUSTOM_AttachShader ~, 1
#define FAKE_CUSTOM_GetProgramiv ~, 1
#define FAKE_CUSTOM_GetProgramInfoLog ~, 1
#define FAKE_CUSTOM_DeleteProgram ~, 1
#define FAKE_CUSTOM_GetUniformLocation ~, 1
#define FAKE_CUSTOM_GetFramebufferAttachmentParameteriv ~, 1
#define FAKE_CUSTOM_CheckFramebufferStatus ~, 1
#define FAKE_CUSTOM_DrawArrays ~, 1
#define FAKE_CUSTOM_IsFramebuffer ~, 1
#define FAKE_CUSTOM_IsEnabled ~, 1
#define FAKE_CUSTOM_GetQueryiv ~, 1
#define FAKE_CUSTOM_GenQueries ~, 1
#define FAKE_CUSTOM_BeginQuery ~, 1
#define FAKE_CUSTOM_EndQuery ~, 1
#define FAKE_CUSTOM_GetQueryObjectuiv ~, 1
#define FAKE_CUSTOM_GetQueryObjectui64v ~, 1
#define FAKE_CUSTOM_TexImage3D ~, 1
#define FAKE_CUSTOM_GetTexLevelParameteriv ~, 1

/* Generated no-ops that leave the state fake_gl_state.h keeps alone: they
 * draw, upload, or set program, texture-object or array-pointer state,
 * which the fake does not keep. Any other generated one is reported by
 * fake_gl_untracked_entry_point when called. */
#define FAKE_STATELESS_Clear ~, 1
#define FAKE_STATELESS_LogicOp ~, 1
#define FAKE_STATELESS_ClearBufferuiv ~, 1
#define FAKE_STATELESS_TexParameteri ~, 1
#define FAKE_STATELESS_TexParameterfv ~, 1
#define FAKE_STATELESS_Finish ~, 1
#define FAKE_STATELESS_Flush ~, 1
#define FAKE_STATELESS_ReadPixels ~, 1
#define FAKE_STATELESS_TexSubImage2D ~, 1
#define FAKE_STATELESS_DrawPixels ~, 1
#define FAKE_STATELESS_RasterPos2f ~, 1
#define FAKE_STATELESS_Begin ~, 1
#define FAKE_STATELESS_End ~, 1
#define FAKE_STATELESS_Vertex3fv ~, 1
#define FAKE_STATELESS_CopyTexSubImage2D ~, 1
#define FAKE_STATELESS_TexImage1D ~, 1
#define FAKE_STATELESS_BufferSubData ~, 1
#define FAKE_STATELESS_GetBufferSubData ~, 1
#define FAKE_STATELESS_MemoryBarrier ~, 1
#define FAKE_STATELESS_ClearBufferData ~, 1
#define FAKE_STATELESS_CompileShader ~, 1
#define FAKE_STATELESS_BindAttribLocation ~, 1
#define FAKE_STATELESS_LinkProgram ~, 1
#define FAKE_STATELESS_Uniform1i ~, 1
#define FAKE_STATELESS_Uniform1f ~, 1
#define FAKE_STATELESS_Uniform3fv ~, 1
#define FAKE_STATELESS_Uniform4fv ~, 1
#define FAKE_STATELESS_Uniform4iv ~, 1
#define FAKE_STATELESS_Uniform1iv ~, 1
#define FAKE_STATELESS_Uniform2uiv ~, 1
#define FAKE_STATELESS_Uniform4uiv ~, 1
#define FAKE_STATELESS_UniformMatrix3fv ~, 1
#define FAKE_STATELESS_UniformMatrix4fv ~, 1
#define FAKE_STATELESS_FramebufferTexture2D ~, 1
#define FAKE_STATELESS_GenerateMipmap ~, 1
#define FAKE_STATELESS_DrawBuffers ~, 1
#define FAKE_STATELESS_BindFragDataLocation ~, 1
#define FAKE_STATELESS_DeleteQueries ~, 1
#define FAKE_STATELESS_QueryCounter ~, 1
#define FAKE_STATELESS_FramebufferTextureLayer ~, 1
#define FAKE_STATELESS_BlendEquationSeparate ~, 1
#define FAKE_STATELESS_TransformFeedbackVaryings ~, 1
#define FAKE_STATELESS_BeginTransformFeedback ~, 1
#define FAKE_STATELESS_EndTransformFeedback ~, 1
#define FAKE_STATELESS_DrawTransformFeedback ~, 1
/* the caller's state stin sets aside: the fake's caller never sets it */
#define FAKE_STATELESS_BindProgramPipeline ~, 1
#define FAKE_STATELESS_ClampColor ~, 1
#define FAKE_STATELESS_ProvokingVertex ~, 1

#define FAKE_IS_CUSTOM(name) FAKE_PROBE(FAKE_CUSTOM_##name)
#define FAKE_IS_STATELESS(name) FAKE_PROBE(FAKE_STATELESS_##name)
/* 00: generated here, 10: written out here, 01: written out in fake_gl_state.c */
#define FAKE_KIND(name) FAKE_CAT(FAKE_IS_CUSTOM(name), FAKE_IS_STATE(name))

#define FAKE_STUB_00(ret, name, params) \
    static ret STIN_APIENTRY fake_##name params { fake_gl.calls[STIN_GLFN_##name]++; }
#define FAKE_STUB_10(ret, name, params) /* written out below */
#define FAKE_STUB_01(ret, name, params) /* in fake_gl_state.c */
#define FAKE_STUB(ret, name, params, need, alt) \
    FAKE_CAT(FAKE_STUB_, FAKE_KIND(name))(ret, name, params)

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#endif
STIN_GL_FUNCS(FAKE_STUB)
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

/* Every stub of this file, by prototype: the hand-written ones below must
 * match the table (fake_gl_state.h declares the others). */
#define FAKE_PROTO_0(ret, name, params) static ret STIN_APIENTRY fake_##name params;
#define FAKE_PROTO_1(ret, name, params)
#define FAKE_PROTO(ret, name, params, need, alt) \
    FAKE_CAT(FAKE_PROTO_, FAKE_IS_STATE(name))(ret, name, params)
STIN_GL_FUNCS(FAKE_PROTO)
#undef FAKE_PROTO

/* 1 for a generated no-op that is not marked stateless. */
#define FAKE_UNTRACKED_000 1
#define FAKE_UNTRACKED_001 0
#define FAKE_UNTRACKED_100 0
#define FAKE_UNTRACKED_010 0
#define FAKE_UNTRACKED(ret, name, params, need, alt) \
    FAKE_CAT(FAKE_UNTRACKED_, FAKE_CAT(FAKE_KIND(name), FAKE_IS_STATELESS(name))),
static const unsigned char untracked_noop[STIN_GLFN_COUNT] = {STIN_GL_FUNCS(FAKE_UNTRACKED)};

const char *fake_gl_untracked_entry_point(void)
{
    int i;
    for (i = 0; i < STIN_GLFN_COUNT; i++)
        if (untracked_noop[i] && fake_gl.calls[i])
            return stin__glfn_name((stin__glfn)i);
    return NULL;
}

/* ---- strings and integers ---------------------------------------------- */
static const GLubyte *STIN_APIENTRY fake_GetString(GLenum name)
{
    const char *s = NULL;
    COUNT(GetString);
    switch (name) {
    case GL_VERSION: s = fake_gl.config.version; break;
    case GL_SHADING_LANGUAGE_VERSION: s = fake_gl.config.glsl_version; break;
    case GL_EXTENSIONS: s = fake_gl.config.extensions; break;
    case GL_RENDERER: s = "stin fake GL"; break;
    case GL_VENDOR: s = "stin unit tests"; break;
    default: break;
    }
    return (const GLubyte *)s;
}

static const GLubyte *STIN_APIENTRY fake_GetStringi(GLenum name, GLuint i)
{
    COUNT(GetStringi);
    if (name != GL_EXTENSIONS || i >= (GLuint)fake_gl.config.extension_count)
        return NULL;
    return (const GLubyte *)fake_gl.config.extension_list[i];
}

/* The caller's framebuffer object `name` of the config, or NULL. */
static const fake_gl_fbo *caller_fbo(GLuint name)
{
    int i;
    for (i = 0; name && i < fake_gl.config.framebuffer_count; i++)
        if (fake_gl.config.framebuffers[i].name == name)
            return &fake_gl.config.framebuffers[i];
    return NULL;
}

/* Stencil and depth bits of the bound draw framebuffer. */
static int bound_bits(int stencil)
{
    const fake_gl_fbo *f = caller_fbo(fake_gl.gl.draw_framebuffer);
    if (f)
        return stencil ? f->stencil_bits : f->depth_bits;
    return stencil ? fake_gl.config.stencil_bits : fake_gl.config.depth_bits;
}

static void STIN_APIENTRY fake_GetIntegerv(GLenum pname, GLint *data)
{
    const fake_gl_config *c = &fake_gl.config;
    COUNT(GetIntegerv);
    switch (pname) {
    case GL_MAX_LIGHTS: *data = c->max_lights; break;
    case GL_MAX_CLIP_PLANES: *data = 8; break; /* Mesa's */
    case 0x88FF: *data = 2048; break; /* GL_MAX_ARRAY_TEXTURE_LAYERS: Mesa's */
    case GL_STENCIL_BITS: *data = bound_bits(1); break;
    case GL_DEPTH_BITS: *data = bound_bits(0); break;
    case GL_ALPHA_BITS: *data = 8; break;
    case GL_SAMPLE_BUFFERS: *data = c->sample_buffers; break;
    case GL_MAX_TEXTURE_SIZE: *data = c->max_texture_size; break;
    case GL_MAX_VIEWPORT_DIMS: data[0] = data[1] = 16384; break; /* Mesa's */
    case GL_MAX_TEXTURE_UNITS: *data = c->max_texture_units; break;
    case GL_MAX_TEXTURE_IMAGE_UNITS: *data = c->max_texture_image_units; break;
    case GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS: *data = c->max_vertex_texture_units; break;
    case GL_MAX_DRAW_BUFFERS: *data = c->max_draw_buffers; break;
    case GL_MAX_VERTEX_UNIFORM_COMPONENTS: case GL_MAX_FRAGMENT_UNIFORM_COMPONENTS:
        *data = 4096; break; /* Mesa's */
    case GL_MAX_VERTEX_UNIFORM_VECTORS: case GL_MAX_FRAGMENT_UNIFORM_VECTORS:
        *data = 1024; break;
    case GL_MAX_GEOMETRY_OUTPUT_VERTICES: *data = c->max_geometry_output_vertices; break;
    case GL_MAX_TESS_GEN_LEVEL: /* GL_INVALID_ENUM without GL 4.0 or ARB_tessellation_shader */
        if (!c->max_tess_gen_level)
            fake_gl_state_refused("glGetIntegerv", pname);
        *data = c->max_tess_gen_level;
        break;
    case GL_NUM_EXTENSIONS: *data = c->extension_count; break;
    case GL_CONTEXT_PROFILE_MASK: *data = c->core_profile ? GL_CONTEXT_CORE_PROFILE_BIT : 2; break;
    default:
        if (!fake_gl_state_get(pname, data)) {
            *data = 0;
            fake_gl_state_untracked("glGetIntegerv", pname);
        }
        break;
    }
}

static void STIN_APIENTRY fake_GetFramebufferAttachmentParameteriv(GLenum target, GLenum att,
                                                                   GLenum pname, GLint *v)
{
    (void)target;
    (void)att;
    COUNT(GetFramebufferAttachmentParameteriv);
    if (pname == 0x8CD0) { /* GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE: none without bits */
        int bits = bound_bits(att == GL_STENCIL || att == 0x8D20);
        *v = !bits ? GL_NONE : fake_gl.gl.draw_framebuffer ? 0x8D41 /* RENDERBUFFER */
                                                           : 0x8218 /* FRAMEBUFFER_DEFAULT */;
        return;
    }
    *v = pname == GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE ? bound_bits(1)
         : pname == GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE ? bound_bits(0)
                                                         : 0;
}

/* ---- drawing ------------------------------------------------------------ */
/* A draw into the test's watched framebuffer, and whether it wrote depth. */
static void watched_draw(void)
{
    const fake_gl_glstate *g = &fake_gl.gl;
    if (g->draw_framebuffer != fake_gl.watched_framebuffer)
        return;
    fake_gl.draws_into_watched++;
    fake_gl.depth_draws_into_watched += g->enabled[FAKE_GL_DEPTH_TEST] && g->depth_mask;
}

static void STIN_APIENTRY fake_DrawElements(GLenum mode, GLsizei count, GLenum type,
                                            const void *idx)
{
    (void)idx;
    COUNT(DrawElements);
    fake_gl.draw_calls++;
    fake_gl.uint_index_draws += type == GL_UNSIGNED_INT;
    fake_gl.ushort_index_draws += type == GL_UNSIGNED_SHORT;
    fake_gl.patch_draws += mode == GL_PATCHES;
    fake_gl.draws_into_default += fake_gl.gl.draw_framebuffer == 0;
    watched_draw();
    fake_gl.drawn_indices += (unsigned)count;
}

static void STIN_APIENTRY fake_DrawArrays(GLenum mode, GLint first, GLsizei count)
{
    (void)first;
    (void)count;
    COUNT(DrawArrays);
    fake_gl.patch_draws += mode == GL_PATCHES;
    fake_gl.draws_into_default += fake_gl.gl.draw_framebuffer == 0;
    watched_draw();
}

/* ---- object names ------------------------------------------------------- */
static void gen_names(GLsizei n, GLuint *out, unsigned *created)
{
    GLsizei i;
    for (i = 0; i < n; i++)
        out[i] = ++fake_gl.next_name;
    *created += (unsigned)n;
}

static void delete_names(GLsizei n, const GLuint *names, unsigned *deleted)
{
    GLsizei i;
    for (i = 0; i < n; i++) {
        if (names[i])
            (*deleted)++;
        else
            fake_gl.deletes_of_zero++;
    }
}

/* glGen<Kind>s / glDelete<Kind>s: names from one counter, counted; a
 * deleted name is unbound where it was bound (fake_gl_state.c). */
#define FAKE_OBJECTS(kind, counter, obj)                                                \
    static void STIN_APIENTRY fake_Gen##kind(GLsizei n, GLuint *names)                  \
    {                                                                                   \
        COUNT(Gen##kind);                                                               \
        gen_names(n, names, &fake_gl.counter##_created);                                \
    }                                                                                   \
    static void STIN_APIENTRY fake_Delete##kind(GLsizei n, const GLuint *names)         \
    {                                                                                   \
        COUNT(Delete##kind);                                                            \
        delete_names(n, names, &fake_gl.counter##_deleted);                             \
        fake_gl_state_deleted(obj, n, names);                                           \
    }
FAKE_OBJECTS(Textures, textures, FAKE_OBJ_TEXTURE)
FAKE_OBJECTS(Buffers, buffers, FAKE_OBJ_BUFFER)
FAKE_OBJECTS(VertexArrays, vertex_arrays, FAKE_OBJ_VERTEX_ARRAY)
FAKE_OBJECTS(Framebuffers, framebuffers, FAKE_OBJ_FRAMEBUFFER)
FAKE_OBJECTS(TransformFeedbacks, transform_feedbacks, FAKE_OBJ_TRANSFORM_FEEDBACK)

/* glBufferData of GL_ARRAY_BUFFER: the buffer bound, its size and usage
 * and a hash of its bytes (a test compares what was uploaded). */
static void STIN_APIENTRY fake_BufferData(GLenum target, GLsizeiptr size, const void *data,
                                          GLenum usage)
{
    const unsigned char *b = (const unsigned char *)data;
    unsigned long long h = 1469598103934665603ull;
    GLsizeiptr i;
    COUNT(BufferData);
    if (target != GL_ARRAY_BUFFER)
        return;
    for (i = 0; b && i < size; i++)
        h = (h ^ b[i]) * 1099511628211ull;
    fake_gl.array_data.buffer = fake_gl.gl.array_buffer;
    fake_gl.array_data.size = (unsigned long long)size;
    fake_gl.array_data.usage = usage;
    fake_gl.array_data.hash = h;
    fake_gl.array_data.uploads++;
}

/* Queries: names of their own (1, 2, ...), so the other objects' names stay
 * as they were. A GL_TIME_ELAPSED query ending takes what the test's
 * time_elapsed callback says it measured; its result is read back by name.
 * Other queries' results leave the caller's value as it was. */
static void STIN_APIENTRY fake_GenQueries(GLsizei n, GLuint *names)
{
    GLsizei i;
    COUNT(GenQueries);
    for (i = 0; i < n; i++)
        names[i] = ++fake_gl.next_query;
}

static void STIN_APIENTRY fake_BeginQuery(GLenum target, GLuint id)
{
    COUNT(BeginQuery);
    if (target == GL_TIME_ELAPSED) {
        fake_gl.time_queries_begun++;
        fake_gl.active_time_query = id;
    }
}

static void STIN_APIENTRY fake_EndQuery(GLenum target)
{
    GLuint id = fake_gl.active_time_query;
    COUNT(EndQuery);
    if (target != GL_TIME_ELAPSED)
        return;
    if (id && id <= FAKE_GL_MAX_QUERIES)
        fake_gl.query_ns[id - 1] =
            fake_gl.time_elapsed ? fake_gl.time_elapsed(fake_gl.time_elapsed_user) : 0;
    fake_gl.active_time_query = 0;
}

static void STIN_APIENTRY fake_GetQueryObjectuiv(GLuint id, GLenum pname, GLuint *v)
{
    (void)id;
    COUNT(GetQueryObjectuiv);
    if (pname == GL_QUERY_RESULT_AVAILABLE)
        *v = !fake_gl.queries_unavailable;
}

static void STIN_APIENTRY fake_GetQueryObjectui64v(GLuint id, GLenum pname, GLuint64 *v)
{
    COUNT(GetQueryObjectui64v);
    if (pname == GL_QUERY_RESULT && id && id <= FAKE_GL_MAX_QUERIES && fake_gl.time_elapsed) {
        *v = fake_gl.query_ns[id - 1];
        fake_gl.time_results_read++;
    }
}

static void STIN_APIENTRY fake_TexImage2D(GLenum target, GLint level, GLint ifmt, GLsizei w,
                                          GLsizei h, GLint border, GLenum fmt, GLenum type,
                                          const void *pixels)
{
    (void)target;
    (void)ifmt;
    (void)border;
    COUNT(TexImage2D);
    fake_gl.tex_images++;
    if (fake_gl_unpack_loose())
        fake_gl.tex_images_loose++;
    if (level == 0)
        fake_gl.tex_levels = 0;
    if (level >= 0 && level < FAKE_GL_MAX_LEVELS) {
        fake_gl.tex_level_width[level] = w;
        fake_gl.tex_level_height[level] = h;
        if (pixels && fmt == GL_RGBA && type == GL_UNSIGNED_BYTE)
            memcpy(fake_gl.tex_level_first_texel[level], pixels, 4);
        if ((unsigned)level + 1 > fake_gl.tex_levels)
            fake_gl.tex_levels = (unsigned)level + 1;
    }
}

/* A proxy array's width reads back as given when its bytes (16 a texel)
 * are within config.max_array_bytes (0: any), else 0, as GL's proxies do. */
static void STIN_APIENTRY fake_TexImage3D(GLenum target, GLint level, GLint ifmt, GLsizei w,
                                          GLsizei h, GLsizei d, GLint border, GLenum fmt,
                                          GLenum type, const void *pixels)
{
    unsigned long long bytes = 16ull * (unsigned long long)w * (unsigned long long)h * d;
    unsigned long long most = fake_gl.config.max_array_bytes;
    (void)level;
    (void)ifmt;
    (void)border;
    (void)fmt;
    (void)type;
    (void)pixels;
    COUNT(TexImage3D);
    if (target == GL_PROXY_TEXTURE_2D_ARRAY)
        fake_gl.proxy_width = most && bytes > most ? 0 : w;
    else
        fake_gl.array_width = w;
}

static void STIN_APIENTRY fake_GetTexLevelParameteriv(GLenum target, GLint level, GLenum pname,
                                                      GLint *v)
{
    (void)level;
    COUNT(GetTexLevelParameteriv);
    *v = target == GL_PROXY_TEXTURE_2D_ARRAY && pname == GL_TEXTURE_WIDTH ? fake_gl.proxy_width
                                                                          : 0;
}

/* ---- shaders and programs ----------------------------------------------- */
static int *shader_version(GLuint s)
{
    static int none;
    none = 0;
    return s >= 1 && s <= FAKE_GL_MAX_SHADERS ? &fake_gl.shader_version[s - 1] : &none;
}

static int shader_compiles(GLuint s)
{
    int from = fake_gl.config.fail_glsl_from;
    return !(from > 0 && *shader_version(s) >= from);
}

/* Shader and program names come from their own small range so that the
 * per-shader "#version" table can be indexed by name. */
static GLuint STIN_APIENTRY fake_CreateShader(GLenum type)
{
    COUNT(CreateShader);
    fake_gl.shaders_created++;
    if (fake_gl.shaders_created <= FAKE_GL_MAX_PROGRAMS)
        fake_gl.shader_is_tesc[fake_gl.shaders_created - 1] = type == GL_TESS_CONTROL_SHADER;
    return (GLuint)fake_gl.shaders_created; /* 1, 2, ...; > FAKE_GL_MAX_SHADERS: no version kept */
}

static void STIN_APIENTRY fake_ShaderSource(GLuint s, GLsizei n, const GLchar *const *src,
                                            const GLint *len)
{
    GLsizei i;
    (void)len;
    COUNT(ShaderSource);
    for (i = 0; i < n; i++) {
        const char *v = src[i] ? strstr(src[i], "#version") : NULL;
        if (v) {
            int version = 0;
            v += 8;
            while (*v == ' ')
                v++;
            while (*v >= '0' && *v <= '9')
                version = version * 10 + (*v++ - '0');
            *shader_version(s) = version;
            return;
        }
    }
    *shader_version(s) = 110; /* no #version line means GLSL 1.10 */
}

static void STIN_APIENTRY fake_GetShaderiv(GLuint s, GLenum pname, GLint *v)
{
    COUNT(GetShaderiv);
    if (pname == GL_COMPILE_STATUS) {
        *v = shader_compiles(s) ? GL_TRUE : GL_FALSE;
        if (!*v)
            fake_gl.shader_compile_failures++;
    } else {
        *v = 0;
    }
}

static void copy_log(GLsizei size, GLsizei *len, GLchar *log, const char *text)
{
    GLsizei n = 0;
    if (size <= 0)
        return;
    while (text[n] && n + 1 < size) {
        log[n] = text[n];
        n++;
    }
    log[n] = '\0';
    if (len)
        *len = n;
}

static void STIN_APIENTRY fake_GetShaderInfoLog(GLuint s, GLsizei size, GLsizei *len, GLchar *log)
{
    (void)s;
    COUNT(GetShaderInfoLog);
    copy_log(size, len, log, "0:1(10): error: GLSL version not supported by the fake GL");
}

static void STIN_APIENTRY fake_DeleteShader(GLuint s)
{
    COUNT(DeleteShader);
    if (s)
        fake_gl.shaders_deleted++;
    else
        fake_gl.deletes_of_zero++;
}

static GLuint STIN_APIENTRY fake_CreateProgram(void)
{
    COUNT(CreateProgram);
    fake_gl.programs_created++;
    return 1000u + fake_gl.programs_created;
}

static void STIN_APIENTRY fake_AttachShader(GLuint p, GLuint s)
{
    COUNT(AttachShader);
    if (p > 1000u && p - 1001u < FAKE_GL_MAX_PROGRAMS && s >= 1u && s <= FAKE_GL_MAX_PROGRAMS &&
        fake_gl.shader_is_tesc[s - 1u])
        fake_gl.program_has_tesc[p - 1001u] = 1;
}

static void STIN_APIENTRY fake_GetProgramiv(GLuint p, GLenum pname, GLint *v)
{
    COUNT(GetProgramiv);
    if (pname == GL_LINK_STATUS) {
        unsigned from = fake_gl.config.fail_link_from;
        *v = fake_gl.config.fail_link || (from && p - 1000u >= from) ? GL_FALSE : GL_TRUE;
        if (!*v)
            fake_gl.program_link_failures++;
    } else {
        *v = 0;
    }
}

static void STIN_APIENTRY fake_GetProgramInfoLog(GLuint p, GLsizei size, GLsizei *len, GLchar *log)
{
    (void)p;
    COUNT(GetProgramInfoLog);
    copy_log(size, len, log, "error: linking refused by the fake GL");
}

static void STIN_APIENTRY fake_DeleteProgram(GLuint p)
{
    COUNT(DeleteProgram);
    if (p)
        fake_gl.programs_deleted++;
    else
        fake_gl.deletes_of_zero++;
}

/* Framebuffers the library builds are always complete here; the caller's
 * report their configured status. */
static GLenum STIN_APIENTRY fake_CheckFramebufferStatus(GLenum target)
{
    const fake_gl_fbo *f = caller_fbo(fake_gl.gl.draw_framebuffer);
    (void)target;
    COUNT(CheckFramebufferStatus);
    if (f)
        return f->status ? f->status : GL_FRAMEBUFFER_COMPLETE;
    if (fake_gl.gl.draw_framebuffer && fake_gl.config.generated_framebuffer_status)
        return fake_gl.config.generated_framebuffer_status;
    return GL_FRAMEBUFFER_COMPLETE;
}

static GLboolean STIN_APIENTRY fake_IsFramebuffer(GLuint fb)
{
    COUNT(IsFramebuffer);
    return caller_fbo(fb) || (fb && fb <= fake_gl.next_name);
}

static GLboolean STIN_APIENTRY fake_IsEnabled(GLenum cap)
{
    COUNT(IsEnabled);
    return (GLboolean)fake_gl_is_enabled(cap);
}

/* No query of the caller's is active. */
static void STIN_APIENTRY fake_GetQueryiv(GLenum target, GLenum pname, GLint *v)
{
    (void)target;
    (void)pname;
    COUNT(GetQueryiv);
    *v = 0;
}

static GLint STIN_APIENTRY fake_GetUniformLocation(GLuint p, const GLchar *name)
{
    int tesc = p > 1000u && p - 1001u < FAKE_GL_MAX_PROGRAMS && fake_gl.program_has_tesc[p - 1001u];
    COUNT(GetUniformLocation);
    return strncmp(name, "u_tess", 6) == 0 && !tesc ? -1 : 1;
}

/* ---- resolution --------------------------------------------------------- */
typedef void (*fake_any_fn)(void);

static const struct {
    const char *name;
    fake_any_fn fn;
} stubs[] = {
#define FAKE_ENTRY(ret, name, params, need, alt) {"gl" #name, (fake_any_fn)fake_##name},
    STIN_GL_FUNCS(FAKE_ENTRY)
#undef FAKE_ENTRY
};

static int is_missing(const char *name)
{
    const char *const *m = fake_gl.config.missing;
    for (; m && *m; m++)
        if (strcmp(*m, name) == 0)
            return 1;
    return 0;
}

void *fake_gl_get_proc(void *user, const char *name)
{
    size_t i;
    void *p = NULL;
    (void)user;
    if (!name || is_missing(name))
        return NULL;
    for (i = 0; i < sizeof stubs / sizeof stubs[0]; i++)
        if (strcmp(stubs[i].name, name) == 0) {
            memcpy(&p, &stubs[i].fn, sizeof p); /* function -> object pointer, as dlsym does */
            return p;
        }
    return NULL;
}

stin_desc fake_gl_desc(fake_log *log)
{
    stin_desc d;
    memset(&d, 0, sizeof d);
    d.get_proc_address = fake_gl_get_proc;
    if (log) {
        memset(log, 0, sizeof *log);
        d.log = fake_log_fn;
        d.log_user = log;
    }
    return d;
}

void fake_gl_reset(const fake_gl_config *config)
{
    memset(&fake_gl, 0, sizeof fake_gl);
    if (config)
        fake_gl.config = *config;
    fake_gl_state_reset();
}

/* ---- profiles ----------------------------------------------------------- */
#define GL13_EXTS                                                                  \
    "GL_ARB_multitexture GL_ARB_texture_env_combine GL_ARB_texture_env_dot3 "      \
    "GL_ARB_texture_cube_map GL_EXT_separate_specular_color"
#define GL14_EXTS                                                                  \
    GL13_EXTS " GL_ARB_depth_texture GL_ARB_shadow GL_EXT_stencil_wrap "           \
              "GL_EXT_stencil_two_side GL_ARB_depth_clamp"

static const char *const core_extensions[] = {
    "GL_ARB_depth_clamp", "GL_EXT_texture_filter_anisotropic", "GL_ARB_texture_float",
    "GL_ARB_shader_bit_encoding"};

fake_gl_config fake_gl_profile(fake_gl_profile_id id)
{
    fake_gl_config c;
    memset(&c, 0, sizeof c);
    c.stencil_bits = 8;
    c.depth_bits = 24;
    c.max_texture_size = 2048;
    c.max_lights = 8;
    c.max_texture_units = 1;
    switch (id) {
    case FAKE_GL11:
        c.version = "1.1 Mesa 22.3.6";
        c.extensions = "";
        break;
    case FAKE_GL13:
        c.version = "1.3 Mesa 22.3.6";
        c.extensions = GL13_EXTS;
        c.max_texture_units = 4;
        break;
    case FAKE_GL14:
        c.version = "1.4 Mesa 22.3.6";
        c.extensions = GL14_EXTS;
        c.max_texture_units = 4;
        break;
    case FAKE_GL21:
        c.version = "2.1 Mesa 22.3.6";
        c.glsl_version = "1.20";
        c.extensions = GL14_EXTS " GL_ARB_framebuffer_object GL_ARB_texture_float";
        c.max_texture_units = 8;
        c.max_texture_image_units = 16;
        c.max_vertex_texture_units = 16;
        c.max_draw_buffers = 8;
        break;
    case FAKE_GL33_CORE:
    case FAKE_GL45_CORE:
        c.version = id == FAKE_GL33_CORE ? "3.3 (Core Profile) Mesa 22.3.6"
                                         : "4.5 (Core Profile) Mesa 22.3.6";
        c.glsl_version = id == FAKE_GL33_CORE ? "3.30" : "4.50";
        c.extension_list = core_extensions;
        c.extension_count = (int)(sizeof core_extensions / sizeof core_extensions[0]);
        c.core_profile = 1;
        c.max_lights = 0;
        c.max_texture_size = 16384;
        c.max_texture_image_units = 32;
        c.max_vertex_texture_units = 32;
        c.max_draw_buffers = 8;
        c.max_geometry_output_vertices = 256;
        c.max_tess_gen_level = id == FAKE_GL45_CORE ? 64 : 0;
        break;
    }
    return c;
}

/* ---- recording logger --------------------------------------------------- */
/* Lines are stored as "<item number> <message>\n". */
void fake_log_fn(void *user, stin_log_level level, stin_log_item item, const char *message)
{
    fake_log *log = (fake_log *)user;
    char head[8];
    size_t n = 0, i;
    if (!log)
        return;
    if ((unsigned)item < STIN_LOG_ITEM_COUNT)
        log->items[item]++;
    if (level == STIN_LOG_LEVEL_ERROR)
        log->errors++;
    else if (level == STIN_LOG_LEVEL_WARNING)
        log->warnings++;
    else
        log->infos++;
    head[n++] = (char)('0' + (unsigned)item / 10 % 10);
    head[n++] = (char)('0' + (unsigned)item % 10);
    head[n++] = ' ';
    head[n] = '\0';
    if (log->used + 2 >= sizeof log->text)
        return; /* full: counted above, not stored */
    for (i = 0; head[i] && log->used + 2 < sizeof log->text; i++)
        log->text[log->used++] = head[i];
    for (i = 0; message[i] && log->used + 2 < sizeof log->text; i++)
        log->text[log->used++] = message[i];
    log->text[log->used++] = '\n';
    log->text[log->used] = '\0';
}

int fake_log_has(const fake_log *log, stin_log_item item, const char *s)
{
    const char *line = log->text;
    size_t len = strlen(s);
    while (*line) {
        const char *end = strchr(line, '\n'), *p;
        unsigned it = (unsigned)(line[0] - '0') * 10u + (unsigned)(line[1] - '0');
        if (!end)
            end = line + strlen(line);
        if (item == STIN_LOG_ITEM_COUNT || it == (unsigned)item)
            for (p = line + 3; p + len <= end; p++)
                if (strncmp(p, s, len) == 0)
                    return 1;
        line = *end ? end + 1 : end;
    }
    return 0;
}
