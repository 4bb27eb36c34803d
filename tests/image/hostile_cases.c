/* SPDX-License-Identifier: MIT */
/* The caller states of the hostile-state test (issue 13 item 19): state an
 * application may leave set when it calls stin_end_frame, each with how to
 * set it, how to undo it, and what the header's GL STATE promises it reads
 * after the frame. */
#include "hostile_cases.h"

#include <stdio.h>
#include <string.h>

static const GLfloat red[4] = {1, 0, 0, 1};

/* ---- after-frame checks --------------------------------------------------------- */
static int enabled_is(hostile_env *e, GLenum cap, int want, char *got, size_t size)
{
    int on = e->gl->IsEnabled(cap) != 0;
    if (on != want)
        snprintf(got, size, "0x%04x is %s", (unsigned)cap, on ? "on" : "off");
    return on == want;
}

static int int_is(hostile_env *e, GLenum pname, GLint want, char *got, size_t size)
{
    GLint v[4] = {0, 0, 0, 0};
    e->gl->GetIntegerv(pname, v);
    if (e->gl->GetError() != GL_NO_ERROR)
        return 1; /* not queryable on this context: the image decides */
    if (v[0] != want)
        snprintf(got, size, "0x%04x reads 0x%x, not 0x%x", (unsigned)pname, (unsigned)v[0],
                 (unsigned)want);
    return v[0] == want;
}

static int float_is(hostile_env *e, GLenum pname, const GLfloat *want, int n, char *got,
                    size_t size)
{
    GLfloat v[16];
    int i;
    memset(v, 0, sizeof v);
    e->gl->GetFloatv(pname, v);
    for (i = 0; i < n; i++)
        if (v[i] != want[i]) {
            snprintf(got, size, "0x%04x[%d] reads %g, not %g", (unsigned)pname, i, v[i],
                     want[i]);
            return 0;
        }
    return 1;
}

/* ---- enables: on with a hostile setting; off (GL's default) or the caller's after -- */
typedef struct enable_case {
    GLenum cap;
    int kept; /* after the frame: 0 off, 1 the caller's (on), 2 the caller's on GL1 only */
} enable_case;

static const enable_case enable_cases[] = {
    {GL_COLOR_LOGIC_OP, 0}, {GL_POLYGON_OFFSET_FILL, 1}, {GL_SCISSOR_TEST, 0},
    {GL_STENCIL_TEST, 0},   {GL_DEPTH_TEST, 0},          {GL_BLEND, 0},
    {GL_CULL_FACE, 0},      {GL_POLYGON_SMOOTH, 0},      {GL_PRIMITIVE_RESTART, 0},
    {GL_PRIMITIVE_RESTART_FIXED_INDEX, 0}, {GL_RASTERIZER_DISCARD, 0}, {GL_DEPTH_CLAMP, 1},
    {GL_CLIP_PLANE0, 0},    {GL_ALPHA_TEST, 0},          {GL_POLYGON_STIPPLE, 0},
    {GL_FOG, 1},            {GL_COLOR_MATERIAL, 1},      {GL_LIGHT5, 1},
    {GL_TEXTURE_GEN_S, 1}};

static const enable_case *enable_of(GLenum cap)
{
    size_t i;
    for (i = 0; i < sizeof enable_cases / sizeof enable_cases[0]; i++)
        if (enable_cases[i].cap == cap)
            return &enable_cases[i];
    return NULL;
}

static int after_enable(hostile_env *e, GLenum cap, char *got, size_t size)
{
    const enable_case *c = enable_of(cap);
    int want = c->kept == 1 || (c->kept == 2 && e->gl1);
    return enabled_is(e, cap, want, got, size);
}

/* ---- the cases -------------------------------------------------------------------- */
static void set_logic_op(hostile_env *e) { e->gl->LogicOp(GL_INVERT); }
static void reset_logic_op(hostile_env *e) { e->gl->LogicOp(GL_COPY); }
static void set_offset(hostile_env *e) { e->gl->PolygonOffset(0.0f, -65536.0f); }
static void reset_offset(hostile_env *e) { e->gl->PolygonOffset(0.0f, 0.0f); }
static void set_scissor(hostile_env *e) { e->gl->Scissor(0, 0, 16, 16); }
static void reset_scissor(hostile_env *e) { e->gl->Scissor(0, 0, e->width, e->height); }

static void set_stencil(hostile_env *e)
{
    e->gl->StencilFunc(GL_NEVER, 1, 0xffu);
    e->gl->StencilMask(0u);
}

static void reset_stencil(hostile_env *e)
{
    e->gl->StencilFunc(GL_ALWAYS, 0, 0xffffffffu);
    e->gl->StencilMask(0xffffffffu);
}

