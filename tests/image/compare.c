/* SPDX-License-Identifier: MIT */
/* Per-pixel comparison of a render with the exact reference. */
#include "compare.h"
#include "aov.h"

#include <math.h>
#include <string.h>

/* A pixel next to a different object (or the background) is a silhouette
 * pixel: rasterisation and ray casting may legitimately pick either side. */
static int on_silhouette(const ref_hit *hits, int w, int h, int x, int y)
{
    int dx, dy, obj = hits[(size_t)y * w + x].hit ? hits[(size_t)y * w + x].object : -1;
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++) {
            int nx = x + dx, ny = y + dy, o;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h)
                continue;
            o = hits[(size_t)ny * w + nx].hit ? hits[(size_t)ny * w + nx].object : -1;
            if (o != obj)
                return 1;
        }
    return 0;
}

static int plain_opaque(const scene *s, const ref_hit *hit)
{
    const scene_material *m = &s->materials[s->objects[hit->object].material];
    return m->color[3] >= 1.0f && m->albedo < 0;
}

void compare_render(const scene *s, const image *gl, const float *ref, const ref_hit *hits,
                    const compare_tolerance *tol, compare_result *out)
{
    int w = gl->width, h = gl->height, x, y, c;
    double beauty_sum = 0;
    memset(out, 0, sizeof *out);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const float *g = gl->pixels + ((size_t)(h - 1 - y) * w + x) * AOV_CHANNELS;
            const float *r = ref + ((size_t)y * w + x) * REFERENCE_CHANNELS;
            const ref_hit *hit = &hits[(size_t)y * w + x];
            int gl_cov = g[AOV_Z] > 0.0f, ref_cov = hit->hit;
            double d2 = 0, limit;
            if (!gl_cov && !ref_cov)
                continue;
            out->covered++;
            if (gl_cov != ref_cov) {
                out->coverage_mismatch++;
                continue;
            }
            for (c = 0; c < 3; c++) {
                double d = g[AOV_PX + c] - r[REFERENCE_CH_PX + c];
                d2 += d * d;
            }
            limit = tol->p_relative * r[REFERENCE_CH_Z] + tol->p_absolute;
            if (sqrt(d2) > limit) {
                out->p_mismatch++;
                continue;
            }
            if (sqrt(d2) / limit > out->p_max_error)
                out->p_max_error = sqrt(d2) / limit;
            out->vis_compared++;
            if (fabs(g[AOV_VIS_R] - r[REFERENCE_CH_VIS_R]) > 0.5)
                out->vis_mismatch++;
            if (on_silhouette(hits, w, h, x, y))
                continue;
            {
                double dot = 0, deg;
                for (c = 0; c < 3; c++)
                    dot += g[AOV_NX + c] * r[REFERENCE_CH_NX + c];
                deg = acos(dot > 1 ? 1 : dot < -1 ? -1 : dot) * 57.29577951308232;
                out->normal_compared++;
                if (deg > tol->normal_deg)
                    out->normal_over++;
                if (deg > out->normal_max_deg)
                    out->normal_max_deg = deg;
            }
            if (!plain_opaque(s, hit))
                continue;
            {
                double worst = 0;
                for (c = 0; c < 3; c++) {
                    double d = fabs(g[AOV_R + c] - r[REFERENCE_CH_R + c]);
                    if (d > worst)
                        worst = d;
                }
                out->beauty_compared++;
                beauty_sum += worst;
                if (worst > tol->beauty)
                    out->beauty_over++;
                if (worst > out->beauty_max)
                    out->beauty_max = worst;
            }
        }
    out->beauty_mean = out->beauty_compared ? beauty_sum / out->beauty_compared : 0;
}
