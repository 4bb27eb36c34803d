/* SPDX-License-Identifier: MIT */
/* The displacement chunk every mesh-drawing program carries
 * (render/displace_chunk.c). */
#ifndef STIN_DISPLACE_CHUNK_H
#define STIN_DISPLACE_CHUNK_H

#include "stin/stin.h"
#include "render/path.h"

/* Every vertex shader that draws meshes has a "// @chunks" line where
 * gl/shader.c splices displace.glsl (the context's displacement is displace
 * or displace-tess) or displace_none.glsl; per draw the chunk's uniforms say
 * whether and how far this draw's vertices move. */
/* 1 when programs are built with the displacement chunk. */
int stin__displace_built(const stin_context *ctx);
/* 1 when they are also tessellated ("displace-tess"). */
int stin__displace_tessellated(const stin_context *ctx);
/* A layer's tessellated programs failed to build: displacement goes on
 * without tessellation ("displace"), the step down logged with why, so the
 * layer need not name displacement's techniques. */
void stin__displace_untessellate(stin_context *ctx, const char *why);
/* The frame's tessellation scale (gl4/tess.tesc's u_tess; [0] and [3] serve
 * the mip level too) and the camera's eye, which every draw's chunk gets:
 * set by displacement at the frame's start (surface/displace.c). */
void stin__displace_frame_scale(stin_context *ctx, const float tess[4], const float eye[3]);
/* What a program's mesh draws are: GL_PATCHES (tessellated) or GL_TRIANGLES. */
GLenum stin__displace_primitive(const stin__displace_locs *l);
/* 1 when this material's draws are displaced. */
int stin__displace_active(const stin_context *ctx, const stin_material *m);
void stin__displace_locate(stin_context *ctx, GLuint program, int camera,
                           stin__displace_locs *out);
/* Per draw, before its DrawElements through a program with the chunk:
 * on or off, the height map on its vertex unit, the scale and bias (d
 * NULL: off, for geometry that is not a draw's). */
void stin__displace_draw(stin_context *ctx, const stin__displace_locs *l, const stin__draw *d);

#endif