static void set_depth(hostile_env *e)
{
    e->gl->DepthFunc(GL_GREATER);
    e->gl->DepthMask(GL_FALSE);
}

static void reset_depth(hostile_env *e)
{
    e->gl->DepthFunc(GL_LESS);
    e->gl->DepthMask(GL_TRUE);
}

static void set_blend(hostile_env *e) { e->gl->BlendFunc(GL_ZERO, GL_ONE); }
static void reset_blend(hostile_env *e) { e->gl->BlendFunc(GL_ONE, GL_ZERO); }

static void set_cull(hostile_env *e)
{
    e->gl->CullFace(GL_FRONT);
    e->gl->FrontFace(GL_CW);
}

static void reset_cull(hostile_env *e)
{
    e->gl->CullFace(GL_BACK);
    e->gl->FrontFace(GL_CCW);
}

static void set_restart(hostile_env *e) { e->gl->PrimitiveRestartIndex(0); }

static void set_clip(hostile_env *e)
{
    static const GLdouble half[4] = {1, 0, 0, 0};
    if (e->compat)
        e->gl->ClipPlane(GL_CLIP_PLANE0, half);
}

static void set_alpha_test(hostile_env *e) { e->gl->AlphaFunc(GL_GREATER, 0.99f); }
static void reset_alpha_test(hostile_env *e) { e->gl->AlphaFunc(GL_ALWAYS, 0.0f); }

static void stipple(hostile_env *e, GLubyte bits)
{
    GLubyte mask[128];
    memset(mask, bits, sizeof mask);
    e->gl->PolygonStipple(mask);
}

static void set_stipple(hostile_env *e) { stipple(e, 0x00); }
static void reset_stipple(hostile_env *e) { stipple(e, 0xff); }

static void set_fog(hostile_env *e)
{
    e->gl->Fogi(GL_FOG_MODE, GL_LINEAR);
    e->gl->Fogf(GL_FOG_START, 0.0f);
    e->gl->Fogf(GL_FOG_END, 0.001f);
    e->gl->Fogfv(GL_FOG_COLOR, red);
}

static void reset_fog(hostile_env *e)
{
    static const GLfloat none[4] = {0, 0, 0, 0};
    e->gl->Fogi(GL_FOG_MODE, GL_EXP);
    e->gl->Fogf(GL_FOG_END, 1.0f);
    e->gl->Fogfv(GL_FOG_COLOR, none);
}

static void set_color_material(hostile_env *e)
{
    e->gl->ColorMaterial(GL_FRONT_AND_BACK, GL_EMISSION);
    e->gl->Color4f(1.0f, 0.0f, 0.0f, 1.0f);
}

static void reset_color_material(hostile_env *e)
{
    static const GLfloat black[4] = {0, 0, 0, 1};
    e->gl->ColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    e->gl->Color4f(1.0f, 1.0f, 1.0f, 1.0f);
    e->gl->Materialfv(GL_FRONT_AND_BACK, GL_EMISSION, black);
}

static void set_light5(hostile_env *e)
{
    static const GLfloat above[4] = {0, 1, 0, 0};
    e->gl->Lightfv(GL_LIGHT5, GL_DIFFUSE, red);
    e->gl->Lightfv(GL_LIGHT5, GL_AMBIENT, red);
    e->gl->Lightfv(GL_LIGHT5, GL_POSITION, above);
}

static void reset_light5(hostile_env *e)
{
    static const GLfloat black[4] = {0, 0, 0, 1};
    e->gl->Lightfv(GL_LIGHT5, GL_DIFFUSE, black);
    e->gl->Lightfv(GL_LIGHT5, GL_AMBIENT, black);
}

static void set_texgen(hostile_env *e) { e->gl->TexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR); }
static void reset_texgen(hostile_env *e) { e->gl->TexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR); }

/* blend equation */
static void set_blend_max(hostile_env *e) { e->gl->BlendEquation(GL_MAX); }
static void reset_blend_max(hostile_env *e) { e->gl->BlendEquation(GL_FUNC_ADD); }
static int after_blend_max(hostile_env *e, char *got, size_t size)
{
    return int_is(e, GL_BLEND_EQUATION, GL_FUNC_ADD, got, size);
}

/* polygon mode */
static void set_lines(hostile_env *e) { e->gl->PolygonMode(GL_FRONT_AND_BACK, GL_LINE); }
static void reset_lines(hostile_env *e) { e->gl->PolygonMode(GL_FRONT_AND_BACK, GL_FILL); }
static int after_lines(hostile_env *e, char *got, size_t size)
{
    return int_is(e, GL_POLYGON_MODE, GL_FILL, got, size);
}

