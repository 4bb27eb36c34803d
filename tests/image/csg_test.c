/* SPDX-License-Identifier: MIT */
/*
 * CSG products ("goldfeather", src/csg/goldfeather.c; "scs", csg/scs.c;
 * "interval", csg/interval.c) against the exact CSG
 * reference (tests/reference/reference_csg.h: every crossing of the camera
 * ray with the primitives, the expression evaluated along it). Run on
 * csg.json (carved, both, common) and the scenes of tests/scenes/csg/
 * beside it (eye-cavity: the eye inside a subtracted sphere, parity counted
 * from behind; eye-cut: the near plane inside the solid, capped; row: one
 * mesh of two spheres in a row minus a slab around the front one;
 * torus-far: a torus intersected with a box around its far half), at every
 * tier the profile runs:
 *   P           within 1e-3 Z + 1e-3 (image_test.c's tolerance: 24-bit
 *               depth) on >= 99.9% of the pixels covered in the render or
 *               the reference (a pixel covered in one only counts against:
 *               a union that paints the background, or a hole, fails here);
 *   N           within 2 degrees on >= 99.5% of the matching pixels away
 *               from edges between primitives (8-bit normal output); the
 *               inside walls of complemented primitives face the eye;
 *   union-equals  the union of two spheres: its P equals the depth-tested
 *               pair drawn as ordinary objects on >= 99.9% of the covered
 *               pixels (within the same tolerance);
 *   shadow      (shadowed.json) light 0's visibility on the matching pixels
 *               that face the light, 2 pixels or more from a reference
 *               shadow edge, within the shadow technique's bound (1% for
 *               the maps and for the exact techniques casting through
 *               their map, 0.5% for volumes, none for vdsm) against the
 *               reference's rays: with the product casting (its walls
 *               shadow the cavity; csg/cast.c, shadow/vdsm_csg.c, and
 *               shadow/cast_map.c for volumes on the GLSL tiers and vdsm
 *               without GL 4.3's storage buffers), for volumes on GL1,
 *               which cast no product, through it; with
 *               at least 100
 *               shadowed pixels of the product compared;
 *   gpu-resolve (GLSL tiers; interval on row and torus-far) the GPU resolve
 *               ran (stin_frame_stats.csg.gpu_resolves) and its image equals
 *               the read-back resolve's (STIN_DEBUG_CSG_READBACK), every
 *               channel, on all but 0.05% of the covered pixels: it
 *               rasterises the candidates in its own buffer, whose coverage
 *               of a pixel an edge passes through exactly can differ from
 *               the frame's (Mesa draws window-system buffers upside down);
 *               measured 0-2 pixels a case;
 *   in-place    (scs, GLSL tiers) a product of one term resolved in the
 *               frame's own buffers (stin_frame_stats.csg.in_place), one
 *               of two terms not but direct (csg.direct: each candidate
 *               snapped into the frame's depth), and the image equal to
 *               the work buffer's merge and snap (STIN_DEBUG_CSG_NO_IN_PLACE)
 *               on all but 0.05% of the covered pixels (gpu-resolve's
 *               bound); SKIP under the packed resolve (no variants);
 *   direct      (goldfeather, GLSL tiers) its GPU resolve direct
 *               (csg.direct = 1), whose image gpu-resolve checks; without
 *               depth textures (bare OpenGL ES 2.0) packed instead
 *               (csg.packed = 1), whose image P and N check;
 *   gl-clean    no GL error, no call outside the profile, no logged error.
 * Every case runs under goldfeather, scs ("csg-scs-") and interval
 * ("csg-interval-"; GL4 only, SKIP elsewhere). Under interval also:
 *   resolved    stin_frame_stats.csg.interval_products = 1;
 *   agrees      P against goldfeather's, pixel by pixel, on >= 99.9% of the
 *               covered pixels (the same P bound: both take the surface's
 *               depth from the frame's own depth buffer, so they differ
 *               only where the two choose different crossings, at
 *               silhouettes);
 *   one-interval-fails  (row: two spheres in a row; torus-far: a torus seen
 *               through its near half) the seed's one interval per operand
 *               (STIN_DEBUG_CSG_INTERVAL_ONE_LAYER) must match the
 *               reference on < 99% of the covered pixels;
 *   overflow    (the same two) k = 2 (STIN_DEBUG_CSG_INTERVAL_TWO_LAYERS)
 *               finds a primitive with more crossings, resolves nothing,
 *               logs it, and goldfeather's image still meets P.
 * Contexts without the technique's needs (a stencil buffer; glDrawPixels
 * or GL4 lighting to write the depth back) report SKIP with the reason.
 */
