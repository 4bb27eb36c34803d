/* SPDX-License-Identifier: MIT */
/* Per-vertex normals (when the caller gives none) and tangent frames: the uv
 * gradient per triangle, accumulated per vertex, Gram-Schmidt against the
 * normal, handedness stored in w. Every surface technique on every tier reads
 * these same tangents. */
#include "internal.h"

static void sub3(float o[3], const float a[3], const float b[3])
{
    o[0] = a[0] - b[0];
    o[1] = a[1] - b[1];
    o[2] = a[2] - b[2];
}

static void cross3(float o[3], const float a[3], const float b[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static float dot3(const float a[3], const float b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static int normalize3(float v[3]) { return stin__normalize3(v); }

int stin__mesh_smooth(const stin__vertex *verts, const uint32_t *tris, uint32_t tri_count)
{
    uint32_t t;
    int k;
    for (t = 0; t < tri_count; t++) {
        const uint32_t *tri = tris + 3u * t;
        float e1[3], e2[3], facet[3];
        sub3(e1, verts[tri[1]].position, verts[tri[0]].position);
        sub3(e2, verts[tri[2]].position, verts[tri[0]].position);
        cross3(facet, e1, e2);
        if (!normalize3(facet))
            continue;
        for (k = 0; k < 3; k++) {
            float n[3], c;
            n[0] = verts[tri[k]].normal[0];
            n[1] = verts[tri[k]].normal[1];
            n[2] = verts[tri[k]].normal[2];
            if (!normalize3(n))
                continue;
            c = dot3(n, facet); /* either way round */
            if (c * c < (1.0f - 1e-6f) * (1.0f - 1e-6f))
                return 1;
        }
    }
    return 0;
}

/* Face normals are taken on positions divided by the largest coordinate
 * (in double), so that their products neither overflow nor underflow at
 * any scale; the common factor leaves the area weighting as it is. */
void stin__mesh_default_normals(stin__vertex *verts, uint32_t vertex_count,
                                const uint32_t *tris, uint32_t tri_count)
{
    uint32_t i, t;
    double scale = 0.0;
    for (i = 0; i < vertex_count; i++) {
        int k;
        for (k = 0; k < 3; k++) {
            double a = verts[i].position[k] < 0.0f ? -(double)verts[i].position[k]
                                                   : (double)verts[i].position[k];
            if (a > scale)
                scale = a;
        }
        verts[i].normal[0] = verts[i].normal[1] = verts[i].normal[2] = 0.0f;
    }
    scale = scale > 0.0 ? 1.0 / scale : 1.0;
    for (t = 0; t < tri_count; t++) {
        const float *p0 = verts[tris[3 * t]].position, *p1 = verts[tris[3 * t + 1]].position,
                    *p2 = verts[tris[3 * t + 2]].position;
        double e1[3], e2[3];
        float n[3];
        int k;
        for (k = 0; k < 3; k++) {
            e1[k] = ((double)p1[k] - (double)p0[k]) * scale;
            e2[k] = ((double)p2[k] - (double)p0[k]) * scale;
        }
        /* length = twice the (scaled) area: area weighting for free */
        n[0] = (float)(e1[1] * e2[2] - e1[2] * e2[1]);
        n[1] = (float)(e1[2] * e2[0] - e1[0] * e2[2]);
        n[2] = (float)(e1[0] * e2[1] - e1[1] * e2[0]);
        for (k = 0; k < 3; k++) {
            float *vn = verts[tris[3 * t + k]].normal;
            vn[0] += n[0];
            vn[1] += n[1];
            vn[2] += n[2];
        }
    }
    for (i = 0; i < vertex_count; i++)
        if (!normalize3(verts[i].normal)) {
            verts[i].normal[0] = verts[i].normal[1] = 0.0f;
            verts[i].normal[2] = 1.0f;
        }
}

/* Any unit vector perpendicular to n. */
static void perpendicular(const float n[3], float out[3])
{
    float a[3] = {1.0f, 0.0f, 0.0f};
    if (n[0] > 0.9f || n[0] < -0.9f) {
        a[0] = 0.0f;
        a[1] = 1.0f;
    }
    cross3(out, n, a);
    normalize3(out);
}

/* Triangle t's position gradients along u (s) and v (u); 0 where its uvs
 * have none. */
static int uv_gradients(const stin__vertex *verts, const uint32_t *tris, uint32_t t, float s[3],
                        float u[3])
{
    const stin__vertex *a = &verts[tris[3 * t]], *b = &verts[tris[3 * t + 1]],
                       *c = &verts[tris[3 * t + 2]];
    float e1[3], e2[3], du1 = b->uv[0] - a->uv[0], dv1 = b->uv[1] - a->uv[1],
                        du2 = c->uv[0] - a->uv[0], dv2 = c->uv[1] - a->uv[1];
    float det = du1 * dv2 - du2 * dv1;
    int j;
    if (det == 0.0f || !stin__isfinite(1.0f / det))
        return 0; /* no uv gradient on this triangle */
    sub3(e1, b->position, a->position);
    sub3(e2, c->position, a->position);
    for (j = 0; j < 3; j++) {
        s[j] = (dv2 * e1[j] - dv1 * e2[j]) / det;
        u[j] = (du1 * e2[j] - du2 * e1[j]) / det;
    }
    return 1;
}

void stin__mesh_uv_units(const stin__vertex *verts, const uint32_t *tris, uint32_t tri_count,
                         float out[2])
{
    double su = 0.0, sv = 0.0;
    uint32_t t, n = 0;
    for (t = 0; t < tri_count; t++) {
        float s[3], u[3];
        if (!uv_gradients(verts, tris, t, s, u))
            continue;
        su += stin__sqrtf(dot3(s, s));
        sv += stin__sqrtf(dot3(u, u));
        n++;
    }
    out[0] = n && su > 0.0 ? (float)(su / n) : 1.0f;
    out[1] = n && sv > 0.0 ? (float)(sv / n) : 1.0f;
}

void stin__mesh_tangents(stin__vertex *verts, uint32_t vertex_count, const uint32_t *tris,
                         uint32_t tri_count, float *acc, int have_uvs)
{
    uint32_t i, t;
    for (i = 0; i < 6u * vertex_count; i++)
        acc[i] = 0.0f;
    if (have_uvs) {
        for (t = 0; t < tri_count; t++) {
            float s[3], u[3];
            int k, j;
            if (!uv_gradients(verts, tris, t, s, u))
                continue;
            for (k = 0; k < 3; k++) {
                float *ac = acc + 6u * tris[3 * t + k];
                for (j = 0; j < 3; j++) {
                    ac[j] += s[j];
                    ac[3 + j] += u[j];
                }
            }
        }
    }
    for (i = 0; i < vertex_count; i++) {
        const float *n = verts[i].normal;
        float *tan = verts[i].tangent, *ac = acc + 6u * i, d = dot3(ac, n), b[3];
        tan[0] = ac[0] - n[0] * d;
        tan[1] = ac[1] - n[1] * d;
        tan[2] = ac[2] - n[2] * d;
        if (!normalize3(tan)) {
            perpendicular(n, tan);
            tan[3] = 1.0f;
            continue;
        }
        cross3(b, n, tan);
        tan[3] = dot3(b, ac + 3) < 0.0f ? -1.0f : 1.0f;
    }
}
