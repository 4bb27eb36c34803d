/* SPDX-License-Identifier: MIT */
/*
 * VDSM ("vdsm", GL4) against the Embree visibility reference, light 0:
 *   vis        no pixel away from a reference shadow edge differs from the
 *              ray-cast visibility of each pixel's surface point, and at
 *              most 0.05% on one (area lights from their centre, as
 *              vdsm shadows them). Not counted, and reported: pixels where
 *              the reference is ambiguous - its answer changes when the ray
 *              origin moves along the surface by 1e-5 of the light's and
 *              the eye's distance (a ray grazing an edge, or the GPU's
 *              interpolated surface point on the other side of it), or the surface is within 1e-4 of edge-on to the light.
 *              Compared: covered pixels whose P matches the reference's.
 *   no-grow    the same count without conservative growth (the seed's
 *              isolated lit pixels): it may not come out lower than with it.
 *   steps      EP off gives the identical mask on every pixel away from a
 *              reference shadow edge (the chain's invariance; open meshes
 *              have EP off anyway), and at most 0.05% differ on one.
 *   gl-clean   no GL error, no call outside the profile.
 */
#include "aov.h"
#include "capture.h"
#include "image_test.h"
#include "reference.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define AMBIGUOUS_MOVE 1e-5
/* Pixels on a reference shadow edge that may differ: the GPU's interpolated
 * surface point is off the exact one by up to about 1e-5 of the eye
 * distance, which moves a shadow edge that far (measured: at most 4 pixels
 * of 18,002 on the spheres scenes at 256x192). */
#define VIS_EDGE_BUDGET 0.0005
#define AMBIGUOUS_COS 1e-4

typedef struct vdsm_case {
    run *r;
    const scene *s;
    const char *scene_name;
    const reference *refr;
    const ref_hit *hits;
    const float *ref;        /* reference AOVs (P), rows bottom to top */
} vdsm_case;

/* The ray cast leaves the surface as vdsm's test does (shaders/gl4/vdsm.frag):
 * 2^-13 of the point's largest coordinate along the facet normal, not the
 * reference's scene epsilon (1e-4 of the scene), which would decide pixels
 * within that distance of a shadow edge differently. */
static float truth_at(const vdsm_case *c, const ref_hit *h)
{
    double a = fabs(h->P[0]), b = fabs(h->P[1]), d = fabs(h->P[2]), m = a > b ? a : b;
    m = m > d ? m : d;
    return reference_visibility_offset(c->refr, h, 0, (m > 1e-3 ? m : 1e-3) / 8192.0);
}

static void name_of(const vdsm_case *c, const char *test, char *out, size_t size)
{
    snprintf(out, size, "gl4/%s/vdsm-%s", c->scene_name, test);
}

static const float *gl_px(const image *img, int x, int y)
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
    double to_light[3], len = 0, cosine = 0, move = AMBIGUOUS_MOVE * ray_lengths(c, h);
    int k, axis;
    for (k = 0; k < 3; k++) {
        to_light[k] = l->type == SCENE_LIGHT_DIRECTIONAL ? -l->direction[k] : l->position[k] - h->P[k];
        len += to_light[k] * to_light[k];
        cosine += to_light[k] * h->Ng[k];
    }
    if (len > 0 && fabs(cosine) / sqrt(len) < AMBIGUOUS_COS)
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
            if (truth_at(c, &moved) != vis)
                return 1;
        }
    }
    return 0;
}

/* Pixels whose visibility differs from the reference; ambiguous ones are
 * counted apart, and of the rest those next to a reference shadow edge. */
static long mismatches(const vdsm_case *c, const capture *cap, long *compared, long *ambig,
                       long *isolated, long *on_edge)
{
    int w = c->r->width, h = c->r->height, x, y;
    long differ = 0;
    *compared = *ambig = *isolated = *on_edge = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const ref_hit *hit = &c->hits[(size_t)y * w + x];
            const float *ref = c->ref + ((size_t)y * w + x) * REFERENCE_CHANNELS;
            const float *g = gl_px(&cap->img, x, y);
            float truth;
            if (!hit->hit || !p_matches(g, ref))
                continue;
            (*compared)++;
            truth = truth_at(c, hit);
            if ((g[AOV_VIS_R] >= 0.5f) == (truth >= 0.5f))
                continue;
            if (ambiguous(c, hit, truth)) {
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
                        if (!o->hit || o->object != hit->object || truth_at(c, o) != truth)
                            edge = 1;
                        else if ((gl_px(&cap->img, nx, ny)[AOV_VIS_R] >= 0.5f) != (truth >= 0.5f))
                            alone = 0;
                    }
                *isolated += alone && !edge;
                *on_edge += edge;
            }
        }
    return differ;
}

static int render(const vdsm_case *c, uint32_t debug, capture *out, const char *test)
{
    capture_options o;
    char err[512], name[256];
    memset(&o, 0, sizeof o);
    o.tier = STIN_TIER_GL4;
    o.shadows = STIN_TECH_SHADOWS_VDSM;
    o.debug_flags = debug;
    if (capture_render(c->r->plat, c->r->profile, c->s, &o, out, err, sizeof err))
        return 1;
    name_of(c, test, name, sizeof name);
    report(c->r, "FAIL", name, "%s", err);
    capture_free(out);
    return 0;
}