#include "aov.h"
#include "capture.h"
#include "compare.h"
#include "image_test.h"
#include "light_reach.h"
#include "reference.h"
#include "reference_csg.h"
#include "scene_gpu.h"
#include "test_context.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CSG_P_RELATIVE 1e-3
#define CSG_P_ABSOLUTE 1e-3
#define CSG_P_MIN_MATCH 0.999
#define CSG_NORMAL_DEGREES 2.0
#define CSG_NORMAL_MIN_MATCH 0.995
#define CSG_VIS_MAP_MAX 0.01
#define CSG_VIS_VOLUME_MAX 0.005
#define CSG_VIS_VDSM_MAX 0.0 /* exact: its position buffer holds the products' surfaces */

static const stin_csg_node minus[] = {
    {STIN_CSG_PRIMITIVE, 0, 0, 0}, {STIN_CSG_PRIMITIVE, 1, 0, 0}, {STIN_CSG_SUBTRACTION, 0, 0, 1}};
static const stin_csg_node both[] = {
    {STIN_CSG_PRIMITIVE, 0, 0, 0}, {STIN_CSG_PRIMITIVE, 1, 0, 0}, {STIN_CSG_UNION, 0, 0, 1}};
static const stin_csg_node common[] = {
    {STIN_CSG_PRIMITIVE, 0, 0, 0}, {STIN_CSG_PRIMITIVE, 1, 0, 0},
    {STIN_CSG_INTERSECTION, 0, 0, 1}};

/* A case: a scene file (relative to csg.json's folder), the objects that
 * are its two primitives, the expression. */
typedef struct csg_case {
    const char *name, *file;
    int objects[2];
    const stin_csg_node *nodes;
    int shadows;   /* test light 0's visibility too */
    int union_equals; /* compare with the ordinary depth-tested render */
    int convex;       /* scs resolves it (else it falls back: a primitive is not convex,
                       * or the near plane cuts one) */
} csg_case;

static const csg_case cases[] = {
    {"carved", "csg.json", {0, 1}, minus, 0, 0, 1},
    {"both", "csg.json", {0, 1}, both, 0, 0, 1},
    {"common", "csg.json", {0, 1}, common, 0, 0, 1},
    {"inside", "csg/inside.json", {0, 1}, minus, 0, 0, 1},
    {"union", "csg/spheres.json", {0, 1}, both, 0, 1, 1},
    {"lens", "csg/spheres.json", {0, 1}, common, 0, 0, 1},
    {"torus-groove", "csg/torus.json", {0, 1}, minus, 0, 0, 0},
    {"torus-cut", "csg/torus.json", {1, 0}, common, 0, 0, 0},
    {"coplanar", "csg/coplanar.json", {0, 1}, minus, 0, 0, 1},
    {"shadowed", "csg/shadowed.json", {0, 1}, minus, 1, 0, 1},
    {"eye-cavity", "csg/eye-cavity.json", {0, 1}, minus, 0, 0, 0},
    {"eye-cut", "csg/eye-cut.json", {0, 1}, minus, 0, 0, 0},
    {"eye-tunnel", "csg/eye-tunnel.json", {0, 1}, minus, 0, 0, 0},
    {"row", "csg/row.json", {0, 1}, minus, 0, 0, 0},
    {"torus-far", "csg/torus-far.json", {0, 1}, common, 0, 0, 0},
};

/* Cases where one interval per operand (the seed's method) is wrong: a
 * non-convex operand seen through itself (torus-far) or bodies behind each
 * other (row). torus-groove and torus-cut are non-convex too, but their
 * rays seldom need a second interval (one interval matches there on
 * 99.99% of the pixels). */
static int non_convex_along_rays(const csg_case *c)
{
    return strcmp(c->name, "torus-far") == 0 || strcmp(c->name, "row") == 0;
}

/* goldfeather's names as they were; scs's with "scs-" in front */
static void case_name(const csg_case *c, stin_technique t, stin_tier tier, const char *test,
                      char *out, size_t n)
{
    snprintf(out, n, "%s/csg-%s%s/%s", stin_tier_name(tier),
             t == STIN_TECH_CSG_SCS        ? "scs-"
             : t == STIN_TECH_CSG_INTERVAL ? "interval-"
                                           : "",
             c->name, test);
}

