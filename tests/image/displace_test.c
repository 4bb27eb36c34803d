/* SPDX-License-Identifier: MIT */
/*
 * Displacement ("displace", GL2/GL4; src/surface/displace.c,
 * shaders/gl2/displace.glsl) on the scenes with displaced materials, against
 * the displaced Embree reference (reference_displace.h: the same meshes moved
 * on the CPU, the height map filtered as GL_LINEAR does at level 0):
 *   position     P within 1e-3 Z + 2e-3 on >= 99.5% of the pixels covered in
 *                the render or the reference (silhouettes included: a pixel
 *                covered in one only counts against). The tolerance is the
 *                other tests' (image_test.c) plus 1e-3: the GPU's bilinear
 *                weights are 8-bit fractions on llvmpipe, so h differs from
 *                the exact bilinear by up to 1/512 of a texel step, which
 *                moves a vertex by up to height_scale / 512 (0.0007 here).
 *   silhouette   the render's coverage differs from the undisplaced mesh's
 *                (reference ray cast of the scene as loaded) on at least
 *                0.5% of the covered pixels: the displacement changes the
 *                outline (pom's would not), and the difference is reported
 *                beside the displaced reference's coverage mismatch.
 *   shadow-T     light 0's visibility (the visibility output) with shadow
 *                technique T (map-pcf, volume; vdsm on GL4) against the ray-cast
 *                visibility of the displaced reference, on pixels whose P
 *                matches, the light reaches the side seen, and no reference
 *                shadow edge lies within 2 pixels: at most 1% differ
 *                (map-pcf's bound, pcf_test.c) and 0.2% for vdsm (exact: its
 *                edge budget plus the displaced surface's steep steps, where
 *                the GPU's interpolated point and the reference's hit lie on
 *                either side of a step). A shadow of the flat mesh fails it.
 *                Volumes cast the displaced draws through their own depth
 *                map (map-pcf's test): map-pcf's bound, and the log must say
 *                so.
 *   fallback     vertex texture units hidden (caps mask): displacement is
 *                "displacement-off", marked fallen back, and the render's
 *                coverage is the undisplaced mesh's (within 0.1%).
 *   guard-band   (camera moved in, the displaced mesh partly off screen) the
 *                default band (1) and no test at all give bit-identical AOVs;
 *                a band of 1e-6 must change pixels (triangles crossing the
 *                screen's edge keep an undisplaced vertex), so the test sees
 *                the band at work.
 *   manual-bilinear  four fetches at texel centres blended in the shader:
 *                the position test's bound against the same reference.
 *   mip-near     the scene's view with and without the height map's mip chain
 *                (STIN_DEBUG_DISPLACE_NO_MIP): bit-identical (level 0 alone
 *                up close).
 *   mip-far      the camera 4x as far: P against the reference that reads
 *                the same levels (reference_displace_ex: log2 of texels per
 *                pixel at each vertex's distance, two levels blended) within
 *                the position test's bound, and the render differs from
 *                level 0 alone (the levels are in use).
 *   gl-clean     no GL error, no call outside the profile.
 *   tess-level1  (GL4) "displace-tess" with a target edge length above
 *                every edge (level 1 everywhere) draws the VTF surface: every
 *                AOV within one 8-bit level of "displace"'s (the tessellator
 *                may emit a triangle's corners in another order, which moves
 *                interpolated values by ulps).
 * A scene whose displaced mesh is coarse for its height map (edges spanning
 * more than 4 texels on average, stin's own "coarse" log) is a tessellation
 * scene: GL4 only, "displace-tess" against the reference of the tessellated
 * limit (reference_displace_split, every triangle split 48 x 48):
 *   tess-position  the position test's bound, silhouettes included.
 *   tess-silhouette  coverage differs from the flat mesh's (as above).
 *   tess-cracks  pixels the render leaves background (the scene puts sky
 *                behind the displaced mesh) while the reference and all 8
 *                of its neighbours hit: must be 0 - a crack between two
 *                patches that split a shared edge differently shows here.
 *   tess-shadow-T  the shadow test above against the limit (map-pcf at its
 *                own bound, 1%: this relief has far more grazing slopes).
 *   vtf-coarse   "displace" on the same coarse mesh against the same limit
 *                must miss the position bound (below 95%): the test sees
 *                what tessellation adds.
 * GL1 and contexts without vertex texture units report SKIP with the reason;
 * so do contexts without tessellation shaders for the tessellation tests.
 */
