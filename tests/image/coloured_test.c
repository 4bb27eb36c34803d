/* SPDX-License-Identifier: MIT */
/*
 * Coloured shadow maps ("coloured", GL2 and GL4) and the opacity threshold
 * ("opaque", every tier) against the Embree reference's transmittance
 * (T.R T.G T.B), on the scenes made for deep (deep-*) and glass-panes.
 * Tolerance 2/255 per channel as deep's: the 8-bit visibility output rounds
 * by 1/255 and the RGBA8 map by 1/510 a factor.
 *   transmittance  the receivers that are not transparent surfaces (floors,
 *                  walls: no transparent caster lies behind them on the
 *                  light's ray, where coloured is exact) within 2/255 of T
 *                  on >= 99.5% of the pixels the light reaches, away from T
 *                  edges, >= 100 of them in partial shadow; with map-pcf
 *                  for the opaque casters too on glass-panes;
 *   values         the seed's values on those receivers (0.5, 0.25, 0.125
 *                  for white panes of 0.5; (0.5,0.25,0.25),
 *                  (0.25,0.0625,0.0625), (0.125,0.125,0.0625) coloured);
 *   between        the inexact case, bounded: transparent surfaces (a pane
 *                  behind another, a box pane's far faces) take every pane
 *                  on their ray, their own and those behind them included,
 *                  so they are never lighter than T: >= 99.5% of them are
 *                  at most T + 2/255 (the fraction within 2/255 is printed);
 *   separate       deep-stack with its panes moved apart (no pane shadows
 *                  another): every pixel, panes included, within 2/255 on
 *                  >= 99.5%, and each pane's lit side within 2/255 of 1
 *                  (not darkened by its own factor);
 *   depth-needed   the same with STIN_DEBUG_COLOURED_NO_DEPTH (no
 *                  nearest-depth test): fewer than half the panes' lit
 *                  pixels stay within 2/255 of 1, so the test above can fail;
 *   opaque         forced opaque on deep-stack (panes of opacity 0.5):
 *                  threshold 0.5 - the floor under the panes (T < 1) has
 *                  visibility 0 within 2/255 on >= 99.5%; threshold 0.75 -
 *                  the same pixels have 1 (the panes cast nothing);
 *   shadows-off    forced coloured with shadows off falls back to opaque,
 *                  saying why;
 *   coloured-forced  below GL2, forcing coloured is refused naming the tier.
 */
#include "deep_case.h"

#include "aov.h"
#include "light_reach.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Transparent surfaces at most T + 2/255: never lighter than the truth. */
static void test_between(const deep_case *c, const capture *cap, const char *name)
{
    long n = 0, not_lighter = 0, exact = 0;
    int x, y, k;
    for (y = 0; y < c->r->height; y++)
        for (x = 0; x < c->r->width; x++) {
            const float *t = deep_ref_px(c, x, y) + REFERENCE_CH_T_R;
            const float *g = deep_gl_px(c, cap, x, y);
            int ok = 1;
            if (!deep_is_transparent(c, &c->hits[(size_t)y * c->r->width + x]) ||
                !deep_comparable(c, cap, x, y))
                continue;
            n++;
            for (k = 0; k < 3; k++)
                ok &= g[AOV_VIS_R + k] <= t[k] + T_TOLERANCE;
            not_lighter += ok;
            exact += deep_within(g, t, T_TOLERANCE);
        }
    report(c->r, n >= MIN_CLASS && not_lighter >= T_MIN_MATCH * n ? "PASS" : "FAIL", name,
           "transparent surfaces: %ld of %ld at most T + 2/255 (need >= %d, 99.5%%); within "
           "2/255 of T (not required: panes behind panes take every factor on the ray): "
           "%.2f%%", not_lighter, n, MIN_CLASS, n ? 100.0 * exact / n : 0.0);
}

/* Without the nearest-depth test the panes' lit sides take their own
 * factor: the own-layer check must see it. */
static void test_depth_needed(const deep_case *c, const char *name)
{
    capture cap;
    capture_options o;
    long n, good;
    deep_options(c, &o);
    o.debug_flags = STIN_DEBUG_COLOURED_NO_DEPTH;
    if (!deep_render(c, c->s, &o, &cap, name))
        return;
    deep_own_layer_counts(c, &cap, &n, &good);
    report(c->r, n >= MIN_PARTIAL && good < 0.5 * n ? "PASS" : "FAIL", name,
           "STIN_DEBUG_COLOURED_NO_DEPTH: %ld of %ld unshadowed pane pixels stay within 2/255 of "
           "1 (must be under half: the nearest-depth test is what keeps them)", good, n);
    capture_free(&cap);
}

