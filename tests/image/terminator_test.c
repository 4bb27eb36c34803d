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
 * The translucent shadow maps ("deep", "coloured") take the same rule: with
 * the meshes at opacity TRANSLUCENT_OPACITY, at most MAP_BUDGET of those
 * pixels may get a light's transmittance below 1 - TRANSMITTANCE_TOLERANCE
 * (the object darkening its own lit side), under vdsm and map-pcf for the
 * opaque casters, and none with maps of FINE_MAP_SIZE, where the lookup's
 * push no longer hides the facets' steps; the reference's count (its
 * transmittance rays take the rule too) is printed beside it.
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
/* the translucent check's opacity, and its tolerance: the visibility
 * output is 8-bit and rounds by 1/255; a lit pixel's maps hold exactly 1
 * (deep's float layers, coloured's 8-bit product) */
#define TRANSLUCENT_OPACITY 0.5f
#define TRANSMITTANCE_TOLERANCE (2.0 / 255.0)
/* At the default size (512) the lookup's push of 1.5 texels (0.035 at light
 * 0's distance) is wider than a 16-slice sphere's sag between its facets
 * (1 - cos(11.25 deg) = 0.019), so the facets' steps hide behind it; at
 * 2048 (0.009) they show unless the lookup takes the terminator rule, which
 * leaves none there. */
#define FINE_MAP_SIZE 2048u
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
    scene translucent;             /* the scene with its materials at TRANSLUCENT_OPACITY */
    const reference *translucent_ref;
    int open_mesh; /* an open mesh, whose walls shadow each other: the reference decides */
} terminator_case;

/* Per-light counts summed over a check's lights, and their text. */
typedef struct light_tally {
    long bad, facing, ref_bad, wrongly_lit, on_edge;
    char counts[160];
    size_t used;
} light_tally;

/* Light li's count: bad of lit pixels (the reference's ref_bad). */
static void tally_light(light_tally *t, int li, long bad, long lit, long ref_bad)
{
    t->bad += bad;
    t->facing += lit;
    t->ref_bad += ref_bad;
    if (t->used < sizeof t->counts)
        t->used += (size_t)snprintf(t->counts + t->used, sizeof t->counts - t->used,
                                    "%slight %d %ld of %ld", li ? ", " : "", li, bad, lit);
}

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

/* 1 when pixel i is on light li's lit side: its shading normal turned
 * more than TERMINATOR_MIN_COS toward the light, away from edges. */
static int lit_side(const terminator_case *c, int li, size_t i)
{
    const ref_hit *h = &c->hits[i];
    double L[3];
    if (!h->hit || on_edge(c, (int)(i % (size_t)c->r->width), (int)(i / (size_t)c->r->width)))
        return 0;
    toward_light(&c->s->lights[li], h, L);
    return h->N[0] * L[0] + h->N[1] * L[1] + h->N[2] * L[2] > TERMINATOR_MIN_COS;
}

/* Light li's lit-side pixels (*facing) and, among them, those the image
 * (R: light li's visibility) or, with image NULL, the reference shadows. */
static long shadowed_lit_side(const terminator_case *c, int li, const uint8_t *image, long *facing)
{
    size_t i, pixels = (size_t)c->r->width * c->r->height;
    long n = 0;
    *facing = 0;
    for (i = 0; i < pixels; i++) {
        if (!lit_side(c, li, i))
            continue;
        (*facing)++;
        n += image ? image[4 * i] < 128 : reference_visibility(c->ref, &c->hits[i], li) < 0.5f;
    }
    return n;
}

/* An open mesh's walls shadow each other's lit side, so there the
 * reference (the terminator rule from the curved surface) is the truth:
 * of light li's lit-side pixels, those the image shadows where the
 * reference lights them (returned) and those it lights where the reference
 * shadows them (*wrongly_lit: a count taken back where the ray left through
 * the mesh's hole and something else shadows it). A pixel next to one the
 * reference decides otherwise lies on a shadow edge, where rasterisation's
 * rounding decides (shadow_test.c's tolerance): *on_edge counts those. */
