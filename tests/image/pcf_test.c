/* SPDX-License-Identifier: MIT */
/*
 * GLSL shadow maps with PCF ("map-pcf", GL2/GL4) against the Embree
 * visibility reference, per map size and kernel: the fraction of pixels the
 * light reaches whose visibility differs (a filtered value is taken as lit
 * at >= 0.5), outside the kernel's penumbra band (pixels whose reference
 * visibility, or the object hit, changes within 1 + r * (2048 / size) / 4
 * pixels, r the kernel radius: at 2048 a texel is about a quarter of a
 * pixel on these scenes). A map that casts nothing must not pass on the lit
 * majority: at least 100 shadowed pixels are compared and at most 2% of
 * them may come out lit.
 * Bound (issue 4): at 2048x2048 at most 1% on the spheres scenes; other sizes
 * are printed as INFO lines, except under a point light (spheres-18k, -76k,
 * -174k), where 512 and 1024 must stay within 0.05% (issue 36, "face
 * seams"): its six faces share one atlas, and a kernel's taps reaching over
 * a face's edge into the next cell read another face's depths; with the
 * shader's clamp to the cell taken out, spheres-18k's 512 and 1024 differ
 * on 0.27-0.83% (2048 on 0.13%).
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

typedef struct pcf_case {
    run *r;
    const scene *s;
    const char *scene_name;
    const float *ref;
    const ref_hit *hits;
    int kernel; /* of the render being judged */
} pcf_case;


/* Also counts the shadowed pixels compared and how many of them came out
 * lit: a map that casts nothing must not pass on the lit majority. */
static double mismatch(const pcf_case *c, const capture *cap, int band, long *compared_out,
                       long *shadowed_out, long *shadowed_wrong_out)
{
    int w = c->r->width, h = c->r->height, x, y, k;
    long compared = 0, differ = 0, shadowed = 0, shadowed_wrong = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const ref_hit *hit = &c->hits[(size_t)y * w + x];
            const float *ref = c->ref + ((size_t)y * w + x) * REFERENCE_CHANNELS;
            const float *g = cap->img.pixels + ((size_t)(h - 1 - y) * w + x) * AOV_CHANNELS;
            double d2 = 0;
            if (!hit->hit || !(g[AOV_Z] > 0.0f) || !light_reaches(c->s, hit) || near_shadow_edge(c->hits, c->ref, w, h, x, y, band))
                continue;
            for (k = 0; k < 3; k++)
                d2 += (g[AOV_PX + k] - ref[REFERENCE_CH_PX + k]) *
                      (g[AOV_PX + k] - ref[REFERENCE_CH_PX + k]);
            if (sqrt(d2) > 1e-3 * ref[REFERENCE_CH_Z] + 1e-3)
                continue;
            compared++;
            if ((g[AOV_VIS_R] >= 0.5f) != (ref[REFERENCE_CH_VIS_R] >= 0.5f))
                differ++;
            if (ref[REFERENCE_CH_VIS_R] < 0.5f) {
                shadowed++;
                if (g[AOV_VIS_R] >= 0.5f)
                    shadowed_wrong++;
            }
        }
    *compared_out = compared;
    *shadowed_out = shadowed;
    *shadowed_wrong_out = shadowed_wrong;
    return compared ? (double)differ / compared : 1.0;
}

