/* SPDX-License-Identifier: MIT */
/* Camera matrices with gluLookAt / gluPerspective semantics (so the GL1
 * tier, the shader tiers and the reference all agree), and scene stats. */
#include "scene_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void normalize3(double v[3])
{
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (len > 0) {
        v[0] /= len;
        v[1] /= len;
        v[2] /= len;
    }
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

void scene_camera_matrices(const scene_camera *cam, int width, int height,
                           float view[16], float projection[16])
{
    double f[3], s[3], u[3], up[3], e[3];
    double aspect = height > 0 ? (double)width / height : 1.0;
    double n = cam->near_plane, fa = cam->far_plane;
    double cot = 1.0 / tan(cam->fovy_deg * 3.14159265358979323846 / 360.0);
    int i;
    for (i = 0; i < 3; i++) {
        f[i] = (double)cam->target[i] - cam->eye[i];
        up[i] = cam->up[i];
        e[i] = cam->eye[i];
    }
    normalize3(f);
    cross3(f, up, s);
    normalize3(s);
    cross3(s, f, u);

    memset(view, 0, 16 * sizeof(float));
    for (i = 0; i < 3; i++) {
        view[4 * i + 0] = (float)s[i];
        view[4 * i + 1] = (float)u[i];
        view[4 * i + 2] = (float)-f[i];
    }
    view[12] = (float)-(s[0] * e[0] + s[1] * e[1] + s[2] * e[2]);
    view[13] = (float)-(u[0] * e[0] + u[1] * e[1] + u[2] * e[2]);
    view[14] = (float)(f[0] * e[0] + f[1] * e[1] + f[2] * e[2]);
    view[15] = 1;

    memset(projection, 0, 16 * sizeof(float));
    projection[0] = (float)(cot / aspect);
    projection[5] = (float)cot;
    projection[10] = (float)((fa + n) / (n - fa));
    projection[11] = -1;
    projection[14] = (float)(2 * fa * n / (n - fa));
}

uint64_t scene_triangle_count(const scene *s)
{
    uint64_t total = 0;
    int i;
    for (i = 0; i < s->object_count; i++)
        total += s->meshes[s->objects[i].mesh].triangle_count;
    return total;
}

void scene_mat4_mul(const float a[16], const float b[16], float out[16])
{
    float r[16];
    int i, k;
    for (i = 0; i < 4; i++)
        for (k = 0; k < 4; k++)
            r[4 * i + k] = a[k] * b[4 * i] + a[4 + k] * b[4 * i + 1] + a[8 + k] * b[4 * i + 2] +
                           a[12 + k] * b[4 * i + 3];
    memcpy(out, r, sizeof r);
}

/* Object-space box of each mesh: 6 floats (lo, hi); empty meshes invert. */
static float *mesh_boxes(const scene *s)
{
    float *box = malloc(((size_t)s->mesh_count + 1) * 6 * sizeof *box);
    int i, k;
    uint32_t v;
    for (i = 0; box && i < s->mesh_count; i++) {
        const scene_mesh *m = &s->meshes[i];
        float *b = box + 6 * (size_t)i;
        for (k = 0; k < 3; k++) {
            b[k] = INFINITY;
            b[3 + k] = -INFINITY;
        }
        for (v = 0; v < m->vertex_count; v++)
            for (k = 0; k < 3; k++) {
                b[k] = fminf(b[k], m->positions[3 * (size_t)v + k]);
                b[3 + k] = fmaxf(b[3 + k], m->positions[3 * (size_t)v + k]);
            }
    }
    return box;
}

/* World bounds of every object: its mesh's box corners transformed. */
static int scene_bounds(const scene *s, double lo[3], double hi[3])
{
    float *box = mesh_boxes(s);
    int i, c, k;
    for (k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (i = 0; box && i < s->object_count; i++) {
        const scene_object *o = &s->objects[i];
        const float *b = box + 6 * (size_t)o->mesh;
        for (c = 0; b[0] <= b[3] && c < 8; c++) {
            const float p[3] = { b[(c & 1) * 3], b[1 + (c & 2 ? 3 : 0)], b[2 + (c & 4 ? 3 : 0)] };
            for (k = 0; k < 3; k++) {
                double w = (double)o->transform[k] * p[0] + (double)o->transform[4 + k] * p[1] +
                           (double)o->transform[8 + k] * p[2] + o->transform[12 + k];
                lo[k] = w < lo[k] ? w : lo[k];
                hi[k] = w > hi[k] ? w : hi[k];
            }
        }
    }
    free(box);
    return lo[0] <= hi[0];
}

void scene_camera_frame(const scene *s, int width, int height, scene_camera *cam)
{
    double lo[3], hi[3], c[3], d[3] = { 0, 1, 2 }, r = 0, half, dist;
    double aspect = height > 0 ? (double)width / height : 1.0;
    int k;
    if (!s->has_camera) {
        const scene_camera def = { { 0, 0, 5 }, { 0, 0, 0 }, { 0, 1, 0 }, 45, 0.1f, 100 };
        *cam = def;
    } else {
        for (k = 0; k < 3; k++)
            d[k] = (double)cam->eye[k] - cam->target[k];
    }
    normalize3(d);
    if (!scene_bounds(s, lo, hi))
        lo[0] = lo[1] = lo[2] = hi[0] = hi[1] = hi[2] = 0;
    for (k = 0; k < 3; k++) {
        c[k] = 0.5 * (lo[k] + hi[k]);
        r += 0.25 * (hi[k] - lo[k]) * (hi[k] - lo[k]);
    }
    r = sqrt(r);
    if (!(r > 1e-6))
        r = 1; /* a point: any size shows it */
    /* the narrower of the two half angles decides */
    half = cam->fovy_deg * 3.14159265358979323846 / 360.0;
    if (aspect < 1)
        half = atan(tan(half) * aspect);
    dist = 1.05 * r / sin(half);
    for (k = 0; k < 3; k++) {
        cam->target[k] = (float)c[k];
        cam->eye[k] = (float)(c[k] + d[k] * dist);
    }
    cam->near_plane = (float)(0.5 * (dist - r));
    cam->far_plane = (float)(2 * (dist + r));
}
