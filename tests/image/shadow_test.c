/* SPDX-License-Identifier: MIT */
/*
 * Shadow-volume tests of one scene at one tier, against the Embree
 * visibility reference:
 *   vis          the vis channel of light 0 equals the ray-cast visibility
 *                from each pixel's surface point on all but 0.1% of the
 *                pixels whose P matches, and no differing pixel lies farther
 *                than one pixel from a reference shadow boundary; an area
 *                light's penumbra (reference strictly between 0 and 1 at
 *                or next to the pixel) is left to soft_test.c, which measures it against the
 *                integrated light: here its umbra and full light must be
 *                exact;
 *   zpass-zfail  with the eye outside every volume, z-pass and z-fail give
 *                the same visibility, pixel for pixel;
 *   two-pass     two-sided stencil with wrap equals the two-pass fallback;
 *   additivity   where light 0 is blocked, the frame equals the frame
 *                without light 0 within 1/255;
 *   gl-clean     no GL error, no call outside the profile.
 */
#include "aov.h"
#include "capture.h"
#include "image_test.h"
#include "reference.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define VIS_MAX_MISMATCH 0.001
/* A pixel in a light's terminator band (reference_terminator_band) is lit
 * by volumes where its stencil count at P, less its own mesh's volume, is
 * zero; the reference casts from the curved surface above P instead. The
 * two points lie a fraction of a facet apart, so they disagree only where a
 * shadow edge, or the mesh's own neighbouring facets (a torus's inner
 * ring), pass between them: at most this share of the compared pixels
 * (measured on the repository's scenes: at most 1 pixel a scene). */
#define BAND_MAX_MISMATCH 0.0001
#define ADDITIVITY_TOLERANCE (1.0 / 255.0)

typedef struct shadow_case {
    const reference *refr;
    run *r;
    stin_tier tier;
    const scene *s;
    const char *scene_name;
    int samples;          /* point samples of light 0 */
    const float *ref;     /* reference AOVs, rows bottom to top */
    const ref_hit *hits;
} shadow_case;

static void name_of(const shadow_case *c, const char *test, char *out, size_t size)
{
    snprintf(out, size, "%s/%s/volume-%s", stin_tier_name(c->tier), c->scene_name, test);
}

static const float *gl_px(const image *img, int x, int y)
{
    return img->pixels + ((size_t)(img->height - 1 - y) * img->width + x) * AOV_CHANNELS;
}

/* A shadow edge passes through the point: its triangle is within 0.1 degree
 * of edge-on to the light (the terminator, where rounding decides), or moving
 * the light by 0.1% of its distance changes its visibility (a ray grazing a
 * silhouette). */
static int grazing(const shadow_case *c, const ref_hit *h)
{
    const scene_light *l = &c->s->lights[0];
    float base, d = 0, p[3], cosine = 0;
    int k, axis;
    if (l->type == SCENE_LIGHT_DIRECTIONAL || l->radius > 0.0f)
        return 0;
    for (k = 0; k < 3; k++) {
        d += (l->position[k] - h->P[k]) * (l->position[k] - h->P[k]);
        cosine += h->Ng[k] * (l->position[k] - h->P[k]);
    }
    d = sqrtf(d);
    /* the pixel's own triangle within 0.1 degree of edge-on: the volume's
     * silhouette quad is coplanar with it to rounding */
    if (fabsf(cosine / d) < 2e-3f)
        return 1;
    d *= 1e-3f;
    base = reference_visibility_to(c->refr, h, l->position);
    for (axis = 0; axis < 6; axis++) {
        for (k = 0; k < 3; k++)
            p[k] = l->position[k] + (k == axis % 3 ? (axis < 3 ? d : -d) : 0.0f);
        if (reference_visibility_to(c->refr, h, p) != base)
            return 1;
    }
    return 0;
}

