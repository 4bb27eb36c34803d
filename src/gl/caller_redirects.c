/* SPDX-License-Identifier: MIT */
/* Caller state that redirects stin's own GL work rather than changing a
 * pass: a bound pixel unpack or pack buffer (a texture's allocation or a
 * read-back becomes an offset into it), a query buffer (query results go
 * into it), a program pipeline object (draws with program 0 go through
 * it), fragment and read colour clamping (float targets clamp), the
 * provoking vertex, and the caller's active queries (stin's own begin on
 * the target fails). stin_create and each frame set these aside and give
 * them back; a frame also gives back what a pass changes but the header
 * does not list (depth clamp, polygon offset fill, the stencil clear value,
 * 2D-array bindings), and turns sRGB encoding off for a frame whose output
 * is data (normal, visibility): GL would encode it like a colour. */
#include "internal.h"

#define PIXEL_PACK_BUFFER 0x88EB
#define PIXEL_UNPACK_BUFFER 0x88EC
#define PIXEL_PACK_BUFFER_BINDING 0x88ED
#define PIXEL_UNPACK_BUFFER_BINDING 0x88EF
#define QUERY_BUFFER 0x9192
#define QUERY_BUFFER_BINDING 0x9193
#define PROGRAM_PIPELINE_BINDING 0x825A
#define PROVOKING_VERTEX 0x8E4F
#define LAST_VERTEX_CONVENTION 0x8E4E
#define CLAMP_FRAGMENT_COLOR 0x891B
#define CLAMP_READ_COLOR 0x891C
#define FIXED_ONLY 0x891D
#define CURRENT_QUERY 0x8865
#define ANY_SAMPLES_PASSED 0x8C2F
#define ANY_SAMPLES_PASSED_CONSERVATIVE 0x8D6A
#define STENCIL_CLEAR_VALUE 0x0B91
#define TEXTURE_BINDING_2D_ARRAY 0x8C1D
#define ARRAY_BUFFER_BINDING 0x8894
#define VERTEX_ARRAY_BINDING 0x85B5
#define FRAMEBUFFER_SRGB 0x8DB9

static int version(const stin_context *ctx) { return ctx->caps.gl_major * 10 + ctx->caps.gl_minor; }

static int has(const stin_context *ctx, stin_cap cap)
{
    return (ctx->caps.present & STIN_CAP_BIT(cap)) != 0;
}

static int loaded(const stin_context *ctx, stin__glfn fn) { return ctx->gl_loaded[fn]; }

/* Each state is queried only where the version or an extension defines it. */
void stin__caller_detect(stin_context *ctx)
{
    unsigned h = 0;
    int v = version(ctx);
    if (has(ctx, STIN_CAP_VBO) && v >= 21)
        h |= STIN__CALLER_PIXEL_BUFFERS;
    if (has(ctx, STIN_CAP_VBO) &&
        (v >= 44 || stin_query_extension(ctx, "GL_ARB_query_buffer_object")))
        h |= STIN__CALLER_QUERY_BUFFER;
    if (loaded(ctx, STIN_GLFN_BindProgramPipeline) && has(ctx, STIN_CAP_GLSL) &&
        (v >= 41 || stin_query_extension(ctx, "GL_ARB_separate_shader_objects")))
        h |= STIN__CALLER_PIPELINE;
    if (loaded(ctx, STIN_GLFN_ClampColor) &&
        (v >= 30 || stin_query_extension(ctx, "GL_ARB_color_buffer_float")))
        h |= STIN__CALLER_CLAMP;
    if (loaded(ctx, STIN_GLFN_ProvokingVertex) &&
        (v >= 32 || stin_query_extension(ctx, "GL_ARB_provoking_vertex") ||
         stin_query_extension(ctx, "GL_EXT_provoking_vertex")))
        h |= STIN__CALLER_PROVOKING;
    if (loaded(ctx, STIN_GLFN_GetQueryiv) && has(ctx, STIN_CAP_OCCLUSION_QUERY))
        h |= STIN__CALLER_QUERIES;
    /* on ES the switch is EXT_sRGB_write_control's (WebGL 2 has none) */
    if (ctx->caps.es ? stin_query_extension(ctx, "GL_EXT_sRGB_write_control")
                     : v >= 30 || stin_query_extension(ctx, "GL_ARB_framebuffer_sRGB") ||
                           stin_query_extension(ctx, "GL_EXT_framebuffer_sRGB"))
        h |= STIN__CALLER_SRGB;
    ctx->caller_has = h;
}