#include "aov.h"
#include "capture.h"
#include "compare.h"
#include "image_test.h"
#include "light_reach.h"
#include "reference.h"
#include "reference_displace.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DISP_P_RELATIVE 1e-3
#define DISP_P_ABSOLUTE 2e-3
#define DISP_P_MIN_MATCH 0.995
#define DISP_SILHOUETTE_MIN 0.005
#define DISP_FALLBACK_MAX 0.001
#define DISP_EDGE_BAND 2
#define DISP_PCF_MAX 0.0025
#define DISP_VDSM_MAX 0.002
#define DISP_GUARD_NARROW 1e-6f
#define DISP_MIP_FAR 4.0 /* the camera this many times as far for the mip test */
#define DISP_COARSE_TEXELS 4.0
#define DISP_LIMIT_SPLIT 48
#define DISP_VTF_COARSE_MAX 0.95
/* level 1 draws the same triangles, but the tessellator may emit their
 * corners in another order: interpolation moves by ulps, a colour by a level */
#define DISP_LEVEL1_EPS (1.0 / 255.0 + 1e-6)
#define DISP_PCF_TESS_MAX 0.01 /* pcf_test.c's bound: the relief's many grazing slopes */

typedef struct disp_case {
    run *r;
    stin_tier tier;
    stin_technique displacement; /* what the renders force */
    int tessellation;            /* the context has tessellation shaders */
    int cast_map;                /* FBOs and depth textures: volumes' depth map for
                                  * displaced draws (compared in the shader without
                                  * shadow compare) */
    char prefix[128];
    const scene *s;      /* as loaded */
    scene ds;            /* displaced */
    ref_hit *hits, *flat_hits;
    float *ref;          /* reference_render of ds */
} disp_case;

int displace_scene(const char *path)
{
    scene s;
    char err[256];
    int yes;
    if (!scene_load(path, &s, err, sizeof err))
        return 0;
    yes = reference_scene_displaces(&s);
    scene_free(&s);
    return yes;
}

static void name_of(const disp_case *c, const char *test, char *out, size_t size)
{
    snprintf(out, size, "%s/%s", c->prefix, test);
}

static int render(disp_case *c, const scene *s, const capture_options *o, capture *cap,
                  const char *test)
{
    char err[512], name[256];
    if (capture_render(c->r->plat, c->r->profile, s, o, cap, err, sizeof err))
        return 1;
    name_of(c, test, name, sizeof name);
    report(c->r, strstr(err, " needs ") ? "SKIP" : "FAIL", name, "%s", err); /* a refusal */
    return 0;
}

static void base_options(const disp_case *c, capture_options *o, stin_technique shadows)
{
    memset(o, 0, sizeof *o);
    o->tier = c->tier;
    o->shadows = shadows;
    o->displacement = c->displacement;
}

static const float *gl_px(const capture *cap, int w, int h, int x, int y)
{
    return cap->img.pixels + ((size_t)(h - 1 - y) * w + x) * AOV_CHANNELS;
}

/* Pixels whose coverage differs between a render and reference hits. */
static long coverage_differs(const disp_case *c, const capture *cap, const ref_hit *hits,
                             long *covered)
{
    int w = c->r->width, h = c->r->height, x, y;
    long n = 0;
    *covered = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            int g = gl_px(cap, w, h, x, y)[AOV_Z] > 0.0f, f = hits[(size_t)y * w + x].hit;
            *covered += g || f;
            n += g != f;
        }
    return n;
}

