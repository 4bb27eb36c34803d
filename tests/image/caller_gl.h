/* SPDX-License-Identifier: MIT */
/* The GL calls a test makes as the application would, resolved through the
 * platform (the same entry points stin gets), for the caller-state tests. */
#ifndef STIN_TESTS_CALLER_GL_H
#define STIN_TESTS_CALLER_GL_H

#include "stin_platform.h"

#include <stdint.h>

#include <GL/gl.h>
#include <GL/glext.h>

#define CALLER_GL_FUNCS(X)                                                                \
    X(void, Enable, (GLenum cap))                                                         \
    X(void, Disable, (GLenum cap))                                                        \
    X(GLboolean, IsEnabled, (GLenum cap))                                                 \
    X(void, GetIntegerv, (GLenum pname, GLint *v))                                        \
    X(void, GetFloatv, (GLenum pname, GLfloat *v))                                        \
    X(GLenum, GetError, (void))                                                           \
    X(void, BlendEquation, (GLenum mode))                                                 \
    X(void, BlendFunc, (GLenum s, GLenum d))                                              \
    X(void, PolygonMode, (GLenum face, GLenum mode))                                      \
    X(void, PolygonOffset, (GLfloat factor, GLfloat units))                               \
    X(void, LogicOp, (GLenum op))                                                         \
    X(void, DepthRange, (GLdouble n, GLdouble f))                                         \
    X(void, DepthFunc, (GLenum f))                                                        \
    X(void, DepthMask, (GLboolean m))                                                     \
    X(void, ColorMask, (GLboolean r, GLboolean g, GLboolean b, GLboolean a))             \
    X(void, CullFace, (GLenum mode))                                                      \
    X(void, FrontFace, (GLenum mode))                                                     \
    X(void, Scissor, (GLint x, GLint y, GLsizei w, GLsizei h))                            \
    X(void, StencilFunc, (GLenum f, GLint ref, GLuint mask))                              \
    X(void, StencilMask, (GLuint mask))                                                   \
    X(void, PrimitiveRestartIndex, (GLuint index))                                        \
    X(void, GenSamplers, (GLsizei n, GLuint *s))                                          \
    X(void, DeleteSamplers, (GLsizei n, const GLuint *s))                                 \
    X(void, BindSampler, (GLuint unit, GLuint s))                                         \
    X(void, SamplerParameteri, (GLuint s, GLenum pname, GLint v))                         \
    X(void, ActiveTexture, (GLenum unit))                                                 \
    X(void, GenTextures, (GLsizei n, GLuint *t))                                          \
    X(void, DeleteTextures, (GLsizei n, const GLuint *t))                                 \
    X(void, BindTexture, (GLenum target, GLuint t))                                       \
    X(void, TexImage2D, (GLenum target, GLint level, GLint ifmt, GLsizei w, GLsizei h,    \
                         GLint border, GLenum fmt, GLenum type, const void *pixels))      \
    X(void, TexParameteri, (GLenum target, GLenum pname, GLint v))                        \
    X(void, GetTexImage, (GLenum target, GLint level, GLenum fmt, GLenum type, void *px)) \
    X(GLuint, CreateShader, (GLenum type))                                                \
    X(void, ShaderSource, (GLuint s, GLsizei n, const GLchar *const *src, const GLint *len)) \
    X(void, CompileShader, (GLuint s))                                                    \
    X(GLuint, CreateProgram, (void))                                                      \
    X(void, AttachShader, (GLuint p, GLuint s))                                           \
    X(void, LinkProgram, (GLuint p))                                                      \
    X(void, GetProgramiv, (GLuint p, GLenum pname, GLint *v))                             \
    X(void, UseProgram, (GLuint p))                                                       \
    X(void, DeleteProgram, (GLuint p))                                                    \
    X(void, DeleteShader, (GLuint s))                                                     \
    X(void, BindAttribLocation, (GLuint p, GLuint index, const GLchar *name))             \
    X(GLint, GetUniformLocation, (GLuint p, const GLchar *name))                          \
    X(void, Uniform1i, (GLint loc, GLint v))                                              \
    X(void, Uniform1f, (GLint loc, GLfloat v))                                            \
    X(void, Uniform4f, (GLint loc, GLfloat x, GLfloat y, GLfloat z, GLfloat w))           \
    X(void, UniformMatrix4fv, (GLint loc, GLsizei n, GLboolean t, const GLfloat *m))      \
    X(void, GetShaderiv, (GLuint s, GLenum pname, GLint *v))                              \
    X(void, GetShaderInfoLog, (GLuint s, GLsizei size, GLsizei *len, GLchar *log))        \
    X(void, GetProgramInfoLog, (GLuint p, GLsizei size, GLsizei *len, GLchar *log))       \
    X(void, GenBuffers, (GLsizei n, GLuint *b))                                           \
    X(void, DeleteBuffers, (GLsizei n, const GLuint *b))                                  \
    X(void, BindBuffer, (GLenum target, GLuint b))                                        \
    X(void, BufferData, (GLenum target, GLsizeiptr size, const void *data, GLenum usage)) \
    X(void, BindBufferBase, (GLenum target, GLuint index, GLuint b))                      \
    X(void, GetIntegeri_v, (GLenum pname, GLuint index, GLint *v))                        \
    X(void, GenVertexArrays, (GLsizei n, GLuint *a))                                      \
    X(void, DeleteVertexArrays, (GLsizei n, const GLuint *a))                             \
    X(void, BindVertexArray, (GLuint a))                                                  \
    X(void, VertexAttribPointer, (GLuint i, GLint size, GLenum type, GLboolean norm,      \
                                  GLsizei stride, const void *p))                         \
    X(void, EnableVertexAttribArray, (GLuint i))                                          \
    X(void, DisableVertexAttribArray, (GLuint i))                                         \
    X(void, DrawArrays, (GLenum mode, GLint first, GLsizei count))                        \
    X(void, BindFramebuffer, (GLenum target, GLuint fb))                                  \
    X(void, GenFramebuffers, (GLsizei n, GLuint *fb))                                     \
    X(void, DeleteFramebuffers, (GLsizei n, const GLuint *fb))                            \
    X(void, FramebufferTexture2D, (GLenum target, GLenum attachment, GLenum textarget,    \
                                   GLuint texture, GLint level))                          \
    X(GLenum, CheckFramebufferStatus, (GLenum target))                                    \
    X(void, ReadPixels, (GLint x, GLint y, GLsizei w, GLsizei h, GLenum fmt, GLenum type, \
                         void *pixels))                                                   \
    X(void, Viewport, (GLint x, GLint y, GLsizei w, GLsizei h))                           \
    X(void, Clear, (GLbitfield mask))                                                     \
    X(void, ClearColor, (GLfloat r, GLfloat g, GLfloat b, GLfloat a))                     \
    X(void, ClearStencil, (GLint s))                                                      \
    X(const GLubyte *, GetString, (GLenum name))                                          \
    X(void, TexImage3D, (GLenum target, GLint level, GLint ifmt, GLsizei w, GLsizei h,    \
                         GLsizei d, GLint border, GLenum fmt, GLenum type, const void *p)) \
    X(void, GenQueries, (GLsizei n, GLuint *q))                                           \
    X(void, DeleteQueries, (GLsizei n, const GLuint *q))                                  \
    X(void, BeginQuery, (GLenum target, GLuint q))                                        \
    X(void, EndQuery, (GLenum target))                                                    \
    X(void, GetQueryiv, (GLenum target, GLenum pname, GLint *v))                          \
    X(void, GetQueryObjectuiv, (GLuint q, GLenum pname, GLuint *v))                       \
    X(GLuint, CreateShaderProgramv, (GLenum type, GLsizei n, const GLchar *const *src))   \
    X(void, GenProgramPipelines, (GLsizei n, GLuint *p))                                  \
    X(void, DeleteProgramPipelines, (GLsizei n, const GLuint *p))                         \
    X(void, BindProgramPipeline, (GLuint p))                                              \
    X(void, UseProgramStages, (GLuint p, GLbitfield stages, GLuint program))              \
    X(void, ClampColor, (GLenum target, GLenum clamp))                                    \
    X(void, ProvokingVertex, (GLenum mode))                                               \
    /* compatibility profile */                                                           \
    X(void, AlphaFunc, (GLenum f, GLclampf ref))                                          \
    X(void, ClipPlane, (GLenum plane, const GLdouble *eq))                                \
    X(void, PolygonStipple, (const GLubyte *mask))                                        \
    X(void, Fogi, (GLenum pname, GLint v))                                                \
    X(void, Fogf, (GLenum pname, GLfloat v))                                              \
    X(void, Fogfv, (GLenum pname, const GLfloat *v))                                      \
    X(void, MatrixMode, (GLenum mode))                                                    \
    X(void, LoadMatrixf, (const GLfloat *m))                                              \
    X(void, ColorMaterial, (GLenum face, GLenum mode))                                    \
    X(void, Color4f, (GLfloat r, GLfloat g, GLfloat b, GLfloat a))                        \
    X(void, TexGeni, (GLenum coord, GLenum pname, GLint v))                               \
    X(void, EnableClientState, (GLenum array))                                            \
    X(void, DisableClientState, (GLenum array))                                           \
    X(void, ColorPointer, (GLint size, GLenum type, GLsizei stride, const void *p))       \
    X(void, PixelTransferf, (GLenum pname, GLfloat v))                                    \
    X(void, Lightfv, (GLenum light, GLenum pname, const GLfloat *v))                      \
    X(void, Materialfv, (GLenum face, GLenum pname, const GLfloat *v))

