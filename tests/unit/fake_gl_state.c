/* SPDX-License-Identifier: MIT */
/* The GL state of fake_gl_state.h: the entry points that change it, the
 * queries that read it, GL's initial values, and the field-by-field diff. */
#define FAKE_GL_STUBS
#include "fake_gl.h"

#include <stdio.h>
#include <string.h>

/* Enums the library does not use (gl_types.h lists only those). */
#ifndef GL_FLAT
#define GL_FLAT 0x1D00
#endif
#ifndef GL_TEXTURE_GEN_MODE
#define GL_TEXTURE_GEN_MODE 0x2500
#endif
#define FAKE_OBJECT_PLANE 0x2501
#define FAKE_SPHERE_MAP 0x2402
#define FAKE_OBJECT_LINEAR 0x2401
#define FAKE_NORMAL_MAP 0x8511
#define FAKE_REFLECTION_MAP 0x8512
#define FAKE_ALPHA_SCALE 0x0D1C
#define FAKE_TEXTURE_ENV_COLOR 0x2201
#define FAKE_SOURCE2_RGB 0x8582
#define FAKE_SOURCE2_ALPHA 0x858A
#define FAKE_OPERAND2_RGB 0x8592
#define FAKE_OPERAND2_ALPHA 0x859A
#define FAKE_ONE_MINUS_SRC_COLOR 0x0301
#define FAKE_DECAL 0x2101
#define FAKE_ADD 0x0104
#define FAKE_INTERPOLATE 0x8575
#define FAKE_SUBTRACT 0x84E7
#define FAKE_COLOR_ARRAY 0x8076
#define FAKE_CLIENT_ACTIVE_TEXTURE 0x84E1
#define FAKE_ACTIVE_STENCIL_FACE_EXT 0x8911
#define FAKE_DRAW_FRAMEBUFFER 0x8CA9
#define FAKE_READ_FRAMEBUFFER 0x8CA8
#define FAKE_READ_FRAMEBUFFER_BINDING 0x8CAA
#define FAKE_DRAW_BUFFER 0x0C01
#define FAKE_READ_BUFFER 0x0C02
#define FAKE_ARRAY_BUFFER_BINDING 0x8894
#define FAKE_ELEMENT_ARRAY_BUFFER_BINDING 0x8895
#define FAKE_VERTEX_ARRAY_BINDING 0x85B5
#define FAKE_PIXEL_UNPACK_BUFFER 0x88EC
#define FAKE_PIXEL_UNPACK_BUFFER_BINDING 0x88EF
#define FAKE_PIXEL_PACK_BUFFER 0x88EB
#define FAKE_PIXEL_PACK_BUFFER_BINDING 0x88ED
#define FAKE_QUERY_BUFFER 0x9192
#define FAKE_QUERY_BUFFER_BINDING 0x9193
#define FAKE_TEXTURE_BINDING_1D 0x8068
#define FAKE_COLOR_INDEXES 0x1603
#define FAKE_LIGHT_MODEL_COLOR_CONTROL 0x81F8

/* ---- tables --------------------------------------------------------------- */
typedef struct named {
    GLenum value;
    const char *name;
    int initial;
} named;

#define FAKE_X_CAP_(name, value, initial) {value, "GL_" #name, initial},
static const named caps[FAKE_GL_CAP_COUNT] = {FAKE_GL_CAPS(FAKE_X_CAP_)};
static const named pixel_store[FAKE_GL_PIXEL_STORE_COUNT] = {FAKE_GL_PIXEL_STORE(FAKE_X_CAP_)};
static const named pixel_transfer[FAKE_GL_PIXEL_TRANSFER_COUNT] = {
    FAKE_GL_PIXEL_TRANSFER(FAKE_X_CAP_)};
#undef FAKE_X_CAP_
#define FAKE_X_UNIT_CAP_(name, value) {value, "GL_" #name, 0},
static const named unit_caps[FAKE_GL_UNIT_CAP_COUNT] = {FAKE_GL_UNIT_CAPS(FAKE_X_UNIT_CAP_)};
#undef FAKE_X_UNIT_CAP_
#define FAKE_X_TARGET_(name, value) {value, "GL_TEXTURE_" #name, 0},
static const named targets[FAKE_GL_TARGET_COUNT] = {FAKE_GL_TARGETS(FAKE_X_TARGET_)};
#undef FAKE_X_TARGET_

static int find(const named *t, int n, GLenum e)
{
    int i;
    for (i = 0; i < n; i++)
        if (t[i].value == e)
            return i;
    return -1;
}

/* ---- initial state (GL 2.1, tables 6.5-6.37) ------------------------------ */
static void set4(GLfloat *d, GLfloat a, GLfloat b, GLfloat c, GLfloat e)
{
    d[0] = a;
    d[1] = b;
    d[2] = c;
    d[3] = e;
}

static void identity(GLfloat *m)
{
    memset(m, 0, 16 * sizeof *m);
    m[0] = m[5] = m[10] = m[15] = 1.0f;
}

