/* SPDX-License-Identifier: MIT */
/* The raw loop's set-up: checks the scene is one it covers, builds stin's
 * vertex layout per mesh in buffer objects (or client arrays, as stin does
 * without them, never on OpenGL ES) and dispatches frames to the tier's
 * loop. */
#include "raw.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RAW_MAX_LIGHTS 8 /* one lighting pass on every tier (GL guarantees 8 lights) */

static int check_scene(const scene *s, char *err, size_t err_size)
{
    int i;
    if (s->light_count > RAW_MAX_LIGHTS) {
        snprintf(err, err_size, "%s: the raw loop draws at most %d lights (one pass), the scene "
                 "has %d", s->path, RAW_MAX_LIGHTS, s->light_count);
        return 0;
    }
    for (i = 0; i < s->object_count; i++) {
        const scene_material *m = &s->materials[s->objects[i].material];
        if (m->color[3] < 1.0f || m->albedo >= 0) {
            snprintf(err, err_size, "%s: material '%s' is blended or textured; the raw loop "
                     "covers opaque untextured scenes", s->path, m->name);
            return 0;
        }
    }
    return 1;
}

static float *interleave(const scene_mesh *m)
{
    float *v = calloc((size_t)m->vertex_count, RAW_VERTEX_STRIDE);
    uint32_t i;
    if (!v)
        return NULL;
    for (i = 0; i < m->vertex_count; i++) {
        float *o = v + (size_t)i * RAW_VERTEX_FLOATS;
        memcpy(o, m->positions + 3u * i, 3 * sizeof(float));
        memcpy(o + 3, m->normals + 3u * i, 3 * sizeof(float));
        memcpy(o + 6, m->uvs + 2u * i, 2 * sizeof(float));
        /* o[8..11]: tangent, unused by the lit shaders; zero */
    }
    return v;
}

static void upload(const raw_renderer *r, raw_mesh *rm, const scene_mesh *m)
{
    const raw_gl *gl = r->gl;
    int i;
    gl->GenBuffers(1, &rm->vbo);
    gl->GenBuffers(1, &rm->ibo);
    if (r->cfg.tier == STIN_TIER_GL4) {
        gl->GenVertexArrays(1, &rm->vao);
        gl->BindVertexArray(rm->vao);
    }
    gl->BindBuffer(GL_ARRAY_BUFFER, rm->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)m->vertex_count * RAW_VERTEX_STRIDE,
                   rm->vertices, GL_STATIC_DRAW);
    gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, rm->ibo);
    gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(3u * sizeof(uint32_t)) * m->triangle_count,
                   m->indices, GL_STATIC_DRAW);
    if (rm->vao) {
        /* The VAO records the attributes once, as stin's do. */
        for (i = 0; i < 3; i++)
            gl->EnableVertexAttribArray((GLuint)i);
        gl->VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, RAW_VERTEX_STRIDE, (const void *)0);
        gl->VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, RAW_VERTEX_STRIDE, (const void *)12);
        gl->VertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, RAW_VERTEX_STRIDE, (const void *)24);
        gl->BindVertexArray(0);
    }
    gl->BindBuffer(GL_ARRAY_BUFFER, 0);
    gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

int raw_create(raw_renderer *r, const raw_gl *gl, const scene *s, const raw_config *cfg,
               char *err, size_t err_size)
{
    int need = RAW_NEED_CORE, i;
    GLint stencil_bits = 0;
    const char *missing;
    memset(r, 0, sizeof *r);
    r->cfg = *cfg;
    r->gl = gl;
    r->s = s;
    /* ES 3.0 forbids client arrays with a vertex array object bound and
     * WebGL has none: buffer objects there, as stin draws from */
    if (cfg->es_glsl)
        r->cfg.use_vbo = 1;
    if (r->cfg.use_vbo)
        need |= RAW_NEED_VBO;
    if (cfg->tier == STIN_TIER_GL1)
        need |= RAW_NEED_FIXED;
    if (cfg->tier != STIN_TIER_GL1)
        need |= RAW_NEED_GLSL;
    if (cfg->tier == STIN_TIER_GL4)
        need |= RAW_NEED_VAO | RAW_NEED_VBO;
    if ((missing = raw_gl_missing(gl, need))) {
        snprintf(err, err_size, "raw loop: %s did not load", missing);
        return 0;
    }
    if (!check_scene(s, err, err_size))
        return 0;
    r->meshes = calloc((size_t)s->mesh_count + 1, sizeof *r->meshes);
    if (!r->meshes) {
        snprintf(err, err_size, "out of memory");
        return 0;
    }
    for (i = 0; i < s->mesh_count; i++) {
        raw_mesh *rm = &r->meshes[i];
        rm->index_count = (GLsizei)(3u * s->meshes[i].triangle_count);
        rm->indices = s->meshes[i].indices;
        rm->vertices = interleave(&s->meshes[i]);
        if (!rm->vertices) {
            snprintf(err, err_size, "out of memory");
            raw_destroy(r);
            return 0;
        }
        if (r->cfg.use_vbo || cfg->tier == STIN_TIER_GL4)
            upload(r, rm, &s->meshes[i]);
    }
    /* Clear what stin clears: colour, depth, and stencil when there is one. */
    gl->GetIntegerv(GL_STENCIL_BITS, &stencil_bits);
    r->clear_bits = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT |
                    (stencil_bits > 0 ? GL_STENCIL_BUFFER_BIT : 0u);
    if (cfg->tier != STIN_TIER_GL1 && !raw_glsl_create(r, err, err_size)) {
        raw_destroy(r);
        return 0;
    }
    return 1;
}

void raw_frame(const raw_renderer *r, int width, int height)
{
    if (r->cfg.tier == STIN_TIER_GL1)
        raw_fixed_frame(r, width, height);
    else
        raw_glsl_frame(r, width, height);
}

void raw_destroy(raw_renderer *r)
{
    int i;
    if (r->cfg.tier == STIN_TIER_GL1 && r->meshes)
        raw_fixed_reset(r);
    else if (r->cfg.tier != STIN_TIER_GL1)
        raw_glsl_destroy(r);
    for (i = 0; r->meshes && i < r->s->mesh_count; i++) {
        raw_mesh *rm = &r->meshes[i];
        if (rm->vbo)
            r->gl->DeleteBuffers(1, &rm->vbo);
        if (rm->ibo)
            r->gl->DeleteBuffers(1, &rm->ibo);
        if (rm->vao)
            r->gl->DeleteVertexArrays(1, &rm->vao);
        free(rm->vertices);
    }
    free(r->meshes);
    memset(r, 0, sizeof *r);
}
