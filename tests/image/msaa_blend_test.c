/* SPDX-License-Identifier: MIT */
/*
 * Blended draws and translucent shadows into a multisampled target (issue
 * 39): msaa/glass.json (two coloured panes over a floor, an opaque pillar
 * in front of one) drawn into the platform's 4x framebuffer object with
 * each peel ("depth-peel", "dual-peel"), the sorted transparency (whole
 * objects back to front, blended per sample; on GL1 too, its panes casting
 * fully: "translucent-solid") and each translucent-shadows
 * technique ("deep", "coloured"; volumes for the opaque pillar), against
 * the reference camera composite lit through the lights' transmittance
 * (reference_composite_at) at the target's own sample positions
 * (glGetMultisamplefv), box-filtered as the resolve averages the samples.
 * The check is the silhouette band: pixels within one pixel of a pixel
 * whose samples see more than one first surface. A sample that took
 * another surface's colour there (a pane's composite on the floor beside
 * it, the floor where the pane covers it, a pillar or floor sample with
 * the other's coloured shadow) is a one-pixel halo.
 */
#include "image_test.h"
#include "msaa_shared.h"
#include "reference.h"
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define BLEND_SAMPLES 4
/* One sample in four of the blue pane against the floor beside it is 0.1
 * or more in a channel; the layers and their composite are 8-bit on GL2
 * (a rounding a store: 3/255 as peel_test.c's) and each surface is shaded
 * at the pixel centre where the reference shades the sample's point. */
#define BLEND_TOLERANCE 0.03
/* Of the band's pixels: measured 3 with the covered samples alone (stin.h,
 * MULTISAMPLED TARGETS: two where both panes and the floor meet in a
 * pixel, one at a pillar corner); the composite over every sample puts 190
 * of 1,325 beyond. GL1's sorted (panes casting fully, lit per vertex):
 * 1 of 1,323; a single-sampled frame resolved puts 357 beyond. */
#define BLEND_MAX_BAND_OVER 6
#define BLEND_MIN_BAND 300
/* Of the pixels away from every edge: measured 0 of 16,653 on every row.
 * The translucent shadows decide most of them: with the panes casting
 * opaque shadows ("opaque" in deep's or coloured's place) 2,262 differ
 * (and 102 of the band), so a transmittance that is wrong away from the
 * silhouettes fails too, not only a halo. */
#define BLEND_MAX_ELSEWHERE_OVER 20

typedef struct blend_case {
    stin_tier tier;
    stin_technique transparency, translucent;
} blend_case;

typedef struct blend_ref {
    int w, h, n;
    int per_vertex;  /* the tier's lighting (GL1: Gouraud) */
    unsigned flags;  /* how the layers are lit (reference_composite_at) */
    int *object;   /* n x w x h: the first surface's object at each sample, -1 background */
    int *stack;    /* n x w x h: that object and the transparent surfaces crossed */
    float *colour; /* w x h x 3: the samples' mean */
    unsigned char *blended;    /* object i's material has opacity < 1 */
    unsigned char *shade_edge; /* w x h: a sample that crosses the centre's surfaces
                                * has another colour there (a shadow edge inside
                                * the pixel: per-pixel shading decides it) */
} blend_ref;

static double channel_diff(const float *a, const float *b)
{
    double d = 0;
    int c;
    for (c = 0; c < 3; c++)
        d = fmax(d, fabs((double)a[c] - b[c]));
    return d;
}

/* The composite of window point (px, py) and its stack code. */
static int sample_at(const scene *s, const reference *ref, const blend_ref *m, const ref_hit *h,
                     double px, double py, float rgb[3], int *stack)
{
    float rgba[4];
    int layers =
        reference_composite_at(s, ref, m->w, m->h, px, py, m->per_vertex, m->flags, rgba, NULL);
    memcpy(rgb, rgba, 3 * sizeof(float));
    *stack = (h->hit ? h->object + 1 : 0) * 1024 + layers;
    return layers >= 0;
}

