/* SPDX-License-Identifier: MIT */
/* Primary rays (the camera of scene_camera_matrices(), recomputed here as an
 * independent check) and visibility rays toward the lights. */
#include <math.h>
#include <string.h>

#include "reference_internal.h"
#include "stin/stin.h"

enum { BATCH = 64 }; /* rays per rtcIntersect1M call */

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static double normalize3(double v[3])
{
    double len = sqrt(dot3(v, v));
    if (len > 0.0 && isfinite(len))
        for (int i = 0; i < 3; i++)
            v[i] /= len;
    return len;
}

void ref_fill_hit(const reference *r, unsigned object, unsigned prim, float u, float v,
                  const float eye[3], ref_hit *hit)
{
    const ref_object *o = &r->objects[object];
    const uint32_t *tri = o->indices + 3 * (size_t)prim;
    double w[3] = {1.0 - (double)u - (double)v, u, v};
    double P[3] = {0, 0, 0}, N[3] = {0, 0, 0}, uv[2] = {0, 0}, e1[3], e2[3], Ng[3];
    for (int k = 0; k < 3; k++) {
        const float *p = o->positions + 3 * (size_t)tri[k];
        const float *n = o->normals + 3 * (size_t)tri[k];
        for (int c = 0; c < 3; c++) {
            P[c] += w[k] * p[c];
            N[c] += w[k] * n[c];
        }
        if (o->uvs)
            for (int c = 0; c < 2; c++)
                uv[c] += w[k] * o->uvs[2 * (size_t)tri[k] + c];
    }
    const float *A = o->positions + 3 * (size_t)tri[0];
    const float *B = o->positions + 3 * (size_t)tri[1];
    const float *C = o->positions + 3 * (size_t)tri[2];
    for (int c = 0; c < 3; c++) {
        e1[c] = (double)B[c] - A[c];
        e2[c] = (double)C[c] - A[c];
    }
    cross3(e1, e2, Ng);
    if (!(normalize3(Ng) > 0.0)) { /* degenerate: Embree does not hit these, but be safe */
        Ng[0] = 0; Ng[1] = 0; Ng[2] = 1;
    }
    if (!(normalize3(N) > 0.0)) /* no normals, or they cancel out */
        memcpy(N, Ng, sizeof N);

    memset(hit, 0, sizeof *hit);
    hit->hit = 1;
    hit->object = (int)object;
    hit->prim = (int)prim;
    hit->u = u;
    hit->v = v;
    double d[3] = {P[0] - eye[0], P[1] - eye[1], P[2] - eye[2]};
    hit->t = (float)sqrt(dot3(d, d));
    for (int c = 0; c < 3; c++) {
        hit->P[c] = (float)P[c];
        hit->N[c] = (float)N[c];
        hit->Ng[c] = (float)Ng[c];
    }
    hit->uv[0] = (float)uv[0];
    hit->uv[1] = (float)uv[1];
}

/* gluLookAt's basis: forward f, side s = f x up, true up u = s x f. */
static int camera_basis(const scene_camera *cam, double f[3], double s[3], double u[3])
{
    double up[3] = {cam->up[0], cam->up[1], cam->up[2]};
    for (int c = 0; c < 3; c++)
        f[c] = (double)cam->target[c] - cam->eye[c];
    if (!(normalize3(f) > 0.0))
        return 0;
    cross3(f, up, s);
    if (!(normalize3(s) > 0.0))
        return 0;
    cross3(s, f, u);
    return 1;
}

static void trace_batch(const reference *r, struct RTCRayHit *rays, unsigned n, ref_hit *out)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect1M(r->rtc, &ctx, rays, n, sizeof *rays);
    for (unsigned i = 0; i < n; i++) {
        const struct RTCHit *h = &rays[i].hit;
        if (h->geomID == RTC_INVALID_GEOMETRY_ID) {
            memset(&out[i], 0, sizeof out[i]);
            continue;
        }
        ref_fill_hit(r, h->geomID, h->primID, h->u, h->v, r->s->camera.eye, &out[i]);
    }
}

int ref_frame_of(const scene_camera *cam, int width, int height, ref_camera_frame *cf)
{
    if (width <= 0 || height <= 0 || !camera_basis(cam, cf->f, cf->s, cf->u) ||
        !(cam->fovy_deg > 0.0f && cam->fovy_deg < 180.0f))
        return 0;
    cf->ty = tan(cam->fovy_deg * (3.14159265358979323846 / 360.0));
    cf->tx = cf->ty * width / height;
    return 1;
}

/* Unnormalised, with a forward component of exactly 1: t along it is the
 * distance along the view axis, so [near, far] is GL's clipping. (px, py):
 * window position in pixels from the bottom-left corner. */
