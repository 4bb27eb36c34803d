/* SPDX-License-Identifier: MIT */
/*
 * The few GL types, enums and entry points the bench's raw-GL loop uses.
 * Copied here rather than taken from a system GL header so that stin-bench
 * links no libGL: every entry point is resolved at run time through
 * stin_platform_get_proc_address, like libstin's own.
 */
#ifndef STIN_BENCH_RAW_GL_H
#define STIN_BENCH_RAW_GL_H

#include <stddef.h>

typedef unsigned int GLenum;
typedef unsigned char GLboolean;
typedef unsigned int GLbitfield;
typedef int GLint;
typedef int GLsizei;
typedef unsigned int GLuint;
typedef float GLfloat;
typedef char GLchar;
typedef unsigned char GLubyte;
typedef ptrdiff_t GLsizeiptr;

#define GL_FALSE 0
#define GL_TRUE 1
#define GL_TRIANGLES 0x0004
#define GL_LESS 0x0201
#define GL_FRONT_AND_BACK 0x0408
#define GL_LIGHTING 0x0B50
#define GL_LIGHT_MODEL_LOCAL_VIEWER 0x0B51
#define GL_LIGHT_MODEL_TWO_SIDE 0x0B52
#define GL_LIGHT_MODEL_AMBIENT 0x0B53
#define GL_DEPTH_TEST 0x0B71
#define GL_NORMALIZE 0x0BA1
#define GL_BLEND 0x0BE2
#define GL_STENCIL_BITS 0x0D57
#define GL_TEXTURE_2D 0x0DE1
#define GL_AMBIENT 0x1200
#define GL_DIFFUSE 0x1201
#define GL_SPECULAR 0x1202
#define GL_POSITION 0x1203
#define GL_SPOT_DIRECTION 0x1204
#define GL_SPOT_EXPONENT 0x1205
#define GL_SPOT_CUTOFF 0x1206
#define GL_CONSTANT_ATTENUATION 0x1207
#define GL_LINEAR_ATTENUATION 0x1208
#define GL_QUADRATIC_ATTENUATION 0x1209
#define GL_UNSIGNED_INT 0x1405
#define GL_FLOAT 0x1406
#define GL_EMISSION 0x1600
#define GL_SHININESS 0x1601
#define GL_AMBIENT_AND_DIFFUSE 0x1602
#define GL_MODELVIEW 0x1700
#define GL_PROJECTION 0x1701
#define GL_SMOOTH 0x1D01
#define GL_RENDERER 0x1F01
#define GL_VERSION 0x1F02
#define GL_LIGHT0 0x4000
#define GL_VERTEX_ARRAY 0x8074
#define GL_NORMAL_ARRAY 0x8075
#define GL_TEXTURE_COORD_ARRAY 0x8078
#define GL_LIGHT_MODEL_COLOR_CONTROL 0x81F8
#define GL_SEPARATE_SPECULAR_COLOR 0x81FA
#define GL_SINGLE_COLOR 0x81F9
#define GL_ARRAY_BUFFER 0x8892
#define GL_ELEMENT_ARRAY_BUFFER 0x8893
#define GL_STATIC_DRAW 0x88E4
#define GL_FRAGMENT_SHADER 0x8B30
#define GL_VERTEX_SHADER 0x8B31
#define GL_COMPILE_STATUS 0x8B81
#define GL_LINK_STATUS 0x8B82
#define GL_DEPTH_BUFFER_BIT 0x00000100
#define GL_STENCIL_BUFFER_BIT 0x00000400
#define GL_COLOR_BUFFER_BIT 0x00004000

/* Which raw paths need an entry point: a missing one fails only those
 * (FIXED: the GL1 loop's fixed function, which OpenGL ES lacks). */
enum { RAW_NEED_CORE = 1, RAW_NEED_VBO = 2, RAW_NEED_GLSL = 4, RAW_NEED_VAO = 8,
       RAW_NEED_FIXED = 16 };

