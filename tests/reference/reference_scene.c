/* SPDX-License-Identifier: MIT */
/* Builds the Embree scene of a reference: world-space copies of every object. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reference_internal.h"

static void set_err(char *err, size_t err_size, const char *fmt, ...)
{
    va_list ap;
    if (!err || err_size == 0)
        return;
    va_start(ap, fmt);
    vsnprintf(err, err_size, fmt, ap);
    va_end(ap);
}

static int device_ok(RTCDevice device, const char *what, char *err, size_t err_size)
{
    enum RTCError e = rtcGetDeviceError(device);
    if (e == RTC_ERROR_NONE)
        return 1;
    set_err(err, err_size, "embree: %s failed (error %d)", what, (int)e);
    return 0;
}

/* Normals go through the inverse transpose = cofactor matrix / det, so a
 * mirroring transform keeps normals pointing out of the surface. */
void ref_normal_matrix(const float m[16], double n[9])
{
    /* a[r][c] = m[c*4 + r] (column-major) */
    double a[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            a[r][c] = m[c * 4 + r];
    double cof[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            cof[r][c] = a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1];
        }
    double det = a[0][0] * cof[0][0] + a[0][1] * cof[0][1] + a[0][2] * cof[0][2];
    double sign = det < 0.0 ? -1.0 : 1.0; /* only the direction matters: normals are renormalised */
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            n[r * 3 + c] = sign * cof[r][c];
}

static int copy_object(const scene *s, int index, ref_object *o, char *err, size_t err_size)
{
    const scene_object *so = &s->objects[index];
    if (so->mesh < 0 || so->mesh >= s->mesh_count) {
        set_err(err, err_size, "object %d: mesh index %d out of range", index, so->mesh);
        return 0;
    }
    if (so->material < 0 || so->material >= s->material_count) {
        set_err(err, err_size, "object %d: material index %d out of range", index, so->material);
        return 0;
    }
    const scene_mesh *m = &s->meshes[so->mesh];
    if ((m->vertex_count > 0 && !m->positions) || (m->triangle_count > 0 && !m->indices)) {
        set_err(err, err_size, "mesh '%s': no positions or indices", m->name);
        return 0;
    }
    for (uint64_t i = 0; i < 3ull * m->triangle_count; i++)
        if (m->indices[i] >= m->vertex_count) {
            set_err(err, err_size, "mesh '%s': vertex index %u out of range", m->name,
                    (unsigned)m->indices[i]);
            return 0;
        }
    size_t nv = m->vertex_count, nt = m->triangle_count;
    o->vertex_count = m->vertex_count;
    o->triangle_count = m->triangle_count;
    o->positions = malloc((3 * nv + 1) * sizeof(float));
    o->normals = malloc((3 * nv + 1) * sizeof(float));
    o->indices = malloc((3 * nt + 1) * sizeof(uint32_t));
    o->uvs = m->uvs ? malloc((2 * nv + 1) * sizeof(float)) : NULL;
    if (!o->positions || !o->normals || !o->indices || (m->uvs && !o->uvs)) {
        set_err(err, err_size, "out of memory");
        return 0;
    }
    const float *t = so->transform;
    double nm[9];
    ref_normal_matrix(t, nm);
    for (size_t v = 0; v < nv; v++) {
        const float *p = m->positions + 3 * v;
        for (int r = 0; r < 3; r++)
            o->positions[3 * v + r] = (float)((double)t[r] * p[0] + (double)t[4 + r] * p[1] +
                                              (double)t[8 + r] * p[2] + t[12 + r]);
        double n[3] = {0, 0, 0}, len = 0;
        if (m->normals) {
            const float *q = m->normals + 3 * v;
            for (int r = 0; r < 3; r++) {
                n[r] = nm[r * 3] * q[0] + nm[r * 3 + 1] * q[1] + nm[r * 3 + 2] * q[2];
                len += n[r] * n[r];
            }
        }
        len = sqrt(len);
        for (int r = 0; r < 3; r++)
            o->normals[3 * v + r] = len > 0 && isfinite(len) ? (float)(n[r] / len) : 0.0f;
    }
    o->positions[3 * nv] = 0.0f;
    o->normals[3 * nv] = 0.0f;
    if (nt > 0)
        memcpy(o->indices, m->indices, 3 * nt * sizeof(uint32_t));
    if (o->uvs && nv > 0)
        memcpy(o->uvs, m->uvs, 2 * nv * sizeof(float));
    o->closed = ref_object_closed(o);
    return 1;
}