static double position_match(disp_case *c, const capture *cap, compare_result *cr)
{
    compare_tolerance tol = {DISP_P_RELATIVE, DISP_P_ABSOLUTE, 1.0, 180.0};
    compare_render(&c->ds, &cap->img, c->ref, c->hits, &tol, cr);
    return cr->covered ? 1.0 - (double)(cr->p_mismatch + cr->coverage_mismatch) / cr->covered : 0;
}

static void test_position(disp_case *c, const capture *cap, const char *test)
{
    compare_result cr;
    char name[256];
    double match = position_match(c, cap, &cr);
    name_of(c, test, name, sizeof name);
    report(c->r, match >= DISP_P_MIN_MATCH && cr.covered ? "PASS" : "FAIL", name,
           "P matches the displaced reference on %.3f%% of %ld covered pixels (coverage differs "
           "on %ld, P on %ld; need %.1f%%)", 100.0 * match, cr.covered, cr.coverage_mismatch,
           cr.p_mismatch, 100.0 * DISP_P_MIN_MATCH);
}

static void test_silhouette(disp_case *c, const capture *cap, const char *test)
{
    long covered, flat = coverage_differs(c, cap, c->flat_hits, &covered), cov_ref;
    long displaced = coverage_differs(c, cap, c->hits, &cov_ref);
    char name[256];
    double f = covered ? (double)flat / covered : 0;
    name_of(c, test, name, sizeof name);
    report(c->r, f >= DISP_SILHOUETTE_MIN ? "PASS" : "FAIL", name,
           "coverage differs from the undisplaced mesh's on %ld of %ld pixels (%.2f%%, need "
           ">= %.1f%%), from the displaced reference's on %ld", flat, covered, 100.0 * f,
           100.0 * DISP_SILHOUETTE_MIN, displaced);
}

static void test_shadow(disp_case *c, stin_technique t, double bound, const char *prefix)
{
    compare_tolerance tol = {DISP_P_RELATIVE, DISP_P_ABSOLUTE, 1.0, 180.0};
    capture_options o;
    capture cap;
    char test[64], name[256];
    int w = c->r->width, h = c->r->height, x, y, logged;
    long compared = 0, differ = 0, shadowed = 0;
    snprintf(test, sizeof test, "%sshadow-%s", prefix, stin_technique_name(t));
    name_of(c, test, name, sizeof name);
    if (t == STIN_TECH_SHADOWS_VOLUME && !c->cast_map) {
        report(c->r, "SKIP", name, "displaced draws cast under volumes through a depth map, "
               "which needs depth textures in framebuffer objects (bare OpenGL ES 2.0 has "
               "none): stin_create refuses the pair");
        return;
    }
    base_options(c, &o, t);
    if (!render(c, c->s, &o, &cap, test))
        return;
    if (cap.choice[STIN_FEATURE_SHADOWS].technique != t) {
        report(c->r, "SKIP", name, "%s does not run here (%s)", stin_technique_name(t),
               cap.choice[STIN_FEATURE_SHADOWS].reason);
        capture_free(&cap);
        return;
    }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const ref_hit *hit = &c->hits[(size_t)y * w + x];
            const float *g = gl_px(&cap, w, h, x, y);
            const float *ref = c->ref + ((size_t)y * w + x) * REFERENCE_CHANNELS;
            double d2 = 0, limit = tol.p_relative * ref[REFERENCE_CH_Z] + tol.p_absolute;
            int k;
            if (!hit->hit || !(g[AOV_Z] > 0.0f) || !light_reaches(&c->ds, hit) ||
                near_shadow_edge(c->hits, c->ref, w, h, x, y, DISP_EDGE_BAND))
                continue;
            for (k = 0; k < 3; k++)
                d2 += (g[AOV_PX + k] - ref[REFERENCE_CH_PX + k]) * (g[AOV_PX + k] - ref[REFERENCE_CH_PX + k]);
            if (d2 > limit * limit)
                continue;
            compared++;
            shadowed += ref[REFERENCE_CH_VIS_R] < 0.5f;
            differ += (g[AOV_VIS_R] >= 0.5f) != (ref[REFERENCE_CH_VIS_R] >= 0.5f);
        }
    /* volumes cast the displaced draws through their own map, and say so */
    logged = t != STIN_TECH_SHADOWS_VOLUME ||
             strstr(cap.fallbacks, "displaced casters cast through map-pcf") != NULL;
    report(c->r,
           compared && shadowed >= 100 && (double)differ <= bound * (double)compared && logged
               ? "PASS"
               : "FAIL",
           name, "visibility differs on %ld of %ld pixels (%.3f%%, bound %.2f%%; %ld shadowed "
           "compared, need >= 100)%s", differ, compared, compared ? 100.0 * differ / compared : 0.0,
           100.0 * bound, shadowed, logged ? "" : "; the log does not say what casts them");
    capture_free(&cap);
}

