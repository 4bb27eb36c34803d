/* SPDX-License-Identifier: MIT */
/* The GL state the fake GL keeps (fake_gl.gl): what a real context holds
 * after the calls it was given, starting from the defaults of the GL 2.1
 * state tables, so that a test can snapshot it and compare it field by field:
 *
 *     fake_gl_glstate before = fake_gl.gl;
 *     ... stin calls ...
 *     fake_gl_state_diff(&before, &fake_gl.gl, report, user);  // one call per field
 *
 * Modelled as GL does: per-unit enables, bindings, texture environment,
 * texgen and texture matrices follow glActiveTexture, texture-coordinate
 * arrays follow glClientActiveTexture, the element-array binding and the
 * generic attribute enables belong to the bound vertex array object, draw
 * and read buffers to the bound framebuffer (only the default one's are
 * kept), light positions and directions are stored in eye space and eye
 * planes as p M^-1 with the modelview of the call, deleting a bound object
 * unbinds it, and the non-separate stencil calls set both faces from GL 2.0
 * on but only the active face (EXT_stencil_two_side) before.
 * A state call with an enum the fake does not model, or a glGetIntegerv it
 * cannot answer, is counted in fake_gl.untracked rather than ignored. */
#ifndef FAKE_GL_STATE_H
#define FAKE_GL_STATE_H

#include "gl/gl_types.h"
#include "gl/gl_funcs.h"

#define FAKE_GL_UNITS 32           /* texture units tracked (image units up to GL4) */
#define FAKE_GL_LIGHTS 8
#define FAKE_GL_ATTRIBS 16
#define FAKE_GL_MODELVIEW_DEPTH 32 /* GL's minimum stack depths */
#define FAKE_GL_PROJECTION_DEPTH 2
#define FAKE_GL_TEXTURE_DEPTH 2
#define FAKE_GL_ATTRIB_STACK_DEPTH 16 /* GL's minimum */
#define FAKE_GL_WINDOW_W 640       /* the default framebuffer: initial viewport and scissor box */
#define FAKE_GL_WINDOW_H 480

/* glEnable caps that are not per texture unit: X(name without GL_, value, initial) */
#define FAKE_GL_CAPS(X)                                                                   \
    X(ALPHA_TEST, 0x0BC0, 0) X(AUTO_NORMAL, 0x0D80, 0) X(BLEND, 0x0BE2, 0)                \
    X(CLIP_PLANE0, 0x3000, 0) X(CLIP_PLANE1, 0x3001, 0) X(CLIP_PLANE2, 0x3002, 0)         \
    X(CLIP_PLANE3, 0x3003, 0) X(CLIP_PLANE4, 0x3004, 0) X(CLIP_PLANE5, 0x3005, 0)         \
    X(CLIP_PLANE6, 0x3006, 0) X(CLIP_PLANE7, 0x3007, 0)                                   \
    X(COLOR_LOGIC_OP, 0x0BF2, 0) X(COLOR_MATERIAL, 0x0B57, 0) X(COLOR_SUM, 0x8458, 0)     \
    X(CULL_FACE, 0x0B44, 0) X(DEPTH_CLAMP, 0x864F, 0) X(DEPTH_TEST, 0x0B71, 0)            \
    X(DITHER, 0x0BD0, 1) X(FOG, 0x0B60, 0) X(FRAMEBUFFER_SRGB, 0x8DB9, 0)                 \
    X(LIGHT0, 0x4000, 0) X(LIGHT1, 0x4001, 0) X(LIGHT2, 0x4002, 0) X(LIGHT3, 0x4003, 0)   \
    X(LIGHT4, 0x4004, 0) X(LIGHT5, 0x4005, 0) X(LIGHT6, 0x4006, 0) X(LIGHT7, 0x4007, 0)   \
    X(LIGHTING, 0x0B50, 0) X(LINE_SMOOTH, 0x0B20, 0) X(LINE_STIPPLE, 0x0B24, 0)           \
    X(MULTISAMPLE, 0x809D, 1) X(NORMALIZE, 0x0BA1, 0) X(POINT_SMOOTH, 0x0B10, 0)          \
    X(POINT_SPRITE, 0x8861, 0) X(POLYGON_OFFSET_FILL, 0x8037, 0)                          \
    X(POLYGON_OFFSET_LINE, 0x2A02, 0) X(POLYGON_OFFSET_POINT, 0x2A01, 0)                  \
    X(POLYGON_SMOOTH, 0x0B41, 0) X(POLYGON_STIPPLE, 0x0B42, 0)                            \
    X(PRIMITIVE_RESTART, 0x8F9D, 0) X(PRIMITIVE_RESTART_FIXED_INDEX, 0x8D69, 0)           \
    X(PROGRAM_POINT_SIZE, 0x8642, 0) X(RASTERIZER_DISCARD, 0x8C89, 0)                     \
    X(RESCALE_NORMAL, 0x803A, 0) X(SAMPLE_ALPHA_TO_COVERAGE, 0x809E, 0)                   \
    X(SAMPLE_ALPHA_TO_ONE, 0x809F, 0) X(SAMPLE_COVERAGE, 0x80A0, 0)                       \
    X(SAMPLE_MASK, 0x8E51, 0)                                                             \
    X(SCISSOR_TEST, 0x0C11, 0) X(STENCIL_TEST, 0x0B90, 0)                                 \
    X(STENCIL_TEST_TWO_SIDE_EXT, 0x8910, 0) X(TEXTURE_CUBE_MAP_SEAMLESS, 0x884F, 0)       \
    X(VERTEX_PROGRAM_TWO_SIDE, 0x8643, 0)

