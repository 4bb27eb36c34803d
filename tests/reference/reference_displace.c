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

/* How one object's heights are read: level 0, or (mips) the chain at
 * lambda = log2(spread x distance to the eye), spread the texels a pixel
 * spans at distance 1. */
typedef struct height_source {
    const reference_displace_lod *lod;
    reference_mips *mips;
    double spread;
} height_source;

/* The mean uv and object-space lengths of a mesh's triangle edges. */
static void mean_edges(const scene_mesh *m, double *uv, double *len)
{
    *uv = *len = 0;
    for (size_t k = 0; k < 3 * (size_t)m->triangle_count; k++) {
        uint32_t a = m->indices[k], b = m->indices[k % 3 == 2 ? k - 2 : k + 1];
        double du = m->uvs[2 * a] - m->uvs[2 * b], dv = m->uvs[2 * a + 1] - m->uvs[2 * b + 1], d2 = 0;
        for (int r = 0; r < 3; r++)
            d2 += (m->positions[3 * a + r] - m->positions[3 * b + r]) *
                  (double)(m->positions[3 * a + r] - m->positions[3 * b + r]);
        *uv += sqrt(du * du + dv * dv);
        *len += sqrt(d2);
    }
}

static double height_at(const height_source *hs, const scene_texture *t, const double uv[2],
                        const double world[3])
{
    float h[4];
    if (!hs->mips) {
        reference_sample_texture(t, (float)uv[0], (float)uv[1], h);
        return h[0];
    }
    double d = 1.0;
    if (hs->lod->perspective) {
        d = 0;
        for (int r = 0; r < 3; r++)
            d += (world[r] - hs->lod->eye[r]) * (world[r] - hs->lod->eye[r]);
        d = sqrt(d);
    }
    reference_sample_mips(hs->mips, (float)uv[0], (float)uv[1], log2(hs->spread * d), h);
    return h[0];
}

/* One point of the displaced surface: the object-space point p with normal
 * q and uv, to world space, moved along its world normal by the height. */
static void displace_point(const scene *s, const scene_object *o, const height_source *hs,
                           const double p[3], const double q[3], const double uv[2], float *pos,
                           float *nrm, float *tex)
{
    const scene_material *mat = &s->materials[o->material];
    const scene_texture *tex_map = &s->textures[mat->height];
    const float *t = o->transform;
    double nm[9], w[3], n[3], len = 0, d;
    ref_normal_matrix(t, nm);
    for (int r = 0; r < 3; r++) {
        w[r] = (double)t[r] * p[0] + (double)t[4 + r] * p[1] + (double)t[8 + r] * p[2] + t[12 + r];
        n[r] = nm[r * 3] * q[0] + nm[r * 3 + 1] * q[1] + nm[r * 3 + 2] * q[2];
        len += n[r] * n[r];
    }
    len = sqrt(len);
    d = height_at(hs, tex_map, uv, w) * mat->height_scale -
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
static int displace_object(const scene *s, const scene_object *o, int split,
                           const height_source *hs, scene_mesh *m)
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
                displace_point(s, o, hs, p, q, uv, m->positions + 3 * v, m->normals + 3 * v,
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
    return reference_displace_ex(s, 1, NULL, out, err, err_size);
}

int reference_displace_split(const scene *s, int split, scene *out, char *err, size_t err_size)
{
    return reference_displace_ex(s, split, NULL, out, err, err_size);
}

/* Object o's height source: its material's map, mipped as lod says. */
static int height_source_of(const scene *s, const scene_object *o,
                            const reference_displace_lod *lod, height_source *hs)
{
    const scene_mesh *m = &s->meshes[o->mesh];
    const scene_texture *t = &s->textures[s->materials[o->material].height];
    const float *x = o->transform;
    double uv, len, scale = 0;
    memset(hs, 0, sizeof *hs);
    if (!lod)
        return 1;
    hs->lod = lod;
    hs->mips = reference_mips_create(t, 0);
    if (!hs->mips || !m->uvs)
        return 0;
    mean_edges(m, &uv, &len);
    for (int c = 0; c < 3; c++)
        scale += sqrt((double)x[4 * c] * x[4 * c] + (double)x[4 * c + 1] * x[4 * c + 1] +
                      (double)x[4 * c + 2] * x[4 * c + 2]) / 3.0;
    hs->spread = len > 0 && scale > 0 ? (t->width > t->height ? t->width : t->height) * uv /
                                            (len * scale) / lod->pixels_per_unit
                                      : 0;
    return 1;
}

int reference_displace_ex(const scene *s, int split, const reference_displace_lod *lod,
                          scene *out, char *err, size_t err_size)
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
        height_source hs = {NULL, NULL, 0};
        int ok = split >= 1 && height_source_of(s, o, lod, &hs) &&
                 displace_object(s, o, split, &hs, &out->meshes[out->mesh_count]);
        reference_mips_destroy(hs.mips);
        if (!ok) {
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