/* The reference image of the case: P, N, Z and light 0's visibility. */
static float *reference_image(const scene *s, reference *ref, const ref_hit *hits, int w, int h)
{
    float *img = calloc((size_t)w * h * REFERENCE_CHANNELS, sizeof *img);
    size_t i;
    if (!img)
        return NULL;
    for (i = 0; i < (size_t)w * h; i++) {
        float *p = img + i * REFERENCE_CHANNELS;
        const ref_hit *hit = &hits[i];
        int k;
        p[REFERENCE_CH_VIS_R] = p[REFERENCE_CH_VIS_G] = p[REFERENCE_CH_VIS_B] = 1.0f;
        if (!hit->hit)
            continue;
        reference_shade(s, NULL, hit, 0, p + REFERENCE_CH_R);
        for (k = 0; k < 3; k++) {
            p[REFERENCE_CH_PX + k] = hit->P[k];
            p[REFERENCE_CH_NX + k] = hit->N[k];
        }
        p[REFERENCE_CH_Z] = hit->t;
        if (s->light_count)
            p[REFERENCE_CH_VIS_R] = p[REFERENCE_CH_VIS_G] = p[REFERENCE_CH_VIS_B] =
                reference_light_visibility(ref, hit, 0);
    }
    return img;
}

static int render(run *r, const scene *s, const capture_options *o, capture *cap,
                  const char *name)
{
    char err[512];
    if (capture_render(r->plat, r->profile, s, o, cap, err, sizeof err))
        return 1;
    report(r, "FAIL", name, "render failed: %s", err);
    return 0;
}

/* Two renders' P pixel by pixel: covered in both and within the tolerance
 * on >= 99.9% of the pixels either covers. */
static void p_agree(run *r, const char *name, const capture *a_cap, const capture *b_cap,
                    const char *what)
{
    long covered = 0, differ = 0;
    int i;
    for (i = 0; i < r->width * r->height; i++) {
        const float *a = a_cap->img.pixels + (size_t)i * AOV_CHANNELS;
        const float *b = b_cap->img.pixels + (size_t)i * AOV_CHANNELS;
        double d2 = 0, limit = CSG_P_RELATIVE * b[AOV_Z] + CSG_P_ABSOLUTE;
        int k, ca = a[AOV_Z] > 0.0f, cb = b[AOV_Z] > 0.0f;
        if (!ca && !cb)
            continue;
        covered++;
        for (k = 0; k < 3; k++)
            d2 += (a[AOV_PX + k] - b[AOV_PX + k]) * (a[AOV_PX + k] - b[AOV_PX + k]);
        differ += ca != cb || d2 > limit * limit;
    }
    report(r, covered && differ <= (1.0 - CSG_P_MIN_MATCH) * covered ? "PASS" : "FAIL", name,
           "P differs from %s on %ld of %ld covered pixels (need <= %.1f%%)", what, differ,
           covered, 100.0 * (1.0 - CSG_P_MIN_MATCH));
}

/* The GPU resolve (GLSL tiers: no read-backs) against the CPU's
 * (STIN_DEBUG_CSG_READBACK) on the same product: the GPU resolve ran, and
 * the two images are the same, depth and colour, but on edge pixels (both
 * end with the faces' own rasterised depth in the frame). */
#define CSG_GPU_MAX_DIFFER 0.0005
typedef struct image_differ {
    long differ, depth_differ, covered;
} image_differ;

static image_differ differ_of(const run *r, const capture *a_cap, const capture *b_cap)
{
    image_differ d = {0, 0, 0};
    int i, k;
    for (i = 0; i < r->width * r->height; i++) {
        const float *a = a_cap->img.pixels + (size_t)i * AOV_CHANNELS;
        const float *b = b_cap->img.pixels + (size_t)i * AOV_CHANNELS;
        int same = 1;
        for (k = 0; k < AOV_CHANNELS; k++)
            same &= a[k] == b[k] || (a[k] != a[k] && b[k] != b[k]);
        d.differ += !same;
        d.depth_differ += a[AOV_Z] != b[AOV_Z];
        d.covered += a[AOV_Z] > 0.0f || b[AOV_Z] > 0.0f;
    }
    return d;
}