static void init_unit(fake_gl_unit *u)
{
    int i;
    memset(u, 0, sizeof *u);
    u->env.mode = GL_MODULATE;
    u->env.combine_rgb = u->env.combine_alpha = GL_MODULATE;
    for (i = 0; i < 3; i++) {
        static const GLenum src[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
        u->env.src_rgb[i] = u->env.src_alpha[i] = src[i];
        u->env.operand_rgb[i] = i < 2 ? GL_SRC_COLOR : GL_SRC_ALPHA;
        u->env.operand_alpha[i] = GL_SRC_ALPHA;
    }
    u->env.rgb_scale = u->env.alpha_scale = 1.0f;
    for (i = 0; i < 4; i++)
        u->gen_mode[i] = GL_EYE_LINEAR;
    u->eye_plane[0][0] = u->object_plane[0][0] = 1.0f; /* S = x, T = y, R = Q = 0 */
    u->eye_plane[1][1] = u->object_plane[1][1] = 1.0f;
    u->matrix_depth = 1;
    identity(u->matrix[0]);
}

void fake_gl_state_init(fake_gl_glstate *s)
{
    int i;
    memset(s, 0, sizeof *s);
    for (i = 0; i < FAKE_GL_CAP_COUNT; i++)
        s->enabled[i] = (GLuint)caps[i].initial;
    s->depth_func = GL_LESS;
    s->depth_mask = GL_TRUE;
    for (i = 0; i < 4; i++)
        s->color_mask[i] = GL_TRUE;
    s->blend_src_rgb = s->blend_src_alpha = GL_ONE;
    s->blend_dst_rgb = s->blend_dst_alpha = GL_ZERO;
    s->blend_equation = 0x8006; /* GL_FUNC_ADD */
    s->patch_vertices = 3;
    s->polygon_mode[0] = s->polygon_mode[1] = 0x1B02; /* GL_FILL */
    s->depth_range[1] = 1.0f;
    for (i = 0; i < 2; i++) {
        fake_gl_stencil *f = &s->stencil[i];
        f->func = GL_ALWAYS;
        f->value_mask = f->writemask = 0xffffffffu;
        f->fail = f->zfail = f->zpass = GL_KEEP;
    }
    s->active_stencil_face = GL_FRONT;
    s->alpha_func = GL_ALWAYS;
    s->cull_face = GL_BACK;
    s->front_face = GL_CCW;
    s->shade_model = GL_SMOOTH;
    s->scissor[2] = s->viewport[2] = FAKE_GL_WINDOW_W;
    s->scissor[3] = s->viewport[3] = FAKE_GL_WINDOW_H;
    s->clear_depth = 1.0;
    set4(s->light_model_ambient, 0.2f, 0.2f, 0.2f, 1.0f);
    s->light_model_color_control = GL_SINGLE_COLOR;
    for (i = 0; i < FAKE_GL_LIGHTS; i++) {
        fake_gl_light *l = &s->lights[i];
        GLfloat on = i == 0 ? 1.0f : 0.0f; /* only light 0 is white */
        set4(l->ambient, 0, 0, 0, 1);
        set4(l->diffuse, on, on, on, 1);
        set4(l->specular, on, on, on, 1);
        set4(l->position, 0, 0, 1, 0);
        l->spot_direction[2] = -1.0f;
        l->spot_cutoff = 180.0f;
        l->attenuation[0] = 1.0f;
    }
    for (i = 0; i < 2; i++) {
        fake_gl_material *m = &s->material[i];
        set4(m->ambient, 0.2f, 0.2f, 0.2f, 1.0f);
        set4(m->diffuse, 0.8f, 0.8f, 0.8f, 1.0f);
        set4(m->specular, 0, 0, 0, 1);
        set4(m->emission, 0, 0, 0, 1);
    }
    s->color_material_face = GL_FRONT_AND_BACK;
    s->color_material_mode = GL_AMBIENT_AND_DIFFUSE;
    set4(s->current_color, 1, 1, 1, 1);
    s->matrix_mode = GL_MODELVIEW;
    s->modelview_depth = s->projection_depth = 1;
    identity(s->modelview[0]);
    identity(s->projection[0]);
    s->active_texture = s->client_active_texture = GL_TEXTURE0;
    for (i = 0; i < FAKE_GL_UNITS; i++)
        init_unit(&s->units[i]);
    s->draw_buffer = s->read_buffer = GL_BACK;
    for (i = 0; i < FAKE_GL_PIXEL_STORE_COUNT; i++)
        s->pixel_store[i] = pixel_store[i].initial;
    for (i = 0; i < FAKE_GL_PIXEL_TRANSFER_COUNT; i++)
        s->pixel_transfer[i] = (GLfloat)pixel_transfer[i].initial;
}

static int parse_version(const char *v)
{
    int major = 0, minor = 0;
    if (!v)
        return 0;
    while (*v >= '0' && *v <= '9')
        major = major * 10 + (*v++ - '0');
    if (*v == '.')
        v++;
    while (*v >= '0' && *v <= '9')
        minor = minor * 10 + (*v++ - '0');
    return 10 * major + minor;
}

void fake_gl_state_reset(void)
{
    fake_gl_state_init(&fake_gl.gl);
    fake_gl.version = parse_version(fake_gl.config.version);
}

/* ---- what the fake cannot or a GL would not do ---------------------------- */
static void describe(char *buf, size_t size, const char *call, GLenum e)
{
    char name[40];
    snprintf(buf, size, "%s(%s)", call, fake_gl_enum_name(e, name, sizeof name));
}

void fake_gl_state_untracked(const char *call, GLenum e)
{
    if (!fake_gl.untracked++)
        describe(fake_gl.untracked_what, sizeof fake_gl.untracked_what, call, e);
}

/* 1 for a table index, else the call is counted as untracked. */
static int known(int i, const char *call, GLenum e)
{
    if (i < 0)
        fake_gl_state_untracked(call, e);
    return i >= 0;
}

void fake_gl_state_refused(const char *call, GLenum e)
{
    if (!fake_gl.gl_errors++)
        describe(fake_gl.gl_error_what, sizeof fake_gl.gl_error_what, call, e);
}

/* ---- where a call lands ---------------------------------------------------- */
#define S (fake_gl.gl)

static fake_gl_unit *unit_of(GLenum texture_enum, const char *call)
{
    GLuint i = texture_enum - GL_TEXTURE0;
    if (i >= FAKE_GL_UNITS) {
        fake_gl_state_refused(call, texture_enum);
        i = 0;
    }
    return &S.units[i];
}

static fake_gl_unit *active_unit(void) { return unit_of(S.active_texture, "active unit"); }

static fake_gl_vao *bound_vao(void)
{
    GLuint name = S.vertex_array_binding;
    int i, free_slot = -1;
    if (!name)
        return &S.vao0;
    for (i = 0; i < FAKE_GL_MAX_VAOS; i++) {
        if (fake_gl.vaos[i].name == name)
            return &fake_gl.vaos[i].state;
        if (!fake_gl.vaos[i].name && free_slot < 0)
            free_slot = i;
    }
    if (free_slot < 0) {
        fake_gl_state_refused("glBindVertexArray: more vertex arrays than the fake keeps", name);
        return &S.vao0;
    }
    fake_gl.vaos[free_slot].name = name;
    return &fake_gl.vaos[free_slot].state;
}

/* The matrix stack glMatrixMode selects: its depth, entries and capacity. */
typedef struct stack {
    GLuint *depth;
    GLfloat (*m)[16];
    GLuint cap;
} stack;

static stack current_stack(void)
{
    stack st;
    if (S.matrix_mode == GL_PROJECTION) {
        st.depth = &S.projection_depth;
        st.m = S.projection;
        st.cap = FAKE_GL_PROJECTION_DEPTH;
    } else if (S.matrix_mode == GL_TEXTURE) {
        fake_gl_unit *u = active_unit();
        st.depth = &u->matrix_depth;
        st.m = u->matrix;
        st.cap = FAKE_GL_TEXTURE_DEPTH;
    } else {
        st.depth = &S.modelview_depth;
        st.m = S.modelview;
        st.cap = FAKE_GL_MODELVIEW_DEPTH;
    }
    return st;
}

static const GLfloat *modelview_top(void) { return S.modelview[S.modelview_depth - 1]; }

/* ---- entry points that set one field, or switch something on and off ----- */
#define FAKE_SET(name, type, field)                 \
    void STIN_APIENTRY fake_##name(type v)          \
    {                                               \
        COUNT(name);                                \
        S.field = v;                                \
    }
FAKE_SET(CullFace, GLenum, cull_face)
FAKE_SET(FrontFace, GLenum, front_face)
FAKE_SET(ShadeModel, GLenum, shade_model)
FAKE_SET(DepthFunc, GLenum, depth_func)
FAKE_SET(ClearDepth, GLdouble, clear_depth)
FAKE_SET(ClearStencil, GLint, clear_stencil)
FAKE_SET(BindVertexArray, GLuint, vertex_array_binding)
FAKE_SET(UseProgram, GLuint, program)

static void enable(const char *call, GLenum cap, GLuint on);
static void client_state(const char *call, GLenum array, GLuint on);
static void attrib_array(const char *call, GLuint i, GLuint on);
#define FAKE_ON_OFF(on, off, type, apply)           \
    void STIN_APIENTRY fake_##on(type x)            \
    {                                               \
        COUNT(on);                                  \
        apply("gl" #on, x, 1);                      \
    }                                               \
    void STIN_APIENTRY fake_##off(type x)           \
    {                                               \
        COUNT(off);                                 \
        apply("gl" #off, x, 0);                     \
    }
FAKE_ON_OFF(Enable, Disable, GLenum, enable)
FAKE_ON_OFF(EnableClientState, DisableClientState, GLenum, client_state)
FAKE_ON_OFF(EnableVertexAttribArray, DisableVertexAttribArray, GLuint, attrib_array)

/* ---- enables ---------------------------------------------------------------- */
static GLuint *cap_slot(GLenum cap)
{
    int i = find(caps, FAKE_GL_CAP_COUNT, cap);
    if (i >= 0)
        return &S.enabled[i];
    i = find(unit_caps, FAKE_GL_UNIT_CAP_COUNT, cap);
    return i >= 0 ? &active_unit()->enabled[i] : NULL;
}

static void enable(const char *call, GLenum cap, GLuint on)
{
    GLuint *slot = cap_slot(cap);
    if (!slot)
        fake_gl_state_untracked(call, cap);
    else
        *slot = on;
}

int fake_gl_is_enabled(GLenum cap)
{
    const GLuint *slot = cap_slot(cap);
    return slot ? (int)*slot : 0;
}

/* ---- per-fragment operations ------------------------------------------------ */
void STIN_APIENTRY fake_DepthMask(GLboolean flag)
{
    COUNT(DepthMask);
    S.depth_mask = flag != 0;
}

void STIN_APIENTRY fake_ColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a)
{
    COUNT(ColorMask);
    S.color_mask[0] = r != 0;
    S.color_mask[1] = g != 0;
    S.color_mask[2] = b != 0;
    S.color_mask[3] = a != 0;
}

void STIN_APIENTRY fake_BlendFunc(GLenum s, GLenum d)
{
    COUNT(BlendFunc);
    S.blend_src_rgb = S.blend_src_alpha = s;
    S.blend_dst_rgb = S.blend_dst_alpha = d;
}

void STIN_APIENTRY fake_BlendEquation(GLenum mode)
{
    COUNT(BlendEquation);
    S.blend_equation = mode;
}

void STIN_APIENTRY fake_PatchParameteri(GLenum pname, GLint value)
{
    COUNT(PatchParameteri);
    if (pname == 0x8E72) /* GL_PATCH_VERTICES */
        S.patch_vertices = value;
}

void STIN_APIENTRY fake_PolygonMode(GLenum face, GLenum mode)
{
    COUNT(PolygonMode);
    if (face == GL_FRONT || face == GL_FRONT_AND_BACK)
        S.polygon_mode[0] = mode;
    if (face == GL_BACK || face == GL_FRONT_AND_BACK)
        S.polygon_mode[1] = mode;
    if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK)
        fake_gl_state_refused("glPolygonMode", face);
}

void STIN_APIENTRY fake_DepthRange(GLdouble n, GLdouble f)
{
    COUNT(DepthRange);
    S.depth_range[0] = (GLfloat)(n < 0.0 ? 0.0 : n > 1.0 ? 1.0 : n); /* GL clamps */
    S.depth_range[1] = (GLfloat)(f < 0.0 ? 0.0 : f > 1.0 ? 1.0 : f);
}

void STIN_APIENTRY fake_BindSampler(GLuint unit, GLuint sampler)
{
    COUNT(BindSampler);
    if (unit >= FAKE_GL_UNITS)
        fake_gl_state_refused("glBindSampler", unit);
    else
        S.units[unit].sampler = sampler;
}

void STIN_APIENTRY fake_PixelTransferf(GLenum pname, GLfloat v)
{
    int i = find(pixel_transfer, FAKE_GL_PIXEL_TRANSFER_COUNT, pname);
    COUNT(PixelTransferf);
    if (i < 0)
        fake_gl_state_untracked("glPixelTransferf", pname);
    else
        S.pixel_transfer[i] = v;
}

/* Pixel transfer is the only float state stin reads back. */
void STIN_APIENTRY fake_GetFloatv(GLenum pname, GLfloat *data)
{
    int i = find(pixel_transfer, FAKE_GL_PIXEL_TRANSFER_COUNT, pname);
    COUNT(GetFloatv);
    if (i < 0) {
        *data = 0.0f;
        fake_gl_state_untracked("glGetFloatv", pname);
    } else {
        *data = S.pixel_transfer[i];
    }
}

void STIN_APIENTRY fake_AlphaFunc(GLenum func, GLfloat ref)
{
    COUNT(AlphaFunc);
    S.alpha_func = func;
    S.alpha_ref = ref < 0.0f ? 0.0f : ref > 1.0f ? 1.0f : ref; /* GL clamps */
}

/* The faces a non-separate stencil call sets: with EXT_stencil_two_side's
 * active face BACK the back face only; else the front, and from GL 2.0 on
 * the back too (glStencilFunc/Op/Mask set both faces there). */
static int stencil_faces(fake_gl_stencil *out[2])
{
    if (S.active_stencil_face == GL_BACK) {
        out[0] = &S.stencil[1];
        return 1;
    }
    out[0] = &S.stencil[0];
    out[1] = &S.stencil[1];
    return fake_gl.version >= 20 ? 2 : 1;
}

static int separate_faces(GLenum face, fake_gl_stencil *out[2], const char *call)
{
    switch (face) {
    case GL_FRONT: out[0] = &S.stencil[0]; return 1;
    case GL_BACK: out[0] = &S.stencil[1]; return 1;
    case GL_FRONT_AND_BACK: out[0] = &S.stencil[0]; out[1] = &S.stencil[1]; return 2;
    default: fake_gl_state_refused(call, face); return 0;
    }
}

static void stencil_ops(fake_gl_stencil **f, int n, GLenum fail, GLenum zfail, GLenum zpass)
{
    int i;
    for (i = 0; i < n; i++) {
        f[i]->fail = fail;
        f[i]->zfail = zfail;
        f[i]->zpass = zpass;
    }
}

void STIN_APIENTRY fake_StencilFunc(GLenum func, GLint ref, GLuint mask)
{
    fake_gl_stencil *f[2];
    int i, n = stencil_faces(f);
    COUNT(StencilFunc);
    for (i = 0; i < n; i++) {
        f[i]->func = func;
        f[i]->ref = ref;
        f[i]->value_mask = mask;
    }
}

void STIN_APIENTRY fake_StencilMask(GLuint mask)
{
    fake_gl_stencil *f[2];
    int i, n = stencil_faces(f);
    COUNT(StencilMask);
    for (i = 0; i < n; i++)
        f[i]->writemask = mask;
}

void STIN_APIENTRY fake_StencilOp(GLenum fail, GLenum zfail, GLenum zpass)
{
    fake_gl_stencil *f[2];
    int n = stencil_faces(f);
    COUNT(StencilOp);
    stencil_ops(f, n, fail, zfail, zpass);
}

void STIN_APIENTRY fake_StencilOpSeparate(GLenum face, GLenum fail, GLenum zfail, GLenum zpass)
{
    fake_gl_stencil *f[2];
    int n = separate_faces(face, f, "glStencilOpSeparate");
    COUNT(StencilOpSeparate);
    stencil_ops(f, n, fail, zfail, zpass);
}

void STIN_APIENTRY fake_ActiveStencilFaceEXT(GLenum face)
{
    COUNT(ActiveStencilFaceEXT);
    if (face != GL_FRONT && face != GL_BACK)
        fake_gl_state_refused("glActiveStencilFaceEXT", face);
    else
        S.active_stencil_face = face;
}

/* ---- rasterisation and the window -------------------------------------------- */
void STIN_APIENTRY fake_PolygonOffset(GLfloat factor, GLfloat units)
{
    COUNT(PolygonOffset);
    S.polygon_offset_factor = factor;
    S.polygon_offset_units = units;
}

static void rect(GLint *r, GLint x, GLint y, GLsizei w, GLsizei h)
{
    r[0] = x;
    r[1] = y;
    r[2] = w;
    r[3] = h;
}

void STIN_APIENTRY fake_Viewport(GLint x, GLint y, GLsizei w, GLsizei h)
{
    COUNT(Viewport);
    rect(S.viewport, x, y, w, h);
}

void STIN_APIENTRY fake_Scissor(GLint x, GLint y, GLsizei w, GLsizei h)
{
    COUNT(Scissor);
    rect(S.scissor, x, y, w, h);
}

void STIN_APIENTRY fake_ClearColor(GLfloat r, GLfloat g, GLfloat b, GLfloat a)
{
    COUNT(ClearColor);
    set4(S.clear_color, r, g, b, a);
}

void STIN_APIENTRY fake_PixelStorei(GLenum pname, GLint param)
{
    int i = find(pixel_store, FAKE_GL_PIXEL_STORE_COUNT, pname);
    COUNT(PixelStorei);
    if (known(i, "glPixelStorei", pname))
        S.pixel_store[i] = param;
}

/* ---- lighting ----------------------------------------------------------------- */
static fake_gl_light *light_of(GLenum light, const char *call)
{
    GLuint i = light - GL_LIGHT0;
    if (i >= FAKE_GL_LIGHTS) {
        fake_gl_state_refused(call, light);
        return NULL;
    }
    return &S.lights[i];
}

/* Scalar light parameters; 0 if pname is not one. */
static int light_scalar(fake_gl_light *l, GLenum pname, GLfloat v)
{
    switch (pname) {
    case GL_SPOT_EXPONENT: l->spot_exponent = v; return 1;
    case GL_SPOT_CUTOFF: l->spot_cutoff = v; return 1;
    case GL_CONSTANT_ATTENUATION: l->attenuation[0] = v; return 1;
    case GL_LINEAR_ATTENUATION: l->attenuation[1] = v; return 1;
    case GL_QUADRATIC_ATTENUATION: l->attenuation[2] = v; return 1;
    default: return 0;
    }
}

void STIN_APIENTRY fake_Lightfv(GLenum light, GLenum pname, const GLfloat *v)
{
    fake_gl_light *l = light_of(light, "glLightfv");
    const GLfloat *m = modelview_top();
    int r;
    COUNT(Lightfv);
    if (!l)
        return;
    switch (pname) {
    case GL_AMBIENT: memcpy(l->ambient, v, sizeof l->ambient); break;
    case GL_DIFFUSE: memcpy(l->diffuse, v, sizeof l->diffuse); break;
    case GL_SPECULAR: memcpy(l->specular, v, sizeof l->specular); break;
    case GL_POSITION: /* kept in eye space: the modelview of the call applies */
        for (r = 0; r < 4; r++)
            l->position[r] = m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2] + m[12 + r] * v[3];
        break;
    case GL_SPOT_DIRECTION: /* by the modelview's upper 3x3 */
        for (r = 0; r < 3; r++)
            l->spot_direction[r] = m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2];
        break;
    default:
        if (!light_scalar(l, pname, v[0]))
            fake_gl_state_untracked("glLightfv", pname);
        break;
    }
}