static void test_clean(const vdsm_case *c, const capture *cap)
{
    char name[256];
    name_of(c, "gl-clean", name, sizeof name);
    if (cap->counters.gl_violations || cap->counters.gl_errors || cap->log_errors)
        report(c->r, "FAIL", name, "%u profile violations, %u GL errors, %u error logs (last: %s)",
               cap->counters.gl_violations, cap->counters.gl_errors, cap->log_errors,
               cap->last_error);
    else
        report(c->r, "PASS", name, "no GL error, no call outside the profile");
}

static long test_vis(const vdsm_case *c, const capture *cap)
{
    long compared, ambig, isolated, edge, differ = mismatches(c, cap, &compared, &ambig, &isolated,
                                                              &edge);
    char name[256];
    name_of(c, "vis", name, sizeof name);
    report(c->r,
           compared > 0 && differ == edge && edge <= VIS_EDGE_BUDGET * compared ? "PASS" : "FAIL",
           name,
           "visibility differs from the ray cast on %ld of %ld pixels, %ld of them next to a "
           "reference shadow edge (at most %.2f%%; none elsewhere), %ld isolated; not counted: "
           "%ld where the reference is ambiguous",
           differ, compared, edge, 100.0 * VIS_EDGE_BUDGET, isolated, ambig);
    return differ;
}

static void test_no_grow(const vdsm_case *c, long with_growth)
{
    capture b;
    long compared, ambig, isolated, edge, differ;
    char name[256];
    name_of(c, "no-grow", name, sizeof name);
    if (!render(c, STIN_DEBUG_VDSM_NO_GROW, &b, "no-grow"))
        return;
    differ = mismatches(c, &b, &compared, &ambig, &isolated, &edge);
    report(c->r, differ >= with_growth ? "PASS" : "FAIL", name,
           "without conservative growth %ld of %ld pixels differ (%ld isolated), with it %ld",
           differ, compared, isolated, with_growth);
    capture_free(&b);
}

/* The reference's visibility (or the object) changes within one pixel. */
static int on_shadow_edge(const vdsm_case *c, int x, int y)
{
    int w = c->r->width, h = c->r->height, dx, dy;
    const ref_hit *me = &c->hits[(size_t)y * w + x];
    float v = me->hit ? truth_at(c, me) : 1.0f;
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++) {
            int nx = x + dx, ny = y + dy;
            const ref_hit *o;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h)
                continue;
            o = &c->hits[(size_t)ny * w + nx];
            if (o->hit != me->hit || o->object != me->object || (o->hit && truth_at(c, o) != v))
                return 1;
        }
    return 0;
}

static void test_steps(const vdsm_case *c, const capture *all)
{
    capture b;
    char name[256];
    long n = 0, edge = 0;
    int x, y, w = c->r->width, h = c->r->height;
    name_of(c, "steps", name, sizeof name);
    if (!render(c, STIN_DEBUG_VDSM_NO_EP, &b, "steps"))
        return;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            if (gl_px(&all->img, x, y)[AOV_VIS_R] != gl_px(&b.img, x, y)[AOV_VIS_R]) {
                if (on_shadow_edge(c, x, y))
                    edge++;
                else
                    n++;
            }
    report(c->r, n == 0 && edge <= VIS_EDGE_BUDGET * w * h ? "PASS" : "FAIL", name,
           "without EP the visibility differs on %ld of %d pixels away from a reference shadow "
           "edge (must be 0) and on %ld on one (at most %.2f%%: which triangle a grazing "
           "segment hits first is rounding)", n, w * h, edge, 100.0 * VIS_EDGE_BUDGET);
    capture_free(&b);
}

void vdsm_tests(run *r, stin_tier tier, const char *path)
{
    scene s;
    reference *ref = NULL;
    ref_hit *hits = NULL;
    float *refimg = NULL;
    capture cap;
    vdsm_case c;
    char err[512], scene_name[128];
    if (tier != STIN_TIER_GL4)
        return;
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    if (!scene_load(path, &s, err, sizeof err))
        return; /* test_scene reported it */
    memset(&c, 0, sizeof c);
    c.r = r;
    c.s = &s;
    c.scene_name = scene_name;
    if (!s.light_count)
        goto done;
    ref = reference_create(&s, err, sizeof err);
    hits = malloc(sizeof *hits * (size_t)r->width * r->height);
    refimg = malloc(sizeof(float) * REFERENCE_CHANNELS * (size_t)r->width * r->height);
    if (!ref || !hits || !refimg || !reference_primary(ref, r->width, r->height, hits) ||
        !reference_render_ex(&s, ref, r->width, r->height, 0, REFERENCE_RENDER_SHADOWED, refimg)) {
        char name[256];
        name_of(&c, "vis", name, sizeof name);
        report(r, "FAIL", name, "reference: %s", ref ? "render failed" : err);
        goto done;
    }
    c.refr = ref;
    c.hits = hits;
    c.ref = refimg;
    if (!render(&c, 0, &cap, "vis"))
        goto done;
    test_clean(&c, &cap);
    test_no_grow(&c, test_vis(&c, &cap));
    test_steps(&c, &cap);
    capture_free(&cap);
done:
    free(hits);
    free(refimg);
    if (ref)
        reference_destroy(ref);
    scene_free(&s);
}