static void test_gpu_resolve(run *r, const csg_case *c, stin_technique t, stin_tier tier,
                             const scene *s, const capture_options *base, const capture *cap)
{
    capture_options o = *base;
    capture cpu;
    char name[256];
    image_differ d;
    case_name(c, t, tier, "gpu-resolve", name, sizeof name);
    if (tier == STIN_TIER_GL1) {
        report(r, "SKIP", name, "the GL1 tier resolves with read-backs (no GLSL)");
        return;
    }
    if (capture_report_gpu_alone(r, name, cap, "no read-back resolve to compare with"))
        return;
    o.debug_flags |= STIN_DEBUG_CSG_READBACK;
    if (!render(r, s, &o, &cpu, name))
        return;
    d = differ_of(r, cap, &cpu);
    report(r,
           cap->stats.csg.gpu_resolves == 1 && cpu.stats.csg.gpu_resolves == 0 && d.covered &&
                   d.differ <= CSG_GPU_MAX_DIFFER * d.covered
               ? "PASS"
               : "FAIL",
           name, "GPU resolve ran: %s (%llu bytes of GL memory), the read-back one ran: %s; the "
           "images differ on %ld of %ld covered pixels (depth on %ld; need <= %.2f%%)",
           cap->stats.csg.gpu_resolves ? "yes" : "no",
           (unsigned long long)cap->stats.csg.gpu_bytes,
           cpu.stats.csg.gpu_resolves ? "no" : "yes", d.differ, d.covered, d.depth_differ,
           100.0 * CSG_GPU_MAX_DIFFER);
    capture_free(&cpu);
}

/* scs's GPU resolve in place (one term in the frame's own buffers) where
 * the product has one term, direct otherwise (each candidate snapped into
 * the frame's depth), against the work buffer's merge and snap
 * (STIN_DEBUG_CSG_NO_IN_PLACE): the same image but on edge pixels, as
 * gpu-resolve. */
static void test_in_place(run *r, const csg_case *c, stin_tier tier, const scene *s,
                          const capture_options *base, const capture *cap)
{
    capture_options o = *base;
    capture merged;
    char name[256];
    image_differ d;
    unsigned in_place = c->convex && cap->stats.csg.terms == 1;
    case_name(c, STIN_TECH_CSG_SCS, tier, "in-place", name, sizeof name);
    if (tier == STIN_TIER_GL1) {
        report(r, "SKIP", name, "the GL1 tier resolves with read-backs (no GLSL)");
        return;
    }
    if (cap->stats.csg.packed) { /* direct's test checks it ran */
        report(r, "SKIP", name, "the packed resolve (no depth textures) has no in-place or "
               "work-buffer variant");
        return;
    }
    o.debug_flags |= STIN_DEBUG_CSG_NO_IN_PLACE;
    if (!render(r, s, &o, &merged, name))
        return;
    d = differ_of(r, cap, &merged);
    report(r,
           cap->stats.csg.in_place == in_place && cap->stats.csg.direct == !in_place &&
                   merged.stats.csg.in_place == 0 && merged.stats.csg.direct == 0 &&
                   merged.stats.csg.gpu_resolves == 1 && d.covered &&
                   d.differ <= CSG_GPU_MAX_DIFFER * d.covered
               ? "PASS"
               : "FAIL",
           name, "in place: %u (want %u: %u terms), direct: %u, with the flag: %u and %u; the "
           "images differ on %ld of %ld covered pixels (depth on %ld; need <= %.2f%%)",
           cap->stats.csg.in_place, in_place, cap->stats.csg.terms, cap->stats.csg.direct,
           merged.stats.csg.in_place, merged.stats.csg.direct, d.differ, d.covered,
           d.depth_differ, 100.0 * CSG_GPU_MAX_DIFFER);
    capture_free(&merged);
}

/* goldfeather's GPU resolve is direct on every case (its image against the
 * read-back resolve's is gpu-resolve's test; the merge and snap it replaces
 * are in-place's baseline under scs). */
static void test_direct(run *r, const csg_case *c, stin_tier tier, const capture *cap)
{
    char name[256];
    unsigned packed;
    case_name(c, STIN_TECH_CSG_GOLDFEATHER, tier, "direct", name, sizeof name);
    if (tier == STIN_TIER_GL1) {
        report(r, "SKIP", name, "the GL1 tier resolves with read-backs (no GLSL)");
        return;
    }
    /* without depth textures (bare OpenGL ES 2.0) the packed resolve instead */
    packed = !(cap->caps_present & STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE));
    report(r,
           cap->stats.csg.direct == !packed && cap->stats.csg.packed == packed &&
                   cap->stats.csg.in_place == 0 && cap->stats.csg.gpu_resolves == 1
               ? "PASS"
               : "FAIL",
           name,
           "direct: %u (want %u), packed: %u (want %u: %s), in place: %u (want 0), GPU "
           "resolve: %u (want 1)",
           cap->stats.csg.direct, !packed, cap->stats.csg.packed, packed,
           packed ? "no depth textures" : "depth textures", cap->stats.csg.in_place,
           cap->stats.csg.gpu_resolves);
}