static void unbind_buffer(stin_context *ctx, GLenum binding, GLenum target, GLint *saved)
{
    GL(ctx, GetIntegerv)(binding, saved);
    if (*saved)
        GL(ctx, BindBuffer)(target, 0);
}

static void set_if(stin_context *ctx, GLenum pname, GLint *saved, GLint want,
                   void (*set)(stin_context *, GLenum, GLint))
{
    GL(ctx, GetIntegerv)(pname, saved);
    if (*saved != want)
        set(ctx, pname, want);
}

static void clamp(stin_context *ctx, GLenum pname, GLint v) { GL(ctx, ClampColor)(pname, (GLenum)v); }
static void provoking(stin_context *ctx, GLenum pname, GLint v)
{
    (void)pname;
    GL(ctx, ProvokingVertex)((GLenum)v);
}

void stin__redirects_begin(stin_context *ctx, stin__redirects *s)
{
    unsigned h = ctx->caller_has;
    stin__memzero(s, sizeof *s);
    s->clamp_fragment = s->clamp_read = FIXED_ONLY;
    s->provoking = LAST_VERTEX_CONVENTION;
    if (h & STIN__CALLER_PIXEL_BUFFERS) {
        unbind_buffer(ctx, PIXEL_UNPACK_BUFFER_BINDING, PIXEL_UNPACK_BUFFER, &s->unpack_buffer);
        unbind_buffer(ctx, PIXEL_PACK_BUFFER_BINDING, PIXEL_PACK_BUFFER, &s->pack_buffer);
    }
    if (h & STIN__CALLER_QUERY_BUFFER)
        unbind_buffer(ctx, QUERY_BUFFER_BINDING, QUERY_BUFFER, &s->query_buffer);
    if (h & STIN__CALLER_PIPELINE) {
        /* a current program hides the bound pipeline (Mesa reads 0), which
         * comes back when the program is 0 */
        GLint program = 0;
        GL(ctx, GetIntegerv)(GL_CURRENT_PROGRAM, &program);
        if (program)
            GL(ctx, UseProgram)(0);
        GL(ctx, GetIntegerv)(PROGRAM_PIPELINE_BINDING, &s->pipeline);
        if (s->pipeline)
            GL(ctx, BindProgramPipeline)(0);
        if (program)
            GL(ctx, UseProgram)((GLuint)program);
    }
    if (h & STIN__CALLER_CLAMP) {
        if (has(ctx, STIN_CAP_FIXED_FUNCTION)) /* not in core profiles */
            set_if(ctx, CLAMP_FRAGMENT_COLOR, &s->clamp_fragment, FIXED_ONLY, clamp);
        set_if(ctx, CLAMP_READ_COLOR, &s->clamp_read, FIXED_ONLY, clamp);
    }
    if (h & STIN__CALLER_PROVOKING)
        set_if(ctx, PROVOKING_VERTEX, &s->provoking, LAST_VERTEX_CONVENTION, provoking);
}

