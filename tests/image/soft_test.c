/* SPDX-License-Identifier: MIT */
/*
 * Soft shadows against the physics, on scenes whose light 0 is an area light
 * (radius > 0, point or spot: shadow-soft), under every shadow technique of
 * the tier: light 0's visibility against reference_light_visibility (the
 * unblocked fraction of the light's solid angle, integrated over
 * REFERENCE_AREA_SAMPLES directions) over the true penumbra, the pixels
 * whose reference lies in (0.02, 0.98), that light 0 can reach, on opaque
 * surfaces, at least one pixel from an object's edge or a jump of the
 * reference by more than 0.5 (a contact shadow), where stin's P matches.
 * There it reports mean |vis - truth| and the distinct values vis takes
 * (quantised to 1/255). Goal: mean <= 0.03 (six 8-bit steps: the hard
 * shadows measure 0.22-0.23 and 8 samples 0.079) and >= 32 levels (no
 * visible bands: the 8 samples give 7-9). A technique that honours the
 * radius must meet it (PASS/FAIL); one that does not yet reports SKIP with
 * its numbers and the reason, never PASS.
 * soft-beauty-T: the beauty agrees with that visibility where light 0
 * reaches a surface stin drew as the reference did: beauty = ambient +
 * (lit - ambient) * vis per channel, from two shadowless renders (light 0
 * at intensity 1e-9, and as given). Mean at most 1/255 and 99.9% of the
 * pixels within 3/255 (the three 8-bit images' roundings and the
 * visibility's own). A lit pass a sample at intensity / n rounds each pass
 * to 8 bits, which adds up in bands up to n / 2 steps: this fails there.
 */
#include "aov.h"
#include "capture.h"
#include "image_test.h"
#include "light_reach.h"
#include "reference.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SOFT_MAX_MEAN 0.03
#define SOFT_MIN_LEVELS 32
#define PENUMBRA_LOW 0.02f
#define PENUMBRA_HIGH 0.98f
#define MIN_PENUMBRA_PIXELS 500 /* shadow-soft has ~2,700: fewer means a broken scene */
#define BEAUTY_MAX_MEAN (1.0 / 255.0)
#define BEAUTY_STEP (3.0 / 255.0)
#define BEAUTY_MIN_WITHIN 0.999

typedef struct soft_case {
    run *r;
    const scene *s;
    stin_tier tier;
    const char *scene_name;
    const ref_hit *hits;
    const float *ref; /* reference_render_ex AOVs, rows bottom to top */
    const image *ambient, *lit; /* shadowless beauties: light 0 off, and on (NULL: none) */
} soft_case;

/* Why a technique draws an area light's penumbra without its radius, or
 * NULL for one that honours it (and must meet the goal). */
static const char *not_soft_yet(stin_technique t)
{
    switch (t) {
    case STIN_TECH_SHADOWS_VOLUME:
        return NULL; /* soft_samples points spread over the light's ball */
    case STIN_TECH_SHADOWS_VDSM:
        return NULL;
    case STIN_TECH_SHADOWS_MAP_PCF:
        return NULL;
    default:
        return "shadow maps treat area lights as points";
    }
}

static int opaque(const scene *s, const ref_hit *h)
{
    return s->materials[s->objects[h->object].material].color[3] >= 1.0f;
}

/* Pixel (x, y) (from the bottom) is an opaque surface light 0 reaches,
 * away from edges, where stin drew the same surface point. */
static int same_surface(const soft_case *c, const float *g, int x, int y)
{
    int w = c->r->width, h = c->r->height, k;
    const ref_hit *hit = &c->hits[(size_t)y * w + x];
    const float *ref = c->ref + ((size_t)y * w + x) * REFERENCE_CHANNELS;
    double d2 = 0;
    if (!hit->hit || !opaque(c->s, hit) || !light_reaches(c->s, hit) ||
        near_shadow_edge(c->hits, c->ref, w, h, x, y, 1) || !(g[AOV_Z] > 0.0f))
        return 0;
    for (k = 0; k < 3; k++)
        d2 += (g[AOV_PX + k] - ref[REFERENCE_CH_PX + k]) * (g[AOV_PX + k] - ref[REFERENCE_CH_PX + k]);
    return sqrt(d2) <= 1e-3 * ref[REFERENCE_CH_Z] + 1e-3;
}

