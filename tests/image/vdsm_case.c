/* SPDX-License-Identifier: MIT */
/* The VDSM image tests' shared case (vdsm_case.h). */
#include "vdsm_case.h"
#include "aov.h"
#include "test_context.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define AMBIGUOUS_MOVE 1e-5
#define AMBIGUOUS_COS 1e-4
#define RASTER_STEP (1.0 / 256.0)


/* The ray cast leaves the surface as vdsm's test does (shaders/gl4/vdsm.frag):
 * 2^-13 of the point's largest coordinate along the facet normal, not the
 * reference's scene epsilon (1e-4 of the scene), which would decide pixels
 * within that distance of a shadow edge differently. */
float vdsm_truth(const vdsm_case *c, const ref_hit *h)
{
    double a = fabs(h->P[0]), b = fabs(h->P[1]), d = fabs(h->P[2]), m = a > b ? a : b;
    m = m > d ? m : d;
    return reference_visibility_offset(c->refr, h, 0, (m > 1e-3 ? m : 1e-3) / 8192.0);
}

void vdsm_name(const vdsm_case *c, const char *test, char *out, size_t size)
{
    snprintf(out, size, "gl4/%s/vdsm-%s", c->scene_name, test);
}

const float *vdsm_px(const image *img, int x, int y)
{
    return img->pixels + ((size_t)(img->height - 1 - y) * img->width + x) * AOV_CHANNELS;
}

static int p_matches(const float *g, const float *ref)
{
    double d2 = 0;
    int k;
    if (!(g[AOV_Z] > 0.0f))
        return 0;
    for (k = 0; k < 3; k++) {
        double d = g[AOV_PX + k] - ref[REFERENCE_CH_PX + k];
        d2 += d * d;
    }
    return sqrt(d2) <= 1e-3 * ref[REFERENCE_CH_Z] + 1e-3;
}

/* The light's distance from the point (directional: the point's distance
 * from the origin plus one) plus the eye's. */
static double ray_lengths(const vdsm_case *c, const ref_hit *h)
{
    const scene_light *l = &c->s->lights[0];
    double d = 0, e = 0;
    int k;
    for (k = 0; k < 3; k++) {
        double a = l->type == SCENE_LIGHT_DIRECTIONAL ? h->P[k] : l->position[k] - h->P[k];
        double b = c->s->camera.eye[k] - h->P[k];
        d += a * a;
        e += b * b;
    }
    return (l->type == SCENE_LIGHT_DIRECTIONAL ? sqrt(d) + 1.0 : sqrt(d)) + sqrt(e);
}

/* The reference's answer is not robust here: see the file comment. */
static int ambiguous(const vdsm_case *c, const ref_hit *h, float vis)
{
    const scene_light *l = &c->s->lights[0];
    double to_light[3], len = 0, cosine = 0, shading = 0;
    double move = AMBIGUOUS_MOVE * ray_lengths(c, h);
    int k, axis;
    for (k = 0; k < 3; k++) {
        to_light[k] = l->type == SCENE_LIGHT_DIRECTIONAL ? -l->direction[k] : l->position[k] - h->P[k];
        len += to_light[k] * to_light[k];
        cosine += to_light[k] * h->Ng[k];
        shading += to_light[k] * h->N[k];
    }
    /* the facet or the shading normal (the terminator rule's other facing
     * test) within rounding of edge-on */
    if (len > 0 && (fabs(cosine) / sqrt(len) < AMBIGUOUS_COS ||
                    fabs(shading) / sqrt(len) < AMBIGUOUS_COS))
        return 1;
    /* along the surface (moving into it would only test the offset) */
    {
        double t1[3], t2[3], pick[3] = {0, 0, 0}, n1 = 0, n2 = 0;
        pick[fabs(h->Ng[0]) < 0.5 ? 0 : 1] = 1.0;
        t1[0] = h->Ng[1] * pick[2] - h->Ng[2] * pick[1];
        t1[1] = h->Ng[2] * pick[0] - h->Ng[0] * pick[2];
        t1[2] = h->Ng[0] * pick[1] - h->Ng[1] * pick[0];
        t2[0] = h->Ng[1] * t1[2] - h->Ng[2] * t1[1];
        t2[1] = h->Ng[2] * t1[0] - h->Ng[0] * t1[2];
        t2[2] = h->Ng[0] * t1[1] - h->Ng[1] * t1[0];
        for (k = 0; k < 3; k++) {
            n1 += t1[k] * t1[k];
            n2 += t2[k] * t2[k];
        }
        for (axis = 0; axis < 4; axis++) {
            ref_hit moved = *h;
            const double *t = axis & 1 ? t2 : t1;
            double s = (axis & 2 ? -move : move) / sqrt(axis & 1 ? n2 : n1);
            for (k = 0; k < 3; k++)
                moved.P[k] += (float)(s * t[k]);
            if (vdsm_truth(c, &moved) != vis)
                return 1;
        }
    }
    return 0;
}