typedef struct caller_gl {
#define CALLER_GL_X_(ret, name, params) ret(APIENTRY *name) params;
    CALLER_GL_FUNCS(CALLER_GL_X_)
#undef CALLER_GL_X_
} caller_gl;

/* Resolves every entry point the driver has (missing ones stay NULL). */
void caller_gl_load(caller_gl *gl, stin_platform *plat);
/* `core` of the program calls, the application's shading language: 0 GLSL
 * 1.10, 1 GLSL 1.50 (core profiles), CALLER_GL_ES GLSL ES 3.00 (OpenGL ES
 * 3.0+), CALLER_GL_ES2 GLSL ES 1.00 (OpenGL ES 2.0). The ES dialects declare
 * highp floats where the fragment stage has them, else mediump. */
#define CALLER_GL_ES 2
#define CALLER_GL_ES2 3
/* The dialect of a context made for profile p. */
int caller_gl_dialect(const stin_profile *p);
/* A linked program writing (r, g, b, 1) at clip-space positions from
 * attribute 0 ("p"); 0 if the context has no GLSL or linking fails. */
GLuint caller_gl_flat_program(const caller_gl *gl, int core, float r, float g, float b);
/* The same vertex shader with a fragment shader of `frag` after the
 * #version line and the dialect's preamble; it writes its colour to "c". */
GLuint caller_gl_program(const caller_gl *gl, int core, const char *frag);
/* A vertex buffer, and where the dialect has them (1.50, ES 3.00) a vertex
 * array object (else 0). */
void caller_gl_buffers(const caller_gl *gl, int core, GLuint *vbo, GLuint *vao);
/* Level 0 of an RGBA8 GL_TEXTURE_2D of w x h texels into `into` (RGBA,
 * rows bottom first): glGetTexImage on desktop GL, on ES (which has none)
 * glReadPixels from a framebuffer the texture is attached to; the
 * framebuffer binding is given back. 0 where neither can. */
int caller_gl_read_texture(const caller_gl *gl, int core, GLuint texture, int w, int h,
                           uint8_t *into);
/* Deletes what is not 0 of a program, buffer and vertex array; all 0 after. */
void caller_gl_delete(const caller_gl *gl, GLuint *program, GLuint *vbo, GLuint *vao);

#endif
