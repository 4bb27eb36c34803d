/* SPDX-License-Identifier: MIT */
/*
 * CSG products casting shadows (src/csg/cast.c: the resolve run from the
 * light into its map) against the exact reference with casting products
 * (reference_csg_cast: a visibility ray is blocked where it passes through
 * a product's solid). Scenes: csg/cast.json (a slab with a spherical hole
 * through it, slab minus ball, over a floor, under a spot light: one map)
 * and csg/cast-point.json (the same under a point light: six faces drawn
 * mid-frame, after the camera's resolve), and csg/cast-lamp.json (a lamp
 * shade, a box minus a ball opening through its bottom face, the point
 * light inside both: vdsm's walk starts inside them, the maps resolve
 * from within), and csg/cast-beside.json (the slab under a spot light
 * straight above its hole, an ordinary box casting beside it, a second
 * light so the GLSL tiers' volumes go through the screen mask), and two
 * past vdsm's walk limits: csg/cast-terms.json (cast.json's slab with 66
 * studs unioned onto its top: one product of 67 terms, past 64) and
 * csg/cast-bores.json (the slab drilled through by 139 thin cylinders
 * besides its hole: 141 primitives in one term, past 128; their spots of
 * light on the floor lie within the 2 pixels left out at shadow edges).
 * Each scene's product is its csg list's. Per shadow technique:
 *   cast-<technique>  light 0's visibility on the pixels whose P matches
 *               the reference (csg_test.c's tolerance), that face the light
 *               and lie 2 pixels or more from a reference shadow edge,
 *               differs from the casting reference on at most 1% (the
 *               maps' bound in csg_test.c and image_test.c), with at least
 *               200 of them shadowed by the product alone (lit where it
 *               casts nothing) and 30 lit through its hole (shadowed where
 *               the slab and the ball cast as ordinary meshes): a render
 *               that leaves the product out, or casts its primitives,
 *               fails. The maps must report stin_frame_stats.csg.cast_maps.
 *               The exact techniques cast products through a map of their
 *               own (shadow/cast_map.c) where they cannot themselves:
 *               volumes on the GLSL tiers and on GL1 for every light
 *               (map-depth's test in framebuffer objects, gl21's GL1
 *               tier, or drawn before the frame's clear and copied,
 *               gl14-shadow; map-combine's ramp, gl13-combine; on GL
 *               1.1, gl11, the light's depth images read back and
 *               tested per pixel on the CPU, the log naming
 *               "read-backs": SKIP before, and with that path switched
 *               off every pixel the product decides differs), vdsm
 *               without GL 4.3's storage
 *               buffers (gl33-core) or past its walk's limits (cast-terms,
 *               cast-bores on gl45-core, where the log must say so, and
 *               nowhere else); there the map's bound (1%) holds on
 *               the pixels the product decides (its shadow, and 2 pixels
 *               around it), the technique's own elsewhere (0.5% volumes, 0
 *               vdsm), and the log must name the map. vdsm with storage
 *               buffers walks the others (stin_frame_stats.shadows.
 *               vdsm_csg_casts; none where the map casts). A point
 *               light a map technique hands to volumes (map-combine, or
 *               map-depth without framebuffer objects: gl13-combine,
 *               gl14-shadow) casts the products as volumes do (their map,
 *               marked after the count): held to the casting reference,
 *               the map's 1%, stin_frame_stats.csg.cast_maps > 0 (before,
 *               they cast none and these rows differed on every pixel the
 *               product decides). Where the technique casts no product the
 *               render is held to the reference without casting (volumes'
 *               0.5%) and the log must say why; volumes that cast none
 *               report SKIP with the log's reason when so held.
 *               STIN_DEBUG_CSG_NO_CAST turns casting off: the map rows
 *               fail with it (tested by hand: 8.5% and 16.3%).
 *   cast-<technique>-bands  the same at a 4096 map (map-pcf on gl45-core,
 *               map-depth on gl21's GL1 tier), whose rectangle under the
 *               product outgrows the staging: it must take more bands
 *               than maps.
 *   cast-map-pcf-interval  the same under the interval technique (its
 *               peels and walk from the light), gl45-core.
 * Contexts without a technique report SKIP with the reason. Without depth
 * read-back (es20-ext, WebGL 2) the maps resolve the products on the GPU
 * alone and the rows hold them to the same bounds, volumes' through their
 * map compared in the shader on es20-ext (no shadow compare); bare es20
 * (the packed resolve: no depth texture to resolve in from a light) SKIPs
 * with the GPU-alone reason.
 */