/* glEnable caps of the active texture unit */
#define FAKE_GL_UNIT_CAPS(X)                                                              \
    X(TEXTURE_1D, 0x0DE0) X(TEXTURE_2D, 0x0DE1) X(TEXTURE_3D, 0x806F)                     \
    X(TEXTURE_CUBE_MAP, 0x8513) X(TEXTURE_GEN_S, 0x0C60) X(TEXTURE_GEN_T, 0x0C61)         \
    X(TEXTURE_GEN_R, 0x0C62) X(TEXTURE_GEN_Q, 0x0C63)

/* glBindTexture targets: X(name without GL_TEXTURE_, value) */
#define FAKE_GL_TARGETS(X) X(1D, 0x0DE0) X(2D, 0x0DE1) X(CUBE_MAP, 0x8513) X(2D_ARRAY, 0x8C1A)

/* glPixelStorei: X(name without GL_, value, initial) */
#define FAKE_GL_PIXEL_STORE(X)                                                            \
    X(UNPACK_SWAP_BYTES, 0x0CF0, 0) X(UNPACK_LSB_FIRST, 0x0CF1, 0)                        \
    X(UNPACK_ROW_LENGTH, 0x0CF2, 0) X(UNPACK_SKIP_ROWS, 0x0CF3, 0)                        \
    X(UNPACK_SKIP_PIXELS, 0x0CF4, 0) X(UNPACK_ALIGNMENT, 0x0CF5, 4)                       \
    X(UNPACK_IMAGE_HEIGHT, 0x806E, 0) X(UNPACK_SKIP_IMAGES, 0x806D, 0)                    \
    X(PACK_SWAP_BYTES, 0x0D00, 0) X(PACK_LSB_FIRST, 0x0D01, 0) X(PACK_ROW_LENGTH, 0x0D02, 0) \
    X(PACK_SKIP_ROWS, 0x0D03, 0) X(PACK_SKIP_PIXELS, 0x0D04, 0) X(PACK_ALIGNMENT, 0x0D05, 4) \
    X(PACK_IMAGE_HEIGHT, 0x806C, 0) X(PACK_SKIP_IMAGES, 0x806B, 0)

/* glPixelTransferf: X(name without GL_, value, initial) */
#define FAKE_GL_PIXEL_TRANSFER(X)                                                         \
    X(MAP_COLOR, 0x0D10, 0) X(MAP_STENCIL, 0x0D11, 0) X(INDEX_SHIFT, 0x0D12, 0)           \
    X(INDEX_OFFSET, 0x0D13, 0) X(RED_SCALE, 0x0D14, 1) X(RED_BIAS, 0x0D15, 0)             \
    X(GREEN_SCALE, 0x0D18, 1) X(GREEN_BIAS, 0x0D19, 0) X(BLUE_SCALE, 0x0D1A, 1)           \
    X(BLUE_BIAS, 0x0D1B, 0) X(ALPHA_SCALE, 0x0D1C, 1) X(ALPHA_BIAS, 0x0D1D, 0)            \
    X(DEPTH_SCALE, 0x0D1E, 1) X(DEPTH_BIAS, 0x0D1F, 0)

