/* SPDX-License-Identifier: MIT */
/*
 * Camera transparency against the reference's composite (reference.h,
 * reference_composite_pixel: every surface up to the first opaque one,
 * shaded, under-blended front to back), on glass-panes and the scenes of
 * tests/scenes/peel/ beside it (panes: three overlapping single-surface
 * panes under an opaque block; cross: two panes through each other;
 * sorted: panes under two directional lights, for the sorted tests alone):
 *   beauty          shadows off: the beauty (and depth-peel's alpha: 1 - T
 *                   (1 - alpha behind)) within 3/255 of the unshadowed
 *                   composite (8-bit layers and composite: a rounding per
 *                   store, 3/255 as test_scene's beauty) on >= 99.5% of the
 *                   compared pixels, which are covered, seen through at
 *                   least one transparent surface (>= 200 of them) and away
 *                   from edges (no 4-neighbour within `band` pixels whose
 *                   reference colour differs by more than 8/255: outlines
 *                   of every layer, which rasterisation may put one pixel
 *                   either way). depth-peel must pass; "sorted" must pass
 *                   on panes (separate single surfaces) and its error is
 *                   measured (INFO) on glass-panes (boxes: self-overlap)
 *                   and cross (intersecting);
 *   order           depth-peel: the objects drawn in reverse order give a
 *                   bit-identical image;
 *   early-stop      depth-peel with transparency.layers 64 gives the image
 *                   of the default cap, bit for bit, in (the scene's layer
 *                   count + 1) passes; STIN_DEBUG_PEEL_NO_EARLY_STOP gives
 *                   it too, in 64 passes;
 *   cap             depth-peel with transparency.layers 1 differs from the
 *                   full composite (the cap is honoured);
 *   shadowed-T      depth-peel under shadows technique T (volume, map-pcf
 *                   where the profile runs them): the beauty within 3/255 of
 *                   the composite whose layers are shadowed (hard
 *                   visibility) on >= 99.5% of the compared pixels (band 2:
 *                   map-pcf's filtered edges), both as a whole and as the
 *                   reference's layers (C, T) over the frame's own opaque
 *                   image (STIN_DEBUG_TRANSPARENCY_OPAQUE_ONLY: the layers' part
 *                   alone), with >= 50 compared pixels whose nearest surface
 *                   is a transparent one in shadow: panes receive shadows
 *                   (>= 100 compared pixels: shadow edges take more away).
 *                   shadowed-deep (GL4): the same with "deep" for the
 *                   transparent casters (volumes for the opaque ones)
 *                   against the composite lit through each light's
 *                   transmittance (coloured shadows on panes and floor);
 *                   shadowed-vdsm (GL4): the same with vdsm, whose
 *                   position buffer is drawn from each layer; -broken:
 *                   STIN_DEBUG_PEEL_VDSM_UNSHADOWED (layers lit
 *                   unshadowed) must fail;
 *   sorted-shadowed-T  peel/sorted (the panes under two directional lights):
 *                   "sorted" forced under map technique T (map-pcf on
 *                   GL2/GL4; map-depth, map-combine on GL1) against the
 *                   shadowed composite as shadowed-T, at T's usual bound
 *                   (99.5%; GL1's hard maps 98% and 95%, map_test.c's
 *                   bounds); -broken: STIN_DEBUG_SORTED_UNSHADOWED must
 *                   fail;
 *   gl-clean        no GL error, no call outside the profile, no error log.
 * On GL1 the transparency technique is "sorted": the depth-peel tests SKIP.
 * peel-beauty checks the default technique (dual-peel on GL4); order,
 * early-stop, cap and shadowed-T run for depth-peel ("peel-*", its beauty
 * as peel-forced-beauty where it is not the default) and for dual-peel
 * ("dual-peel-*", GL4; early-stop wants n / 2 + 1 passes and, without it,
 * 64 / 2), and:
 *   dual-peel-agrees     dual-peel's image against depth-peel's within
 *                        1/255 on every pixel (the same layers lit the same
 *                        way; only the composite's order of operations
 *                        differs, both in half floats, one 8-bit rounding);
 *   dual-peel-passes-n   (panes, n = 1..4 copies of a pane stacked 0.3
 *                        apart) n layers (depth-peel's transparency.peel_layers) lit by
 *                        dual-peel in n / 2 + 1 passes, and -agrees-n.
 * On GL2 and GL1 the dual-peel tests SKIP (GL4 only).
 */
#include "image_test.h"
#include "reference.h"
#include "scene.h"
#include "scene_gpu.h"
#include "stin/stin_debug.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TOLERANCE (3.0 / 255.0)
#define MIN_MATCH 0.995
#define EDGE_STEP (8.0 / 255.0)
#define MIN_SEEN_THROUGH 200
#define MIN_SHADOWED_PANE 50
#define MIN_SHADOWED_COMPARED 100 /* shadow edges (band 2) leave fewer pixels */
#define HIGH_CAP 64 /* desc.transparency.layers at most */

typedef struct peel_case {
    run *r;
    const scene *s;
    reference *ref;
    const char *scene_name;
    stin_tier tier;
    int per_vertex;
} peel_case;

typedef struct frame_opts {
    stin_technique shadows, transparency;
    uint32_t layers;
    uint64_t debug_flags;
    stin_technique translucent; /* NONE: translucent-solid */
} frame_opts;