void STIN_APIENTRY fake_Lightf(GLenum light, GLenum pname, GLfloat v)
{
    fake_gl_light *l = light_of(light, "glLightf");
    COUNT(Lightf);
    if (l && !light_scalar(l, pname, v))
        fake_gl_state_untracked("glLightf", pname);
}

static void light_model(const char *call, GLenum pname, const GLfloat *v)
{
    switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT:
        memcpy(S.light_model_ambient, v, sizeof S.light_model_ambient);
        break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: S.light_model_local_viewer = v[0] != 0.0f; break;
    case GL_LIGHT_MODEL_TWO_SIDE: S.light_model_two_side = v[0] != 0.0f; break;
    case FAKE_LIGHT_MODEL_COLOR_CONTROL: S.light_model_color_control = (GLenum)v[0]; break;
    default: fake_gl_state_untracked(call, pname); break;
    }
}

void STIN_APIENTRY fake_LightModelfv(GLenum pname, const GLfloat *v)
{
    COUNT(LightModelfv);
    light_model("glLightModelfv", pname, v);
}

void STIN_APIENTRY fake_LightModeli(GLenum pname, GLint v)
{
    GLfloat f[4] = {(GLfloat)v, 0, 0, 0};
    COUNT(LightModeli);
    if (pname == GL_LIGHT_MODEL_AMBIENT)
        fake_gl_state_untracked("glLightModeli", pname); /* a vector: not through this call */
    else
        light_model("glLightModeli", pname, f);
}

