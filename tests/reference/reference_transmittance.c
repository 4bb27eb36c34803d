/* SPDX-License-Identifier: MIT */
/* Transmittance toward a light through transparent casters: every hit along
 * the segment, found by tracing again past the last one, multiplies the
 * light's colour by the deep shadow maps' coloured factor (seed 001, eq 5.3)
 * and an opaque hit stops it. The segment starts where the terminator
 * rule says (ref_smooth_start), as the shadow rays' do. */
#include <math.h>
#include <string.h>

#include "reference_internal.h"

enum { MAX_HITS = 256 }; /* a segment crossing more surfaces is taken as blocked */

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void reference_transmittance_factor(const float color[3], float a, float inout[3])
{
    for (int c = 0; c < 3; c++) {
        double k = 1.0 - a + color[c];
        k = k < 0.0 ? 0.0 : k > 1.0 ? 1.0 : k;
        inout[c] = (float)(inout[c] * (1.0 - a) * k);
    }
}

/* The surface at an Embree hit as a caster: 0 when it is opaque, else its
 * opacity and colour (material colour times the albedo texel). */
static int transparent_at(const reference *r, unsigned object, unsigned prim, float u, float v,
                          float *a, float color[3])
{
    const scene *s = r->s;
    const scene_material *m = &s->materials[s->objects[object].material];
    float tex[4] = {1, 1, 1, 1};
    if (m->color[3] >= 1.0f)
        return 0; /* stin draws a material of opacity 1 opaque, whatever its texture */
    if (m->albedo >= 0 && m->albedo < s->texture_count) {
        ref_hit h;
        ref_fill_hit(r, object, prim, u, v, s->camera.eye, &h);
        reference_sample_texture(&s->textures[m->albedo], h.uv[0], h.uv[1], tex);
    }
    *a = m->color[3] * tex[3];
    for (int c = 0; c < 3; c++)
        color[c] = m->color[c] * tex[c];
    return 1;
}

/* Transmittance from hit toward `to` (a position, or directional: the
 * direction toward the light), from the terminator rule's start
 * (ref_smooth_start) left by eps on the side the eye sees. */
static void transmit(const reference *r, const ref_hit *hit, const double to[3], int directional,
                     float out[3])
{
    double Ng[3] = {hit->Ng[0], hit->Ng[1], hit->Ng[2]}, org[3], facing[3], dir[3];
    double dist = INFINITY, len, side = ref_eye_side(r, hit, 1.0);
    out[0] = out[1] = out[2] = 1.0f;
    ref_smooth_start(r, hit, side, org, facing);
    for (int c = 0; c < 3; c++)
        dir[c] = directional ? to[c] : to[c] - org[c];
    /* the seen side turns away, by its facet and its shading normal: its own shadow */
    if (side * dot3(Ng, dir) <= 0.0 && dot3(facing, dir) <= 0.0) {
        out[0] = out[1] = out[2] = 0.0f;
        return;
    }
    for (int c = 0; c < 3; c++) {
        org[c] += side * r->eps * Ng[c];
        dir[c] = directional ? to[c] : to[c] - org[c];
    }
    len = sqrt(dot3(dir, dir));
    if (!(len > 0.0))
        return;
    for (int c = 0; c < 3; c++)
        dir[c] /= len;
    if (!directional)
        dist = len;
    float tnear = 0.0f;
    for (int n = 0; n < MAX_HITS; n++) {
        struct RTCRayHit rh;
        struct RTCIntersectContext ctx;
        float a, color[3];
        memset(&rh, 0, sizeof rh);
        rh.ray.org_x = (float)org[0];
        rh.ray.org_y = (float)org[1];
        rh.ray.org_z = (float)org[2];
        rh.ray.dir_x = (float)dir[0];
        rh.ray.dir_y = (float)dir[1];
        rh.ray.dir_z = (float)dir[2];
        rh.ray.tnear = tnear;
        rh.ray.tfar = (float)dist;
        rh.ray.mask = 0xffffffffu;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcInitIntersectContext(&ctx);
        rtcIntersect1(r->rtc, &ctx, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
            return;
        if (!transparent_at(r, rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v, &a, color)) {
            out[0] = out[1] = out[2] = 0.0f;
            return;
        }
        reference_transmittance_factor(color, a, out);
        /* past this surface: the next one lies at least eps farther */
        tnear = rh.ray.tfar + (float)r->eps;
    }
    out[0] = out[1] = out[2] = 0.0f;
}

void reference_transmittance(const reference *r, const ref_hit *hit, int light, float out[3])
{
    out[0] = out[1] = out[2] = 1.0f;
    if (!r || !hit || !hit->hit || light < 0 || light >= r->s->light_count)
        return;
    const scene_light *l = &r->s->lights[light];
    int directional = l->type == SCENE_LIGHT_DIRECTIONAL;
    unsigned n = ref_area_sample_count(r, l);
    double sum[3] = {0, 0, 0}, to[3];
    ref_area_cone cone;
    if (n > 1 && !ref_area_cone_of(l, hit->P, &cone))
        n = 1; /* inside the light's sphere: its centre */
    for (unsigned k = 0; k < n; k++) {
        float t[3];
        if (n > 1)
            ref_area_cone_point(&cone, k, n, to);
        else
            for (int c = 0; c < 3; c++)
                to[c] = directional ? -(double)l->direction[c] : (double)l->position[c];
        transmit(r, hit, to, directional, t);
        for (int c = 0; c < 3; c++)
            sum[c] += t[c];
    }
    for (int c = 0; c < 3; c++)
        out[c] = (float)(sum[c] / n);
}