#include "aov.h"
#include "capture.h"
#include "image_test.h"
#include "light_reach.h"
#include "reference.h"
#include "reference_csg.h"
#include "scene_csg.h"
#include "scene_gpu.h"
#include "test_context.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CAST_P_RELATIVE 1e-3
#define CAST_P_ABSOLUTE 1e-3
#define CAST_MAP_MAX 0.01
#define CAST_VOLUME_MAX 0.005
#define CAST_VDSM_MAX 0.0 /* exact away from shadow edges, as vdsm_test.c holds it */
#define CAST_MIN_PRODUCT_SHADOW 200
#define CAST_MIN_HOLE 30
#define CAST_PRODUCT_REACH 2 /* pixels: the map's edge may stray this far */
#define BANDS_MAP_SIZE 4096u
/* interval resolves a light's map under the product texel by texel, so its
 * row's time goes with the map's area: at 512 rather than the default 1024
 * cast-point took 1.1 CPU s instead of 2.9, cast-beside 0.9 instead of 1.8,
 * cast 0.3 instead of 0.6, with the same maps in the same bands, and with
 * casting off (STIN_DEBUG_CSG_NO_CAST) each still fails (8.1-16.3% of the
 * pixels differ; docs/testing.md, "Where make check's time goes"). The
 * others keep the default: cast-lamp's faces outgrow the staging only
 * there (12 bands for 6 maps; 6 at 512), cast-terms and cast-bores save
 * nothing (0.03-0.06 s). */
#define INTERVAL_MAP_SIZE 512u

/* The scenes; past_walk: a product past vdsm's walk limits (128 primitives,
 * 64 terms: include/stin/stin.h), which vdsm casts through the map even
 * with storage buffers; interval_map: the interval row's map size (0:
 * stin's default). */
static const struct cast_scene {
    const char *file;
    int past_walk;
    uint32_t interval_map;
} cast_scenes[] = {{"cast", 0, INTERVAL_MAP_SIZE}, {"cast-point", 0, INTERVAL_MAP_SIZE},
                   {"cast-lamp", 0, 0},                 {"cast-beside", 0, INTERVAL_MAP_SIZE},
                   {"cast-terms", 1, 0},                {"cast-bores", 1, 0}};

/* Per pixel: the reference's hit and light 0's visibility three ways. */
typedef struct truth {
    ref_hit *hits;
    float *vis_cast, *vis_none, *vis_naive; /* products cast; cast nothing; primitives cast */
    float *shadow_ref; /* REFERENCE_CHANNELS per pixel: P, Z and vis_cast (near_shadow_edge) */
} truth;

static void truth_free(truth *t)
{
    free(t->hits);
    free(t->vis_cast);
    free(t->vis_none);
    free(t->vis_naive);
    free(t->shadow_ref);
}

static int truth_make(const scene *s, const scene_gpu_csg *product, int w, int h, truth *t,
                      char *err, size_t n)
{
    size_t i, px = (size_t)w * (size_t)h;
    ref_csg_product rp = {product->objects, product->primitive_count, product->nodes,
                          product->node_count};
    reference *ref = reference_create(s, err, n), *naive = reference_create(s, err, n);
    int ok = 0;
    memset(t, 0, sizeof *t);
    t->hits = calloc(px, sizeof *t->hits);
    t->vis_cast = calloc(px, sizeof(float));
    t->vis_none = calloc(px, sizeof(float));
    t->vis_naive = calloc(px, sizeof(float));
    t->shadow_ref = calloc(px * REFERENCE_CHANNELS, sizeof(float));
    if (!ref || !naive || !t->hits || !t->vis_cast || !t->vis_none || !t->vis_naive ||
        !t->shadow_ref || !reference_csg_mark(ref, &rp, 1) ||
        !reference_csg_primary(ref, &rp, 1, w, h, t->hits, NULL)) {
        snprintf(err, n, "reference failed (memory or embree)");
        goto done;
    }
    for (i = 0; i < px; i++) {
        const ref_hit *hit = &t->hits[i];
        t->vis_none[i] = hit->hit ? reference_light_visibility(ref, hit, 0) : 1.0f;
        t->vis_naive[i] = hit->hit ? reference_light_visibility(naive, hit, 0) : 1.0f;
    }
    if (!reference_csg_cast(ref, &rp, 1)) {
        snprintf(err, n, "reference_csg_cast failed");
        goto done;
    }
    for (i = 0; i < px; i++) {
        const ref_hit *hit = &t->hits[i];
        float *p = t->shadow_ref + i * REFERENCE_CHANNELS;
        int k;
        t->vis_cast[i] = hit->hit ? reference_light_visibility(ref, hit, 0) : 1.0f;
        for (k = 0; k < 3; k++)
            p[REFERENCE_CH_PX + k] = hit->P[k];
        p[REFERENCE_CH_Z] = hit->t;
        p[REFERENCE_CH_VIS_R] = p[REFERENCE_CH_VIS_G] = p[REFERENCE_CH_VIS_B] = t->vis_cast[i];
    }
    ok = 1;
done:
    reference_destroy(ref);
    reference_destroy(naive);
    return ok;
}