/* The verdict of one map-pcf render (named as one() names it). */
static void judge(pcf_case *c, const char *name, uint32_t size, const capture *cap)
{
    long compared, shadowed, shadowed_wrong;
    /* The kernel's penumbra in pixels: on these scenes a 2048 map's texel is
     * about a quarter of a pixel where the shadows fall, so r texels stay
     * within the one pixel every edge gets; smaller maps widen it. */
    double f = mismatch(c, cap, 1 + (c->kernel / 2) * (int)(2048u / size) / 4, &compared,
                        &shadowed, &shadowed_wrong);
    if (cap->counters.gl_violations || cap->log_errors)
        report(c->r, "FAIL", name, "%u profile violations, %u error logs (last: %s)",
               cap->counters.gl_violations, cap->log_errors, cap->last_error);
    else if (cap->choice[STIN_FEATURE_SHADOWS].technique != STIN_TECH_SHADOWS_MAP_PCF)
        report(c->r, "FAIL", name, "not drawn by map-pcf (%s)",
               stin_technique_name(cap->choice[STIN_FEATURE_SHADOWS].technique));
    else if (size != 2048 && c->s->lights[0].type == SCENE_LIGHT_POINT)
        report(c->r, f <= 0.0005 ? "PASS" : "FAIL", name,
               "face seams: visibility differs on %.3f%% of %ld reachable pixels outside the "
               "kernel's penumbra band (at most 0.05%%: no tap reads a neighbouring face)",
               100.0 * f, compared);
    else if (size != 2048 || !strstr(c->scene_name, "spheres"))
        printf("INFO %s/%s/%s: visibility differs on %.3f%% of %ld reachable pixels outside the "
               "penumbra band\n", c->r->platform_name, c->r->profile_name, name, 100.0 * f,
               compared);
    else
        report(c->r,
               f <= 0.01 && shadowed >= 100 && shadowed_wrong <= shadowed / 50 ? "PASS" : "FAIL",
               name,
               "visibility differs on %.3f%% of %ld reachable pixels outside the kernel's "
               "penumbra band (at most 1%%); of the %ld shadowed ones (at least 100) %ld came out "
               "lit (at most 2%%)", 100.0 * f, compared, shadowed, shadowed_wrong);
}

/* extra_mask: capabilities hidden on top of the profile's (the row's name
 * says which: "-no-compare" for SHADOW, "-packed" for depth textures too);
 * debug: STIN_DEBUG_* flags ("-no-derivatives"); 0 for the plain rows. */
static void one(pcf_case *c, stin_tier tier, uint32_t size, int kernel, uint64_t extra_mask,
                uint64_t debug, const char *suffix)
{
    capture cap;
    capture_options o;
    scene copy = *c->s;
    scene_light lights[8];
    char name[256], err[512];
    int i;
    for (i = 0; i < copy.light_count && i < 8; i++) {
        lights[i] = copy.lights[i];
        lights[i].pcf_kernel = kernel;
    }
    copy.lights = lights;
    memset(&o, 0, sizeof o);
    o.tier = tier;
    o.shadows = STIN_TECH_SHADOWS_MAP_PCF;
    o.shadow_map_size = size;
    o.extra_mask = extra_mask;
    o.debug_flags = debug;
    snprintf(name, sizeof name, "%s/%s/map-pcf-%u-k%d%s", stin_tier_name(tier), c->scene_name,
             size, kernel, suffix);
    if (!capture_render(c->r->plat, c->r->profile, &copy, &o, &cap, err, sizeof err)) {
        report(c->r, "FAIL", name, "%s", err);
        return;
    }
    c->kernel = kernel;
    judge(c, name, size, &cap);
    capture_free(&cap);
}