/* deep-stack with its panes apart: low (object 1) 2.4 toward -z, high
 * (object 3) 2.4 toward +z, so no pane's shadow falls on another. */
static void separate_tests(deep_case *base, const scene *s)
{
    deep_case c = *base;
    scene apart = *s;
    scene_object *objects = malloc(sizeof *objects * (size_t)s->object_count);
    reference *ref = NULL;
    capture cap;
    capture_options o;
    char err[512], name[256];
    const char *tier = stin_tier_name(c.tier);
    int i;
    if (!objects)
        return;
    for (i = 0; i < s->object_count; i++) /* floor, low, middle, high */
        objects[i] = s->objects[i];
    if (s->object_count == 4) {
        objects[1].transform[14] -= 2.4f; /* column-major: z of the translation */
        objects[3].transform[14] += 2.4f;
    }
    apart.objects = objects;
    c.s = &apart;
    c.skip_transparent = 0;
    snprintf(name, sizeof name, "%s/%s/coloured-separate", tier, c.scene_name);
    if (!deep_make_reference(&c, &ref, err, sizeof err)) {
        report(c.r, "FAIL", name, "reference: %s", err);
    } else {
        deep_options(&c, &o);
        if (deep_render(&c, &apart, &o, &cap, name)) {
            deep_test_transmittance(&c, &cap, name);
            snprintf(name, sizeof name, "%s/%s/coloured-separate-own-layer", tier, c.scene_name);
            deep_test_own_layer(&c, &cap, name);
            capture_free(&cap);
            snprintf(name, sizeof name, "%s/%s/coloured-depth-needed", tier, c.scene_name);
            test_depth_needed(&c, name);
        }
    }
    deep_free_reference(&c, ref);
    free(objects);
}

/* The floor under the panes (T < 1) at `expect` with the threshold. */
static void opaque_case(deep_case *c, float threshold, float expect, const char *what)
{
    capture cap;
    capture_options o;
    char name[256];
    long n = 0, good = 0;
    int x, y;
    const float want[3] = {expect, expect, expect};
    snprintf(name, sizeof name, "%s/%s/opaque-%s", stin_tier_name(c->tier), c->scene_name, what);
    deep_options(c, &o);
    o.opaque_threshold = threshold;
    if (!deep_render(c, c->s, &o, &cap, name))
        return;
    for (y = 0; y < c->r->height; y++)
        for (x = 0; x < c->r->width; x++) {
            const float *t = deep_ref_px(c, x, y) + REFERENCE_CH_T_R;
            if (t[0] >= 1.0f || !deep_comparable(c, &cap, x, y))
                continue;
            n++;
            good += deep_within(deep_gl_px(c, &cap, x, y), want, T_TOLERANCE);
        }
    report(c->r, n >= MIN_PARTIAL && good >= T_MIN_MATCH * n ? "PASS" : "FAIL", name,
           "threshold %.2f, panes of opacity 0.5: %ld of %ld floor pixels under them at %g "
           "within 2/255 (need >= %d, 99.5%%); shadows %s", threshold, good, n, expect,
           MIN_PARTIAL, stin_technique_name(cap.choice[STIN_FEATURE_SHADOWS].technique));
    capture_free(&cap);
}

/* The rows of one coloured frame against the reference: transmittance on
 * the receivers, seams, the seed's values and the transparent surfaces'
 * bound where the scene has them. */
static void frame_rows(deep_case *c, const capture *base, int stack, int colour, int panes)
{
    char name[256];
    const char *tier = stin_tier_name(c->tier);
    c->skip_transparent = 1;
    snprintf(name, sizeof name, "%s/%s/coloured-transmittance", tier, c->scene_name);
    deep_test_transmittance(c, base, name);
    if (!strcmp(c->scene_name, "deep-seams")) {
        snprintf(name, sizeof name, "%s/%s/coloured-seams", tier, c->scene_name);
        deep_test_seams(c, base, name);
    }
    if (stack || colour) {
        snprintf(name, sizeof name, "%s/%s/coloured-values", tier, c->scene_name);
        deep_test_values(c, base, name);
    }
    c->skip_transparent = 0;
    if (stack || colour || panes) {
        snprintf(name, sizeof name, "%s/%s/coloured-between", tier, c->scene_name);
        test_between(c, base, name);
    }
}

