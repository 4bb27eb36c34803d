/* SPDX-License-Identifier: MIT */
/* Mesh subdivision at creation (stin_mesh_desc.subdivide), for vertex
 * displacement: each level splits every triangle into four at its edges'
 * midpoints, one midpoint vertex per edge (by vertex indices), so
 * neighbours share it and the displaced mesh stays watertight. In place in
 * the mesh's own ranges of the stores; the edge table lives in the
 * mesh-creation scratch. */
#include "internal.h"

#define EMPTY 0xffffffffu

typedef struct mid_entry {
    uint32_t a, b, mid;
} mid_entry;

static uint32_t pow2_at_least(uint64_t n)
{
    uint64_t p = 16;
    while (p < n)
        p <<= 1;
    return p > 0x80000000u ? 0x80000000u : (uint32_t)p;
}

/* The table for the edges of `tris` triangles (at most 3 a triangle), or
 * NULL when the scratch is too small. */
static mid_entry *table_for(stin_context *ctx, uint32_t tris, size_t limit, uint32_t *size)
{
    uint32_t i;
    mid_entry *t = (mid_entry *)(void *)ctx->scratch;
    *size = pow2_at_least(4ull * tris);
    if ((size_t)*size * sizeof(mid_entry) > limit)
        return NULL;
    for (i = 0; i < *size; i++)
        t[i].a = EMPTY;
    return t;
}

/* The entry of edge (va, vb); *fresh = 1 when it was empty (now keyed). */
static mid_entry *edge_slot(mid_entry *t, uint32_t size, uint32_t va, uint32_t vb, int *fresh)
{
    uint32_t a = va < vb ? va : vb, b = va < vb ? vb : va;
    uint32_t s = stin__weld_mix(a * 0x9e3779b9u ^ stin__weld_mix(b)) & (size - 1u);
    while (t[s].a != EMPTY && (t[s].a != a || t[s].b != b))
        s = (s + 1u) & (size - 1u);
    *fresh = t[s].a == EMPTY;
    t[s].a = a;
    t[s].b = b;
    return &t[s];
}

stin_result stin__subdivide_counts(stin_context *ctx, const uint32_t *tris, uint32_t tri_count,
                                   uint32_t vertex_count, uint32_t levels, size_t scratch_limit,
                                   uint32_t *out_vertices, uint32_t *out_triangles)
{
    uint32_t size, i, l;
    uint64_t edges = 0, v = vertex_count, t = tri_count;
    mid_entry *table = table_for(ctx, tri_count, scratch_limit, &size);
    if (!table)
        return STIN_ERROR_CAPACITY;
    for (i = 0; i < 3u * tri_count; i++) {
        int fresh;
        edge_slot(table, size, tris[i], tris[i - i % 3u + (i + 1u) % 3u], &fresh);
        edges += (uint64_t)fresh;
    }
    /* each level: every edge gains a vertex and splits in two, every
     * triangle gains three inner edges and becomes four */
    for (l = 0; l < levels; l++) {
        v += edges;
        edges = 2u * edges + 3u * t;
        t *= 4u;
        if (t > 0xffffffffu / 4u || v > 0xffffffffu)
            return STIN_ERROR_CAPACITY;
    }
    /* the last level's table: the level before's triangles' edges */
    if (levels && (size_t)pow2_at_least(t) * sizeof(mid_entry) > ctx->scratch_bytes)
        return STIN_ERROR_CAPACITY;
    *out_vertices = (uint32_t)v;
    *out_triangles = (uint32_t)t;
    return STIN_OK;
}

static void midpoint(stin__vertex *out, const stin__vertex *a, const stin__vertex *b)
{
    int k;
    for (k = 0; k < 3; k++) {
        out->position[k] = 0.5f * (a->position[k] + b->position[k]);
        out->normal[k] = 0.5f * (a->normal[k] + b->normal[k]);
    }
    out->uv[0] = 0.5f * (a->uv[0] + b->uv[0]);
    out->uv[1] = 0.5f * (a->uv[1] + b->uv[1]);
    out->tangent[0] = out->tangent[1] = out->tangent[2] = 0.0f;
    out->tangent[3] = 1.0f;
}