void ref_window_dir(const ref_camera_frame *cf, int width, int height, double px, double py,
                       double dir[3])
{
    double nx = 2.0 * px / width - 1.0, ny = 2.0 * py / height - 1.0;
    for (int c = 0; c < 3; c++)
        dir[c] = cf->f[c] + nx * cf->tx * cf->s[c] + ny * cf->ty * cf->u[c];
}

static int primary_traced(const reference *r, int width, int height, ref_hit *hits)
{
    return reference_primary_at(r, width, height, 0.5, 0.5, hits);
}

int reference_primary_at(const reference *r, int width, int height, double dx, double dy,
                         ref_hit *hits)
{
    if (!r || !hits)
        return 0;
    const scene_camera *cam = &r->s->camera;
    ref_camera_frame cf;
    if (!ref_frame_of(cam, width, height, &cf))
        return 0;
    struct RTCRayHit rays[BATCH];
    size_t total = (size_t)width * (size_t)height, base = 0;
    unsigned n = 0;
    for (size_t i = 0; i < total; i++) {
        double dir[3];
        struct RTCRayHit *rh = &rays[n];
        ref_window_dir(&cf, width, height, (double)(i % (size_t)width) + dx,
                   (double)(i / (size_t)width) + dy, dir);
        memset(rh, 0, sizeof *rh);
        rh->ray.org_x = cam->eye[0];
        rh->ray.org_y = cam->eye[1];
        rh->ray.org_z = cam->eye[2];
        rh->ray.dir_x = (float)dir[0];
        rh->ray.dir_y = (float)dir[1];
        rh->ray.dir_z = (float)dir[2];
        rh->ray.tnear = cam->near_plane;
        rh->ray.tfar = cam->far_plane;
        rh->ray.mask = 0xffffffffu;
        rh->hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh->hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        if (++n == BATCH || i + 1 == total) {
            trace_batch(r, rays, n, hits + base);
            base += n;
            n = 0;
        }
    }
    return rtcGetDeviceError(r->device) == RTC_ERROR_NONE;
}

/* Cached by the reference's state and the size (reference_cache.h). */
int reference_primary(const reference *r, int width, int height, ref_hit *hits)
{
    ref_hasher h;
    ref_cache_key key;
    ref_cache_part part;
    int cached = 0;
    if (r && hits && width > 0 && height > 0 && ref_cache_key_begin(r, "primary", &h)) {
        ref_hash_u64(&h, (uint64_t)width);
        ref_hash_u64(&h, (uint64_t)height);
        ref_cache_key_end(&h, &key);
        part.data = hits;
        part.size = (size_t)width * (size_t)height * sizeof *hits;
        cached = 1;
        if (ref_cache_load(&key, &part, 1))
            return 1;
    }
    int ok;
    if (cached)
        ref_cache_compute_begin();
    ok = primary_traced(r, width, height, hits);
    if (cached)
        ref_cache_compute_end();
    if (!ok)
        return 0;
    if (cached)
        ref_cache_store(&key, &part, 1);
    return 1;
}

int reference_hit_on_plane(const reference *r, int width, int height, const ref_hit *hit,
                           double px, double py, ref_hit *out)
{
    if (!r || !hit || !out || !hit->hit || hit->object < 0 || hit->object >= r->object_count)
        return 0;
    const ref_object *o = &r->objects[hit->object];
    const uint32_t *tri = o->indices + 3 * (size_t)hit->prim;
    const float *eye = r->s->camera.eye;
    ref_camera_frame cf;
    double dir[3], e1[3], e2[3], q[3], Ng[3];
    if (!ref_frame_of(&r->s->camera, width, height, &cf))
        return 0;
    ref_window_dir(&cf, width, height, px, py, dir);
    for (int c = 0; c < 3; c++) {
        double a = o->positions[3 * (size_t)tri[0] + c];
        e1[c] = o->positions[3 * (size_t)tri[1] + c] - a;
        e2[c] = o->positions[3 * (size_t)tri[2] + c] - a;
        q[c] = eye[c] - a;
    }
    cross3(e1, e2, Ng);
    double den = dot3(dir, Ng);
    if (!(fabs(den) > 1e-30 * sqrt(dot3(Ng, Ng) * dot3(dir, dir))))
        return 0; /* the ray runs along the plane */
    double t = -dot3(q, Ng) / den;
    for (int c = 0; c < 3; c++)
        q[c] += t * dir[c]; /* the point on the plane, from vertex A */
    /* barycentrics of q in (e1, e2), beyond the triangle's edges too */
    double d11 = dot3(e1, e1), d12 = dot3(e1, e2), d22 = dot3(e2, e2);
    double dq1 = dot3(q, e1), dq2 = dot3(q, e2), det = d11 * d22 - d12 * d12;
    ref_fill_hit(r, (unsigned)hit->object, (unsigned)hit->prim, (float)((d22 * dq1 - d12 * dq2) / det),
                 (float)((d11 * dq2 - d12 * dq1) / det), eye, out);
    return 1;
}

