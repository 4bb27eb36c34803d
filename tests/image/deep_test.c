/* SPDX-License-Identifier: MIT */
/*
 * Deep shadow maps ("deep", GL4) against the exact transmittance of the
 * Embree reference (T.R T.G T.B: the product of the eq 5.3 factors of every
 * surface between the point and light 0), on the scenes made for them
 * (deep-*) and glass-panes:
 *   transmittance  (translucent.deep_layers 6 on glass-panes, whose three panes are
 *                  boxes: six surfaces) the visibility output (the shadows technique's times the
 *                  deep map's, 8-bit) within 2/255 of T per channel (the
 *                  8-bit output rounds by 1/255 and the layer's float depth
 *                  and colour add less) on >= 99.5% of the pixels the light
 *                  reaches, away from transmittance edges (a nearest-texel
 *                  map moves an edge by up to a texel: pixels whose T or
 *                  object changes within `band` pixels are left out); at
 *                  least 100 compared pixels must lie in a partial shadow
 *                  (0 < T < 1), so a map that casts nothing cannot pass;
 *   values         the seed's numbers: every class of T the scene is made
 *                  for (0.5, 0.25, 0.125 for white panes of opacity 0.5;
 *                  (0.5,0.25,0.25), (0.25,0.0625,0.0625), (0.125,0.125,0.0625)
 *                  for red, red + red, red + green) has >= 50 compared
 *                  pixels and >= 99.5% of them within 2/255;
 *   own-layer      pane pixels the reference sees unshadowed (T = 1) are
 *                  within 2/255 of 1: a pane is not darkened by its layer;
 *   layer-cap      with translucent.deep_layers 2, where three panes overlap (T 0.125)
 *                  the floor gets 0.25 (the third pane is not captured);
 *   order          the objects drawn in reverse order give bit-identical
 *                  visibility and beauty;
 *   early-stop     STIN_DEBUG_DEEP_NO_EARLY_STOP gives bit-identical
 *                  visibility and beauty, with more layers peeled, and
 *                  six faces peeled where the early stop leaves out those
 *                  no transparent caster reaches (glass-panes: its panes
 *                  lie in one face of the point light's cube, so one);
 *   flag-stop      (GL 4.3) the storage flag's early stop against the
 *                  occlusion query's (STIN_DEBUG_DEEP_QUERY_STOP):
 *                  bit-identical, the same layers, fewer than every layer;
 *   with-volume, with-map-pcf  the transmittance test with those shadows
 *                  techniques for the opaque casters (glass-panes);
 *   texture        (deep-window) a textured pane's opaque cells cast their
 *                  colour, its alpha-0 cells nothing;
 *   mono           translucent.deep_mono: the colour cases come out grey, 1 - a per pane;
 *   size-max       (deep-stack) translucent.deep_map_size 4096, the documented
 *                  maximum (6.3 GB of maps): the maps step down to a size
 *                  the driver takes, saying so, with no GL error (before:
 *                  GL_OUT_OF_MEMORY, no log, no maps) and the transmittance
 *                  test as above;
 *   shadows-off    forced deep with shadows off falls back to
 *                  translucent-solid at set-up, saying why;
 *   gl-clean       no GL error, no call outside the profile.
 * Below GL4 the deep tests SKIP (the tier has no deep), and forcing deep
 * there must be refused, naming what is missing.
 */
#include "caller_gl.h"
#include "deep_case.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


static void test_layer_cap(const deep_case *c, const char *name)
{
    capture cap;
    capture_options o;
    static const float quarter[3] = {0.25f, 0.25f, 0.25f};
    long n = 0, good = 0;
    int x, y;
    deep_options(c, &o);
    o.deep_layers = 2;
    if (!deep_render(c, c->s, &o, &cap, name))
        return;
    for (y = 0; y < c->r->height; y++)
        for (x = 0; x < c->r->width; x++) {
            const float *t = deep_ref_px(c, x, y) + REFERENCE_CH_T_R;
            if (fabsf(t[0] - 0.125f) > 1e-5f || !deep_comparable(c, &cap, x, y))
                continue;
            n++;
            good += deep_within(deep_gl_px(c, &cap, x, y), quarter, T_TOLERANCE);
        }
    report(c->r, n >= MIN_CLASS && good >= T_MIN_MATCH * n ? "PASS" : "FAIL", name,
           "translucent.deep_layers 2: %ld of %ld pixels under three panes (T 0.125) get 0.25 within 2/255 "
           "(need >= %d pixels, 99.5%%)", good, n, MIN_CLASS);
    capture_free(&cap);
}

