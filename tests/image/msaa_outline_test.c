/* SPDX-License-Identifier: MIT */
/*
 * The deferred outline (src/post/outline.c) into a multisampled target
 * (issue 39): msaa/halo.json (a lit ball over its own shadow) into the 4x
 * target with a half-transparent magenta outline at step 1. The outline
 * is decided once a pixel by design (stin.h, MULTISAMPLED TARGETS: the
 * normals and depth it filters are the single-sampled mask's, its screen
 * pass blends over every sample of the pixel), so what 4x must keep is
 *   - its pixels: those the outline changes (against the same frame
 *     without one) are the single-sampled target's, which outline_test.c
 *     holds to the filter on the reference;
 *   - the frame under it: the 4x reference at the samples
 *     (msaa_ref_build), blended with the outline colour on those pixels,
 *     held by msaa_compare_band. The outline covers both sides of every
 *     silhouette, so the silhouette band is the outline's: its resolve
 *     must be the outline over the antialiased edge, not over a
 *     single-sampled one nor over a part of the samples.
 */
#include "msaa_common.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define OUTLINE_SAMPLES 4
/* msaa_test.c's: a sample in four of the floor's light is 0.085, half
 * that under the outline's alpha. */
#define OUTLINE_TOLERANCE 0.03
/* Of the band's 698 pixels: measured 0 (max 0.006) on GL2 (volumes, the
 * mask the outline reuses) and GL4 (vdsm); single-sampled frames resolved
 * against the same reference put 171 over (max 0.14). */
#define OUTLINE_MAX_BAND_OVER 3
/* Of the other 17,695: measured 0 (max 0.004). */
#define OUTLINE_MAX_OVER_FRACTION 0.01
/* Of the 1,404 outlined pixels, those outlined in one target and not in
 * the other: measured 0 (the same single-sampled mask decides both). */
#define OUTLINE_MAX_SET_DIFFERS 0

static const float outline_color[4] = {1.0f, 0.0f, 1.0f, 0.5f};

typedef struct outline_case {
    stin_tier tier;
    stin_technique shadows;
    int facets; /* the technique's visibility rule (msaa_test.c's) */
} outline_case;

/* The frame without and with the outline into changed (w x h: 1 where the
 * outline drew), the outlined frame into lined: 1, or 0 (reported). */
static int outlined(run *r, const scene *s, const msaa_techniques *t, const char *name,
                    uint8_t *plain, uint8_t *lined, unsigned char *changed)
{
    static const float none[4] = {0, 0, 0, 0};
    char why[512] = "";
    int x, y, got = msaa_render_outlined(r, s, t, 0.0f, none, plain, why, sizeof why);
    if (got > 0)
        got = msaa_render_outlined(r, s, t, 1.0f, outline_color, lined, why, sizeof why);
    if (got <= 0) {
        report(r, got < 0 ? "SKIP" : "FAIL", name, "%s", why);
        return 0;
    }
    for (y = 0; y < s->height; y++)
        for (x = 0; x < s->width; x++) {
            size_t i = 4 * ((size_t)y * r->width + x);
            changed[(size_t)y * s->width + x] = memcmp(plain + i, lined + i, 3) != 0;
        }
    return 1;
}

static void one_case(run *r, const scene *s, const outline_case *oc, const float pos[][2],
                     int n)
{
    static const msaa_bounds bounds = {OUTLINE_TOLERANCE, OUTLINE_MAX_BAND_OVER,
                                       OUTLINE_MAX_OVER_FRACTION};
    msaa_techniques tech = {oc->tier,       oc->shadows,    STIN_TECH_NONE,
                            STIN_TECH_NONE, STIN_TECH_NONE, STIN_TECH_NONE};
    size_t px = (size_t)s->width * s->height, i, frame = (size_t)r->width * r->height * 4;
    uint8_t *plain = malloc(frame), *lined = malloc(frame);
    unsigned char *multi = malloc(px), *single = malloc(px);
    char name[128], why[512] = "", err[512];
    long differ = 0, count = 0;
    msaa_ref m;
    int c, ok;
    msaa_ref_init(&m, s);
    snprintf(name, sizeof name, "%s/msaa-outline-%s", stin_tier_name(oc->tier),
             stin_technique_name(oc->shadows));
    if (!plain || !lined || !multi || !single) {
        report(r, "FAIL", name, "out of memory");
        goto done;
    }
    /* the single-sampled target's outline first, then the 4x frames */
    if (!stin_platform_set_samples(r->plat, 0, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        goto done;
    }
    ok = outlined(r, s, &tech, name, plain, lined, single);
    if (!stin_platform_set_samples(r->plat, n, err, sizeof err)) {
        report(r, "FAIL", name, "back to %d samples: %s", n, err);
        goto done;
    }
    if (!ok || !outlined(r, s, &tech, name, plain, lined, multi))
        goto done;
    if (!msaa_ref_build(s, oc->facets, 0, pos, n, &m, why, sizeof why)) {
        report(r, "FAIL", name, "reference: %s", why);
        goto done;
    }
    for (i = 0; i < px; i++) {
        differ += multi[i] != single[i];
        count += multi[i];
        if (multi[i])
            for (c = 0; c < 3; c++)
                m.colour[3 * i + c] += outline_color[3] * (outline_color[c] - m.colour[3 * i + c]);
    }
    snprintf(why, sizeof why, "%s/pixels", name);
    report(r, differ <= OUTLINE_MAX_SET_DIFFERS && count > 0 ? "PASS" : "FAIL", why,
           "%ld of %ld outline pixels not the single-sampled target's (at most %d)", differ,
           count, OUTLINE_MAX_SET_DIFFERS);
    msaa_report_band(r, name, &m, lined, &bounds);
done:
    msaa_ref_free(&m);
    free(plain);
    free(lined);
    free(multi);
    free(single);
}

/* From shadow-overlap: GL4 (vdsm) on gl45-core, GL2 (volumes through
 * the mask the outline reuses) on gl21; the GL1 tier has no outline. */
void msaa_outline_tests(run *r, stin_tier tier, const char *path)
{
    static const outline_case gl4 = {STIN_TIER_GL4, STIN_TECH_SHADOWS_VDSM,
                                     REFERENCE_FACETS_NONE},
                              gl2 = {STIN_TIER_GL2, STIN_TECH_SHADOWS_VOLUME,
                                     REFERENCE_FACETS_OPEN};
    float pos[MSAA_MAX_SAMPLES][2];
    char name[64];
    scene s;
    int n;
    if (tier == STIN_TIER_GL1 || strcmp(scene_base_name(path), "shadow-overlap") ||
        strcmp(r->profile_name, tier == STIN_TIER_GL4 ? "gl45-core" : "gl21"))
        return;
    snprintf(name, sizeof name, "%s/msaa-outline", stin_tier_name(tier));
    n = msaa_open(r, path, "halo.json", OUTLINE_SAMPLES, name, &s, pos);
    if (!n)
        return;
    one_case(r, &s, tier == STIN_TIER_GL4 ? &gl4 : &gl2, (const float(*)[2])pos, n);
    msaa_close(r, name, &s);
}