void stin__redirects_end(stin_context *ctx, const stin__redirects *s)
{
    if (s->unpack_buffer)
        GL(ctx, BindBuffer)(PIXEL_UNPACK_BUFFER, (GLuint)s->unpack_buffer);
    if (s->pack_buffer)
        GL(ctx, BindBuffer)(PIXEL_PACK_BUFFER, (GLuint)s->pack_buffer);
    if (s->query_buffer)
        GL(ctx, BindBuffer)(QUERY_BUFFER, (GLuint)s->query_buffer);
    if (s->pipeline)
        GL(ctx, BindProgramPipeline)((GLuint)s->pipeline);
    if (s->clamp_fragment != FIXED_ONLY)
        clamp(ctx, CLAMP_FRAGMENT_COLOR, s->clamp_fragment);
    if (s->clamp_read != FIXED_ONLY)
        clamp(ctx, CLAMP_READ_COLOR, s->clamp_read);
    if (s->provoking != LAST_VERTEX_CONVENTION)
        provoking(ctx, PROVOKING_VERTEX, s->provoking);
}

/* ---- stin_create: the bindings its set-up makes ----------------------------- */
void stin__create_bindings_save(stin_context *ctx, stin__create_bindings *s)
{
    stin__memzero(s, sizeof *s);
    if (has(ctx, STIN_CAP_VAO))
        GL(ctx, GetIntegerv)(VERTEX_ARRAY_BINDING, &s->vao);
    if (has(ctx, STIN_CAP_VBO))
        GL(ctx, GetIntegerv)(ARRAY_BUFFER_BINDING, &s->array_buffer);
    s->unit = GL_TEXTURE0;
    if (has(ctx, STIN_CAP_MULTITEXTURE)) {
        GL(ctx, GetIntegerv)(GL_ACTIVE_TEXTURE, &s->unit);
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    }
    GL(ctx, GetIntegerv)(GL_TEXTURE_BINDING_2D, &s->texture_2d);
    if (version(ctx) >= 30)
        GL(ctx, GetIntegerv)(TEXTURE_BINDING_2D_ARRAY, &s->texture_2d_array);
    if (has(ctx, STIN_CAP_TEXTURE_CUBE_MAP))
        GL_ENUM(ctx, GetIntegerv, GL_TEXTURE_BINDING_CUBE_MAP)(GL_TEXTURE_BINDING_CUBE_MAP,
                                                              &s->texture_cube);
    stin__redirects_begin(ctx, &s->redirects);
}