static void test_fallback(disp_case *c)
{
    capture_options o;
    capture cap;
    char name[256];
    long covered, flat;
    const stin_choice *ch;
    name_of(c, "fallback", name, sizeof name);
    base_options(c, &o, STIN_TECH_SHADOWS_OFF);
    o.displacement = STIN_TECH_NONE;
    o.extra_mask = STIN_CAP_BIT(STIN_CAP_VERTEX_TEXTURE_FETCH);
    if (!render(c, c->s, &o, &cap, "fallback"))
        return;
    ch = &cap.choice[STIN_FEATURE_DISPLACEMENT];
    flat = coverage_differs(c, &cap, c->flat_hits, &covered);
    report(c->r,
           ch->technique == STIN_TECH_DISPLACEMENT_OFF && ch->fell_back &&
                   (double)flat <= DISP_FALLBACK_MAX * (double)covered
               ? "PASS"
               : "FAIL",
           name, "vertex textures hidden: displacement %s (%s); coverage differs from the "
           "undisplaced mesh's on %ld of %ld pixels", stin_technique_name(ch->technique),
           ch->reason, flat, covered);
    capture_free(&cap);
}

/* Pixels where any AOV channel differs at all. */
static long pixels_differ(const capture *a, const capture *b)
{
    size_t i, n = (size_t)a->img.width * a->img.height;
    long d = 0;
    for (i = 0; i < n; i++)
        d += memcmp(a->img.pixels + i * AOV_CHANNELS, b->img.pixels + i * AOV_CHANNELS,
                    sizeof(float) * AOV_CHANNELS) != 0;
    return d;
}

static void test_guard_band(disp_case *c)
{
    scene near = *c->s;
    capture_options o;
    capture on, off, narrow;
    char name[256];
    long same, changed;
    int k;
    /* the camera moved in: the displaced mesh reaches past the screen's edges */
    for (k = 0; k < 3; k++)
        near.camera.eye[k] = near.camera.target[k] + 0.45f * (near.camera.eye[k] - near.camera.target[k]);
    name_of(c, "guard-band", name, sizeof name);
    base_options(c, &o, STIN_TECH_SHADOWS_OFF);
    if (!render(c, &near, &o, &on, "guard-band"))
        return;
    o.debug_flags = STIN_DEBUG_DISPLACE_NO_GUARD;
    if (!render(c, &near, &o, &off, "guard-band")) {
        capture_free(&on);
        return;
    }
    o.debug_flags = 0;
    o.guard_band = DISP_GUARD_NARROW;
    if (!render(c, &near, &o, &narrow, "guard-band")) {
        capture_free(&on);
        capture_free(&off);
        return;
    }
    same = pixels_differ(&on, &off);
    changed = pixels_differ(&narrow, &off);
    report(c->r, same == 0 && changed > 0 ? "PASS" : "FAIL", name,
           "band 1 vs no test: %ld pixels differ (need 0); band 1e-6 vs no test: %ld (need > 0)",
           same, changed);
    capture_free(&on);
    capture_free(&off);
    capture_free(&narrow);
}

