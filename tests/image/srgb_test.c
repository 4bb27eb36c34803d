/* SPDX-License-Identifier: MIT */
/*
 * Frames into an sRGB colour target (stin_platform_set_srgb: GL_SRGB8_ALPHA8,
 * GL_FRAMEBUFFER_SRGB enabled by the caller) against the Embree reference
 * encoded by the sRGB transfer function, per shadow technique of the tier,
 * on four-lights under gl21 (the GL1 and GL2 tiers), gl33-core and
 * gl45-core (GL4), on EGL (OSMesa's target is the same framebuffer object
 * on the same rasteriser: make check's time goes elsewhere).
 *
 * The bound, in the encoded space: GL shades in float, encodes once and
 * rounds to 8 bits, half a step (0.5/255). A frame that adds a pass per
 * light blends in linear space over the stored (rounded) value, and each
 * earlier rounding reaches the final encoded value at most as large
 * (d enc / d linear falls as the value grows, and a sum only grows), so k
 * writes cost at most k/2 steps: four-lights' ambient and four light
 * passes, 2.5/255. Half a step more for the driver's encoder and float
 * shading: 3/255 per channel on at least 99.5% of the compared pixels,
 * mean at most 1/255 (the linear beauty test's numbers, now in the encoded
 * space, where a dark tone's step is up to 12.92 times finer).
 * Compared: opaque untextured pixels away from silhouettes whose linear
 * frame (the same context into the default framebuffer) is within 3/255
 * of the linear reference: where a technique misplaces a shadow edge the
 * shadow tests hold it, not this one.
 */
#include "image_test.h"
#include "reference.h"
#include "scene.h"
#include "test_context.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SRGB_TOLERANCE (3.0 / 255.0)
#define SRGB_MIN_MATCH 0.995
#define SRGB_MAX_MEAN (1.0 / 255.0)
#define LINEAR_TOLERANCE (3.0 / 255.0)
/* A mid-tone pixel tells encoded once from not at all and from twice: its
 * encoded reference is more than twice the tolerance from both. */
#define MIDTONE_MIN 500
#define MIDTONE_MAX_WRONG 0.01

/* IEC 61966-2-1's encoding, exact and piecewise. */
static double srgb_encode(double l)
{
    l = l < 0 ? 0 : l > 1 ? 1 : l;
    return l <= 0.0031308 ? 12.92 * l : 1.055 * pow(l, 1.0 / 2.4) - 0.055;
}

typedef struct srgb_case {
    run *r;
    const scene *s;
    stin_tier tier;
    int per_vertex;
    const float *ref;      /* REFERENCE_CHANNELS a pixel, rows bottom to top */
    float *shadowed, *lit; /* the references with and without shadows */
    const ref_hit *hits;
    uint8_t *linear, *encoded; /* read-backs */
} srgb_case;

static int plain_inside(const srgb_case *c, int x, int y)
{
    int w = c->r->width, h = c->r->height, dx, dy;
    const ref_hit *hit = &c->hits[(size_t)y * w + x];
    const scene_material *m;
    if (!hit->hit || x == 0 || y == 0 || x == w - 1 || y == h - 1)
        return 0;
    m = &c->s->materials[c->s->objects[hit->object].material];
    if (m->color[3] < 1.0f || m->albedo >= 0)
        return 0;
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++) {
            const ref_hit *n = &c->hits[(size_t)(y + dy) * w + x + dx];
            if (!n->hit || n->object != hit->object)
                return 0;
        }
    return 1;
}

/* One frame of the context into the platform's current target, read back. */
static int frame_into(srgb_case *c, test_context *t, stin_output output, uint8_t *out)
{
    stin_frame_desc fd;
    test_frame_desc(c->r, c->s, &fd);
    fd.output = output;
    return test_context_frame(t, c->s, &fd, -1) == STIN_OK &&
           stin_platform_read_color(c->r->plat, out);
}

static int set_target(srgb_case *c, int srgb, const char *name)
{
    char err[512];
    if (stin_platform_set_srgb(c->r->plat, srgb, err, sizeof err))
        return 1;
    report(c->r, "SKIP", name, "%s", err);
    return 0;
}