static void test_size_max(const deep_case *c, char *name, size_t size)
{
    deep_case stepped = *c;
    caller_gl gl;
    capture cap;
    capture_options o;
    GLenum pending;
    const char *said;
    caller_gl_load(&gl, c->r->plat);
    deep_options(c, &o);
    o.deep_map_size = 4096;
    if (!deep_render(c, c->s, &o, &cap, name))
        return;
    pending = gl.GetError();
    said = strstr(cap.fallbacks, "the maps are ");
    if (cap.log_errors || pending != GL_NO_ERROR || !said ||
        sscanf(said, "the maps are %u", &stepped.map_size) != 1) {
        report(c->r, "FAIL", name,
               "translucent.deep_map_size 4096: %u error logs (last: %s), GL "
               "error 0x%x pending, the step down %s", cap.log_errors,
               cap.last_error, pending, said ? "logged" : "not logged");
    } else {
        report(c->r, "PASS", name, "translucent.deep_map_size 4096: no GL error; the log says "
               "%.*s", (int)strcspn(said, "\n"), said);
        strncat(name, "-transmittance", size - strlen(name) - 1);
        deep_test_transmittance(&stepped, &cap, name);
    }
    capture_free(&cap);
}

static void test_order(const deep_case *c, const capture *base, const char *name)
{
    scene reversed = *c->s;
    scene_object *objects = malloc(sizeof *objects * (size_t)c->s->object_count);
    capture cap;
    capture_options o;
    int i;
    long d;
    if (!objects)
        return;
    for (i = 0; i < c->s->object_count; i++)
        objects[i] = c->s->objects[c->s->object_count - 1 - i];
    reversed.objects = objects;
    deep_options(c, &o);
    if (deep_render(c, &reversed, &o, &cap, name)) {
        d = deep_differing(base, &cap);
        report(c->r, d == 0 ? "PASS" : "FAIL", name,
               "objects drawn in reverse order: visibility and beauty differ on %ld pixels "
               "(must be 0)", d);
        capture_free(&cap);
    }
    free(objects);
}

static void test_early_stop(const deep_case *c, const capture *base, const char *name)
{
    capture cap;
    capture_options o;
    unsigned want_faces;
    long d;
    deep_options(c, &o);
    o.debug_flags = STIN_DEBUG_DEEP_NO_EARLY_STOP;
    if (!deep_render(c, c->s, &o, &cap, name))
        return;
    d = deep_differing(base, &cap);
    /* glass-panes' three panes lie below the light: its -y face alone */
    want_faces = strcmp(c->scene_name, "glass-panes") ? base->stats.translucent.deep_faces : 1u;
    report(c->r,
           d == 0 && cap.stats.translucent.deep_layers >= base->stats.translucent.deep_layers &&
                   cap.stats.translucent.deep_faces == 6 && base->stats.translucent.deep_faces == want_faces
               ? "PASS"
               : "FAIL",
           name,
           "every layer peeled: visibility and beauty differ on %ld pixels (must be 0); layers "
           "peeled in the visibility frame %u with the early stop, %u without; faces %u with "
           "it (want %u), %u without (want 6)", d, base->stats.translucent.deep_layers,
           cap.stats.translucent.deep_layers, base->stats.translucent.deep_faces, want_faces, cap.stats.translucent.deep_faces);
    capture_free(&cap);
}

/* GL 4.3's storage flag against the occlusion query: the same images and
 * the same layers peeled, fewer than with every layer (so a flag that is
 * never or always set fails); SKIP where the context has no compute
 * capability (gl33-core: the query is the early stop there). */