/* depth range */
static void set_range(hostile_env *e) { e->gl->DepthRange(0.25, 0.75); }
static void reset_range(hostile_env *e) { e->gl->DepthRange(0.0, 1.0); }
static int after_range(hostile_env *e, char *got, size_t size)
{
    static const GLfloat full[2] = {0, 1};
    return float_is(e, GL_DEPTH_RANGE, full, 2, got, size);
}

/* colour mask */
static void set_mask(hostile_env *e) { e->gl->ColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE); }
static void reset_mask(hostile_env *e) { e->gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE); }
static int after_mask(hostile_env *e, char *got, size_t size)
{
    static const GLfloat all[4] = {1, 1, 1, 1};
    return float_is(e, GL_COLOR_WRITEMASK, all, 4, got, size);
}

/* sampler objects with nearest filtering and clamping on the first units */
#define SAMPLER_UNITS 8
static void set_samplers(hostile_env *e)
{
    int u;
    for (u = 0; u < SAMPLER_UNITS; u++)
        e->gl->BindSampler((GLuint)u, e->sampler);
}

static void reset_samplers(hostile_env *e)
{
    int u;
    for (u = 0; u < SAMPLER_UNITS; u++)
        e->gl->BindSampler((GLuint)u, 0);
}

static int after_samplers(hostile_env *e, char *got, size_t size)
{
    int u, ok = 1;
    for (u = 0; u < SAMPLER_UNITS && ok; u++) {
        e->gl->ActiveTexture((GLenum)(GL_TEXTURE0 + u));
        ok = int_is(e, GL_SAMPLER_BINDING, 0, got, size);
    }
    e->gl->ActiveTexture(GL_TEXTURE0);
    return ok;
}

/* a bound GLSL program */
static void set_program(hostile_env *e) { e->gl->UseProgram(e->program); }
static void reset_program(hostile_env *e) { e->gl->UseProgram(0); }
static int after_program(hostile_env *e, char *got, size_t size)
{
    return int_is(e, GL_CURRENT_PROGRAM, 0, got, size);
}

/* the active texture unit */
static void set_unit3(hostile_env *e) { e->gl->ActiveTexture(GL_TEXTURE3); }
static void reset_unit3(hostile_env *e) { e->gl->ActiveTexture(GL_TEXTURE0); }
static int after_unit3(hostile_env *e, char *got, size_t size)
{
    return int_is(e, GL_ACTIVE_TEXTURE, GL_TEXTURE0, got, size);
}

/* a red texture enabled on the fixed-function units 0-3 */
static void units_textured(hostile_env *e, int on)
{
    int u;
    for (u = 0; u < e->fixed_units && u < 4; u++) {
        e->gl->ActiveTexture((GLenum)(GL_TEXTURE0 + u));
        e->gl->BindTexture(GL_TEXTURE_2D, on ? e->texture : 0);
        if (on)
            e->gl->Enable(GL_TEXTURE_2D);
        else
            e->gl->Disable(GL_TEXTURE_2D);
    }
    e->gl->ActiveTexture(GL_TEXTURE0);
}

static void set_textures(hostile_env *e) { units_textured(e, 1); }
static void reset_textures(hostile_env *e) { units_textured(e, 0); }
static int after_textures(hostile_env *e, char *got, size_t size)
{
    int ok;
    if (e->fixed_units < 2) /* unit 0's binding is documented as emptied */
        return enabled_is(e, GL_TEXTURE_2D, 1, got, size);
    /* enables are the caller's; GL1 gives unit 1's binding back (GLSL
     * techniques empty the units they use) */
    e->gl->ActiveTexture(GL_TEXTURE1);
    ok = enabled_is(e, GL_TEXTURE_2D, 1, got, size) &&
         (!e->gl1 || int_is(e, GL_TEXTURE_BINDING_2D, (GLint)e->texture, got, size));
    e->gl->ActiveTexture(GL_TEXTURE0);
    return ok;
}

/* unit 0's texture matrix */
static void texture_matrix(hostile_env *e, GLfloat scale)
{
    GLfloat m[16] = {0};
    m[0] = m[5] = m[10] = scale;
    m[15] = 1.0f;
    e->gl->MatrixMode(GL_TEXTURE);
    e->gl->LoadMatrixf(m);
    e->gl->MatrixMode(GL_MODELVIEW);
}

static void set_matrix(hostile_env *e) { texture_matrix(e, 4.0f); }
static void reset_matrix(hostile_env *e) { texture_matrix(e, 1.0f); }
static int after_matrix(hostile_env *e, char *got, size_t size)
{
    static const GLfloat four = 4.0f;
    return float_is(e, GL_TEXTURE_MATRIX, &four, 1, got, size);
}