static uint32_t mid_of(mid_entry *table, uint32_t size, uint32_t a, uint32_t b)
{
    int fresh;
    return edge_slot(table, size, a, b, &fresh)->mid;
}

void stin__subdivide(stin_context *ctx, stin__vertex *verts, uint32_t vertex_count,
                     uint32_t *tris, uint32_t tri_count, uint32_t levels)
{
    uint32_t l, v = vertex_count, t = tri_count;
    for (l = 0; l < levels; l++) {
        uint32_t size, i;
        mid_entry *table = table_for(ctx, t, ctx->scratch_bytes, &size); /* checked by _counts */
        for (i = 0; i < 3u * t; i++) {
            uint32_t a = tris[i], b = tris[i - i % 3u + (i + 1u) % 3u];
            int fresh;
            mid_entry *e = edge_slot(table, size, a, b, &fresh);
            if (fresh) {
                e->mid = v;
                midpoint(&verts[v++], &verts[a], &verts[b]);
            }
        }
        /* from the last triangle down: its four land at 4i.., never on one not yet read */
        for (i = t; i-- > 0;) {
            uint32_t a = tris[3u * i], b = tris[3u * i + 1u], c = tris[3u * i + 2u];
            uint32_t ab = mid_of(table, size, a, b), bc = mid_of(table, size, b, c);
            uint32_t ca = mid_of(table, size, c, a);
            uint32_t *o = tris + 12u * i;
            o[0] = a;  o[1] = ab; o[2] = ca;
            o[3] = ab; o[4] = b;  o[5] = bc;
            o[6] = ca; o[7] = bc; o[8] = c;
            o[9] = ab; o[10] = bc; o[11] = ca;
        }
        t *= 4u;
    }
}

/* Corner k of triangle i of level `level` (of `levels`): a child k keeps
 * its parent's corner k (the order stin__subdivide writes), so it is the
 * stored triangle reached by child k at every level below. */
static uint32_t corner(const uint32_t *tris, uint32_t level, uint32_t levels, uint32_t i,
                       uint32_t k)
{
    for (; level < levels; level++)
        i = 4u * i + k;
    return tris[3u * i + k];
}

void stin__subdivide_again(stin__vertex *verts, const uint32_t *tris, uint32_t tri_count,
                           uint32_t levels)
{
    uint32_t l, i, count = tri_count >> (2u * levels);
    for (l = 0; l < levels; l++, count *= 4u)
        for (i = 0; i < count; i++) {
            uint32_t a = corner(tris, l, levels, i, 0), b = corner(tris, l, levels, i, 1);
            uint32_t c = corner(tris, l, levels, i, 2);
            /* children 0 (a, ab, ca) and 1 (ab, b, bc); a midpoint is the
             * same whichever neighbour made it (a + b == b + a) */
            midpoint(&verts[corner(tris, l + 1u, levels, 4u * i, 1)], &verts[a], &verts[b]);
            midpoint(&verts[corner(tris, l + 1u, levels, 4u * i + 1u, 2)], &verts[b], &verts[c]);
            midpoint(&verts[corner(tris, l + 1u, levels, 4u * i, 2)], &verts[c], &verts[a]);
        }
}

void stin__mesh_mean_edges(const stin__vertex *verts, const uint32_t *tris, uint32_t tri_count,
                           float *uv_edge, float *edge)
{
    double uv = 0.0, len = 0.0;
    uint32_t i;
    for (i = 0; i < 3u * tri_count; i++) {
        const stin__vertex *a = &verts[tris[i]], *b = &verts[tris[i - i % 3u + (i + 1u) % 3u]];
        float dx = a->position[0] - b->position[0], dy = a->position[1] - b->position[1];
        float dz = a->position[2] - b->position[2];
        if (uv_edge) {
            float du = a->uv[0] - b->uv[0], dv = a->uv[1] - b->uv[1];
            uv += (double)stin__sqrtf(du * du + dv * dv);
        }
        len += (double)stin__sqrtf(dx * dx + dy * dy + dz * dz);
    }
    if (uv_edge)
        *uv_edge = tri_count ? (float)(uv / (3.0 * (double)tri_count)) : 0.0f;
    *edge = tri_count ? (float)(len / (3.0 * (double)tri_count)) : 0.0f;
}
