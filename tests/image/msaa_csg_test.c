/* SPDX-License-Identifier: MIT */
/*
 * CSG products into a multisampled target (issue 39): msaa/csg.json (a
 * cube minus a sphere on a floor, casting onto it) drawn into the
 * platform's 4x framebuffer object by each CSG technique of the tier with
 * map-pcf shadows, against the exact CSG reference (ray intervals) shaded
 * at the target's own sample positions and box-filtered as the resolve
 * averages them (msaa_common.c). The resolve is single-sampled; the snap
 * must keep each face's fragment wherever the face covers samples
 * (csg/merge.c): a snap that tests the face's depth at the pixel centre
 * against the resolved one drops the samples of the triangle that does not
 * cover the centre, a line along every triangle edge inside the product,
 * which shows on the pixels away from any change of object. Then
 * msaa/csg-cast.json (the product hovering over its own shadow, as
 * msaa/halo.json's ball) under the other shadows techniques: the product
 * casting, and the halo check along its outline over that shadow.
 */
#include "msaa_common.h"
#include "reference_csg.h"
#include "scene_csg.h"
#include "test_context.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MSAA_CSG_SAMPLES 4
/* A sample dropped from a face (the old snap's lines) moves its pixel by a
 * quarter of the contrast with what lies behind (the cavity's orange over
 * the floor or the black background: 0.12 or more). The reference shades
 * each sample where multisampling shades (its surface at the pixel
 * centre) but at the sample itself where that point would leave the
 * sample's triangle (msaa_common.h): half a pixel of shading, 0.05 in the
 * cavity's highlight. */
#define MSAA_CSG_TOLERANCE 0.06
/* Of the pixels away from a change of object among the samples (and from
 * shadow edges): measured 17 of 17,448 on llvmpipe on every row: the
 * highlight, and the sphere's pole, where a fragment shaded at the centre
 * extrapolates its vertex normals beyond a sliver facet (multisampling's
 * shading, as for any mesh; a snap band four times wider leaves the same
 * pixels); the snap at the pixel centre leaves 597. */
#define MSAA_CSG_MAX_OVER 40
/* Of the silhouette band (pixels within one of a change of object): the
 * product's own edges between its primitives (the cavity's rim) are
 * decided once a pixel, at its centre, as in a single-sampled target
 * (stin.h, MULTISAMPLED TARGETS), so they are not antialiased and differ
 * by up to the two surfaces' contrast there. Measured 148 of 1,387 (0.11);
 * the snap at the centre, whose silhouettes against the floor are aliased
 * too, 278 (0.20). */
#define MSAA_CSG_MAX_BAND_SHARE 0.15

/* Of the silhouette band where the cavity is left out (the casting rows):
 * measured 0 of 695 on the GLSL tiers, 19 (0.03) on GL1 (per-vertex
 * shading along the product's outline); a halo along its lower outline
 * over its own shadow is 0.2 of the band (vdsm's before its position
 * buffer took the products' depth). */
#define MSAA_CSG_CAST_MAX_BAND_SHARE 0.05

/* One row: the CSG technique and the shadows technique the product casts
 * under; cavity_out: leave the subtracted primitive's inside out (see
 * leave_out_cavity), and hold the band to MSAA_CSG_CAST_MAX_BAND_SHARE;
 * row: the name after msaa-csg- (NULL: the CSG technique's). */
typedef struct msaa_csg_case {
    stin_technique csg, shadows;
    int cavity_out;
    const char *row;
} msaa_csg_case;

typedef struct csg_run {
    const scene *s;
    scene_csg_products prods;
    msaa_ref m;
} csg_run;

/* One frame of the scene's product at its own size into the platform's
 * target: 1, 0 on failure (why), -1 where the tier or technique does not
 * run here (why). */