typedef struct srgb_counts {
    long compared, over, left_out, midtones, as_linear, as_twice;
    double max, sum;
} srgb_counts;

static void count_pixel(const srgb_case *c, size_t i, srgb_counts *n)
{
    const float *ref = c->ref + i * REFERENCE_CHANNELS;
    int ch, over = 0, midtone = 0, near_linear = 1, near_twice = 1;
    for (ch = 0; ch < 3; ch++)
        if (fabs(c->linear[4 * i + ch] / 255.0 - ref[ch]) > LINEAR_TOLERANCE) {
            n->left_out++;
            return;
        }
    n->compared++;
    for (ch = 0; ch < 3; ch++) {
        double want = srgb_encode(ref[ch]), got = c->encoded[4 * i + ch] / 255.0;
        double d = fabs(got - want);
        n->sum += d;
        n->max = d > n->max ? d : n->max;
        over |= d > SRGB_TOLERANCE;
        if (fabs(want - ref[ch]) > 2 * SRGB_TOLERANCE &&
            fabs(want - srgb_encode(want)) > 2 * SRGB_TOLERANCE)
            midtone = 1;
        near_linear &= fabs(got - ref[ch]) <= SRGB_TOLERANCE;
        near_twice &= fabs(got - srgb_encode(want)) <= SRGB_TOLERANCE;
    }
    n->over += over;
    if (midtone) {
        n->midtones++;
        n->as_linear += near_linear;
        n->as_twice += near_twice;
    }
}

/* The normal output is data: into the sRGB target it must store what it
 * stores into a linear one, within the 8-bit rounding of a blended pass
 * (encoded, 0.5 would be 188/255 instead of 128/255). */
static void compare_normal_output(srgb_case *c, test_context *t)
{
    char name[160];
    size_t i, npix = (size_t)c->r->width * c->r->height;
    long differ = 0;
    int ok;
    snprintf(name, sizeof name, "%s/four-lights/srgb-normal-output", stin_tier_name(c->tier));
    ok = set_target(c, 0, name) && frame_into(c, t, STIN_OUTPUT_NORMAL, c->linear) &&
         set_target(c, 1, name) && frame_into(c, t, STIN_OUTPUT_NORMAL, c->encoded);
    set_target(c, 0, name);
    if (!ok) {
        report(c->r, "FAIL", name, "a frame or its read-back failed");
        return;
    }
    for (i = 0; i < 3 * npix; i++)
        differ += abs((int)c->linear[i / 3 * 4 + i % 3] - (int)c->encoded[i / 3 * 4 + i % 3]) > 1;
    report(c->r, differ == 0 ? "PASS" : "FAIL", name,
           "%ld channels of %zu pixels more than 1/255 from the linear target's (need 0: GL "
           "must not encode data; the GL1 path's two blended passes round by a step apart "
           "in the two formats)", differ, npix);
}

/* Its PASS/FAIL lines from the two read-backs; label: "srgb" or
 * "srgb-msaa" (the names' prefix after the scene's). */
static void report_beauty(srgb_case *c, stin_technique shadows, const char *label)
{
    char name[160];
    srgb_counts n;
    int x, y, w = c->r->width, h = c->r->height;
    double match, mean;
    memset(&n, 0, sizeof n);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            if (plain_inside(c, x, y))
                count_pixel(c, (size_t)y * w + x, &n);
    match = n.compared ? 1.0 - (double)n.over / n.compared : 0;
    mean = n.compared ? n.sum / (3.0 * n.compared) : 1;
    snprintf(name, sizeof name, "%s/four-lights/%s-%s", stin_tier_name(c->tier), label,
             stin_technique_name(shadows));
    report(c->r, match >= SRGB_MIN_MATCH && mean <= SRGB_MAX_MEAN ? "PASS" : "FAIL", name,
           "encoded reference within %.4f on %.3f%% of %ld pixels (max %.4f, mean %.5f; need "
           "%.1f%% and mean <= 1/255); %ld left out where the linear frame differs",
           SRGB_TOLERANCE, 100.0 * match, n.compared, n.max, mean, 100.0 * SRGB_MIN_MATCH,
           n.left_out);
    snprintf(name, sizeof name, "%s/four-lights/%s-%s-once", stin_tier_name(c->tier), label,
             stin_technique_name(shadows));
    report(c->r,
           n.midtones >= MIDTONE_MIN && n.as_linear <= MIDTONE_MAX_WRONG * n.midtones &&
                   n.as_twice <= MIDTONE_MAX_WRONG * n.midtones
               ? "PASS"
               : "FAIL",
           name,
           "of %ld mid-tone pixels %ld look unencoded, %ld encoded twice (need >= %d pixels, "
           "each count <= %.0f%%)",
           n.midtones, n.as_linear, n.as_twice, MIDTONE_MIN, 100.0 * MIDTONE_MAX_WRONG);
}

