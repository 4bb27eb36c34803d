/* SPDX-License-Identifier: MIT */
/* The terminator band (stin.h, "The terminator rule"; the GLSL path's
 * terminator_band.frag) without a fragment shader. What that shader asks
 * of each fragment is asked here of each triangle where it cannot change
 * across one, and of each fragment by the alpha test where it is (close
 * to) linear:
 * - the facet's side of the light and of the eye is constant over a
 *   planar facet;
 * - the curved surface lies above the facet on the whole triangle or not:
 *   a triangle where it does not everywhere (a concave corner, a saddle),
 *   or whose corner normals turn from the side of the facet the eye sees,
 *   keeps its facet (shadowed by its own volume as before);
 * - the rule's "shading normal toward the light" is each corner's n.(L - p)
 *   at the corners and, blended by the barycentrics, exact inside for a
 *   directional light; for a point light the way from the lifted point
 *   bends its zero line at second order in the facet's size, so the
 *   corners' values are set to turn where the rule turns on the two edges
 *   it crosses. Each corner's colour has alpha 0.5 + 0.5 value (values in
 *   -1..1) and the alpha test keeps the fragments above one half.
 * The positions and modelview are the lit pass's (draw_mesh), so depth
 * EQUAL meets its depths; the caller's stencil state takes the count back. */
#include "render/terminator_fixed.h"
#include "internal.h"

typedef struct corner {
    float p[3], n[3]; /* world position and unit normal */
} corner;

static float dot(const float a[3], const float b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void world_positions(const stin__draw *d, const stin__vertex *v, const uint32_t *tri,
                            corner c[3])
{
    int i;
    for (i = 0; i < 3; i++)
        stin__mat4_transform_point(d->transform, v[tri[i]].position, c[i].p);
}

/* 0 where a normal is zero. */
static int world_normals(const float normal_matrix[9], const stin__vertex *v, const uint32_t *tri,
                         corner c[3])
{
    int i, r;
    for (i = 0; i < 3; i++) {
        const float *n = v[tri[i]].normal;
        for (r = 0; r < 3; r++) /* column-major */
            c[i].n[r] = normal_matrix[r] * n[0] + normal_matrix[3 + r] * n[1] +
                        normal_matrix[6 + r] * n[2];
        if (!stin__normalize3(c[i].n))
            return 0;
    }
    return 1;
}

/* The facet's unit normal on the side the eye sees; 0 edge-on. */
static int eye_side_facet(const corner c[3], const float eye[3], float g[3])
{
    float e1[3], e2[3], to_eye[3];
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = c[1].p[k] - c[0].p[k];
        e2[k] = c[2].p[k] - c[0].p[k];
        to_eye[k] = eye[k] - c[0].p[k];
    }
    g[0] = e1[1] * e2[2] - e1[2] * e2[1];
    g[1] = e1[2] * e2[0] - e1[0] * e2[2];
    g[2] = e1[0] * e2[1] - e1[1] * e2[0];
    if (dot(g, to_eye) < 0.0f)
        for (k = 0; k < 3; k++)
            g[k] = -g[k];
    return dot(g, to_eye) != 0.0f && stin__normalize3(g);
}

/* The lift (the curved surface's height over the facet, along g) is
 * sum over the corner pairs j, k of b_j b_k (p_k - p_j).(n_k (n_k.g) -
 * n_j (n_j.g)): zero at the corners, above the facet inside the triangle
 * when no pair's term is below zero (to rounding) and one is above. */
static int lifted_above(const corner c[3], const float g[3])
{
    float most = 0.0f;
    int j, k;
    for (j = 0; j < 3; j++) {
        const corner *a = &c[j], *b = &c[(j + 1) % 3];
        float e[3], term;
        for (k = 0; k < 3; k++)
            e[k] = b->p[k] - a->p[k];
        term = dot(e, b->n) * dot(b->n, g) - dot(e, a->n) * dot(a->n, g);
        if (term < -1e-5f * stin__sqrtf(dot(e, e)))
            return 0;
        if (term > most)
            most = term;
    }
    return most > 0.0f;
}