/* Reference visibility changes (or an object edge) within one pixel. */
static int near_boundary(const shadow_case *c, int x, int y, double threshold)
{
    int w = c->r->width, h = c->r->height, dx, dy;
    const ref_hit *me = &c->hits[(size_t)y * w + x];
    float v = c->ref[((size_t)y * w + x) * REFERENCE_CHANNELS + REFERENCE_CH_VIS_R];
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++) {
            int nx = x + dx, ny = y + dy;
            const ref_hit *o;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h)
                continue;
            o = &c->hits[(size_t)ny * w + nx];
            if (o->hit != me->hit || o->object != me->object)
                return 1;
            if (fabs(c->ref[((size_t)ny * w + nx) * REFERENCE_CHANNELS + REFERENCE_CH_VIS_R] - v) >
                threshold)
                return 1;
        }
    return 0;
}

/* An area light's reference is partial at or next to the pixel: its
 * penumbra, one pixel wider for a sliver of the light that the reference's
 * directions miss and one of stin's point samples does not. */
static int near_penumbra(const shadow_case *c, int x, int y)
{
    int w = c->r->width, h = c->r->height, dx, dy;
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++) {
            int nx = x + dx, ny = y + dy;
            float v;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h)
                continue;
            v = c->ref[((size_t)ny * w + nx) * REFERENCE_CHANNELS + REFERENCE_CH_VIS_R];
            if (v > 0.0f && v < 1.0f)
                return 1;
        }
    return 0;
}

/* The side of the surface the eye sees faces light 0: only there can the
 * light arrive, so only there is visibility a property of the technique
 * (z-pass cannot know that a sheet seen from behind shadows itself). */
static int faces_light(const shadow_case *c, const ref_hit *h)
{
    const scene_light *l = &c->s->lights[0];
    const float *eye = c->s->camera.eye;
    double to_eye = 0, to_light = 0;
    int k;
    for (k = 0; k < 3; k++) {
        double L = l->type == SCENE_LIGHT_DIRECTIONAL ? -l->direction[k] : l->position[k] - h->P[k];
        to_eye += h->Ng[k] * (eye[k] - h->P[k]);
        to_light += h->Ng[k] * L;
    }
    return (to_eye >= 0) == (to_light > 0);
}

static int opaque(const shadow_case *c, const ref_hit *h)
{
    return c->s->materials[c->s->objects[h->object].material].color[3] >= 1.0f;
}

static int p_matches(const shadow_case *c, const float *g, const float *ref)
{
    double d2 = 0;
    int k;
    if (!(g[AOV_Z] > 0.0f))
        return 0;
    for (k = 0; k < 3; k++) {
        double d = g[AOV_PX + k] - ref[REFERENCE_CH_PX + k];
        d2 += d * d;
    }
    (void)c;
    return sqrt(d2) <= 1e-3 * ref[REFERENCE_CH_Z] + 1e-3;
}