static int render(run *r, const csg_run *c, stin_tier tier, const msaa_csg_case *mc,
                  uint64_t flags, uint8_t *rgba, char *why, size_t why_size)
{
    stin_desc d;
    stin_context *ctx = NULL;
    scene_gpu g;
    void *block;
    size_t size;
    int ok = 0;
    stin_result res;
    test_desc(r, tier, &d);
    d.techniques[STIN_FEATURE_SHADOWS] = mc->shadows;
    d.techniques[STIN_FEATURE_CSG] = mc->csg;
    d.debug_flags = flags;
    scene_gpu_size_desc(c->s, &d);
    size = stin_memory_size(&d);
    block = malloc(size);
    if (!block || stin_create(&d, block, size, &ctx) != STIN_OK) {
        free(block);
        snprintf(why, why_size, "%s with %s does not run on this tier here",
                 stin_technique_name(mc->csg), stin_technique_name(mc->shadows));
        return -1;
    }
    if (stin_query_choice(ctx, STIN_FEATURE_CSG).technique != mc->csg ||
        stin_query_choice(ctx, STIN_FEATURE_SHADOWS).technique != mc->shadows) {
        snprintf(why, why_size, "%s with %s falls back here (%s; %s)",
                 stin_technique_name(mc->csg), stin_technique_name(mc->shadows),
                 stin_query_choice(ctx, STIN_FEATURE_CSG).reason,
                 stin_query_choice(ctx, STIN_FEATURE_SHADOWS).reason);
        ok = -1;
    } else if (!scene_gpu_create(&g, c->s, ctx, why, why_size)) {
        ok = 0;
    } else {
        g.csg = c->prods.products;
        g.csg_count = c->prods.count;
        res = scene_gpu_frame(&g, ctx, c->s->width, c->s->height, STIN_OUTPUT_BEAUTY,
                              stin_platform_framebuffer(r->plat));
        if (res != STIN_OK)
            snprintf(why, why_size, "frame: %s", stin_result_name(res));
        else if (stin_query_frame_stats(ctx).csg.gpu_resolves != (tier != STIN_TIER_GL1) ||
                 stin_query_frame_stats(ctx).csg.products != 1)
            snprintf(why, why_size, "the product was not resolved %s (%u dropped)",
                     tier == STIN_TIER_GL1 ? "by the read-back resolve" : "on the GPU",
                     (unsigned)stin_query_frame_stats(ctx).csg.dropped);
        else if (!stin_platform_read_color(r->plat, rgba))
            snprintf(why, why_size, "read-back failed");
        else
            ok = 1;
        scene_gpu_destroy(&g, ctx);
    }
    stin_destroy(ctx);
    free(block);
    return ok;
}

/* GL1's rows: the pixels (and their neighbours) where a sample sees a
 * subtracted primitive's inside are left out of both bounds. There GL1's
 * volumes light the cavity (a product does not shadow its own faces
 * through the volumes' cast map, single-sampled too) and the per-vertex
 * reference shades it with the primitive's outward vertex normals: its
 * shading, not the samples' depth, decides those pixels. */
static void leave_out_cavity(csg_run *c)
{
    size_t px = (size_t)c->m.w * c->m.h, i;
    int k, j, sub = -1;
    const scene_gpu_csg *p = &c->prods.products[0];
    for (j = 0; j < p->primitive_count; j++)
        if (j > 0) /* a - b: b's faces are the cavity */
            sub = p->objects[j];
    for (i = 0; sub >= 0 && i < px; i++)
        for (k = 0; k < c->m.n; k++)
            if (c->m.hits[px * (size_t)k + i].hit && c->m.hits[px * (size_t)k + i].object == sub)
                c->m.centre_differs[i] = 1;
}