#define FAKE_X_ENUM_(name, ...) FAKE_GL_##name,
enum { FAKE_GL_CAPS(FAKE_X_ENUM_) FAKE_GL_CAP_COUNT };
enum { FAKE_GL_UNIT_CAPS(FAKE_X_ENUM_) FAKE_GL_UNIT_CAP_COUNT };
enum { FAKE_GL_PIXEL_STORE(FAKE_X_ENUM_) FAKE_GL_PIXEL_STORE_COUNT };
enum { FAKE_GL_PIXEL_TRANSFER(FAKE_X_ENUM_) FAKE_GL_PIXEL_TRANSFER_COUNT };
#undef FAKE_X_ENUM_
#define FAKE_X_ENUM_(name, value) FAKE_GL_TARGET_##name,
enum { FAKE_GL_TARGETS(FAKE_X_ENUM_) FAKE_GL_TARGET_COUNT };
#undef FAKE_X_ENUM_

/* Booleans are GLuint so that every field is a 4-byte word (no padding
 * inside the per-unit and per-light records). */
typedef struct fake_gl_stencil {
    GLenum func;
    GLint ref;
    GLuint value_mask, writemask;
    GLenum fail, zfail, zpass;
} fake_gl_stencil;

typedef struct fake_gl_texenv {
    GLenum mode, combine_rgb, combine_alpha;
    GLenum src_rgb[3], src_alpha[3], operand_rgb[3], operand_alpha[3];
    GLfloat rgb_scale, alpha_scale, color[4];
} fake_gl_texenv;

typedef struct fake_gl_unit {
    GLuint enabled[FAKE_GL_UNIT_CAP_COUNT];
    GLuint binding[FAKE_GL_TARGET_COUNT];
    fake_gl_texenv env;
    GLenum gen_mode[4];                    /* S, T, R, Q */
    GLfloat eye_plane[4][4], object_plane[4][4];
    GLuint texcoord_array;                 /* client state of this client unit */
    GLuint matrix_depth;
    GLfloat matrix[FAKE_GL_TEXTURE_DEPTH][16];
    GLuint sampler;                        /* glBindSampler (GL 3.3) */
} fake_gl_unit;

typedef struct fake_gl_light {
    GLfloat ambient[4], diffuse[4], specular[4], position[4]; /* position in eye space */
    GLfloat spot_direction[3], spot_exponent, spot_cutoff, attenuation[3];
} fake_gl_light;

typedef struct fake_gl_material {
    GLfloat ambient[4], diffuse[4], specular[4], emission[4], shininess;
} fake_gl_material;

/* State of a vertex array object (the default one lives in fake_gl_glstate). */
typedef struct fake_gl_vao {
    GLuint element_buffer;
    GLuint attrib_array[FAKE_GL_ATTRIBS];
} fake_gl_vao;