/* The pixel's centre lies within the rasterizer's precision (vertices
 * snapped to 1/256 pixel) of an edge of the triangle the reference hit:
 * the GPU may give the pixel to the triangle across that edge, a surface
 * with another normal (and so another facing) at the same point. */
static int on_triangle_edge(const vdsm_case *c, int x, int y, const ref_hit *h)
{
    static const double d[4][2] = {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
    int k;
    for (k = 0; k < 4; k++) {
        ref_hit q;
        if (!reference_hit_on_plane(c->refr, c->r->width, c->r->height, h,
                                    x + 0.5 + d[k][0] * RASTER_STEP,
                                    y + 0.5 + d[k][1] * RASTER_STEP, &q) ||
            q.u < 0.0f || q.v < 0.0f || q.u + q.v > 1.0f)
            return 1;
    }
    return 0;
}

/* The ray cast from the point stin shaded (its P output, which the
 * position test accepts as this pixel's hit) gives stin's answer: the exact
 * hit and the interpolated one lie on either side of a shadow edge, and the
 * reference cannot say which the pixel is. */
static int shaded_point_agrees(const vdsm_case *c, const ref_hit *h, const float *g)
{
    ref_hit moved = *h;
    int k;
    for (k = 0; k < 3; k++)
        moved.P[k] = g[AOV_PX + k];
    return (vdsm_truth(c, &moved) >= 0.5f) == (g[AOV_VIS_R] >= 0.5f);
}

/* The reference's visibility (or the object) changes within one pixel. */
int vdsm_on_shadow_edge(const vdsm_case *c, int x, int y)
{
    int w = c->r->width, h = c->r->height, dx, dy;
    const ref_hit *me = &c->hits[(size_t)y * w + x];
    float v = me->hit ? vdsm_truth(c, me) : 1.0f;
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++) {
            int nx = x + dx, ny = y + dy;
            const ref_hit *o;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h)
                continue;
            o = &c->hits[(size_t)ny * w + nx];
            if (o->hit != me->hit || o->object != me->object || (o->hit && vdsm_truth(c, o) != v))
                return 1;
        }
    return 0;
}

/* Pixels whose visibility differs from the reference; ambiguous ones are
 * counted apart, and of the rest those next to a reference shadow edge. */