void stin__create_bindings_restore(stin_context *ctx, const stin__create_bindings *s)
{
    stin__redirects_end(ctx, &s->redirects);
    if (has(ctx, STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, (GLuint)s->texture_2d);
    if (version(ctx) >= 30)
        GL_ENUM(ctx, BindTexture, GL_TEXTURE_2D_ARRAY)(GL_TEXTURE_2D_ARRAY,
                                                      (GLuint)s->texture_2d_array);
    if (has(ctx, STIN_CAP_TEXTURE_CUBE_MAP))
        GL_ENUM(ctx, BindTexture, GL_TEXTURE_CUBE_MAP)(GL_TEXTURE_CUBE_MAP,
                                                      (GLuint)s->texture_cube);
    if (has(ctx, STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)((GLenum)s->unit);
    if (has(ctx, STIN_CAP_VAO))
        GL(ctx, BindVertexArray)((GLuint)s->vao);
    if (has(ctx, STIN_CAP_VBO))
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, (GLuint)s->array_buffer);
}

/* ---- a frame: what its passes change beyond the header's list ------------------ */
/* GL_TEXTURE_2D_ARRAY bindings: GLSL frames bind arrays on these units at most. */
static int array_units(const stin_context *ctx)
{
    int n = ctx->caps.max_texture_image_units;
    if (version(ctx) < 30 || !has(ctx, STIN_CAP_GLSL))
        return 0;
    n = n < STIN__CALLER_ARRAY_UNITS ? n : STIN__CALLER_ARRAY_UNITS;
    return has(ctx, STIN_CAP_MULTITEXTURE) ? n : (n > 0);
}

static void busy_queries(stin_context *ctx)
{
    static const struct {
        GLenum target;
        int version;
        unsigned bit;
    } targets[] = {{GL_SAMPLES_PASSED, 15, STIN__QUERY_SAMPLES},
                   {ANY_SAMPLES_PASSED, 33, STIN__QUERY_SAMPLES},
                   {ANY_SAMPLES_PASSED_CONSERVATIVE, 43, STIN__QUERY_SAMPLES},
                   {GL_PRIMITIVES_GENERATED, 30, STIN__QUERY_PRIMITIVES},
                   {GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, 30, STIN__QUERY_FEEDBACK},
                   {GL_TIME_ELAPSED, 33, STIN__QUERY_TIME}};
    size_t i;
    ctx->queries_busy = 0;
    if (!(ctx->caller_has & STIN__CALLER_QUERIES))
        return;
    for (i = 0; i < sizeof targets / sizeof targets[0]; i++) {
        GLint current = 0;
        if (version(ctx) < targets[i].version)
            continue;
        GL(ctx, GetQueryiv)(targets[i].target, CURRENT_QUERY, &current);
        if (current)
            ctx->queries_busy |= targets[i].bit;
    }
}

void stin__caller_frame_begin(stin_context *ctx, stin__caller_frame *s)
{
    int u, n = array_units(ctx);
    stin__redirects_begin(ctx, &s->redirects);
    busy_queries(ctx);
    s->depth_clamp = has(ctx, STIN_CAP_DEPTH_CLAMP) &&
                     GL_ENUM(ctx, IsEnabled, GL_DEPTH_CLAMP)(GL_DEPTH_CLAMP);
    s->offset_fill = GL(ctx, IsEnabled)(GL_POLYGON_OFFSET_FILL) != 0;
    s->srgb = (ctx->caller_has & STIN__CALLER_SRGB) && ctx->frame.output != STIN_OUTPUT_BEAUTY &&
              GL(ctx, IsEnabled)(FRAMEBUFFER_SRGB);
    if (s->srgb)
        GL(ctx, Disable)(FRAMEBUFFER_SRGB);
    GL(ctx, GetIntegerv)(STENCIL_CLEAR_VALUE, &s->clear_stencil);
    for (u = 0; u < n; u++) {
        if (has(ctx, STIN_CAP_MULTITEXTURE))
            GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + u));
        GL(ctx, GetIntegerv)(TEXTURE_BINDING_2D_ARRAY, &s->arrays[u]);
    }
    if (n && has(ctx, STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
}

/* After the header's list is applied. Every unit the caller had an array
 * on gets it again: a module may bind and empty a unit mid-frame. */
void stin__caller_frame_end(stin_context *ctx, const stin__caller_frame *s)
{
    int u, n = array_units(ctx);
    for (u = 0; u < n; u++) {
        if (!s->arrays[u])
            continue;
        if (has(ctx, STIN_CAP_MULTITEXTURE))
            GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + u));
        GL_ENUM(ctx, BindTexture, GL_TEXTURE_2D_ARRAY)(GL_TEXTURE_2D_ARRAY, (GLuint)s->arrays[u]);
    }
    if (n && has(ctx, STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    if (s->depth_clamp)
        GL_ENABLE(ctx, GL_DEPTH_CLAMP);
    if (s->offset_fill)
        GL(ctx, Enable)(GL_POLYGON_OFFSET_FILL);
    if (s->srgb)
        GL(ctx, Enable)(FRAMEBUFFER_SRGB);
    GL(ctx, ClearStencil)(s->clear_stencil);
    ctx->queries_busy = 0;
    stin__redirects_end(ctx, &s->redirects);
}

int stin__query_begin(stin_context *ctx, unsigned which, GLenum target, GLuint id)
{
    if (ctx->queries_busy & which)
        return 0;
    GL_ENUM(ctx, BeginQuery, target)(target, id);
    return 1;
}
