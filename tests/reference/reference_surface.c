/* SPDX-License-Identifier: MIT */
/* The CPU reference of the GLSL surface techniques (reference_surface.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reference_internal.h"
#include "reference_surface.h"

struct ref_surface {
    int object_count;
    float **tangents; /* per object: world tangent xyz + w per vertex */
    int texture_count;
    reference_mips **mips; /* per texture: stin's chain (none for height maps) */
};

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3(double o[3], const double a[3], const double b[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static int normalize3(double v[3])
{
    double l = sqrt(dot3(v, v));
    if (!(l > 1e-30))
        return 0;
    v[0] /= l;
    v[1] /= l;
    v[2] /= l;
    return 1;
}

void ref_mesh_tangents(const scene_mesh *m, float *out)
{
    double *acc = calloc(6 * (size_t)m->vertex_count + 1, sizeof *acc);
    uint32_t t, i;
    if (!acc)
        return;
    for (t = 0; m->uvs && t < m->triangle_count; t++) {
        const uint32_t *tri = m->indices + 3 * (size_t)t;
        const float *a = m->positions + 3 * (size_t)tri[0], *b = m->positions + 3 * (size_t)tri[1],
                    *c = m->positions + 3 * (size_t)tri[2];
        const float *ua = m->uvs + 2 * (size_t)tri[0], *ub = m->uvs + 2 * (size_t)tri[1],
                    *uc = m->uvs + 2 * (size_t)tri[2];
        double du1 = ub[0] - ua[0], dv1 = ub[1] - ua[1], du2 = uc[0] - ua[0], dv2 = uc[1] - ua[1];
        double det = du1 * dv2 - du2 * dv1;
        int k, j;
        if (det == 0.0)
            continue;
        for (k = 0; k < 3; k++)
            for (j = 0; j < 3; j++) {
                double e1 = b[j] - a[j], e2 = c[j] - a[j];
                acc[6 * (size_t)tri[k] + j] += (dv2 * e1 - dv1 * e2) / det;
                acc[6 * (size_t)tri[k] + 3 + j] += (du1 * e2 - du2 * e1) / det;
            }
    }
    for (i = 0; i < m->vertex_count; i++) {
        double n[3] = {m->normals[3 * i], m->normals[3 * i + 1], m->normals[3 * i + 2]};
        double *ac = acc + 6 * (size_t)i, d = dot3(ac, n), tg[3], b[3];
        int j;
        for (j = 0; j < 3; j++)
            tg[j] = ac[j] - n[j] * d;
        if (!normalize3(tg)) {
            double a[3] = {1, 0, 0};
            if (fabs(n[0]) > 0.9) {
                a[0] = 0;
                a[1] = 1;
            }
            cross3(tg, n, a);
            normalize3(tg);
            out[4 * i + 3] = 1.0f;
        } else {
            cross3(b, n, tg);
            out[4 * i + 3] = dot3(b, ac + 3) < 0.0 ? -1.0f : 1.0f;
        }
        for (j = 0; j < 3; j++)
            out[4 * i + j] = (float)tg[j];
    }
    free(acc);
}

/* Height maps have level 0 only in stin (the march reads the true field). */
static int build_mips(const scene *s, ref_surface *rs)
{
    int i;
    rs->mips = calloc((size_t)s->texture_count + 1, sizeof *rs->mips);
    if (!rs->mips)
        return 0;
    rs->texture_count = s->texture_count;
    for (i = 0; i < s->texture_count; i++) {
        const scene_texture *t = &s->textures[i];
        if (t->kind == SCENE_TEXTURE_HEIGHT)
            continue;
        rs->mips[i] = reference_mips_create(t, t->kind == SCENE_TEXTURE_NORMAL);
        if (!rs->mips[i])
            return 0;
    }
    return 1;
}

ref_surface *ref_surface_create(const scene *s)
{
    ref_surface *rs = calloc(1, sizeof *rs);
    int o;
    if (!rs)
        return NULL;
    rs->object_count = s->object_count;
    rs->tangents = calloc((size_t)s->object_count + 1, sizeof *rs->tangents);
    if (!rs->tangents) {
        free(rs);
        return NULL;
    }
    for (o = 0; o < s->object_count; o++) {
        const scene_mesh *m = &s->meshes[s->objects[o].mesh];
        const float *x = s->objects[o].transform;
        float *t = malloc(4 * sizeof(float) * ((size_t)m->vertex_count + 1));
        uint32_t i;
        if (!t) {
            ref_surface_destroy(rs);
            return NULL;
        }
        ref_mesh_tangents(m, t);
        for (i = 0; i < m->vertex_count; i++) { /* tangents follow the surface: the 3x3 */
            float a = t[4 * i], b = t[4 * i + 1], c = t[4 * i + 2];
            int k;
            for (k = 0; k < 3; k++)
                t[4 * i + k] = x[k] * a + x[4 + k] * b + x[8 + k] * c;
        }
        rs->tangents[o] = t;
    }
    return build_mips(s, rs) ? rs : (ref_surface_destroy(rs), NULL);
}

void ref_surface_destroy(ref_surface *rs)
{
    int o;
    if (!rs)
        return;
    for (o = 0; o < rs->object_count; o++)
        free(rs->tangents[o]);
    for (o = 0; rs->mips && o < rs->texture_count; o++)
        reference_mips_destroy(rs->mips[o]);
    free(rs->mips);
    free(rs->tangents);
    free(rs);
}

typedef struct frame {
    double T[3], B[3], N[3];
    double au[2], av[2]; /* uv per scene unit along T and along B */
} frame;

static void world_point(const float *x, const float *p, double out[3])
{
    int k;
    for (k = 0; k < 3; k++)
        out[k] = x[k] * p[0] + x[4 + k] * p[1] + x[8 + k] * p[2] + x[12 + k];
}

static void hit_frame(const scene *s, const ref_surface *rs, const ref_hit *hit, frame *f)
{
    const scene_object *o = &s->objects[hit->object];
    const scene_mesh *m = &s->meshes[o->mesh];
    const uint32_t *tri = m->indices + 3 * (size_t)hit->prim;
    const float *tg = rs->tangents[hit->object];
    double w[3] = {1.0 - hit->u - hit->v, hit->u, hit->v}, t[3] = {0, 0, 0}, P[3][3], d, hand = 0;
    double e1[3], e2[3], q1[2], q2[2], duv1[2], duv2[2], det;
    int k, j;
    for (j = 0; j < 3; j++)
        f->N[j] = hit->N[j];
    for (k = 0; k < 3; k++) {
        for (j = 0; j < 3; j++)
            t[j] += w[k] * tg[4 * (size_t)tri[k] + j];
        hand += w[k] * tg[4 * (size_t)tri[k] + 3];
        world_point(o->transform, m->positions + 3 * (size_t)tri[k], P[k]);
    }
    d = dot3(t, f->N);
    for (j = 0; j < 3; j++)
        f->T[j] = t[j] - f->N[j] * d;
    normalize3(f->T);
    cross3(f->B, f->N, f->T);
    if (hand < 0)
        for (j = 0; j < 3; j++)
            f->B[j] = -f->B[j];
    for (j = 0; j < 3; j++) {
        e1[j] = P[1][j] - P[0][j];
        e2[j] = P[2][j] - P[0][j];
    }
    q1[0] = dot3(e1, f->T);
    q1[1] = dot3(e1, f->B);
    q2[0] = dot3(e2, f->T);
    q2[1] = dot3(e2, f->B);
    for (j = 0; j < 2; j++) {
        duv1[j] = m->uvs ? m->uvs[2 * (size_t)tri[1] + j] - m->uvs[2 * (size_t)tri[0] + j] : 0;
        duv2[j] = m->uvs ? m->uvs[2 * (size_t)tri[2] + j] - m->uvs[2 * (size_t)tri[0] + j] : 0;
    }
    det = q1[0] * q2[1] - q2[0] * q1[1];
    if (fabs(det) < 1e-20) {
        f->au[0] = 1;
        f->au[1] = 0;
        f->av[0] = 0;
        f->av[1] = 1;
        return;
    }
    /* [duv1 duv2] = A [q1 q2]  ->  A = [duv1 duv2] [q1 q2]^-1 */
    for (j = 0; j < 2; j++) {
        f->au[j] = (duv1[j] * q2[1] - duv2[j] * q1[1]) / det;
        f->av[j] = (duv2[j] * q1[0] - duv1[j] * q2[0]) / det;
    }
}

static double height_at(const scene_texture *h, double u, double v)
{
    float px[4];
    reference_sample_texture(h, (float)u, (float)v, px);
    return px[0];
}

/* The POM view march (reference_surface.h, pom): moves uv to where the view
 * ray (vt: unit, toward the eye, tangent frame) meets the recessed field and
 * returns the depth there, 0..1 of the scale. */
static double pom_march(const scene_texture *ht, const frame *f, const double vt[3], double scale,
                        double uv[2])
{
    double vz = vt[2] > 1e-3 ? vt[2] : 1e-3, dir[2], lo = 0, hi = 0, d = 0;
    const int steps = 4096;
    int i, j;
    for (j = 0; j < 2; j++)
        dir[j] = -(f->au[j] * vt[0] + f->av[j] * vt[1]) / vz * scale;
    if (1.0 - height_at(ht, uv[0], uv[1]) > 0.0) {
        for (i = 1; i <= steps; i++) {
            double dd = (double)i / steps;
            if (1.0 - height_at(ht, uv[0] + dir[0] * dd, uv[1] + dir[1] * dd) <= dd) {
                hi = dd;
                break;
            }
            lo = dd;
        }
        for (i = 0; i < 40; i++) {
            double mid = 0.5 * (lo + hi);
            if (1.0 - height_at(ht, uv[0] + dir[0] * mid, uv[1] + dir[1] * mid) <= mid)
                hi = mid;
            else
                lo = mid;
        }
        d = 0.5 * (lo + hi);
    }
    uv[0] += dir[0] * d;
    uv[1] += dir[1] * d;
    return d;
}

/* A colour or normal map at uv: through its mip chain with fp's level of
 * detail, else bilinear at level 0. */
static void sample_map(const scene *s, const ref_surface *rs, int tex, const double uv[2],
                       const ref_footprint *fp, float out[4])
{
    const scene_texture *t = &s->textures[tex];
    if (fp && rs->mips[tex])
        reference_sample_mips(rs->mips[tex], (float)uv[0], (float)uv[1],
                              reference_mip_lambda(fp->dx, fp->dy, t->width, t->height), out);
    else
        reference_sample_texture(t, (float)uv[0], (float)uv[1], out);
}

/* Per-pixel shading at the final uv: the albedo sampled as the normal map
 * was, the shininess widened by the filtered normal's length (the lit
 * shader's Toksvig: s l / (l + s (1 - l)), l clamped to [0.05, 1]). */
static void shade_mapped(const scene *s, const ref_surface *rs, const ref_hit *h2,
                         const scene_material *m, float normal_length, const ref_footprint *fp,
                         float out_rgba[4])
{
    scene_material mm = *m;
    float tex[4] = {1, 1, 1, 1};
    double uv[2] = {h2->uv[0], h2->uv[1]};
    float l = normal_length < 0.05f ? 0.05f : normal_length > 1.0f ? 1.0f : normal_length;
    if (m->albedo >= 0 && m->albedo < s->texture_count)
        sample_map(s, rs, m->albedo, uv, fp, tex);
    mm.shininess = m->shininess * l / (l + m->shininess * (1.0f - l));
    ref_shade_material(s, NULL, h2, 0, &mm, tex, s->lights, s->light_count, NULL, 0, out_rgba);
}

void ref_surface_shade(const scene *s, const ref_surface *rs, const ref_hit *hit, int technique,
                       float height_bias, float out_rgba[4], float out_uv[2])
{
    ref_surface_shade_filtered(s, rs, hit, technique, height_bias, NULL, out_rgba, out_uv);
}

void ref_surface_shade_filtered(const scene *s, const ref_surface *rs, const ref_hit *hit,
                                int technique, float height_bias, const ref_footprint *fp,
                                float out_rgba[4], float out_uv[2])
{
    const scene_material *m;
    ref_hit h2;
    frame f;
    double V[3], vt[3], uv[2], scale, bias;
    float nm[4];
    int j;
    if (out_uv && hit->hit) {
        out_uv[0] = hit->uv[0];
        out_uv[1] = hit->uv[1];
    }
    if (!hit->hit || hit->object < 0 || hit->object >= s->object_count || !rs) {
        reference_shade(s, NULL, hit, 0, out_rgba);
        return;
    }
    m = &s->materials[s->objects[hit->object].material];
    if (m->normal < 0)
        technique = REF_SURFACE_PLAIN;
    if (m->height < 0 && technique > REF_SURFACE_NORMAL)
        technique = REF_SURFACE_NORMAL;
    if (technique == REF_SURFACE_PLAIN) {
        shade_mapped(s, rs, hit, m, 1.0f, fp, out_rgba);
        return;
    }
    hit_frame(s, rs, hit, &f);
    for (j = 0; j < 3; j++)
        V[j] = s->camera.eye[j] - hit->P[j];
    normalize3(V);
    vt[0] = dot3(V, f.T);
    vt[1] = dot3(V, f.B);
    vt[2] = dot3(V, f.N);
    uv[0] = hit->uv[0];
    uv[1] = hit->uv[1];
    scale = m->height_scale > 0 ? m->height_scale : 1e-30;
    bias = height_bias < 0 ? 0.5 * scale : height_bias;
    if (technique == REF_SURFACE_PARALLAX) {
        double hh = height_at(&s->textures[m->height], uv[0], uv[1]) * scale - bias;
        double ox = vt[0] * hh, oy = vt[1] * hh;
        uv[0] += f.au[0] * ox + f.av[0] * oy;
        uv[1] += f.au[1] * ox + f.av[1] * oy;
    } else if (technique == REF_SURFACE_POM) {
        pom_march(&s->textures[m->height], &f, vt, scale, uv);
    }
    sample_map(s, rs, m->normal, uv, fp, nm);
    h2 = *hit;
    {
        double n[3], c[3];
        for (j = 0; j < 3; j++)
            c[j] = (nm[j] * 255.0 - 128.0) / 127.0;
        for (j = 0; j < 3; j++)
            n[j] = f.T[j] * c[0] + f.B[j] * c[1] + f.N[j] * c[2];
        normalize3(n);
        for (j = 0; j < 3; j++)
            h2.N[j] = (float)n[j];
    }
    h2.uv[0] = (float)uv[0];
    h2.uv[1] = (float)uv[1];
    if (out_uv) {
        out_uv[0] = h2.uv[0];
        out_uv[1] = h2.uv[1];
    }
    shade_mapped(s, rs, &h2, m, fp ? nm[3] : 1.0f, fp, out_rgba);
}

/* The material of a hit with a normal and a height map, its scale and the
 * tangent frame; 0 where the hit has none. */
static const scene_material *mapped(const scene *s, const ref_surface *rs, const ref_hit *hit,
                                    frame *f, double *scale)
{
    const scene_material *m;
    if (!hit->hit || !rs || hit->object < 0 || hit->object >= s->object_count)
        return NULL;
    m = &s->materials[s->objects[hit->object].material];
    if (m->normal < 0 || m->height < 0)
        return NULL;
    hit_frame(s, rs, hit, f);
    *scale = m->height_scale > 0 ? m->height_scale : 1e-30;
    return m;
}

int ref_surface_parallax_terms(const scene *s, const ref_surface *rs, const ref_hit *hit,
                               float height_bias, double *h_prime, double vt[3])
{
    const scene_material *m;
    frame f;
    double V[3], scale, bias;
    int j;
    if (!(m = mapped(s, rs, hit, &f, &scale)))
        return 0;
    for (j = 0; j < 3; j++)
        V[j] = s->camera.eye[j] - hit->P[j];
    normalize3(V);
    vt[0] = dot3(V, f.T);
    vt[1] = dot3(V, f.B);
    vt[2] = dot3(V, f.N);
    bias = height_bias < 0 ? 0.5 * scale : height_bias;
    *h_prime = height_at(&s->textures[m->height], hit->uv[0], hit->uv[1]) * scale - bias;
    return 1;
}

int ref_surface_uv_to_plane(const scene *s, const ref_surface *rs, const ref_hit *hit,
                            const double duv[2], double out[2])
{
    frame f;
    double scale, det;
    if (!mapped(s, rs, hit, &f, &scale))
        return 0;
    /* duv = au x + av y: solve the 2x2 */
    det = f.au[0] * f.av[1] - f.av[0] * f.au[1];
    if (fabs(det) < 1e-30)
        return 0;
    out[0] = (duv[0] * f.av[1] - f.av[0] * duv[1]) / det;
    out[1] = (f.au[0] * duv[1] - duv[0] * f.au[1]) / det;
    return 1;
}

float ref_surface_pom_shadow(const scene *s, const ref_surface *rs, const ref_hit *hit,
                             const float to_light[3], double epsilon, float out_uv[2],
                             float *out_depth)
{
    const scene_material *m;
    const scene_texture *ht;
    frame f;
    double V[3], L[3], vt[3], lt[3], uv[2], dir[2], scale, d;
    long i, steps;
    int j;
    if (!(m = mapped(s, rs, hit, &f, &scale)))
        return 1.0f;
    ht = &s->textures[m->height];
    for (j = 0; j < 3; j++) {
        V[j] = s->camera.eye[j] - hit->P[j];
        L[j] = to_light[j];
    }
    normalize3(V);
    normalize3(L);
    vt[0] = dot3(V, f.T);
    vt[1] = dot3(V, f.B);
    vt[2] = dot3(V, f.N);
    uv[0] = hit->uv[0];
    uv[1] = hit->uv[1];
    d = pom_march(ht, &f, vt, scale, uv);
    if (out_uv) {
        out_uv[0] = (float)uv[0];
        out_uv[1] = (float)uv[1];
    }
    if (out_depth)
        *out_depth = (float)d;
    if (!(d > 0.0))
        return 1.0f; /* on the top: nothing of the field is above it */
    lt[0] = dot3(L, f.T);
    lt[1] = dot3(L, f.B);
    lt[2] = dot3(L, f.N);
    if (!(lt[2] > 0.0))
        return 0.0f; /* toward a light under the polygon the ray never leaves the field */
    /* uv change per unit of depth climbed toward the light */
    for (j = 0; j < 2; j++)
        dir[j] = (f.au[j] * lt[0] + f.av[j] * lt[1]) / lt[2] * scale;
    steps = (long)ceil(4096.0 * d);
    for (i = 1; i < steps; i++) { /* climb c from the hit (depth d) to the top (depth 0) */
        double c = d * (double)i / steps, ray = d - c;
        double field = 1.0 - height_at(ht, uv[0] + dir[0] * c, uv[1] + dir[1] * c);
        if (ray - field > epsilon)
            return 0.0f;
    }
    return 1.0f;
}
