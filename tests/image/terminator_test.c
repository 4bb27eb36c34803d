/* SPDX-License-Identifier: MIT */
/*
 * The shadow terminator (issue 37, item 2), on the scenes
 * tests/scenes/terminator-*.json: one convex object alone (a low-poly
 * sphere, a box, a capped cylinder), lit from two or three directions, some
 * grazing. A convex object cannot shadow the side that faces a light, so
 * every pixel whose shading normal (the reference hit's interpolated
 * normal) has N.L > TERMINATOR_MIN_COS toward light L must come out lit
 * (visibility >= 0.5 in the visibility output of a frame with L first).
 * This asserts the physics, not the terminator rule stin and the reference
 * share: the reference's own count is printed beside it, not used.
 * Per shadow technique the tier runs: vdsm and volumes are exact, so none
 * may be shadowed; the maps' depth resolution allows acne on at most
 * MAP_BUDGET of those pixels at their default size. A technique that still
 * decides self-shadowing by the facet (GL1's map-combine: stin.h) reports
 * SKIP with its count until it adopts the rule. A point light that a GL1 map technique leaves to stencil volumes
 * (no six faces) is left out of that technique's count.
 */
#include "image_test.h"
#include "reference.h"
#include "scene.h"
#include "test_context.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Clear of the terminator: the shading normal turned more than 3 degrees
 * toward the light, where lighting is already visibly above 0. */
#define TERMINATOR_MIN_COS 0.05
#define MAP_BUDGET 0.001
/* Which face a pixel on a silhouette or a crease shows is rasterisation's
 * rounding, not shadowing: pixels with a 4-neighbour on the background,
 * another object or a normal more than 30 degrees apart are left out
 * (the sphere's and the cylinder's smooth edges turn a few degrees). */
#define CREASE_COS 0.866

typedef struct terminator_case {
    run *r;
    scene *s;
    const reference *ref;
    const ref_hit *hits;
    uint8_t *color;
} terminator_case;

/* The unit direction from the hit toward light li. */
static void toward_light(const scene_light *l, const ref_hit *h, double out[3])
{
    double len = 0.0;
    int k;
    for (k = 0; k < 3; k++) {
        out[k] = l->type == SCENE_LIGHT_DIRECTIONAL ? -(double)l->direction[k]
                                                     : (double)l->position[k] - h->P[k];
        len += out[k] * out[k];
    }
    len = sqrt(len);
    for (k = 0; k < 3; k++)
        out[k] = len > 0.0 ? out[k] / len : 0.0;
}

