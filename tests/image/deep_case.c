/* SPDX-License-Identifier: MIT */
/* What the deep and coloured image tests share (deep_case.h). */
#include "deep_case.h"

#include "aov.h"
#include "light_reach.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const float *deep_ref_px(const deep_case *c, int x, int y)
{
    return c->ref + ((size_t)y * c->r->width + x) * REFERENCE_CHANNELS;
}

/* The capture's pixel (x, y from the bottom, as the reference's rows). */
const float *deep_gl_px(const deep_case *c, const capture *cap, int x, int y)
{
    return cap->img.pixels + ((size_t)(c->r->height - 1 - y) * c->r->width + x) * AOV_CHANNELS;
}

/* 1 where T or the object hit changes within band pixels of (x, y). */
static int deep_near_t_edge(const deep_case *c, int x, int y)
{
    int w = c->r->width, h = c->r->height, dx, dy, k;
    const float *t = deep_ref_px(c, x, y) + REFERENCE_CH_T_R;
    for (dy = -c->band; dy <= c->band; dy++)
        for (dx = -c->band; dx <= c->band; dx++) {
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h)
                continue;
            if (c->hits[(size_t)ny * w + nx].object != c->hits[(size_t)y * w + x].object)
                return 1;
            for (k = 0; k < 3; k++)
                if (fabsf(deep_ref_px(c, nx, ny)[REFERENCE_CH_T_R + k] - t[k]) > T_TOLERANCE)
                    return 1;
        }
    return 0;
}

int deep_is_transparent(const deep_case *c, const ref_hit *hit)
{
    return hit->hit && c->s->materials[c->s->objects[hit->object].material].color[3] < 1.0f;
}

/* A pixel the comparison counts: covered, the light reaches it, away from
 * transmittance edges, and the render's surface is the reference's. */
int deep_comparable(const deep_case *c, const capture *cap, int x, int y)
{
    const ref_hit *hit = &c->hits[(size_t)y * c->r->width + x];
    const float *g = deep_gl_px(c, cap, x, y), *ref = deep_ref_px(c, x, y);
    double d2 = 0;
    int k;
    if (!hit->hit || !(g[AOV_Z] > 0.0f) || !light_reaches(c->s, hit) ||
        deep_near_t_edge(c, x, y) || (c->skip_transparent && deep_is_transparent(c, hit)))
        return 0;
    for (k = 0; k < 3; k++)
        d2 += (g[AOV_PX + k] - ref[REFERENCE_CH_PX + k]) * (g[AOV_PX + k] - ref[REFERENCE_CH_PX + k]);
    return sqrt(d2) <= 1e-3 * ref[REFERENCE_CH_Z] + 1e-3;
}

int deep_within(const float *g, const float *expect, double tol)
{
    int k;
    for (k = 0; k < 3; k++)
        if (fabs(g[AOV_VIS_R + k] - expect[k]) > tol)
            return 0;
    return 1;
}


void deep_test_transmittance(const deep_case *c, const capture *cap, const char *name)
{
    int w = c->r->width, h = c->r->height, x, y;
    long compared = 0, match = 0, partial = 0;
    double worst = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const float *t = deep_ref_px(c, x, y) + REFERENCE_CH_T_R;
            const float *g = deep_gl_px(c, cap, x, y);
            int k;
            if (!deep_comparable(c, cap, x, y))
                continue;
            compared++;
            match += deep_within(g, t, T_TOLERANCE);
            partial += t[0] > 0.0f && t[0] < 1.0f;
            for (k = 0; k < 3; k++)
                if (fabs(g[AOV_VIS_R + k] - t[k]) > worst)
                    worst = fabs(g[AOV_VIS_R + k] - t[k]);
        }
    report(c->r,
           compared && match >= T_MIN_MATCH * compared && partial >= MIN_PARTIAL ? "PASS" : "FAIL",
           name,
           "%ux%u a face: transmittance within 2/255 of the reference on %.3f%% of %ld pixels the "
           "light reaches, %d px from T edges (need 99.5%%); %ld in partial shadow (need %d); "
           "largest difference %.4f", c->map_size, c->map_size,
           compared ? 100.0 * match / compared : 0.0, compared, c->band, partial, MIN_PARTIAL,
           worst);
}