typedef struct fake_gl_glstate {
    GLuint enabled[FAKE_GL_CAP_COUNT];
    /* per-fragment operations */
    GLenum depth_func;
    GLuint depth_mask, color_mask[4];
    GLenum blend_src_rgb, blend_dst_rgb, blend_src_alpha, blend_dst_alpha;
    GLenum blend_equation;
    GLint patch_vertices;                  /* GL 4.0 */
    fake_gl_stencil stencil[2];            /* front, back */
    GLenum active_stencil_face;            /* EXT_stencil_two_side */
    GLenum alpha_func;
    GLfloat alpha_ref;
    /* rasterisation and the window */
    GLenum cull_face, front_face, shade_model;
    GLenum polygon_mode[2];                /* front, back */
    GLfloat depth_range[2];
    GLfloat polygon_offset_factor, polygon_offset_units;
    GLint scissor[4], viewport[4];
    GLfloat clear_color[4];
    GLdouble clear_depth;
    GLint clear_stencil;
    /* lighting */
    GLfloat light_model_ambient[4];
    GLuint light_model_local_viewer, light_model_two_side;
    GLenum light_model_color_control;
    fake_gl_light lights[FAKE_GL_LIGHTS];
    fake_gl_material material[2];          /* front, back */
    GLenum color_material_face, color_material_mode;
    GLfloat current_color[4];
    /* transformation */
    GLenum matrix_mode;
    GLuint modelview_depth, projection_depth;
    GLfloat modelview[FAKE_GL_MODELVIEW_DEPTH][16], projection[FAKE_GL_PROJECTION_DEPTH][16];
    /* texturing */
    GLenum active_texture, client_active_texture;
    fake_gl_unit units[FAKE_GL_UNITS];
    /* vertex arrays and buffers */
    GLuint vertex_array, normal_array, color_array;
    GLuint index_array, edge_flag_array, fog_coord_array, secondary_color_array;
    GLuint array_buffer, vertex_array_binding;
    GLuint pixel_unpack_buffer, pixel_pack_buffer, query_buffer;
    GLuint shader_storage_buffer, shader_storage_buffer0; /* generic, index 0 */
    /* the transform feedback object bound; its buffer's generic binding and
     * index 0 of the default object (a caller's feedback would land there) */
    GLuint transform_feedback, transform_feedback_buffer, transform_feedback_buffer0;
    fake_gl_vao vao0;
    /* programs, framebuffers, pixel transfer */
    GLuint program;
    GLuint draw_framebuffer, read_framebuffer;
    GLenum draw_buffer, read_buffer;       /* of the default framebuffer */
    GLint pixel_store[FAKE_GL_PIXEL_STORE_COUNT];
    GLfloat pixel_transfer[FAKE_GL_PIXEL_TRANSFER_COUNT];
} fake_gl_glstate;

/* GL's initial state (double-buffered default framebuffer of FAKE_GL_WINDOW_*). */
void fake_gl_state_init(fake_gl_glstate *s);

/* Calls `fn` once per field of `got` that differs from `expected`, with the
 * field's name ("unit3.binding GL_TEXTURE_2D", "light0.diffuse",
 * "enable GL_LIGHTING") and both values as text; returns the count. `fn` may
 * be NULL (count only). */
typedef void (*fake_gl_diff_fn)(void *user, const char *field, const char *expected,
                                const char *got);
unsigned fake_gl_state_diff(const fake_gl_glstate *expected, const fake_gl_glstate *got,
                            fake_gl_diff_fn fn, void *user);

/* "GL_LEQUAL", "GL_TEXTURE3", or the value in hex. */
const char *fake_gl_enum_name(GLenum e, char *buf, size_t size);

/* ---- shared by fake_gl.c and fake_gl_state.c only ---------------------------- */
#ifdef FAKE_GL_STUBS
/* FAKE_STATE_<Name>: the entry point is written out in fake_gl_state.c (it
 * changes tracked state). FAKE_IS_STATE(name) is 1 for those, else 0. An
 * entry point added to gl_funcs.h gets a generated no-op; if it changes
 * state, mark it here and write it out there (test_state reports a call to
 * a generated no-op that fake_gl.c does not mark FAKE_STATELESS_). */
