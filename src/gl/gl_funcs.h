/* SPDX-License-Identifier: MIT */
/* Every GL entry point stin calls, as one X-macro list:
 *   X(return type, name without "gl", parameter list, what it needs, alternate name)
 * "needs" is a STIN_CAP_* or NEED_CORE (GL 1.1) / NEED_GL30 (GL 3.0) /
 * NEED_DESKTOP (GL 1.1, not on OpenGL ES) / NEED_ES (ES only) ...; an entry
 * point whose capability the context (after the caps mask) lacks must not be
 * called, and the checked build (STIN_GL_CHECK) fails a test that does.
 * The alternate name is tried when the core name does not resolve (ARB/EXT). */
#ifndef STIN_GL_FUNCS_H
#define STIN_GL_FUNCS_H

#define STIN_GL_FUNCS(X)                                                                  \
    /* GL 1.1 core */                                                                     \
    X(const GLubyte *, GetString, (GLenum name), NEED_CORE, "")                           \
    X(void, GetIntegerv, (GLenum pname, GLint *data), NEED_CORE, "")                      \
    X(void, GetFloatv, (GLenum pname, GLfloat *data), NEED_CORE, "")                      \
    X(void, GetTexLevelParameteriv, (GLenum target, GLint level, GLenum pname, GLint *v),  \
      NEED_CORE, "")                                                                       \
    X(void, Enable, (GLenum cap), NEED_CORE, "")                                          \
    X(void, LogicOp, (GLenum op), NEED_DESKTOP, "")                                          \
    X(void, Disable, (GLenum cap), NEED_CORE, "")                                         \
    X(void, Clear, (GLbitfield mask), NEED_CORE, "")                                      \
    X(void, ClearColor, (GLfloat r, GLfloat g, GLfloat b, GLfloat a), NEED_CORE, "")      \
    X(void, ClearDepth, (GLdouble d), NEED_DESKTOP, "")                                      \
    X(void, ClearStencil, (GLint s), NEED_CORE, "")                                       \
    X(void, Viewport, (GLint x, GLint y, GLsizei w, GLsizei h), NEED_CORE, "")            \
    X(void, DepthFunc, (GLenum func), NEED_CORE, "")                                      \
    X(void, DepthMask, (GLboolean flag), NEED_CORE, "")                                   \
    X(void, ColorMask, (GLboolean r, GLboolean g, GLboolean b, GLboolean a), NEED_CORE, "") \
    X(void, BlendFunc, (GLenum s, GLenum d), NEED_CORE, "")                               \
    X(void, CullFace, (GLenum mode), NEED_CORE, "")                                       \
    X(void, StencilMask, (GLuint mask), NEED_CORE, "")                                    \
    X(void, StencilFunc, (GLenum func, GLint ref, GLuint mask), NEED_CORE, "")            \
    X(void, StencilOp, (GLenum sfail, GLenum dpfail, GLenum dppass), NEED_CORE, "")       \
    X(void, Scissor, (GLint x, GLint y, GLsizei w, GLsizei h), NEED_CORE, "")             \
    X(void, FrontFace, (GLenum mode), NEED_CORE, "")                                      \
    X(void, DrawElements, (GLenum mode, GLsizei count, GLenum type, const void *idx), NEED_CORE, "") \
    X(void, DrawArrays, (GLenum mode, GLint first, GLsizei count), NEED_CORE, "")         \
    X(void, GenTextures, (GLsizei n, GLuint *tex), NEED_CORE, "")                         \
    X(void, DeleteTextures, (GLsizei n, const GLuint *tex), NEED_CORE, "")                \
    X(void, BindTexture, (GLenum target, GLuint tex), NEED_CORE, "")                      \
    X(void, TexImage2D, (GLenum target, GLint level, GLint ifmt, GLsizei w, GLsizei h,    \
                         GLint border, GLenum fmt, GLenum type, const void *pixels), NEED_CORE, "") \
    X(void, TexParameteri, (GLenum target, GLenum pname, GLint param), NEED_CORE, "")     \
    X(void, TexSubImage2D, (GLenum target, GLint level, GLint xo, GLint yo, GLsizei w,     \
                            GLsizei h, GLenum fmt, GLenum type, const void *pixels), NEED_CORE, "") \
    X(void, TexParameterfv, (GLenum target, GLenum pname, const GLfloat *v), NEED_CORE, "") \
    X(void, PixelStorei, (GLenum pname, GLint param), NEED_CORE, "")                      \
    X(void, Finish, (void), NEED_CORE, "")                                                \
    X(void, Flush, (void), NEED_CORE, "")                                                 \
    X(void, ReadPixels, (GLint x, GLint y, GLsizei w, GLsizei h, GLenum fmt, GLenum type,  \
                         void *pixels), NEED_CORE, "")                                    \
    X(void, PolygonOffset, (GLfloat factor, GLfloat units), NEED_CORE, "")                \
    X(void, DrawBuffer, (GLenum buf), NEED_DESKTOP, "")                                      \
    X(void, ReadBuffer, (GLenum buf), NEED_CORE, "")                                      \
    X(void, CopyTexSubImage2D, (GLenum target, GLint level, GLint xo, GLint yo, GLint x,  \
                                GLint y, GLsizei w, GLsizei h), NEED_CORE, "")            \
    X(void, TexImage1D, (GLenum target, GLint level, GLint ifmt, GLsizei w, GLint border, \
                         GLenum fmt, GLenum type, const void *pixels), NEED_DESKTOP, "")     \
    X(void, PolygonMode, (GLenum face, GLenum mode), NEED_DESKTOP, "")                       \
    X(void, DepthRange, (GLdouble n, GLdouble f), NEED_DESKTOP, "")                          \
    X(void, BlendEquation, (GLenum mode), NEED_GL14, "glBlendEquationEXT")                \
    /* OpenGL ES's float forms of glClearDepth and glDepthRange */                       \
    X(void, ClearDepthf, (GLfloat d), NEED_ES, "")                                        \
    X(void, DepthRangef, (GLfloat n, GLfloat f), NEED_ES, "")                              \
    X(void, BindSampler, (GLuint unit, GLuint sampler), NEED_GL33, "")                    \
    /* fixed function (compatibility contexts) */                                         \
    X(void, MatrixMode, (GLenum mode), STIN_CAP_FIXED_FUNCTION, "")                       \
    X(void, LoadMatrixf, (const GLfloat *m), STIN_CAP_FIXED_FUNCTION, "")                 \
    X(void, PushMatrix, (void), STIN_CAP_FIXED_FUNCTION, "")                              \
    X(void, PushAttrib, (GLbitfield mask), STIN_CAP_FIXED_FUNCTION, "")                   \
    X(void, PopAttrib, (void), STIN_CAP_FIXED_FUNCTION, "")                               \
    X(void, PopMatrix, (void), STIN_CAP_FIXED_FUNCTION, "")                               \
    X(void, RasterPos2f, (GLfloat x, GLfloat y), STIN_CAP_FIXED_FUNCTION, "")             \
    X(void, DrawPixels, (GLsizei w, GLsizei h, GLenum fmt, GLenum type, const void *pixels), \
      STIN_CAP_FIXED_FUNCTION, "")                                                        \
    X(void, Lightfv, (GLenum light, GLenum pname, const GLfloat *v), STIN_CAP_FIXED_FUNCTION, "") \
    X(void, Lightf, (GLenum light, GLenum pname, GLfloat v), STIN_CAP_FIXED_FUNCTION, "") \
    X(void, LightModelfv, (GLenum pname, const GLfloat *v), STIN_CAP_FIXED_FUNCTION, "")  \
    X(void, LightModeli, (GLenum pname, GLint v), STIN_CAP_FIXED_FUNCTION, "")            \
    X(void, Materialfv, (GLenum face, GLenum pname, const GLfloat *v), STIN_CAP_FIXED_FUNCTION, "") \
    X(void, Materialf, (GLenum face, GLenum pname, GLfloat v), STIN_CAP_FIXED_FUNCTION, "") \
    X(void, Color4f, (GLfloat r, GLfloat g, GLfloat b, GLfloat a), STIN_CAP_FIXED_FUNCTION, "") \
    X(void, Begin, (GLenum mode), STIN_CAP_FIXED_FUNCTION, "")                            \
    X(void, End, (void), STIN_CAP_FIXED_FUNCTION, "")                                     \
    X(void, Vertex3fv, (const GLfloat *v), STIN_CAP_FIXED_FUNCTION, "")                   \
    X(void, ShadeModel, (GLenum mode), STIN_CAP_FIXED_FUNCTION, "")                       \
    X(void, EnableClientState, (GLenum array), STIN_CAP_FIXED_FUNCTION, "")               \
    X(void, DisableClientState, (GLenum array), STIN_CAP_FIXED_FUNCTION, "")              \
    X(void, VertexPointer, (GLint size, GLenum type, GLsizei stride, const void *p), STIN_CAP_FIXED_FUNCTION, "") \
    X(void, NormalPointer, (GLenum type, GLsizei stride, const void *p), STIN_CAP_FIXED_FUNCTION, "") \
    X(void, TexCoordPointer, (GLint size, GLenum type, GLsizei stride, const void *p), STIN_CAP_FIXED_FUNCTION, "") \
    X(void, TexEnvi, (GLenum target, GLenum pname, GLint param), STIN_CAP_FIXED_FUNCTION, "") \
    X(void, TexEnvfv, (GLenum target, GLenum pname, const GLfloat *v), STIN_CAP_FIXED_FUNCTION, "") \
    X(void, TexGeni, (GLenum coord, GLenum pname, GLint param), STIN_CAP_FIXED_FUNCTION, "") \
    X(void, TexGenfv, (GLenum coord, GLenum pname, const GLfloat *v), STIN_CAP_FIXED_FUNCTION, "") \
    X(void, AlphaFunc, (GLenum func, GLfloat ref), STIN_CAP_FIXED_FUNCTION, "")           \
    X(void, PixelTransferf, (GLenum pname, GLfloat v), STIN_CAP_FIXED_FUNCTION, "")       \
    /* multitexture (GL 1.3 / ARB) */                                                     \
    X(void, ActiveTexture, (GLenum unit), STIN_CAP_MULTITEXTURE, "glActiveTextureARB")    \
    X(void, ClientActiveTexture, (GLenum unit), STIN_CAP_MULTITEXTURE, "glClientActiveTextureARB") \
    /* two-sided stencil: EXT_stencil_two_side, or GL 2.0 / ATI separate stencil */       \
    X(void, ActiveStencilFaceEXT, (GLenum face), STIN_CAP_STENCIL_TWO_SIDE, "")           \
    X(void, StencilOpSeparate, (GLenum face, GLenum sfail, GLenum dpfail, GLenum dppass), \
      STIN_CAP_SEPARATE_STENCIL, "glStencilOpSeparateATI")                                \
    /* buffers (GL 1.5 / ARB_vertex_buffer_object) */                                     \
    X(void, GenBuffers, (GLsizei n, GLuint *b), STIN_CAP_VBO, "glGenBuffersARB")          \
    X(void, DeleteBuffers, (GLsizei n, const GLuint *b), STIN_CAP_VBO, "glDeleteBuffersARB") \
    X(void, BindBuffer, (GLenum target, GLuint b), STIN_CAP_VBO, "glBindBufferARB")       \
    X(void, BufferData, (GLenum target, GLsizeiptr size, const void *data, GLenum usage), STIN_CAP_VBO, "glBufferDataARB") \
    /* GLSL (GL 2.0) */                                                                   \
    X(GLuint, CreateShader, (GLenum type), STIN_CAP_GLSL, "")                             \
    X(void, ShaderSource, (GLuint s, GLsizei n, const GLchar *const *src, const GLint *len), STIN_CAP_GLSL, "") \
    X(void, CompileShader, (GLuint s), STIN_CAP_GLSL, "")                                 \
    X(void, GetShaderiv, (GLuint s, GLenum pname, GLint *v), STIN_CAP_GLSL, "")           \
    X(void, GetShaderInfoLog, (GLuint s, GLsizei size, GLsizei *len, GLchar *log), STIN_CAP_GLSL, "") \
    X(void, DeleteShader, (GLuint s), STIN_CAP_GLSL, "")                                  \
    X(GLuint, CreateProgram, (void), STIN_CAP_GLSL, "")                                   \
    X(void, AttachShader, (GLuint p, GLuint s), STIN_CAP_GLSL, "")                        \
    X(void, BindAttribLocation, (GLuint p, GLuint index, const GLchar *name), STIN_CAP_GLSL, "") \
    X(void, LinkProgram, (GLuint p), STIN_CAP_GLSL, "")                                   \
    X(void, GetProgramiv, (GLuint p, GLenum pname, GLint *v), STIN_CAP_GLSL, "")          \
    X(void, GetProgramInfoLog, (GLuint p, GLsizei size, GLsizei *len, GLchar *log), STIN_CAP_GLSL, "") \
    X(void, DeleteProgram, (GLuint p), STIN_CAP_GLSL, "")                                 \
    X(void, UseProgram, (GLuint p), STIN_CAP_GLSL, "")                                    \
    X(GLint, GetUniformLocation, (GLuint p, const GLchar *name), STIN_CAP_GLSL, "")       \
    X(void, GetActiveUniform, (GLuint p, GLuint i, GLsizei size, GLsizei *len, GLint *count, \
                               GLenum *type, GLchar *name), STIN_CAP_GLSL, "")            \
    X(void, Uniform1i, (GLint loc, GLint v), STIN_CAP_GLSL, "")                           \
    X(void, Uniform1f, (GLint loc, GLfloat v), STIN_CAP_GLSL, "")                         \
    X(void, Uniform3fv, (GLint loc, GLsizei n, const GLfloat *v), STIN_CAP_GLSL, "")      \
    X(void, Uniform4fv, (GLint loc, GLsizei n, const GLfloat *v), STIN_CAP_GLSL, "")      \
    X(void, Uniform4iv, (GLint loc, GLsizei n, const GLint *v), STIN_CAP_GLSL, "")        \
    X(void, Uniform1iv, (GLint loc, GLsizei n, const GLint *v), STIN_CAP_GLSL, "")        \
    X(void, Uniform2uiv, (GLint loc, GLsizei n, const GLuint *v), NEED_GL30, "")          \
    X(void, Uniform4uiv, (GLint loc, GLsizei n, const GLuint *v), NEED_GL30, "")          \
    X(void, UniformMatrix3fv, (GLint loc, GLsizei n, GLboolean t, const GLfloat *v), STIN_CAP_GLSL, "") \
    X(void, UniformMatrix4fv, (GLint loc, GLsizei n, GLboolean t, const GLfloat *v), STIN_CAP_GLSL, "") \
    X(void, VertexAttribPointer, (GLuint i, GLint size, GLenum type, GLboolean norm,      \
                                  GLsizei stride, const void *p), STIN_CAP_GLSL, "")      \
    X(void, EnableVertexAttribArray, (GLuint i), STIN_CAP_GLSL, "")                       \
    X(void, DisableVertexAttribArray, (GLuint i), STIN_CAP_GLSL, "")                      \
    /* GL 3.0 */                                                                          \
    X(const GLubyte *, GetStringi, (GLenum name, GLuint i), NEED_GL30, "")                \
    X(void, GenVertexArrays, (GLsizei n, GLuint *a), STIN_CAP_VAO, "")                    \
    X(void, DeleteVertexArrays, (GLsizei n, const GLuint *a), STIN_CAP_VAO, "")           \
    X(void, BindVertexArray, (GLuint a), STIN_CAP_VAO, "")                                \
    X(void, BindFramebuffer, (GLenum target, GLuint fb), STIN_CAP_FBO, "glBindFramebufferEXT") \
    X(void, GenFramebuffers, (GLsizei n, GLuint *fb), STIN_CAP_FBO, "glGenFramebuffersEXT") \
    X(void, DeleteFramebuffers, (GLsizei n, const GLuint *fb), STIN_CAP_FBO, "glDeleteFramebuffersEXT") \
    X(void, FramebufferTexture2D, (GLenum target, GLenum att, GLenum textarget, GLuint tex, \
                                   GLint level), STIN_CAP_FBO, "glFramebufferTexture2DEXT") \
    X(GLenum, CheckFramebufferStatus, (GLenum target), STIN_CAP_FBO, "glCheckFramebufferStatusEXT") \
    X(GLboolean, IsFramebuffer, (GLuint fb), STIN_CAP_FBO, "glIsFramebufferEXT")           \
    /* GL 3.0, ARB_framebuffer_object or EXT_framebuffer_blit (target.separate_read) */    \
    X(void, BlitFramebuffer, (GLint sx0, GLint sy0, GLint sx1, GLint sy1, GLint dx0,       \
                              GLint dy0, GLint dx1, GLint dy1, GLbitfield mask,            \
                              GLenum filter), NEED_CHECKED, "glBlitFramebufferEXT")        \
    X(void, GenRenderbuffers, (GLsizei n, GLuint *rb), STIN_CAP_FBO, "glGenRenderbuffersEXT") \
    X(void, DeleteRenderbuffers, (GLsizei n, const GLuint *rb), STIN_CAP_FBO,             \
      "glDeleteRenderbuffersEXT")                                                          \
    X(void, BindRenderbuffer, (GLenum target, GLuint rb), STIN_CAP_FBO, "glBindRenderbufferEXT") \
    X(void, RenderbufferStorage, (GLenum target, GLenum internal, GLsizei w, GLsizei h),    \
      STIN_CAP_FBO, "glRenderbufferStorageEXT")                                            \
    X(void, FramebufferRenderbuffer, (GLenum target, GLenum att, GLenum rb_target, GLuint rb), \
      STIN_CAP_FBO, "glFramebufferRenderbufferEXT")                                        \
    X(void, GetFramebufferAttachmentParameteriv, (GLenum target, GLenum att, GLenum pname, \
                                                  GLint *v), NEED_GL30, "")               \
    X(void, GenerateMipmap, (GLenum target), STIN_CAP_FBO, "glGenerateMipmapEXT")         \
    X(void, DrawBuffers, (GLsizei n, const GLenum *bufs), STIN_CAP_GLSL, "")              \
    X(void, BindFragDataLocation, (GLuint p, GLuint color, const GLchar *name), NEED_GL30, "") \
    X(void, ClearBufferuiv, (GLenum buffer, GLint drawbuffer, const GLuint *value), NEED_GL30, "") \
    X(void, BeginQuery, (GLenum target, GLuint id), STIN_CAP_OCCLUSION_QUERY, "glBeginQueryARB") \
    X(void, EndQuery, (GLenum target), STIN_CAP_OCCLUSION_QUERY, "glEndQueryARB")          \
    X(void, GenQueries, (GLsizei n, GLuint *ids), STIN_CAP_OCCLUSION_QUERY, "glGenQueriesARB") \
    X(void, DeleteQueries, (GLsizei n, const GLuint *ids), STIN_CAP_OCCLUSION_QUERY,       \
      "glDeleteQueriesARB")                                                                \
    X(void, BlendEquationSeparate, (GLenum rgb, GLenum alpha), NEED_GL30, "")              \
    X(void, GetQueryObjectuiv, (GLuint id, GLenum pname, GLuint *v), STIN_CAP_OCCLUSION_QUERY, \
      "glGetQueryObjectuivARB")                                                            \
    X(void, GetQueryiv, (GLenum target, GLenum pname, GLint *v), STIN_CAP_OCCLUSION_QUERY, \
      "glGetQueryivARB")                                                                   \
    /* the caller's state set aside around stin's work (gl/caller_redirects.c) */          \
    X(GLboolean, IsEnabled, (GLenum cap), NEED_CORE, "")                                   \
    X(void, BindProgramPipeline, (GLuint pipeline), NEED_CHECKED, "")                      \
    X(void, ClampColor, (GLenum target, GLenum clamp), NEED_CHECKED, "glClampColorARB")    \
    X(void, ProvokingVertex, (GLenum mode), NEED_CHECKED, "glProvokingVertexEXT")          \
    /* GL 3.3 / ARB_timer_query (STIN_DEBUG_STAGE_TIMES) */                                \
    X(void, QueryCounter, (GLuint id, GLenum target), STIN_CAP_TIMER_QUERY, "")            \
    X(void, GetQueryObjectui64v, (GLuint id, GLenum pname, GLuint64 *v), STIN_CAP_TIMER_QUERY, \
      "")                                                                                  \
    /* GL 4.0 / ARB_tessellation_shader */                                                 \
    X(void, PatchParameteri, (GLenum pname, GLint value), STIN_CAP_TESSELLATION, "")                                            \
    /* deep shadow maps: layers of array textures */                                      \
    X(void, TexImage3D, (GLenum target, GLint level, GLint ifmt, GLsizei w, GLsizei h,     \
                         GLsizei d, GLint border, GLenum fmt, GLenum type, const void *p), \
      NEED_GL30, "")                                                                       \
    X(void, FramebufferTextureLayer, (GLenum target, GLenum att, GLuint tex, GLint level,  \
                                      GLint layer), NEED_GL30, "")                          \
    /* vdsm's culling pass: transform feedback (GL 3.0), drawn from its object (4.0) */   \
    X(void, TransformFeedbackVaryings, (GLuint p, GLsizei n, const GLchar *const *names,   \
                                        GLenum mode), NEED_GL30, "")                       \
    X(void, BeginTransformFeedback, (GLenum mode), NEED_GL30, "")                          \
    X(void, EndTransformFeedback, (void), NEED_GL30, "")                                   \
    X(void, BindBufferBase, (GLenum target, GLuint index, GLuint b), NEED_GL30, "")         \
    X(void, GenTransformFeedbacks, (GLsizei n, GLuint *ids), STIN_CAP_TRANSFORM_FEEDBACK,  \
      "")                                                                                  \
    X(void, DeleteTransformFeedbacks, (GLsizei n, const GLuint *ids),                      \
      STIN_CAP_TRANSFORM_FEEDBACK, "")                                                     \
    X(void, BindTransformFeedback, (GLenum target, GLuint id), STIN_CAP_TRANSFORM_FEEDBACK, \
      "")                                                                                  \
    X(void, DrawTransformFeedback, (GLenum mode, GLuint id), STIN_CAP_TRANSFORM_FEEDBACK,  \
      "")                                                                                  \
    /* deep's early stop by a shader storage flag (GL 4.3: SSBOs with compute); the     \
     * 16-bit index chunks' uploads (GL 1.5, ES 2.0: any buffer objects) */               \
    X(void, BufferSubData, (GLenum target, GLintptr off, GLsizeiptr size, const void *d),  \
      STIN_CAP_VBO, "glBufferSubDataARB")                                                   \
    X(void, GetBufferSubData, (GLenum target, GLintptr off, GLsizeiptr size, void *d),     \
      STIN_CAP_COMPUTE, "")                                                                 \
    X(void, MemoryBarrier, (GLbitfield barriers), STIN_CAP_COMPUTE, "")                   \
    X(void, ClearBufferData, (GLenum target, GLenum ifmt, GLenum fmt, GLenum type,         \
                              const void *d), STIN_CAP_COMPUTE, "")                         \
    /* vdsm's area lights on OpenGL ES: their bits ORed by image atomics (GL 4.2, ES     \
     * 3.1: images bind only immutable textures there) */                                 \
    X(void, TexStorage2D, (GLenum target, GLsizei levels, GLenum ifmt, GLsizei w,          \
                           GLsizei h), NEED_GL42, "")                                       \
    X(void, BindImageTexture, (GLuint unit, GLuint tex, GLint level, GLboolean layered,    \
                               GLint layer, GLenum access, GLenum format), NEED_GL42, "")

#endif