static void material(const char *call, GLenum face, GLenum pname, const GLfloat *v)
{
    int i, first = face == GL_BACK ? 1 : 0, last = face == GL_FRONT ? 0 : 1;
    if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) {
        fake_gl_state_refused(call, face);
        return;
    }
    for (i = first; i <= last; i++) {
        fake_gl_material *m = &S.material[i];
        switch (pname) {
        case GL_AMBIENT: memcpy(m->ambient, v, sizeof m->ambient); break;
        case GL_DIFFUSE: memcpy(m->diffuse, v, sizeof m->diffuse); break;
        case GL_AMBIENT_AND_DIFFUSE:
            memcpy(m->ambient, v, sizeof m->ambient);
            memcpy(m->diffuse, v, sizeof m->diffuse);
            break;
        case GL_SPECULAR: memcpy(m->specular, v, sizeof m->specular); break;
        case GL_EMISSION: memcpy(m->emission, v, sizeof m->emission); break;
        case GL_SHININESS: m->shininess = v[0]; break;
        default: fake_gl_state_untracked(call, pname); return;
        }
    }
}

void STIN_APIENTRY fake_Materialfv(GLenum face, GLenum pname, const GLfloat *v)
{
    COUNT(Materialfv);
    material("glMaterialfv", face, pname, v);
}

void STIN_APIENTRY fake_Materialf(GLenum face, GLenum pname, GLfloat v)
{
    COUNT(Materialf);
    if (pname != GL_SHININESS)
        fake_gl_state_refused("glMaterialf", pname); /* only the scalar one is allowed */
    else
        material("glMaterialf", face, pname, &v);
}

void STIN_APIENTRY fake_Color4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a)
{
    COUNT(Color4f);
    set4(S.current_color, r, g, b, a);
    if (S.enabled[FAKE_GL_COLOR_MATERIAL]) /* the material tracks the colour */
        material("glColor4f", S.color_material_face, S.color_material_mode, S.current_color);
}

/* ---- transformation ------------------------------------------------------------- */
void STIN_APIENTRY fake_MatrixMode(GLenum mode)
{
    COUNT(MatrixMode);
    if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE)
        fake_gl_state_untracked("glMatrixMode", mode);
    else
        S.matrix_mode = mode;
}

void STIN_APIENTRY fake_LoadMatrixf(const GLfloat *m)
{
    stack st = current_stack();
    COUNT(LoadMatrixf);
    memcpy(st.m[*st.depth - 1], m, 16 * sizeof *m);
}

void STIN_APIENTRY fake_PushMatrix(void)
{
    stack st = current_stack();
    COUNT(PushMatrix);
    if (*st.depth >= st.cap) {
        fake_gl_state_refused("glPushMatrix: stack overflow in mode", S.matrix_mode);
        return;
    }
    memcpy(st.m[*st.depth], st.m[*st.depth - 1], sizeof st.m[0]);
    (*st.depth)++;
}

void STIN_APIENTRY fake_PopMatrix(void)
{
    stack st = current_stack();
    COUNT(PopMatrix);
    if (*st.depth <= 1) {
        fake_gl_state_refused("glPopMatrix: stack underflow in mode", S.matrix_mode);
        return;
    }
    (*st.depth)--;
    memset(st.m[*st.depth], 0, sizeof st.m[0]); /* entries above the top stay zero */
}

/* ---- texturing -------------------------------------------------------------------- */
static void select_unit(GLenum *field, GLenum unit, const char *call)
{
    if (unit - GL_TEXTURE0 >= FAKE_GL_UNITS)
        fake_gl_state_refused(call, unit);
    else
        *field = unit;
}

void STIN_APIENTRY fake_ActiveTexture(GLenum unit)
{
    COUNT(ActiveTexture);
    select_unit(&S.active_texture, unit, "glActiveTexture");
}

void STIN_APIENTRY fake_ClientActiveTexture(GLenum unit)
{
    COUNT(ClientActiveTexture);
    select_unit(&S.client_active_texture, unit, "glClientActiveTexture");
}

void STIN_APIENTRY fake_BindTexture(GLenum target, GLuint tex)
{
    int i = find(targets, FAKE_GL_TARGET_COUNT, target);
    COUNT(BindTexture);
    if (known(i, "glBindTexture", target))
        active_unit()->binding[i] = tex;
}

void STIN_APIENTRY fake_TexEnvi(GLenum target, GLenum pname, GLint param)
{
    fake_gl_texenv *e = &active_unit()->env;
    GLenum p = (GLenum)param;
    COUNT(TexEnvi);
    if (target != GL_TEXTURE_ENV) {
        fake_gl_state_untracked("glTexEnvi", target);
        return;
    }
    switch (pname) {
    case GL_TEXTURE_ENV_MODE: e->mode = p; break;
    case GL_COMBINE_RGB: e->combine_rgb = p; break;
    case GL_COMBINE_ALPHA: e->combine_alpha = p; break;
    case GL_RGB_SCALE: e->rgb_scale = (GLfloat)param; break;
    case FAKE_ALPHA_SCALE: e->alpha_scale = (GLfloat)param; break;
    case GL_SOURCE0_RGB: case GL_SOURCE1_RGB: case FAKE_SOURCE2_RGB:
        e->src_rgb[pname - GL_SOURCE0_RGB] = p;
        break;
    case GL_SOURCE0_ALPHA: case GL_SOURCE1_ALPHA: case FAKE_SOURCE2_ALPHA:
        e->src_alpha[pname - GL_SOURCE0_ALPHA] = p;
        break;
    case GL_OPERAND0_RGB: case GL_OPERAND1_RGB: case FAKE_OPERAND2_RGB:
        e->operand_rgb[pname - GL_OPERAND0_RGB] = p;
        break;
    case GL_OPERAND0_ALPHA: case GL_OPERAND1_ALPHA: case FAKE_OPERAND2_ALPHA:
        e->operand_alpha[pname - GL_OPERAND0_ALPHA] = p;
        break;
    default: fake_gl_state_untracked("glTexEnvi", pname); break;
    }
}

void STIN_APIENTRY fake_TexEnvfv(GLenum target, GLenum pname, const GLfloat *v)
{
    COUNT(TexEnvfv);
    if (target != GL_TEXTURE_ENV || pname != GL_TEXTURE_ENV_COLOR) {
        fake_gl_state_untracked("glTexEnvfv", target != GL_TEXTURE_ENV ? target : pname);
        return;
    }
    memcpy(active_unit()->env.color, v, sizeof active_unit()->env.color);
}

static int coord_of(GLenum coord, const char *call)
{
    if (coord < GL_S || coord > GL_Q) {
        fake_gl_state_refused(call, coord);
        return -1;
    }
    return (int)(coord - GL_S);
}