static int setup(disp_case *c, int split, const reference_displace_lod *lod, char *err,
                 size_t err_size)
{
    reference *ref = NULL, *flat = NULL;
    size_t n = (size_t)c->r->width * c->r->height;
    int ok;
    if (!reference_displace_ex(c->s, split, lod, &c->ds, err, err_size))
        return 0;
    c->hits = malloc(sizeof *c->hits * n);
    c->flat_hits = malloc(sizeof *c->flat_hits * n);
    c->ref = malloc(sizeof(float) * REFERENCE_CHANNELS * n);
    ref = reference_create(&c->ds, err, err_size);
    /* displaced draws keep their facets (their vertex normals do not describe
     * the displaced surface); the other objects of these scenes are planes */
    reference_facet_terminator(ref, 1);
    flat = reference_create(c->s, err, err_size);
    ok = ref && flat && c->hits && c->flat_hits && c->ref &&
         reference_primary(ref, c->r->width, c->r->height, c->hits) &&
         reference_primary(flat, c->r->width, c->r->height, c->flat_hits) &&
         reference_render_ex(&c->ds, ref, c->r->width, c->r->height, 0, REFERENCE_RENDER_SHADOWED,
                             c->ref);
    if (!ok && ref && flat)
        snprintf(err, err_size, "reference render failed");
    reference_destroy(ref);
    reference_destroy(flat);
    return ok;
}

/* Background pixels of the render inside the reference's coverage: the
 * reference and its 8 neighbours hit (away from the outline). */
static long cracks(const disp_case *c, const capture *cap)
{
    int w = c->r->width, h = c->r->height, x, y, dx, dy;
    long n = 0;
    for (y = 1; y + 1 < h; y++)
        for (x = 1; x + 1 < w; x++) {
            int inside = 1;
            for (dy = -1; dy <= 1; dy++)
                for (dx = -1; dx <= 1; dx++)
                    inside &= c->hits[(size_t)(y + dy) * w + x + dx].hit;
            n += inside && !(gl_px(cap, w, h, x, y)[AOV_Z] > 0.0f);
        }
    return n;
}

/* 1 when a displaced mesh's edges span more than DISP_COARSE_TEXELS texels
 * of its height map on average (stin's coarse-mesh log). */
static int coarse_scene(const scene *s)
{
    int i;
    for (i = 0; i < s->object_count; i++) {
        const scene_object *o = &s->objects[i];
        const scene_mesh *m;
        const scene_texture *t;
        double sum = 0;
        uint32_t k;
        if (o->material < 0 || o->mesh < 0 || !s->materials[o->material].displace ||
            s->materials[o->material].height < 0)
            continue;
        m = &s->meshes[o->mesh];
        t = &s->textures[s->materials[o->material].height];
        if (!m->uvs || !m->triangle_count)
            continue;
        for (k = 0; k < 3 * m->triangle_count; k++) {
            uint32_t a = m->indices[k], b = m->indices[k % 3 == 2 ? k - 2 : k + 1];
            double du = m->uvs[2 * a] - m->uvs[2 * b], dv = m->uvs[2 * a + 1] - m->uvs[2 * b + 1];
            sum += sqrt(du * du + dv * dv);
        }
        if (sum / (3.0 * m->triangle_count) * (t->width > t->height ? t->width : t->height) >
            DISP_COARSE_TEXELS)
            return 1;
    }
    return 0;
}