/* The reference at the target's sample positions, the product casting. */
static int ref_build(csg_run *c, const float pos[][2], int n, int per_vertex, char *err,
                     size_t err_size)
{
    reference *ref = reference_create(c->s, err, err_size);
    ref_csg_product p[4];
    size_t px;
    int k, ok = ref != NULL && c->prods.count >= 1 && c->prods.count <= 4;
    c->m.w = c->s->width;
    c->m.h = c->s->height;
    px = (size_t)c->m.w * c->m.h;
    ok = msaa_ref_alloc(&c->m, n) && ok;
    for (k = 0; ok && k < c->prods.count; k++) {
        p[k].objects = c->prods.products[k].objects;
        p[k].primitive_count = c->prods.products[k].primitive_count;
        p[k].nodes = c->prods.products[k].nodes;
        p[k].node_count = c->prods.products[k].node_count;
    }
    ok = ok && reference_csg_mark(ref, p, c->prods.count) &&
         reference_csg_cast(ref, p, c->prods.count);
    for (k = 0; ok && k < n; k++)
        ok = reference_csg_primary_at(ref, p, c->prods.count, c->m.w, c->m.h, pos[k][0],
                                      pos[k][1], c->m.hits + px * (size_t)k, NULL);
    if (ok)
        msaa_ref_shade(c->s, ref, per_vertex, MSAA_AT_CENTRE_INSIDE, &c->m);
    if (ok && per_vertex)
        leave_out_cavity(c);
    if (ref)
        reference_destroy(ref);
    if (!ok && err[0] == '\0')
        snprintf(err, err_size, "reference failed");
    return ok;
}

/* The band comparison, the cavity left out where the row asks (on a copy:
 * the other rows keep it). */
static void compare(csg_run *c, const msaa_csg_case *mc, const uint8_t *rgba, int stride,
                    msaa_band *b)
{
    size_t px = (size_t)c->m.w * c->m.h;
    unsigned char *kept = mc->cavity_out ? malloc(px) : NULL;
    if (kept) {
        memcpy(kept, c->m.centre_differs, px);
        leave_out_cavity(c);
    }
    msaa_compare_band(&c->m, rgba, stride, MSAA_CSG_TOLERANCE, b);
    if (kept) {
        memcpy(c->m.centre_differs, kept, px);
        free(kept);
    }
}

/* flags: STIN_DEBUG_CSG_SNAP_AT_CENTRE for the row that must fail. */
static void one_case(run *r, csg_run *c, stin_tier tier, const msaa_csg_case *mc,
                     uint64_t flags)
{
    char name[128], why[512] = "";
    uint8_t *rgba = malloc((size_t)r->width * r->height * 4);
    msaa_band b;
    int got, pass;
    double share, most = mc->cavity_out ? MSAA_CSG_CAST_MAX_BAND_SHARE : MSAA_CSG_MAX_BAND_SHARE;
    snprintf(name, sizeof name, "%s/msaa-csg-%s%s", stin_tier_name(tier),
             mc->row ? mc->row : stin_technique_name(mc->csg),
             flags ? "-at-centre-fails" : "");
    got = rgba ? render(r, c, tier, mc, flags, rgba, why, sizeof why) : 0;
    if (got < 0) {
        report(r, "SKIP", name, "%s", why);
    } else if (!got) {
        report(r, "FAIL", name, "%s", why);
    } else {
        compare(c, mc, rgba, r->width, &b);
        share = b.band ? (double)b.over / (double)b.band : 1.0;
        pass = b.compared > 1000 && b.band > 100 && b.compared_over <= MSAA_CSG_MAX_OVER &&
               share <= most;
        report(r, pass != !!flags ? "PASS" : "FAIL", name,
               "%d samples, %s, %s: %ld of %ld pixels away from edges beyond %.2f of the "
               "reference at the samples (max %.3f; at most %d); silhouette band: %ld of %ld "
               "(%.2f; at most %.2f)%s", c->m.n, stin_technique_name(mc->csg),
               stin_technique_name(mc->shadows), b.compared_over, b.compared,
               MSAA_CSG_TOLERANCE, b.compared_max, MSAA_CSG_MAX_OVER, b.over, b.band, share,
               most, flags ? " (must fail: the snap at the centre)" : "");
        if (pass == !!flags)
            msaa_save_pair(r, name, rgba, c->m.colour, c->m.w, c->m.h);
    }
    free(rgba);
}

/* Where the read-back resolve (GL1 tiers) cannot copy the multisampled
 * target (here packed depth-stencil hidden, as a context without it; the
 * GL 1.x profiles hide framebuffer objects, and the platform has no
 * multisampled target there), a product into it is refused, not drawn
 * wrong (stin.h, stin_draw_csg). */
