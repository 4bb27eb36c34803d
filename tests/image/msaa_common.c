/* SPDX-License-Identifier: MIT */
#include "msaa_common.h"
#include "test_context.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void msaa_ref_init(msaa_ref *m, const scene *s)
{
    memset(m, 0, sizeof *m);
    m->w = s->width;
    m->h = s->height;
}

int msaa_ref_alloc(msaa_ref *m, int n)
{
    size_t px = (size_t)m->w * m->h;
    m->n = n;
    m->hits = malloc(sizeof *m->hits * px * (size_t)n);
    m->colour = calloc(px * 3, sizeof(float));
    m->vis = malloc(sizeof(float) * px * (size_t)n);
    m->centre_differs = calloc(px, 1);
    return m->hits && m->colour && m->vis && m->centre_differs;
}

/* The lights' visibilities at a hit as one number: sum of v_i 2^i. */
static float visibility_code(const scene *s, const reference *ref, const ref_hit *h)
{
    float code = 0.0f;
    int l;
    for (l = 0; h->hit && l < s->light_count && l < 8; l++)
        code += reference_light_visibility(ref, h, l) * (float)(1 << l);
    return code;
}

void msaa_ref_shade(const scene *s, const reference *ref, int per_vertex, int at_centre,
                    msaa_ref *m)
{
    size_t px = (size_t)m->w * m->h, i;
    int k, q;
    for (k = 0; k < m->n; k++) {
        const ref_hit *hk = m->hits + px * (size_t)k;
        for (i = 0; i < px; i++) {
            int x = (int)(i % (size_t)m->w), y = (int)(i / (size_t)m->w);
            ref_hit c = hk[i];
            float rgba[4], *v = &m->vis[px * (size_t)k + i];
            *v = m->unshadowed ? 0.0f : visibility_code(s, ref, &hk[i]);
            if (at_centre && hk[i].hit &&
                reference_hit_on_plane(ref, m->w, m->h, &hk[i], x + 0.5, y + 0.5, &c)) {
                /* the plane's own normals: turned back where the hit's
                 * were (a complemented primitive's inside wall) */
                if (c.Ng[0] * hk[i].Ng[0] + c.Ng[1] * hk[i].Ng[1] + c.Ng[2] * hk[i].Ng[2] < 0)
                    for (q = 0; q < 3; q++) {
                        c.N[q] = -c.N[q];
                        c.Ng[q] = -c.Ng[q];
                    }
                if (at_centre == MSAA_AT_CENTRE_INSIDE &&
                    (c.u < 0.0f || c.v < 0.0f || c.u + c.v > 1.0f))
                    c = hk[i];
                if (!m->unshadowed && visibility_code(s, ref, &c) != *v)
                    m->centre_differs[i] = 1;
            }
            if (m->unshadowed)
                reference_shade(s, ref, &c, per_vertex, rgba);
            else
                reference_shade_passes(s, ref, &c, per_vertex, rgba);
            m->colour[3 * i] += rgba[0] / (float)m->n;
            m->colour[3 * i + 1] += rgba[1] / (float)m->n;
            m->colour[3 * i + 2] += rgba[2] / (float)m->n;
        }
    }
}

void msaa_ref_free(msaa_ref *m)
{
    free(m->hits);
    free(m->colour);
    free(m->vis);
    free(m->centre_differs);
}

int msaa_ref_build(const scene *s, int facets, int per_vertex, const float pos[][2], int n,
                   msaa_ref *m, char *err, size_t err_size)
{
    reference *ref = reference_create(s, err, err_size);
    size_t px = (size_t)m->w * m->h;
    int k, ok = ref != NULL;
    ok = msaa_ref_alloc(m, n) && ok;
    if (ok) {
        reference_facet_terminator(ref, facets);
        reference_set_area_samples(ref, 64);
    }
    for (k = 0; ok && k < n; k++)
        ok = reference_primary_at(ref, m->w, m->h, pos[k][0], pos[k][1],
                                  m->hits + px * (size_t)k);
    if (ok)
        msaa_ref_shade(s, ref, per_vertex, 1, m);
    if (ref)
        reference_destroy(ref);
    if (!ok && err[0] == '\0')
        snprintf(err, err_size, "reference failed");
    return ok;
}

static int object_at(const msaa_ref *m, int k, int x, int y)
{
    const ref_hit *h = &m->hits[(size_t)k * m->w * m->h + (size_t)y * m->w + x];
    return h->hit ? h->object : -1;
}

