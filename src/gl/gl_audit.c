/* SPDX-License-Identifier: MIT */
/* The checked build's OpenGL ES audit: the ES version (or the extension,
 * as a capability) that first has each enum stin passes, and wrappers that
 * check the enum arguments of the calls that take them before the driver
 * sees them. A call or enum the context's ES version (after max_gl_version
 * and the caps mask) lacks is a GL-audit violation naming its call site
 * (gl_violations, STIN_LOG_GL_ERROR), which the image tests fail on. The
 * desktop profiles are audited by capability in load.c, as before. */
#include "internal.h"

typedef int stin__gl_audit_unit; /* ISO C: a translation unit is never empty */

#if defined(STIN_GL_CHECK) && STIN_GL_CHECK

/* Facts from the OpenGL ES 2.0, 3.0, 3.1 and 3.2 specifications (the enums
 * stin uses, not every enum of ES). es: the first ES version with the enum
 * in core, ES_NEVER for desktop-only ones (or ES extensions stin does not
 * map); cap: the capability that brings it to an earlier ES version (the ES
 * 2.0 extensions of caps.c), -1 none. Enums not listed are ES 2.0 core. */
enum { ES_NEVER = 0 };
typedef struct es_enum {
    GLenum e;
    const char *name;
    unsigned char es;
    signed char cap;
    const char *ext; /* an ES extension stin checks for before it passes the enum */
} es_enum;
#define E(v, name, es, cap) {v, name, es, cap, NULL}
#define E_EXT(v, name, ext) {v, name, ES_NEVER, -1, ext}
static const es_enum es_enums[] = {
    /* enables */
    E(0x0DE0, "GL_TEXTURE_1D", ES_NEVER, -1), E(0x864F, "GL_DEPTH_CLAMP", ES_NEVER, -1),
    E(0x0BF2, "GL_COLOR_LOGIC_OP", ES_NEVER, -1), E(0x0B41, "GL_POLYGON_SMOOTH", ES_NEVER, -1),
    E(0x0B20, "GL_LINE_SMOOTH", ES_NEVER, -1), E(0x2A02, "GL_POLYGON_OFFSET_LINE", ES_NEVER, -1),
    E(0x2A01, "GL_POLYGON_OFFSET_POINT", ES_NEVER, -1),
    E(0x3000, "GL_CLIP_DISTANCE0", ES_NEVER, -1), E(0x3001, "GL_CLIP_DISTANCE1", ES_NEVER, -1),
    E(0x3002, "GL_CLIP_DISTANCE2", ES_NEVER, -1), E(0x3003, "GL_CLIP_DISTANCE3", ES_NEVER, -1),
    E(0x3004, "GL_CLIP_DISTANCE4", ES_NEVER, -1), E(0x3005, "GL_CLIP_DISTANCE5", ES_NEVER, -1),
    E(0x3006, "GL_CLIP_DISTANCE6", ES_NEVER, -1), E(0x3007, "GL_CLIP_DISTANCE7", ES_NEVER, -1),
    E(0x8F9D, "GL_PRIMITIVE_RESTART", ES_NEVER, -1),
    E_EXT(0x8DB9, "GL_FRAMEBUFFER_SRGB", "GL_EXT_sRGB_write_control"), E(0x809D, "GL_MULTISAMPLE", ES_NEVER, -1),
    E(0x809F, "GL_SAMPLE_ALPHA_TO_ONE", ES_NEVER, -1),
    E(0x8642, "GL_PROGRAM_POINT_SIZE", ES_NEVER, -1),
    E(0x884F, "GL_TEXTURE_CUBE_MAP_SEAMLESS", ES_NEVER, -1),
    E(0x8C89, "GL_RASTERIZER_DISCARD", 30, -1),
    E(0x8D69, "GL_PRIMITIVE_RESTART_FIXED_INDEX", 30, -1), E(0x8E51, "GL_SAMPLE_MASK", 31, -1),
    /* texture targets */
    E(0x806F, "GL_TEXTURE_3D", 30, -1), E(0x8C1A, "GL_TEXTURE_2D_ARRAY", 30, -1),
    E(0x9100, "GL_TEXTURE_2D_MULTISAMPLE", 31, -1), E(0x9009, "GL_TEXTURE_CUBE_MAP_ARRAY", 32, -1),
    /* buffer and framebuffer targets and their bindings */
    E(0x8CA8, "GL_READ_FRAMEBUFFER", 30, -1), E(0x8CA9, "GL_DRAW_FRAMEBUFFER", 30, -1),
    E(0x8CAA, "GL_READ_FRAMEBUFFER_BINDING", 30, -1),
    E(0x88EB, "GL_PIXEL_PACK_BUFFER", 30, -1), E(0x88EC, "GL_PIXEL_UNPACK_BUFFER", 30, -1),
    E(0x88ED, "GL_PIXEL_PACK_BUFFER_BINDING", 30, -1),
    E(0x88EF, "GL_PIXEL_UNPACK_BUFFER_BINDING", 30, -1),
    E(0x8C8E, "GL_TRANSFORM_FEEDBACK_BUFFER", 30, -1), E(0x8A11, "GL_UNIFORM_BUFFER", 30, -1),
    E(0x8F36, "GL_COPY_READ_BUFFER", 30, -1), E(0x8F37, "GL_COPY_WRITE_BUFFER", 30, -1),
    E(0x90D2, "GL_SHADER_STORAGE_BUFFER", 31, -1),
    E(0x90D3, "GL_SHADER_STORAGE_BUFFER_BINDING", 31, -1),
    E(0x92C0, "GL_ATOMIC_COUNTER_BUFFER", 31, -1), E(0x8F3F, "GL_DRAW_INDIRECT_BUFFER", 31, -1),
    E(0x9192, "GL_QUERY_BUFFER", ES_NEVER, -1), E(0x9193, "GL_QUERY_BUFFER_BINDING", ES_NEVER, -1),
    E(0x85B5, "GL_VERTEX_ARRAY_BINDING", 30, STIN_CAP_VAO),
    E(0x8E22, "GL_TRANSFORM_FEEDBACK", 30, -1), E(0x8E25, "GL_TRANSFORM_FEEDBACK_BINDING", 30, -1),
    E(0x8919, "GL_SAMPLER_BINDING", 30, -1), E(0x825A, "GL_PROGRAM_PIPELINE_BINDING", 31, -1),
    E(0x8C1D, "GL_TEXTURE_BINDING_2D_ARRAY", 30, -1),
    /* queries */
    E(0x8914, "GL_SAMPLES_PASSED", ES_NEVER, -1), E(0x8C2F, "GL_ANY_SAMPLES_PASSED", 30, -1),
    E(0x8D6A, "GL_ANY_SAMPLES_PASSED_CONSERVATIVE", 30, -1),
    E(0x88BF, "GL_TIME_ELAPSED", ES_NEVER, -1), E(0x8E28, "GL_TIMESTAMP", ES_NEVER, -1),
    E(0x8C87, "GL_PRIMITIVES_GENERATED", 32, -1),
    E(0x8C88, "GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN", 30, -1),
    /* primitives and shader stages */
    E(0x000A, "GL_LINES_ADJACENCY", 32, STIN_CAP_GEOMETRY_SHADER),
    E(0x000C, "GL_TRIANGLES_ADJACENCY", 32, STIN_CAP_GEOMETRY_SHADER),
    E(0x000E, "GL_PATCHES", 32, STIN_CAP_TESSELLATION), E(0x0007, "GL_QUADS", ES_NEVER, -1),
    E(0x8DD9, "GL_GEOMETRY_SHADER", 32, STIN_CAP_GEOMETRY_SHADER),
    E(0x8E88, "GL_TESS_CONTROL_SHADER", 32, STIN_CAP_TESSELLATION),
    E(0x8E87, "GL_TESS_EVALUATION_SHADER", 32, STIN_CAP_TESSELLATION),
    E(0x91B9, "GL_COMPUTE_SHADER", 31, -1),
    E(0x8E72, "GL_PATCH_VERTICES", 32, STIN_CAP_TESSELLATION),
    /* pixel store */
    E(0x0D02, "GL_PACK_ROW_LENGTH", 30, -1), E(0x0D03, "GL_PACK_SKIP_ROWS", 30, -1),
    E(0x0D04, "GL_PACK_SKIP_PIXELS", 30, -1), E(0x0CF2, "GL_UNPACK_ROW_LENGTH", 30, -1),
    E(0x0CF3, "GL_UNPACK_SKIP_ROWS", 30, -1), E(0x0CF4, "GL_UNPACK_SKIP_PIXELS", 30, -1),
    E(0x806E, "GL_UNPACK_IMAGE_HEIGHT", 30, -1), E(0x806D, "GL_UNPACK_SKIP_IMAGES", 30, -1),
    E(0x0CF0, "GL_UNPACK_SWAP_BYTES", ES_NEVER, -1), E(0x0CF1, "GL_UNPACK_LSB_FIRST", ES_NEVER, -1),
    E(0x0D00, "GL_PACK_SWAP_BYTES", ES_NEVER, -1), E(0x0D01, "GL_PACK_LSB_FIRST", ES_NEVER, -1),
    E(0x806C, "GL_PACK_IMAGE_HEIGHT", ES_NEVER, -1), E(0x806B, "GL_PACK_SKIP_IMAGES", ES_NEVER, -1),
    /* texture parameters and their values */
    E(0x8072, "GL_TEXTURE_WRAP_R", 30, -1), E(0x813C, "GL_TEXTURE_BASE_LEVEL", 30, -1),
    E(0x813D, "GL_TEXTURE_MAX_LEVEL", 30, -1), E(0x813A, "GL_TEXTURE_MIN_LOD", 30, -1),
    E(0x813B, "GL_TEXTURE_MAX_LOD", 30, -1),
    E(0x884C, "GL_TEXTURE_COMPARE_MODE", 30, STIN_CAP_SHADOW),
    E(0x884D, "GL_TEXTURE_COMPARE_FUNC", 30, STIN_CAP_SHADOW),
    E(0x884E, "GL_COMPARE_REF_TO_TEXTURE", 30, STIN_CAP_SHADOW),
    E(0x884B, "GL_DEPTH_TEXTURE_MODE", ES_NEVER, -1), E(0x8501, "GL_TEXTURE_LOD_BIAS", ES_NEVER, -1),
    E(0x812D, "GL_CLAMP_TO_BORDER", 32, -1), E(0x1004, "GL_TEXTURE_BORDER_COLOR", 32, -1),
    E(0x2900, "GL_CLAMP", ES_NEVER, -1), E(0x8191, "GL_GENERATE_MIPMAP", ES_NEVER, -1),
    /* formats and types */
    E(0x1902, "GL_DEPTH_COMPONENT", 30, STIN_CAP_DEPTH_TEXTURE),
    E(0x81A6, "GL_DEPTH_COMPONENT24", 30, -1), E(0x81A7, "GL_DEPTH_COMPONENT32", ES_NEVER, -1),
    E(0x8CAC, "GL_DEPTH_COMPONENT32F", 30, -1),
    E(0x84F9, "GL_DEPTH_STENCIL", 30, STIN_CAP_PACKED_DEPTH_STENCIL),
    E(0x84FA, "GL_UNSIGNED_INT_24_8", 30, STIN_CAP_PACKED_DEPTH_STENCIL),
    E(0x88F0, "GL_DEPTH24_STENCIL8", 30, STIN_CAP_PACKED_DEPTH_STENCIL),
    E(0x1901, "GL_STENCIL_INDEX", ES_NEVER, -1),
    E(0x8058, "GL_RGBA8", 30, -1), E(0x8051, "GL_RGB8", 30, -1), E(0x8229, "GL_R8", 30, -1),
    E(0x822B, "GL_RG8", 30, -1), E(0x1903, "GL_RED", 30, -1), E(0x8227, "GL_RG", 30, -1),
    E(0x822E, "GL_R32F", 30, -1), E(0x8230, "GL_RG32F", 30, -1), E(0x8814, "GL_RGBA32F", 30, -1),
    E(0x881A, "GL_RGBA16F", 30, -1), E(0x140B, "GL_HALF_FLOAT", 30, -1),
    E(0x8D70, "GL_RGBA32UI", 30, -1), E(0x823C, "GL_RG32UI", 30, -1),
    E(0x8D99, "GL_RGBA_INTEGER", 30, -1), E(0x8228, "GL_RG_INTEGER", 30, -1),
    E(0x8236, "GL_R32UI", 30, -1), E(0x8D94, "GL_RED_INTEGER", 30, -1),
    E(0x8C43, "GL_SRGB8_ALPHA8", 30, -1), E(0x8049, "GL_INTENSITY", ES_NEVER, -1),
    E(0x804B, "GL_INTENSITY8", ES_NEVER, -1), E(0x80E1, "GL_BGRA", ES_NEVER, -1),
    E(0x8367, "GL_UNSIGNED_INT_8_8_8_8_REV", ES_NEVER, -1),
    /* attachments, draw and read buffers */
    E(0x821A, "GL_DEPTH_STENCIL_ATTACHMENT", 30, -1), E(0x8CE1, "GL_COLOR_ATTACHMENT1", 30, -1),
    E(0x8CE2, "GL_COLOR_ATTACHMENT2", 30, -1), E(0x8CE3, "GL_COLOR_ATTACHMENT3", 30, -1),
    /* blending */
    E(0x8007, "GL_MIN", 30, -1), E(0x8008, "GL_MAX", 30, -1),
    /* image access (the barrier bits are no enums: glMemoryBarrier is ES 3.1) */
    E(0x88BA, "GL_READ_WRITE", 31, -1),
    /* queried state and limits */
    E(0x84E2, "GL_MAX_TEXTURE_UNITS", ES_NEVER, -1), E(0x0D32, "GL_MAX_CLIP_PLANES", ES_NEVER, -1),
    E(0x0D31, "GL_MAX_LIGHTS", ES_NEVER, -1), E(0x8824, "GL_MAX_DRAW_BUFFERS", 30, -1),
    E(0x88FF, "GL_MAX_ARRAY_TEXTURE_LAYERS", 30, -1),
    E(0x8CDF, "GL_MAX_COLOR_ATTACHMENTS", 30, -1),
    E(0x8DE0, "GL_MAX_GEOMETRY_OUTPUT_VERTICES", 32, STIN_CAP_GEOMETRY_SHADER),
    E(0x8E7E, "GL_MAX_TESS_GEN_LEVEL", 32, STIN_CAP_TESSELLATION),
    E(0x821D, "GL_NUM_EXTENSIONS", 30, -1), E(0x9126, "GL_CONTEXT_PROFILE_MASK", ES_NEVER, -1),
    E(0x8E4F, "GL_PROVOKING_VERTEX", ES_NEVER, -1), E(0x891C, "GL_CLAMP_READ_COLOR", ES_NEVER, -1),
    E(0x891A, "GL_CLAMP_VERTEX_COLOR", ES_NEVER, -1),
    E(0x891B, "GL_CLAMP_FRAGMENT_COLOR", ES_NEVER, -1), E(0x0B40, "GL_POLYGON_MODE", ES_NEVER, -1),
    E(0x1B01, "GL_LINE (polygon mode)", ES_NEVER, -1),
    E(0x1B02, "GL_FILL (polygon mode)", ES_NEVER, -1)};
