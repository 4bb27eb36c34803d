/* SPDX-License-Identifier: MIT */
/* Shadow-volume geometry of one caster for one light, on the CPU, in chunks
 * of homogeneous object-space triangles (vertices extruded away from the
 * light onto the request's far plane, or to infinity: w = 0).
 *
 * Closed 2-manifold casters get the classic volume: the light-facing
 * triangles, side quads on their silhouette edges, caps for z-fail.
 * Any other caster (open edges, edges of three or more triangles, mixed
 * orientation) gets the generalised volume: every triangle contributes its
 * own closed volume, averted ones flipped to face the light, and side quads
 * on an edge shared by two triangles of equal facing cancel and are skipped.
 * A point's stencil count is then the number of triangles between it and the
 * light (the per-edge multiplicity rule), so open casters cast without leaks. */
#include "internal.h"

#define NO_TRI 0xffffffffu

typedef struct emitter {
    const stin__volume_request *r;
    uint32_t used, triangles;
    int clockwise;
} emitter;

static void flush(emitter *e)
{
    if (e->used) {
        e->r->sink(e->r->user, e->r->buffer, e->used, e->clockwise);
        e->used = 0;
    }
}

static void put(emitter *e, const float a[4], const float b[4], const float c[4])
{
    float *o;
    if (e->used + 3 > e->r->buffer_vertices)
        flush(e);
    o = e->r->buffer + 4u * e->used;
    stin__memcopy(o, a, 4 * sizeof(float));
    stin__memcopy(o + 4, b, 4 * sizeof(float));
    stin__memcopy(o + 8, c, 4 * sizeof(float));
    e->used += 3;
    e->triangles++;
}

static void finite_point(const float p[3], float out[4])
{
    out[0] = p[0];
    out[1] = p[1];
    out[2] = p[2];
    out[3] = 1.0f;
}

/* Where the ray from the light through p meets the far plane pl: with f
 * the ray's point at infinity, (pl . f) p - (pl . p) f, homogeneous (pl =
 * (0, 0, 0, -1) gives f itself). The same operations as
 * volume_extrude.geom's far_point. */
static void extrude(const float p[3], const float l[4], const float pl[4], float out[4])
{
    float f[3], pf, pp;
    int k;
    for (k = 0; k < 3; k++)
        f[k] = p[k] * l[3] - l[k];
    pf = pl[0] * f[0] + pl[1] * f[1] + pl[2] * f[2];
    pp = pl[0] * p[0] + pl[1] * p[1] + pl[2] * p[2] + pl[3];
    for (k = 0; k < 3; k++)
        out[k] = pf * p[k] - pp * f[k];
    out[3] = pf;
}

int stin__triangle_faces_light(const float *a, const float *b, const float *c, const float l[4])
{
    float e1[3], e2[3], n[3], d[3];
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = b[k] - a[k];
        e2[k] = c[k] - a[k];
        d[k] = l[k] - l[3] * a[k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    return n[0] * d[0] + n[1] * d[1] + n[2] * d[2] > 0.0f;
}

uint32_t stin__volume_build(const stin__volume_request *r)
{
    emitter e;
    uint32_t t;
    int k;
    e.r = r;
    e.used = e.triangles = 0;
    e.clockwise = 0;
    for (t = 0; t < r->tri_count; t++) {
        const uint32_t *tri = r->tris + 3u * t;
        r->facing[t] = (unsigned char)stin__triangle_faces_light(
            r->verts[tri[0]].position, r->verts[tri[1]].position, r->verts[tri[2]].position,
            r->light);
    }
    for (t = 0; t < r->tri_count; t++) {
        const uint32_t *tri = r->tris + 3u * t;
        const float *p[3];
        float fin[3][4], inf[3][4];
        int facing = r->facing[t];
        if (!facing && r->closed)
            continue; /* inside the volume of the facing side */
        /* Orient the triangle toward the light: averted ones are flipped. */
        p[0] = r->verts[tri[0]].position;
        p[1] = r->verts[tri[facing ? 1 : 2]].position;
        p[2] = r->verts[tri[facing ? 2 : 1]].position;
        for (k = 0; k < 3; k++) {
            finite_point(p[k], fin[k]);
            extrude(p[k], r->light, r->far_plane, inf[k]);
        }
        if (r->caps) {
            if (facing) /* an averted one's light cap follows below */
                put(&e, fin[0], fin[1], fin[2]);
            put(&e, inf[2], inf[1], inf[0]);
        }
        for (k = 0; k < 3; k++) {
            /* edge k of the oriented triangle: p[k] -> p[k+1]; its index in
             * the stored triangle depends on the flip */
            int stored = facing ? k : (k == 0 ? 2 : k == 1 ? 1 : 0);
            uint32_t n = r->adjacency[3u * t + (uint32_t)stored];
            int k1 = (k + 1) % 3;
            if (n != NO_TRI && r->facing[n] == facing)
                continue; /* the neighbour's side quad cancels this one */
            put(&e, fin[k1], fin[k], inf[k]);
            put(&e, fin[k1], inf[k], inf[k1]);
        }
    }
    flush(&e);
    /* Light caps of averted triangles lie on the surface they came from and
     * must rasterise to exactly its depths: keep the stored vertex order and
     * flip the winding convention instead of the vertices. */
    if (r->caps && !r->closed) {
        e.clockwise = 1;
        for (t = 0; t < r->tri_count; t++) {
            const uint32_t *tri = r->tris + 3u * t;
            float fin[3][4];
            if (r->facing[t])
                continue;
            for (k = 0; k < 3; k++)
                finite_point(r->verts[tri[k]].position, fin[k]);
            put(&e, fin[0], fin[1], fin[2]);
        }
        flush(&e);
    }
    return e.triangles;
}