/* Whether the product decides a pixel within CAST_PRODUCT_REACH pixels: its
 * truth with the product casting differs from without. */
static int product_near(const truth *tr, int w, int h, int x, int y)
{
    int dx, dy;
    for (dy = -CAST_PRODUCT_REACH; dy <= CAST_PRODUCT_REACH; dy++)
        for (dx = -CAST_PRODUCT_REACH; dx <= CAST_PRODUCT_REACH; dx++) {
            int u = x + dx, v = y + dy;
            size_t j;
            if (u < 0 || v < 0 || u >= w || v >= h)
                continue;
            j = (size_t)v * w + u;
            if ((tr->vis_cast[j] >= 0.5f) != (tr->vis_none[j] >= 0.5f))
                return 1;
        }
    return 0;
}

/* Volumes cast products through their depth map: on the GLSL tiers, and
 * on GL1 with multitexture and either depth textures with shadow compare
 * (map-depth's test, drawn in framebuffer objects or, without them, in the
 * frame's buffer before its clear and copied out) or texture_env_combine
 * (map-combine's ramp of depths), for every kind of light (a point light's
 * six faces each marking its own pyramid); on GL 1.1 (gl11: one texture
 * unit) and wherever GL1 has neither map, through the light's depth
 * images read back and tested per pixel on the CPU
 * (shadow/cast_readback.c): wherever volumes run (they need a stencil). */
int csg_volume_casts(const capture *one)
{
    return (one->caps_present & STIN_CAP_BIT(STIN_CAP_STENCIL)) != 0;
}

/* Volumes' map on the GLSL tiers needs framebuffer objects and depth
 * textures (shadow/cast_map.c; es20-ext, without shadow compare, compares
 * in the shader): bare es20 has no depth textures, so there volumes cast
 * no product. */
static int volume_map_here(const capture *one)
{
    uint64_t need = STIN_CAP_BIT(STIN_CAP_FBO) | STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE);
    return one->choice[STIN_FEATURE_LIGHTING].technique == STIN_TECH_LIGHTING_FIXED ||
           (one->caps_present & need) == need;
}