#undef E
#undef E_EXT

static const es_enum *es_enum_find(GLenum e)
{
    size_t i;
    for (i = 0; i < sizeof es_enums / sizeof es_enums[0]; i++)
        if (es_enums[i].e == e)
            return &es_enums[i];
    return NULL;
}

int stin__es_enum_version(GLenum e, int *cap)
{
    const es_enum *t = es_enum_find(e);
    *cap = t ? t->cap : -1;
    return t ? t->es : 20;
}

/* The context whose GL() call is under way (stin__gl_check_call sets it,
 * with the call site) for the wrappers below, which see only the driver's
 * arguments. The checked build is a test build: one context a thread at a
 * time, as the tests run. */
static struct {
    stin_context *ctx;
    const char *file;
    int line;
} audit;

void stin__gl_audit_at(stin_context *ctx, const char *file, int line)
{
    audit.ctx = ctx;
    audit.file = file;
    audit.line = line;
}

/* What has the enum, for the message. */
static const char *first_with(const es_enum *t, int es)
{
    if (t && t->ext)
        return t->ext;
    return es == ES_NEVER ? "desktop GL only" : es == 30 ? "ES 3.0" : es == 31 ? "ES 3.1" : "ES 3.2";
}

void stin__gl_audit_enum_es(stin_context *ctx, stin__glfn fn, GLenum e, const char *file, int line)
{
    int cap, es;
    const int version = ctx->caps.gl_major * 10 + ctx->caps.gl_minor;
    const es_enum *t;
    if (!ctx->caps.es)
        return;
    t = es_enum_find(e);
    es = stin__es_enum_version(e, &cap);
    if ((es != ES_NEVER && version >= es) ||
        (cap >= 0 && (ctx->caps.present & STIN_CAP_BIT(cap))) ||
        (t && t->ext && stin_query_extension(ctx, t->ext)))
        return;
    ctx->gl_violations++;
    stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_GL_ERROR,
              "%s(%s 0x%x) at %s:%d: OpenGL ES %d.%d lacks it (%s%s%s)", stin__glfn_name(fn),
              t ? t->name : "?", (unsigned)e, file ? file : "?", line, ctx->caps.gl_major,
              ctx->caps.gl_minor, first_with(t, es), cap >= 0 ? " or " : "",
              cap >= 0 ? stin_cap_name((stin_cap)cap) : "");
}