static void test_flag_stop(const deep_case *c, const capture *base, const char *name)
{
    capture query, every;
    capture_options o;
    long d;
    if (!(base->caps_present & STIN_CAP_BIT(STIN_CAP_COMPUTE))) {
        report(c->r, "SKIP", name, "no %s (GL 4.3, shader storage buffers): the early stop is "
                                   "the occlusion query here", stin_cap_name(STIN_CAP_COMPUTE));
        return;
    }
    deep_options(c, &o);
    o.debug_flags = STIN_DEBUG_DEEP_QUERY_STOP;
    if (!deep_render(c, c->s, &o, &query, name))
        return;
    o.debug_flags = STIN_DEBUG_DEEP_NO_EARLY_STOP;
    if (deep_render(c, c->s, &o, &every, name)) {
        d = deep_differing(base, &query);
        report(c->r,
               d == 0 && base->stats.translucent.deep_layers == query.stats.translucent.deep_layers &&
                       base->stats.translucent.deep_layers < every.stats.translucent.deep_layers
                   ? "PASS"
                   : "FAIL",
               name,
               "storage flag vs occlusion query: visibility and beauty differ on %ld pixels "
               "(must be 0); layers peeled %u with the flag, %u with the query (must be equal), "
               "%u with every layer (must be more)", d, base->stats.translucent.deep_layers,
               query.stats.translucent.deep_layers, every.stats.translucent.deep_layers);
        capture_free(&every);
    }
    capture_free(&query);
}

/* The transmittance test with another shadows technique for the opaque
 * casters (the base capture's is the context's choice, vdsm). */
static void with_shadows(const deep_case *c, stin_technique shadows)
{
    capture cap;
    capture_options o;
    char name[256];
    deep_options(c, &o);
    o.shadows = shadows;
    snprintf(name, sizeof name, "%s/%s/deep-with-%s", stin_tier_name(c->tier), c->scene_name,
             stin_technique_name(shadows));
    if (!deep_render(c, c->s, &o, &cap, name))
        return;
    if (cap.choice[STIN_FEATURE_SHADOWS].technique != shadows)
        report(c->r, "FAIL", name, "shadows fell back: %s", cap.choice[STIN_FEATURE_SHADOWS].reason);
    else
        deep_test_transmittance(c, &cap, name);
    capture_free(&cap);
}

/* The textured window: its opaque cells' colour (opacity 0.8 x texel alpha
 * 1, colour (1, 51/255, 26/255): T = (0.2, 0.08, 0.0604)) and, where the
 * reference's hard visibility says the window is in the way but T is 1,
 * its alpha-0 cells, which cast nothing. */
static void test_texture(const deep_case *c, const capture *cap, const char *name)
{
    static const float cell[3] = {0.2f, 0.2f * (0.2f + 51.0f / 255.0f), 0.2f * (0.2f + 26.0f / 255.0f)};
    static const float one[3] = {1, 1, 1};
    long n[2] = {0}, good[2] = {0};
    int x, y;
    for (y = 0; y < c->r->height; y++)
        for (x = 0; x < c->r->width; x++) {
            const float *ref = deep_ref_px(c, x, y), *t = ref + REFERENCE_CH_T_R;
            int k = fabsf(t[0] - cell[0]) < 1e-3f && fabsf(t[1] - cell[1]) < 1e-3f &&
                            fabsf(t[2] - cell[2]) < 1e-3f
                        ? 0
                        : t[0] == 1.0f && t[1] == 1.0f && t[2] == 1.0f &&
                                  ref[REFERENCE_CH_VIS_R] == 0.0f
                              ? 1
                              : -1;
            if (k < 0 || !deep_comparable(c, cap, x, y))
                continue;
            n[k]++;
            good[k] += deep_within(deep_gl_px(c, cap, x, y), k ? one : cell, T_TOLERANCE);
        }
    report(c->r,
           n[0] >= MIN_CLASS && n[1] >= MIN_CLASS && good[0] >= T_MIN_MATCH * n[0] &&
                   good[1] >= T_MIN_MATCH * n[1]
               ? "PASS"
               : "FAIL",
           name,
           "opaque cells' shadow (%.3f,%.3f,%.3f): %ld of %ld within 2/255; behind alpha-0 cells "
           "(T 1): %ld of %ld (need >= %d each, 99.5%%)", cell[0], cell[1], cell[2], good[0], n[0],
           good[1], n[1], MIN_CLASS);
}