/* The ordinary render's P against the union's. */
static void test_union_equals(run *r, const csg_case *c, stin_technique t, stin_tier tier,
                              const scene *s, const capture *csg)
{
    capture_options o;
    capture plain;
    char name[256];
    case_name(c, t, tier, "union-equals", name, sizeof name);
    memset(&o, 0, sizeof o);
    o.tier = tier;
    if (!render(r, s, &o, &plain, name))
        return;
    p_agree(r, name, csg, &plain, "the depth-tested pair");
    capture_free(&plain);
}

/* scs or interval (t) against goldfeather on the same product. */
static void test_agree(run *r, const csg_case *c, stin_technique t, stin_tier tier,
                       const scene *s, const capture_options *base, const capture *cap)
{
    capture_options o = *base;
    capture gold;
    char name[256];
    case_name(c, t, tier, "agrees", name, sizeof name);
    o.csg_technique = STIN_TECH_CSG_GOLDFEATHER;
    if (!render(r, s, &o, &gold, name))
        return;
    p_agree(r, name, cap, &gold, "goldfeather's");
    capture_free(&gold);
}

/* scs resolved a convex product itself, and handed a non-convex one to
 * goldfeather with a logged reason. */
static void test_scs_used(run *r, const csg_case *c, stin_tier tier, const capture *cap)
{
    char name[256];
    case_name(c, STIN_TECH_CSG_SCS, tier, c->convex ? "resolved" : "falls-back", name,
              sizeof name);
    if (c->convex)
        report(r, cap->stats.csg.scs_products == 1 ? "PASS" : "FAIL", name,
               "%u of 1 products resolved by scs", cap->stats.csg.scs_products);
    else
        report(r,
               cap->stats.csg.scs_products == 0 && cap->log_fallbacks &&
                       strstr(cap->fallbacks, "scs: ")
                   ? "PASS"
                   : "FAIL",
               name, "%u products resolved by scs (want 0), fallback logged: %s",
               cap->stats.csg.scs_products,
               strstr(cap->fallbacks, "scs: ") ? strstr(cap->fallbacks, "scs: ") : "no");
}

/* Light 0's visibility where P matches, the light reaches the side seen
 * and no reference shadow edge lies within 2 pixels (a map's texels blur
 * edges over that band; image_test.c's other shadow tests do the same). */
static void test_shadow(run *r, const csg_case *c, stin_technique tech, stin_tier tier,
                        const scene *s,
                        const capture_options *base, stin_technique t, const ref_hit *hits,
                        const float *ref_none, const float *ref_cast)
{
    const float *ref;
    int vdsm_casts, via_map;
    double bound = t == STIN_TECH_SHADOWS_VDSM     ? CSG_VIS_VDSM_MAX
                   : t == STIN_TECH_SHADOWS_VOLUME ? CSG_VIS_VOLUME_MAX
                                                   : CSG_VIS_MAP_MAX;
    int w = r->width, h = r->height, x, y;
    long compared = 0, differ = 0, shadowed = 0, on_product = 0;
    char test[64], name[256];
    capture_options o = *base;
    capture one, *cap = &one;
    snprintf(test, sizeof test, "shadow-%s", stin_technique_name(t));
    case_name(c, tech, tier, test, name, sizeof name);
    o.shadows = t;
    if (!capture_forced(r, s, &o, STIN_FEATURE_SHADOWS, t, &one, name))
        return;
    /* vdsm walks products where it has GL 4.3's storage buffers, else casts
     * them through a map of its own; volumes cast through that map (the
     * map's bound then) save on GL1 without multitexture (csg_cast_test.c) */
    vdsm_casts = t == STIN_TECH_SHADOWS_VDSM &&
                 (cap->caps_present & STIN_CAP_BIT(STIN_CAP_COMPUTE));
    via_map = (t == STIN_TECH_SHADOWS_VOLUME && csg_volume_casts(cap)) ||
              (t == STIN_TECH_SHADOWS_VDSM && !vdsm_casts);
    if (via_map)
        bound = CSG_VIS_MAP_MAX;
    ref = t == STIN_TECH_SHADOWS_VOLUME && !via_map ? ref_none : ref_cast;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const ref_hit *hit = &hits[(size_t)y * w + x];
            const float *g = cap->img.pixels + ((size_t)(h - 1 - y) * w + x) * AOV_CHANNELS;
            const float *p = ref + ((size_t)y * w + x) * REFERENCE_CHANNELS;
            double d2 = 0, limit = CSG_P_RELATIVE * p[REFERENCE_CH_Z] + CSG_P_ABSOLUTE;
            int k;
            if (!hit->hit || !(g[AOV_Z] > 0.0f) || !light_reaches(s, hit) ||
                near_shadow_edge(hits, ref, w, h, x, y, 2))
                continue;
            for (k = 0; k < 3; k++)
                d2 += (g[AOV_PX + k] - p[REFERENCE_CH_PX + k]) *
                      (g[AOV_PX + k] - p[REFERENCE_CH_PX + k]);
            if (d2 > limit * limit)
                continue;
            compared++;
            shadowed += p[REFERENCE_CH_VIS_R] < 0.5f;
            on_product += p[REFERENCE_CH_VIS_R] < 0.5f &&
                          (hit->object == c->objects[0] || hit->object == c->objects[1]);
            differ += (g[AOV_VIS_R] >= 0.5f) != (p[REFERENCE_CH_VIS_R] >= 0.5f);
        }
    report(r,
           compared && on_product >= 100 && (double)differ <= bound * (double)compared &&
                   (!vdsm_casts || cap->stats.shadows.vdsm_csg_casts > 0)
               ? "PASS"
               : "FAIL",
           name, "%s: visibility differs on %ld of %ld pixels the light reaches from the %s "
           "reference (%.3f%%, bound %.2f%%; %ld shadowed compared, %ld of them on the product, "
           "need >= 100; %u vdsm casts)",
           stin_technique_name(t), differ, compared, ref == ref_cast ? "casting" : "non-casting",
           compared ? 100.0 * differ / compared : 0.0, 100.0 * bound, shadowed, on_product,
           cap->stats.shadows.vdsm_csg_casts);
    capture_free(&one);
}