/* The coloured tests of one scene at a GLSL tier. */
static void glsl_tests(deep_case *c, int stack, int colour, int panes)
{
    capture base;
    capture_options o;
    char name[256];
    const char *tier = stin_tier_name(c->tier);
    deep_options(c, &o);
    snprintf(name, sizeof name, "%s/%s/coloured", tier, c->scene_name);
    if (!deep_render(c, c->s, &o, &base, name))
        return;
    snprintf(name, sizeof name, "%s/%s/coloured-gl-clean", tier, c->scene_name);
    capture_report_clean(c->r, name, &base);
    frame_rows(c, &base, stack, colour, panes);
    capture_free(&base);
    if (stack) {
        snprintf(name, sizeof name, "%s/%s/coloured-shadows-off", tier, c->scene_name);
        deep_test_shadows_off(c, name, STIN_TECH_TRANSLUCENT_OPAQUE);
    }
    if (panes) { /* the opaque casters under map-pcf too */
        capture cap;
        deep_options(c, &o);
        o.shadows = STIN_TECH_SHADOWS_MAP_PCF;
        snprintf(name, sizeof name, "%s/%s/coloured-with-map-pcf", tier, c->scene_name);
        if (deep_render(c, c->s, &o, &cap, name)) {
            c->skip_transparent = 1;
            deep_test_transmittance(c, &cap, name);
            c->skip_transparent = 0;
            capture_free(&cap);
        }
    }
}

static void case_of(deep_case *c, run *r, stin_tier tier, const scene *s, const char *scene_name,
                    int stack)
{
    deep_case_init(c, r, tier, s, scene_name, STIN_TECH_TRANSLUCENT_COLOURED, stack);
}

void coloured_frame_rows(run *r, stin_tier tier, const char *path, const capture *cap)
{
    deep_case c;
    scene s;
    reference *ref = NULL;
    char err[512], scene_name[128];
    int stack;
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    stack = !strcmp(scene_name, "deep-stack");
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", "coloured-reference", "%s: %s", scene_name, err);
        return;
    }
    case_of(&c, r, tier, &s, scene_name, stack);
    if (!deep_make_reference(&c, &ref, err, sizeof err))
        report(r, "FAIL", "coloured-reference", "%s/%s: %s", stin_tier_name(tier), scene_name, err);
    else
        frame_rows(&c, cap, stack, !strcmp(scene_name, "deep-colour"),
                   !strcmp(scene_name, "glass-panes"));
    deep_free_reference(&c, ref);
    scene_free(&s);
}

void coloured_tests(run *r, stin_tier tier, const char *path)
{
    deep_case c;
    scene s;
    reference *ref = NULL;
    char err[512], scene_name[128];
    int stack, colour, omni, window, panes;
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    stack = !strcmp(scene_name, "deep-stack");
    colour = !strcmp(scene_name, "deep-colour");
    omni = !strcmp(scene_name, "deep-omni") || !strcmp(scene_name, "deep-seams");
    window = !strcmp(scene_name, "deep-window");
    panes = !strcmp(scene_name, "glass-panes");
    if ((!stack && !colour && !omni && !window && !panes) || !scene_load(path, &s, err, sizeof err))
        return;
    if (tier == STIN_TIER_GL1 && stack)
        deep_refusal(r, tier, scene_name, &s, STIN_TECH_TRANSLUCENT_COLOURED,
                     "has no colour maps (GL2 and up: GLSL, FBOs, depth textures): transparent "
                     "casters cast by the opacity threshold here", "coloured needs tier gl2");
    if (tier == STIN_TIER_GL1 && !stack) {
        scene_free(&s);
        return;
    }
    case_of(&c, r, tier, &s, scene_name, stack);
    if (!deep_make_reference(&c, &ref, err, sizeof err)) {
        report(r, "FAIL", "coloured-reference", "%s/%s: %s", stin_tier_name(tier), scene_name, err);
    } else {
        if (tier != STIN_TIER_GL1) {
            glsl_tests(&c, stack, colour, panes);
            if (stack)
                separate_tests(&c, &s);
        }
        if (stack) { /* the threshold both ways, on every tier */
            c.tech = STIN_TECH_TRANSLUCENT_OPAQUE;
            c.tag = "opaque";
            c.skip_transparent = 1;
            opaque_case(&c, 0.5f, 0.0f, "casts");
            opaque_case(&c, 0.75f, 1.0f, "casts-nothing");
        }
    }
    deep_free_reference(&c, ref);
    scene_free(&s);
}