typedef struct frame_out {
    uint8_t *rgba;           /* rows bottom to top */
    stin_frame_stats stats;
    stin_choice choice[STIN_FEATURE_COUNT];
    stin_debug_counters counters;
    uint64_t caps_present;
    unsigned errors;
    char last_error[256];
} frame_out;

static void keep_errors(void *user, stin_log_level level, stin_log_item item, const char *msg)
{
    frame_out *o = (frame_out *)user;
    (void)item;
    if (level != STIN_LOG_LEVEL_ERROR)
        return;
    o->errors++;
    snprintf(o->last_error, sizeof o->last_error, "%s", msg);
}

/* One beauty frame of s; 0 with err on failure. */
static int render(const peel_case *c, const scene *s, const frame_opts *fo, frame_out *out,
                  char *err, size_t err_size)
{
    stin_desc d;
    stin_context *ctx = NULL;
    scene_gpu g;
    void *block = NULL;
    size_t size;
    int ok = 0, have_gpu = 0, f;
    memset(out, 0, sizeof *out);
    memset(&d, 0, sizeof d);
    d.get_proc_address = stin_platform_get_proc_address;
    d.get_proc_user = c->r->plat;
    d.log = keep_errors;
    d.log_user = out;
    d.tier = c->tier;
    d.caps_mask = c->r->profile->caps_mask;
    d.max_gl_version = c->r->profile->max_gl_version;
    d.techniques[STIN_FEATURE_SHADOWS] = fo->shadows;
    d.techniques[STIN_FEATURE_TRANSPARENCY] = fo->transparency;
    d.techniques[STIN_FEATURE_TRANSLUCENT_SHADOWS] =
        fo->translucent != STIN_TECH_NONE ? fo->translucent : STIN_TECH_TRANSLUCENT_SOLID;
    d.transparency.layers = fo->layers;
    d.debug_flags = fo->debug_flags;
    scene_gpu_size_desc(s, &d);
    size = stin_memory_size(&d);
    out->rgba = malloc((size_t)4 * c->r->width * c->r->height);
    block = malloc(size);
    if (!out->rgba || !block || stin_create(&d, block, size, &ctx) != STIN_OK) {
        snprintf(err, err_size, "stin_create: %s", out->last_error);
        goto done;
    }
    for (f = 0; f < STIN_FEATURE_COUNT; f++)
        out->choice[f] = stin_query_choice(ctx, (stin_feature)f);
    out->caps_present = stin_query_caps(ctx)->present;
    if (!scene_gpu_create(&g, s, ctx, err, err_size))
        goto done;
    have_gpu = 1;
    if (scene_gpu_frame(&g, ctx, c->r->width, c->r->height, STIN_OUTPUT_BEAUTY,
                        stin_platform_framebuffer(c->r->plat)) != STIN_OK ||
        !stin_platform_read_color(c->r->plat, out->rgba)) {
        snprintf(err, err_size, "frame or readback failed: %s", out->last_error);
        goto done;
    }
    out->stats = stin_query_frame_stats(ctx);
    out->counters = stin_debug_query_counters(ctx);
    ok = 1;
done:
    if (have_gpu)
        scene_gpu_destroy(&g, ctx);
    if (ctx)
        stin_destroy(ctx);
    free(block);
    if (!ok) {
        free(out->rgba);
        out->rgba = NULL;
    }
    return ok;
}

/* The reference composite of every pixel (RGBA, rows bottom to top) and
 * each pixel's transparent layer count. */
typedef struct composite_ref {
    float *rgba;
    float *part;             /* the transparent surfaces' (C, T) */
    int *layers;
    int max_layers;
} composite_ref;

static int reference_of(const peel_case *c, unsigned flags, composite_ref *out)
{
    int w = c->r->width, h = c->r->height, x, y;
    out->rgba = malloc(sizeof(float) * 4 * (size_t)w * h);
    out->layers = malloc(sizeof(int) * (size_t)w * h);
    out->part = malloc(sizeof(float) * 4 * (size_t)w * h);
    out->max_layers = 0;
    if (!out->rgba || !out->layers || !out->part)
        return 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            int n = reference_composite_pixel(c->s, c->ref, w, h, x, y, c->per_vertex, flags,
                                              out->rgba + 4 * i, out->part + 4 * i);
            if (n < 0)
                return 0;
            out->layers[i] = n;
            if (n > out->max_layers)
                out->max_layers = n;
        }
    return 1;
}

static void reference_free(composite_ref *c)
{
    free(c->rgba);
    free(c->part);
    free(c->layers);
}

static double step(const composite_ref *ref, size_t a, size_t b)
{
    double worst = 0;
    int k;
    for (k = 0; k < 3; k++) {
        double d = fabs(ref->rgba[4 * a + k] - ref->rgba[4 * b + k]);
        if (d > worst)
            worst = d;
    }
    return worst;
}

/* 1 where a 4-neighbour's reference colour steps by more than EDGE_STEP. */
static unsigned char *edge_map(const peel_case *c, const composite_ref *ref)
{
    int w = c->r->width, h = c->r->height, x, y;
    unsigned char *e = calloc((size_t)w * h, 1);
    if (!e)
        return NULL;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            if ((x + 1 < w && step(ref, i, i + 1) > EDGE_STEP) ||
                (y + 1 < h && step(ref, i, i + (size_t)w) > EDGE_STEP))
                e[i] = 1;
        }
    return e;
}