/* Largest of the bounding-box diagonal and the largest coordinate, so the
 * visibility offset stays above float resolution far from the origin. */
static double scene_extent(const reference *r)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    double big = 0.0;
    for (int i = 0; i < r->object_count; i++) {
        const ref_object *o = &r->objects[i];
        for (size_t k = 0; k < 3 * (size_t)o->vertex_count; k++) {
            double x = o->positions[k];
            if (!isfinite(x))
                continue;
            if (x < lo[k % 3]) lo[k % 3] = x;
            if (x > hi[k % 3]) hi[k % 3] = x;
            if (fabs(x) > big) big = fabs(x);
        }
    }
    double d2 = 0.0;
    for (int c = 0; c < 3; c++)
        if (hi[c] >= lo[c])
            d2 += (hi[c] - lo[c]) * (hi[c] - lo[c]);
    double e = sqrt(d2) > big ? sqrt(d2) : big;
    return e > 0.0 ? e : 1.0;
}

static int attach(reference *r, unsigned id, char *err, size_t err_size)
{
    ref_object *o = &r->objects[id];
    if (o->triangle_count == 0)
        return 1;
    RTCGeometry g = rtcNewGeometry(r->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!g)
        return device_ok(r->device, "rtcNewGeometry", err, err_size);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, o->positions, 0,
                               3 * sizeof(float), o->vertex_count);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, o->indices, 0,
                               3 * sizeof(uint32_t), o->triangle_count);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(r->rtc, g, id);
    rtcReleaseGeometry(g);
    return device_ok(r->device, "geometry set-up", err, err_size);
}

reference *reference_create(const scene *s, char *err, size_t err_size)
{
    set_err(err, err_size, "ok");
    if (!s || s->object_count < 0 || (s->object_count > 0 && !s->objects)) {
        set_err(err, err_size, "reference_create: no scene");
        return NULL;
    }
    reference *r = calloc(1, sizeof *r);
    if (!r) {
        set_err(err, err_size, "out of memory");
        return NULL;
    }
    r->s = s;
    r->object_count = s->object_count;
    r->objects = calloc(s->object_count > 0 ? (size_t)s->object_count : 1, sizeof *r->objects);
    if (!r->objects) {
        set_err(err, err_size, "out of memory");
        free(r);
        return NULL;
    }
    for (int i = 0; i < s->object_count; i++)
        if (!copy_object(s, i, &r->objects[i], err, err_size))
            goto fail;
    r->eps = REFERENCE_EPS_SCALE * scene_extent(r);
    r->area_samples = REFERENCE_AREA_SAMPLES;

    r->device = rtcNewDevice(NULL);
    if (!r->device) {
        set_err(err, err_size, "embree: rtcNewDevice failed (error %d)",
                (int)rtcGetDeviceError(NULL));
        goto fail;
    }
    r->rtc = rtcNewScene(r->device);
    if (!device_ok(r->device, "rtcNewScene", err, err_size))
        goto fail;
    /* Robust mode: no hits lost through cracks between neighbouring triangles.
     * Context filters: the CSG rays collect every hit along the ray, and
     * visibility rays pass through CSG primitives (reference_csg.c). */
    rtcSetSceneFlags(r->rtc, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    rtcSetSceneBuildQuality(r->rtc, RTC_BUILD_QUALITY_HIGH);
    for (int i = 0; i < r->object_count; i++)
        if (!attach(r, (unsigned)i, err, err_size))
            goto fail;
    rtcCommitScene(r->rtc);
    if (!device_ok(r->device, "rtcCommitScene", err, err_size))
        goto fail;
    ref_cache_snapshot(r);
    return r;
fail:
    reference_destroy(r);
    return NULL;
}

void reference_destroy(reference *r)
{
    if (!r)
        return;
    if (r->rtc)
        rtcReleaseScene(r->rtc);
    if (r->device)
        rtcReleaseDevice(r->device);
    for (int i = 0; i < r->object_count; i++) {
        free(r->objects[i].positions);
        free(r->objects[i].normals);
        free(r->objects[i].uvs);
        free(r->objects[i].indices);
    }
    free(r->objects);
    free(r->csg_primitive);
    ref_csg_cast_free(r->csg_cast);
    free(r);
}