/* a colour array left enabled */
static void set_colors(hostile_env *e)
{
    e->gl->ColorPointer(4, GL_FLOAT, 0, e->colors);
    e->gl->EnableClientState(GL_COLOR_ARRAY);
}

static void reset_colors(hostile_env *e) { e->gl->DisableClientState(GL_COLOR_ARRAY); }
static int after_colors(hostile_env *e, char *got, size_t size)
{
    return enabled_is(e, GL_COLOR_ARRAY, !e->gl1, got, size); /* GL1 disables client arrays */
}

/* pixel transfer (the GL1 maps' copies without FBOs) */
static void set_transfer(hostile_env *e)
{
    e->gl->PixelTransferf(GL_DEPTH_SCALE, 0.5f);
    e->gl->PixelTransferf(GL_RED_SCALE, 0.5f);
}

static void reset_transfer(hostile_env *e)
{
    e->gl->PixelTransferf(GL_DEPTH_SCALE, 1.0f);
    e->gl->PixelTransferf(GL_RED_SCALE, 1.0f);
}

static int after_transfer(hostile_env *e, char *got, size_t size)
{
    static const GLfloat half = 0.5f;
    return float_is(e, GL_DEPTH_SCALE, &half, 1, got, size);
}

/* the caller's storage buffer on binding points 0-2 and the generic binding;
 * after the frame the ones a technique used read 0 (stin.h GL STATE: deep's
 * flag point 0, vdsm's CSG lists 0-2, vdsm's receivers 0), the others the
 * caller's */
static void storage_to(hostile_env *e, GLuint b)
{
    GLuint i;
    for (i = 0; i < 3; i++)
        e->gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, i, b);
    e->gl->BindBuffer(GL_SHADER_STORAGE_BUFFER, b);
}

static void set_storage(hostile_env *e) { storage_to(e, e->storage); }
static void reset_storage(hostile_env *e) { storage_to(e, 0); }
static int after_storage(hostile_env *e, char *got, size_t size)
{
    GLint v = -1;
    unsigned i;
    for (i = 0; i < 4; i++) {
        GLint want = (e->storage_used >> i) & 1u ? 0 : (GLint)e->storage;
        if (i < 3)
            e->gl->GetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, i, &v);
        else
            e->gl->GetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &v);
        if (v != want) {
            snprintf(got, size, "storage binding %s%u reading %d, not %d",
                     i < 3 ? "point " : "generic ", i < 3 ? i : 0u, v, want);
            return 0;
        }
    }
    return 1;
}


/* ---- state that redirects stin's own work (issue 38) ------------------------------ */
static int binding_is(hostile_env *e, GLenum pname, GLuint want, char *got, size_t size)
{
    return int_is(e, pname, (GLint)want, got, size);
}

/* a query buffer: query results would be written into it */
static int query_buffer_available(const hostile_env *e)
{
    return (e->version >= 44 || e->ext_query_buffer) && e->buffer;
}
static void set_query_buffer(hostile_env *e) { e->gl->BindBuffer(GL_QUERY_BUFFER, e->buffer); }
static void reset_query_buffer(hostile_env *e) { e->gl->BindBuffer(GL_QUERY_BUFFER, 0); }
static int after_query_buffer(hostile_env *e, char *got, size_t size)
{
    return binding_is(e, GL_QUERY_BUFFER_BINDING, e->buffer, got, size);
}

/* the caller's samples-passed query, active across the frame */
static int query_available(const hostile_env *e) { return e->query != 0; }
static void set_samples_query(hostile_env *e) { e->gl->BeginQuery(GL_SAMPLES_PASSED, e->query); }
static void reset_samples_query(hostile_env *e)
{
    e->gl->EndQuery(GL_SAMPLES_PASSED);
    while (e->gl->GetError() != GL_NO_ERROR) { /* stin's frame may have ended it */
    }
}
static int after_samples_query(hostile_env *e, char *got, size_t size)
{
    GLint current = 0;
    e->gl->GetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &current);
    if (current != (GLint)e->query)
        snprintf(got, size, "the caller's samples query %s",
                 current ? "replaced" : "no longer active");
    return current == (GLint)e->query;
}