/* X(return type, name without "gl", parameters, need) */
#define RAW_GL_FUNCS(X)                                                                    \
    X(void, Viewport, (GLint, GLint, GLsizei, GLsizei), RAW_NEED_CORE)                     \
    X(void, ClearColor, (GLfloat, GLfloat, GLfloat, GLfloat), RAW_NEED_CORE)               \
    X(void, Clear, (GLbitfield), RAW_NEED_CORE)                                            \
    X(void, Enable, (GLenum), RAW_NEED_CORE)                                               \
    X(void, Disable, (GLenum), RAW_NEED_CORE)                                              \
    X(void, DepthFunc, (GLenum), RAW_NEED_CORE)                                            \
    X(void, DepthMask, (GLboolean), RAW_NEED_CORE)                                         \
    X(void, Finish, (void), RAW_NEED_CORE)                                                 \
    X(const GLubyte *, GetString, (GLenum), RAW_NEED_CORE)                                 \
    X(void, GetIntegerv, (GLenum, GLint *), RAW_NEED_CORE)                                 \
    X(GLenum, GetError, (void), RAW_NEED_CORE)                                             \
    X(void, DrawElements, (GLenum, GLsizei, GLenum, const void *), RAW_NEED_CORE)          \
    X(void, MatrixMode, (GLenum), RAW_NEED_FIXED)                                          \
    X(void, LoadMatrixf, (const GLfloat *), RAW_NEED_FIXED)                                \
    X(void, ShadeModel, (GLenum), RAW_NEED_FIXED)                                          \
    X(void, Lightfv, (GLenum, GLenum, const GLfloat *), RAW_NEED_FIXED)                    \
    X(void, Lightf, (GLenum, GLenum, GLfloat), RAW_NEED_FIXED)                             \
    X(void, LightModelfv, (GLenum, const GLfloat *), RAW_NEED_FIXED)                       \
    X(void, LightModeli, (GLenum, GLint), RAW_NEED_FIXED)                                  \
    X(void, Materialfv, (GLenum, GLenum, const GLfloat *), RAW_NEED_FIXED)                 \
    X(void, Materialf, (GLenum, GLenum, GLfloat), RAW_NEED_FIXED)                          \
    X(void, EnableClientState, (GLenum), RAW_NEED_FIXED)                                   \
    X(void, DisableClientState, (GLenum), RAW_NEED_FIXED)                                  \
    X(void, VertexPointer, (GLint, GLenum, GLsizei, const void *), RAW_NEED_FIXED)         \
    X(void, NormalPointer, (GLenum, GLsizei, const void *), RAW_NEED_FIXED)                \
    X(void, TexCoordPointer, (GLint, GLenum, GLsizei, const void *), RAW_NEED_FIXED)       \
    X(void, GenBuffers, (GLsizei, GLuint *), RAW_NEED_VBO)                                 \
    X(void, DeleteBuffers, (GLsizei, const GLuint *), RAW_NEED_VBO)                        \
    X(void, BindBuffer, (GLenum, GLuint), RAW_NEED_VBO)                                    \
    X(void, BufferData, (GLenum, GLsizeiptr, const void *, GLenum), RAW_NEED_VBO)          \
    X(GLuint, CreateShader, (GLenum), RAW_NEED_GLSL)                                       \
    X(void, ShaderSource, (GLuint, GLsizei, const GLchar *const *, const GLint *),         \
      RAW_NEED_GLSL)                                                                       \
    X(void, CompileShader, (GLuint), RAW_NEED_GLSL)                                        \
    X(void, GetShaderiv, (GLuint, GLenum, GLint *), RAW_NEED_GLSL)                         \
    X(void, GetShaderInfoLog, (GLuint, GLsizei, GLsizei *, GLchar *), RAW_NEED_GLSL)       \
    X(void, DeleteShader, (GLuint), RAW_NEED_GLSL)                                         \
    X(GLuint, CreateProgram, (void), RAW_NEED_GLSL)                                        \
    X(void, AttachShader, (GLuint, GLuint), RAW_NEED_GLSL)                                 \
    X(void, BindAttribLocation, (GLuint, GLuint, const GLchar *), RAW_NEED_GLSL)           \
    X(void, LinkProgram, (GLuint), RAW_NEED_GLSL)                                          \
    X(void, GetProgramiv, (GLuint, GLenum, GLint *), RAW_NEED_GLSL)                        \
    X(void, GetProgramInfoLog, (GLuint, GLsizei, GLsizei *, GLchar *), RAW_NEED_GLSL)      \
    X(void, DeleteProgram, (GLuint), RAW_NEED_GLSL)                                        \
    X(void, UseProgram, (GLuint), RAW_NEED_GLSL)                                           \
    X(GLint, GetUniformLocation, (GLuint, const GLchar *), RAW_NEED_GLSL)                  \
    X(void, Uniform1i, (GLint, GLint), RAW_NEED_GLSL)                                      \
    X(void, Uniform1f, (GLint, GLfloat), RAW_NEED_GLSL)                                    \
    X(void, Uniform3fv, (GLint, GLsizei, const GLfloat *), RAW_NEED_GLSL)                  \
    X(void, Uniform4fv, (GLint, GLsizei, const GLfloat *), RAW_NEED_GLSL)                  \
    X(void, UniformMatrix3fv, (GLint, GLsizei, GLboolean, const GLfloat *), RAW_NEED_GLSL) \
    X(void, UniformMatrix4fv, (GLint, GLsizei, GLboolean, const GLfloat *), RAW_NEED_GLSL) \
    X(void, EnableVertexAttribArray, (GLuint), RAW_NEED_GLSL)                              \
    X(void, DisableVertexAttribArray, (GLuint), RAW_NEED_GLSL)                             \
    X(void, VertexAttribPointer, (GLuint, GLint, GLenum, GLboolean, GLsizei, const void *), \
      RAW_NEED_GLSL)                                                                       \
    X(void, GenVertexArrays, (GLsizei, GLuint *), RAW_NEED_VAO)                            \
    X(void, DeleteVertexArrays, (GLsizei, const GLuint *), RAW_NEED_VAO)                   \
    X(void, BindVertexArray, (GLuint), RAW_NEED_VAO)

typedef struct raw_gl {
#define RAW_X_(ret, name, params, need) ret (*name) params;
    RAW_GL_FUNCS(RAW_X_)
#undef RAW_X_
} raw_gl;

/* Resolves every entry point through get_proc (the ARB name as a fallback for
 * buffer objects on GL 1.4 + ARB_vertex_buffer_object); missing ones stay NULL. */
void raw_gl_load(raw_gl *gl, void *(*get_proc)(void *user, const char *name), void *user);
/* Name of the first entry point that `need` (RAW_NEED_* bits) requires and
 * that did not load, or NULL when all did. */
const char *raw_gl_missing(const raw_gl *gl, int need);

#endif
