/* SPDX-License-Identifier: MIT */
/* Which vertices are one position, for adjacency: bit-equal positions, or
 * positions within a tolerance on every axis (a grid of tolerance-sized
 * cells; a vertex looks for an earlier one in its own and the 26
 * neighbouring cells). Welded vertices are snapped onto the first of their
 * group so that whatever is built from the mesh stays watertight. */
#include "internal.h"

#define NO_VERTEX 0xffffffffu
#define DEFAULT_RELATIVE (1.0 / 1048576.0) /* 2^-20 of the largest extent */
#define GRID_CELLS_MAX 1099511627776.0     /* 2^40 cells a side: finer is bit-equal anyway */

uint32_t stin__weld_mix(uint32_t h)
{
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

static uint32_t float_bits(float f)
{
    union { float f; uint32_t u; } v;
    v.f = f == 0.0f ? 0.0f : f; /* -0 welds with +0 */
    return v.u;
}

typedef struct grid {
    double origin[3], cell;
} grid;

static void cell_of(const grid *g, const float *p, int64_t c[3])
{
    int k;
    for (k = 0; k < 3; k++) /* non-negative from the bounds' minimum: truncation floors */
        c[k] = (int64_t)(((double)p[k] - g->origin[k]) / g->cell);
}

static uint32_t cell_hash(const int64_t c[3])
{
    return stin__weld_mix((uint32_t)c[0] ^
                          stin__weld_mix((uint32_t)c[1] ^ stin__weld_mix((uint32_t)c[2])));
}

static int same_bits(const float *a, const float *b)
{
    return float_bits(a[0]) == float_bits(b[0]) && float_bits(a[1]) == float_bits(b[1]) &&
           float_bits(a[2]) == float_bits(b[2]);
}

static int within(const float *a, const float *b, double tol)
{
    int k;
    for (k = 0; k < 3; k++) {
        double d = (double)a[k] - (double)b[k];
        if (d > tol || d < -tol)
            return 0;
    }
    return 1;
}

/* The cell size, or 0 for bit-equal welding. */
static double cell_size(const stin__vertex *verts, uint32_t n, float tolerance, grid *g)
{
    double lo[3], hi[3], extent = 0.0, tol;
    uint32_t i;
    int k;
    if (tolerance < 0.0f || n == 0)
        return 0.0;
    for (k = 0; k < 3; k++)
        lo[k] = hi[k] = verts[0].position[k];
    for (i = 1; i < n; i++)
        for (k = 0; k < 3; k++) {
            double v = verts[i].position[k];
            lo[k] = v < lo[k] ? v : lo[k];
            hi[k] = v > hi[k] ? v : hi[k];
        }
    for (k = 0; k < 3; k++) {
        g->origin[k] = lo[k];
        extent = hi[k] - lo[k] > extent ? hi[k] - lo[k] : extent;
    }
    tol = tolerance > 0.0f ? (double)tolerance : extent * DEFAULT_RELATIVE;
    if (!(tol > 0.0) || extent / tol > GRID_CELLS_MAX)
        return 0.0;
    return tol;
}

static uint32_t find_exact(const stin__vertex *verts, uint32_t i, uint32_t *table, uint32_t size)
{
    const float *p = verts[i].position;
    uint32_t s = stin__weld_mix(float_bits(p[0]) ^
                                stin__weld_mix(float_bits(p[1]) ^ stin__weld_mix(float_bits(p[2])))) &
                 (size - 1);
    for (;;) {
        uint32_t o = table[s];
        if (o == NO_VERTEX) {
            table[s] = i;
            return i;
        }
        if (same_bits(verts[o].position, p))
            return o;
        s = (s + 1) & (size - 1);
    }
}

/* An earlier vertex within g->cell of vertex i, else i (then entered in its cell). */
static uint32_t find_near(const stin__vertex *verts, uint32_t i, const grid *g, uint32_t *table,
                          uint32_t size)
{
    const float *p = verts[i].position;
    int64_t own[3], c[3], oc[3];
    int dx, dy, dz;
    uint32_t s;
    cell_of(g, p, own);
    for (dx = -1; dx <= 1; dx++)
        for (dy = -1; dy <= 1; dy++)
            for (dz = -1; dz <= 1; dz++) {
                c[0] = own[0] + dx;
                c[1] = own[1] + dy;
                c[2] = own[2] + dz;
                if (c[0] < 0 || c[1] < 0 || c[2] < 0)
                    continue;
                for (s = cell_hash(c) & (size - 1); table[s] != NO_VERTEX; s = (s + 1) & (size - 1)) {
                    uint32_t o = table[s];
                    cell_of(g, verts[o].position, oc);
                    if (oc[0] == c[0] && oc[1] == c[1] && oc[2] == c[2] &&
                        within(verts[o].position, p, g->cell))
                        return o;
                }
            }
    for (s = cell_hash(own) & (size - 1); table[s] != NO_VERTEX; s = (s + 1) & (size - 1)) {
    }
    table[s] = i;
    return i;
}

uint32_t stin__weld_positions(stin__vertex *verts, uint32_t n, float tolerance, uint32_t *weld,
                              uint32_t *table, uint32_t size)
{
    grid g;
    uint32_t i, moved = 0;
    int k;
    g.cell = cell_size(verts, n, tolerance, &g);
    for (i = 0; i < size; i++)
        table[i] = NO_VERTEX;
    for (i = 0; i < n; i++) {
        weld[i] = g.cell > 0.0 ? find_near(verts, i, &g, table, size) : find_exact(verts, i, table, size);
        if (weld[i] != i && !same_bits(verts[i].position, verts[weld[i]].position)) {
            for (k = 0; k < 3; k++)
                verts[i].position[k] = verts[weld[i]].position[k];
            moved++;
        }
    }
    return moved;
}
