/* SPDX-License-Identifier: MIT */
/* Edge adjacency over position-welded vertices (assets/mesh_weld.c): which
 * triangle lies across each edge, how many edges are open or shared by more
 * than two triangles, and whether the mesh is a consistently oriented closed
 * 2-manifold, and whether it bounds one convex solid (every edge convex,
 * one piece). Welding by position means split normals or uv seams do not
 * open the mesh. */
#include "internal.h"

#define NO_TRI 0xffffffffu

typedef struct edge_entry {
    uint32_t a, b;     /* welded endpoints, a < b; a == NO_TRI marks an empty slot */
    uint32_t he0, he1; /* first two half-edges (3 * triangle + edge) */
} edge_entry;

static uint32_t pow2_at_least(uint64_t n)
{
    uint32_t p = 16;
    while (p < n && p < 0x80000000u)
        p <<= 1;
    return p;
}

/* Whether triangle t1 bends away from t0 across their shared edge (t1's
 * far vertex on or behind t0's plane, within 1e-5 of t0's longest edge:
 * a flat quad split in two counts as convex). */
static int convex_edge(const stin__vertex *verts, const uint32_t *tris, uint32_t t0,
                       uint32_t h1)
{
    const float *a = verts[tris[3 * t0]].position, *b = verts[tris[3 * t0 + 1]].position;
    const float *c = verts[tris[3 * t0 + 2]].position;
    const float *far = verts[tris[3 * (h1 / 3u) + (h1 % 3u + 2u) % 3u]].position;
    double u[3], v[3], n[3], d = 0.0, nn = 0.0, longest = 0.0, e;
    int k;
    for (k = 0; k < 3; k++) {
        u[k] = (double)b[k] - a[k];
        v[k] = (double)c[k] - a[k];
    }
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    for (k = 0; k < 3; k++) {
        d += n[k] * ((double)far[k] - a[k]);
        nn += n[k] * n[k];
        e = u[k] - v[k];
        longest += e * e;
    }
    e = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    longest = longest > e ? longest : e;
    e = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    longest = longest > e ? longest : e;
    return d <= 0.0 || d * d <= 1e-10 * longest * nn;
}

size_t stin__adjacency_scratch_bytes(uint32_t vertex_count, uint32_t tri_count)
{
    size_t weld = (size_t)vertex_count * 4u + (size_t)pow2_at_least(2ull * vertex_count) * 4u;
    uint32_t edges = pow2_at_least(4ull * tri_count);
    return stin__align16(weld) + (size_t)edges * (sizeof(edge_entry) + 1u) + 32u;
}