double ref_eye_side(const reference *r, const ref_hit *hit, double eps)
{
    const float *eye = r->s->camera.eye;
    double to_eye[3] = {eye[0] - hit->P[0], eye[1] - hit->P[1], eye[2] - hit->P[2]};
    double Ng[3] = {hit->Ng[0], hit->Ng[1], hit->Ng[2]};
    return dot3(Ng, to_eye) >= 0.0 ? eps : -eps;
}

/* The terminator rule stin shares (Hanika, "Hacking the Shadow Terminator",
 * Ray Tracing Gems II, 2021): a triangle whose vertex normals bend away from
 * its facet stands for a curved surface, so its shadow ray starts on that
 * surface - P projected onto each vertex's tangent plane, the projections
 * blended by the barycentrics - where the blend lies above the facet
 * (convex; a concave corner keeps P), and the side faces the light where its
 * facet or its shading normal (turned to the side of the facet the eye sees)
 * does: lit by its shading normal, it does not shadow itself along the
 * facets' steps; facing by its facet it stays lit as before (seen from the
 * light, everything is). A facet whose vertex normals all equal its own
 * (planes, boxes) keeps P. `org` gets the point, `facing` the shading normal
 * (the facet's where it keeps P). */
void ref_smooth_start(const reference *r, const ref_hit *hit, double side, double org[3],
                      double facing[3])
{
    const ref_object *o = &r->objects[hit->object];
    const uint32_t *tri = o->indices + 3 * (size_t)hit->prim;
    double w[3] = {1.0 - (double)hit->u - (double)hit->v, hit->u, hit->v};
    double P[3] = {hit->P[0], hit->P[1], hit->P[2]}, Ng[3] = {hit->Ng[0], hit->Ng[1], hit->Ng[2]};
    double n[3][3], e1[3], e2[3], tri_ng[3], lift = 0.0;
    int k, c, smooth = 0;
    for (c = 0; c < 3; c++) {
        org[c] = P[c];
        facing[c] = side * Ng[c];
    }
    if (r->facet_terminator == REFERENCE_FACETS_ALL ||
        (r->facet_terminator == REFERENCE_FACETS_OPEN && !o->closed) ||
        (uint32_t)hit->prim >= o->triangle_count)
        return;
    for (c = 0; c < 3; c++) {
        e1[c] = (double)o->positions[3 * (size_t)tri[1] + c] - o->positions[3 * (size_t)tri[0] + c];
        e2[c] = (double)o->positions[3 * (size_t)tri[2] + c] - o->positions[3 * (size_t)tri[0] + c];
    }
    cross3(e1, e2, tri_ng);
    /* not this triangle's point (a CSG cap); a CSG exit's Ng is turned */
    if (!(normalize3(tri_ng) > 0.0) || fabs(dot3(tri_ng, Ng)) < 1.0 - 1e-6)
        return;
    for (k = 0; k < 3; k++) {
        for (c = 0; c < 3; c++)
            n[k][c] = o->normals[3 * (size_t)tri[k] + c];
        if (dot3(n[k], n[k]) == 0.0)
            return; /* no normals: the facet */
        smooth |= fabs(dot3(n[k], Ng)) < 1.0 - 1e-6; /* either way round */
    }
    if (!smooth)
        return;
    double S[3] = {0, 0, 0}, Q[3];
    for (k = 0; k < 3; k++) {
        const float *p = o->positions + 3 * (size_t)tri[k];
        double d = 0.0;
        for (c = 0; c < 3; c++)
            d += (P[c] - p[c]) * n[k][c];
        for (c = 0; c < 3; c++) {
            S[c] += w[k] * n[k][c];
            Q[c] = P[c] - d * n[k][c];
            org[c] += w[k] * (Q[c] - P[c]);
        }
    }
    normalize3(S);
    double turn = dot3(S, Ng) * side < 0.0 ? -1.0 : 1.0;
    for (c = 0; c < 3; c++) {
        lift += (org[c] - P[c]) * side * Ng[c];
        facing[c] = turn * S[c];
    }
    if (!(lift > 0.0)) /* concave: the facet's own point */
        for (c = 0; c < 3; c++)
            org[c] = P[c];
}