static int near_edge(const peel_case *c, const unsigned char *e, int x, int y, int band)
{
    int dx, dy;
    for (dy = -band - 1; dy <= band; dy++) /* an edge flag sits on the lower/left pixel */
        for (dx = -band - 1; dx <= band; dx++) {
            int nx = x + dx, ny = y + dy;
            if (nx >= 0 && ny >= 0 && nx < c->r->width && ny < c->r->height &&
                e[(size_t)ny * c->r->width + nx])
                return 1;
        }
    return 0;
}

typedef struct match {
    long compared, over, seen_through, shadowed_pane;
    double worst, mean;
} match;

/* The render against ref on the pixels seen through a transparent surface
 * away from edges (alpha too where `alpha`); shadowed_pane counts those
 * whose nearest surface is a transparent one the light does not reach. */
static void compare(const peel_case *c, const frame_out *f, const composite_ref *ref,
                    const frame_out *opaque, int band, int alpha, match *m)
{
    int w = c->r->width, h = c->r->height, x, y, k;
    unsigned char *e = edge_map(c, ref);
    ref_hit *hits = malloc(sizeof *hits * (size_t)w * h);
    double sum = 0;
    memset(m, 0, sizeof *m);
    if (!e || !hits || !reference_primary(c->ref, w, h, hits)) {
        free(e);
        free(hits);
        m->over = 1;
        return;
    }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            double worst = 0;
            if (ref->layers[i] < 1 || near_edge(c, e, x, y, band))
                continue;
            m->seen_through++;
            /* alpha against the whole composite: 1 - T (1 - alpha behind) */
            for (k = 0; k < (alpha && !opaque ? 4 : 3); k++) {
                double want = opaque ? ref->part[4 * i + k] +
                                           ref->part[4 * i + 3] * (opaque->rgba[4 * i + k] / 255.0)
                                     : ref->rgba[4 * i + k];
                double d = fabs(f->rgba[4 * i + k] / 255.0 - want);
                if (d > worst)
                    worst = d;
            }
            m->compared++;
            sum += worst;
            if (worst > TOLERANCE)
                m->over++;
            if (worst > m->worst)
                m->worst = worst;
            if (c->s->light_count > 0 && hits[i].hit &&
                c->s->materials[c->s->objects[hits[i].object].material].color[3] < 1.0f &&
                reference_visibility(c->ref, &hits[i], 0) == 0.0f)
                m->shadowed_pane++;
        }
    m->mean = m->compared ? sum / m->compared : 0;
    free(e);
    free(hits);
}

static int matches_at_least(const match *m, long least)
{
    return m->compared >= least && m->over <= (1.0 - MIN_MATCH) * m->compared;
}

static int matches(const match *m) { return matches_at_least(m, MIN_SEEN_THROUGH); }

/* As matches_at_least with the fraction `need` instead of MIN_MATCH. */
static int matches_fraction(const match *m, long least, double need)
{
    return m->compared >= least && m->over <= (1.0 - need) * m->compared;
}

static long differing(const peel_case *c, const frame_out *a, const frame_out *b)
{
    size_t i, n = (size_t)4 * c->r->width * c->r->height;
    long d = 0;
    for (i = 0; i < n; i += 4)
        d += memcmp(a->rgba + i, b->rgba + i, 4) != 0;
    return d;
}

static void report_clean(const peel_case *c, const char *name, const frame_out *f)
{
    if (f->counters.gl_violations || f->errors)
        report(c->r, "FAIL", name, "%u profile violations, %u error logs (last: %s)",
               f->counters.gl_violations, f->errors, f->last_error);
    else
        report(c->r, "PASS", name, "no error logged, no call outside the profile");
}

static void test_beauty(const peel_case *c, const frame_out *f, const composite_ref *ref,
                        const char *name)
{
    match m;
    stin_technique t = f->choice[STIN_FEATURE_TRANSPARENCY].technique;
    int peeled = t == STIN_TECH_TRANSPARENCY_DEPTH_PEEL || t == STIN_TECH_TRANSPARENCY_DUAL_PEEL;
    int exact_expected = peeled || !strcmp(c->scene_name, "panes");
    /* the peels' alpha too; sorted's is GL 1.1 blending's (a a + (1 - a) alpha) */
    compare(c, f, ref, NULL, 1, peeled, &m);
    report(c->r, !exact_expected ? "INFO" : matches(&m) ? "PASS" : "FAIL", name,
           "%s: composite within 3/255 on %.3f%% of %ld pixels seen through glass (max %.4f, "
           "mean %.5f; %s)", stin_technique_name(t),
           m.compared ? 100.0 * (1.0 - (double)m.over / m.compared) : 0.0, m.compared, m.worst,
           m.mean, exact_expected ? "need 99.5% of >= 200" : "measured: sorted is not exact here");
}

/* The objects drawn in reverse order and rotated by one (each a different
 * submission order of the blended draws) give base's image bit for bit. */