static void refused(run *r, const csg_run *c, stin_tier tier)
{
    stin_profile hidden = *r->profile;
    run without = *r;
    test_context tc;
    stin_frame_desc fd;
    stin_csg_primitive prim[2];
    stin_csg_desc cd;
    stin_result res = STIN_OK;
    const scene_gpu_csg *p = &c->prods.products[0];
    char name[64];
    int i;
    snprintf(name, sizeof name, "%s/msaa-csg-refused", stin_tier_name(tier));
    hidden.caps_mask |= STIN_CAP_BIT(STIN_CAP_PACKED_DEPTH_STENCIL);
    without.profile = &hidden;
    if (!test_context_create(&tc, &without, c->s, tier, STIN_TECH_NONE, 0)) {
        report(r, "SKIP", name, "the tier does not run here");
        return;
    }
    test_frame_desc(r, c->s, &fd);
    memset(prim, 0, sizeof prim);
    for (i = 0; i < p->primitive_count && i < 2; i++) {
        prim[i].mesh = tc.g.meshes[c->s->objects[p->objects[i]].mesh];
        prim[i].material = tc.g.materials[c->s->objects[p->objects[i]].material];
        memcpy(prim[i].transform, c->s->objects[p->objects[i]].transform,
               sizeof prim[i].transform);
    }
    memset(&cd, 0, sizeof cd);
    cd.primitives = prim;
    cd.primitive_count = (uint32_t)i;
    cd.nodes = p->nodes;
    cd.node_count = (uint32_t)p->node_count;
    if (stin_begin_frame(tc.ctx, &fd) == STIN_OK) {
        res = stin_draw_csg(tc.ctx, &cd);
        stin_end_frame(tc.ctx);
    }
    report(r, res == STIN_ERROR_UNSUPPORTED && stin_query_frame_stats(tc.ctx).csg.dropped == 1
                  ? "PASS" : "FAIL",
           name, "stin_draw_csg into a %d-sample target on the read-back resolve without "
           "packed depth-stencil: %s, %u dropped (want STIN_ERROR_UNSUPPORTED, 1)", stin_platform_samples(r->plat),
           stin_result_name(res), (unsigned)stin_query_frame_stats(tc.ctx).csg.dropped);
    test_context_destroy(&tc);
}

/* The rows of each profile on msaa/csg.json (each a distinct resolve; the
 * budget of make check's time allows no more): gl45-core's GL4
 * goldfeather (and the row at the centre that must fail), scs and
 * interval; gl33-core's GL4 goldfeather; gl21's GL2 goldfeather and scs,
 * and its GL1 goldfeather (and the row at the centre) and scs through the
 * read-back resolve, and its refusal without packed depth-stencil. GL1 has
 * no PCF: volumes there; every GL1 row leaves the cavity out (ref_build). */
static int resolve_cases(const run *r, stin_tier tier, msaa_csg_case out[4])
{
    static const stin_technique gl4[] = {STIN_TECH_CSG_GOLDFEATHER, STIN_TECH_CSG_SCS,
                                         STIN_TECH_CSG_INTERVAL};
    int i, n = 0;
    if (tier == STIN_TIER_GL4 && !strcmp(r->profile_name, "gl45-core"))
        n = 3;
    else if (tier == STIN_TIER_GL4 && !strcmp(r->profile_name, "gl33-core"))
        n = 1;
    else if (tier != STIN_TIER_GL4 && !strcmp(r->profile_name, "gl21"))
        n = 2;
    for (i = 0; i < n; i++) {
        out[i].csg = gl4[i];
        out[i].shadows = tier == STIN_TIER_GL1 ? STIN_TECH_SHADOWS_VOLUME
                                                : STIN_TECH_SHADOWS_MAP_PCF;
        out[i].cavity_out = 0;
        out[i].row = NULL;
    }
    return n;
}

/* The rows of each profile on msaa/csg-cast.json: the product casting
 * under the tier's shadows techniques but map-pcf (the resolves' rows
 * cast under it), through goldfeather: vdsm on gl45-core (gl33-core's
 * casts no product: GL 4.3) and volumes (both through the screen mask:
 * two lights) on the GLSL tiers, GL1's volumes and two maps on gl21's GL1
 * tier. Volumes do not shadow a product's faces by the product (their
 * cast map), and GL1's reference shades the cavity with the ball's
 * outward normals: the cavity is left out (vdsm's own shadow in it is
 * csg_cast_test.c's). */