/* pixel unpack and pack buffers: allocations and read-backs would use them */
static int pixel_buffer_available(const hostile_env *e) { return e->version >= 21 && e->buffer; }
static void set_unpack(hostile_env *e) { e->gl->BindBuffer(GL_PIXEL_UNPACK_BUFFER, e->buffer); }
static void reset_unpack(hostile_env *e) { e->gl->BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0); }
static int after_unpack(hostile_env *e, char *got, size_t size)
{
    return binding_is(e, GL_PIXEL_UNPACK_BUFFER_BINDING, e->buffer, got, size);
}
static void set_pack(hostile_env *e) { e->gl->BindBuffer(GL_PIXEL_PACK_BUFFER, e->buffer); }
static void reset_pack(hostile_env *e) { e->gl->BindBuffer(GL_PIXEL_PACK_BUFFER, 0); }
static int after_pack(hostile_env *e, char *got, size_t size)
{
    return binding_is(e, GL_PIXEL_PACK_BUFFER_BINDING, e->buffer, got, size);
}

/* a program pipeline drawing red: draws with program 0 would go through it */
static int pipeline_available(const hostile_env *e) { return e->pipeline != 0; }
static void set_pipeline(hostile_env *e) { e->gl->BindProgramPipeline(e->pipeline); }
static void reset_pipeline(hostile_env *e) { e->gl->BindProgramPipeline(0); }
static int after_pipeline(hostile_env *e, char *got, size_t size)
{
    return binding_is(e, GL_PROGRAM_PIPELINE_BINDING, e->pipeline, got, size);
}

/* colour clamping on: float targets would clamp (fragment: compatibility only) */
static int clamp_available(const hostile_env *e)
{
    return (e->version >= 30 || e->ext_clamp) && e->gl->ClampColor;
}
static void clamping(hostile_env *e, GLenum mode)
{
    if (e->compat)
        e->gl->ClampColor(GL_CLAMP_FRAGMENT_COLOR, mode);
    e->gl->ClampColor(GL_CLAMP_READ_COLOR, mode);
}
static void set_clamp(hostile_env *e) { clamping(e, GL_TRUE); }
static void reset_clamp(hostile_env *e) { clamping(e, GL_FIXED_ONLY); }
static int after_clamp(hostile_env *e, char *got, size_t size)
{
    return (!e->compat || int_is(e, GL_CLAMP_FRAGMENT_COLOR, GL_TRUE, got, size)) &&
           int_is(e, GL_CLAMP_READ_COLOR, GL_TRUE, got, size);
}

/* the first vertex provokes: flat-shaded values would come from it */
static int provoking_available(const hostile_env *e)
{
    return (e->version >= 32 || e->ext_provoking) && e->gl->ProvokingVertex;
}
static void set_provoking(hostile_env *e) { e->gl->ProvokingVertex(GL_FIRST_VERTEX_CONVENTION); }
static void reset_provoking(hostile_env *e) { e->gl->ProvokingVertex(GL_LAST_VERTEX_CONVENTION); }
static int after_provoking(hostile_env *e, char *got, size_t size)
{
    return int_is(e, GL_PROVOKING_VERTEX, GL_FIRST_VERTEX_CONVENTION, got, size);
}

/* the stencil clear value */
static void set_clear_stencil(hostile_env *e) { e->gl->ClearStencil(0x5a); }
static void reset_clear_stencil(hostile_env *e) { e->gl->ClearStencil(0); }
static int after_clear_stencil(hostile_env *e, char *got, size_t size)
{
    return int_is(e, GL_STENCIL_CLEAR_VALUE, 0x5a, got, size);
}

/* a 2D-array texture on units 0-7 (stin binds its own arrays on some) */
#define ARRAY_UNITS 8
static int arrays_available(const hostile_env *e) { return e->array_texture != 0; }
static void arrays_to(hostile_env *e, GLuint t)
{
    int u;
    for (u = 0; u < ARRAY_UNITS; u++) {
        e->gl->ActiveTexture((GLenum)(GL_TEXTURE0 + u));
        e->gl->BindTexture(GL_TEXTURE_2D_ARRAY, t);
    }
    e->gl->ActiveTexture(GL_TEXTURE0);
}
static void set_arrays(hostile_env *e) { arrays_to(e, e->array_texture); }
static void reset_arrays(hostile_env *e) { arrays_to(e, 0); }
static int after_arrays(hostile_env *e, char *got, size_t size)
{
    int u, ok = 1;
    for (u = 0; u < ARRAY_UNITS && ok; u++) {
        e->gl->ActiveTexture((GLenum)(GL_TEXTURE0 + u));
        ok = binding_is(e, GL_TEXTURE_BINDING_2D_ARRAY, e->array_texture, got, size);
    }
    e->gl->ActiveTexture(GL_TEXTURE0);
    return ok;
}

/* stin_create's set-up: the caller's vertex array, array buffer, active unit
 * 3, and unit 0's 2D and 2D-array textures */
