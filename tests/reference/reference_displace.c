/* SPDX-License-Identifier: MIT */
/* The displaced copy of a scene (reference_displace.h). */
#include "reference_displace.h"
#include "reference.h"
#include "reference_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int displaced(const scene *s, const scene_object *o)
{
    const scene_material *m = &s->materials[o->material];
    return m->displace && m->height >= 0 && m->height < s->texture_count;
}

int reference_scene_displaces(const scene *s)
{
    for (int i = 0; i < s->object_count; i++)
        if (s->objects[i].material >= 0 && s->objects[i].material < s->material_count &&
            displaced(s, &s->objects[i]))
            return 1;
    return 0;
}

/* Object o's mesh in world space, displaced, into m. */
static int displace_object(const scene *s, const scene_object *o, scene_mesh *m)
{
    const scene_mesh *src = &s->meshes[o->mesh];
    const scene_material *mat = &s->materials[o->material];
    const scene_texture *tex = &s->textures[mat->height];
    const float *t = o->transform;
    double nm[9];
    size_t nv = src->vertex_count;
    memset(m, 0, sizeof *m);
    snprintf(m->name, sizeof m->name, "%.50s-displaced", src->name);
    m->vertex_count = src->vertex_count;
    m->triangle_count = src->triangle_count;
    m->positions = malloc((3 * nv + 1) * sizeof(float));
    m->normals = malloc((3 * nv + 1) * sizeof(float));
    m->uvs = malloc((2 * nv + 1) * sizeof(float));
    m->indices = malloc((3 * (size_t)src->triangle_count + 1) * sizeof(uint32_t));
    if (!m->positions || !m->normals || !m->uvs || !m->indices || !src->normals || !src->uvs)
        return 0;
    ref_normal_matrix(t, nm);
    for (size_t v = 0; v < nv; v++) {
        const float *p = src->positions + 3 * v, *q = src->normals + 3 * v;
        const float *uv = src->uvs + 2 * v;
        double w[3], n[3], len = 0, d;
        float h[4];
        for (int r = 0; r < 3; r++) {
            w[r] = (double)t[r] * p[0] + (double)t[4 + r] * p[1] + (double)t[8 + r] * p[2] + t[12 + r];
            n[r] = nm[r * 3] * q[0] + nm[r * 3 + 1] * q[1] + nm[r * 3 + 2] * q[2];
            len += n[r] * n[r];
        }
        len = sqrt(len);
        reference_sample_texture(tex, uv[0], uv[1], h);
        d = (double)h[0] * mat->height_scale -
            (mat->has_height_bias ? mat->height_bias : 0.5 * mat->height_scale);
        for (int r = 0; r < 3; r++) {
            n[r] = len > 0 ? n[r] / len : 0.0;
            m->positions[3 * v + r] = (float)(w[r] + n[r] * d);
            m->normals[3 * v + r] = (float)n[r];
        }
        m->uvs[2 * v] = uv[0];
        m->uvs[2 * v + 1] = uv[1];
    }
    memcpy(m->indices, src->indices, 3 * (size_t)src->triangle_count * sizeof(uint32_t));
    return 1;
}

int reference_displace(const scene *s, scene *out, char *err, size_t err_size)
{
    static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    *out = *s;
    out->meshes = calloc((size_t)s->mesh_count + (size_t)s->object_count + 1, sizeof *out->meshes);
    out->objects = calloc((size_t)s->object_count + 1, sizeof *out->objects);
    if (!out->meshes || !out->objects) {
        snprintf(err, err_size, "out of memory");
        reference_displace_free(out, s);
        return 0;
    }
    memcpy(out->meshes, s->meshes, sizeof *s->meshes * (size_t)s->mesh_count);
    out->mesh_count = s->mesh_count;
    for (int i = 0; i < s->object_count; i++) {
        const scene_object *o = &s->objects[i];
        out->objects[i] = *o;
        if (o->mesh < 0 || o->mesh >= s->mesh_count || o->material < 0 ||
            o->material >= s->material_count || !displaced(s, o))
            continue;
        if (!displace_object(s, o, &out->meshes[out->mesh_count])) {
            out->mesh_count++;
            snprintf(err, err_size, "object %d: out of memory, or its mesh has no normals or uvs", i);
            reference_displace_free(out, s);
            return 0;
        }
        out->objects[i].mesh = out->mesh_count++;
        memcpy(out->objects[i].transform, identity, sizeof identity);
    }
    return 1;
}

void reference_displace_free(scene *out, const scene *source)
{
    /* the displaced meshes follow the source's; everything else is shared */
    for (int i = source->mesh_count; out->meshes && i < out->mesh_count; i++) {
        free(out->meshes[i].positions);
        free(out->meshes[i].normals);
        free(out->meshes[i].uvs);
        free(out->meshes[i].indices);
    }
    free(out->meshes);
    free(out->objects);
    out->meshes = NULL;
    out->objects = NULL;
}