void STIN_APIENTRY fake_TexGeni(GLenum coord, GLenum pname, GLint param)
{
    int c = coord_of(coord, "glTexGeni");
    COUNT(TexGeni);
    if (c < 0)
        return;
    if (pname != GL_TEXTURE_GEN_MODE)
        fake_gl_state_untracked("glTexGeni", pname);
    else
        active_unit()->gen_mode[c] = (GLenum)param;
}

void STIN_APIENTRY fake_TexGenfv(GLenum coord, GLenum pname, const GLfloat *v)
{
    fake_gl_unit *u = active_unit();
    int c = coord_of(coord, "glTexGenfv"), j;
    GLfloat inv[16];
    COUNT(TexGenfv);
    if (c < 0)
        return;
    if (pname == FAKE_OBJECT_PLANE) {
        memcpy(u->object_plane[c], v, sizeof u->object_plane[c]);
    } else if (pname == GL_EYE_PLANE) {
        if (!stin__mat4_invert(inv, modelview_top())) { /* the library's, tested on its own */
            fake_gl_state_refused("glTexGenfv: singular modelview for", pname);
            return;
        }
        for (j = 0; j < 4; j++) /* p M^-1: the plane in eye space */
            u->eye_plane[c][j] = v[0] * inv[4 * j] + v[1] * inv[4 * j + 1] +
                                 v[2] * inv[4 * j + 2] + v[3] * inv[4 * j + 3];
    } else if (pname == GL_TEXTURE_GEN_MODE) {
        u->gen_mode[c] = (GLenum)v[0];
    } else {
        fake_gl_state_untracked("glTexGenfv", pname);
    }
}

/* ---- vertex arrays, buffers, programs, framebuffers ----------------------------- */
static void client_state(const char *call, GLenum array, GLuint on)
{
    switch (array) {
    case GL_VERTEX_ARRAY: S.vertex_array = on; break;
    case GL_NORMAL_ARRAY: S.normal_array = on; break;
    case FAKE_COLOR_ARRAY: S.color_array = on; break;
    case 0x8077: S.index_array = on; break;           /* GL_INDEX_ARRAY */
    case 0x8079: S.edge_flag_array = on; break;       /* GL_EDGE_FLAG_ARRAY */
    case 0x8457: S.fog_coord_array = on; break;       /* GL_FOG_COORD_ARRAY */
    case 0x845E: S.secondary_color_array = on; break; /* GL_SECONDARY_COLOR_ARRAY */
    case GL_TEXTURE_COORD_ARRAY:
        unit_of(S.client_active_texture, call)->texcoord_array = on;
        break;
    default: fake_gl_state_untracked(call, array); break;
    }
}

static void attrib_array(const char *call, GLuint i, GLuint on)
{
    if (i >= FAKE_GL_ATTRIBS)
        fake_gl_state_refused(call, i);
    else
        bound_vao()->attrib_array[i] = on;
}

void STIN_APIENTRY fake_BindBuffer(GLenum target, GLuint b)
{
    COUNT(BindBuffer);
    if (target == FAKE_PIXEL_UNPACK_BUFFER)
        S.pixel_unpack_buffer = b;
    else if (target == FAKE_PIXEL_PACK_BUFFER)
        S.pixel_pack_buffer = b;
    else if (target == FAKE_QUERY_BUFFER)
        S.query_buffer = b;
    else if (target == GL_ARRAY_BUFFER)
        S.array_buffer = b;
    else if (target == GL_ELEMENT_ARRAY_BUFFER)
        bound_vao()->element_buffer = b;
    else if (target == GL_SHADER_STORAGE_BUFFER)
        S.shader_storage_buffer = b;
    else if (target == GL_TRANSFORM_FEEDBACK_BUFFER)
        S.transform_feedback_buffer = b;
    else
        fake_gl_state_untracked("glBindBuffer", target);
}

/* Shader storage index 0 (deep's early-stop flag) and transform feedback
 * index 0 (vdsm's culling pass), with their generic bindings. */
void STIN_APIENTRY fake_BindBufferBase(GLenum target, GLuint index, GLuint b)
{
    COUNT(BindBufferBase);
    if (index == 0 && target == GL_SHADER_STORAGE_BUFFER) {
        S.shader_storage_buffer = b;
        S.shader_storage_buffer0 = b;
    } else if (index == 0 && target == GL_TRANSFORM_FEEDBACK_BUFFER) {
        S.transform_feedback_buffer = b;
        if (!S.transform_feedback)
            S.transform_feedback_buffer0 = b;
    } else
        fake_gl_state_untracked("glBindBufferBase", target);
}

void STIN_APIENTRY fake_BindTransformFeedback(GLenum target, GLuint id)
{
    COUNT(BindTransformFeedback);
    if (target != GL_TRANSFORM_FEEDBACK)
        fake_gl_state_untracked("glBindTransformFeedback", target);
    else
        S.transform_feedback = id;
}

void STIN_APIENTRY fake_BindFramebuffer(GLenum target, GLuint fb)
{
    COUNT(BindFramebuffer);
    if (target == GL_FRAMEBUFFER || target == FAKE_DRAW_FRAMEBUFFER)
        S.draw_framebuffer = fb;
    if (target == GL_FRAMEBUFFER || target == FAKE_READ_FRAMEBUFFER)
        S.read_framebuffer = fb;
    if (target != GL_FRAMEBUFFER && target != FAKE_DRAW_FRAMEBUFFER &&
        target != FAKE_READ_FRAMEBUFFER)
        fake_gl_state_refused("glBindFramebuffer", target);
}

/* Client-memory pointers are refused while a vertex array object is bound
 * (GL 3.x compatibility): a caller's VAO with no array buffer bound makes
 * them GL_INVALID_OPERATION. */
static void pointer_call(const char *call, const void *p)
{
    if (S.vertex_array_binding && !S.array_buffer && p)
        fake_gl_state_refused(call, S.vertex_array_binding);
}

void STIN_APIENTRY fake_VertexPointer(GLint size, GLenum type, GLsizei stride, const void *p)
{
    (void)size, (void)type, (void)stride;
    COUNT(VertexPointer);
    pointer_call("glVertexPointer with client memory in vertex array", p);
}

void STIN_APIENTRY fake_NormalPointer(GLenum type, GLsizei stride, const void *p)
{
    (void)type, (void)stride;
    COUNT(NormalPointer);
    pointer_call("glNormalPointer with client memory in vertex array", p);
}

void STIN_APIENTRY fake_TexCoordPointer(GLint size, GLenum type, GLsizei stride, const void *p)
{
    (void)size, (void)type, (void)stride;
    COUNT(TexCoordPointer);
    pointer_call("glTexCoordPointer with client memory in vertex array", p);
}

void STIN_APIENTRY fake_VertexAttribPointer(GLuint i, GLint size, GLenum type, GLboolean norm,
                                           GLsizei stride, const void *p)
{
    (void)i, (void)size, (void)type, (void)norm, (void)stride;
    COUNT(VertexAttribPointer);
    pointer_call("glVertexAttribPointer with client memory in vertex array", p);
}

int fake_gl_unpack_loose(void)
{
    return S.pixel_store[FAKE_GL_UNPACK_ROW_LENGTH] || S.pixel_store[FAKE_GL_UNPACK_SKIP_ROWS] ||
           S.pixel_store[FAKE_GL_UNPACK_SKIP_PIXELS] || S.pixel_unpack_buffer;
}

/* Draw and read buffers belong to the bound framebuffer: a framebuffer
 * object's are not kept (they are the object's state, not the context's). */
void STIN_APIENTRY fake_DrawBuffer(GLenum buf)
{
    COUNT(DrawBuffer);
    if (!S.draw_framebuffer)
        S.draw_buffer = buf;
}

void STIN_APIENTRY fake_ReadBuffer(GLenum buf)
{
    COUNT(ReadBuffer);
    if (!S.read_framebuffer)
        S.read_buffer = buf;
}

/* Deleting a bound object reverts its bindings in this context to 0. */
static void unbind(GLuint *binding, GLuint name)
{
    if (name && *binding == name)
        *binding = 0;
}