static int bindings_available(const hostile_env *e) { return e->vao && e->array_texture; }
static void create_bindings(hostile_env *e, int on)
{
    e->gl->BindVertexArray(on ? e->vao : 0);
    e->gl->BindBuffer(GL_ARRAY_BUFFER, on ? e->buffer : 0);
    e->gl->ActiveTexture(GL_TEXTURE0);
    e->gl->BindTexture(GL_TEXTURE_2D, on ? e->texture : 0);
    e->gl->BindTexture(GL_TEXTURE_2D_ARRAY, on ? e->array_texture : 0);
    e->gl->ActiveTexture(on ? GL_TEXTURE3 : GL_TEXTURE0);
}
static void set_create_bindings(hostile_env *e) { create_bindings(e, 1); }
static void reset_create_bindings(hostile_env *e) { create_bindings(e, 0); }
static int after_create_bindings(hostile_env *e, char *got, size_t size)
{
    int ok = binding_is(e, GL_VERTEX_ARRAY_BINDING, e->vao, got, size) &&
             binding_is(e, GL_ARRAY_BUFFER_BINDING, e->buffer, got, size) &&
             int_is(e, GL_ACTIVE_TEXTURE, GL_TEXTURE3, got, size);
    e->gl->ActiveTexture(GL_TEXTURE0);
    ok = ok && binding_is(e, GL_TEXTURE_BINDING_2D, e->texture, got, size) &&
         binding_is(e, GL_TEXTURE_BINDING_2D_ARRAY, e->array_texture, got, size);
    e->gl->ActiveTexture(GL_TEXTURE3);
    return ok;
}

#define ENABLE(name, cap, version, compat, set, reset) \
    {name, cap, version, compat, set, reset, NULL, HOSTILE_FRAME, NULL, NULL}
#define STATE(name, version, compat, set, reset, after) \
    {name, 0, version, compat, set, reset, after, HOSTILE_FRAME, NULL, NULL}
/* version 0: `available` decides */
#define REDIRECT(name, when, available, set, reset, after) \
    {name, 0, 0, 0, set, reset, after, when, available, NULL}

const hostile_case hostile_cases[] = {
    ENABLE("logic-op-invert", GL_COLOR_LOGIC_OP, 11, 0, set_logic_op, reset_logic_op),
    ENABLE("polygon-offset-fill", GL_POLYGON_OFFSET_FILL, 11, 0, set_offset, reset_offset),
    ENABLE("scissor-16x16", GL_SCISSOR_TEST, 11, 0, set_scissor, reset_scissor),
    ENABLE("stencil-never", GL_STENCIL_TEST, 11, 0, set_stencil, reset_stencil),
    ENABLE("depth-greater-no-write", GL_DEPTH_TEST, 11, 0, set_depth, reset_depth),
    ENABLE("blend-zero-one", GL_BLEND, 11, 0, set_blend, reset_blend),
    ENABLE("cull-front-cw", GL_CULL_FACE, 11, 0, set_cull, reset_cull),
    ENABLE("polygon-smooth", GL_POLYGON_SMOOTH, 11, 0, NULL, NULL),
    ENABLE("primitive-restart-0", GL_PRIMITIVE_RESTART, 31, 0, set_restart, NULL),
    ENABLE("primitive-restart-fixed", GL_PRIMITIVE_RESTART_FIXED_INDEX, 43, 0, NULL, NULL),
    ENABLE("rasterizer-discard", GL_RASTERIZER_DISCARD, 30, 0, NULL, NULL),
    ENABLE("depth-clamp", GL_DEPTH_CLAMP, 32, 0, NULL, NULL),
    ENABLE("clip-plane", GL_CLIP_PLANE0, 11, 0, set_clip, NULL),
    ENABLE("alpha-test-greater", GL_ALPHA_TEST, 11, 1, set_alpha_test, reset_alpha_test),
    ENABLE("polygon-stipple-empty", GL_POLYGON_STIPPLE, 11, 1, set_stipple, reset_stipple),
    ENABLE("fog-red", GL_FOG, 11, 1, set_fog, reset_fog),
    ENABLE("colour-material-emission", GL_COLOR_MATERIAL, 11, 1, set_color_material,
           reset_color_material),
    ENABLE("light5-red", GL_LIGHT5, 11, 1, set_light5, reset_light5),
    ENABLE("texgen-s", GL_TEXTURE_GEN_S, 11, 1, set_texgen, reset_texgen),
    STATE("blend-equation-max", 14, 0, set_blend_max, reset_blend_max, after_blend_max),
    STATE("polygon-mode-line", 11, 0, set_lines, reset_lines, after_lines),
    STATE("depth-range", 11, 0, set_range, reset_range, after_range),
    STATE("colour-mask", 11, 0, set_mask, reset_mask, after_mask),
    STATE("sampler-objects", 33, 0, set_samplers, reset_samplers, after_samplers),
    STATE("glsl-program", 20, 0, set_program, reset_program, after_program),
    STATE("active-unit-3", 13, 0, set_unit3, reset_unit3, after_unit3),
    STATE("textures-enabled", 11, 1, set_textures, reset_textures, after_textures),
    STATE("texture-matrix", 11, 1, set_matrix, reset_matrix, after_matrix),
    STATE("colour-array", 11, 1, set_colors, reset_colors, after_colors),
    STATE("pixel-transfer", 11, 1, set_transfer, reset_transfer, after_transfer),
    STATE("storage-buffers", 43, 0, set_storage, reset_storage, after_storage),
    REDIRECT("query-buffer", HOSTILE_FRAME, query_buffer_available, set_query_buffer,
             reset_query_buffer, after_query_buffer),
    REDIRECT("samples-query-active", HOSTILE_FRAME, query_available, set_samples_query,
             reset_samples_query, after_samples_query),
    REDIRECT("pixel-unpack-buffer", HOSTILE_FRAME | HOSTILE_CREATE, pixel_buffer_available,
             set_unpack, reset_unpack, after_unpack),
    REDIRECT("pixel-pack-buffer", HOSTILE_FRAME, pixel_buffer_available, set_pack, reset_pack,
             after_pack),
    REDIRECT("program-pipeline", HOSTILE_FRAME, pipeline_available, set_pipeline,
             reset_pipeline, after_pipeline),
    REDIRECT("clamp-colour", HOSTILE_FRAME, clamp_available, set_clamp, reset_clamp,
             after_clamp),
    REDIRECT("provoking-first", HOSTILE_FRAME, provoking_available, set_provoking,
             reset_provoking, after_provoking),
    STATE("stencil-clear-value", 11, 0, set_clear_stencil, reset_clear_stencil,
          after_clear_stencil),
    REDIRECT("2d-array-units", HOSTILE_FRAME, arrays_available, set_arrays, reset_arrays,
             after_arrays),
    REDIRECT("create-bindings", HOSTILE_CREATE, bindings_available, set_create_bindings,
             reset_create_bindings, after_create_bindings)};

