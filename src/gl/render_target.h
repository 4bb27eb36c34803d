/* SPDX-License-Identifier: MIT */
/* Off-screen render targets (gl/render_target.c): the screen-sized textures,
 * the shadow maps and the framebuffers the render and feature passes draw
 * into, made one way. */
#ifndef STIN_RENDER_TARGET_H
#define STIN_RENDER_TARGET_H

#include "stin/stin.h"
#include "gl/gl_types.h"

/* Binds `tex` on the active unit and gives it nearest filtering, edge
 * clamping and a w x h level 0 of `internal` (no data: format, type). Leaves
 * it bound; the caller chooses the unit and unbinds. */
void stin__rt_texture(struct stin_context *ctx, GLuint tex, GLenum internal, GLenum format,
                      GLenum type, int w, int h);

/* Binds `tex` on the active unit as a w x h DEPTH_COMPONENT24 shadow map
 * (no data): edge clamped, compared LEQUAL against the lookup's r and
 * filtered LINEAR, the hardware's 2x2 PCF where it has one. Leaves it
 * bound. */
void stin__rt_shadow_map(struct stin_context *ctx, GLuint tex, int w, int h);

/* 24-bit depth's step: glPolygonOffset's r in the sized depth textures. */
#define STIN__DEPTH24_UNIT (1.0f / 16777216.0f)
/* With a framebuffer bound whose depth attachment is an unsized depth
 * texture (OpenGL ES 2.0's OES_depth_texture, which takes the bits the
 * driver gives: Mesa 32), measures them once (GL_DEPTH_BITS). */
void stin__rt_depth_measure(struct stin_context *ctx);
/* glPolygonOffset's r in the depth textures stin draws into: the depth one
 * offset unit moves there (2^-24 unless measured otherwise). */
float stin__rt_depth_unit(const struct stin_context *ctx);

/* A new w x h depth renderbuffer (DEPTH_COMPONENT16 on ES 2.0, 24
 * elsewhere): the depth test beside a colour target that holds the depth
 * itself (map-pcf's packed maps); GL_RENDERBUFFER left unbound. */
GLuint stin__rt_depth_renderbuffer(struct stin_context *ctx, int w, int h);

/* Binds `fbo` and attaches the 2D textures that are not 0: `color` to colour
 * attachment 0, `depth` to the depth, `stencil` to the stencil attachment;
 * the framebuffer's draw and read buffers stay as they are (a caller may
 * attach its colour some other way, an array layer, or later). Returns the
 * completeness status (GL_FRAMEBUFFER_COMPLETE or why not), leaving `fbo`
 * bound. */
GLenum stin__rt_attach(struct stin_context *ctx, GLuint fbo, GLuint color, GLuint depth,
                       GLuint stencil);
/* The same for a framebuffer that never has colour: it draws and reads no
 * colour buffer (GL 2.x framebuffers are incomplete otherwise). */
GLenum stin__rt_attach_depth_only(struct stin_context *ctx, GLuint fbo, GLuint depth,
                                  GLuint stencil);

#endif