void fake_gl_state_deleted(fake_gl_object kind, GLsizei n, const GLuint *names)
{
    GLsizei k;
    int u, t;
    for (k = 0; k < n; k++) {
        GLuint name = names[k];
        switch (kind) {
        case FAKE_OBJ_TEXTURE:
            for (u = 0; u < FAKE_GL_UNITS; u++)
                for (t = 0; t < FAKE_GL_TARGET_COUNT; t++)
                    unbind(&S.units[u].binding[t], name);
            break;
        case FAKE_OBJ_BUFFER:
            unbind(&S.array_buffer, name);
            unbind(&S.pixel_unpack_buffer, name);
            unbind(&S.pixel_pack_buffer, name);
            unbind(&S.query_buffer, name);
            unbind(&S.shader_storage_buffer, name);
            unbind(&S.shader_storage_buffer0, name);
            unbind(&S.transform_feedback_buffer, name);
            unbind(&S.transform_feedback_buffer0, name);
            unbind(&bound_vao()->element_buffer, name);
            break;
        case FAKE_OBJ_VERTEX_ARRAY:
            unbind(&S.vertex_array_binding, name);
            for (u = 0; u < FAKE_GL_MAX_VAOS; u++)
                if (name && fake_gl.vaos[u].name == name)
                    memset(&fake_gl.vaos[u], 0, sizeof fake_gl.vaos[u]);
            break;
        case FAKE_OBJ_FRAMEBUFFER:
            unbind(&S.draw_framebuffer, name);
            unbind(&S.read_framebuffer, name);
            break;
        case FAKE_OBJ_TRANSFORM_FEEDBACK:
            unbind(&S.transform_feedback, name);
            break;
        }
    }
}

/* ---- glGetIntegerv of the kept state --------------------------------------------- */
static int get_ints(GLint *data, const GLint *v, int n)
{
    memcpy(data, v, (size_t)n * sizeof *v);
    return 1;
}

static int get_stencil(GLenum pname, GLint *data)
{
    /* the active face's (EXT_stencil_two_side), else front; GL 2.0's BACK_ names */
    static const GLenum front[7] = {0x0B92, 0x0B97, 0x0B93, 0x0B98, 0x0B94, 0x0B95, 0x0B96};
    static const GLenum back[7] = {0x8800, 0x8CA3, 0x8CA4, 0x8CA5, 0x8801, 0x8802, 0x8803};
    int i;
    for (i = 0; i < 7; i++)
        if (pname == front[i] || pname == back[i]) {
            const fake_gl_stencil *f =
                &S.stencil[pname == back[i] || S.active_stencil_face == GL_BACK];
            const GLint v[7] = {(GLint)f->func, f->ref,           (GLint)f->value_mask,
                                (GLint)f->writemask, (GLint)f->fail, (GLint)f->zfail,
                                (GLint)f->zpass};
            *data = v[i];
            return 1;
        }
    return 0;
}

int fake_gl_state_get(GLenum pname, GLint *data)
{
    const fake_gl_unit *u = active_unit();
    int i;
    switch (pname) {
    case GL_VIEWPORT: return get_ints(data, S.viewport, 4);
    case 0x0C10: return get_ints(data, S.scissor, 4); /* GL_SCISSOR_BOX */
    case GL_ACTIVE_TEXTURE: *data = (GLint)S.active_texture; return 1;
    case FAKE_CLIENT_ACTIVE_TEXTURE: *data = (GLint)S.client_active_texture; return 1;
    case FAKE_ACTIVE_STENCIL_FACE_EXT: *data = (GLint)S.active_stencil_face; return 1;
    case GL_CURRENT_PROGRAM: *data = (GLint)S.program; return 1;
    case FAKE_ARRAY_BUFFER_BINDING: *data = (GLint)S.array_buffer; return 1;
    case FAKE_ELEMENT_ARRAY_BUFFER_BINDING: *data = (GLint)bound_vao()->element_buffer; return 1;
    case FAKE_VERTEX_ARRAY_BINDING: *data = (GLint)S.vertex_array_binding; return 1;
    case FAKE_PIXEL_UNPACK_BUFFER_BINDING: *data = (GLint)S.pixel_unpack_buffer; return 1;
    case FAKE_PIXEL_PACK_BUFFER_BINDING: *data = (GLint)S.pixel_pack_buffer; return 1;
    case FAKE_QUERY_BUFFER_BINDING: *data = (GLint)S.query_buffer; return 1;
    case 0x8C1D: *data = (GLint)u->binding[FAKE_GL_TARGET_2D_ARRAY]; return 1; /* 2D array */
    /* the caller's state stin sets aside, at GL's defaults in the fake */
    case 0x825A: *data = 0; return 1;          /* GL_PROGRAM_PIPELINE_BINDING */
    case 0x8E4F: *data = 0x8E4E; return 1;     /* GL_PROVOKING_VERTEX: LAST */
    case 0x891B: case 0x891C: *data = 0x891D; return 1; /* GL_CLAMP_*_COLOR: FIXED_ONLY */
    case GL_DRAW_FRAMEBUFFER_BINDING: *data = (GLint)S.draw_framebuffer; return 1;
    case FAKE_READ_FRAMEBUFFER_BINDING: *data = (GLint)S.read_framebuffer; return 1;
    case FAKE_DRAW_BUFFER: *data = (GLint)S.draw_buffer; return 1;
    case FAKE_READ_BUFFER: *data = (GLint)S.read_buffer; return 1;
    case FAKE_TEXTURE_BINDING_1D: *data = (GLint)u->binding[FAKE_GL_TARGET_1D]; return 1;
    case GL_TEXTURE_BINDING_2D: *data = (GLint)u->binding[FAKE_GL_TARGET_2D]; return 1;
    case GL_TEXTURE_BINDING_CUBE_MAP: *data = (GLint)u->binding[FAKE_GL_TARGET_CUBE_MAP]; return 1;
    case 0x0B74: *data = (GLint)S.depth_func; return 1;         /* GL_DEPTH_FUNC */
    case 0x0B72: *data = (GLint)S.depth_mask; return 1;         /* GL_DEPTH_WRITEMASK */
    case 0x0C23: return get_ints(data, (const GLint *)S.color_mask, 4); /* GL_COLOR_WRITEMASK */
    case 0x0BE1: *data = (GLint)S.blend_src_rgb; return 1;      /* GL_BLEND_SRC */
    case 0x0BE0: *data = (GLint)S.blend_dst_rgb; return 1;      /* GL_BLEND_DST */
    case 0x0B45: *data = (GLint)S.cull_face; return 1;          /* GL_CULL_FACE_MODE */
    case 0x0B46: *data = (GLint)S.front_face; return 1;         /* GL_FRONT_FACE */
    case 0x0B54: *data = (GLint)S.shade_model; return 1;        /* GL_SHADE_MODEL */
    case 0x0BA0: *data = (GLint)S.matrix_mode; return 1;        /* GL_MATRIX_MODE */
    case 0x0BA3: *data = (GLint)S.modelview_depth; return 1;    /* GL_MODELVIEW_STACK_DEPTH */
    case 0x0BA4: *data = (GLint)S.projection_depth; return 1;   /* GL_PROJECTION_STACK_DEPTH */
    case 0x0BA5: *data = (GLint)u->matrix_depth; return 1;      /* GL_TEXTURE_STACK_DEPTH */
    case 0x0BC1: *data = (GLint)S.alpha_func; return 1;         /* GL_ALPHA_TEST_FUNC */
    case 0x8009: *data = (GLint)S.blend_equation; return 1;     /* GL_BLEND_EQUATION */
    case 0x8E72: *data = S.patch_vertices; return 1;            /* GL_PATCH_VERTICES */
    case 0x0B40: return get_ints(data, (const GLint *)S.polygon_mode, 2); /* GL_POLYGON_MODE */
    case 0x0B91: *data = S.clear_stencil; return 1;             /* GL_STENCIL_CLEAR_VALUE */
    default: break;
    }
    if (get_stencil(pname, data))
        return 1;
    i = find(pixel_store, FAKE_GL_PIXEL_STORE_COUNT, pname);
    if (i >= 0) {
        *data = S.pixel_store[i];
        return 1;
    }
    if (cap_slot(pname)) { /* glGetIntegerv(cap) is glIsEnabled(cap) */
        *data = fake_gl_is_enabled(pname);
        return 1;
    }
    return 0;
}
#undef S

