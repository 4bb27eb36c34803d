/* SPDX-License-Identifier: MIT */
/*
 * Multisampled targets (issue 39): msaa/halo.json (a lit ball over its own
 * shadow) drawn into the platform's 4x framebuffer object by every shadow
 * technique of the tier, against the exact reference shaded at the
 * target's own sample positions (glGetMultisamplefv) and box-filtered, as
 * the resolve averages the samples. The check is at silhouettes: a sample
 * that took the other surface's visibility (a screen mask read at the
 * pixel, single-sampled) shows as a lit rim on the shadowed floor or a dark
 * one on the ball there, a one-pixel halo. The same check into 2 and 8
 * samples where the context has them (one technique a tier), with the
 * count the driver allocated.
 */
#include "msaa_common.h"
#include "test_context.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MSAA_SAMPLES 4
/* A sample of the floor's light (0.34 here) in four: 0.085; the reference
 * shades where multisampling does (each surface at the pixel centre), so
 * what is left is 8-bit rounding and float interpolation. */
#define MSAA_TOLERANCE 0.03
/* Of the silhouette band's pixels (within one pixel of a change of object
 * among the samples): measured 0 with per-sample visibility; a halo along
 * the ball's outline over its shadow is 40 or more. */
#define MSAA_MAX_BAND_OVER 3

typedef struct msaa_case {
    stin_tier tier;
    stin_technique shadows;
} msaa_case;

/* 2x and 8x: one technique a tier (vdsm, GL2's map-pcf, GL1's volumes),
 * which keeps make check's time; the 4x rows run every one. */
static const msaa_case other_counts[] = {
    {STIN_TIER_GL4, STIN_TECH_SHADOWS_VDSM},
    {STIN_TIER_GL2, STIN_TECH_SHADOWS_MAP_PCF},
    {STIN_TIER_GL1, STIN_TECH_SHADOWS_VOLUME},
};

/* The visibility rule of each technique's reference (shadow_test.c's). */
static int facets_of(stin_tier tier, stin_technique t)
{
    if (tier == STIN_TIER_GL1)
        return REFERENCE_FACETS_ALL;
    return t == STIN_TECH_SHADOWS_VOLUME ? REFERENCE_FACETS_OPEN : REFERENCE_FACETS_NONE;
}

static void one_case(run *r, const scene *s, const msaa_case *mc, int asked, int per_vertex,
                     const float pos[][2], int n)
{
    char name[128], why[512] = "";
    uint8_t *rgba = malloc((size_t)r->width * r->height * 4);
    msaa_techniques tech = {mc->tier, mc->shadows, STIN_TECH_NONE, STIN_TECH_NONE,
                            STIN_TECH_NONE, STIN_TECH_NONE};
    msaa_ref m;
    msaa_band b;
    int got;
    msaa_ref_init(&m, s);
    if (asked == MSAA_SAMPLES)
        snprintf(name, sizeof name, "%s/msaa-%s%s", stin_tier_name(mc->tier),
                 s->light_count && s->lights[0].radius > 0.0f ? "soft-" : "",
                 stin_technique_name(mc->shadows));
    else
        snprintf(name, sizeof name, "%s/msaa-%dx-%s", stin_tier_name(mc->tier), asked,
                 stin_technique_name(mc->shadows));
    got = rgba ? msaa_render(r, s, &tech, rgba, why, sizeof why) : 0;
    if (got < 0) {
        report(r, "SKIP", name, "%s", why);
    } else if (!got) {
        report(r, "FAIL", name, "%s", why);
    } else if (!msaa_ref_build(s, facets_of(mc->tier, mc->shadows), per_vertex, pos, n,
                                       &m, why, sizeof why)) {
        report(r, "FAIL", name, "reference: %s", why);
    } else {
        msaa_compare_band(&m, rgba, r->width, MSAA_TOLERANCE, &b);
        report(r, b.over <= MSAA_MAX_BAND_OVER && b.band > 100 ? "PASS" : "FAIL", name,
               "%d samples (%d asked): %ld of %ld silhouette-band pixels beyond %.2f of the "
               "reference at the samples (max %.3f; at most %d); elsewhere %ld of %ld",
               n, asked, b.over, b.band, MSAA_TOLERANCE, b.band_max, MSAA_MAX_BAND_OVER,
               b.compared_over, b.compared);
        if (b.over > MSAA_MAX_BAND_OVER)
            msaa_save_pair(r, name, rgba, m.colour, m.w, m.h);
    }
    msaa_ref_free(&m);
    free(rgba);
}

/* One run a tier: GL4 on the two core profiles, GL2 and the GL1 path on
 * gl21 (the GL 1.x profiles hide framebuffer objects from stin). */
static int runs_here(const run *r, stin_tier tier)
{
    if (tier == STIN_TIER_GL4)
        return !strcmp(r->profile_name, "gl45-core") || !strcmp(r->profile_name, "gl33-core");
    return !strcmp(r->profile_name, "gl21");
}