static void test_visibility(const shadow_case *c, const capture *cap)
{
    int w = c->r->width, h = c->r->height, x, y;
    /* one sample's worth, less what 8-bit accumulation can add up to */
    double threshold = 0.5 / c->samples;
    long compared = 0, differ = 0, far = 0, edge_on = 0, penumbra = 0, band = 0;
    char name[256], soft[96];
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const float *ref = c->ref + ((size_t)y * w + x) * REFERENCE_CHANNELS;
            const float *g = gl_px(&cap->img, x, y);
            if (!c->hits[(size_t)y * w + x].hit || !p_matches(c, g, ref))
                continue;
            if (c->samples > 1 && near_penumbra(c, x, y)) {
                penumbra++; /* soft_test.c's */
                continue;
            }
            compared++;
            if (fabs(g[AOV_VIS_R] - ref[REFERENCE_CH_VIS_R]) <= threshold)
                continue;
            if (grazing(c, &c->hits[(size_t)y * w + x])) {
                edge_on++; /* rounding decides: outside the budget */
                continue;
            }
            if (reference_terminator_band(c->refr, &c->hits[(size_t)y * w + x], 0)) {
                band++;
                if (getenv("STIN_TEST_VERBOSE"))
                    fprintf(stderr, "  band mismatch at pixel %d,%d: stin %.3f, reference %.3f\n",
                            x, h - 1 - y, g[AOV_VIS_R], ref[REFERENCE_CH_VIS_R]);
                continue;
            }
            differ++;
            if (near_boundary(c, x, y, threshold))
                continue;
            {
                far++;
                if (getenv("STIN_TEST_VERBOSE")) /* file rows count from the top */
                    fprintf(stderr, "  far mismatch at pixel %d,%d: stin %.3f, reference %.3f\n", x,
                            h - 1 - y, g[AOV_VIS_R], ref[REFERENCE_CH_VIS_R]);
            }
        }
    name_of(c, "vis", name, sizeof name);
    if ((differ > VIS_MAX_MISMATCH * compared || far) && c->r->out_dir) {
        char path[1024], err[256];
        snprintf(path, sizeof path, "%s/%s-%s-%s-%s-volume.exr", c->r->out_dir, c->r->platform_name,
                 c->r->profile_name, stin_tier_name(c->tier), c->scene_name);
        if (!image_write(path, &cap->img, 0, err, sizeof err))
            fprintf(stderr, "stin-imagetest: %s\n", err);
    }
    soft[0] = '\0';
    if (c->samples > 1)
        snprintf(soft, sizeof soft, ", %ld in an area light's penumbra (soft-volume measures them)",
                 penumbra);
    /* an area light has one shadow boundary per sample: 0.1% for each */
    report(c->r, compared && differ <= VIS_MAX_MISMATCH * c->samples * compared && far == 0 &&
                         band <= BAND_MAX_MISMATCH * compared
                     ? "PASS" : "FAIL",
           name, "visibility differs on %ld of %ld pixels (%.4f%%; at most 0.1%% a sample), %ld of them "
           "farther than one pixel from a reference shadow boundary (must be 0); not counted: %ld "
           "on a shadow edge in light space (0.1 degree from edge-on, or a 0.1%% light move "
           "changes them)%s; %ld in a terminator band (at most %.0f: the count at P, the "
           "reference from the curved surface); %d sample%s",
           differ, compared, compared ? 100.0 * differ / compared : 0.0, far, edge_on, soft, band,
           BAND_MAX_MISMATCH * compared, c->samples, c->samples == 1 ? "" : "s");
}

static void test_clean(const shadow_case *c, const capture *cap)
{
    char name[256];
    name_of(c, "gl-clean", name, sizeof name);
    capture_report_clean(c->r, name, cap);
}

/* Pixels whose channels [first, first+count) differ by more than tol, among
 * the covered pixels where the light can arrive and the surface is opaque. */
static long differing(const shadow_case *c, const image *a, const image *b, int first, int count,
                      double tol, double *max_diff)
{
    long n = 0;
    int x, y, k;
    *max_diff = 0;
    for (y = 0; y < a->height; y++)
        for (x = 0; x < a->width; x++) {
        const ref_hit *h = &c->hits[(size_t)y * a->width + x];
        size_t i = (size_t)(a->height - 1 - y) * a->width + x;
        double worst = 0;
        if (!h->hit || !faces_light(c, h) || !opaque(c, h))
            continue;
        for (k = first; k < first + count; k++) {
            double d = fabs(a->pixels[i * AOV_CHANNELS + k] - b->pixels[i * AOV_CHANNELS + k]);
            if (d > worst)
                worst = d;
        }
        if (worst > *max_diff)
            *max_diff = worst;
        if (worst > tol)
            n++;
        }
    return n;
}

static int render(const shadow_case *c, const scene *s, uint64_t debug, uint64_t mask, capture *out,
                  const char *test)
{
    capture_options o;
    char err[512], name[256];
    memset(&o, 0, sizeof o);
    o.tier = c->tier;
    o.shadows = STIN_TECH_SHADOWS_VOLUME;
    o.debug_flags = debug;
    o.extra_mask = mask;
    if (capture_render(c->r->plat, c->r->profile, s, &o, out, err, sizeof err))
        return 1;
    name_of(c, test, name, sizeof name);
    report(c->r, "FAIL", name, "%s", err);
    capture_free(out);
    return 0;
}