#define FAKE_STATE_Enable ~, 1
#define FAKE_STATE_Disable ~, 1
#define FAKE_STATE_ClearColor ~, 1
#define FAKE_STATE_ClearDepth ~, 1
#define FAKE_STATE_ClearStencil ~, 1
#define FAKE_STATE_Viewport ~, 1
#define FAKE_STATE_DepthFunc ~, 1
#define FAKE_STATE_DepthMask ~, 1
#define FAKE_STATE_ColorMask ~, 1
#define FAKE_STATE_BlendFunc ~, 1
#define FAKE_STATE_CullFace ~, 1
#define FAKE_STATE_StencilMask ~, 1
#define FAKE_STATE_StencilFunc ~, 1
#define FAKE_STATE_StencilOp ~, 1
#define FAKE_STATE_Scissor ~, 1
#define FAKE_STATE_FrontFace ~, 1
#define FAKE_STATE_BindTexture ~, 1
#define FAKE_STATE_PixelStorei ~, 1
#define FAKE_STATE_PolygonOffset ~, 1
#define FAKE_STATE_DrawBuffer ~, 1
#define FAKE_STATE_ReadBuffer ~, 1
#define FAKE_STATE_MatrixMode ~, 1
#define FAKE_STATE_LoadMatrixf ~, 1
#define FAKE_STATE_PushMatrix ~, 1
#define FAKE_STATE_PopMatrix ~, 1
#define FAKE_STATE_Lightfv ~, 1
#define FAKE_STATE_Lightf ~, 1
#define FAKE_STATE_LightModelfv ~, 1
#define FAKE_STATE_LightModeli ~, 1
#define FAKE_STATE_Materialfv ~, 1
#define FAKE_STATE_Materialf ~, 1
#define FAKE_STATE_Color4f ~, 1
#define FAKE_STATE_ShadeModel ~, 1
#define FAKE_STATE_EnableClientState ~, 1
#define FAKE_STATE_DisableClientState ~, 1
#define FAKE_STATE_TexEnvi ~, 1
#define FAKE_STATE_TexEnvfv ~, 1
#define FAKE_STATE_TexGeni ~, 1
#define FAKE_STATE_TexGenfv ~, 1
#define FAKE_STATE_AlphaFunc ~, 1
#define FAKE_STATE_ActiveTexture ~, 1
#define FAKE_STATE_ClientActiveTexture ~, 1
#define FAKE_STATE_ActiveStencilFaceEXT ~, 1
#define FAKE_STATE_StencilOpSeparate ~, 1
#define FAKE_STATE_BindBuffer ~, 1
#define FAKE_STATE_BindBufferBase ~, 1
#define FAKE_STATE_BindTransformFeedback ~, 1
#define FAKE_STATE_UseProgram ~, 1
#define FAKE_STATE_EnableVertexAttribArray ~, 1
#define FAKE_STATE_DisableVertexAttribArray ~, 1
#define FAKE_STATE_BindVertexArray ~, 1
#define FAKE_STATE_BindFramebuffer ~, 1
#define FAKE_STATE_VertexPointer ~, 1 /* refused with a VAO bound and no buffer */
#define FAKE_STATE_NormalPointer ~, 1
#define FAKE_STATE_TexCoordPointer ~, 1
#define FAKE_STATE_VertexAttribPointer ~, 1
#define FAKE_STATE_PolygonMode ~, 1
#define FAKE_STATE_DepthRange ~, 1
#define FAKE_STATE_BlendEquation ~, 1
#define FAKE_STATE_PatchParameteri ~, 1
#define FAKE_STATE_BindSampler ~, 1
#define FAKE_STATE_PixelTransferf ~, 1
#define FAKE_STATE_GetFloatv ~, 1
#define FAKE_STATE_PushAttrib ~, 1 /* fake_gl_attrib.c */
#define FAKE_STATE_PopAttrib ~, 1

/* "Is FAKE_<KIND>_<name> defined as '~, 1'?" as 0 or 1, usable by ## */
#define FAKE_SECOND(a, b, ...) b
#define FAKE_PROBE(...) FAKE_SECOND(__VA_ARGS__, 0, ~)
#define FAKE_IS_STATE(name) FAKE_PROBE(FAKE_STATE_##name)
#define FAKE_CAT(a, b) FAKE_CAT_(a, b)
#define FAKE_CAT_(a, b) a##b

#define FAKE_STATE_PROTO_0(ret, name, params)
#define FAKE_STATE_PROTO_1(ret, name, params) ret STIN_APIENTRY fake_##name params;
#define FAKE_STATE_PROTO(ret, name, params, need, alt) \
    FAKE_CAT(FAKE_STATE_PROTO_, FAKE_IS_STATE(name))(ret, name, params)
STIN_GL_FUNCS(FAKE_STATE_PROTO)

#define COUNT(name) (fake_gl.calls[STIN_GLFN_##name]++)

/* Hooks of fake_gl.c's object and query stubs into the tracked state. */
typedef enum fake_gl_object {
    FAKE_OBJ_TEXTURE,
    FAKE_OBJ_BUFFER,
    FAKE_OBJ_VERTEX_ARRAY,
    FAKE_OBJ_FRAMEBUFFER,
    FAKE_OBJ_TRANSFORM_FEEDBACK
} fake_gl_object;
void fake_gl_state_deleted(fake_gl_object kind, GLsizei n, const GLuint *names);
int fake_gl_state_get(GLenum pname, GLint *data); /* 0: not a state the fake keeps */
void fake_gl_state_untracked(const char *call, GLenum e);
/* A call a real GL would refuse with an error: counted in fake_gl.gl_errors. */
void fake_gl_state_refused(const char *call, GLenum e);
void fake_gl_state_reset(void);
#endif

#endif