/* The list's rows of this tier into a target of `asked` samples. */
static void at_count(run *r, const scene *s, stin_tier tier, int asked, const msaa_case *list,
                     size_t count)
{
    char err[512], name[64];
    float pos[MSAA_MAX_SAMPLES][2];
    int n, per_vertex = tier == STIN_TIER_GL1 ? msaa_gl1_per_vertex(r, s) : 0;
    size_t i;
    if (asked == MSAA_SAMPLES)
        snprintf(name, sizeof name, "%s/msaa", stin_tier_name(tier));
    else
        snprintf(name, sizeof name, "%s/msaa-%dx", stin_tier_name(tier), asked);
    if (!stin_platform_set_samples(r->plat, asked, err, sizeof err)) {
        report(r, "SKIP", name, "%s", err);
        return;
    }
    n = msaa_sample_positions(r, pos);
    if (!n)
        report(r, "SKIP", name, "the context cannot say where its samples lie "
                                "(glGetMultisamplefv: GL 3.2 or ARB_texture_multisample)");
    else
        for (i = 0; i < count; i++)
            if (list[i].tier == tier)
                one_case(r, s, &list[i], asked, per_vertex, (const float(*)[2])pos, n);
    if (!stin_platform_set_samples(r->plat, 0, err, sizeof err))
        report(r, "FAIL", name, "back to the default framebuffer: %s", err);
}

/* Area-light shadows (msaa/halo-soft.json): the techniques that honour a
 * light's radius (soft_test.c), GL4 on gl45-core alone (gl33-core runs
 * the same programs), GL2 and GL1 on gl21. GL1's volumes (points over
 * the light's ball, pass by pass) count in the frame's own stencil:
 * measured 0 of 642 band pixels over; a single-sampled frame resolved
 * against the same reference puts 171 over (max 0.28). */
static void soft_rows(run *r, stin_tier tier, const char *path)
{
    static const msaa_case soft[] = {
        {STIN_TIER_GL4, STIN_TECH_SHADOWS_VDSM},    {STIN_TIER_GL4, STIN_TECH_SHADOWS_VOLUME},
        {STIN_TIER_GL4, STIN_TECH_SHADOWS_MAP_PCF}, {STIN_TIER_GL2, STIN_TECH_SHADOWS_VOLUME},
        {STIN_TIER_GL2, STIN_TECH_SHADOWS_MAP_PCF}, {STIN_TIER_GL1, STIN_TECH_SHADOWS_VOLUME},
    };
    float pos[MSAA_MAX_SAMPLES][2];
    char name[64];
    scene s;
    if (!strcmp(r->profile_name, "gl33-core"))
        return;
    snprintf(name, sizeof name, "%s/msaa-soft", stin_tier_name(tier));
    if (!msaa_open(r, path, "halo-soft.json", MSAA_SAMPLES, name, &s, pos))
        return;
    at_count(r, &s, tier, MSAA_SAMPLES, soft, sizeof soft / sizeof soft[0]);
    msaa_close(r, name, &s);
}

/* GL1's map-combine hands the scene's point lights to stencil volumes;
 * map-depth draws their six faces, and its side test once lit a fragment
 * whose pixel centre lies beyond its surface's edge (as the light sees it)
 * at half strength, a rim along the floor's outline this check found (101
 * of 711; docs/testing.md). */
void msaa_tests(run *r, stin_tier tier, const char *path)
{
    static const msaa_case cases[] = {
        {STIN_TIER_GL4, STIN_TECH_SHADOWS_VDSM},    {STIN_TIER_GL4, STIN_TECH_SHADOWS_VOLUME},
        {STIN_TIER_GL4, STIN_TECH_SHADOWS_MAP_PCF}, {STIN_TIER_GL2, STIN_TECH_SHADOWS_VOLUME},
        {STIN_TIER_GL2, STIN_TECH_SHADOWS_MAP_PCF}, {STIN_TIER_GL1, STIN_TECH_SHADOWS_VOLUME},
        {STIN_TIER_GL1, STIN_TECH_SHADOWS_MAP_COMBINE},
        {STIN_TIER_GL1, STIN_TECH_SHADOWS_MAP_DEPTH},
    };
    char file[1024], err[512], name[64];
    const char *slash = strrchr(path, '/');
    scene s;
    if (strcmp(scene_base_name(path), "shadow-overlap"))
        return;
    snprintf(name, sizeof name, "%s/msaa", stin_tier_name(tier));
    if (!runs_here(r, tier))
        return;
    snprintf(file, sizeof file, "%.*smsaa/halo.json", slash ? (int)(slash - path + 1) : 0, path);
    if (!scene_load(file, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    if (s.width > r->width || s.height > r->height) {
        report(r, "SKIP", name, "the run's %dx%d is smaller than the scene's %dx%d", r->width,
               r->height, s.width, s.height);
        scene_free(&s);
        return;
    }
    at_count(r, &s, tier, MSAA_SAMPLES, cases, sizeof cases / sizeof cases[0]);
    at_count(r, &s, tier, 2, other_counts, sizeof other_counts / sizeof other_counts[0]);
    at_count(r, &s, tier, 8, other_counts, sizeof other_counts / sizeof other_counts[0]);
    scene_free(&s);
    soft_rows(r, tier, path);
}
