/* SPDX-License-Identifier: MIT */
/* A model handed from the importer's child to the parent: counts, then each
 * mesh, part, material and texture, then the warnings. The parent checks
 * every size, index and number before it keeps anything. */
#include "scene_model.h"
#include "scene_internal.h"
#include "scene_primitives.h"
#include "isolate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WIRE_MAGIC 0x4c444d53u /* "SMDL" */

int scene_model_write(int fd, const scene_model *m)
{
    const uint32_t head[6] = { WIRE_MAGIC, m->mesh_count, m->part_count, m->material_count,
                               m->texture_count,
                               m->warnings ? (uint32_t)strlen(m->warnings) : 0u };
    uint32_t i;
    int ok = isolate_write(fd, head, sizeof head);
    for (i = 0; ok && i < m->mesh_count; i++) {
        const scene_mesh *s = &m->meshes[i];
        const uint32_t counts[2] = { s->vertex_count, s->triangle_count };
        ok = isolate_write(fd, counts, sizeof counts) && isolate_write(fd, s->name, sizeof s->name) &&
             isolate_write(fd, s->positions, (size_t)counts[0] * 3 * sizeof(float)) &&
             isolate_write(fd, s->normals, (size_t)counts[0] * 3 * sizeof(float)) &&
             isolate_write(fd, s->uvs, (size_t)counts[0] * 2 * sizeof(float)) &&
             isolate_write(fd, s->indices, (size_t)counts[1] * 3 * sizeof(uint32_t));
    }
    ok = ok && isolate_write(fd, m->parts, m->part_count * sizeof *m->parts) &&
         isolate_write(fd, m->materials, m->material_count * sizeof *m->materials);
    for (i = 0; ok && i < m->texture_count; i++) {
        const scene_texture *t = &m->textures[i];
        const int32_t head_t[3] = { t->width, t->height, (int32_t)t->kind };
        ok = isolate_write(fd, head_t, sizeof head_t) && isolate_write(fd, t->name, sizeof t->name) &&
             isolate_write(fd, t->rgba, 4 * (size_t)t->width * (size_t)t->height);
    }
    return ok && isolate_write(fd, m->warnings ? m->warnings : "", head[5]);
}

typedef struct reader {
    const unsigned char *at, *end;
} reader;

static int take(reader *r, void *out, size_t n)
{
    if ((size_t)(r->end - r->at) < n)
        return 0;
    memcpy(out, r->at, n);
    r->at += n;
    return 1;
}

/* Allocates count elements of size and fills them from r (count may be 0). */
static int take_array(reader *r, void **out, size_t count, size_t size)
{
    if (count > (size_t)(r->end - r->at) / (size ? size : 1))
        return 0;
    *out = malloc(count * size + 1);
    return *out && take(r, *out, count * size);
}