static void test_cast(run *r, stin_tier tier, const struct cast_scene *c, const scene *s,
                      const scene_gpu_csg *product, const truth *tr, stin_technique t,
                      uint32_t map_size, stin_technique csg)
{
    int w = r->width, h = r->height, x, y, vdsm = t == STIN_TECH_SHADOWS_VDSM,
        volume = t == STIN_TECH_SHADOWS_VOLUME, map = !volume && !vdsm, storage, past;
    long compared = 0, differ = 0, compared_product = 0, differ_product = 0, product_shadow = 0,
         hole = 0;
    int said, cast, ok, logged, via_map, readback;
    char name[256];
    const float *truth_vis;
    double bound;
    capture_options o;
    capture one;
    snprintf(name, sizeof name, "%s/csg-%s/cast-%s%s%s%s", stin_tier_name(tier), c->file,
             stin_technique_name(t), map_size == BANDS_MAP_SIZE ? "-bands" : "", csg ? "-" : "",
             csg ? stin_technique_name(csg) : "");
    memset(&o, 0, sizeof o);
    o.tier = tier;
    o.shadow_map_size = map_size;
    o.csg_technique = csg;
    o.shadows = t;
    o.csg = product;
    o.csg_count = 1;
    if (!capture_forced(r, s, &o, STIN_FEATURE_SHADOWS, t, &one, name))
        return;
    if (one.choice[STIN_FEATURE_CSG].technique == STIN_TECH_CSG_OFF ||
        (csg && one.choice[STIN_FEATURE_CSG].technique != csg)) {
        report(r, "SKIP", name, "no CSG technique runs here (%s)",
               one.choice[STIN_FEATURE_CSG].reason);
        capture_free(&one);
        return;
    }
    if (strstr(one.fallbacks, "the GPU resolve from a light needs depth textures") &&
        capture_report_gpu_alone(r, name, &one, "its products cast no shadow")) {
        capture_free(&one);
        return;
    }
    /* a map casts, and a point light it hands to volumes (map-depth without
     * framebuffer objects, map-combine) casts as volumes do; vdsm walks them
     * where the context has GL 4.3's storage buffers, else casts them
     * through a map of its own; volumes cast through that map on the GLSL
     * tiers */
    said = strstr(one.fallbacks, "CSG products cast no shadow") != NULL;
    cast = map && s->lights[0].type != SCENE_LIGHT_POINT ? 1
           : map || volume ? csg_volume_casts(&one) && (!volume || volume_map_here(&one))
                           : 1;
    storage = (one.caps_present & STIN_CAP_BIT(STIN_CAP_COMPUTE)) != 0;
    past = vdsm && storage && c->past_walk; /* the walk is there but cannot take the product */
    via_map = cast && (volume || (vdsm && (!storage || past)));
    truth_vis = cast ? tr->vis_cast : tr->vis_none;
    bound = cast ? (vdsm ? CAST_VDSM_MAX : CAST_MAP_MAX) : CAST_VOLUME_MAX;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            const ref_hit *hit = &tr->hits[i];
            const float *g = one.img.pixels + ((size_t)(h - 1 - y) * w + x) * AOV_CHANNELS;
            double d2 = 0, limit = CAST_P_RELATIVE * hit->t + CAST_P_ABSOLUTE;
            int k, lit, wrong, by_product;
            if (!hit->hit || !(g[AOV_Z] > 0.0f) || !light_reaches(s, hit) ||
                near_shadow_edge(tr->hits, tr->shadow_ref, w, h, x, y, 2))
                continue;
            for (k = 0; k < 3; k++)
                d2 += (g[AOV_PX + k] - hit->P[k]) * (g[AOV_PX + k] - hit->P[k]);
            if (d2 > limit * limit)
                continue;
            lit = g[AOV_VIS_R] >= 0.5f;
            wrong = lit != (truth_vis[i] >= 0.5f);
            /* under volumes, where the product decides (its shadow, or light
             * through its hole) the map's bound holds; elsewhere the exact one */
            by_product = via_map && product_near(tr, w, h, x, y);
            compared += !by_product;
            differ += wrong && !by_product;
            compared_product += by_product;
            differ_product += wrong && by_product;
            product_shadow += tr->vis_cast[i] < 0.5f && tr->vis_none[i] >= 0.5f;
            hole += tr->vis_cast[i] >= 0.5f && tr->vis_naive[i] < 0.5f;
        }
    if (via_map)
        bound = vdsm ? CAST_VDSM_MAX : CAST_VOLUME_MAX;
    readback = volume && one.choice[STIN_FEATURE_LIGHTING].technique == STIN_TECH_LIGHTING_FIXED &&
               !(one.caps_present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE));
    logged = (!via_map ||
              strstr(one.fallbacks, vdsm       ? "vdsm: CSG products cast through map-pcf"
                                    : readback ? "volume: CSG products cast through read-backs"
                                               : "volume: CSG products cast through map-")) &&
             past == (strstr(one.fallbacks, "is past the walk's limits") != NULL);
    ok = compared && (double)differ <= bound * (double)compared &&
         (double)differ_product <= CAST_MAP_MAX * (double)compared_product &&
         product_shadow >= CAST_MIN_PRODUCT_SHADOW && hole >= CAST_MIN_HOLE && logged &&
         (cast ? (vdsm && !via_map ? one.stats.shadows.vdsm_csg_casts > 0 && !said
                                   : one.stats.csg.cast_maps > 0 &&
                                         (!vdsm || one.stats.shadows.vdsm_csg_casts == 0))
               : said) &&
         (map_size != BANDS_MAP_SIZE || one.stats.csg.cast_bands > one.stats.csg.cast_maps);
    if (ok && !cast && volume) {
        /* nothing casts the products here (held to the non-casting reference) */
        report(r, "SKIP", name, "volume casts no product here (%ld of %ld pixels differ from "
               "the non-casting reference); the log: %s", differ, compared, one.fallbacks);
        capture_free(&one);
        return;
    }
    report(r, ok ? "PASS" : "FAIL", name,
           "%s %s: visibility differs from the %s reference on %ld of %ld pixels (%.3f%%, bound "
           "%.1f%%) and on %ld of %ld pixels where the product decides (%.3f%%, bound %.1f%%); "
           "%ld shadowed by the product alone, %ld lit through its hole (need %d, %d); %u maps "
           "cast into in %u bands, %u vdsm casts; the log %s",
           stin_technique_name(t), cast ? "casts" : "casts no product",
           cast ? "casting" : "non-casting", differ, compared,
           compared ? 100.0 * differ / compared : 0.0, 100.0 * bound, differ_product,
           compared_product, compared_product ? 100.0 * differ_product / compared_product : 0.0,
           100.0 * CAST_MAP_MAX, product_shadow, hole, CAST_MIN_PRODUCT_SHADOW, CAST_MIN_HOLE,
           one.stats.csg.cast_maps, one.stats.csg.cast_bands, one.stats.shadows.vdsm_csg_casts,
           said               ? "says why products cast nothing"
           : !via_map          ? "says nothing of casting"
           : logged && past    ? "names the walk's limits and the map that casts them"
           : logged            ? "names the map that casts them"
                               : "does not name what casts them");
    capture_free(&one);
}