/* The seed's classes of T this scene has: white panes or the colour cases. */
void deep_test_values(const deep_case *c, const capture *cap, const char *name)
{
    static const float classes[6][3] = {{0.5f, 0.5f, 0.5f},     {0.25f, 0.25f, 0.25f},
                                        {0.125f, 0.125f, 0.125f}, {0.5f, 0.25f, 0.25f},
                                        {0.25f, 0.0625f, 0.0625f}, {0.125f, 0.125f, 0.0625f}};
    int first = strstr(c->scene_name, "colour") ? 3 : 0, k, x, y, ok = 1;
    long n[6] = {0}, good[6] = {0};
    char detail[512];
    size_t used = 0;
    for (y = 0; y < c->r->height; y++)
        for (x = 0; x < c->r->width; x++) {
            const float *t = deep_ref_px(c, x, y) + REFERENCE_CH_T_R;
            if (!deep_comparable(c, cap, x, y))
                continue;
            for (k = first; k < first + 3; k++)
                if (fabsf(t[0] - classes[k][0]) < 1e-5f && fabsf(t[1] - classes[k][1]) < 1e-5f &&
                    fabsf(t[2] - classes[k][2]) < 1e-5f) {
                    n[k]++;
                    good[k] += deep_within(deep_gl_px(c, cap, x, y), classes[k], T_TOLERANCE);
                }
        }
    detail[0] = '\0';
    for (k = first; k < first + 3; k++) {
        ok &= n[k] >= MIN_CLASS && good[k] >= T_MIN_MATCH * n[k];
        used += (size_t)snprintf(detail + used, sizeof detail - used, "%s(%g,%g,%g): %ld of %ld",
                                 k > first ? ", " : "", classes[k][0], classes[k][1],
                                 classes[k][2], good[k], n[k]);
    }
    report(c->r, ok ? "PASS" : "FAIL", name,
           "pixels of each of the seed's values within 2/255 (need >= %d a value, 99.5%%): %s",
           MIN_CLASS, detail);
}

void deep_own_layer_counts(const deep_case *c, const capture *cap, long *n, long *good)
{
    int x, y;
    static const float one[3] = {1, 1, 1};
    *n = *good = 0;
    for (y = 0; y < c->r->height; y++)
        for (x = 0; x < c->r->width; x++) {
            const float *t = deep_ref_px(c, x, y) + REFERENCE_CH_T_R;
            if (!deep_is_transparent(c, &c->hits[(size_t)y * c->r->width + x]) || t[0] < 1.0f ||
                t[1] < 1.0f || t[2] < 1.0f || !deep_comparable(c, cap, x, y))
                continue;
            (*n)++;
            *good += deep_within(deep_gl_px(c, cap, x, y), one, T_TOLERANCE);
        }
}

void deep_test_own_layer(const deep_case *c, const capture *cap, const char *name)
{
    long n, good;
    deep_own_layer_counts(c, cap, &n, &good);
    report(c->r, n >= MIN_PARTIAL && good >= T_MIN_MATCH * n ? "PASS" : "FAIL", name,
           "%ld of %ld pane pixels the reference sees unshadowed are within 2/255 of 1 (need "
           ">= %d pixels, 99.5%%)", good, n, MIN_PARTIAL);
}

/* Near a seam of a point light's cube: the direction from the light has
 * its two largest components within 3% of each other, where a lookup that
 * strays into the neighbouring face would show (a band wider than the
 * lookup's push, so a stray strip is a sizeable share of it). */
static int near_seam(const float *light, const float *p)
{
    float a[3], hi, mid;
    int k;
    for (k = 0; k < 3; k++)
        a[k] = fabsf(p[k] - light[k]);
    hi = fmaxf(a[0], fmaxf(a[1], a[2]));
    mid = a[0] == hi ? fmaxf(a[1], a[2]) : a[1] == hi ? fmaxf(a[0], a[2]) : fmaxf(a[0], a[1]);
    return hi > 0.0f && mid >= 0.97f * hi;
}

void deep_test_seams(const deep_case *c, const capture *cap, const char *name)
{
    const float *light = c->s->lights[0].position;
    int w = c->r->width, h = c->r->height, x, y;
    long n = 0, good = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const ref_hit *hit = &c->hits[(size_t)y * w + x];
            if (!hit->hit || !near_seam(light, hit->P) || !deep_comparable(c, cap, x, y))
                continue;
            n++;
            good += deep_within(deep_gl_px(c, cap, x, y), deep_ref_px(c, x, y) + REFERENCE_CH_T_R,
                                T_TOLERANCE);
        }
    report(c->r, n >= MIN_PARTIAL && good >= T_MIN_MATCH * n ? "PASS" : "FAIL", name,
           "transmittance within 2/255 of the reference on %ld of %ld pixels beside a seam of the "
           "light's cube faces (need >= %d pixels, 99.5%%)", good, n, MIN_PARTIAL);
}

/* Below the technique's tier: a SKIP line saying why (skip_why), then
 * forcing it must be refused with `expect` in the message. */
