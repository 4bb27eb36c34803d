/* SPDX-License-Identifier: MIT */
/* Tessellated primitives; orientation and seam rules in scene_primitives.h. */
#include "scene_primitives.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI_D 3.14159265358979323846

int scene_mesh_alloc(scene_mesh *m, uint32_t vertex_count, uint32_t triangle_count)
{
    m->positions = malloc((size_t)vertex_count * 3 * sizeof(float));
    m->normals = malloc((size_t)vertex_count * 3 * sizeof(float));
    m->uvs = malloc((size_t)vertex_count * 2 * sizeof(float));
    m->indices = malloc((size_t)triangle_count * 3 * sizeof(uint32_t));
    m->vertex_count = vertex_count;
    m->triangle_count = triangle_count;
    if (!m->positions || !m->normals || !m->uvs || !m->indices) {
        scene_mesh_release(m);
        return 0;
    }
    return 1;
}

void scene_mesh_release(scene_mesh *m)
{
    free(m->positions);
    free(m->normals);
    free(m->uvs);
    free(m->indices);
    m->positions = m->normals = m->uvs = NULL;
    m->indices = NULL;
    m->vertex_count = m->triangle_count = 0;
}

static void put_vertex(scene_mesh *m, uint32_t v, float px, float py, float pz,
                       float nx, float ny, float nz, float u, float t)
{
    m->positions[3 * v + 0] = px;
    m->positions[3 * v + 1] = py;
    m->positions[3 * v + 2] = pz;
    m->normals[3 * v + 0] = nx;
    m->normals[3 * v + 1] = ny;
    m->normals[3 * v + 2] = nz;
    m->uvs[2 * v + 0] = u;
    m->uvs[2 * v + 1] = t;
}

static void put_triangle(scene_mesh *m, uint32_t *t, uint32_t a, uint32_t b, uint32_t c)
{
    m->indices[3 * *t + 0] = a;
    m->indices[3 * *t + 1] = b;
    m->indices[3 * *t + 2] = c;
    (*t)++;
}

/* a, b, c, d counter-clockwise seen from the front. */
static void put_quad(scene_mesh *m, uint32_t *t, uint32_t a, uint32_t b, uint32_t c, uint32_t d)
{
    put_triangle(m, t, a, b, c);
    put_triangle(m, t, a, c, d);
}

/* cos/sin of 2*pi*i/n for i < n; callers index with i % n so that the seam
 * column reuses the first column's exact values. */
static int angle_table(int n, float **cs, float **sn)
{
    int i;
    *cs = malloc((size_t)n * sizeof(float));
    *sn = malloc((size_t)n * sizeof(float));
    if (!*cs || !*sn) {
        free(*cs);
        free(*sn);
        return 0;
    }
    for (i = 0; i < n; i++) {
        double a = 2.0 * PI_D * i / n;
        (*cs)[i] = (float)cos(a);
        (*sn)[i] = (float)sin(a);
    }
    return 1;
}

int scene_prim_plane(scene_mesh *m, float sx, float sz, int nx, int nz)
{
    uint32_t row = (uint32_t)nx + 1, t = 0;
    int i, j;
    if (!scene_mesh_alloc(m, row * (uint32_t)(nz + 1), 2u * (uint32_t)nx * (uint32_t)nz))
        return 0;
    for (j = 0; j <= nz; j++)
        for (i = 0; i <= nx; i++) {
            float u = (float)i / nx, w = (float)j / nz;
            put_vertex(m, (uint32_t)j * row + (uint32_t)i, sx * (u - 0.5f), 0.0f,
                       sz * (w - 0.5f), 0, 1, 0, u, 1.0f - w);
        }
    for (j = 0; j < nz; j++)
        for (i = 0; i < nx; i++) {
            uint32_t a = (uint32_t)j * row + (uint32_t)i;
            put_quad(m, &t, a, a + row, a + row + 1, a + 1);
        }
    return 1;
}