/* The fraction of covered pixels whose P matches the reference. */
static double p_match(const scene *s, const capture *cap, const float *refimg,
                      const ref_hit *hits, compare_result *cr)
{
    compare_tolerance tol = {CSG_P_RELATIVE, CSG_P_ABSOLUTE, 1.0, CSG_NORMAL_DEGREES};
    compare_render(s, &cap->img, refimg, hits, &tol, cr);
    return cr->covered ? 1.0 - (double)(cr->p_mismatch + cr->coverage_mismatch) / cr->covered
                       : 0;
}

/* The seed's one interval per operand (interval's debug mode) must fail
 * these cases: P off the reference on more than 1% of the covered pixels
 * (ten times the bound the layered method meets), so the layers matter. */
static void test_one_interval(run *r, const csg_case *c, stin_tier tier, const scene *s,
                              const capture_options *base, const float *refimg,
                              const ref_hit *hits)
{
    capture_options o = *base;
    capture one;
    compare_result cr;
    char name[256];
    double match;
    case_name(c, STIN_TECH_CSG_INTERVAL, tier, "one-interval-fails", name, sizeof name);
    o.debug_flags |= STIN_DEBUG_CSG_INTERVAL_ONE_LAYER;
    if (!render(r, s, &o, &one, name))
        return;
    match = p_match(s, &one, refimg, hits, &cr);
    report(r, one.stats.csg.interval_products == 1 && match < 0.99 ? "PASS" : "FAIL", name,
           "one interval per operand: P matches on %.3f%% of %ld covered pixels (coverage "
           "differs on %ld, P on %ld; must be below 99%% to show the layers matter)",
           100.0 * match, cr.covered, cr.coverage_mismatch, cr.p_mismatch);
    capture_free(&one);
}

/* Two layers where a primitive crosses a ray more often: the overflow is
 * found, the product handed on (logged) and the image still right. */
static void test_overflow(run *r, const csg_case *c, stin_tier tier, const scene *s,
                          const capture_options *base, const float *refimg,
                          const ref_hit *hits)
{
    capture_options o = *base;
    capture two;
    compare_result cr;
    char name[256];
    double match;
    const char *said;
    case_name(c, STIN_TECH_CSG_INTERVAL, tier, "overflow", name, sizeof name);
    o.debug_flags |= STIN_DEBUG_CSG_INTERVAL_TWO_LAYERS;
    if (!render(r, s, &o, &two, name))
        return;
    match = p_match(s, &two, refimg, hits, &cr);
    said = strstr(two.fallbacks, "interval: a primitive crosses");
    report(r,
           two.stats.csg.interval_products == 0 && said && match >= CSG_P_MIN_MATCH ? "PASS"
                                                                                   : "FAIL",
           name, "k = 2: %u products resolved by interval (want 0), overflow logged: %s; P "
           "matches on %.3f%% of %ld covered pixels (need %.1f%%)",
           two.stats.csg.interval_products, said ? "yes" : "no", 100.0 * match, cr.covered,
           100.0 * CSG_P_MIN_MATCH);
    capture_free(&two);
}