static void test_order(const peel_case *c, stin_technique t, const frame_out *base,
                       const char *name)
{
    scene permuted = *c->s;
    scene_object *objects = malloc(sizeof *objects * (size_t)c->s->object_count);
    frame_opts fo = {STIN_TECH_SHADOWS_OFF, STIN_TECH_NONE, 0, 0, STIN_TECH_NONE};
    frame_out f;
    char err[256];
    long d[2] = {0, 0};
    int i, n = c->s->object_count, order;
    fo.transparency = t;
    if (!objects)
        return;
    permuted.objects = objects;
    for (order = 0; order < 2; order++) {
        for (i = 0; i < n; i++)
            objects[i] = c->s->objects[order == 0 ? n - 1 - i : (i + 1) % n];
        if (!render(c, &permuted, &fo, &f, err, sizeof err)) {
            report(c->r, "FAIL", name, "%s", err);
            free(objects);
            return;
        }
        d[order] = differing(c, base, &f);
        free(f.rgba);
    }
    report(c->r, d[0] == 0 && d[1] == 0 ? "PASS" : "FAIL", name,
           "%s: objects drawn in reverse order and rotated by one: the image differs on %ld and "
           "%ld pixels (must be 0)", stin_technique_name(t), d[0], d[1]);
    free(objects);
}

/* The passes a scene of n layers takes with the early stop: depth-peel one
 * per layer and one that finds nothing; dual-peel n / 2 + 1 (two layers a
 * pass; after an odd count's middle layer its back layer drew nothing). */
static uint32_t passes_for(stin_technique t, int n)
{
    return t == STIN_TECH_TRANSPARENCY_DUAL_PEEL ? (uint32_t)n / 2u + 1u : (uint32_t)n + 1u;
}

static void test_early_stop(const peel_case *c, stin_technique t, const frame_out *base,
                            const composite_ref *ref, const char *name)
{
    frame_opts fo = {STIN_TECH_SHADOWS_OFF, STIN_TECH_NONE, HIGH_CAP, 0, STIN_TECH_NONE};
    frame_out high, all;
    char err[256];
    int dual = t == STIN_TECH_TRANSPARENCY_DUAL_PEEL;
    uint32_t want = passes_for(t, ref->max_layers), want_all = dual ? HIGH_CAP / 2 : HIGH_CAP;
    long d1, d2;
    uint64_t queries = STIN_CAP_BIT(STIN_CAP_OCCLUSION_QUERY) |
                       STIN_CAP_BIT(STIN_CAP_ANY_SAMPLES_QUERY);
    if (!(base->caps_present & queries)) {
        report(c->r, "SKIP", name, "no occlusion queries (peeling runs to its layer cap)");
        return;
    }
    fo.transparency = t;
    if (!render(c, c->s, &fo, &high, err, sizeof err)) {
        report(c->r, "FAIL", name, "%s", err);
        return;
    }
    fo.debug_flags = dual ? STIN_DEBUG_DUAL_PEEL_NO_EARLY_STOP : STIN_DEBUG_PEEL_NO_EARLY_STOP;
    if (!render(c, c->s, &fo, &all, err, sizeof err)) {
        report(c->r, "FAIL", name, "%s", err);
        free(high.rgba);
        return;
    }
    d1 = differing(c, base, &high);
    d2 = differing(c, base, &all);
    report(c->r,
           d1 == 0 && d2 == 0 && high.stats.transparency.peel_passes == want &&
                   high.stats.transparency.peel_layers == (uint32_t)ref->max_layers &&
                   all.stats.transparency.peel_passes == want_all
               ? "PASS"
               : "FAIL",
           name,
           "%s, cap %d: %u passes, %u layers lit (the scene has %d: want %u passes and as many "
           "layers); without early stop %u passes (want %u); images differ from the default "
           "cap's on %ld and %ld pixels (must be 0)", stin_technique_name(t), HIGH_CAP,
           high.stats.transparency.peel_passes, high.stats.transparency.peel_layers, ref->max_layers, want,
           all.stats.transparency.peel_passes, want_all, d1, d2);
    free(high.rgba);
    free(all.rgba);
}

static void test_cap(const peel_case *c, stin_technique t, const composite_ref *ref,
                     const char *name)
{
    frame_opts fo = {STIN_TECH_SHADOWS_OFF, STIN_TECH_NONE, 1, 0, STIN_TECH_NONE};
    frame_out f;
    char err[256];
    match m;
    fo.transparency = t;
    if (!render(c, c->s, &fo, &f, err, sizeof err)) {
        report(c->r, "FAIL", name, "%s", err);
        return;
    }
    compare(c, &f, ref, NULL, 1, 0, &m);
    report(c->r, f.stats.transparency.peel_passes == 1 && ref->max_layers > 1 && !matches(&m) ? "PASS" : "FAIL",
           name, "%s, transparency.layers 1: %u pass, composite matched on only %ld of %ld "
           "pixels (the scene has %d layers: one layer must not be the whole composite)",
           stin_technique_name(t), f.stats.transparency.peel_passes, m.compared - m.over, m.compared, ref->max_layers);
    free(f.rgba);
}

/* The shadowed frame of transparency technique `transparency` against ref:
 * its transparent part over the technique's own opaque image
 * (STIN_DEBUG_TRANSPARENCY_OPAQUE_ONLY) and as a whole; 1 when both match with
 * enough pixels of a pane in shadow. */
typedef struct shadowed_run {
    match part, whole;
    int ran, ok;
    char err[512];
} shadowed_run;