void pcf_tests(run *r, stin_tier tier, const char *path)
{
    static const uint32_t sizes[] = {512, 1024, 2048};
    static const int kernels[] = {1, 3, 5};
    scene s;
    reference *ref = NULL;
    ref_hit *hits = NULL;
    float *refimg = NULL;
    pcf_case c;
    capture probe;
    capture_options o;
    char err[512], scene_name[128], name[256];
    size_t i, k;
    if (tier == STIN_TIER_GL1)
        return; /* GLSL only */
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    if (!scene_load(path, &s, err, sizeof err))
        return;
    if (!s.light_count || !strstr(scene_name, "spheres")) {
        scene_free(&s); /* the spheres scenes carry the bound; others would only repeat it */
        return;
    }
    memset(&o, 0, sizeof o);
    o.tier = tier;
    o.shadows = STIN_TECH_SHADOWS_OFF;
    snprintf(name, sizeof name, "%s/%s/map-pcf", stin_tier_name(tier), scene_name);
    ref = reference_create(&s, err, sizeof err);
    hits = malloc(sizeof *hits * (size_t)r->width * r->height);
    refimg = malloc(sizeof(float) * REFERENCE_CHANNELS * (size_t)r->width * r->height);
    if (!ref || !hits || !refimg || !reference_primary(ref, r->width, r->height, hits) ||
        !reference_render_ex(&s, ref, r->width, r->height, 0, REFERENCE_RENDER_SHADOWED, refimg) ||
        !capture_render(r->plat, r->profile, &s, &o, &probe, err, sizeof err)) {
        report(r, "FAIL", name, "set-up: %s", err);
        goto done;
    }
    {
        /* without shadow compare or depth textures the maps are compared in
         * the shader or packed into colour (bare ES 2.0) */
        uint64_t need = STIN_CAP_BIT(STIN_CAP_FBO);
        if ((probe.caps_present & need) != need) {
            report(r, "SKIP", name, "the profile has no FBOs");
            capture_free(&probe);
            goto done;
        }
    }
    capture_free(&probe);
    c.r = r;
    c.s = &s;
    c.scene_name = scene_name;
    c.ref = refimg;
    c.hits = hits;
    for (i = 0; i < sizeof sizes / sizeof sizes[0]; i++)
        for (k = 0; k < sizeof kernels / sizeof kernels[0]; k++)
            one(&c, tier, sizes[i], kernels[k], 0, 0, "");
    /* OpenGL ES 2.0's maps: depth textures without shadow compare, the
     * lit programs comparing (pcf_tap_depth.glsl), and on bare ES 2.0 no
     * depth textures at all: the depth packed into RGBA8 maps; held to the
     * 2048 rows' bound, on one scene and one tier each of gl21 (GL2) and
     * gl33-core (GL4), where the programs differ. Bare ES 2.0's lit
     * programs also lack derivatives (the receiver plane and the geometric
     * normal from the interpolated normal): that row on gl21, which runs
     * them */
    if (!strcmp(scene_name, "spheres-18k-spot") &&
        ((tier == STIN_TIER_GL2 && !strcmp(r->profile_name, "gl21")) ||
         (tier == STIN_TIER_GL4 && !strcmp(r->profile_name, "gl33-core"))))
    {
        uint64_t depth = STIN_CAP_BIT(STIN_CAP_SHADOW) | STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE);
        int egl = !strcmp(r->platform_name, "egl"); /* the new rows once: make check's time */
        one(&c, tier, 2048, 3, STIN_CAP_BIT(STIN_CAP_SHADOW), 0, "-no-compare");
        if (egl)
            one(&c, tier, 2048, 3, depth, 0, "-packed");
        if (egl && tier == STIN_TIER_GL2)
            one(&c, tier, 2048, 3, depth, STIN_DEBUG_NO_DERIVATIVES, "-packed-no-derivatives");
    }
done:
    free(hits);
    free(refimg);
    if (ref)
        reference_destroy(ref);
    scene_free(&s);
}

void pcf_rows(run *r, stin_tier tier, const char *path, uint32_t size, int kernel,
              const capture *cap)
{
    scene s;
    reference *ref = NULL;
    ref_hit *hits = NULL;
    float *refimg = NULL;
    pcf_case c;
    char err[512], scene_name[128], name[256];
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    snprintf(name, sizeof name, "%s/%s/map-pcf-%u-k%d", stin_tier_name(tier), scene_name, size,
             kernel);
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    ref = reference_create(&s, err, sizeof err);
    hits = malloc(sizeof *hits * (size_t)r->width * r->height);
    refimg = malloc(sizeof(float) * REFERENCE_CHANNELS * (size_t)r->width * r->height);
    if (!s.light_count || !ref || !hits || !refimg ||
        !reference_primary(ref, r->width, r->height, hits) ||
        !reference_render_ex(&s, ref, r->width, r->height, 0, REFERENCE_RENDER_SHADOWED, refimg)) {
        report(r, "FAIL", name, "set-up: %s", s.light_count ? err : "no light");
    } else {
        c.r = r;
        c.s = &s;
        c.scene_name = scene_name;
        c.ref = refimg;
        c.hits = hits;
        c.kernel = kernel;
        judge(&c, name, size, cap);
    }
    free(hits);
    free(refimg);
    if (ref)
        reference_destroy(ref);
    scene_free(&s);
}