/* ---- names and the diff ------------------------------------------------------------ */
static const struct {
    GLenum value;
    const char *name;
} enum_names[] = {
    {0x0200, "GL_NEVER"}, {0x0201, "GL_LESS"}, {0x0202, "GL_EQUAL"}, {0x0203, "GL_LEQUAL"},
    {0x0204, "GL_GREATER"}, {0x0205, "GL_NOTEQUAL"}, {0x0206, "GL_GEQUAL"}, {0x0207, "GL_ALWAYS"},
    {0x0300, "GL_SRC_COLOR"}, {0x0301, "GL_ONE_MINUS_SRC_COLOR"}, {0x0302, "GL_SRC_ALPHA"},
    {0x0303, "GL_ONE_MINUS_SRC_ALPHA"}, {0x0304, "GL_DST_ALPHA"},
    {0x0305, "GL_ONE_MINUS_DST_ALPHA"}, {0x0306, "GL_DST_COLOR"},
    {0x0307, "GL_ONE_MINUS_DST_COLOR"}, {0x0404, "GL_FRONT"}, {0x0405, "GL_BACK"},
    {0x0408, "GL_FRONT_AND_BACK"}, {0x0402, "GL_BACK_LEFT"}, {0x0900, "GL_CW"}, {0x0901, "GL_CCW"},
    {0x1D00, "GL_FLAT"}, {0x1D01, "GL_SMOOTH"}, {0x1700, "GL_MODELVIEW"},
    {0x1701, "GL_PROJECTION"}, {0x1702, "GL_TEXTURE"}, {0x1E00, "GL_KEEP"}, {0x1E01, "GL_REPLACE"},
    {0x1E02, "GL_INCR"}, {0x1E03, "GL_DECR"}, {0x150A, "GL_INVERT"}, {0x8507, "GL_INCR_WRAP"},
    {0x8508, "GL_DECR_WRAP"}, {0x2100, "GL_MODULATE"}, {0x2101, "GL_DECAL"}, {0x0BE2, "GL_BLEND"},
    {0x0104, "GL_ADD"}, {0x8570, "GL_COMBINE"}, {0x8574, "GL_ADD_SIGNED"},
    {0x8575, "GL_INTERPOLATE"}, {0x84E7, "GL_SUBTRACT"}, {0x86AE, "GL_DOT3_RGB"},
    {0x86AF, "GL_DOT3_RGBA"}, {0x8740, "GL_DOT3_RGB_EXT"}, {0x8741, "GL_DOT3_RGBA_EXT"},
    {0x8576, "GL_CONSTANT"}, {0x8577, "GL_PRIMARY_COLOR"}, {0x8578, "GL_PREVIOUS"},
    {0x2400, "GL_EYE_LINEAR"}, {0x2401, "GL_OBJECT_LINEAR"}, {0x2402, "GL_SPHERE_MAP"},
    {0x8511, "GL_NORMAL_MAP"}, {0x8512, "GL_REFLECTION_MAP"}, {0x81F9, "GL_SINGLE_COLOR"},
    {0x81FA, "GL_SEPARATE_SPECULAR_COLOR"}, {0x1200, "GL_AMBIENT"}, {0x1201, "GL_DIFFUSE"},
    {0x1202, "GL_SPECULAR"}, {0x1600, "GL_EMISSION"}, {0x1602, "GL_AMBIENT_AND_DIFFUSE"},
    {0x8CE0, "GL_COLOR_ATTACHMENT0"}, {0x8D40, "GL_FRAMEBUFFER"},
    {0x0DE0, "GL_TEXTURE_1D"}, {0x0DE1, "GL_TEXTURE_2D"}, {0x8513, "GL_TEXTURE_CUBE_MAP"},
    {0x8892, "GL_ARRAY_BUFFER"}, {0x8893, "GL_ELEMENT_ARRAY_BUFFER"},
};

const char *fake_gl_enum_name(GLenum e, char *buf, size_t size)
{
    size_t i;
    int k;
    for (i = 0; i < sizeof enum_names / sizeof enum_names[0]; i++)
        if (enum_names[i].value == e)
            return enum_names[i].name;
    if (e - GL_TEXTURE0 < 32u)
        snprintf(buf, size, "GL_TEXTURE%u", e - GL_TEXTURE0);
    else if (e - GL_LIGHT0 < 8u)
        snprintf(buf, size, "GL_LIGHT%u", e - GL_LIGHT0);
    else if ((k = find(caps, FAKE_GL_CAP_COUNT, e)) >= 0)
        return caps[k].name;
    else if ((k = find(unit_caps, FAKE_GL_UNIT_CAP_COUNT, e)) >= 0)
        return unit_caps[k].name;
    else if ((k = find(pixel_store, FAKE_GL_PIXEL_STORE_COUNT, e)) >= 0)
        return pixel_store[k].name;
    else
        snprintf(buf, size, "0x%X", e);
    return buf;
}

typedef struct differ {
    fake_gl_diff_fn fn;
    void *user;
    unsigned count;
    const char *prefix; /* "unit3.", "light0.", "" */
} differ;

typedef enum kind { K_ENUM, K_BOOL, K_INT, K_HEX } kind;

static void report(differ *d, const char *field, const char *a, const char *b)
{
    char name[96];
    d->count++;
    if (!d->fn)
        return;
    snprintf(name, sizeof name, "%s%s", d->prefix, field);
    d->fn(d->user, name, a, b);
}

static void format_word(char *buf, size_t size, kind k, GLuint v)
{
    char name[40];
    switch (k) {
    case K_ENUM:
        if (v <= 1) /* GL_ZERO/GL_NONE/GL_FALSE and GL_ONE read better as numbers */
            snprintf(buf, size, "%u", v);
        else
            snprintf(buf, size, "%s", fake_gl_enum_name(v, name, sizeof name));
        break;
    case K_BOOL: snprintf(buf, size, "%s", v ? "GL_TRUE" : "GL_FALSE"); break;
    case K_INT: snprintf(buf, size, "%d", (int)v); break;
    case K_HEX: snprintf(buf, size, "0x%X", v); break;
    }
}

static void word(differ *d, const char *field, kind k, GLuint a, GLuint b)
{
    char ta[48], tb[48];
    if (a == b)
        return;
    format_word(ta, sizeof ta, k, a);
    format_word(tb, sizeof tb, k, b);
    report(d, field, ta, tb);
}

static void format_floats(char *buf, size_t size, const GLfloat *v, int n)
{
    size_t used = 0;
    int i;
    for (i = 0; i < n && used < size; i++)
        used += (size_t)snprintf(buf + used, size - used, "%s%g%s", i ? " " : (n > 1 ? "(" : ""),
                                 (double)v[i], i == n - 1 && n > 1 ? ")" : "");
}

static void floats(differ *d, const char *field, const GLfloat *a, const GLfloat *b, int n)
{
    char ta[200], tb[200];
    int i;
    for (i = 0; i < n && a[i] == b[i]; i++)
        ;
    if (i == n)
        return;
    format_floats(ta, sizeof ta, a, n);
    format_floats(tb, sizeof tb, b, n);
    report(d, field, ta, tb);
}

static void words(differ *d, const char *field, kind k, const GLuint *a, const GLuint *b, int n)
{
    char name[64];
    int i;
    for (i = 0; i < n; i++) {
        snprintf(name, sizeof name, "%s[%d]", field, i);
        word(d, n > 1 ? name : field, k, a[i], b[i]);
    }
}

#define WORD(field, k) word(d, #field, k, (GLuint)a->field, (GLuint)b->field)
#define FLOATS(field, n) floats(d, #field, a->field, b->field, n)
#define FLOAT1(field) floats(d, #field, &a->field, &b->field, 1)

static void diff_stencil(differ *d, const fake_gl_stencil *a, const fake_gl_stencil *b)
{
    WORD(func, K_ENUM);
    WORD(ref, K_INT);
    WORD(value_mask, K_HEX);
    WORD(writemask, K_HEX);
    WORD(fail, K_ENUM);
    WORD(zfail, K_ENUM);
    WORD(zpass, K_ENUM);
}

static void with_prefix(differ *d, const char *fmt, int i)
{
    static char prefix[32];
    snprintf(prefix, sizeof prefix, fmt, i);
    d->prefix = prefix;
}

static void diff_env(differ *d, const fake_gl_texenv *a, const fake_gl_texenv *b)
{
    WORD(mode, K_ENUM);
    WORD(combine_rgb, K_ENUM);
    WORD(combine_alpha, K_ENUM);
    words(d, "src_rgb", K_ENUM, a->src_rgb, b->src_rgb, 3);
    words(d, "src_alpha", K_ENUM, a->src_alpha, b->src_alpha, 3);
    words(d, "operand_rgb", K_ENUM, a->operand_rgb, b->operand_rgb, 3);
    words(d, "operand_alpha", K_ENUM, a->operand_alpha, b->operand_alpha, 3);
    FLOAT1(rgb_scale);
    FLOAT1(alpha_scale);
    FLOATS(color, 4);
}