static void shadowed_frame(const peel_case *c, const frame_opts *base, const composite_ref *ref,
                           double need, shadowed_run *out)
{
    frame_opts fo = *base;
    frame_out f, behind;
    memset(out, 0, sizeof *out);
    fo.debug_flags = base->debug_flags | STIN_DEBUG_TRANSPARENCY_OPAQUE_ONLY; /* what the layers go over */
    if (!render(c, c->s, &fo, &behind, out->err, sizeof out->err))
        return;
    fo.debug_flags = base->debug_flags;
    if (!render(c, c->s, &fo, &f, out->err, sizeof out->err)) {
        free(behind.rgba);
        out->ran = -1;
        return;
    }
    out->ran = 1;
    if (f.choice[STIN_FEATURE_SHADOWS].technique != base->shadows) {
        snprintf(out->err, sizeof out->err, "%s fell back to %s: %s",
                 stin_technique_name(base->shadows),
                 stin_technique_name(f.choice[STIN_FEATURE_SHADOWS].technique),
                 f.choice[STIN_FEATURE_SHADOWS].reason);
        out->ran = 0; /* the profile lacks it: a SKIP */
    } else if (f.choice[STIN_FEATURE_TRANSPARENCY].technique != base->transparency ||
        (base->translucent != STIN_TECH_NONE &&
         f.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].technique != base->translucent)) {
        snprintf(out->err, sizeof out->err, "%s or %s fell back: %s %s",
                 stin_technique_name(base->transparency),
                 stin_technique_name(base->translucent),
                 f.choice[STIN_FEATURE_TRANSPARENCY].reason,
                 f.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].reason);
        out->ran = -1;
    } else {
        compare(c, &f, ref, &behind, 2, 0, &out->part);
        compare(c, &f, ref, NULL, 2, 0, &out->whole);
        out->ok = matches_fraction(&out->part, MIN_SHADOWED_COMPARED, need) &&
                  matches_fraction(&out->whole, MIN_SHADOWED_COMPARED, need) &&
                  out->part.shadowed_pane >= MIN_SHADOWED_PANE;
    }
    free(f.rgba);
    free(behind.rgba);
}

static double percent(const match *m)
{
    return m->compared ? 100.0 * (1.0 - (double)m->over / m->compared) : 0.0;
}

/* Shadows technique `shadows` (and `translucent`) under `transparency`,
 * `need` of the compared pixels within 3/255; with `broken` (a debug flag
 * that leaves the transparent surfaces unshadowed) the same comparison must
 * fail, reported as name-broken. */
static void test_shadowed_need(const peel_case *c, stin_technique shadows,
                               stin_technique translucent, stin_technique transparency,
                               uint64_t broken, double need, const composite_ref *ref,
                               const char *name)
{
    frame_opts fo = {STIN_TECH_NONE, STIN_TECH_NONE, 0, 0, STIN_TECH_NONE};
    shadowed_run r;
    char broken_name[224];
    fo.shadows = shadows;
    fo.translucent = translucent;
    fo.transparency = transparency;
    shadowed_frame(c, &fo, ref, need, &r);
    if (r.ran == 0) {
        report(c->r, "SKIP", name, "%s does not run here (%s)", stin_technique_name(shadows),
               r.err);
        return;
    }
    if (r.ran < 0) {
        report(c->r, "FAIL", name, "%s", r.err);
        return;
    }
    report(c->r, r.ok ? "PASS" : "FAIL", name,
           "%s, %s: shadowed transparent surfaces over the technique's own opaque image within "
           "3/255 on %.3f%% of %ld pixels (max %.4f, mean %.5f), %ld of them a pane in shadow "
           "(need %.1f%% and >= %d, of >= %d); the whole frame against the reference %.3f%% "
           "(need %.1f%%)", stin_technique_name(transparency), stin_technique_name(shadows),
           percent(&r.part), r.part.compared, r.part.worst, r.part.mean, r.part.shadowed_pane,
           100.0 * need, MIN_SHADOWED_PANE, MIN_SHADOWED_COMPARED, percent(&r.whole),
           100.0 * need);
    if (!broken)
        return;
    snprintf(broken_name, sizeof broken_name, "%s-broken", name);
    fo.debug_flags = broken;
    shadowed_frame(c, &fo, ref, need, &r);
    if (r.ran <= 0) {
        report(c->r, "FAIL", broken_name, "%s", r.err);
        return;
    }
    report(c->r, !r.ok ? "PASS" : "FAIL", broken_name,
           "transparent surfaces left unshadowed (debug flag %u): within 3/255 on only %.3f%% "
           "of %ld pixels (max %.4f), the whole frame %.3f%%: the test must fail here",
           (unsigned)broken, percent(&r.part), r.part.compared, r.part.worst,
           percent(&r.whole));
}

static void test_shadowed(const peel_case *c, stin_technique shadows, stin_technique translucent,
                          stin_technique transparency, uint64_t broken, const composite_ref *ref,
                          const char *name)
{
    test_shadowed_need(c, shadows, translucent, transparency, broken, MIN_MATCH, ref, name);
}

/* sorted under the tier's map techniques, each at its usual bound (the
 * fraction of pixels it may get wrong: map-pcf as under depth-peel; GL1's
 * hard maps as map_test.c bounds their visibility, 2% map-depth, 5%
 * map-combine), and unshadowed (STIN_DEBUG_SORTED_UNSHADOWED) failing. */