/* translucent.deep_mono: the colour cases give grey 1 - a per pane: (0.5,0.25,0.25) ->
 * 0.5, (0.25,0.0625,0.0625) and (0.125,0.125,0.0625) -> 0.25. */
static void test_mono(const deep_case *c, const char *name)
{
    static const float coloured[3][3] = {
        {0.5f, 0.25f, 0.25f}, {0.25f, 0.0625f, 0.0625f}, {0.125f, 0.125f, 0.0625f}};
    static const float grey[3][3] = {{0.5f, 0.5f, 0.5f}, {0.25f, 0.25f, 0.25f}, {0.25f, 0.25f, 0.25f}};
    capture cap;
    capture_options o;
    long n[3] = {0}, good[3] = {0};
    int x, y, k, ok = 1;
    deep_options(c, &o);
    o.deep_mono = 1;
    if (!deep_render(c, c->s, &o, &cap, name))
        return;
    for (y = 0; y < c->r->height; y++)
        for (x = 0; x < c->r->width; x++) {
            const float *t = deep_ref_px(c, x, y) + REFERENCE_CH_T_R;
            if (!deep_comparable(c, &cap, x, y))
                continue;
            for (k = 0; k < 3; k++)
                if (fabsf(t[0] - coloured[k][0]) < 1e-5f && fabsf(t[1] - coloured[k][1]) < 1e-5f &&
                    fabsf(t[2] - coloured[k][2]) < 1e-5f) {
                    n[k]++;
                    good[k] += deep_within(deep_gl_px(c, &cap, x, y), grey[k], T_TOLERANCE);
                }
        }
    for (k = 0; k < 3; k++)
        ok &= n[k] >= MIN_CLASS && good[k] >= T_MIN_MATCH * n[k];
    report(c->r, ok ? "PASS" : "FAIL", name,
           "translucent.deep_mono: red %ld of %ld at 0.5, red + red %ld of %ld and red + green %ld of %ld at "
           "0.25, within 2/255 (need >= %d a value, 99.5%%)", good[0], n[0], good[1], n[1],
           good[2], n[2], MIN_CLASS);
    capture_free(&cap);
}

/* The tests of one GL4 scene; which ones depends on what the scene is for. */
static void gl4_tests(deep_case *c, int stack, int colour, int omni)
{
    capture base;
    capture_options o;
    char name[256];
    const char *tier = stin_tier_name(c->tier), *scene_name = c->scene_name;
    deep_options(c, &o);
    snprintf(name, sizeof name, "%s/%s/deep", tier, scene_name);
    if (!deep_render(c, c->s, &o, &base, name))
        return;
    snprintf(name, sizeof name, "%s/%s/deep-gl-clean", tier, scene_name);
    capture_report_clean(c->r, name, &base);
    snprintf(name, sizeof name, "%s/%s/deep-transmittance", tier, scene_name);
    deep_test_transmittance(c, &base, name);
    snprintf(name, sizeof name, "%s/%s/deep-own-layer", tier, scene_name);
    deep_test_own_layer(c, &base, name);
    if (!strcmp(scene_name, "deep-seams")) {
        snprintf(name, sizeof name, "%s/%s/deep-seams", tier, scene_name);
        deep_test_seams(c, &base, name);
    }
    if (stack || colour) {
        snprintf(name, sizeof name, "%s/%s/deep-values", tier, scene_name);
        deep_test_values(c, &base, name);
        snprintf(name, sizeof name, "%s/%s/deep-order", tier, scene_name);
        test_order(c, &base, name);
    }
    if (stack) {
        snprintf(name, sizeof name, "%s/%s/deep-layer-cap", tier, scene_name);
        test_layer_cap(c, name);
        snprintf(name, sizeof name, "%s/%s/deep-size-max", tier, scene_name);
        test_size_max(c, name, sizeof name);
        snprintf(name, sizeof name, "%s/%s/deep-shadows-off", tier, scene_name);
        deep_test_shadows_off(c, name, STIN_TECH_TRANSLUCENT_SOLID);
    } else if (colour) {
        snprintf(name, sizeof name, "%s/%s/deep-mono", tier, scene_name);
        test_mono(c, name);
    } else { /* point lights: faces without panes stop after one layer */
        snprintf(name, sizeof name, "%s/%s/deep-early-stop", tier, scene_name);
        test_early_stop(c, &base, name);
        snprintf(name, sizeof name, "%s/%s/deep-flag-stop", tier, scene_name);
        test_flag_stop(c, &base, name);
    }
    if (!stack && !colour && !omni) {
        /* glass-panes' opaque casters under the other shadows techniques */
        with_shadows(c, STIN_TECH_SHADOWS_VOLUME);
        with_shadows(c, STIN_TECH_SHADOWS_MAP_PCF);
    }
    capture_free(&base);
}