static int finite_all(const float *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

static int read_mesh(reader *r, scene_mesh *s)
{
    uint32_t counts[2], t;
    char name[SCENE_NAME_MAX];
    if (!take(r, counts, sizeof counts) || !take(r, name, sizeof name) || !counts[0] || !counts[1] ||
        (size_t)counts[0] * 8 * sizeof(float) + (size_t)counts[1] * 3 * sizeof(uint32_t) >
            (size_t)(r->end - r->at) ||
        !scene_mesh_alloc(s, counts[0], counts[1]))
        return 0;
    name[SCENE_NAME_MAX - 1] = '\0';
    memcpy(s->name, name, sizeof name);
    if (!take(r, s->positions, (size_t)counts[0] * 3 * sizeof(float)) ||
        !take(r, s->normals, (size_t)counts[0] * 3 * sizeof(float)) ||
        !take(r, s->uvs, (size_t)counts[0] * 2 * sizeof(float)) ||
        !take(r, s->indices, (size_t)counts[1] * 3 * sizeof(uint32_t)))
        return 0;
    for (t = 0; t < 3 * counts[1]; t++)
        if (s->indices[t] >= counts[0])
            return 0;
    return 1;
}

static int read_texture(reader *r, scene_texture *t)
{
    int32_t head[3];
    if (!take(r, head, sizeof head) || !take(r, t->name, sizeof t->name) || head[0] < 1 ||
        head[1] < 1 || head[0] > SCENE_TEXTURE_SIZE_MAX || head[1] > SCENE_TEXTURE_SIZE_MAX ||
        (head[2] != SCENE_TEXTURE_ALBEDO && head[2] != SCENE_TEXTURE_NORMAL))
        return 0;
    t->name[SCENE_NAME_MAX - 1] = '\0';
    t->width = head[0];
    t->height = head[1];
    t->kind = (scene_texture_kind)head[2];
    return take_array(r, (void **)&t->rgba, 4 * (size_t)head[0] * (size_t)head[1], 1);
}

static int check_parts_materials(const scene_model *m)
{
    uint32_t i;
    for (i = 0; i < m->part_count; i++) {
        const scene_model_part *p = &m->parts[i];
        if (p->mesh >= m->mesh_count || p->material < -1 || p->material >= (int32_t)m->material_count ||
            !finite_all(p->transform, 16))
            return 0;
    }
    for (i = 0; i < m->material_count; i++) {
        scene_model_material *mt = &m->materials[i];
        mt->name[SCENE_NAME_MAX - 1] = '\0';
        if (!finite_all(mt->color, 4) || !finite_all(mt->specular, 3) || !isfinite(mt->shininess) ||
            mt->albedo < -1 || mt->albedo >= (int32_t)m->texture_count || mt->normal < -1 ||
            mt->normal >= (int32_t)m->texture_count || mt->alpha_mode < SCENE_ALPHA_OPAQUE ||
            mt->alpha_mode > SCENE_ALPHA_MASK)
            return 0;
    }
    return 1;
}

int scene_model_read(const unsigned char *bytes, size_t size, scene_model *out, char *why,
                     size_t why_size)
{
    reader r = { bytes, bytes + size };
    scene_model m;
    uint32_t head[6], i;
    int ok;
    memset(&m, 0, sizeof m);
    ok = take(&r, head, sizeof head) && head[0] == WIRE_MAGIC && head[1] && head[2] &&
         head[2] <= SCENE_MODEL_PARTS_MAX && head[1] <= (size_t)(r.end - r.at) / 8;
    if (ok) {
        m.meshes = calloc(head[1], sizeof *m.meshes);
        m.textures = calloc((size_t)head[4] + 1, sizeof *m.textures);
        ok = m.meshes && m.textures && head[4] <= (size_t)(r.end - r.at) / 12;
        m.mesh_count = m.meshes ? head[1] : 0;
        m.texture_count = m.textures ? head[4] : 0;
    }
    for (i = 0; ok && i < m.mesh_count; i++)
        ok = read_mesh(&r, &m.meshes[i]);
    ok = ok && take_array(&r, (void **)&m.parts, head[2], sizeof *m.parts) &&
         take_array(&r, (void **)&m.materials, head[3], sizeof *m.materials);
    m.part_count = m.parts ? head[2] : 0;
    m.material_count = m.materials ? head[3] : 0;
    for (i = 0; ok && i < m.texture_count; i++)
        ok = read_texture(&r, &m.textures[i]);
    ok = ok && take_array(&r, (void **)&m.warnings, head[5], 1);
    if (ok)
        m.warnings[head[5]] = '\0';
    if (!ok || r.at != r.end || !check_parts_materials(&m)) {
        snprintf(why, why_size, "the importer returned a malformed model");
        scene_model_free(&m);
        return 0;
    }
    *out = m;
    return 1;
}

void scene_model_free(scene_model *m)
{
    uint32_t i;
    for (i = 0; m->meshes && i < m->mesh_count; i++)
        scene_mesh_release(&m->meshes[i]);
    for (i = 0; m->textures && i < m->texture_count; i++)
        free(m->textures[i].rgba);
    free(m->meshes);
    free(m->parts);
    free(m->materials);
    free(m->textures);
    free(m->warnings);
    memset(m, 0, sizeof *m);
}