static void sorted_tests(const peel_case *c, const composite_ref *shadowed)
{
    static const struct {
        stin_technique t;
        stin_tier tier;
        double need;
    } maps[] = {{STIN_TECH_SHADOWS_MAP_PCF, STIN_TIER_GL2, MIN_MATCH},
                {STIN_TECH_SHADOWS_MAP_PCF, STIN_TIER_GL4, MIN_MATCH},
                {STIN_TECH_SHADOWS_MAP_DEPTH, STIN_TIER_GL1, 0.98},
                {STIN_TECH_SHADOWS_MAP_COMBINE, STIN_TIER_GL1, 0.95}};
    char name[192];
    size_t i;
    for (i = 0; i < sizeof maps / sizeof maps[0]; i++) {
        if (maps[i].tier != c->tier)
            continue;
        snprintf(name, sizeof name, "%s/%s/sorted-shadowed-%s", stin_tier_name(c->tier),
                 c->scene_name, stin_technique_name(maps[i].t));
        test_shadowed_need(c, maps[i].t, STIN_TECH_NONE, STIN_TECH_TRANSPARENCY_SORTED,
                           STIN_DEBUG_SORTED_UNSHADOWED, maps[i].need, shadowed, name);
    }
}

/* Technique t's tests under names prefix-*: its beauty (where it is not
 * the default, whose beauty peel-beauty checks), order, early-stop and cap;
 * its image (shadows off, default cap) into out. 0 (SKIP) where t does not
 * run here. */
static int battery(const peel_case *c, stin_technique t, stin_technique chosen,
                   const composite_ref *ref, const char *prefix, frame_out *out)
{
    frame_opts fo = {STIN_TECH_SHADOWS_OFF, STIN_TECH_NONE, 0, 0, STIN_TECH_NONE};
    char err[256], name[224];
    fo.transparency = t;
    if (!render(c, c->s, &fo, out, err, sizeof err)) {
        snprintf(name, sizeof name, "%s-layers", prefix);
        report(c->r, "SKIP", name, "%s does not run here (%s)", stin_technique_name(t), err);
        return 0;
    }
    if (t != chosen) {
        snprintf(name, sizeof name, "%s-forced-beauty", prefix);
        test_beauty(c, out, ref, name);
    }
    snprintf(name, sizeof name, "%s-order", prefix);
    test_order(c, t, out, name);
    snprintf(name, sizeof name, "%s-early-stop", prefix);
    test_early_stop(c, t, out, ref, name);
    snprintf(name, sizeof name, "%s-cap", prefix);
    test_cap(c, t, ref, name);
    return 1;
}

/* dual-peel against depth-peel, pixel by pixel: within 1/255 on every one
 * (the same layers, lit by the same passes into the same RGBA8 textures;
 * only the composite's arithmetic differs: depth-peel rounds its 8-bit
 * composite per layer, dual-peel's is half floats, rounded once). */
static void test_agrees(const peel_case *c, const frame_out *dual, const frame_out *depth,
                        const char *name)
{
    size_t i, n = (size_t)c->r->width * c->r->height;
    long differ = 0, over = 0;
    int worst = 0, k;
    for (i = 0; i < n; i++) {
        int d = 0;
        for (k = 0; k < 4; k++) {
            int e = abs((int)dual->rgba[4 * i + k] - (int)depth->rgba[4 * i + k]);
            d = e > d ? e : d;
        }
        differ += d > 0;
        over += d > 1;
        worst = d > worst ? d : worst;
    }
    report(c->r, over == 0 ? "PASS" : "FAIL", name,
           "dual-peel against depth-peel: %ld of %ld pixels differ, %ld by more than 1/255 "
           "(must be 0; worst %d/255)", differ, (long)n, over, worst);
}

/* A copy of the panes scene with its opaque objects and `n` copies of its
 * first pane, each 0.3 above the one before: n layers where they overlap. */
static int stacked(const scene *s, int n, scene *out)
{
    int i, k = 0, first = -1;
    *out = *s;
    out->objects = malloc(sizeof *out->objects * (size_t)(s->object_count + n));
    if (!out->objects)
        return 0;
    for (i = 0; i < s->object_count; i++) {
        if (s->materials[s->objects[i].material].color[3] >= 1.0f)
            out->objects[k++] = s->objects[i];
        else if (first < 0)
            first = i;
    }
    for (i = 0; i < n && first >= 0; i++) {
        out->objects[k] = s->objects[first];
        out->objects[k].transform[13] += 0.3f * (float)i; /* column-major: y */
        k++;
    }
    out->object_count = k;
    return first >= 0;
}

/* dual-peel's passes on 1 to 4 stacked panes: N layers (depth-peel's
 * transparency.peel_layers) in N / 2 + 1 passes, with depth-peel's image within 1/255. */
