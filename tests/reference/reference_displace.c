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

/* One point of the displaced surface: the object-space point p with normal
 * q and uv, to world space, moved along its world normal by the height. */
static void displace_point(const scene *s, const scene_object *o, const double p[3],
                           const double q[3], const double uv[2], float *pos, float *nrm,
                           float *tex)
{
    const scene_material *mat = &s->materials[o->material];
    const scene_texture *tex_map = &s->textures[mat->height];
    const float *t = o->transform;
    double nm[9], w[3], n[3], len = 0, d;
    float h[4];
    ref_normal_matrix(t, nm);
    for (int r = 0; r < 3; r++) {
        w[r] = (double)t[r] * p[0] + (double)t[4 + r] * p[1] + (double)t[8 + r] * p[2] + t[12 + r];
        n[r] = nm[r * 3] * q[0] + nm[r * 3 + 1] * q[1] + nm[r * 3 + 2] * q[2];
        len += n[r] * n[r];
    }
    len = sqrt(len);
    reference_sample_texture(tex_map, (float)uv[0], (float)uv[1], h);
    d = (double)h[0] * mat->height_scale -
        (mat->has_height_bias ? mat->height_bias : 0.5 * mat->height_scale);
    for (int r = 0; r < 3; r++) {
        n[r] = len > 0 ? n[r] / len : 0.0;
        pos[r] = (float)(w[r] + n[r] * d);
        nrm[r] = (float)n[r];
    }
    tex[0] = (float)uv[0];
    tex[1] = (float)uv[1];
}

/* Object o's mesh in world space, each triangle split into split^2 (the
 * points at barycentric weights (a, b, c) / split, a shared edge's points
 * computed alike from either side), displaced, into m. */
static int displace_object(const scene *s, const scene_object *o, int split, scene_mesh *m)
{
    const scene_mesh *src = &s->meshes[o->mesh];
    size_t per_tri = (size_t)(split + 1) * (split + 2) / 2, nt = src->triangle_count;
    size_t nv = nt * per_tri, v = 0, k = 0;
    memset(m, 0, sizeof *m);
    snprintf(m->name, sizeof m->name, "%.50s-displaced", src->name);
    m->vertex_count = (uint32_t)nv;
    m->triangle_count = (uint32_t)(nt * (size_t)split * split);
    m->positions = malloc((3 * nv + 1) * sizeof(float));
    m->normals = malloc((3 * nv + 1) * sizeof(float));
    m->uvs = malloc((2 * nv + 1) * sizeof(float));
    m->indices = malloc((3 * (size_t)m->triangle_count + 1) * sizeof(uint32_t));
    if (!m->positions || !m->normals || !m->uvs || !m->indices || !src->normals || !src->uvs)
        return 0;
    for (size_t t = 0; t < nt; t++) {
        const uint32_t *tri = src->indices + 3 * t;
        size_t first = v;
        /* row j (weight c = j), column i (weight b = i): index first + row start + i */
        for (int j = 0; j <= split; j++)
            for (int i = 0; i + j <= split; i++, v++) {
                double wgt[3] = {(double)(split - i - j), (double)i, (double)j};
                double p[3] = {0, 0, 0}, q[3] = {0, 0, 0}, uv[2] = {0, 0};
                for (int c = 0; c < 3; c++) {
                    for (int r = 0; r < 3; r++) {
                        p[r] += wgt[c] * src->positions[3 * tri[c] + r];
                        q[r] += wgt[c] * src->normals[3 * tri[c] + r];
                    }
                    for (int r = 0; r < 2; r++)
                        uv[r] += wgt[c] * src->uvs[2 * tri[c] + r];
                }
                for (int r = 0; r < 3; r++) {
                    p[r] /= split;
                    q[r] /= split;
                }
                uv[0] /= split;
                uv[1] /= split;
                displace_point(s, o, p, q, uv, m->positions + 3 * v, m->normals + 3 * v,
                               m->uvs + 2 * v);
            }
        for (int j = 0; j < split; j++) {
            size_t row = first + (size_t)j * (split + 1) - (size_t)j * (j - 1) / 2;
            size_t next = row + (size_t)(split + 1 - j);
            for (int i = 0; i + j < split; i++) {
                m->indices[k++] = (uint32_t)(row + i);
                m->indices[k++] = (uint32_t)(row + i + 1);
                m->indices[k++] = (uint32_t)(next + i);
                if (i + j + 1 < split) {
                    m->indices[k++] = (uint32_t)(row + i + 1);
                    m->indices[k++] = (uint32_t)(next + i + 1);
                    m->indices[k++] = (uint32_t)(next + i);
                }
            }
        }
    }
    return 1;
}

int reference_displace(const scene *s, scene *out, char *err, size_t err_size)
{
    return reference_displace_split(s, 1, out, err, err_size);
}

int reference_displace_split(const scene *s, int split, scene *out, char *err, size_t err_size)
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
        if (split < 1 || !displace_object(s, o, split, &out->meshes[out->mesh_count])) {
            out->mesh_count++;
            snprintf(err, err_size, "object %d: out of memory, its mesh has no normals or uvs, "
                                    "or split %d < 1", i, split);
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
