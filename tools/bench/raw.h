/* SPDX-License-Identifier: MIT */
/*
 * The raw-GL loop stin-bench compares libstin with: the same scene drawn on
 * the same GL context by the minimum of GL calls that produce stin's image on
 * a tier, with the pipeline configured as stin configures it (same vertex
 * layout and buffers, same lighting model, same shaders), so that what differs
 * is stin's own per-frame work. Covers opaque, untextured scenes with at most
 * 8 lights (one lighting pass), which is what the spheres scenes are.
 */
#ifndef STIN_BENCH_RAW_H
#define STIN_BENCH_RAW_H

#include "raw_gl.h"
#include "scene.h"
#include "stin/stin.h"

#include <stdint.h>

typedef struct raw_config {
    stin_tier tier;          /* GL1, GL2 or GL4 */
    int use_vbo;             /* as stin: buffer objects when the context has them */
    int separate_specular;   /* GL1: as stin, when the context has the capability */
    const char *shader_dir;  /* GL2/GL4: the folder holding gl2/ and gl4/ */
    /* 0: desktop GL; 300, 310 or 320: an OpenGL ES 3.x context, whose GLSL
     * ES version the sources run as (raw_es.c); buffer objects only there */
    int es_glsl;
} raw_config;

typedef struct raw_mesh {
    GLuint vbo, ibo, vao;
    GLsizei index_count;
    float *vertices;         /* interleaved, kept for client arrays */
    const uint32_t *indices; /* the scene's, for client arrays */
} raw_mesh;

typedef struct raw_program {
    GLuint name;
    GLint u_model, u_view_proj, u_normal_matrix, u_eye, u_ambient, u_albedo, u_specular,
        u_shininess, u_light_count, u_lights, u_has_albedo_tex;
} raw_program;

typedef struct raw_renderer {
    raw_config cfg;
    const raw_gl *gl;
    const scene *s;
    raw_mesh *meshes;        /* one per scene mesh */
    GLbitfield clear_bits;
    raw_program prog;        /* GL2/GL4 */
} raw_renderer;

/* Builds meshes (and the program on GL2/GL4). On failure writes a message,
 * releases what was made and returns 0. */
int raw_create(raw_renderer *r, const raw_gl *gl, const scene *s, const raw_config *cfg,
               char *err, size_t err_size);
/* One frame into the bound framebuffer: clear, then every object. */
void raw_frame(const raw_renderer *r, int width, int height);
void raw_destroy(raw_renderer *r);

/* Per tier (raw_fixed.c, raw_glsl.c). */
void raw_fixed_frame(const raw_renderer *r, int width, int height);
void raw_fixed_reset(const raw_renderer *r); /* GL state back to defaults */
int raw_glsl_create(raw_renderer *r, char *err, size_t err_size);
void raw_glsl_frame(const raw_renderer *r, int width, int height);
void raw_glsl_destroy(raw_renderer *r);
/* The tier's lit program as stin builds its unshadowed plain one, from the
 * GLSL files under cfg->shader_dir (raw_program.c), with frag_defines (NULL:
 * none) after lit.frag's #version line (on ES: after the preamble that
 * replaces it). 0 with a message on failure. */
GLuint raw_program_link(const raw_gl *gl, const raw_config *cfg, const char *frag_defines,
                        char *err, size_t err_size);
/* The lines that replace a source's #version line on ES 3.x (raw_es.c):
 * into parts (at most RAW_ES_PARTS), version_line holding the first;
 * gl2_source: a shaders/gl2 file, whose GLSL 1.10 names get mapped. */
#define RAW_ES_PARTS 3
int raw_es_preamble(int es_version, int fragment, int gl2_source, char *version_line,
                    size_t line_size, const char **parts);

/* Interleaved vertex: position, normal, uv, tangent — stin's layout, so that
 * both fetch the same bytes. */
#define RAW_VERTEX_FLOATS 12
#define RAW_VERTEX_STRIDE ((GLsizei)(RAW_VERTEX_FLOATS * sizeof(float)))

#endif
