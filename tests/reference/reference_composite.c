/* SPDX-License-Identifier: MIT */
/* The camera composite: every surface along a pixel's ray up to the first
 * opaque one, each shaded as an opaque surface would be there, blended front
 * to back under the ones before it (C += T a c; T *= 1 - a) and over the
 * opaque hit or the background. What depth peeling converges to with enough
 * layers; per-object sorting matches it only where objects do not overlap
 * themselves or each other in depth. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reference_internal.h"

enum { MAX_LAYERS = 256 }; /* a ray crossing more surfaces stops compositing there */

/* Opacity of the surface at hit: the material's times its albedo texel's. */
static float opacity_at(const scene *s, const ref_hit *hit)
{
    const scene_material *m = &s->materials[s->objects[hit->object].material];
    float tex[4] = {1, 1, 1, 1};
    if (m->color[3] >= 1.0f)
        return 1.0f; /* opacity 1 is drawn opaque, whatever its texture */
    if (m->albedo >= 0 && m->albedo < s->texture_count)
        reference_sample_texture(&s->textures[m->albedo], hit->uv[0], hit->uv[1], tex);
    return m->color[3] * tex[3];
}

/* One surface shaded under the lighting the flags ask for: unshadowed; each
 * light weighted by its visibility; or per RGB channel the transmittance of
 * each light (the channel's shading uses that channel's weights). */
static void shade_surface(const scene *s, const reference *r, const ref_hit *hit, int per_vertex,
                          unsigned flags, float *weight, float out[3])
{
    float px[4];
    if (flags & REFERENCE_RENDER_TRANSMITTANCE) {
        float t[3];
        int n = s->light_count;
        for (int c = 0; c < 3; c++) {
            for (int i = 0; i < n; i++) {
                reference_transmittance(r, hit, i, t);
                weight[i] = t[c];
            }
            ref_shade_lights(s, r, hit, per_vertex, s->lights, n, weight, 0, px);
            out[c] = px[c];
        }
        return;
    }
    if (flags & REFERENCE_RENDER_SHADOWED) {
        ref_light_weights(r, hit, weight);
        ref_shade_lights(s, r, hit, per_vertex, s->lights, s->light_count, weight, 0, px);
    } else {
        reference_shade(s, r, hit, per_vertex, px);
    }
    memcpy(out, px, 3 * sizeof *out);
}

int reference_composite_pixel(const scene *s, const reference *r, int width, int height, int x,
                              int y, int per_vertex, unsigned flags, float out_rgba[4],
                              float part[4])
{
    return reference_composite_at(s, r, width, height, x + 0.5, y + 0.5, per_vertex, flags,
                                  out_rgba, part);
}

int reference_composite_at(const scene *s, const reference *r, int width, int height, double px,
                           double py, int per_vertex, unsigned flags, float out_rgba[4],
                           float part[4])
{
    ref_camera_frame cf;
    double dir[3], len;
    float T = 1.0f, C[3] = {0, 0, 0};
    int layers = 0;
    if (!s || !r || r->s != s || !out_rgba || !ref_frame_of(&s->camera, width, height, &cf))
        return -1;
    float *weight = malloc(((size_t)s->light_count + 1) * sizeof *weight);
    if (!weight)
        return -1;
    ref_window_dir(&cf, width, height, px, py, dir);
    len = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    float tnear = s->camera.near_plane, behind[4];
    for (int c = 0; c < 4; c++)
        behind[c] = s->background[c];
    for (int n = 0; n < MAX_LAYERS; n++) {
        struct RTCRayHit rh;
        struct RTCIntersectContext ctx;
        ref_hit hit;
        float a, shaded[3];
        memset(&rh, 0, sizeof rh);
        rh.ray.org_x = s->camera.eye[0];
        rh.ray.org_y = s->camera.eye[1];
        rh.ray.org_z = s->camera.eye[2];
        rh.ray.dir_x = (float)dir[0];
        rh.ray.dir_y = (float)dir[1];
        rh.ray.dir_z = (float)dir[2];
        rh.ray.tnear = tnear;
        rh.ray.tfar = s->camera.far_plane;
        rh.ray.mask = 0xffffffffu;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcInitIntersectContext(&ctx);
        rtcIntersect1(r->rtc, &ctx, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
            break; /* the background shows through what is left */
        ref_fill_hit(r, rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v, s->camera.eye, &hit);
        a = opacity_at(s, &hit);
        shade_surface(s, r, &hit, per_vertex, flags, weight, shaded);
        if (a >= 1.0f) {
            memcpy(behind, shaded, sizeof shaded);
            behind[3] = 1.0f;
            break;
        }
        for (int c = 0; c < 3; c++)
            C[c] += T * a * shaded[c];
        T *= 1.0f - a;
        layers++;
        /* past this surface: t runs along the view axis, eps is a length */
        tnear = rh.ray.tfar + (float)(r->eps / len);
    }
    for (int c = 0; c < 3; c++)
        out_rgba[c] = C[c] + T * behind[c];
    out_rgba[3] = 1.0f - T * (1.0f - behind[3]);
    if (part) {
        memcpy(part, C, sizeof C);
        part[3] = T;
    }
    free(weight);
    return layers;
}