static long open_mesh_counts(const terminator_case *c, int li, const uint8_t *image,
                             long *wrongly_lit, long *on_edge)
{
    int w = c->r->width, h = c->r->height, x, y, dx, dy;
    unsigned char *truth = malloc((size_t)w * h);
    long n = 0;
    *wrongly_lit = *on_edge = 0;
    if (!truth)
        return -1;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const ref_hit *hit = &c->hits[(size_t)y * w + x];
            truth[(size_t)y * w + x] = hit->hit && reference_visibility(c->ref, hit, li) < 0.5f;
        }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            int shadowed = image[4 * i] < 128, edge = 0;
            if (!lit_side(c, li, i) || shadowed == truth[i])
                continue;
            for (dy = -1; dy <= 1; dy++)
                for (dx = -1; dx <= 1; dx++)
                    edge |= x + dx >= 0 && x + dx < w && y + dy >= 0 && y + dy < h &&
                            truth[(size_t)(y + dy) * w + x + dx] != truth[i];
            if (edge)
                (*on_edge)++;
            else if (shadowed)
                n++;
            else
                (*wrongly_lit)++;
        }
    free(truth);
    return n;
}

/* Light li's lit-side pixels (*facing) and, among them, those whose
 * transmittance is below 1 - TRANSMITTANCE_TOLERANCE in any channel: in a
 * visibility frame's read-back (vis, rows bottom to top as the
 * reference's, light li drawn first; 1 where depth shows the background,
 * as in the AOV image) or,
 * with vis NULL, the translucent scene's reference. */
