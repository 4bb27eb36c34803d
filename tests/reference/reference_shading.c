/* SPDX-License-Identifier: MIT */
/* The lighting model of stin.h (LIGHTING MODEL), per vertex (GL1 Gouraud with
 * separate specular) and per pixel (GL2/GL4), in double precision. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reference_internal.h"

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void normalize3(double v[3])
{
    double len = sqrt(dot3(v, v));
    if (len > 0.0 && isfinite(len))
        for (int i = 0; i < 3; i++)
            v[i] /= len;
}

static double clamp01(double x)
{
    return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x;
}

/* Attenuation times spot factor of light l at P; L receives the unit vector
 * from P toward the light. */
static double light_factor(const scene_light *l, const double P[3], double L[3])
{
    if (l->type == SCENE_LIGHT_DIRECTIONAL) {
        for (int c = 0; c < 3; c++)
            L[c] = -(double)l->direction[c];
        normalize3(L);
        return 1.0;
    }
    for (int c = 0; c < 3; c++)
        L[c] = (double)l->position[c] - P[c];
    double d = sqrt(dot3(L, L));
    normalize3(L);
    double k = l->attenuation[0] + l->attenuation[1] * d + l->attenuation[2] * d * d;
    double factor = k > 0.0 ? 1.0 / k : 0.0; /* a non-positive denominator is no light at all */
    if (l->type == SCENE_LIGHT_SPOT) {
        double D[3] = {l->direction[0], l->direction[1], l->direction[2]};
        normalize3(D);
        double s = -dot3(L, D);
        if (s < cos(l->spot_cutoff_deg * (3.14159265358979323846 / 180.0)))
            return 0.0;
        factor *= pow(s > 0.0 ? s : 0.0, l->spot_exponent); /* C: pow(x, 0) == 1 */
    }
    return factor;
}

/* The lights one evaluation of the model sees: ambient on or off, a light
 * list with optional weights (NULL = all 1). */
typedef struct light_set {
    int ambient;
    const scene_light *lights;
    int count;
    const float *weight;
} light_set;

/* primary = ambient * albedo + diffuse, secondary = specular, unclamped. */
static void model(const scene *s, const scene_material *m, const double P[3], const double N[3],
                  const light_set *ls, double primary[3], double secondary[3])
{
    double V[3];
    const float *weight = ls->weight;
    for (int c = 0; c < 3; c++) {
        V[c] = (double)s->camera.eye[c] - P[c];
        primary[c] = ls->ambient ? (double)s->ambient[c] * m->color[c] : 0.0;
        secondary[c] = 0.0;
    }
    normalize3(V);
    for (int i = 0; i < ls->count; i++) {
        const scene_light *l = &ls->lights[i];
        double L[3], H[3];
        double f = light_factor(l, P, L) * (weight ? weight[i] : 1.0) * l->intensity;
        if (f == 0.0)
            continue;
        double ndotl = dot3(N, L);
        for (int c = 0; c < 3; c++)
            H[c] = L[c] + V[c];
        normalize3(H);
        double ndoth = dot3(N, H);
        double diffuse = ndotl > 0.0 ? ndotl : 0.0;
        double spec = ndotl > 0.0 ? pow(ndoth > 0.0 ? ndoth : 0.0, m->shininess) : 0.0;
        for (int c = 0; c < 3; c++) {
            primary[c] += f * diffuse * l->color[c] * m->color[c];
            secondary[c] += f * spec * l->color[c] * m->specular[c];
        }
    }
}

static void background(const scene *s, float out_rgba[4])
{
    for (int c = 0; c < 4; c++)
        out_rgba[c] = s->background[c];
}

/* Gouraud: the model at the three vertices, clamped per vertex (as GL clamps
 * the lit vertex colours), then interpolated. */
static void per_vertex(const scene *s, const reference *r, const ref_hit *hit,
                       const scene_material *m, const light_set *ls, int single_color,
                       double primary[3], double secondary[3])
{
    const ref_object *o = &r->objects[hit->object];
    const uint32_t *tri = o->indices + 3 * (size_t)hit->prim;
    double w[3] = {1.0 - (double)hit->u - (double)hit->v, hit->u, hit->v};
    memset(primary, 0, 3 * sizeof *primary);
    memset(secondary, 0, 3 * sizeof *secondary);
    for (int k = 0; k < 3; k++) {
        double P[3], N[3], pk[3], sk[3];
        for (int c = 0; c < 3; c++) {
            P[c] = o->positions[3 * (size_t)tri[k] + c];
            N[c] = o->normals[3 * (size_t)tri[k] + c];
        }
        if (dot3(N, N) == 0.0) /* no usable vertex normal: the face normal */
            for (int c = 0; c < 3; c++)
                N[c] = hit->Ng[c];
        model(s, m, P, N, ls, pk, sk);
        for (int c = 0; c < 3; c++) {
            if (single_color) { /* GL 1.1: one colour, the sum clamped per vertex */
                primary[c] += w[k] * clamp01(pk[c] + sk[c]);
            } else {
                primary[c] += w[k] * clamp01(pk[c]);
                secondary[c] += w[k] * clamp01(sk[c]);
            }
        }
    }
}