const size_t hostile_case_count = sizeof hostile_cases / sizeof hostile_cases[0];

/* The cases whose state OpenGL ES has, with the ES version that brings it
 * (stin.h, GL STATE: "On OpenGL ES"); the others (logic op, polygon mode
 * and smooth, depth clamp, clip planes, glDepthRange, fixed function,
 * samples-passed queries, query buffers, colour clamping, the provoking
 * vertex, program pipelines and storage buffers, which stin does not use
 * on ES) do not exist there or are not stin's on ES. */
static const struct {
    const char *name;
    int es;
} es_cases[] = {
    {"polygon-offset-fill", 20}, {"scissor-16x16", 20}, {"stencil-never", 20},
    {"depth-greater-no-write", 20}, {"blend-zero-one", 20}, {"cull-front-cw", 20},
    {"colour-mask", 20}, {"glsl-program", 20}, {"active-unit-3", 20},
    {"stencil-clear-value", 20}, {"blend-equation-max", 30}, {"rasterizer-discard", 30},
    {"primitive-restart-fixed", 30}, {"sampler-objects", 30}, {"pixel-unpack-buffer", 30},
    {"pixel-pack-buffer", 30}, {"2d-array-units", 30}, {"create-bindings", 30}};

static int es_version_of(const hostile_case *c)
{
    size_t i;
    for (i = 0; i < sizeof es_cases / sizeof es_cases[0]; i++)
        if (!strcmp(es_cases[i].name, c->name))
            return es_cases[i].es;
    return 0;
}

int hostile_applies(const hostile_case *c, const hostile_env *e)
{
    if (e->es) {
        int es = es_version_of(c);
        return es && e->version >= es && (!c->available || c->available(e));
    }
    return e->version >= c->version && (!c->compat || e->compat) &&
           (!c->available || c->available(e));
}

void hostile_set(const hostile_case *c, hostile_env *e)
{
    if (c->set)
        c->set(e);
    if (c->cap)
        e->gl->Enable(c->cap);
}

void hostile_reset(const hostile_case *c, hostile_env *e)
{
    if (c->cap)
        e->gl->Disable(c->cap);
    if (c->reset)
        c->reset(e);
}