/* Pixel (x, y) has samples of more than one object (or background). */
static int mixed(const msaa_ref *m, int x, int y)
{
    int k, o = object_at(m, 0, x, y);
    for (k = 1; k < m->n; k++)
        if (object_at(m, k, x, y) != o)
            return 1;
    return 0;
}

/* A shadow edge of one object inside the pixel or its 8 neighbours, or
 * between a sample and its surface's point at the pixel centre: the
 * technique decides visibility once a pixel per surface (multisampling
 * shades at the centre), which the box filter of per-sample visibility
 * does not; those pixels are the shadow tests' business, not the halo's. */
static int shadow_edge(const msaa_ref *m, int x, int y)
{
    size_t px = (size_t)m->w * m->h;
    int dx, dy, k, j;
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++) {
            int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= m->w || yy >= m->h)
                continue;
            if (m->centre_differs[(size_t)yy * m->w + xx])
                return 1;
            for (k = 0; k < m->n; k++)
                for (j = 0; j < m->n; j++) {
                    size_t a = px * (size_t)k + (size_t)y * m->w + x;
                    size_t b = px * (size_t)j + (size_t)yy * m->w + xx;
                    if (object_at(m, k, x, y) == object_at(m, j, xx, yy) &&
                        m->vis[a] != m->vis[b])
                        return 1;
                }
        }
    return 0;
}

void msaa_compare_band(const msaa_ref *m, const uint8_t *rgba, int stride, double tolerance,
                       msaa_band *b)
{
    int x, y, dx, dy;
    memset(b, 0, sizeof *b);
    for (y = 0; y < m->h; y++)
        for (x = 0; x < m->w; x++) {
            const uint8_t *p = rgba + 4 * ((size_t)y * stride + x);
            const float *c = m->colour + 3 * ((size_t)y * m->w + x);
            double d = 0;
            int c3, near_edge = 0;
            for (c3 = 0; c3 < 3; c3++)
                d = fmax(d, fabs(p[c3] / 255.0 - c[c3]));
            if (shadow_edge(m, x, y))
                continue;
            for (dy = -1; dy <= 1 && !near_edge; dy++)
                for (dx = -1; dx <= 1 && !near_edge; dx++) {
                    int xx = x + dx, yy = y + dy;
                    near_edge = xx >= 0 && yy >= 0 && xx < m->w && yy < m->h && mixed(m, xx, yy);
                }
            if (near_edge) {
                b->band++;
                b->over += d > tolerance;
                b->band_max = fmax(b->band_max, d);
            } else {
                b->compared++;
                b->compared_over += d > tolerance;
                b->compared_max = fmax(b->compared_max, d);
            }
        }
}

void msaa_report_band(run *r, const char *name, const msaa_ref *m, const uint8_t *rgba,
                      const msaa_bounds *bd)
{
    msaa_band b;
    int pass;
    msaa_compare_band(m, rgba, r->width, bd->tolerance, &b);
    pass = b.over <= bd->max_band_over && b.band > 100 &&
           b.compared_over <= bd->max_over_fraction * (double)b.compared;
    report(r, pass ? "PASS" : "FAIL", name,
           "%d samples: %ld of %ld silhouette-band pixels beyond %.3f of the reference at the "
           "samples (max %.3f; at most %d); elsewhere %ld of %ld (max %.3f; at most %.0f%%)",
           m->n, b.over, b.band, bd->tolerance, b.band_max, bd->max_band_over, b.compared_over,
           b.compared, b.compared_max, 100.0 * bd->max_over_fraction);
    if (!pass)
        msaa_save_pair(r, name, rgba, m->colour, m->w, m->h);
}

void msaa_row(run *r, const scene *s, const msaa_techniques *t, const char *name, int n,
              msaa_ref_fn build, const void *ctx, const msaa_bounds *bd)
{
    uint8_t *rgba = malloc((size_t)r->width * r->height * 4);
    char why[512] = "";
    msaa_ref m;
    msaa_ref_init(&m, s);
    m.n = n;
    if (msaa_render_reported(r, s, t, rgba, name)) {
        if (build(ctx, &m, why, sizeof why))
            msaa_report_band(r, name, &m, rgba, bd);
        else
            report(r, "FAIL", name, "reference: %s", why);
    }
    msaa_ref_free(&m);
    free(rgba);
}