/* The rule's "shading normal toward the light" (S.(L - org)) on the edge
 * from a to b at t: the corners' normals blended, from the curved
 * surface's point org = P + t (1 - t) ((e.n_b) n_b - (e.n_a) n_a). */
static float edge_rule(const corner *a, const corner *b, const float light[4], float t)
{
    float e[3], s[3], to_light[3], ea, eb;
    int k;
    for (k = 0; k < 3; k++)
        e[k] = b->p[k] - a->p[k];
    ea = dot(e, a->n);
    eb = dot(e, b->n);
    for (k = 0; k < 3; k++) {
        float org = a->p[k] + t * e[k] + t * (1.0f - t) * (eb * b->n[k] - ea * a->n[k]);
        s[k] = (1.0f - t) * a->n[k] + t * b->n[k];
        to_light[k] = light[k] - light[3] * org;
    }
    return dot(s, to_light);
}

/* Where on the edge from a to b (t in 0-1) the rule turns, a's side at 0
 * and the other at 1: by false position (Illinois), the rule being close
 * to linear along an edge. */
static float edge_zero(const corner *a, const corner *b, const float light[4], int a_toward)
{
    float lo = 0.0f, hi = 1.0f, f_lo = edge_rule(a, b, light, 0.0f),
          f_hi = edge_rule(a, b, light, 1.0f), t = 0.5f;
    int i, last = 0;
    for (i = 0; i < 8 && f_hi != f_lo; i++) {
        float f;
        t = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        f = edge_rule(a, b, light, t);
        if ((f > 0.0f) == a_toward) {
            lo = t;
            f_lo = f;
            if (last < 0)
                f_hi *= 0.5f;
            last = -1;
        } else {
            hi = t;
            f_hi = f;
            if (last > 0)
                f_lo *= 0.5f;
            last = 1;
        }
    }
    return t < 1e-6f ? 1e-6f : t > 1.0f - 1e-6f ? 1.0f - 1e-6f : t;
}

/* Corner values whose blend turns where the rule turns on the two edges
 * it crosses (the corners' own signs kept): the alpha test's line then
 * meets the rule's curve at both ends, which the corners' own values do
 * only for a directional light. */
static void fit_zero_line(const corner c[3], const float light[4], float h[3])
{
    int odd, i, toward;
    float most = 1.0f;
    if ((h[0] > 0.0f) == (h[1] > 0.0f) && (h[0] > 0.0f) == (h[2] > 0.0f))
        return; /* no edge crosses */
    odd = (h[0] > 0.0f) == (h[1] > 0.0f) ? 2 : (h[0] > 0.0f) == (h[2] > 0.0f) ? 1 : 0;
    toward = h[odd] > 0.0f;
    for (i = 0; i < 3; i++) {
        float t;
        if (i == odd)
            continue;
        t = edge_zero(&c[odd], &c[i], light, toward);
        h[i] = (toward ? -1.0f : 1.0f) * (1.0f - t) / t;
        if (h[i] > most || -h[i] > most)
            most = h[i] > 0.0f ? h[i] : -h[i];
    }
    h[odd] = toward ? 1.0f : -1.0f;
    for (i = 0; i < 3; i++)
        h[i] /= most;
}

/* Whether the facet (g, seen by the eye) turns away from the light: no
 * count to take back where it faces it. */
static int turned_from(const corner c[3], const float g[3], const float light[4])
{
    float to_light[3];
    int k;
    for (k = 0; k < 3; k++)
        to_light[k] = light[k] - light[3] * c[0].p[k];
    return dot(g, to_light) <= 0.0f;
}

/* Each corner's shading normal toward the light (h: n.(L - p), L's w 0 a
 * direction) where the triangle may hold band fragments; 0 where none. */