/* 1 when nothing lies between the hit's start (ref_smooth_start, offset along Ng
 * to the side the eye sees) and the light: toward `to` (a position) or,
 * directional, along `to` (the direction toward the light) to infinity. The
 * visible side is what is lit: a side turned away from the light is in its
 * own shadow (0), for a sheet seen from behind as for a closed object's far
 * side. */
static float visible_off(const reference *r, const ref_hit *hit, const double to[3], int directional,
                         double eps)
{
    double Ng[3] = {hit->Ng[0], hit->Ng[1], hit->Ng[2]}, org[3], facing[3], dir[3];
    double dist = INFINITY;
    /* Leave the surface on the eye's side so the ray cannot hit its own triangle. */
    double side = ref_eye_side(r, hit, 1.0);
    ref_smooth_start(r, hit, side, org, facing);
    for (int c = 0; c < 3; c++)
        dir[c] = directional ? to[c] : to[c] - org[c];
    if (!(normalize3(dir) > 0.0))
        return 1.0f; /* the light sits on the point */
    /* The side the eye sees turns away from the light: it shadows itself. */
    if (side * dot3(Ng, dir) <= 0.0 && dot3(facing, dir) <= 0.0)
        return 0.0f;
    for (int c = 0; c < 3; c++)
        org[c] += side * eps * Ng[c];
    if (!directional) {
        for (int c = 0; c < 3; c++)
            dir[c] = to[c] - org[c];
        dist = normalize3(dir);
        if (!(dist > 0.0))
            return 1.0f;
    }
    struct RTCRay ray;
    memset(&ray, 0, sizeof ray);
    ray.org_x = (float)org[0];
    ray.org_y = (float)org[1];
    ray.org_z = (float)org[2];
    ray.dir_x = (float)dir[0];
    ray.dir_y = (float)dir[1];
    ray.dir_z = (float)dir[2];
    ray.tnear = 0.0f;
    ray.tfar = (float)dist;
    ray.mask = 0xffffffffu;
    ref_csg_context ctx;
    ref_csg_context_init(r, &ctx);
    rtcOccluded1(r->rtc, &ctx.rtc, &ray);
    if (ray.tfar < 0.0f) /* Embree sets tfar to -inf on a hit */
        return 0.0f;
    if (r->csg_cast) {
        const float o[3] = {ray.org_x, ray.org_y, ray.org_z};
        const float d[3] = {ray.dir_x, ray.dir_y, ray.dir_z};
        return ref_csg_blocks(r, o, d, dist) != 0 ? 0.0f : 1.0f; /* an overflow: shadowed */
    }
    return 1.0f;
}

static float visible(const reference *r, const ref_hit *hit, const double to[3], int directional)
{
    return visible_off(r, hit, to, directional, r->eps);
}

void reference_facet_terminator(reference *r, int on)
{
    if (r)
        r->facet_terminator = on;
}

float reference_visibility_offset(const reference *r, const ref_hit *hit, int light, double offset)
{
    if (!r || !hit || !hit->hit || light < 0 || light >= r->s->light_count || !(offset > 0.0))
        return 1.0f;
    const scene_light *l = &r->s->lights[light];
    int directional = l->type == SCENE_LIGHT_DIRECTIONAL;
    double to[3];
    for (int c = 0; c < 3; c++)
        to[c] = directional ? -(double)l->direction[c] : (double)l->position[c];
    return visible_off(r, hit, to, directional, offset);
}

int reference_terminator_band(const reference *r, const ref_hit *hit, int light)
{
    if (!r || !hit || !hit->hit || light < 0 || light >= r->s->light_count)
        return 0;
    const scene_light *l = &r->s->lights[light];
    double Ng[3] = {hit->Ng[0], hit->Ng[1], hit->Ng[2]}, org[3], facing[3], dir[3];
    double side = ref_eye_side(r, hit, 1.0), moved = 0.0;
    ref_smooth_start(r, hit, side, org, facing);
    for (int c = 0; c < 3; c++) {
        dir[c] = l->type == SCENE_LIGHT_DIRECTIONAL ? -(double)l->direction[c]
                                                    : (double)l->position[c] - org[c];
        moved += fabs(org[c] - (double)hit->P[c]);
    }
    return moved > 0.0 && side * dot3(Ng, dir) <= 0.0 && dot3(facing, dir) > 0.0;
}

float reference_visibility(const reference *r, const ref_hit *hit, int light)
{
    return reference_visibility_offset(r, hit, light, r ? r->eps : 1.0);
}

float reference_visibility_to(const reference *r, const ref_hit *hit, const float position[3])
{
    if (!r || !hit || !hit->hit || !position)
        return 1.0f;
    double to[3] = {position[0], position[1], position[2]};
    return visible(r, hit, to, 0);
}
