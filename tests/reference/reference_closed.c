/* SPDX-License-Identifier: MIT */
/* Whether an object's mesh is a closed, consistently oriented 2-manifold
 * once vertices at equal positions are welded: the meshes stin's shadow
 * volumes give the silhouette's volume (its mesh info's closed_manifold),
 * the only ones whose volumes follow the terminator rule. */
#include "reference_internal.h"

#include <stdlib.h>
#include <string.h>

static const float *sort_positions;

static int by_position(const void *a, const void *b)
{
    const float *p = sort_positions + 3 * (size_t)*(const uint32_t *)a;
    const float *q = sort_positions + 3 * (size_t)*(const uint32_t *)b;
    int c = memcmp(p, q, 3 * sizeof(float));
    return c ? c : (*(const uint32_t *)a > *(const uint32_t *)b) - (*(const uint32_t *)a < *(const uint32_t *)b);
}

/* directed edges (from, to) of welded vertices */
static int by_edge(const void *a, const void *b)
{
    const uint32_t *e = a, *f = b;
    uint32_t e0 = e[0] < e[1] ? e[0] : e[1], e1 = e[0] < e[1] ? e[1] : e[0];
    uint32_t f0 = f[0] < f[1] ? f[0] : f[1], f1 = f[0] < f[1] ? f[1] : f[0];
    if (e0 != f0)
        return e0 < f0 ? -1 : 1;
    return (e1 > f1) - (e1 < f1);
}

int ref_object_closed(const ref_object *o)
{
    size_t nv = o->vertex_count, ne = 3 * (size_t)o->triangle_count, i;
    uint32_t *order = malloc((nv + 1) * sizeof *order), *weld = malloc((nv + 1) * sizeof *weld);
    uint32_t *edges = malloc((2 * ne + 1) * sizeof *edges);
    int closed = order && weld && edges && ne > 0;
    for (i = 0; closed && i < nv; i++)
        order[i] = (uint32_t)i;
    sort_positions = o->positions;
    if (closed)
        qsort(order, nv, sizeof *order, by_position);
    for (i = 0; closed && i < nv; i++)
        weld[order[i]] = i > 0 && !memcmp(o->positions + 3 * (size_t)order[i],
                                           o->positions + 3 * (size_t)order[i - 1],
                                           3 * sizeof(float))
                             ? weld[order[i - 1]]
                             : order[i];
    for (i = 0; closed && i < ne; i++) {
        size_t t = i / 3, k = i % 3;
        edges[2 * i] = weld[o->indices[3 * t + k]];
        edges[2 * i + 1] = weld[o->indices[3 * t + (k + 1) % 3]];
    }
    if (closed)
        qsort(edges, ne, 2 * sizeof *edges, by_edge);
    /* every edge twice, traversed once each way */
    for (i = 0; closed && i < ne; i += 2)
        closed = i + 1 < ne && !by_edge(edges + 2 * i, edges + 2 * i + 2) &&
                 edges[2 * i] == edges[2 * i + 3] && edges[2 * i] != edges[2 * i + 1] &&
                 (i + 2 >= ne || by_edge(edges + 2 * i, edges + 2 * i + 4));
    free(order);
    free(weld);
    free(edges);
    return closed;
}