/* The casters stin counts with z-pass (its near-clip test found their
 * volumes clear of the near plane) give exactly what z-fail gives. */
static void test_zpass_zfail(const shadow_case *c, const capture *chosen)
{
    capture b;
    char name[256];
    double max_diff;
    long n;
    name_of(c, "zpass-zfail", name, sizeof name);
    if (!chosen->stats.shadows.zpass_casters) {
        report(c->r, "SKIP", name, "every caster needs z-fail here (its volume may reach the near "
                                   "plane)");
        return;
    }
    if (!render(c, c->s, STIN_DEBUG_VOLUME_ZFAIL, 0, &b, "zpass-zfail"))
        return;
    n = differing(c, &chosen->img, &b.img, AOV_VIS_R, 3, 0.0, &max_diff);
    report(c->r, n == 0 ? "PASS" : "FAIL", name,
           "with %u of %u casters counted by z-pass, visibility differs from all-z-fail on %ld "
           "light-facing opaque pixels (max %.4f; must be 0)", chosen->stats.shadows.zpass_casters,
           chosen->stats.shadows.zpass_casters + chosen->stats.shadows.zfail_casters, n, max_diff);
    capture_free(&b);
}

static void test_two_pass(const shadow_case *c, const capture *one_pass)
{
    const uint64_t two_sided = STIN_CAP_BIT(STIN_CAP_STENCIL_TWO_SIDE) |
                               STIN_CAP_BIT(STIN_CAP_SEPARATE_STENCIL);
    capture b;
    char name[256];
    double max_diff;
    long n;
    name_of(c, "two-pass", name, sizeof name);
    if (!(one_pass->caps_present & STIN_CAP_BIT(STIN_CAP_STENCIL_WRAP)) ||
        !(one_pass->caps_present & two_sided)) {
        report(c->r, "SKIP", name, "the profile has no two-sided stencil with wrap to compare");
        return;
    }
    if (!render(c, c->s, 0, two_sided | STIN_CAP_BIT(STIN_CAP_STENCIL_WRAP), &b, "two-pass"))
        return;
    n = differing(c, &one_pass->img, &b.img, AOV_R, AOV_CHANNELS, 0.0, &max_diff);
    report(c->r, n == 0 ? "PASS" : "FAIL", name,
           "two-sided+wrap and two-pass frames differ on %ld light-facing opaque pixels in any "
           "channel (max %.4f; must be 0)", n, max_diff);
    capture_free(&b);
}

/* Pixels whose light-0 visibility differs between two frames, and of those
 * how many each gets wrong against the reference. */
static long vis_disagreements(const shadow_case *c, const image *a, const image *b, long *a_wrong,
                              long *b_wrong)
{
    int w = c->r->width, h = c->r->height, x, y;
    long n = 0;
    *a_wrong = *b_wrong = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const ref_hit *hit = &c->hits[(size_t)y * w + x];
            const float *ref = c->ref + ((size_t)y * w + x) * REFERENCE_CHANNELS;
            float va = gl_px(a, x, y)[AOV_VIS_R], vb = gl_px(b, x, y)[AOV_VIS_R];
            if (!hit->hit || !faces_light(c, hit) || !opaque(c, hit) || fabsf(va - vb) < 0.5f)
                continue;
            n++;
            *a_wrong += fabsf(va - ref[REFERENCE_CH_VIS_R]) >= 0.5f;
            *b_wrong += fabsf(vb - ref[REFERENCE_CH_VIS_R]) >= 0.5f;
        }
    return n;
}

/* GL4 extrudes the volumes in a geometry shader. Its triangles must be the
 * ones the CPU builds (both counts), and its frame the CPU-built one's but
 * for depth ties: its light caps sit 2^-20 behind the surface instead of on
 * it, and a silhouette's edge pixels may round the other way. So at most
 * 0.05% of the compared pixels may disagree, and there the extruded frame
 * may be no more often wrong against the reference than the CPU's. */