static void test_stacks(const peel_case *c, const char *prefix)
{
    int n;
    for (n = 1; n <= 4; n++) {
        frame_opts fo = {STIN_TECH_SHADOWS_OFF, STIN_TECH_TRANSPARENCY_DEPTH_PEEL, 0, 0,
                         STIN_TECH_NONE};
        frame_out depth, dual;
        peel_case sc = *c;
        scene s;
        char err[256], name[224];
        snprintf(name, sizeof name, "%s-passes-%d", prefix, n);
        if (!stacked(c->s, n, &s)) {
            report(c->r, "FAIL", name, "the scene has no pane to stack");
            free(s.objects);
            continue;
        }
        sc.s = &s;
        if (!render(&sc, &s, &fo, &depth, err, sizeof err)) {
            report(c->r, "FAIL", name, "depth-peel: %s", err);
        } else {
            fo.transparency = STIN_TECH_TRANSPARENCY_DUAL_PEEL;
            if (!render(&sc, &s, &fo, &dual, err, sizeof err)) {
                report(c->r, "FAIL", name, "dual-peel: %s", err);
            } else {
                uint32_t layers = depth.stats.transparency.peel_layers;
                report(c->r,
                       layers == (uint32_t)n && dual.stats.transparency.peel_layers == layers &&
                               dual.stats.transparency.peel_passes == layers / 2 + 1
                           ? "PASS"
                           : "FAIL",
                       name,
                       "%d stacked panes: %u layers (depth-peel), dual-peel %u layers in %u "
                       "passes (want %d and %u), depth-peel %u passes",
                       n, layers, dual.stats.transparency.peel_layers, dual.stats.transparency.peel_passes, n,
                       layers / 2 + 1, depth.stats.transparency.peel_passes);
                snprintf(name, sizeof name, "%s-agrees-%d", prefix, n);
                test_agrees(&sc, &dual, &depth, name);
                free(dual.rgba);
            }
            free(depth.rgba);
        }
        free(s.objects);
    }
}

/* The panes scene's own tests: the stacks, and both peels under each
 * shadows technique that runs here (its layers receive shadows): volume,
 * map-pcf, vdsm's masks made from each layer (without them,
 * STIN_DEBUG_PEEL_VDSM_UNSHADOWED, the panes in shadow are lit and the
 * -broken run must fail) and deep's coloured shadows. */
static void panes_tests(peel_case *c, stin_tier tier, composite_ref *shadowed)
{
    static const stin_technique shadows[] = {STIN_TECH_SHADOWS_VOLUME,
                                             STIN_TECH_SHADOWS_MAP_PCF};
    static const stin_technique peels[2] = {STIN_TECH_TRANSPARENCY_DEPTH_PEEL,
                                            STIN_TECH_TRANSPARENCY_DUAL_PEEL};
    static const char *const prefix[2] = {"peel", "dual-peel"};
    const char *tn = stin_tier_name(tier);
    int peel_count = tier == STIN_TIER_GL4 ? 2 : 1; /* dual-peel is GL4 only */
    char name[192];
    size_t i;
    int t;
    snprintf(name, sizeof name, "%s/%s/dual-peel", tn, c->scene_name);
    if (tier == STIN_TIER_GL4)
        test_stacks(c, name);
    else
        report(c->r, "SKIP", name, "dual-peel is GL4 only: no pass counts here");
    if (!reference_of(c, REFERENCE_RENDER_SHADOWED, shadowed)) {
        report(c->r, "FAIL", name, "shadowed reference composite failed");
        return;
    }
    for (t = 0; t < peel_count; t++)
        for (i = 0; i < sizeof shadows / sizeof shadows[0]; i++) {
            snprintf(name, sizeof name, "%s/%s/%s-shadowed-%s", tn, c->scene_name, prefix[t],
                     stin_technique_name(shadows[i]));
            test_shadowed(c, shadows[i], STIN_TECH_NONE, peels[t], 0, shadowed, name);
        }
    if (tier != STIN_TIER_GL4) {
        snprintf(name, sizeof name, "%s/%s/peel-shadowed-deep", tn, c->scene_name);
        report(c->r, "SKIP", name, "deep shadow maps are GL4 only");
        snprintf(name, sizeof name, "%s/%s/peel-shadowed-vdsm", tn, c->scene_name);
        report(c->r, "SKIP", name, "vdsm is GL4 only");
        return;
    }
    for (t = 0; t < peel_count; t++) {
        snprintf(name, sizeof name, "%s/%s/%s-shadowed-vdsm", tn, c->scene_name, prefix[t]);
        test_shadowed(c, STIN_TECH_SHADOWS_VDSM, STIN_TECH_NONE, peels[t],
                      STIN_DEBUG_PEEL_VDSM_UNSHADOWED, shadowed, name);
    }
    /* deep: the layers get coloured shadows; the composite's layers are lit
     * through the transmittance */
    reference_free(shadowed);
    memset(shadowed, 0, sizeof *shadowed);
    if (!reference_of(c, REFERENCE_RENDER_TRANSMITTANCE, shadowed)) {
        report(c->r, "FAIL", name, "transmittance reference composite failed");
        return;
    }
    for (t = 0; t < peel_count; t++) {
        snprintf(name, sizeof name, "%s/%s/%s-shadowed-deep", tn, c->scene_name, prefix[t]);
        test_shadowed(c, STIN_TECH_SHADOWS_VOLUME, STIN_TECH_TRANSLUCENT_DEEP, peels[t], 0,
                      shadowed, name);
    }
}