/* ... and it belongs to the true penumbra. */
static int in_penumbra(const soft_case *c, const float *g, int x, int y)
{
    float v = c->ref[((size_t)y * c->r->width + x) * REFERENCE_CHANNELS + REFERENCE_CH_VIS_R];
    return v > PENUMBRA_LOW && v < PENUMBRA_HIGH && same_surface(c, g, x, y);
}

/* soft-beauty-T (above). */
static void beauty_agrees(const soft_case *c, stin_technique t, const capture *cap)
{
    int w = c->r->width, h = c->r->height, x, y, k;
    long n = 0, within = 0;
    double sum = 0, worst = 0;
    char name[256];
    snprintf(name, sizeof name, "%s/%s/soft-beauty-%s", stin_tier_name(c->tier), c->scene_name,
             stin_technique_name(t));
    if (!c->ambient || !c->lit) {
        report(c->r, "FAIL", name, "the shadowless renders failed");
        return;
    }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t i = ((size_t)(h - 1 - y) * w + x) * AOV_CHANNELS;
            const float *g = cap->img.pixels + i;
            double d = 0;
            if (!same_surface(c, g, x, y))
                continue;
            for (k = 0; k < 3; k++) {
                double a = c->ambient->pixels[i + AOV_R + k], l = c->lit->pixels[i + AOV_R + k];
                double e = fabs(g[AOV_R + k] - (a + (l - a) * g[AOV_VIS_R]));
                d = e > d ? e : d;
            }
            n++;
            sum += d;
            within += d <= BEAUTY_STEP;
            worst = d > worst ? d : worst;
        }
    report(c->r,
           n >= MIN_PENUMBRA_PIXELS && sum / n <= BEAUTY_MAX_MEAN &&
                   within >= BEAUTY_MIN_WITHIN * n
               ? "PASS"
               : "FAIL",
           name, "beauty against ambient + lit * vis on %ld pixels: mean %.4f (at most %.4f), "
           "%.3f%% within %.4f (need %.1f%%), max %.4f", n, n ? sum / n : 0.0, BEAUTY_MAX_MEAN,
           n ? 100.0 * within / n : 0.0, BEAUTY_STEP, 100.0 * BEAUTY_MIN_WITHIN, worst);
}

static void one_technique(const soft_case *c, stin_technique t)
{
    capture cap;
    capture_options o;
    char name[256], err[512];
    int w = c->r->width, h = c->r->height, x, y, levels = 0;
    unsigned char seen[256];
    long n = 0;
    double sum = 0;
    const char *why = not_soft_yet(t);
    snprintf(name, sizeof name, "%s/%s/soft-%s", stin_tier_name(c->tier), c->scene_name,
             stin_technique_name(t));
    memset(&o, 0, sizeof o);
    o.tier = c->tier;
    o.shadows = t;
    if (!capture_render(c->r->plat, c->r->profile, c->s, &o, &cap, err, sizeof err)) {
        /* a technique the profile lacks a capability for is refused by name */
        report(c->r, strstr(err, " needs ") ? "SKIP" : "FAIL", name, "%s", err);
        return;
    }
    if (cap.choice[STIN_FEATURE_SHADOWS].technique != t) {
        report(c->r, "SKIP", name, "%s does not run here: %s", stin_technique_name(t),
               cap.choice[STIN_FEATURE_SHADOWS].reason);
        capture_free(&cap);
        return;
    }
    memset(seen, 0, sizeof seen);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const float *g = cap.img.pixels + ((size_t)(h - 1 - y) * w + x) * AOV_CHANNELS;
            double v = g[AOV_VIS_R];
            int q;
            if (!in_penumbra(c, g, x, y))
                continue;
            n++;
            sum += fabs(v - c->ref[((size_t)y * w + x) * REFERENCE_CHANNELS + REFERENCE_CH_VIS_R]);
            q = (int)floor((v < 0 ? 0 : v > 1 ? 1 : v) * 255.0 + 0.5);
            levels += !seen[q];
            seen[q] = 1;
        }
    if (n < MIN_PENUMBRA_PIXELS) {
        report(c->r, "FAIL", name, "only %ld penumbra pixels to compare (at least %d)", n,
               MIN_PENUMBRA_PIXELS);
    } else if (why) {
        report(c->r, "SKIP", name, "%s: area lights not yet soft (mean |vis - truth| %.4f, %d "
               "levels over %ld penumbra pixels; goal <= %.2f and >= %d): %s (%s)",
               stin_technique_name(t), sum / n, levels, n, SOFT_MAX_MEAN, SOFT_MIN_LEVELS, why,
               strstr(cap.fallbacks, "area light") ? "logged" : "not logged");
    } else {
        report(c->r, sum / n <= SOFT_MAX_MEAN && levels >= SOFT_MIN_LEVELS ? "PASS" : "FAIL", name,
               "mean |vis - truth| %.4f over %ld penumbra pixels (at most %.2f), %d distinct "
               "levels (at least %d)", sum / n, n, SOFT_MAX_MEAN, levels, SOFT_MIN_LEVELS);
        beauty_agrees(c, t, &cap);
    }
    capture_free(&cap);
}