static void test_gpu_extrusion(const shadow_case *c, const capture *gpu)
{
    capture cpu, counted;
    char name[256];
    long compared = 0, n, gpu_wrong, cpu_wrong;
    int x, y;
    name_of(c, "gpu-extrusion", name, sizeof name);
    if (!gpu->stats.shadows.volume_gpu_casters) {
        if (c->tier == STIN_TIER_GL4 && (gpu->caps_present & STIN_CAP_BIT(STIN_CAP_GEOMETRY_SHADER)))
            report(c->r, "FAIL", name, "tier gl4 with geometry shaders built every volume on the CPU");
        else
            report(c->r, "SKIP", name, "%s",
                   c->tier != STIN_TIER_GL4
                       ? "volumes are extruded on the GPU at tier gl4 only (geometry shaders)"
                       : "no geometry shaders here (as on OpenGL ES 3.0 and 3.1): volumes are "
                         "built on the CPU");
        return;
    }
    if (!render(c, c->s, STIN_DEBUG_VOLUME_CPU, 0, &cpu, "gpu-extrusion"))
        return;
    if (!render(c, c->s, STIN_DEBUG_VOLUME_COUNT, 0, &counted, "gpu-extrusion")) {
        capture_free(&cpu);
        return;
    }
    for (y = 0; y < c->r->height; y++)
        for (x = 0; x < c->r->width; x++) {
            const ref_hit *hit = &c->hits[(size_t)y * c->r->width + x];
            compared += hit->hit && faces_light(c, hit) && opaque(c, hit);
        }
    n = vis_disagreements(c, &gpu->img, &cpu.img, &gpu_wrong, &cpu_wrong);
    report(c->r,
           !cpu.stats.shadows.volume_gpu_casters &&
                   counted.stats.shadows.volume_triangles == cpu.stats.shadows.volume_triangles &&
                   n * 2000 <= compared && gpu_wrong <= cpu_wrong
               ? "PASS"
               : "FAIL",
           name,
           "%u casters extruded by the geometry shader emitted %u volume triangles, the CPU "
           "builds %u (must be equal); visibility differs from the CPU-built frame on %ld of %ld "
           "light-facing opaque pixels (at most 0.05%%), wrong against the reference on %ld of "
           "them, the CPU's on %ld (may not be fewer)",
           gpu->stats.shadows.volume_gpu_casters, counted.stats.shadows.volume_triangles,
           cpu.stats.shadows.volume_triangles, n, compared, gpu_wrong, cpu_wrong);
    capture_free(&cpu);
    capture_free(&counted);
}

/* Where light 0 is blocked, removing it changes nothing. */
static void test_additivity(const shadow_case *c, const capture *all)
{
    scene without = *c->s;
    capture b;
    char name[256];
    int w = c->r->width, h = c->r->height, x, y, k;
    long compared = 0, over = 0;
    double worst = 0;
    name_of(c, "additivity", name, sizeof name);
    if (c->s->light_count < 2) {
        report(c->r, "SKIP", name, "needs two lights or more");
        return;
    }
    without.lights = c->s->lights + 1;
    without.light_count = c->s->light_count - 1;
    if (!render(c, &without, 0, 0, &b, "additivity"))
        return;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const float *ref = c->ref + ((size_t)y * w + x) * REFERENCE_CHANNELS;
            const float *g = gl_px(&all->img, x, y), *g2 = gl_px(&b.img, x, y);
            double d = 0;
            if (!c->hits[(size_t)y * w + x].hit || !p_matches(c, g, ref) ||
                ref[REFERENCE_CH_VIS_R] > 0.0f || g[AOV_VIS_R] > 0.0f || near_boundary(c, x, y, 0.5))
                continue;
            compared++;
            for (k = 0; k < 3; k++)
                if (fabs(g[AOV_R + k] - g2[AOV_R + k]) > d)
                    d = fabs(g[AOV_R + k] - g2[AOV_R + k]);
            if (d > worst)
                worst = d;
            if (d > ADDITIVITY_TOLERANCE + 1e-6)
                over++;
        }
    if (!compared)
        report(c->r, "SKIP", name, "light 0 is blocked nowhere in view");
    else
        report(c->r, over == 0 ? "PASS" : "FAIL", name,
               "where light 0 is blocked (%ld pixels) the frame equals the frame without it "
               "within 1/255 on all but %ld (max %.4f)", compared, over, worst);
    capture_free(&b);
}