int scene_prim_box(scene_mesh *m, float sx, float sy, float sz)
{
    /* Per face: outward normal n, then in-face axes u, v with u x v = n. */
    static const float faces[6][9] = {
        { 1, 0, 0, 0, 0, -1, 0, 1, 0 }, { -1, 0, 0, 0, 0, 1, 0, 1, 0 },
        { 0, 1, 0, 1, 0, 0, 0, 0, -1 }, { 0, -1, 0, 1, 0, 0, 0, 0, 1 },
        { 0, 0, 1, 1, 0, 0, 0, 1, 0 },  { 0, 0, -1, -1, 0, 0, 0, 1, 0 },
    };
    static const float corner[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
    const float h[3] = { 0.5f * sx, 0.5f * sy, 0.5f * sz };
    uint32_t t = 0, f, k;
    if (!scene_mesh_alloc(m, 24, 12))
        return 0;
    for (f = 0; f < 6; f++) {
        const float *n = faces[f], *u = faces[f] + 3, *v = faces[f] + 6;
        for (k = 0; k < 4; k++) {
            float p[3];
            int c;
            for (c = 0; c < 3; c++)
                p[c] = h[c] * (n[c] + corner[k][0] * u[c] + corner[k][1] * v[c]);
            put_vertex(m, 4 * f + k, p[0], p[1], p[2], n[0], n[1], n[2],
                       0.5f + 0.5f * corner[k][0], 0.5f + 0.5f * corner[k][1]);
        }
        put_quad(m, &t, 4 * f, 4 * f + 1, 4 * f + 2, 4 * f + 3);
    }
    return 1;
}

int scene_prim_sphere(scene_mesh *m, float radius, int slices, int stacks)
{
    /* Layout: `slices` north pole copies (one per fan triangle so each gets
     * its own u), stacks-1 rings of slices+1 (the last column repeats the
     * first with u = 1), then `slices` south pole copies. */
    uint32_t ring = (uint32_t)slices + 1, t = 0;
    uint32_t first_ring = (uint32_t)slices;
    uint32_t south = first_ring + ring * (uint32_t)(stacks - 1);
    float *cs, *sn;
    int i, j;
    if (!angle_table(slices, &cs, &sn))
        return 0;
    if (!scene_mesh_alloc(m, south + (uint32_t)slices, 2u * (uint32_t)slices * (uint32_t)(stacks - 1))) {
        free(cs);
        free(sn);
        return 0;
    }
    for (i = 0; i < slices; i++) {
        float u = (i + 0.5f) / slices;
        put_vertex(m, (uint32_t)i, 0, radius, 0, 0, 1, 0, u, 1);
        put_vertex(m, south + (uint32_t)i, 0, -radius, 0, 0, -1, 0, u, 0);
    }
    for (j = 1; j < stacks; j++) {
        double phi = PI_D * j / stacks;
        float y = (float)cos(phi), s = (float)sin(phi);
        for (i = 0; i <= slices; i++) {
            float nx = s * sn[i % slices], nz = s * cs[i % slices];
            put_vertex(m, first_ring + (uint32_t)(j - 1) * ring + (uint32_t)i,
                       radius * nx, radius * y, radius * nz, nx, y, nz,
                       (float)i / slices, 1.0f - (float)j / stacks);
        }
    }
    for (i = 0; i < slices; i++) {
        uint32_t top = first_ring + (uint32_t)i;
        uint32_t bottom = first_ring + ring * (uint32_t)(stacks - 2) + (uint32_t)i;
        put_triangle(m, &t, (uint32_t)i, top, top + 1);
        for (j = 1; j < stacks - 1; j++) {
            uint32_t a = first_ring + ring * (uint32_t)(j - 1) + (uint32_t)i;
            put_quad(m, &t, a, a + ring, a + ring + 1, a + 1);
        }
        put_triangle(m, &t, bottom, south + (uint32_t)i, bottom + 1);
    }
    free(cs);
    free(sn);
    return 1;
}

int scene_prim_torus(scene_mesh *m, float major_radius, float minor_radius, int rings, int sides)
{
    uint32_t row = (uint32_t)sides + 1, t = 0;
    float *rc, *rs, *sc, *ss;
    int i, j, ok;
    if (!angle_table(rings, &rc, &rs))
        return 0;
    ok = angle_table(sides, &sc, &ss);
    if (ok && !scene_mesh_alloc(m, row * (uint32_t)(rings + 1), 2u * (uint32_t)rings * (uint32_t)sides)) {
        free(sc);
        free(ss);
        ok = 0;
    }
    if (!ok) {
        free(rc);
        free(rs);
        return 0;
    }
    for (i = 0; i <= rings; i++)
        for (j = 0; j <= sides; j++) {
            float ct = rc[i % rings], st = rs[i % rings];
            float cp = sc[j % sides], sp = ss[j % sides];
            float d = major_radius + minor_radius * cp;
            put_vertex(m, (uint32_t)i * row + (uint32_t)j, d * ct, minor_radius * sp, d * st,
                       cp * ct, sp, cp * st, (float)i / rings, (float)j / sides);
        }
    for (i = 0; i < rings; i++)
        for (j = 0; j < sides; j++) {
            uint32_t a = (uint32_t)i * row + (uint32_t)j;
            put_quad(m, &t, a, a + 1, a + row + 1, a + row);
        }
    free(rc);
    free(rs);
    free(sc);
    free(ss);
    return 1;
}

int scene_prim_cylinder(scene_mesh *m, float radius, float height, int slices, int capped)
{
    /* Side: a top row and a bottom row of slices+1 vertices (seam repeated);
     * each cap: a centre and `slices` rim vertices. */
    uint32_t row = (uint32_t)slices + 1, n = (uint32_t)slices, t = 0, i;
    uint32_t verts = 2 * row + (capped ? 2 * (n + 1) : 0);
    uint32_t tris = 2 * n + (capped ? 2 * n : 0);
    float hy = 0.5f * height, *cs, *sn;
    if (!angle_table(slices, &cs, &sn))
        return 0;
    if (!scene_mesh_alloc(m, verts, tris)) {
        free(cs);
        free(sn);
        return 0;
    }
    for (i = 0; i <= n; i++) {
        float x = sn[i % n], z = cs[i % n], u = (float)i / n;
        put_vertex(m, i, radius * x, hy, radius * z, x, 0, z, u, 1);
        put_vertex(m, row + i, radius * x, -hy, radius * z, x, 0, z, u, 0);
    }
    for (i = 0; i < n; i++)
        put_quad(m, &t, i, row + i, row + i + 1, i + 1);
    if (capped) {
        uint32_t top = 2 * row, bottom = top + n + 1;
        put_vertex(m, top, 0, hy, 0, 0, 1, 0, 0.5f, 0.5f);
        put_vertex(m, bottom, 0, -hy, 0, 0, -1, 0, 0.5f, 0.5f);
        for (i = 0; i < n; i++) {
            float x = sn[i], z = cs[i];
            put_vertex(m, top + 1 + i, radius * x, hy, radius * z, 0, 1, 0,
                       0.5f + 0.5f * x, 0.5f - 0.5f * z);
            put_vertex(m, bottom + 1 + i, radius * x, -hy, radius * z, 0, -1, 0,
                       0.5f + 0.5f * x, 0.5f + 0.5f * z);
        }
        for (i = 0; i < n; i++) {
            uint32_t next = (i + 1) % n;
            put_triangle(m, &t, top, top + 1 + i, top + 1 + next);
            put_triangle(m, &t, bottom, bottom + 1 + next, bottom + 1 + i);
        }
    }
    free(cs);
    free(sn);
    return 1;
}