static int band_corners(const corner c[3], const float g[3], const float light[4], float h[3])
{
    float to_light[3], most = 0.0f, scale = 0.0f;
    int i, k, smooth = 0;
    for (i = 0; i < 3; i++) {
        float facing = dot(c[i].n, g);
        if (facing <= 0.0f)
            return 0;
        smooth |= facing < 1.0f - 1e-6f;
        for (k = 0; k < 3; k++)
            to_light[k] = light[k] - light[3] * c[i].p[k];
        h[i] = dot(c[i].n, to_light);
        if (h[i] > most)
            most = h[i];
        if (h[i] > scale || -h[i] > scale)
            scale = h[i] > 0.0f ? h[i] : -h[i];
    }
    if (!smooth || most <= 0.0f || !lifted_above(c, g))
        return 0;
    for (i = 0; i < 3; i++) /* within [-1, 1]: GL clamps colours */
        h[i] /= scale;
    fit_zero_line(c, light, h);
    return 1;
}

int stin__band_view_init(const stin_context *ctx, const stin__draw *d, stin__band_view *bv)
{
    float view_inv[16];
    if (!stin__mat4_invert(view_inv, ctx->frame.view))
        return 0;
    stin__memcopy(bv->eye, view_inv + 12, sizeof bv->eye);
    stin__mat3_normal(bv->normal_matrix, d->transform);
    return 1;
}

/* The triangle's facts (h: its corners' values) where it may hold band
 * fragments; 0 where none. */
static int band_triangle(const stin_context *ctx, const stin__band_view *bv, const stin__draw *d,
                         const float light[4], const uint32_t *tri, float h[3])
{
    const stin__vertex *v = ctx->vertices + ctx->meshes[d->mesh_slot].first_vertex;
    corner c[3];
    float g[3];
    world_positions(d, v, tri, c);
    return eye_side_facet(c, bv->eye, g) && turned_from(c, g, light) &&
           world_normals(bv->normal_matrix, v, tri, c) && band_corners(c, g, light, h);
}

int stin__band_triangle(const stin_context *ctx, const stin__band_view *bv, const stin__draw *d,
                        const float light[4], const uint32_t *tri)
{
    float h[3];
    return band_triangle(ctx, bv, d, light, tri, h);
}

void stin__fixed_terminator_band(stin_context *ctx, const stin__draw *d, const float light[4],
                                 const uint32_t *tris, uint32_t n)
{
    const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
    const stin__vertex *v = ctx->vertices + m->first_vertex;
    stin__band_view bv;
    float mv[16];
    uint32_t t;
    int i;
    if (!stin__band_view_init(ctx, d, &bv))
        return;
    stin__mat4_mul(mv, ctx->frame.view, d->transform);
    GL_DISABLE(ctx, GL_LIGHTING);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(mv);
    /* a quarter of an 8-bit step under one half: where GL tests alpha in
     * 8 bits (llvmpipe rounds both to 255ths) that keeps alpha >= 0.5
     * exactly (0.5 itself would keep 128.5/255 up, a tenth of a pixel
     * off the rule's line on the test scenes); in float, 0.001 under it */
    GL_ENABLE(ctx, GL_ALPHA_TEST);
    GL(ctx, AlphaFunc)(GL_GREATER, 0.5f - 0.25f / 255.0f);
    GL(ctx, Begin)(GL_TRIANGLES);
    for (t = 0; t < n; t++) {
        const uint32_t *tri = tris + 3u * t;
        float h[3];
        if (!band_triangle(ctx, &bv, d, light, tri, h))
            continue;
        for (i = 0; i < 3; i++) {
            GL(ctx, Color4f)(0.0f, 0.0f, 0.0f, 0.5f + 0.5f * h[i]);
            GL(ctx, Vertex3fv)(v[tri[i]].position);
        }
    }
    GL(ctx, End)();
    GL_DISABLE(ctx, GL_ALPHA_TEST);
    GL(ctx, AlphaFunc)(GL_ALWAYS, 0.0f);
}