/* Everything a case needs but the render: the scene and its references.
 * 0 when there is nothing to test (no lights, or a failure reported). */
typedef struct shadow_set {
    scene s;
    reference *ref;
    ref_hit *hits;
    float *refimg;
    char scene_name[128];
    int loaded;
} shadow_set;

static void shadow_set_free(shadow_set *set)
{
    free(set->hits);
    free(set->refimg);
    if (set->ref)
        reference_destroy(set->ref);
    if (set->loaded)
        scene_free(&set->s);
}

static int shadow_set_up(run *r, stin_tier tier, const char *path, shadow_set *set,
                         shadow_case *c)
{
    char err[512];
    memset(set, 0, sizeof *set);
    snprintf(set->scene_name, sizeof set->scene_name, "%s", scene_base_name(path));
    if (!scene_load(path, &set->s, err, sizeof err))
        return 0; /* test_scene reported it */
    set->loaded = 1;
    c->r = r;
    c->tier = tier;
    c->s = &set->s;
    c->scene_name = set->scene_name;
    c->samples = set->s.light_count > 0 && set->s.lights[0].radius > 0.0f &&
                         set->s.lights[0].type != SCENE_LIGHT_DIRECTIONAL
                     ? 32 /* stin's default desc.shadows.soft_samples */
                     : 1;
    if (!set->s.light_count)
        return 0;
    set->ref = reference_create(&set->s, err, sizeof err);
    /* volumes take the terminator rule on every smooth mesh, on every tier */
    if (set->ref)
        reference_facet_terminator(set->ref, REFERENCE_FACETS_NONE);
    set->hits = malloc(sizeof *set->hits * (size_t)r->width * r->height);
    set->refimg = malloc(sizeof(float) * REFERENCE_CHANNELS * (size_t)r->width * r->height);
    if (!set->ref || !set->hits || !set->refimg ||
        !reference_primary(set->ref, r->width, r->height, set->hits) ||
        !reference_render_ex(&set->s, set->ref, r->width, r->height, 0, REFERENCE_RENDER_SHADOWED,
                             set->refimg)) {
        char name[256];
        snprintf(name, sizeof name, "%s/%s/volume", stin_tier_name(tier), set->scene_name);
        report(r, "FAIL", name, "reference: %s", set->ref ? "render failed" : err);
        return 0;
    }
    c->ref = set->refimg;
    c->hits = set->hits;
    c->refr = set->ref;
    return 1;
}

void shadow_tests(run *r, stin_tier tier, const char *path)
{
    shadow_set set;
    shadow_case c;
    capture cap;
    if (shadow_set_up(r, tier, path, &set, &c) && render(&c, &set.s, 0, 0, &cap, "vis")) {
        test_clean(&c, &cap);
        test_visibility(&c, &cap);
        test_zpass_zfail(&c, &cap);
        test_two_pass(&c, &cap);
        test_gpu_extrusion(&c, &cap);
        test_additivity(&c, &cap);
        capture_free(&cap);
    }
    shadow_set_free(&set);
}

void shadow_vis_rows(run *r, stin_tier tier, const char *path, const capture *cap)
{
    shadow_set set;
    shadow_case c;
    if (shadow_set_up(r, tier, path, &set, &c))
        test_visibility(&c, cap);
    shadow_set_free(&set);
}