/* One clamped evaluation (a GL pass): 0 and NaN in out_rgb when the hit
 * cannot be shaded per vertex. */
static void shade_set(const scene *s, const reference *r, const ref_hit *hit, int per_vertex_lighting,
                      const scene_material *m, const float tex[4], const light_set *ls, double out_rgb[3])
{
    double primary[3], secondary[3];
    if (per_vertex_lighting) {
        per_vertex(s, r, hit, m, ls, per_vertex_lighting == REFERENCE_GOURAUD_SINGLE_COLOR, primary,
                   secondary);
    } else {
        double P[3] = {hit->P[0], hit->P[1], hit->P[2]}, N[3] = {hit->N[0], hit->N[1], hit->N[2]};
        model(s, m, P, N, ls, primary, secondary);
    }
    for (int c = 0; c < 3; c++)
        out_rgb[c] = clamp01(primary[c] * tex[c] + secondary[c]);
}

void ref_shade_lights(const scene *s, const reference *r, const ref_hit *hit, int per_vertex_lighting,
                      const scene_light *lights, int light_count, const float *weight, int passes,
                      float out_rgba[4])
{
    if (!hit->hit || hit->object < 0 || hit->object >= s->object_count) {
        background(s, out_rgba);
        return;
    }
    int mi = s->objects[hit->object].material;
    if (mi < 0 || mi >= s->material_count) {
        background(s, out_rgba);
        return;
    }
    const scene_material *m = &s->materials[mi];
    float tex[4] = {1, 1, 1, 1};
    if (m->albedo >= 0 && m->albedo < s->texture_count)
        reference_sample_texture(&s->textures[m->albedo], hit->uv[0], hit->uv[1], tex);
    ref_shade_material(s, r, hit, per_vertex_lighting, m, tex, lights, light_count, weight, passes,
                       out_rgba);
}

void ref_shade_material(const scene *s, const reference *r, const ref_hit *hit,
                        int per_vertex_lighting, const scene_material *m, const float tex[4],
                        const scene_light *lights, int light_count, const float *weight,
                        int passes, float out_rgba[4])
{
    if (per_vertex_lighting &&
        (!r || hit->object >= r->object_count || hit->prim < 0 ||
         (uint32_t)hit->prim >= r->objects[hit->object].triangle_count)) {
        for (int c = 0; c < 4; c++) /* loud, never a silent per-pixel answer */
            out_rgba[c] = NAN;
        return;
    }
    double sum[3];
    if (!passes) {
        light_set all = {1, lights, light_count, weight};
        shade_set(s, r, hit, per_vertex_lighting, m, tex, &all, sum);
    } else {
        /* The ambient pass, then each light alone where it is visible: every
         * pass clamped by itself, the framebuffer adds and clamps at 1. */
        light_set ambient = {1, NULL, 0, NULL};
        shade_set(s, r, hit, per_vertex_lighting, m, tex, &ambient, sum);
        for (int i = 0; i < light_count; i++) {
            double pass[3];
            light_set one = {0, &lights[i], 1, weight ? &weight[i] : NULL};
            if (weight && weight[i] == 0.0f)
                continue; /* the stencil test drops the whole pass */
            shade_set(s, r, hit, per_vertex_lighting, m, tex, &one, pass);
            for (int c = 0; c < 3; c++)
                sum[c] += pass[c];
        }
    }
    for (int c = 0; c < 3; c++)
        out_rgba[c] = (float)clamp01(sum[c]);
    out_rgba[3] = m->color[3];
}

void reference_shade_weighted(const scene *s, const reference *r, const ref_hit *hit,
                              int per_vertex_lighting, const float *light_weight,
                              float out_rgba[4])
{
    ref_shade_lights(s, r, hit, per_vertex_lighting, s->lights, s->light_count, light_weight, 0,
                     out_rgba);
}

void reference_shade(const scene *s, const reference *r, const ref_hit *hit, int per_vertex,
                     float out_rgba[4])
{
    reference_shade_weighted(s, r, hit, per_vertex, NULL, out_rgba);
}

/* Opaque hits: the per-light-pass beauty of a stencil-volume frame. Blended
 * materials (opacity < 1) are drawn after the passes, unshadowed, in one pass. */
void reference_shade_passes(const scene *s, const reference *r, const ref_hit *hit, int per_vertex,
                            float out_rgba[4])
{
    if (!r || r->s != s) {
        for (int c = 0; c < 4; c++)
            out_rgba[c] = NAN;
        return;
    }
    if (hit->hit && hit->object >= 0 && hit->object < s->object_count) {
        int mi = s->objects[hit->object].material;
        if (mi >= 0 && mi < s->material_count && s->materials[mi].color[3] < 1.0f) {
            reference_shade(s, r, hit, per_vertex, out_rgba);
            return;
        }
    }
    float *weight = malloc(((size_t)s->light_count + 1) * sizeof *weight);
    if (!weight) {
        for (int c = 0; c < 4; c++)
            out_rgba[c] = NAN;
    } else {
        if (hit->hit)
            ref_light_weights(r, hit, weight);
        ref_shade_lights(s, r, hit, per_vertex, s->lights, hit->hit ? s->light_count : 0, weight,
                         1, out_rgba);
    }
    free(weight);
}