static void peel_scene(run *r, stin_tier tier, const char *path, const char *scene_name)
{
    scene s;
    peel_case c;
    composite_ref unshadowed, shadowed;
    frame_opts fo = {STIN_TECH_SHADOWS_OFF, STIN_TECH_NONE, 0, 0, STIN_TECH_NONE};
    static const stin_technique peels[2] = {STIN_TECH_TRANSPARENCY_DEPTH_PEEL,
                                            STIN_TECH_TRANSPARENCY_DUAL_PEEL};
    frame_out base, layered[2];
    char err[512], name[192];
    const char *tn = stin_tier_name(tier);
    int t;
    memset(&unshadowed, 0, sizeof unshadowed);
    memset(&shadowed, 0, sizeof shadowed);
    snprintf(name, sizeof name, "%s/%s/peel", tn, scene_name);
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    memset(&c, 0, sizeof c);
    c.r = r;
    c.s = &s;
    c.tier = tier;
    c.scene_name = scene_name;
    c.ref = reference_create(&s, err, sizeof err);
    if (!c.ref) {
        report(r, "FAIL", name, "reference: %s", err);
        scene_free(&s);
        return;
    }
    if (!render(&c, &s, &fo, &base, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        goto done;
    }
    if (tier == STIN_TIER_GL1) /* Gouraud, as test_scene */
        c.per_vertex = (base.caps_present & STIN_CAP_BIT(STIN_CAP_SEPARATE_SPECULAR))
                           ? 1
                           : REFERENCE_GOURAUD_SINGLE_COLOR;
    if (!reference_of(&c, 0, &unshadowed)) {
        report(r, "FAIL", name, "reference composite failed");
        free(base.rgba);
        goto done;
    }
    if (!strcmp(scene_name, "sorted")) { /* map shadows on sorted draws only */
        if (!reference_of(&c, REFERENCE_RENDER_SHADOWED, &shadowed))
            report(r, "FAIL", name, "shadowed reference composite failed");
        else
            sorted_tests(&c, &shadowed);
        free(base.rgba);
        goto done;
    }
    snprintf(name, sizeof name, "%s/%s/peel-gl-clean", tn, scene_name);
    report_clean(&c, name, &base);
    snprintf(name, sizeof name, "%s/%s/peel-beauty", tn, scene_name);
    test_beauty(&c, &base, &unshadowed, name);
    for (t = 0; t < 2; t++) {
        snprintf(name, sizeof name, "%s/%s/%s", tn, scene_name, t ? "dual-peel" : "peel");
        if (!battery(&c, peels[t], base.choice[STIN_FEATURE_TRANSPARENCY].technique,
                     &unshadowed, name, &layered[t]))
            layered[t].rgba = NULL;
    }
    snprintf(name, sizeof name, "%s/%s/dual-peel-agrees", tn, scene_name);
    if (layered[0].rgba && layered[1].rgba)
        test_agrees(&c, &layered[1], &layered[0], name);
    else
        report(r, "SKIP", name, "%s does not run here: nothing to compare",
               layered[1].rgba ? "depth-peel" : "dual-peel");
    free(base.rgba);
    free(layered[0].rgba);
    free(layered[1].rgba);
    if (!strcmp(scene_name, "panes")) /* the scene with a pane in shadow */
        panes_tests(&c, tier, &shadowed);
done:
    reference_free(&unshadowed);
    reference_free(&shadowed);
    reference_destroy(c.ref);
    scene_free(&s);
}

void peel_frame_rows(run *r, stin_tier tier, const char *path, const uint8_t *rgba,
                     stin_technique chosen)
{
    scene s;
    peel_case c;
    composite_ref unshadowed;
    frame_out f;
    char err[512], name[192];
    memset(&c, 0, sizeof c);
    memset(&f, 0, sizeof f);
    memset(&unshadowed, 0, sizeof unshadowed);
    c.r = r;
    c.s = &s;
    c.tier = tier;
    c.scene_name = scene_base_name(path);
    snprintf(name, sizeof name, "%s/%s/peel-beauty", stin_tier_name(tier), c.scene_name);
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    c.ref = reference_create(&s, err, sizeof err);
    f.rgba = (uint8_t *)rgba;
    f.choice[STIN_FEATURE_TRANSPARENCY].technique = chosen;
    if (!c.ref || !reference_of(&c, 0, &unshadowed))
        report(r, "FAIL", name, "reference: %s", c.ref ? "composite failed" : err);
    else
        test_beauty(&c, &f, &unshadowed, name);
    reference_free(&unshadowed);
    if (c.ref)
        reference_destroy(c.ref);
    scene_free(&s);
}

void peel_tests(run *r, stin_tier tier, const char *path)
{
    static const char *const beside[] = {"panes", "cross", "sorted"};
    char dir[1024], sub[1100];
    const char *base = scene_base_name(path);
    size_t i;
    if (strcmp(base, "glass-panes") != 0)
        return;
    peel_scene(r, tier, path, "glass-panes");
    snprintf(dir, sizeof dir, "%s", path);
    if (strrchr(dir, '/'))
        strrchr(dir, '/')[1] = '\0';
    else
        dir[0] = '\0';
    for (i = 0; i < sizeof beside / sizeof beside[0]; i++) {
        snprintf(sub, sizeof sub, "%speel/%s.json", dir, beside[i]);
        peel_scene(r, tier, sub, beside[i]);
    }
}