static ref_csg_product ref_product_of(const csg_case *c)
{
    ref_csg_product rp;
    rp.objects = c->objects;
    rp.primitive_count = 2;
    rp.nodes = c->nodes;
    rp.node_count = 3;
    return rp;
}

/* The case's reference, CSG marked, its primary hits and image; 0 with a
 * FAIL line under name. The caller frees what is set. */
static int case_reference(run *r, const scene *s, const ref_csg_product *rp, reference **ref,
                          ref_hit **hits, float **img, const char *name)
{
    char err[512];
    int w = r->width, h = r->height;
    *ref = reference_create(s, err, sizeof err);
    *hits = calloc((size_t)w * h, sizeof **hits);
    if (*ref && *hits && reference_csg_mark(*ref, rp, 1) &&
        reference_csg_primary(*ref, rp, 1, w, h, *hits, NULL) &&
        (*img = reference_image(s, *ref, *hits, w, h)) != NULL)
        return 1;
    report(r, "FAIL", name, "reference failed: %s", *ref ? "out of memory or embree" : err);
    return 0;
}

/* P and N of a frame (drawn here or elsewhere: a browser's) against the
 * case's reference image. */
static void p_n_rows(run *r, const csg_case *c, stin_technique tech, stin_tier tier,
                     const scene *s, const capture *cap, const float *refimg, const ref_hit *hits)
{
    compare_result cr;
    compare_tolerance tol = {CSG_P_RELATIVE, CSG_P_ABSOLUTE, 1.0, CSG_NORMAL_DEGREES};
    char name[256];
    double match;
    compare_render(s, &cap->img, refimg, hits, &tol, &cr);
    match = cr.covered ? 1.0 - (double)(cr.p_mismatch + cr.coverage_mismatch) / cr.covered : 0;
    case_name(c, tech, tier, "P", name, sizeof name);
    report(r, cr.covered && match >= CSG_P_MIN_MATCH ? "PASS" : "FAIL", name,
           "P matches the CSG reference on %.3f%% of %ld covered pixels (coverage differs on "
           "%ld, P on %ld; need %.1f%%)", 100.0 * match, cr.covered, cr.coverage_mismatch,
           cr.p_mismatch, 100.0 * CSG_P_MIN_MATCH);
    case_name(c, tech, tier, "N", name, sizeof name);
    csg_report_normals(r, name, &cr, CSG_NORMAL_DEGREES, CSG_NORMAL_MIN_MATCH);
}

void csg_frame_rows(run *r, stin_tier tier, const char *path, const char *case_name_,
                    stin_technique tech, const capture *cap)
{
    const csg_case *c = NULL;
    reference *ref = NULL;
    ref_hit *hits = NULL;
    float *refimg = NULL;
    ref_csg_product rp;
    scene s;
    char err[512];
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
        if (!strcmp(cases[i].name, case_name_) && !strcmp(cases[i].file, "csg.json"))
            c = &cases[i];
    if (!c || !scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", case_name_, "%s", c ? err : "no such case of csg.json");
        return;
    }
    rp = ref_product_of(c);
    if (case_reference(r, &s, &rp, &ref, &hits, &refimg, case_name_))
        p_n_rows(r, c, tech, tier, &s, cap, refimg, hits);
    free(refimg);
    free(hits);
    reference_destroy(ref);
    scene_free(&s);
}