/* The same context's frame into the linear and into the sRGB target. */
static void compare_technique(srgb_case *c, stin_technique shadows)
{
    char name[160];
    test_context t;
    int ok;
    snprintf(name, sizeof name, "%s/four-lights/srgb-%s", stin_tier_name(c->tier),
             stin_technique_name(shadows));
    if (!test_context_create(&t, c->r, c->s, c->tier, shadows, 1)) {
        report(c->r, "FAIL", name, "%s did not run on this tier", stin_technique_name(shadows));
        return;
    }
    c->ref = shadows == STIN_TECH_SHADOWS_OFF ? c->lit : c->shadowed;
    ok = set_target(c, 0, name) && frame_into(c, &t, STIN_OUTPUT_BEAUTY, c->linear) &&
         set_target(c, 1, name) && frame_into(c, &t, STIN_OUTPUT_BEAUTY, c->encoded);
    set_target(c, 0, name);
    if (!ok)
        report(c->r, "FAIL", name, "a frame or its read-back failed");
    else
        report_beauty(c, shadows, "srgb");
    if (ok && shadows == STIN_TECH_SHADOWS_OFF) /* its context serves the data output too */
        compare_normal_output(c, &t);
    test_context_destroy(&t);
}

/* The tier's first technique into a 4x sRGB target (GL_SRGB8_ALPHA8
 * samples, resolved by a blit into an sRGB twin with GL_FRAMEBUFFER_SRGB
 * on) against the encoded reference, by the single-sampled bound: the
 * compared pixels lie inside one surface, where every sample of a pixel
 * takes the fragment's one colour and the resolve gives it back. The linear
 * frame that picks them is the same context's into a 4x linear target. A
 * context with both targets apart must give them together (FAIL, not SKIP). */
static void compare_msaa(srgb_case *c, stin_technique shadows)
{
    char name[160], err[512];
    test_context t;
    int ok;
    snprintf(name, sizeof name, "%s/four-lights/srgb-msaa-%s", stin_tier_name(c->tier),
             stin_technique_name(shadows));
    if (!stin_platform_set_samples(c->r->plat, 4, err, sizeof err)) {
        report(c->r, "SKIP", name, "%s", err);
        return;
    }
    if (!test_context_create(&t, c->r, c->s, c->tier, shadows, 1)) {
        report(c->r, "FAIL", name, "%s did not run on this tier", stin_technique_name(shadows));
    } else {
        c->ref = c->shadowed;
        ok = frame_into(c, &t, STIN_OUTPUT_BEAUTY, c->linear);
        if (ok && !stin_platform_set_srgb(c->r->plat, 1, err, sizeof err))
            report(c->r, "FAIL", name, "4x and sRGB targets apart, not together: %s", err);
        else if (!ok || !frame_into(c, &t, STIN_OUTPUT_BEAUTY, c->encoded))
            report(c->r, "FAIL", name, "a frame or its read-back failed");
        else
            report_beauty(c, shadows, "srgb-msaa");
        test_context_destroy(&t);
    }
    if (!stin_platform_set_srgb(c->r->plat, 0, err, sizeof err) ||
        !stin_platform_set_samples(c->r->plat, 0, err, sizeof err))
        report(c->r, "FAIL", name, "back to the default framebuffer: %s", err);
}