/* The reference of c's scene: primary hits and the shadowed AOVs. 1, or 0
 * with what failed in err. */
static int reference_of(soft_case *c, reference **ref, ref_hit **hits, float **img, char *err,
                        size_t err_size)
{
    size_t pixels = (size_t)c->r->width * c->r->height;
    if (!(*ref = reference_create(c->s, err, err_size)))
        return 0;
    *hits = malloc(sizeof **hits * pixels);
    *img = malloc(sizeof **img * REFERENCE_CHANNELS * pixels);
    snprintf(err, err_size, "out of memory or an Embree error");
    if (!*hits || !*img || !reference_primary(*ref, c->r->width, c->r->height, *hits))
        return 0;
    c->hits = *hits;
    c->ref = *img;
    return reference_render_ex(c->s, *ref, c->r->width, c->r->height, 0, REFERENCE_RENDER_SHADOWED,
                               *img);
}

/* The scene without shadows, light 0 off and on, into c->ambient, c->lit
 * (left NULL where a render fails; beauty_agrees reports it). */
static void shadowless(soft_case *c, capture *ambient, capture *lit)
{
    capture_options o;
    scene *s = (scene *)c->s;
    float intensity = s->lights[0].intensity;
    char err[512];
    memset(&o, 0, sizeof o);
    o.tier = c->tier;
    o.shadows = STIN_TECH_SHADOWS_OFF;
    s->lights[0].intensity = 1e-9f; /* 0 would read as "the default" */
    if (capture_render(c->r->plat, c->r->profile, s, &o, ambient, err, sizeof err))
        c->ambient = &ambient->img;
    s->lights[0].intensity = intensity;
    if (capture_render(c->r->plat, c->r->profile, s, &o, lit, err, sizeof err))
        c->lit = &lit->img;
}

void soft_tests(run *r, stin_tier tier, const char *path)
{
    /* the shadow techniques each tier offers (GL1's maps are fixed-function,
     * the GLSL tiers' PCF) */
    static const stin_technique techniques[3][3] = {
        {STIN_TECH_SHADOWS_VOLUME, STIN_TECH_SHADOWS_MAP_DEPTH, STIN_TECH_SHADOWS_MAP_COMBINE},
        {STIN_TECH_SHADOWS_VOLUME, STIN_TECH_SHADOWS_MAP_PCF, STIN_TECH_NONE},
        {STIN_TECH_SHADOWS_VDSM, STIN_TECH_SHADOWS_VOLUME, STIN_TECH_SHADOWS_MAP_PCF}};
    const stin_technique *list = techniques[tier == STIN_TIER_GL1 ? 0 : tier == STIN_TIER_GL2 ? 1 : 2];
    scene s;
    reference *ref = NULL;
    ref_hit *hits = NULL;
    float *img = NULL;
    soft_case c;
    capture ambient, lit;
    char err[512], scene_name[128], name[256];
    int i;
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    if (!scene_load(path, &s, err, sizeof err))
        return; /* test_scene reported it */
    c.r = r;
    c.s = &s;
    c.tier = tier;
    c.scene_name = scene_name;
    c.ambient = c.lit = NULL;
    if (s.light_count && s.lights[0].radius > 0.0f && s.lights[0].type != SCENE_LIGHT_DIRECTIONAL) {
        if (reference_of(&c, &ref, &hits, &img, err, sizeof err)) {
            shadowless(&c, &ambient, &lit);
            for (i = 0; i < 3 && list[i] != STIN_TECH_NONE; i++)
                one_technique(&c, list[i]);
            if (c.ambient)
                capture_free(&ambient);
            if (c.lit)
                capture_free(&lit);
        } else {
            snprintf(name, sizeof name, "%s/%s/soft", stin_tier_name(tier), scene_name);
            report(r, "FAIL", name, "reference: %s", err);
        }
    }
    free(hits);
    free(img);
    if (ref)
        reference_destroy(ref);
    scene_free(&s);
}