stin_result stin__mesh_adjacency_build(stin_context *ctx, stin__vertex *verts,
                                       uint32_t vertex_count, float weld_tolerance,
                                       const uint32_t *tris, uint32_t tri_count,
                                       uint32_t *adjacency, uint32_t *welds,
                                       stin_mesh_info *info, int *one_piece)
{
    uint32_t weld_size = pow2_at_least(2ull * vertex_count);
    uint32_t edge_size = pow2_at_least(4ull * tri_count);
    unsigned char *base = ctx->scratch;
    uint32_t *weld = (uint32_t *)(void *)base;
    uint32_t *weld_table = weld + vertex_count;
    edge_entry *edges = (edge_entry *)(void *)(base + stin__align16(
        (size_t)vertex_count * 4u + (size_t)weld_size * 4u));
    unsigned char *counts = (unsigned char *)(edges + edge_size);
    uint32_t he, i, inconsistent = 0, welded_count = 0, edge_count = 0;

    if (stin__adjacency_scratch_bytes(vertex_count, tri_count) > ctx->scratch_bytes)
        return STIN_ERROR_CAPACITY;
    info->welded_vertices =
        stin__weld_positions(verts, vertex_count, weld_tolerance, weld, weld_table, weld_size);
    for (i = 0; i < edge_size; i++) {
        edges[i].a = NO_TRI;
        counts[i] = 0;
    }
    for (he = 0; he < 3u * tri_count; he++) {
        uint32_t t = he / 3u, e = he % 3u;
        uint32_t va = weld[tris[3 * t + e]], vb = weld[tris[3 * t + (e + 1) % 3]];
        uint32_t a = va < vb ? va : vb, b = va < vb ? vb : va;
        uint32_t s = stin__weld_mix(a * 0x9e3779b9u ^ stin__weld_mix(b)) & (edge_size - 1);
        adjacency[he] = NO_TRI;
        while (edges[s].a != NO_TRI && (edges[s].a != a || edges[s].b != b))
            s = (s + 1) & (edge_size - 1);
        if (edges[s].a == NO_TRI) {
            edges[s].a = a;
            edges[s].b = b;
            edges[s].he0 = he;
        } else if (counts[s] == 1) {
            edges[s].he1 = he;
        }
        if (counts[s] < 255)
            counts[s]++;
    }
    info->open_edges = info->nonmanifold_edges = 0;
    for (i = 0; i < edge_size; i++) {
        uint32_t h0, h1, t0, t1, s0, s1;
        if (edges[i].a == NO_TRI)
            continue;
        edge_count++;
        if (counts[i] == 1) {
            info->open_edges++;
            continue;
        }
        if (counts[i] > 2) {
            info->nonmanifold_edges++;
            continue;
        }
        h0 = edges[i].he0;
        h1 = edges[i].he1;
        t0 = h0 / 3u;
        t1 = h1 / 3u;
        /* Opposite traversal directions mean consistent orientation. */
        s0 = weld[tris[3 * t0 + h0 % 3u]];
        s1 = weld[tris[3 * t1 + h1 % 3u]];
        if (s0 == s1) {
            inconsistent++;
            continue;
        }
        adjacency[h0] = t1;
        adjacency[h1] = t0;
    }
    info->nonmanifold_edges += inconsistent;
    info->closed_manifold = info->open_edges == 0 && info->nonmanifold_edges == 0;
    /* Locally convex closed pieces are spheres (Euler characteristic 2
     * each): one piece when V - E + F = 2 (an unused vertex also breaks it:
     * not convex, the safe side) */
    for (i = 0; i < vertex_count; i++) {
        welded_count += weld[i] == i;
        welds[i] = weld[i];
    }
    *one_piece = (int64_t)welded_count - (int64_t)edge_count + (int64_t)tri_count == 2;
    info->convex = info->closed_manifold && *one_piece &&
                   !stin__mesh_concave_edge(verts, tris, adjacency, welds, tri_count);
    return STIN_OK;
}

/* The half-edge of triangle n that runs t's edge e (the same welded
 * endpoints), or NO_TRI. A sliver may border t on two edges: the
 * endpoints tell which. */
static uint32_t twin(const uint32_t *tris, const uint32_t *adjacency, const uint32_t *welds,
                     uint32_t t, uint32_t e, uint32_t n)
{
    uint32_t a = welds[tris[3u * t + e]], b = welds[tris[3u * t + (e + 1u) % 3u]], j;
    for (j = 0; j < 3u; j++) {
        uint32_t p = welds[tris[3u * n + j]], q = welds[tris[3u * n + (j + 1u) % 3u]];
        if (adjacency[3u * n + j] == t && ((p == b && q == a) || (p == a && q == b)))
            return 3u * n + j;
    }
    return NO_TRI;
}

/* Each pair once, from its lower half-edge, as the build met them. */
int stin__mesh_concave_edge(const stin__vertex *verts, const uint32_t *tris,
                            const uint32_t *adjacency, const uint32_t *welds, uint32_t tri_count)
{
    uint32_t he;
    for (he = 0; he < 3u * tri_count; he++) {
        uint32_t n = adjacency[he], h1;
        if (n == NO_TRI)
            continue;
        h1 = twin(tris, adjacency, welds, he / 3u, he % 3u, n);
        if (h1 != NO_TRI && h1 > he && !convex_edge(verts, tris, he / 3u, h1))
            return 1;
    }
    return 0;
}