void deep_refusal(run *r, stin_tier tier, const char *scene_name, const scene *s,
                  stin_technique t, const char *skip_why, const char *expect)
{
    capture cap;
    capture_options o;
    char err[512], name[256];
    int refused;
    snprintf(name, sizeof name, "%s/%s/%s", stin_tier_name(tier), scene_name,
             stin_technique_name(t));
    report(r, "SKIP", name, "tier %s %s", stin_tier_name(tier), skip_why);
    memset(&o, 0, sizeof o);
    o.tier = tier;
    o.translucent = t;
    refused = !capture_render(r->plat, r->profile, s, &o, &cap, err, sizeof err);
    snprintf(name, sizeof name, "%s/%s/%s-forced", stin_tier_name(tier), scene_name,
             stin_technique_name(t));
    report(r, refused && strstr(err, expect) ? "PASS" : "FAIL", name, "forcing %s at tier %s: %s",
           stin_technique_name(t), stin_tier_name(tier),
           refused ? err : "created (must be refused)");
    if (!refused)
        capture_free(&cap);
}

/* Visibility and beauty identical, pixel for pixel; returns the count that differ. */
long deep_differing(const capture *a, const capture *b)
{
    size_t i, n = (size_t)a->img.width * a->img.height;
    long d = 0;
    int k;
    static const int ch[] = {AOV_R, AOV_G, AOV_B, AOV_VIS_R, AOV_VIS_G, AOV_VIS_B};
    for (i = 0; i < n; i++)
        for (k = 0; k < 6; k++)
            if (a->img.pixels[i * AOV_CHANNELS + ch[k]] != b->img.pixels[i * AOV_CHANNELS + ch[k]]) {
                d++;
                break;
            }
    return d;
}

int deep_render(const deep_case *c, const scene *s, const capture_options *o, capture *cap,
                  const char *name)
{
    char err[512];
    if (!capture_render(c->r->plat, c->r->profile, s, o, cap, err, sizeof err)) {
        report(c->r, "FAIL", name, "%s", err);
        return 0;
    }
    if (cap->choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].technique != c->tech) {
        report(c->r, "FAIL", name, "%s fell back: %s", c->tag,
               cap->choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].reason);
        capture_free(cap);
        return 0;
    }
    return 1;
}

void deep_case_init(deep_case *c, run *r, stin_tier tier, const scene *s, const char *scene_name,
                    stin_technique t, int stack)
{
    memset(c, 0, sizeof *c);
    c->r = r;
    c->s = s;
    c->scene_name = scene_name;
    c->tier = tier;
    c->tech = t;
    c->tag = t == STIN_TECH_TRANSLUCENT_DEEP ? "deep" : "coloured";
    c->map_size = stack ? 2048u : 512u;
    c->band = stack ? 1 : 3;
}

void deep_options(const deep_case *c, capture_options *o)
{
    memset(o, 0, sizeof *o);
    o->tier = c->tier;
    o->translucent = c->tech;
    o->deep_map_size = c->map_size;
    o->deep_layers = c->layers;
}

/* The reference's AOVs (transmittance among them) and primary hits of the
 * case's scene; 0 with a message in err. Free with free_reference. */
int deep_make_reference(deep_case *c, reference **ref, char *err, size_t err_size)
{
    size_t n = (size_t)c->r->width * c->r->height;
    ref_hit *hits = malloc(sizeof *hits * n);
    float *img = malloc(sizeof(float) * REFERENCE_CHANNELS * n);
    c->hits = hits;
    c->ref = img;
    *ref = reference_create(c->s, err, err_size);
    if (*ref && hits && img && reference_primary(*ref, c->r->width, c->r->height, hits) &&
        reference_render(c->s, *ref, c->r->width, c->r->height, 0, img))
        return 1;
    if (*ref)
        snprintf(err, err_size, "render failed");
    return 0;
}

void deep_free_reference(deep_case *c, reference *ref)
{
    free((void *)c->hits);
    free((void *)c->ref);
    if (ref)
        reference_destroy(ref);
}

void deep_test_shadows_off(const deep_case *c, const char *name, stin_technique expect)
{
    capture cap;
    capture_options o;
    char err[512];
    const stin_choice *t;
    deep_options(c, &o);
    o.shadows = STIN_TECH_SHADOWS_OFF;
    if (!capture_render(c->r->plat, c->r->profile, c->s, &o, &cap, err, sizeof err)) {
        report(c->r, "FAIL", name, "%s", err);
        return;
    }
    t = &cap.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS];
    report(c->r,
           t->technique == expect && t->fell_back && strstr(t->reason, "shadows are off") &&
                   !cap.log_errors && !cap.stats.translucent.deep_layers
               ? "PASS"
               : "FAIL",
           name, "forced %s with shadows off: %s (%s), %u layers peeled, %u errors logged",
           c->tag, stin_technique_name(t->technique), t->reason, cap.stats.translucent.deep_layers,
           cap.log_errors);
    capture_free(&cap);
}