static void diff_unit(differ *d, int unit, const fake_gl_unit *a, const fake_gl_unit *b)
{
    static const char coord[4] = {'S', 'T', 'R', 'Q'};
    char name[64];
    int i;
    with_prefix(d, "unit%d.env.", unit);
    diff_env(d, &a->env, &b->env);
    with_prefix(d, "unit%d.", unit);
    for (i = 0; i < FAKE_GL_UNIT_CAP_COUNT; i++) {
        snprintf(name, sizeof name, "enable %s", unit_caps[i].name);
        word(d, name, K_BOOL, a->enabled[i], b->enabled[i]);
    }
    for (i = 0; i < FAKE_GL_TARGET_COUNT; i++) {
        snprintf(name, sizeof name, "binding %s", targets[i].name);
        word(d, name, K_INT, a->binding[i], b->binding[i]);
    }
    for (i = 0; i < 4; i++) {
        snprintf(name, sizeof name, "texgen %c mode", coord[i]);
        word(d, name, K_ENUM, a->gen_mode[i], b->gen_mode[i]);
        snprintf(name, sizeof name, "texgen %c eye plane", coord[i]);
        floats(d, name, a->eye_plane[i], b->eye_plane[i], 4);
        snprintf(name, sizeof name, "texgen %c object plane", coord[i]);
        floats(d, name, a->object_plane[i], b->object_plane[i], 4);
    }
    WORD(texcoord_array, K_BOOL);
    WORD(matrix_depth, K_INT);
    WORD(sampler, K_INT);
    for (i = 0; i < FAKE_GL_TEXTURE_DEPTH; i++) {
        snprintf(name, sizeof name, "texture matrix[%d]", i);
        floats(d, name, a->matrix[i], b->matrix[i], 16);
    }
}

static void diff_light(differ *d, const fake_gl_light *a, const fake_gl_light *b)
{
    FLOATS(ambient, 4);
    FLOATS(diffuse, 4);
    FLOATS(specular, 4);
    FLOATS(position, 4);
    FLOATS(spot_direction, 3);
    FLOAT1(spot_exponent);
    FLOAT1(spot_cutoff);
    FLOATS(attenuation, 3);
}

static void diff_material(differ *d, const fake_gl_material *a, const fake_gl_material *b)
{
    FLOATS(ambient, 4);
    FLOATS(diffuse, 4);
    FLOATS(specular, 4);
    FLOATS(emission, 4);
    FLOAT1(shininess);
}

static void diff_vao(differ *d, const fake_gl_vao *a, const fake_gl_vao *b)
{
    WORD(element_buffer, K_INT);
    words(d, "attrib_array", K_BOOL, a->attrib_array, b->attrib_array, FAKE_GL_ATTRIBS);
}

unsigned fake_gl_state_diff(const fake_gl_glstate *a, const fake_gl_glstate *b, fake_gl_diff_fn fn,
                            void *user)
{
    differ dd = {fn, user, 0, ""}, *d = &dd;
    char name[64];
    int i;
    for (i = 0; i < FAKE_GL_CAP_COUNT; i++) {
        snprintf(name, sizeof name, "enable %s", caps[i].name);
        word(d, name, K_BOOL, a->enabled[i], b->enabled[i]);
    }
    WORD(depth_func, K_ENUM);
    WORD(depth_mask, K_BOOL);
    words(d, "color_mask", K_BOOL, a->color_mask, b->color_mask, 4);
    WORD(blend_src_rgb, K_ENUM);
    WORD(blend_dst_rgb, K_ENUM);
    WORD(blend_src_alpha, K_ENUM);
    WORD(blend_dst_alpha, K_ENUM);
    WORD(blend_equation, K_ENUM);
    WORD(patch_vertices, K_INT);
    for (i = 0; i < 2; i++) {
        d->prefix = i ? "stencil back." : "stencil front.";
        diff_stencil(d, &a->stencil[i], &b->stencil[i]);
    }
    d->prefix = "";
    WORD(active_stencil_face, K_ENUM);
    WORD(alpha_func, K_ENUM);
    FLOAT1(alpha_ref);
    WORD(cull_face, K_ENUM);
    WORD(front_face, K_ENUM);
    WORD(shade_model, K_ENUM);
    words(d, "polygon_mode", K_ENUM, a->polygon_mode, b->polygon_mode, 2);
    FLOATS(depth_range, 2);
    FLOAT1(polygon_offset_factor);
    FLOAT1(polygon_offset_units);
    words(d, "scissor", K_INT, (const GLuint *)a->scissor, (const GLuint *)b->scissor, 4);
    words(d, "viewport", K_INT, (const GLuint *)a->viewport, (const GLuint *)b->viewport, 4);
    FLOATS(clear_color, 4);
    if (a->clear_depth != b->clear_depth) {
        char ta[32], tb[32];
        snprintf(ta, sizeof ta, "%g", a->clear_depth);
        snprintf(tb, sizeof tb, "%g", b->clear_depth);
        report(d, "clear_depth", ta, tb);
    }
    WORD(clear_stencil, K_INT);
    FLOATS(light_model_ambient, 4);
    WORD(light_model_local_viewer, K_BOOL);
    WORD(light_model_two_side, K_BOOL);
    WORD(light_model_color_control, K_ENUM);
    for (i = 0; i < FAKE_GL_LIGHTS; i++) {
        with_prefix(d, "light%d.", i);
        diff_light(d, &a->lights[i], &b->lights[i]);
    }
    for (i = 0; i < 2; i++) {
        d->prefix = i ? "material back." : "material front.";
        diff_material(d, &a->material[i], &b->material[i]);
    }
    d->prefix = "";
    WORD(color_material_face, K_ENUM);
    WORD(color_material_mode, K_ENUM);
    FLOATS(current_color, 4);
    WORD(matrix_mode, K_ENUM);
    WORD(modelview_depth, K_INT);
    WORD(projection_depth, K_INT);
    for (i = 0; i < FAKE_GL_MODELVIEW_DEPTH; i++) {
        snprintf(name, sizeof name, "modelview[%d]", i);
        floats(d, name, a->modelview[i], b->modelview[i], 16);
    }
    for (i = 0; i < FAKE_GL_PROJECTION_DEPTH; i++) {
        snprintf(name, sizeof name, "projection[%d]", i);
        floats(d, name, a->projection[i], b->projection[i], 16);
    }
    WORD(active_texture, K_ENUM);
    WORD(client_active_texture, K_ENUM);
    for (i = 0; i < FAKE_GL_UNITS; i++)
        diff_unit(d, i, &a->units[i], &b->units[i]);
    d->prefix = "";
    WORD(vertex_array, K_BOOL);
    WORD(normal_array, K_BOOL);
    WORD(color_array, K_BOOL);
    WORD(index_array, K_BOOL);
    WORD(edge_flag_array, K_BOOL);
    WORD(fog_coord_array, K_BOOL);
    WORD(secondary_color_array, K_BOOL);
    WORD(array_buffer, K_INT);
    WORD(vertex_array_binding, K_INT);
    WORD(pixel_unpack_buffer, K_INT);
    WORD(pixel_pack_buffer, K_INT);
    WORD(query_buffer, K_INT);
    WORD(shader_storage_buffer, K_INT);
    WORD(shader_storage_buffer0, K_INT);
    WORD(transform_feedback, K_INT);
    WORD(transform_feedback_buffer, K_INT);
    WORD(transform_feedback_buffer0, K_INT);
    d->prefix = "vao0.";
    diff_vao(d, &a->vao0, &b->vao0);
    d->prefix = "";
    WORD(program, K_INT);
    WORD(draw_framebuffer, K_INT);
    WORD(read_framebuffer, K_INT);
    WORD(draw_buffer, K_ENUM);
    WORD(read_buffer, K_ENUM);
    for (i = 0; i < FAKE_GL_PIXEL_STORE_COUNT; i++)
        word(d, pixel_store[i].name, K_INT, (GLuint)a->pixel_store[i], (GLuint)b->pixel_store[i]);
    for (i = 0; i < FAKE_GL_PIXEL_TRANSFER_COUNT; i++)
        floats(d, pixel_transfer[i].name, &a->pixel_transfer[i], &b->pixel_transfer[i], 1);
    return dd.count;
}