long vdsm_mismatches(const vdsm_case *c, const capture *cap, long *compared, long *ambig,
                       long *isolated, long *on_edge)
{
    int w = c->r->width, h = c->r->height, x, y;
    long differ = 0;
    *compared = *ambig = *isolated = *on_edge = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const ref_hit *hit = &c->hits[(size_t)y * w + x];
            const float *ref = c->ref + ((size_t)y * w + x) * REFERENCE_CHANNELS;
            const float *g = vdsm_px(&cap->img, x, y);
            float truth;
            if (!hit->hit || !p_matches(g, ref))
                continue;
            (*compared)++;
            truth = vdsm_truth(c, hit);
            if ((g[AOV_VIS_R] >= 0.5f) == (truth >= 0.5f))
                continue;
            if (ambiguous(c, hit, truth) || shaded_point_agrees(c, hit, g) ||
                on_triangle_edge(c, x, y, hit)) {
                (*ambig)++;
                continue;
            }
            differ++;
            if (getenv("STIN_TEST_VERBOSE"))
                fprintf(stderr, "  vdsm mismatch at pixel %d,%d: stin %.3f, reference %.3f\n", x,
                        h - 1 - y, g[AOV_VIS_R], truth);
            {
                /* isolated: every neighbour agrees with the reference (the seed's
                 * lone lit pixel in a shadow); on an edge: the reference changes
                 * (or the object does) within one pixel */
                int dx, dy, alone = 1, edge = 0;
                for (dy = -1; dy <= 1; dy++)
                    for (dx = -1; dx <= 1; dx++) {
                        int nx = x + dx, ny = y + dy;
                        const ref_hit *o;
                        if (!(dx || dy) || nx < 0 || ny < 0 || nx >= w || ny >= h)
                            continue;
                        o = &c->hits[(size_t)ny * w + nx];
                        if (!o->hit || o->object != hit->object || vdsm_truth(c, o) != truth)
                            edge = 1;
                        else if ((vdsm_px(&cap->img, nx, ny)[AOV_VIS_R] >= 0.5f) != (truth >= 0.5f))
                            alone = 0;
                    }
                *isolated += alone && !edge;
                *on_edge += edge;
            }
        }
    return differ;
}


static int render(const vdsm_case *c, uint64_t debug, uint32_t map_size, int visibility_only,
                  capture *out, const char *test)
{
    capture_options o;
    char err[512], name[256];
    memset(&o, 0, sizeof o);
    o.tier = STIN_TIER_GL4;
    o.shadows = STIN_TECH_SHADOWS_VDSM;
    o.debug_flags = debug;
    o.shadow_map_size = map_size;
    o.visibility_only = visibility_only;
    if (capture_render(c->r->plat, c->r->profile, c->s, &o, out, err, sizeof err))
        return 1;
    vdsm_name(c, test, name, sizeof name);
    report(c->r, "FAIL", name, "%s", err);
    capture_free(out);
    return 0;
}

int vdsm_render(const vdsm_case *c, uint64_t debug, capture *out, const char *test)
{
    return render(c, debug, 0, 0, out, test);
}

int vdsm_render_mask(const vdsm_case *c, uint64_t debug, uint32_t map_size, capture *out,
                     const char *test)
{
    return render(c, debug, map_size, 1, out, test);
}

int vdsm_runs_here(run *r, const char *scene_name, const char *test)
{
    static int refused = -1; /* one profile a run */
    static char why[512];
    char name[256];
    if (refused < 0)
        refused = technique_refused(r, STIN_TIER_GL4, STIN_FEATURE_SHADOWS,
                                    STIN_TECH_SHADOWS_VDSM, why, sizeof why);
    if (refused) {
        snprintf(name, sizeof name, "gl4/%s/vdsm-%s", scene_name, test);
        report(r, "SKIP", name, "vdsm does not run here (%s)", why);
    }
    return !refused;
}

/* The reference of a case: 0 (reported under `test`) when it cannot be made. */
int vdsm_case_open(vdsm_case *c, run *r, const scene *s, const char *scene_name,
                     const char *test)
{
    char err[512];
    reference *ref;
    memset(c, 0, sizeof *c);
    c->r = r;
    c->s = s;
    c->scene_name = scene_name;
    ref = reference_create(s, err, sizeof err);
    c->refr = ref;
    c->hits = malloc(sizeof *c->hits * (size_t)r->width * r->height);
    c->ref = malloc(sizeof(float) * REFERENCE_CHANNELS * (size_t)r->width * r->height);
    if (!ref || !c->hits || !c->ref ||
        !reference_primary(ref, r->width, r->height, (ref_hit *)c->hits) ||
        !reference_render_ex(s, ref, r->width, r->height, 0, REFERENCE_RENDER_SHADOWED,
                             (float *)c->ref)) {
        char name[256];
        vdsm_name(c, test, name, sizeof name);
        report(r, "FAIL", name, "reference: %s", ref ? "render failed" : err);
        return 0;
    }
    return 1;
}

void vdsm_case_close(vdsm_case *c)
{
    free((void *)c->hits);
    free((void *)c->ref);
    if (c->refr)
        reference_destroy((reference *)c->refr);
}