static void run_case(run *r, stin_tier tier, const char *dir, const csg_case *c,
                     stin_technique tech)
{
    char path[1200], err[512], name[256];
    scene s;
    reference *ref = NULL;
    ref_hit *hits = NULL;
    float *refimg = NULL, *refcast = NULL;
    capture cap;
    capture_options o;
    scene_gpu_csg product;
    ref_csg_product rp;
    int w = r->width, h = r->height, have_cap = 0;
    snprintf(path, sizeof path, "%s/%s", dir, c->file);
    case_name(c, tech, tier, "P", name, sizeof name);
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    product.objects = c->objects;
    product.primitive_count = 2;
    product.nodes = c->nodes;
    product.node_count = 3;
    rp = ref_product_of(c);
    memset(&o, 0, sizeof o);
    o.tier = tier;
    o.csg = &product;
    o.csg_count = 1;
    o.csg_technique = tech;
    /* the camera's resolve alone in the stats: volumes (a default) resolve
     * the product from each light too, to cast it (the shadow tests below
     * choose their technique) */
    o.shadows = STIN_TECH_SHADOWS_OFF;
    if (!capture_forced(r, &s, &o, STIN_FEATURE_CSG, tech, &cap, name))
        goto done;
    have_cap = 1;
    if (!case_reference(r, &s, &rp, &ref, &hits, &refimg, name))
        goto done;
    p_n_rows(r, c, tech, tier, &s, &cap, refimg, hits);
    if (c->shadows) {
        static const stin_technique shadow_techniques[] = {
            STIN_TECH_SHADOWS_VOLUME, STIN_TECH_SHADOWS_MAP_PCF, STIN_TECH_SHADOWS_MAP_DEPTH,
            STIN_TECH_SHADOWS_MAP_COMBINE, STIN_TECH_SHADOWS_VDSM};
        size_t k;
        if (!reference_csg_cast(ref, &rp, 1) ||
            !(refcast = reference_image(&s, ref, hits, w, h))) {
            report(r, "FAIL", name, "the casting reference failed (out of memory or embree)");
            goto done;
        }
        for (k = 0; k < sizeof shadow_techniques / sizeof shadow_techniques[0]; k++)
            test_shadow(r, c, tech, tier, &s, &o, shadow_techniques[k], hits, refimg, refcast);
    }
    if (c->union_equals)
        test_union_equals(r, c, tech, tier, &s, &cap);
    if (tech == STIN_TECH_CSG_SCS) {
        test_scs_used(r, c, tier, &cap);
        test_agree(r, c, STIN_TECH_CSG_SCS, tier, &s, &o, &cap);
        test_in_place(r, c, tier, &s, &o, &cap);
    }
    if (tech == STIN_TECH_CSG_GOLDFEATHER)
        test_direct(r, c, tier, &cap);
    if (tech == STIN_TECH_CSG_INTERVAL) {
        case_name(c, tech, tier, "resolved", name, sizeof name);
        report(r, cap.stats.csg.interval_products == 1 ? "PASS" : "FAIL", name,
               "%u of 1 products resolved by interval (%llu bytes of layers)",
               cap.stats.csg.interval_products,
               (unsigned long long)cap.stats.csg.interval_bytes);
        test_agree(r, c, tech, tier, &s, &o, &cap);
        if (non_convex_along_rays(c)) {
            test_one_interval(r, c, tier, &s, &o, refimg, hits);
            test_overflow(r, c, tier, &s, &o, refimg, hits);
        }
    }
    if (tech != STIN_TECH_CSG_INTERVAL || non_convex_along_rays(c))
        test_gpu_resolve(r, c, tech, tier, &s, &o, &cap);
    case_name(c, tech, tier, "gl-clean", name, sizeof name);
    capture_report_clean(r, name, &cap);
done:
    if (have_cap)
        capture_free(&cap);
    free(refimg);
    free(refcast);
    free(hits);
    reference_destroy(ref);
    scene_free(&s);
}

void csg_report_normals(run *r, const char *name, const compare_result *cr, double degrees,
                        double min_match)
{
    report(r,
           cr->normal_compared && cr->normal_over <= (1.0 - min_match) * cr->normal_compared
               ? "PASS"
               : "FAIL",
           name, "N within %.0f degrees on %ld of %ld pixels away from edges (max %.1f; need "
           "%.1f%%)", degrees, cr->normal_compared - cr->normal_over, cr->normal_compared,
           cr->normal_max_deg, 100.0 * min_match);
}

void csg_tests(run *r, stin_tier tier, const char *path)
{
    char dir[1024];
    const char *slash;
    size_t i;
    if (strcmp(scene_base_name(path), "csg") != 0)
        return;
    slash = strrchr(path, '/');
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - path) : 1, slash ? path : ".");
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        run_case(r, tier, dir, &cases[i], STIN_TECH_CSG_GOLDFEATHER);
        run_case(r, tier, dir, &cases[i], STIN_TECH_CSG_SCS);
        run_case(r, tier, dir, &cases[i], STIN_TECH_CSG_INTERVAL);
    }
    csg_many_tests(r, tier);
    csg_cast_tests(r, tier, dir);
}
