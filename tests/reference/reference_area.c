/* SPDX-License-Identifier: MIT */
/* Area lights integrated: a light of radius r > 0 (point or spot) is a
 * sphere of uniform radiance, and what a point sees of it is the cone of
 * directions that meet the sphere (half-angle asin(r / d) at distance d).
 * Its visibility is the unoccluded fraction of that cone's solid angle,
 * estimated with a spherical Fibonacci set of directions over the cone,
 * turned about the axis by an angle hashed from the point (stratified, and
 * no pattern shared by neighbouring pixels). */
#include <math.h>
#include <string.h>

#include "reference_internal.h"

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

int ref_is_area_light(const scene_light *l)
{
    return l->radius > 0.0f && l->type != SCENE_LIGHT_DIRECTIONAL;
}

unsigned ref_area_sample_count(const reference *r, const scene_light *l)
{
    return ref_is_area_light(l) ? r->area_samples : 1u;
}

/* A turn in [0, 1) from the bits of P: the same point, the same pattern. */
static double turn_of(const float P[3])
{
    uint32_t h = 2166136261u, bits;
    for (int c = 0; c < 3; c++) {
        memcpy(&bits, &P[c], sizeof bits);
        h = (h ^ bits) * 16777619u;
        h ^= h >> 15;
    }
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    return (double)h / 4294967296.0;
}

int ref_area_cone_of(const scene_light *l, const float P[3], ref_area_cone *cone)
{
    double *axis = cone->axis, *e1 = cone->e1, *e2 = cone->e2, len;
    for (int c = 0; c < 3; c++) {
        cone->P[c] = P[c];
        axis[c] = (double)l->position[c] - P[c];
    }
    cone->d = sqrt(dot3(axis, axis));
    cone->r = l->radius;
    if (!(cone->d > cone->r))
        return 0; /* on or inside the light: no cone */
    for (int c = 0; c < 3; c++)
        axis[c] /= cone->d;
    /* e1, e2: any basis of the plane across the axis */
    if (fabs(axis[0]) < 0.6) {
        e1[0] = 0; e1[1] = axis[2]; e1[2] = -axis[1];
    } else {
        e1[0] = -axis[2]; e1[1] = 0; e1[2] = axis[0];
    }
    len = sqrt(dot3(e1, e1));
    for (int c = 0; c < 3; c++)
        e1[c] /= len;
    e2[0] = axis[1] * e1[2] - axis[2] * e1[1];
    e2[1] = axis[2] * e1[0] - axis[0] * e1[2];
    e2[2] = axis[0] * e1[1] - axis[1] * e1[0];
    cone->cos_max = sqrt(1.0 - (cone->r / cone->d) * (cone->r / cone->d));
    cone->turn = 2.0 * 3.14159265358979323846 * turn_of(P);
    return 1;
}

static const double golden = 2.39996322972865332; /* pi (3 - sqrt 5): direction k turns by k of it */

/* Direction k of n of the cone (unit), turned to the angle whose cosine and
 * sine are cp, sp, and the distance from the apex to where it meets the
 * light's sphere. */
static double cone_direction(const ref_area_cone *cone, unsigned k, unsigned n, double cp, double sp,
                             double w[3])
{
    /* uniform in solid angle: cos(theta) uniform in [cos_max, 1] */
    double cos_t = 1.0 - (k + 0.5) / n * (1.0 - cone->cos_max);
    double sin_t = sqrt(fmax(0.0, 1.0 - cos_t * cos_t));
    for (int c = 0; c < 3; c++)
        w[c] = cos_t * cone->axis[c] + sin_t * (cp * cone->e1[c] + sp * cone->e2[c]);
    /* the near side of the sphere */
    return cone->d * cos_t - sqrt(fmax(0.0, cone->r * cone->r - cone->d * cone->d * sin_t * sin_t));
}

void ref_area_cone_point(const ref_area_cone *cone, unsigned k, unsigned n, double out[3])
{
    double w[3], phi = golden * k + cone->turn, t = cone_direction(cone, k, n, cos(phi), sin(phi), w);
    for (int c = 0; c < 3; c++)
        out[c] = cone->P[c] + t * w[c];
}