/* The textured window: transmittance and the cells' pattern. */
static void window_tests(deep_case *c)
{
    capture cap;
    capture_options o;
    char name[256];
    deep_options(c, &o);
    snprintf(name, sizeof name, "%s/%s/deep", stin_tier_name(c->tier), c->scene_name);
    if (!deep_render(c, c->s, &o, &cap, name))
        return;
    snprintf(name, sizeof name, "%s/%s/deep-transmittance", stin_tier_name(c->tier), c->scene_name);
    deep_test_transmittance(c, &cap, name);
    snprintf(name, sizeof name, "%s/%s/deep-texture", stin_tier_name(c->tier), c->scene_name);
    test_texture(c, &cap, name);
    capture_free(&cap);
}

void deep_frame_rows(run *r, stin_tier tier, const char *path, const capture *cap)
{
    deep_case c;
    scene s;
    reference *ref = NULL;
    char err[512], scene_name[128], name[256];
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", "deep-reference", "%s: %s", scene_name, err);
        return;
    }
    deep_case_init(&c, r, tier, &s, scene_name, STIN_TECH_TRANSLUCENT_DEEP, 0);
    c.layers = 6; /* deep_tests' on glass-panes */
    if (!deep_make_reference(&c, &ref, err, sizeof err)) {
        report(r, "FAIL", "deep-reference", "%s/%s: %s", stin_tier_name(tier), scene_name, err);
    } else {
        snprintf(name, sizeof name, "%s/%s/deep-transmittance", stin_tier_name(tier), scene_name);
        deep_test_transmittance(&c, cap, name);
        snprintf(name, sizeof name, "%s/%s/deep-own-layer", stin_tier_name(tier), scene_name);
        deep_test_own_layer(&c, cap, name);
    }
    deep_free_reference(&c, ref);
    scene_free(&s);
}

void deep_tests(run *r, stin_tier tier, const char *path)
{
    deep_case c;
    scene s;
    reference *ref = NULL;
    char err[512], scene_name[128];
    int stack, colour, omni, window;
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    stack = !strcmp(scene_name, "deep-stack");
    colour = !strcmp(scene_name, "deep-colour");
    omni = !strcmp(scene_name, "deep-omni") || !strcmp(scene_name, "deep-seams");
    window = !strcmp(scene_name, "deep-window");
    if ((!stack && !colour && !omni && !window && strcmp(scene_name, "glass-panes")) ||
        !scene_load(path, &s, err, sizeof err))
        return;
    if (tier != STIN_TIER_GL4) {
        if (stack) /* once per tier */
            deep_refusal(r, tier, scene_name, &s, STIN_TECH_TRANSLUCENT_DEEP,
                         "has no deep shadow maps (GL4 only): coloured or opaque shadows "
                         "transparent casters here", "deep needs tier gl4");
        scene_free(&s);
        return;
    }
    deep_case_init(&c, r, tier, &s, scene_name, STIN_TECH_TRANSLUCENT_DEEP, stack);
    /* glass-panes' panes are boxes: up to six surfaces along a ray */
    c.layers = stack || colour || omni || window ? 0 : 6;
    if (!deep_make_reference(&c, &ref, err, sizeof err))
        report(r, "FAIL", "deep-reference", "%s/%s: %s", stin_tier_name(tier), scene_name, err);
    else if (window)
        window_tests(&c);
    else
        gl4_tests(&c, stack, colour, omni);
    deep_free_reference(&c, ref);
    scene_free(&s);
}