static long dimmed_lit_side(const terminator_case *c, int li, const uint8_t *vis,
                            const float *depth, long *facing)
{
    size_t i, pixels = (size_t)c->r->width * c->r->height;
    long n = 0;
    *facing = 0;
    for (i = 0; i < pixels; i++) {
        float t[3];
        int k, dim = 0;
        if (!lit_side(c, li, i))
            continue;
        (*facing)++;
        if (vis) {
            for (k = 0; k < 3; k++)
                t[k] = depth[i] < 1.0f ? vis[4 * i + k] / 255.0f : 1.0f;
        } else {
            reference_transmittance(c->translucent_ref, &c->hits[i], li, t);
        }
        for (k = 0; k < 3; k++)
            dim |= t[k] < 1.0 - TRANSMITTANCE_TOLERANCE;
        n += dim;
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

/* debug: STIN_DEBUG_VOLUME_FACETS, the volumes as before they took the
 * rule, whose steps the check must see; STIN_DEBUG_NO_DERIVATIVES, the
 * shaders' derivative-free paths (bare ES 2.0's), held to the same bound;
 * 0: the technique as it is. */
static void check_technique(terminator_case *c, stin_tier tier, const char *scene_name,
                            stin_technique t, uint64_t debug)
{
    uint64_t facets = debug & STIN_DEBUG_VOLUME_FACETS;
    test_context tc;
    stin_frame_desc fd;
    char name[160];
    light_tally tally;
    long allowed;
    int li, exact = t == STIN_TECH_SHADOWS_VDSM || t == STIN_TECH_SHADOWS_VOLUME, failed = 0, facet;
    if (!test_context_create_debug(&tc, c->r, c->s, tier, t, 1, debug))
        return; /* not a technique of this tier and profile */
    snprintf(name, sizeof name, "%s/%s/terminator-%s%s", stin_tier_name(tier), scene_name,
             stin_technique_name(t),
             facets ? "-facets" : debug & STIN_DEBUG_NO_DERIVATIVES ? "-no-derivatives" : "");
    memset(&tally, 0, sizeof tally);
    test_frame_desc(c->r, c->s, &fd);
    fd.output = STIN_OUTPUT_VISIBILITY;
    for (li = 0; li < c->s->light_count; li++) {
        long lit, n, ref_n;
        if (volumes_stand_in(tc.ctx, t, &c->s->lights[li])) {
            if (tally.used < sizeof tally.counts)
                tally.used += (size_t)snprintf(tally.counts + tally.used,
                                               sizeof tally.counts - tally.used,
                                               "%slight %d: volumes", li ? ", " : "", li);
            continue;
        }
        if (test_context_frame(&tc, c->s, &fd, li) != STIN_OK ||
            !stin_platform_read_color(c->r->plat, c->color)) {
            failed = 1;
            break;
        }
        n = shadowed_lit_side(c, li, c->color, &lit);
        ref_n = shadowed_lit_side(c, li, NULL, &lit);
        if (c->open_mesh) {
            long wrongly_lit, on_edge;
            n = open_mesh_counts(c, li, c->color, &wrongly_lit, &on_edge);
            tally.wrongly_lit += wrongly_lit;
            tally.on_edge += on_edge;
            failed |= n < 0;
        }
        tally_light(&tally, li, n, lit, ref_n);
    }
    facet = by_facet(t);
    test_context_destroy(&tc);
    allowed = exact ? 0 : (long)(MAP_BUDGET * (double)tally.facing);
    if (failed)
        report(c->r, "FAIL", name, "a visibility frame failed");
    else if (facets)
        report(c->r, tally.bad > allowed ? "PASS" : "INFO", name,
               "the check can fail: volumes keeping the facets (STIN_DEBUG_VOLUME_FACETS) shadow "
               "%ld of %ld pixels whose shading normal faces a light%s (%s)%s", tally.bad,
               tally.facing, c->open_mesh ? " that the reference lights" : "", tally.counts,
               tally.bad > allowed ? "" : ": no smooth triangle here");
    else if (c->open_mesh)
        report(c->r, tally.bad <= allowed && tally.wrongly_lit == 0 && tally.facing > 0 ? "PASS"
                                                                                       : "FAIL",
               name,
               "%ld of %ld pixels whose shading normal faces a light (N.L > %.2f) shadowed where "
               "the reference lights them (%s; at most %ld allowed), %ld lit where it shadows "
               "them (must be 0; the reference shadows %ld there: the open mesh's walls and the "
               "box); not counted: %ld next to a reference shadow edge",
               tally.bad, tally.facing, TERMINATOR_MIN_COS, tally.counts, allowed,
               tally.wrongly_lit, tally.ref_bad, tally.on_edge);
    else if (facet)
        report(c->r, "SKIP", name,
               "open: %s still decides self-shadowing by the facet; %ld of %ld pixels whose "
               "shading normal faces a light shadowed (%s; %ld to be allowed)",
               stin_technique_name(t), tally.bad, tally.facing, tally.counts, allowed);
    else
        report(c->r, tally.bad <= allowed && tally.facing > 0 ? "PASS" : "FAIL", name,
               "%ld of %ld pixels whose shading normal faces a light (N.L > %.2f) shadowed "
               "(%s; at most %ld allowed); the shared terminator rule's reference shadows %ld",
               tally.bad, tally.facing, TERMINATOR_MIN_COS, tally.counts, allowed, tally.ref_bad);
}

/* Translucent technique tt with shadows technique t for the opaque casters,
 * on the scene made translucent: a visibility frame per light, that light
 * first, all from one context (only light 0's visibility is read: a
 * capture's beauty frame made every light's maps, and a context a light
 * cost 3 frames; 12 CPU s a scene at 2048 texels before); fine: with maps
 * of FINE_MAP_SIZE, where none may be dimmed. */
static void check_translucent(terminator_case *c, stin_tier tier, const char *scene_name,
                              stin_technique tt, stin_technique t, int fine)
{
    const scene *s = &c->translucent;
    capture_options o;
    capture log;
    test_context tc;
    stin_frame_desc fd;
    stin_technique ran;
    char name[160];
    light_tally tally;
    long allowed;
    size_t pixels = (size_t)c->r->width * c->r->height;
    float *depth;
    int li, failed = 0;
    if (tier == STIN_TIER_GL1 ||
        (tier != STIN_TIER_GL4 && (tt == STIN_TECH_TRANSLUCENT_DEEP || t == STIN_TECH_SHADOWS_VDSM)))
        return; /* not techniques of this tier */
    snprintf(name, sizeof name, "%s/%s/terminator-%s-%s%s", stin_tier_name(tier), scene_name,
             stin_technique_name(tt), stin_technique_name(t), fine ? "-fine" : "");
    memset(&o, 0, sizeof o);
    o.tier = tier;
    o.shadows = t;
    o.translucent = tt;
    o.deep_map_size = fine ? FINE_MAP_SIZE : 0;
    if (!test_context_forced(&tc, c->r, s, &o, STIN_FEATURE_TRANSLUCENT_SHADOWS, tt, &log, name))
        return;
    ran = stin_query_choice(tc.ctx, STIN_FEATURE_SHADOWS).technique;
    if (ran != t) { /* another technique's own run covers it */
        test_context_destroy(&tc);
        report(c->r, "SKIP", name, "%s does not run here: %s does", stin_technique_name(t),
               stin_technique_name(ran));
        return;
    }
    memset(&tally, 0, sizeof tally);
    depth = malloc(pixels * sizeof *depth);
    test_frame_desc(c->r, s, &fd);
    fd.output = STIN_OUTPUT_VISIBILITY;
    for (li = 0; li < s->light_count && !failed; li++) {
        long lit, n, ref_n;
        failed = !depth || test_context_frame(&tc, s, &fd, li) != STIN_OK ||
                 !stin_platform_read_data(c->r->plat, c->color) ||
                 !stin_platform_read_depth(c->r->plat, depth);
        if (failed)
            break;
        n = dimmed_lit_side(c, li, c->color, depth, &lit);
        ref_n = dimmed_lit_side(c, li, NULL, NULL, &lit);
        tally_light(&tally, li, n, lit, ref_n);
    }
    test_context_destroy(&tc);
    free(depth);
    if (failed) {
        report(c->r, "FAIL", name, "render failed: a visibility frame failed");
        return;
    }
    allowed = fine ? 0 : (long)(MAP_BUDGET * (double)tally.facing);
    report(c->r, tally.bad <= allowed && tally.facing > 0 ? "PASS" : "FAIL", name,
           "opacity %.1f, %s maps: %ld of %ld pixels whose shading normal faces a light (N.L > "
           "%.2f) get its transmittance below 1 - 2/255 (%s; at most %ld allowed); the reference %ld",
           TRANSLUCENT_OPACITY, fine ? "2048-texel" : "default", tally.bad, tally.facing,
           TERMINATOR_MIN_COS, tally.counts, allowed, tally.ref_bad);
}

/* The scene at path: every shadow technique and the translucent checks,
 * or with open_mesh (terminator/open-can.json) volumes alone, the only
 * technique that decided an open mesh's terminator otherwise. */
static void run_scene(run *r, stin_tier tier, const char *path, int open_mesh)
{
    static const stin_technique shadows[] = {
        STIN_TECH_SHADOWS_VDSM, STIN_TECH_SHADOWS_VOLUME, STIN_TECH_SHADOWS_MAP_PCF,
        STIN_TECH_SHADOWS_MAP_DEPTH, STIN_TECH_SHADOWS_MAP_COMBINE};
    static const stin_technique translucent[] = {STIN_TECH_TRANSLUCENT_DEEP,
                                                 STIN_TECH_TRANSLUCENT_COLOURED};
    /* every caster of the translucent scene is translucent, so the opaque
     * shadow technique casts nothing there: one that runs on GL2 and GL4 */
    static const stin_technique opaque[] = {STIN_TECH_SHADOWS_MAP_PCF};
    const char *base = scene_base_name(path);
    char scene_name[128], err[256], name[192];
    terminator_case c;
    scene s;
    reference *ref = NULL, *translucent_ref = NULL;
    scene_material *materials = NULL;
    ref_hit *hits = NULL;
    int fine;
    size_t i, j, pixels = (size_t)r->width * r->height;
    snprintf(scene_name, sizeof scene_name, "%s%s", open_mesh ? "terminator-" : "", base);
    snprintf(name, sizeof name, "%s/%s/terminator", stin_tier_name(tier), scene_name);
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    memset(&c, 0, sizeof c);
    hits = malloc(sizeof *hits * pixels);
    c.color = malloc(pixels * 4);
    materials = malloc(sizeof *materials * (size_t)(s.material_count ? s.material_count : 1));
    c.translucent = s;
    c.translucent.materials = materials;
    for (i = 0; materials && i < (size_t)s.material_count; i++) {
        materials[i] = s.materials[i];
        materials[i].color[3] = TRANSLUCENT_OPACITY;
    }
    if (!hits || !c.color || !materials || !(ref = reference_create(&s, err, sizeof err)) ||
        !(translucent_ref = reference_create(&c.translucent, err, sizeof err)) ||
        !reference_primary(ref, r->width, r->height, hits)) {
        report(r, "FAIL", name, "reference: %s", ref ? "primary rays failed" : err);
    } else {
        c.r = r;
        c.s = &s;
        c.ref = ref;
        c.open_mesh = open_mesh;
        c.hits = hits;
        for (i = 0; i < sizeof shadows / sizeof shadows[0]; i++)
            if (!open_mesh || shadows[i] == STIN_TECH_SHADOWS_VOLUME)
                check_technique(&c, tier, scene_name, shadows[i], 0);
        check_technique(&c, tier, scene_name, STIN_TECH_SHADOWS_VOLUME,
                        STIN_DEBUG_VOLUME_FACETS);
        /* without derivatives (the GLSL 1.10 programs bare ES 2.0 runs):
         * the band's facet facts asked per triangle on the CPU, map-pcf's
         * geometric normal the interpolated one; once, on gl21's sphere
         * on egl */
        for (i = 0; !open_mesh && tier == STIN_TIER_GL2 && !strcmp(r->profile_name, "gl21") &&
                    !strcmp(r->platform_name, "egl") && !strcmp(base, "terminator-sphere") &&
                    i < 2;
             i++)
            check_technique(&c, tier, scene_name,
                            i ? STIN_TECH_SHADOWS_MAP_PCF : STIN_TECH_SHADOWS_VOLUME,
                            STIN_DEBUG_NO_DERIVATIVES);
        c.translucent_ref = translucent_ref;
        for (i = 0; !open_mesh && i < sizeof translucent / sizeof translucent[0]; i++)
            for (j = 0; j < sizeof opaque / sizeof opaque[0]; j++)
                for (fine = 0; fine < 2; fine++)
                    check_translucent(&c, tier, scene_name, translucent[i], opaque[j], fine);
    }
    if (translucent_ref)
        reference_destroy(translucent_ref);
    if (ref)
        reference_destroy(ref);
    free(hits);
    free(c.color);
    free(materials);
    scene_free(&s);
}

/* Paths the open mesh's case takes with volumes: the fixed-function band
 * (gl11: two culled counting passes; gl14-shadow: two-sided with wrap),
 * GLSL 1.10 (gl21) and GLSL 1.50 (gl45-core); the other profiles run one
 * of these again. */
static int open_mesh_profile(const run *r, stin_tier tier)
{
    const char *p = r->profile_name;
    if (tier == STIN_TIER_GL1)
        return strcmp(p, "gl11") == 0 || strcmp(p, "gl14-shadow") == 0;
    return strcmp(p, "gl21") == 0 || strcmp(p, "gl45-core") == 0;
}

void terminator_tests(run *r, stin_tier tier, const char *path)
{
    const char *base = scene_base_name(path), *slash = strrchr(path, '/');
    char open_path[1024];
    if (strncmp(base, "open-", 5) == 0 && strstr(path, "terminator/open-")) {
        run_scene(r, tier, path, 1); /* named on the command line: any profile */
        return;
    }
    if (strncmp(base, "terminator-", 11) != 0)
        return;
    run_scene(r, tier, path, 0);
    if (strcmp(base, "terminator-sphere") != 0 || !open_mesh_profile(r, tier))
        return;
    snprintf(open_path, sizeof open_path, "%.*s/terminator/open-can.json",
             slash ? (int)(slash - path) : 1, slash ? path : ".");
    run_scene(r, tier, open_path, 1);
}