int hostile_after(const hostile_case *c, hostile_env *e, char *got, size_t size)
{
    return c->after ? c->after(e, got, size) : after_enable(e, c->cap, got, size);
}

int hostile_after_create(const hostile_case *c, hostile_env *e, char *got, size_t size)
{
    return c->after_create ? c->after_create(e, got, size) : hostile_after(c, e, got, size);
}

/* ---- the caller's objects ----------------------------------------------------------- */
static const char red_fragment[] = "#version 150\nout vec4 c;\nvoid main() { c = vec4(1.0, 0.0, 0.0, 1.0); }\n";
static const char red_fragment_110[] = "#version 110\nvoid main() { gl_FragColor = vec4(1.0, 0.0, 0.0, 1.0); }\n";

static void make_pipeline(hostile_env *e, int core)
{
    const char *src = core ? red_fragment : red_fragment_110;
    GLuint fragment;
    if (!(e->version >= 41 || e->ext_pipeline) || !e->gl->GenProgramPipelines ||
        !e->gl->CreateShaderProgramv)
        return;
    fragment = e->gl->CreateShaderProgramv(GL_FRAGMENT_SHADER, 1, &src);
    if (!fragment)
        return;
    e->gl->GenProgramPipelines(1, &e->pipeline);
    e->gl->UseProgramStages(e->pipeline, GL_FRAGMENT_SHADER_BIT, fragment);
    e->gl->DeleteProgram(fragment); /* the pipeline keeps it */
}

void hostile_objects_make(hostile_env *e, int core)
{
    static const GLubyte texel[4] = {255, 0, 0, 255};
    const caller_gl *gl = e->gl;
    gl->GenTextures(1, &e->texture);
    gl->BindTexture(GL_TEXTURE_2D, e->texture);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    if (e->version >= 20)
        e->program = caller_gl_flat_program(gl, core, 1.0f, 0.0f, 0.0f);
    if (e->version >= 43 && gl->GenBuffers && gl->BindBufferBase && gl->GetIntegeri_v) {
        gl->GenBuffers(1, &e->storage);
        gl->BindBuffer(GL_SHADER_STORAGE_BUFFER, e->storage);
        gl->BufferData(GL_SHADER_STORAGE_BUFFER, 64, NULL, GL_DYNAMIC_DRAW);
        gl->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    }
    if (e->version >= 15 && gl->GenBuffers) {
        gl->GenBuffers(1, &e->buffer);
        gl->BindBuffer(GL_ARRAY_BUFFER, e->buffer);
        gl->BufferData(GL_ARRAY_BUFFER, 64, NULL, GL_DYNAMIC_DRAW);
        gl->BindBuffer(GL_ARRAY_BUFFER, 0);
    }
    if (e->version >= 15 && !e->es && gl->GenQueries && gl->GetQueryiv)
        gl->GenQueries(1, &e->query);
    if (e->version >= 30 && gl->TexImage3D) {
        gl->GenTextures(1, &e->array_texture);
        gl->BindTexture(GL_TEXTURE_2D_ARRAY, e->array_texture);
        gl->TexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                       texel);
        gl->BindTexture(GL_TEXTURE_2D_ARRAY, 0);
    }
    if (e->version >= 30 && gl->GenVertexArrays)
        gl->GenVertexArrays(1, &e->vao);
    if ((e->version >= 33 || (e->es && e->version >= 30)) && gl->GenSamplers) {
        gl->GenSamplers(1, &e->sampler);
        gl->SamplerParameteri(e->sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl->SamplerParameteri(e->sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl->SamplerParameteri(e->sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl->SamplerParameteri(e->sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    if (!e->es)
        make_pipeline(e, core);
    while (gl->GetError() != GL_NO_ERROR) {
    }
}

void hostile_objects_free(hostile_env *e)
{
    const caller_gl *gl = e->gl;
    gl->DeleteTextures(1, &e->texture);
    if (e->program)
        gl->DeleteProgram(e->program);
    if (e->sampler)
        gl->DeleteSamplers(1, &e->sampler);
    if (e->storage)
        gl->DeleteBuffers(1, &e->storage);
    if (e->buffer)
        gl->DeleteBuffers(1, &e->buffer);
    if (e->query)
        gl->DeleteQueries(1, &e->query);
    if (e->array_texture)
        gl->DeleteTextures(1, &e->array_texture);
    if (e->vao)
        gl->DeleteVertexArrays(1, &e->vao);
    if (e->pipeline)
        gl->DeleteProgramPipelines(1, &e->pipeline);
    e->texture = e->program = e->sampler = e->storage = e->buffer = e->query = 0;
    e->array_texture = e->vao = e->pipeline = 0;
}