enum { BATCH = 64 }; /* rays per rtcOccluded1M call */

/* Of the directions [k0, k1) of the cone, how many reach the light from org
 * (the start, offset along Ng by side) with nothing in between; facing: the
 * shading normal of the terminator rule (ref_smooth_start). The
 * batch of one pixel's rays is coherent: they fan out of one point. */
static unsigned clear_directions(const reference *r, const ref_hit *hit, const ref_area_cone *cone,
                                 const double org[3], double side, const double facing[3],
                                 unsigned k0, unsigned k1, unsigned n)
{
    struct RTCRay rays[BATCH];
    double dist[BATCH];
    unsigned m = 0, clear = 0;
    double phi = golden * k0 + cone->turn, cp = cos(phi), sp = sin(phi);
    const double cg = cos(golden), sg = sin(golden);
    for (unsigned k = k0; k < k1; k++) {
        double w[3], t = cone_direction(cone, k, n, cp, sp, w), next = cp * cg - sp * sg;
        sp = sp * cg + cp * sg; /* the turn of direction k + 1, without a sine a ray */
        cp = next;
        double Ngw = hit->Ng[0] * w[0] + hit->Ng[1] * w[1] + hit->Ng[2] * w[2];
        if (side * Ngw <= 0.0 && facing[0] * w[0] + facing[1] * w[1] + facing[2] * w[2] <= 0.0)
            continue; /* under both horizons of the side the eye sees: its own shadow */
        struct RTCRay *ray = &rays[m];
        memset(ray, 0, sizeof *ray);
        ray->org_x = (float)org[0];
        ray->org_y = (float)org[1];
        ray->org_z = (float)org[2];
        ray->dir_x = (float)w[0];
        ray->dir_y = (float)w[1];
        ray->dir_z = (float)w[2];
        ray->tfar = (float)(t - side * Ngw); /* from org, to first order in eps */
        ray->mask = 0xffffffffu;
        dist[m++] = t - side * Ngw;
    }
    ref_csg_context ctx;
    ref_csg_context_init(r, &ctx);
    ctx.rtc.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcOccluded1M(r->rtc, &ctx.rtc, rays, m, sizeof *rays);
    for (unsigned i = 0; i < m; i++) {
        if (rays[i].tfar < 0.0f) /* Embree sets tfar to -inf on a hit */
            continue;
        if (r->csg_cast) {
            const float o[3] = {rays[i].org_x, rays[i].org_y, rays[i].org_z};
            const float d[3] = {rays[i].dir_x, rays[i].dir_y, rays[i].dir_z};
            if (ref_csg_blocks(r, o, d, dist[i]) != 0) /* an overflow: shadowed */
                continue;
        }
        clear++;
    }
    return clear;
}

float reference_light_visibility(const reference *r, const ref_hit *hit, int light)
{
    if (!r || !hit || !hit->hit || light < 0 || light >= r->s->light_count)
        return 1.0f;
    const scene_light *l = &r->s->lights[light];
    unsigned n = ref_area_sample_count(r, l), clear = 0;
    ref_area_cone cone;
    if (n <= 1 || !ref_area_cone_of(l, hit->P, &cone))
        return reference_visibility(r, hit, light);
    /* the start and the facing of the terminator rule, as for a point light */
    double side = ref_eye_side(r, hit, r->eps), org[3], facing[3];
    ref_smooth_start(r, hit, side > 0.0 ? 1.0 : -1.0, org, facing);
    for (int c = 0; c < 3; c++)
        org[c] += side * hit->Ng[c];
    for (unsigned k = 0; k < n; k += BATCH)
        clear += clear_directions(r, hit, &cone, org, side, facing, k,
                                  k + BATCH < n ? k + BATCH : n, n);
    return (float)((double)clear / n);
}

void ref_light_weights(const reference *r, const ref_hit *hit, float *weight)
{
    for (int i = 0; i < r->s->light_count; i++)
        weight[i] = reference_light_visibility(r, hit, i);
}

void reference_set_area_samples(reference *r, unsigned n)
{
    if (r)
        r->area_samples = n < 1 ? 1 : n;
}