static int ref_build(const scene *s, const float pos[][2], int n, blend_ref *m, char *err,
                     size_t err_size)
{
    reference *ref = reference_create(s, err, err_size);
    size_t px = (size_t)m->w * m->h, i;
    ref_hit *hits = malloc(sizeof *hits * px), *centre = malloc(sizeof *centre * px);
    float *at_centre = malloc(sizeof(float) * 3 * px);
    int *centre_stack = malloc(sizeof(int) * px);
    int k, ok = ref != NULL;
    m->n = n;
    m->object = malloc(sizeof(int) * px * (size_t)n);
    m->stack = malloc(sizeof(int) * px * (size_t)n);
    m->colour = calloc(px * 3, sizeof(float));
    m->shade_edge = calloc(px, 1);
    m->blended = calloc((size_t)s->object_count + 1, 1);
    for (i = 0; m->blended && i < (size_t)s->object_count; i++)
        m->blended[i] = s->materials[s->objects[i].material].color[3] < 1.0f;
    ok = ok && m->blended && hits && centre && at_centre && centre_stack && m->object && m->stack &&
         m->colour && m->shade_edge;
    ok = ok && reference_primary(ref, m->w, m->h, centre);
    for (i = 0; ok && i < px; i++)
        ok = sample_at(s, ref, m, &centre[i], (double)(i % (size_t)m->w) + 0.5,
                       (double)(i / (size_t)m->w) + 0.5, at_centre + 3 * i, &centre_stack[i]);
    for (k = 0; ok && k < n; k++) {
        ok = reference_primary_at(ref, m->w, m->h, pos[k][0], pos[k][1], hits);
        for (i = 0; ok && i < px; i++) {
            size_t ki = px * (size_t)k + i;
            float rgb[3];
            int c;
            ok = sample_at(s, ref, m, &hits[i], (double)(i % (size_t)m->w) + pos[k][0],
                           (double)(i / (size_t)m->w) + pos[k][1], rgb, &m->stack[ki]);
            m->object[ki] = hits[i].hit ? hits[i].object : -1;
            for (c = 0; c < 3; c++)
                m->colour[3 * i + c] += rgb[c] / (float)n;
            if (m->stack[ki] == centre_stack[i] &&
                channel_diff(rgb, at_centre + 3 * i) > BLEND_TOLERANCE)
                m->shade_edge[i] = 1;
        }
    }
    if (ref)
        reference_destroy(ref);
    free(hits);
    free(centre);
    free(at_centre);
    free(centre_stack);
    if (!ok && err[0] == '\0')
        snprintf(err, err_size, "reference failed");
    return ok;
}

static void ref_free(blend_ref *m)
{
    free(m->object);
    free(m->stack);
    free(m->colour);
    free(m->shade_edge);
    free(m->blended);
    memset(m, 0, sizeof *m);
}

/* Samples of pixel (x, y) differ in `codes` (n images of w x h); for the
 * first surfaces (m->object), only where one of them is opaque or the
 * background: a blended surface's edge over another blended one is an
 * inner edge (the layers hold one stack a pixel). */
static int mixed(const blend_ref *m, const int *codes, int x, int y)
{
    size_t px = (size_t)m->w * m->h, i = (size_t)y * m->w + x;
    int k, differ = 0, opaque = 0;
    for (k = 0; k < m->n; k++) {
        int o = m->object[px * (size_t)k + i];
        differ |= codes[px * (size_t)k + i] != codes[i];
        opaque |= o < 0 || m->blended[o] == 0;
    }
    return differ && (codes != m->object || opaque);
}

/* Whether a pixel of the 3 x 3 around (x, y) has the property. */
static int near(const blend_ref *m, const int *codes, int x, int y)
{
    int dx, dy;
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++) {
            int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= m->w || yy >= m->h)
                continue;
            if (codes ? mixed(m, codes, xx, yy) : m->shade_edge[(size_t)yy * m->w + xx])
                return 1;
        }
    return 0;
}

typedef struct band_result {
    long band, over, inner, inner_over, compared, compared_over, left_out;
    double band_max;
} band_result;

/* The silhouette band (first surfaces differ among the samples, one of
 * them opaque or the background), the inner band (a blended surface's edge
 * over another, or seen through one: the layers hold one stack a pixel)
 * and the rest; pixels near a shadow edge inside a pixel are left out. */
static void compare_band(const blend_ref *m, const uint8_t *rgba, int stride, band_result *b)
{
    int x, y, c;
    memset(b, 0, sizeof *b);
    for (y = 0; y < m->h; y++)
        for (x = 0; x < m->w; x++) {
            const uint8_t *p = rgba + 4 * ((size_t)y * stride + x);
            float got[3];
            double d;
            for (c = 0; c < 3; c++)
                got[c] = p[c] / 255.0f;
            d = channel_diff(got, m->colour + 3 * ((size_t)y * m->w + x));
            if (near(m, NULL, x, y)) {
                b->left_out++;
            } else if (near(m, m->object, x, y)) {
                b->band++;
                b->over += d > BLEND_TOLERANCE;
                b->band_max = fmax(b->band_max, d);
            } else if (near(m, m->stack, x, y)) {
                b->inner++;
                b->inner_over += d > BLEND_TOLERANCE;
            } else {
                b->compared++;
                b->compared_over += d > BLEND_TOLERANCE;
            }
        }
}