static int on_edge(const terminator_case *c, int x, int y)
{
    static const int step[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    const ref_hit *h = &c->hits[(size_t)y * c->r->width + x];
    int k;
    for (k = 0; k < 4; k++) {
        int nx = x + step[k][0], ny = y + step[k][1];
        const ref_hit *n;
        if (nx < 0 || ny < 0 || nx >= c->r->width || ny >= c->r->height)
            return 1;
        n = &c->hits[(size_t)ny * c->r->width + nx];
        if (!n->hit || n->object != h->object ||
            h->N[0] * n->N[0] + h->N[1] * n->N[1] + h->N[2] * n->N[2] < CREASE_COS)
            return 1;
    }
    return 0;
}

/* Light li's lit-side pixels (*facing) and, among them, those the image
 * (R: light li's visibility) or, with image NULL, the reference shadows. */
static long shadowed_lit_side(const terminator_case *c, int li, const uint8_t *image, long *facing)
{
    const scene_light *l = &c->s->lights[li];
    size_t i, pixels = (size_t)c->r->width * c->r->height;
    long n = 0;
    *facing = 0;
    for (i = 0; i < pixels; i++) {
        const ref_hit *h = &c->hits[i];
        double L[3];
        if (!h->hit || on_edge(c, (int)(i % (size_t)c->r->width), (int)(i / (size_t)c->r->width)))
            continue;
        toward_light(l, h, L);
        if (h->N[0] * L[0] + h->N[1] * L[1] + h->N[2] * L[2] <= TERMINATOR_MIN_COS)
            continue;
        (*facing)++;
        n += image ? image[4 * i] < 128 : reference_visibility(c->ref, h, li) < 0.5f;
    }
    return n;
}

/* 1 when technique t decides self-shadowing by the facet: map-combine
 * (its combiner stages cannot join the side test to the depth compare). */
static int by_facet(stin_technique t)
{
    return t == STIN_TECH_SHADOWS_MAP_COMBINE;
}

/* 1 when technique t leaves light l to stencil volumes in context ctx: a
 * point light where the GL1 maps have no six faces (map-combine, map-depth
 * without framebuffer objects). The volumes' own check counts it. */
static int volumes_stand_in(const stin_context *ctx, stin_technique t, const scene_light *l)
{
    int fbo = (stin_query_caps(ctx)->present & STIN_CAP_BIT(STIN_CAP_FBO)) != 0;
    return l->type == SCENE_LIGHT_POINT && (t == STIN_TECH_SHADOWS_MAP_COMBINE ||
                                            (t == STIN_TECH_SHADOWS_MAP_DEPTH && !fbo));
}

/* facets: STIN_DEBUG_VOLUME_FACETS, the volumes as before they took the
 * rule, whose steps the check must see (0: the technique as it is). */
static void check_technique(terminator_case *c, stin_tier tier, const char *scene_name,
                            stin_technique t, uint64_t facets)
{
    test_context tc;
    stin_frame_desc fd;
    char name[160], counts[160];
    long shadowed = 0, facing = 0, ref_shadowed = 0, allowed;
    size_t used = 0;
    int li, exact = t == STIN_TECH_SHADOWS_VDSM || t == STIN_TECH_SHADOWS_VOLUME, failed = 0, facet;
    if (!test_context_create_debug(&tc, c->r, c->s, tier, t, 1, facets))
        return; /* not a technique of this tier and profile */
    snprintf(name, sizeof name, "%s/%s/terminator-%s%s", stin_tier_name(tier), scene_name,
             stin_technique_name(t), facets ? "-facets" : "");
    counts[0] = '\0';
    test_frame_desc(c->r, c->s, &fd);
    fd.output = STIN_OUTPUT_VISIBILITY;
    for (li = 0; li < c->s->light_count; li++) {
        long lit_side, n, ref_n;
        if (volumes_stand_in(tc.ctx, t, &c->s->lights[li])) {
            if (used < sizeof counts)
                used += (size_t)snprintf(counts + used, sizeof counts - used,
                                         "%slight %d: volumes", li ? ", " : "", li);
            continue;
        }
        if (test_context_frame(&tc, c->s, &fd, li) != STIN_OK ||
            !stin_platform_read_color(c->r->plat, c->color)) {
            failed = 1;
            break;
        }
        n = shadowed_lit_side(c, li, c->color, &lit_side);
        ref_n = shadowed_lit_side(c, li, NULL, &lit_side);
        shadowed += n;
        facing += lit_side;
        ref_shadowed += ref_n;
        if (used < sizeof counts)
            used += (size_t)snprintf(counts + used, sizeof counts - used, "%slight %d %ld of %ld",
                                     li ? ", " : "", li, n, lit_side);
    }
    facet = by_facet(t);
    test_context_destroy(&tc);
    allowed = exact ? 0 : (long)(MAP_BUDGET * (double)facing);
    if (failed)
        report(c->r, "FAIL", name, "a visibility frame failed");
    else if (facets)
        report(c->r, shadowed > allowed ? "PASS" : "INFO", name,
               "the check can fail: volumes keeping the facets (STIN_DEBUG_VOLUME_FACETS) shadow "
               "%ld of %ld pixels whose shading normal faces a light (%s)%s",
               shadowed, facing, counts, shadowed > allowed ? "" : ": no smooth triangle here");
    else if (facet)
        report(c->r, "SKIP", name,
               "open: %s still decides self-shadowing by the facet; %ld of %ld pixels whose "
               "shading normal faces a light shadowed (%s; %ld to be allowed)",
               stin_technique_name(t), shadowed, facing, counts, allowed);
    else
        report(c->r, shadowed <= allowed && facing > 0 ? "PASS" : "FAIL", name,
               "%ld of %ld pixels whose shading normal faces a light (N.L > %.2f) shadowed "
               "(%s; at most %ld allowed); the shared terminator rule's reference shadows %ld",
               shadowed, facing, TERMINATOR_MIN_COS, counts, allowed, ref_shadowed);
}

void terminator_tests(run *r, stin_tier tier, const char *path)
{
    static const stin_technique shadows[] = {
        STIN_TECH_SHADOWS_VDSM, STIN_TECH_SHADOWS_VOLUME, STIN_TECH_SHADOWS_MAP_PCF,
        STIN_TECH_SHADOWS_MAP_DEPTH, STIN_TECH_SHADOWS_MAP_COMBINE};
    const char *base = scene_base_name(path);
    char scene_name[128], err[256], name[192];
    terminator_case c;
    scene s;
    reference *ref = NULL;
    ref_hit *hits = NULL;
    size_t i, pixels = (size_t)r->width * r->height;
    if (strncmp(base, "terminator-", 11) != 0)
        return;
    snprintf(scene_name, sizeof scene_name, "%s", base);
    snprintf(name, sizeof name, "%s/%s/terminator", stin_tier_name(tier), scene_name);
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    memset(&c, 0, sizeof c);
    hits = malloc(sizeof *hits * pixels);
    c.color = malloc(pixels * 4);
    if (!hits || !c.color || !(ref = reference_create(&s, err, sizeof err)) ||
        !reference_primary(ref, r->width, r->height, hits)) {
        report(r, "FAIL", name, "reference: %s", ref ? "primary rays failed" : err);
    } else {
        c.r = r;
        c.s = &s;
        c.ref = ref;
        c.hits = hits;
        for (i = 0; i < sizeof shadows / sizeof shadows[0]; i++)
            check_technique(&c, tier, scene_name, shadows[i], 0);
        check_technique(&c, tier, scene_name, STIN_TECH_SHADOWS_VOLUME,
                        STIN_DEBUG_VOLUME_FACETS);
    }
    if (ref)
        reference_destroy(ref);
    free(hits);
    free(c.color);
    scene_free(&s);
}
