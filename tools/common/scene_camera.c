/* SPDX-License-Identifier: MIT */
/* Camera matrices with gluLookAt / gluPerspective semantics (so the GL1
 * tier, the shader tiers and the reference all agree), and scene stats. */
#include "scene.h"

#include <math.h>
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