static void case_free(disp_case *c, const scene *source)
{
    free(c->hits);
    free(c->flat_hits);
    free(c->ref);
    if (c->ds.meshes)
        reference_displace_free(&c->ds, source);
}

/* The mip chain: up close level 0 alone (on and off identical); from afar
 * the levels stin picks by distance, against the reference that reads the
 * same levels, and different from level 0 alone. */
static void test_mips(disp_case *c)
{
    scene far = *c->s;
    disp_case f = *c;
    reference_displace_lod lod;
    capture_options o;
    capture on, off;
    compare_result cr;
    char name[256], err[512];
    double match, match_off;
    long near_differ, far_differ;
    int k;
    name_of(c, "mip-near", name, sizeof name);
    base_options(c, &o, STIN_TECH_SHADOWS_OFF);
    if (!render(c, c->s, &o, &on, "mip-near"))
        return;
    o.debug_flags = STIN_DEBUG_DISPLACE_NO_MIP;
    if (!render(c, c->s, &o, &off, "mip-near")) {
        capture_free(&on);
        return;
    }
    near_differ = pixels_differ(&on, &off);
    report(c->r, near_differ == 0 ? "PASS" : "FAIL", name,
           "the scene's own view with and without the mip chain: %ld pixels differ (need 0)",
           near_differ);
    capture_free(&on);
    capture_free(&off);
    for (k = 0; k < 3; k++)
        far.camera.eye[k] = far.camera.target[k] + DISP_MIP_FAR * (far.camera.eye[k] - far.camera.target[k]);
    memset(&lod, 0, sizeof lod);
    lod.pixels_per_unit = 0.5 * c->r->height / tan(far.camera.fovy_deg * (3.14159265358979 / 360.0));
    lod.perspective = 1;
    for (k = 0; k < 3; k++)
        lod.eye[k] = far.camera.eye[k];
    f.s = &far;
    memset(&f.ds, 0, sizeof f.ds);
    f.hits = f.flat_hits = NULL;
    f.ref = NULL;
    name_of(c, "mip-far", name, sizeof name);
    if (!setup(&f, 1, &lod, err, sizeof err)) {
        report(c->r, "FAIL", name, "reference: %s", err);
        case_free(&f, &far);
        return;
    }
    o.debug_flags = 0;
    if (render(c, &far, &o, &on, "mip-far")) {
        o.debug_flags = STIN_DEBUG_DISPLACE_NO_MIP;
        if (render(c, &far, &o, &off, "mip-far")) {
            match = position_match(&f, &on, &cr);
            match_off = position_match(&f, &off, &cr);
            far_differ = pixels_differ(&on, &off);
            report(c->r, match >= DISP_P_MIN_MATCH && far_differ > 0 ? "PASS" : "FAIL", name,
                   "camera %.0fx as far: P matches the mipped reference on %.3f%% of %ld covered "
                   "pixels (need %.1f%%; level 0 alone: %.3f%%), %ld pixels differ from level 0 "
                   "alone (need > 0)", DISP_MIP_FAR, 100.0 * match, cr.covered,
                   100.0 * DISP_P_MIN_MATCH, 100.0 * match_off, far_differ);
            capture_free(&off);
        }
        capture_free(&on);
    }
    case_free(&f, &far);
}

