/* SPDX-License-Identifier: MIT */
/* The caller's state that would redirect stin's own GL work, set aside
 * around stin_create and each frame (gl/caller_redirects.c). */
#ifndef STIN_GL_CALLER_REDIRECTS_H
#define STIN_GL_CALLER_REDIRECTS_H

#include "gl/gl_calls.h"

struct stin_context;

/* What the context defines, so may be queried (ctx->caller_has). */
enum {
    STIN__CALLER_PIXEL_BUFFERS = 1u, /* pixel pack and unpack buffers (GL 2.1) */
    STIN__CALLER_QUERY_BUFFER = 2u,  /* GL 4.4, ARB_query_buffer_object */
    STIN__CALLER_PIPELINE = 4u,      /* GL 4.1, ARB_separate_shader_objects */
    STIN__CALLER_CLAMP = 8u,         /* GL 3.0, ARB_color_buffer_float */
    STIN__CALLER_PROVOKING = 16u,    /* GL 3.2, ARB/EXT_provoking_vertex */
    STIN__CALLER_QUERIES = 32u,      /* glGetQueryiv: the caller's active queries */
    STIN__CALLER_SRGB = 64u          /* GL 3.0, ARB/EXT_framebuffer_sRGB; ES: EXT_sRGB_write_control */
};

/* Query targets the caller's active queries hold this frame (ctx->queries_busy). */
enum {
    STIN__QUERY_SAMPLES = 1u,    /* samples passed, any samples passed (conservative) */
    STIN__QUERY_PRIMITIVES = 2u, /* primitives generated */
    STIN__QUERY_FEEDBACK = 4u,   /* transform feedback primitives written */
    STIN__QUERY_TIME = 8u        /* time elapsed */
};

typedef struct stin__redirects {
    GLint unpack_buffer, pack_buffer, query_buffer, pipeline;
    GLint clamp_fragment, clamp_read, provoking;
} stin__redirects;

/* stin_create's set-up binds these; it gives them back. */
typedef struct stin__create_bindings {
    GLint vao, array_buffer, unit, texture_2d, texture_2d_array, texture_cube;
    stin__redirects redirects;
} stin__create_bindings;

#define STIN__CALLER_ARRAY_UNITS 16
typedef struct stin__caller_frame {
    stin__redirects redirects;
    int depth_clamp, offset_fill;
    int srgb; /* GL_FRAMEBUFFER_SRGB, turned off for a data output's frame */
    GLint clear_stencil;
    GLint arrays[STIN__CALLER_ARRAY_UNITS]; /* each unit's 2D-array binding */
    GLint pushed_fbo[2]; /* draw and read bindings at the GL1 tier's attribute push */
} stin__caller_frame;

/* At stin_create, after detection: ctx->caller_has. */
void stin__caller_detect(struct stin_context *ctx);
/* Pixel buffers, query buffer, program pipeline unbound; colour clamping
 * FIXED_ONLY, provoking vertex LAST: end gives the caller's back. */
void stin__redirects_begin(struct stin_context *ctx, stin__redirects *s);
void stin__redirects_end(struct stin_context *ctx, const stin__redirects *s);
/* Around stin_create's set-up: the vertex array, array buffer, active
 * unit, unit 0's 2D, 2D-array and cube-map textures, and the redirects. */
void stin__create_bindings_save(struct stin_context *ctx, stin__create_bindings *s);
void stin__create_bindings_restore(struct stin_context *ctx, const stin__create_bindings *s);
/* Around a frame: the redirects, the caller's busy query targets, and what
 * a pass changes that the header does not list (depth clamp, polygon
 * offset fill, the stencil clear value, each unit's 2D-array binding),
 * given back at the end; sRGB encoding off for a normal or visibility
 * output (data, not colour). */
void stin__caller_frame_begin(struct stin_context *ctx, stin__caller_frame *s);
void stin__caller_frame_end(struct stin_context *ctx, const stin__caller_frame *s);
/* Begins query `id` on `target` unless a caller's query holds it (the
 * STIN__QUERY_* bit `which`): 1 when begun, so the caller of this ends it. */
int stin__query_begin(struct stin_context *ctx, unsigned which, GLenum target, GLuint id);
/* The target of stin's "did any sample pass" queries: GL_SAMPLES_PASSED
 * where the context counts samples (desktop), else GL_ANY_SAMPLES_PASSED
 * (OpenGL ES 3.0+); only where ANY_SAMPLES_QUERY is present. */
GLenum stin__any_samples_target(const struct stin_context *ctx);
/* stin__query_begin of an any-samples query on id (STIN__QUERY_SAMPLES). */
int stin__any_samples_begin(struct stin_context *ctx, GLuint id);
/* Ends the query stin__any_samples_begin began; 1 when any sample passed. */
int stin__any_samples_end(struct stin_context *ctx, GLuint id);

#endif