/* four-lights on EGL under gl21, gl33-core and gl45-core. */
static int srgb_runs_here(const run *r, const char *path)
{
    static const char *const profiles[] = {"gl21", "gl33-core", "gl45-core"};
    size_t i;
    if (strcmp(scene_base_name(path), "four-lights") || strcmp(r->platform_name, "egl"))
        return 0;
    for (i = 0; i < sizeof profiles / sizeof profiles[0]; i++)
        if (!strcmp(r->profile_name, profiles[i]))
            return 1;
    return 0;
}

void srgb_tests(run *r, stin_tier tier, const char *path)
{
    static const stin_technique gl1[] = {STIN_TECH_SHADOWS_VOLUME, STIN_TECH_SHADOWS_MAP_DEPTH,
                                         STIN_TECH_SHADOWS_MAP_COMBINE, STIN_TECH_SHADOWS_OFF,
                                         STIN_TECH_NONE};
    static const stin_technique gl2[] = {STIN_TECH_SHADOWS_VOLUME, STIN_TECH_SHADOWS_MAP_PCF,
                                         STIN_TECH_SHADOWS_OFF, STIN_TECH_NONE};
    static const stin_technique gl4[] = {STIN_TECH_SHADOWS_VDSM, STIN_TECH_SHADOWS_VOLUME,
                                         STIN_TECH_SHADOWS_MAP_PCF, STIN_TECH_SHADOWS_OFF,
                                         STIN_TECH_NONE};
    const stin_technique *list = tier == STIN_TIER_GL1 ? gl1 : tier == STIN_TIER_GL2 ? gl2 : gl4;
    size_t npix = (size_t)r->width * r->height;
    srgb_case c = {0};
    reference *ref = NULL;
    ref_hit *hits = NULL;
    test_context probe;
    scene s;
    char err[512], name[128];
    int i;
    if (!srgb_runs_here(r, path))
        return;
    c.r = r;
    c.s = &s;
    c.tier = tier;
    snprintf(name, sizeof name, "%s/four-lights/srgb", stin_tier_name(tier));
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", name, "scene: %s", err);
        return;
    }
    if (tier == STIN_TIER_GL1 && test_context_create(&probe, r, &s, tier, STIN_TECH_NONE, 0)) {
        /* Gouraud; GL 1.1 has no separate specular colour */
        c.per_vertex = (stin_query_caps(probe.ctx)->present &
                        STIN_CAP_BIT(STIN_CAP_SEPARATE_SPECULAR))
                           ? 1
                           : REFERENCE_GOURAUD_SINGLE_COLOR;
        test_context_destroy(&probe);
    }
    ref = reference_create(&s, err, sizeof err);
    hits = malloc(sizeof *hits * npix);
    c.shadowed = malloc(sizeof(float) * REFERENCE_CHANNELS * npix);
    c.lit = malloc(sizeof(float) * REFERENCE_CHANNELS * npix);
    c.linear = malloc(4 * npix);
    c.encoded = malloc(4 * npix);
    if (!ref || !hits || !c.shadowed || !c.lit || !c.linear || !c.encoded ||
        !reference_primary(ref, r->width, r->height, hits) ||
        !reference_render_ex(&s, ref, r->width, r->height, c.per_vertex,
                             REFERENCE_RENDER_SHADOWED, c.shadowed) ||
        !reference_render(&s, ref, r->width, r->height, c.per_vertex, c.lit)) {
        report(r, "FAIL", name, "reference: %s", ref ? "render failed" : err);
    } else {
        c.hits = hits;
        for (i = 0; list[i] != STIN_TECH_NONE; i++)
            compare_technique(&c, list[i]);
        if (strcmp(r->profile_name, "gl33-core")) /* gl45-core runs GL4's */
            compare_msaa(&c, list[0]);
    }
    free(c.linear);
    free(c.encoded);
    free(hits);
    free(c.shadowed);
    free(c.lit);
    if (ref)
        reference_destroy(ref);
    scene_free(&s);
}