void csg_cast_tests(run *r, stin_tier tier, const char *dir)
{
    static const stin_technique techniques[] = {
        STIN_TECH_SHADOWS_MAP_PCF, STIN_TECH_SHADOWS_MAP_DEPTH, STIN_TECH_SHADOWS_MAP_COMBINE,
        STIN_TECH_SHADOWS_VOLUME, STIN_TECH_SHADOWS_VDSM};
    size_t f, k;
    for (f = 0; f < sizeof cast_scenes / sizeof cast_scenes[0]; f++) {
        const struct cast_scene *c = &cast_scenes[f];
        char path[1200], err[512], name[256];
        scene s;
        scene_csg_products p;
        truth tr;
        snprintf(path, sizeof path, "%s/csg/%s.json", dir, c->file);
        snprintf(name, sizeof name, "%s/csg-%s/reference", stin_tier_name(tier), c->file);
        if (!scene_load(path, &s, err, sizeof err)) {
            report(r, "FAIL", name, "%s", err);
            continue;
        }
        if (!scene_csg_products_build(&s, &p) || p.count != 1) {
            report(r, "FAIL", name, "the scene's csg list is not one product (or no memory)");
            scene_csg_products_free(&p);
            scene_free(&s);
            continue;
        }
        if (!truth_make(&s, &p.products[0], r->width, r->height, &tr, err, sizeof err)) {
            report(r, "FAIL", name, "%s", err);
            truth_free(&tr);
            scene_csg_products_free(&p);
            scene_free(&s);
            continue;
        }
        for (k = 0; k < sizeof techniques / sizeof techniques[0]; k++)
            test_cast(r, tier, c, &s, &p.products[0], &tr, techniques[k], 0, STIN_TECH_NONE);
        /* a 4096 map: the products' rectangle outgrows the staging beside
         * the camera's resolve and goes in bands (once per technique: GLSL
         * maps on gl45-core, map-depth's framebuffer objects and side test,
         * resolved again band by band, on gl21) */
        if (f == 0 && strcmp(r->profile->name, "gl45-core") == 0 && tier == STIN_TIER_GL4)
            test_cast(r, tier, c, &s, &p.products[0], &tr, STIN_TECH_SHADOWS_MAP_PCF,
                      BANDS_MAP_SIZE, STIN_TECH_NONE);
        if (f == 0 && strcmp(r->profile->name, "gl21") == 0 && tier == STIN_TIER_GL1)
            test_cast(r, tier, c, &s, &p.products[0], &tr, STIN_TECH_SHADOWS_MAP_DEPTH,
                      BANDS_MAP_SIZE, STIN_TECH_NONE);
        /* interval resolves from the light too (in the map's resolve
         * framebuffer), both scenes, once: gl45-core */
        if (strcmp(r->profile->name, "gl45-core") == 0 && tier == STIN_TIER_GL4)
            test_cast(r, tier, c, &s, &p.products[0], &tr, STIN_TECH_SHADOWS_MAP_PCF,
                      c->interval_map, STIN_TECH_CSG_INTERVAL);
        truth_free(&tr);
        scene_csg_products_free(&p);
        scene_free(&s);
    }
}