static void one_case(run *r, const scene *s, const blend_case *bc, const float pos[][2], int n,
                     blend_ref *m)
{
    msaa_techniques tech = {bc->tier, STIN_TECH_SHADOWS_VOLUME, bc->transparency,
                            bc->translucent, STIN_TECH_NONE, STIN_TECH_NONE};
    char name[128], why[512] = "";
    uint8_t *rgba = malloc((size_t)r->width * r->height * 4);
    band_result b;
    int got, pass;
    snprintf(name, sizeof name, "%s/msaa-blend-%s-%s", stin_tier_name(bc->tier),
             stin_technique_name(bc->transparency), stin_technique_name(bc->translucent));
    got = rgba ? msaa_render(r, s, &tech, rgba, why, sizeof why) : 0;
    if (got < 0) {
        report(r, "SKIP", name, "%s", why);
    } else if (!got) {
        report(r, "FAIL", name, "%s", why);
    } else if (!m->colour && !ref_build(s, pos, n, m, why, sizeof why)) {
        report(r, "FAIL", name, "reference: %s", why);
        ref_free(m);
    } else {
        compare_band(m, rgba, r->width, &b);
        pass = b.over <= BLEND_MAX_BAND_OVER && b.band >= BLEND_MIN_BAND &&
               b.compared_over <= BLEND_MAX_ELSEWHERE_OVER;
        report(r, pass ? "PASS" : "FAIL", name,
               "%d samples: %ld of %ld silhouette-band pixels beyond %.2f of the reference "
               "at the samples (max %.3f; at most %d); inner edges %ld of %ld; elsewhere "
               "%ld of %ld (at most %d); %ld near shadow edges left out",
               n, b.over, b.band, BLEND_TOLERANCE, b.band_max, BLEND_MAX_BAND_OVER,
               b.inner_over, b.inner, b.compared_over, b.compared, BLEND_MAX_ELSEWHERE_OVER,
               b.left_out);
        if (!pass)
            msaa_save_pair(r, name, rgba, m->colour, m->w, m->h);
    }
    free(rgba);
}

/* GL4 on gl45-core (gl33-core runs the same programs), GL2 and GL1 on
 * gl21 (the GL 1.x profiles hide framebuffer objects from stin). */
static int runs_here(const run *r, stin_tier tier)
{
    if (tier == STIN_TIER_GL4)
        return !strcmp(r->profile_name, "gl45-core");
    return !strcmp(r->profile_name, "gl21");
}

void msaa_blend_tests(run *r, stin_tier tier, const char *path)
{
    static const blend_case cases[] = {
        {STIN_TIER_GL4, STIN_TECH_TRANSPARENCY_DUAL_PEEL, STIN_TECH_TRANSLUCENT_DEEP},
        {STIN_TIER_GL4, STIN_TECH_TRANSPARENCY_DEPTH_PEEL, STIN_TECH_TRANSLUCENT_DEEP},
        {STIN_TIER_GL4, STIN_TECH_TRANSPARENCY_DUAL_PEEL, STIN_TECH_TRANSLUCENT_COLOURED},
        {STIN_TIER_GL2, STIN_TECH_TRANSPARENCY_DEPTH_PEEL, STIN_TECH_TRANSLUCENT_COLOURED},
        {STIN_TIER_GL4, STIN_TECH_TRANSPARENCY_SORTED, STIN_TECH_TRANSLUCENT_DEEP},
        {STIN_TIER_GL2, STIN_TECH_TRANSPARENCY_SORTED, STIN_TECH_TRANSLUCENT_COLOURED},
        {STIN_TIER_GL1, STIN_TECH_TRANSPARENCY_SORTED, STIN_TECH_TRANSLUCENT_SOLID},
    };
    float pos[MSAA_MAX_SAMPLES][2];
    char name[64];
    blend_ref m;
    size_t i;
    scene s;
    int n;
    if (strcmp(scene_base_name(path), "shadow-overlap") || !runs_here(r, tier))
        return;
    snprintf(name, sizeof name, "%s/msaa-blend", stin_tier_name(tier));
    n = msaa_open(r, path, "glass.json", BLEND_SAMPLES, name, &s, pos);
    if (!n)
        return;
    memset(&m, 0, sizeof m);
    m.w = s.width;
    m.h = s.height;
    /* GL1 has no translucent shadows: the panes cast fully, lit per vertex */
    m.per_vertex = tier == STIN_TIER_GL1 ? msaa_gl1_per_vertex(r, &s) : 0;
    m.flags = tier == STIN_TIER_GL1 ? REFERENCE_RENDER_SHADOWED : REFERENCE_RENDER_TRANSMITTANCE;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
        if (cases[i].tier == tier)
            one_case(r, &s, &cases[i], (const float(*)[2])pos, n, &m);
    ref_free(&m);
    msaa_close(r, name, &s);
}