/* Level 1 everywhere: the tessellated programs draw the VTF surface. */
static void test_tess_level1(disp_case *c)
{
    capture_options o;
    capture tess, vtf;
    char name[256];
    long n;
    name_of(c, "tess-level1", name, sizeof name);
    if (!c->tessellation) {
        report(c->r, "SKIP", name, "the context has no tessellation shaders (GL 4.0)");
        return;
    }
    c->displacement = STIN_TECH_DISPLACEMENT_VTF;
    base_options(c, &o, STIN_TECH_SHADOWS_VDSM);
    if (!render(c, c->s, &o, &vtf, "tess-level1"))
        return;
    o.displacement = STIN_TECH_DISPLACEMENT_TESS;
    o.tess_pixels = 1e6f;
    if (!render(c, c->s, &o, &tess, "tess-level1")) {
        capture_free(&vtf);
        return;
    }
    {
        size_t i, px = (size_t)tess.img.width * tess.img.height;
        double worst = 0;
        n = 0;
        for (i = 0; i < px; i++) {
            double d = 0;
            int k;
            for (k = 0; k < AOV_CHANNELS; k++) {
                double e = fabs((double)tess.img.pixels[i * AOV_CHANNELS + k] -
                                vtf.img.pixels[i * AOV_CHANNELS + k]);
                d = e > d ? e : d;
            }
            worst = d > worst ? d : worst;
            n += d > DISP_LEVEL1_EPS;
        }
        report(c->r, n == 0 ? "PASS" : "FAIL", name,
               "displace-tess at level 1 vs displace (vdsm shadows): %ld pixels differ by more "
               "than one 8-bit level in any AOV (need 0); largest difference %g, %ld differ at all", n, worst,
               pixels_differ(&tess, &vtf));
    }
    capture_free(&tess);
    capture_free(&vtf);
}

/* A coarse scene under "displace-tess" against the tessellated limit. */
static void tess_tests(disp_case *c)
{
    capture_options o;
    capture cap;
    compare_result cr;
    char name[256];
    double match;
    name_of(c, "tess", name, sizeof name);
    if (!c->tessellation) {
        report(c->r, "SKIP", name, "the context has no tessellation shaders (GL 4.0)");
        return;
    }
    c->displacement = STIN_TECH_DISPLACEMENT_TESS;
    base_options(c, &o, STIN_TECH_SHADOWS_OFF);
    if (!render(c, c->s, &o, &cap, "tess-position"))
        return;
    name_of(c, "tess-gl-clean", name, sizeof name);
    capture_report_clean(c->r, name, &cap);
    test_position(c, &cap, "tess-position");
    test_silhouette(c, &cap, "tess-silhouette");
    {
        long n = cracks(c, &cap);
        name_of(c, "tess-cracks", name, sizeof name);
        report(c->r, n == 0 ? "PASS" : "FAIL", name,
               "%ld background pixels inside the limit's coverage (need 0)", n);
    }
    capture_free(&cap);
    test_shadow(c, STIN_TECH_SHADOWS_MAP_PCF, DISP_PCF_TESS_MAX, "tess-");
    test_shadow(c, STIN_TECH_SHADOWS_VOLUME, DISP_PCF_TESS_MAX, "tess-");
    test_shadow(c, STIN_TECH_SHADOWS_VDSM, DISP_VDSM_MAX, "tess-");
    c->displacement = STIN_TECH_DISPLACEMENT_VTF;
    base_options(c, &o, STIN_TECH_SHADOWS_OFF);
    if (!render(c, c->s, &o, &cap, "vtf-coarse"))
        return;
    match = position_match(c, &cap, &cr);
    name_of(c, "vtf-coarse", name, sizeof name);
    report(c->r, match < DISP_VTF_COARSE_MAX ? "PASS" : "FAIL", name,
           "displace without tessellation matches the limit on %.2f%% of %ld pixels (must "
           "stay below %.0f%%: the coarse scene needs tessellation)", 100.0 * match, cr.covered,
           100.0 * DISP_VTF_COARSE_MAX);
    capture_free(&cap);
}

/* A case of "displace" on the scene at path, its rows named after it. */
static void case_begin(disp_case *c, run *r, stin_tier tier, const char *path)
{
    memset(c, 0, sizeof *c);
    c->r = r;
    c->tier = tier;
    c->displacement = STIN_TECH_DISPLACEMENT_VTF;
    snprintf(c->prefix, sizeof c->prefix, "%s/%s/displace", stin_tier_name(tier),
             scene_base_name(path));
}