static int cast_cases(const run *r, stin_tier tier, msaa_csg_case out[4])
{
    static const msaa_csg_case vdsm = {STIN_TECH_CSG_GOLDFEATHER, STIN_TECH_SHADOWS_VDSM, 1,
                                       "cast-vdsm"};
    static const msaa_csg_case volume = {STIN_TECH_CSG_GOLDFEATHER, STIN_TECH_SHADOWS_VOLUME,
                                         1, "cast-volume"};
    static const msaa_csg_case gl1[] = {
        {STIN_TECH_CSG_GOLDFEATHER, STIN_TECH_SHADOWS_VOLUME, 1, "cast-volume"},
        {STIN_TECH_CSG_GOLDFEATHER, STIN_TECH_SHADOWS_MAP_DEPTH, 1, "cast-map-depth"},
        {STIN_TECH_CSG_GOLDFEATHER, STIN_TECH_SHADOWS_MAP_COMBINE, 1, "cast-map-combine"},
    };
    if (tier == STIN_TIER_GL4 && !strcmp(r->profile_name, "gl45-core")) {
        out[0] = vdsm;
        out[1] = volume;
        return 2;
    }
    if ((tier == STIN_TIER_GL4 && !strcmp(r->profile_name, "gl33-core")) ||
        (tier == STIN_TIER_GL2 && !strcmp(r->profile_name, "gl21"))) {
        out[0] = volume;
        return 1;
    }
    if (tier == STIN_TIER_GL1 && !strcmp(r->profile_name, "gl21")) {
        memcpy(out, gl1, sizeof gl1);
        return 3;
    }
    return 0;
}

/* One scene's rows into the 4x target; extras: the GL1 refusal and the
 * rows at the centre that must fail. */
static void scene_rows(run *r, stin_tier tier, const char *path, const char *file,
                       const msaa_csg_case *cases, int count, int extras)
{
    char err[512] = "", name[64];
    float pos[MSAA_MAX_SAMPLES][2];
    int i, n;
    scene s;
    csg_run c;
    snprintf(name, sizeof name, "%s/msaa-csg", stin_tier_name(tier));
    n = msaa_open(r, path, file, MSAA_CSG_SAMPLES, name, &s, pos);
    if (!n)
        return;
    memset(&c, 0, sizeof c);
    c.s = &s;
    if (!scene_csg_products_build(&s, &c.prods) || c.prods.count < 1) {
        report(r, "FAIL", name, "%s: the scene's csg list did not build", file);
    } else {
        if (extras && tier == STIN_TIER_GL1)
            refused(r, &c, tier);
        if (!ref_build(&c, (const float(*)[2])pos, n,
                       tier == STIN_TIER_GL1 ? msaa_gl1_per_vertex(r, &s) : 0, err, sizeof err))
            report(r, "FAIL", name, "reference: %s", err);
        else
            for (i = 0; i < count; i++) {
                one_case(r, &c, tier, &cases[i], 0);
                if (extras && i == 0 &&
                    (tier == STIN_TIER_GL1 || !strcmp(r->profile_name, "gl45-core")))
                    one_case(r, &c, tier, &cases[i], STIN_DEBUG_CSG_SNAP_AT_CENTRE);
            }
    }
    msaa_ref_free(&c.m);
    scene_csg_products_free(&c.prods);
    msaa_close(r, name, &s);
}

void msaa_csg_tests(run *r, stin_tier tier, const char *path)
{
    msaa_csg_case cases[4];
    int count;
    if (strcmp(scene_base_name(path), "csg"))
        return;
    count = resolve_cases(r, tier, cases);
    if (count)
        scene_rows(r, tier, path, "csg.json", cases, count, 1);
    count = cast_cases(r, tier, cases);
    if (count)
        scene_rows(r, tier, path, "csg-cast.json", cases, count, 0);
}