/* ---- the wrappers: each audits its enum arguments, then calls the driver -- */
#define AUDIT(fn, e) \
    (audit.ctx ? stin__gl_audit_enum_es(audit.ctx, STIN_GLFN_##fn, (e), audit.file, audit.line) \
               : (void)0)
#define DRIVER(fn) (audit.ctx->gl_driver.fn)

static void STIN_APIENTRY w_Enable(GLenum c) { AUDIT(Enable, c); DRIVER(Enable)(c); }
static void STIN_APIENTRY w_Disable(GLenum c) { AUDIT(Disable, c); DRIVER(Disable)(c); }
static GLboolean STIN_APIENTRY w_IsEnabled(GLenum c)
{
    AUDIT(IsEnabled, c);
    return DRIVER(IsEnabled)(c);
}
static void STIN_APIENTRY w_GetIntegerv(GLenum p, GLint *d)
{
    AUDIT(GetIntegerv, p);
    DRIVER(GetIntegerv)(p, d);
}
static void STIN_APIENTRY w_BindTexture(GLenum t, GLuint x)
{
    AUDIT(BindTexture, t);
    DRIVER(BindTexture)(t, x);
}
/* parameters whose value is an enum, audited as one */
static int enum_param(GLenum pname)
{
    return pname == 0x2802 || pname == 0x2803 || pname == 0x8072 || pname == 0x2801 ||
           pname == 0x2800 || pname == 0x884C || pname == 0x884D || pname == 0x884B;
}
static void STIN_APIENTRY w_TexParameteri(GLenum t, GLenum p, GLint v)
{
    AUDIT(TexParameteri, t);
    AUDIT(TexParameteri, p);
    if (enum_param(p))
        AUDIT(TexParameteri, (GLenum)v);
    DRIVER(TexParameteri)(t, p, v);
}
static void STIN_APIENTRY w_TexImage2D(GLenum t, GLint l, GLint ifmt, GLsizei w, GLsizei h,
                                       GLint b, GLenum f, GLenum ty, const void *px)
{
    AUDIT(TexImage2D, t);
    AUDIT(TexImage2D, (GLenum)ifmt);
    AUDIT(TexImage2D, f);
    if (ty != GL_UNSIGNED_INT) /* the depth type: OES_depth_texture's */
        AUDIT(TexImage2D, ty);
    DRIVER(TexImage2D)(t, l, ifmt, w, h, b, f, ty, px);
}
static void STIN_APIENTRY w_TexImage3D(GLenum t, GLint l, GLint ifmt, GLsizei w, GLsizei h,
                                       GLsizei d, GLint b, GLenum f, GLenum ty, const void *px)
{
    AUDIT(TexImage3D, t);
    AUDIT(TexImage3D, (GLenum)ifmt);
    AUDIT(TexImage3D, f);
    AUDIT(TexImage3D, ty);
    DRIVER(TexImage3D)(t, l, ifmt, w, h, d, b, f, ty, px);
}
static void STIN_APIENTRY w_TexStorage2D(GLenum t, GLsizei n, GLenum ifmt, GLsizei w, GLsizei h)
{
    AUDIT(TexStorage2D, t);
    AUDIT(TexStorage2D, ifmt);
    DRIVER(TexStorage2D)(t, n, ifmt, w, h);
}
static void STIN_APIENTRY w_BindImageTexture(GLuint u, GLuint x, GLint l, GLboolean layered,
                                             GLint layer, GLenum access, GLenum f)
{
    AUDIT(BindImageTexture, access);
    AUDIT(BindImageTexture, f);
    DRIVER(BindImageTexture)(u, x, l, layered, layer, access, f);
}
static void STIN_APIENTRY w_PixelStorei(GLenum p, GLint v)
{
    AUDIT(PixelStorei, p);
    DRIVER(PixelStorei)(p, v);
}
static void STIN_APIENTRY w_BindBuffer(GLenum t, GLuint b)
{
    AUDIT(BindBuffer, t);
    DRIVER(BindBuffer)(t, b);
}
static void STIN_APIENTRY w_BindFramebuffer(GLenum t, GLuint f)
{
    AUDIT(BindFramebuffer, t);
    DRIVER(BindFramebuffer)(t, f);
}
static void STIN_APIENTRY w_FramebufferTexture2D(GLenum t, GLenum a, GLenum tt, GLuint x, GLint l)
{
    AUDIT(FramebufferTexture2D, t);
    AUDIT(FramebufferTexture2D, a);
    AUDIT(FramebufferTexture2D, tt);
    DRIVER(FramebufferTexture2D)(t, a, tt, x, l);
}
/* An argument valid in some of its call's slots only, refused in this one. */
static void slot_violation(const char *call, const char *lacks)
{
    audit.ctx->gl_violations++;
    stin__log(audit.ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_GL_ERROR,
              "%s at %s:%d: OpenGL ES %d.%d lacks it (%s)", call, audit.file, audit.line,
              audit.ctx->caps.gl_major, audit.ctx->caps.gl_minor, lacks);
}
static void STIN_APIENTRY w_DrawElements(GLenum m, GLsizei n, GLenum ty, const void *i)
{
    AUDIT(DrawElements, m);
    if (ty == GL_UNSIGNED_INT && audit.ctx && audit.ctx->caps.es &&
        audit.ctx->caps.gl_major < 3 &&
        !(audit.ctx->caps.present & STIN_CAP_BIT(STIN_CAP_ELEMENT_INDEX_UINT)))
        slot_violation("glDrawElements(GL_UNSIGNED_INT)", "ES 3.0 or OES_element_index_uint");
    DRIVER(DrawElements)(m, n, ty, i);
}
static void STIN_APIENTRY w_DrawArrays(GLenum m, GLint f, GLsizei n)
{
    AUDIT(DrawArrays, m);
    DRIVER(DrawArrays)(m, f, n);
}
static void STIN_APIENTRY w_ReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum f,
                                       GLenum ty, void *p)
{
    AUDIT(ReadPixels, f);
    if (ty != GL_UNSIGNED_INT_24_8 || !audit.ctx || !audit.ctx->caps.es) /* NV_read_depth_stencil */
        AUDIT(ReadPixels, ty);
    if (f == GL_DEPTH_COMPONENT && ty == GL_FLOAT && audit.ctx && audit.ctx->caps.es)
        slot_violation("glReadPixels(GL_DEPTH_COMPONENT, GL_FLOAT)",
                       "ES reads depth as GL_DEPTH_STENCIL words, NV_read_depth_stencil");
    DRIVER(ReadPixels)(x, y, w, h, f, ty, p);
}
static void STIN_APIENTRY w_BlendEquation(GLenum m)
{
    AUDIT(BlendEquation, m);
    DRIVER(BlendEquation)(m);
}
static void STIN_APIENTRY w_BeginQuery(GLenum t, GLuint id)
{
    AUDIT(BeginQuery, t);
    DRIVER(BeginQuery)(t, id);
}
static void STIN_APIENTRY w_EndQuery(GLenum t) { AUDIT(EndQuery, t); DRIVER(EndQuery)(t); }
static void STIN_APIENTRY w_ReadBuffer(GLenum b) { AUDIT(ReadBuffer, b); DRIVER(ReadBuffer)(b); }
static GLuint STIN_APIENTRY w_CreateShader(GLenum t)
{
    AUDIT(CreateShader, t);
    return DRIVER(CreateShader)(t);
}
static void STIN_APIENTRY w_BindBufferBase(GLenum t, GLuint i, GLuint b)
{
    AUDIT(BindBufferBase, t);
    DRIVER(BindBufferBase)(t, i, b);
}
static void STIN_APIENTRY w_PatchParameteri(GLenum p, GLint v)
{
    AUDIT(PatchParameteri, p);
    DRIVER(PatchParameteri)(p, v);
}

void stin__gl_audit_install(stin_context *ctx)
{
    ctx->gl_driver = ctx->gl;
    if (!ctx->caps.es)
        return;
#define WRAP(fn) \
    if (ctx->gl.fn) \
        ctx->gl.fn = w_##fn;
    WRAP(Enable) WRAP(Disable) WRAP(IsEnabled) WRAP(GetIntegerv) WRAP(BindTexture)
    WRAP(TexParameteri) WRAP(TexImage2D) WRAP(TexImage3D) WRAP(PixelStorei) WRAP(BindBuffer)
    WRAP(BindFramebuffer) WRAP(FramebufferTexture2D) WRAP(DrawElements) WRAP(DrawArrays)
    WRAP(ReadPixels) WRAP(BlendEquation) WRAP(BeginQuery) WRAP(EndQuery) WRAP(ReadBuffer)
    WRAP(CreateShader) WRAP(BindBufferBase) WRAP(PatchParameteri)
    WRAP(TexStorage2D) WRAP(BindImageTexture)
#undef WRAP
    audit.ctx = ctx;
}

void stin__gl_audit_forget(stin_context *ctx)
{
    if (audit.ctx == ctx)
        audit.ctx = NULL;
}

#endif