void displace_frame_rows(run *r, stin_tier tier, const char *path, const capture *cap)
{
    disp_case c;
    scene s;
    char err[512];
    case_begin(&c, r, tier, path);
    c.s = &s;
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", c.prefix, "%s", err);
        return;
    }
    if (coarse_scene(&s))
        report(r, "SKIP", c.prefix, "a coarse mesh: a tessellation scene (displace-tess, GL4)");
    else if (!setup(&c, 1, NULL, err, sizeof err))
        report(r, "FAIL", c.prefix, "reference: %s", err);
    else {
        test_position(&c, cap, "position");
        test_silhouette(&c, cap, "silhouette");
    }
    case_free(&c, &s);
    scene_free(&s);
}

void displace_tests(run *r, stin_tier tier, const char *path)
{
    disp_case c;
    scene s;
    capture_options o;
    capture cap;
    char err[512], name[256];
    case_begin(&c, r, tier, path);
    if (tier == STIN_TIER_GL1) {
        report(r, "SKIP", c.prefix, "displace is GLSL only (vertex texture fetch)");
        return;
    }
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", c.prefix, "%s", err);
        return;
    }
    c.s = &s;
    base_options(&c, &o, STIN_TECH_SHADOWS_OFF);
    o.displacement = STIN_TECH_NONE;
    if (render(&c, &s, &o, &cap, "position")) {
        int vtf = (cap.caps_present & STIN_CAP_BIT(STIN_CAP_VERTEX_TEXTURE_FETCH)) != 0;
        const uint64_t cast_map = STIN_CAP_BIT(STIN_CAP_FBO) |
                                  STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE);
        c.tessellation = (cap.caps_present & STIN_CAP_BIT(STIN_CAP_TESSELLATION)) != 0;
        c.cast_map = (cap.caps_present & cast_map) == cast_map;
        if (vtf)
            displace_seed_tests(r, tier, cap.caps_present);
        capture_free(&cap);
        if (!vtf) {
            report(r, "SKIP", c.prefix, "the context has no vertex texture units");
            scene_free(&s);
            return;
        }
    }
    if (coarse_scene(&s) && tier != STIN_TIER_GL4) {
        report(r, "SKIP", c.prefix, "a coarse mesh: a tessellation scene (displace-tess, GL4)");
        goto done;
    }
    if (!setup(&c, coarse_scene(&s) ? DISP_LIMIT_SPLIT : 1, NULL, err, sizeof err)) {
        report(r, "FAIL", c.prefix, "reference: %s", err);
        goto done;
    }
    if (coarse_scene(&s)) {
        tess_tests(&c);
        goto done;
    }
    base_options(&c, &o, STIN_TECH_SHADOWS_OFF);
    if (render(&c, &s, &o, &cap, "position")) {
        name_of(&c, "gl-clean", name, sizeof name);
        capture_report_clean(r, name, &cap);
        test_position(&c, &cap, "position");
        test_silhouette(&c, &cap, "silhouette");
        capture_free(&cap);
    }
    o.debug_flags = STIN_DEBUG_DISPLACE_MANUAL_BILINEAR;
    if (render(&c, &s, &o, &cap, "manual-bilinear")) {
        test_position(&c, &cap, "manual-bilinear");
        capture_free(&cap);
    }
    test_shadow(&c, STIN_TECH_SHADOWS_MAP_PCF, DISP_PCF_MAX, "");
    test_shadow(&c, STIN_TECH_SHADOWS_VOLUME, DISP_PCF_MAX, "");
    if (tier == STIN_TIER_GL4)
        test_shadow(&c, STIN_TECH_SHADOWS_VDSM, DISP_VDSM_MAX, "");
    test_fallback(&c);
    test_guard_band(&c);
    test_mips(&c);
    if (tier == STIN_TIER_GL4)
        test_tess_level1(&c);
done:
    case_free(&c, &s);
    scene_free(&s);
}
