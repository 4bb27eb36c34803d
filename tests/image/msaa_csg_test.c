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
 * which shows on the pixels away from any change of object.
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

typedef struct csg_run {
    const scene *s;
    scene_csg_products prods;
    msaa_ref m;
} csg_run;

/* One frame of the scene's product at its own size into the platform's
 * target: 1, 0 on failure (why), -1 where the tier or technique does not
 * run here (why). */
static int render(run *r, const csg_run *c, stin_tier tier, stin_technique csg, uint64_t flags,
                  uint8_t *rgba, char *why, size_t why_size)
{
    stin_desc d;
    stin_context *ctx = NULL;
    scene_gpu g;
    void *block;
    size_t size;
    int ok = 0;
    stin_result res;
    test_desc(r, tier, &d);
    /* GL1 has no PCF: volumes there (its rows leave the cavity out: ref_build) */
    d.techniques[STIN_FEATURE_SHADOWS] =
        tier == STIN_TIER_GL1 ? STIN_TECH_SHADOWS_VOLUME : STIN_TECH_SHADOWS_MAP_PCF;
    d.techniques[STIN_FEATURE_CSG] = csg;
    d.debug_flags = flags;
    scene_gpu_size_desc(c->s, &d);
    size = stin_memory_size(&d);
    block = malloc(size);
    if (!block || stin_create(&d, block, size, &ctx) != STIN_OK) {
        free(block);
        snprintf(why, why_size, "%s with %s does not run on this tier here",
                 stin_technique_name(csg),
                 stin_technique_name(d.techniques[STIN_FEATURE_SHADOWS]));
        return -1;
    }
    if (stin_query_choice(ctx, STIN_FEATURE_CSG).technique != csg) {
        snprintf(why, why_size, "%s falls back here (%s)", stin_technique_name(csg),
                 stin_query_choice(ctx, STIN_FEATURE_CSG).reason);
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

/* flags: STIN_DEBUG_CSG_SNAP_AT_CENTRE for the row that must fail. */
static void one_case(run *r, const csg_run *c, stin_tier tier, stin_technique csg,
                     uint64_t flags)
{
    char name[128], why[512] = "";
    uint8_t *rgba = malloc((size_t)r->width * r->height * 4);
    msaa_band b;
    int got, pass;
    double share;
    snprintf(name, sizeof name, "%s/msaa-csg-%s%s", stin_tier_name(tier),
             stin_technique_name(csg), flags ? "-at-centre-fails" : "");
    got = rgba ? render(r, c, tier, csg, flags, rgba, why, sizeof why) : 0;
    if (got < 0) {
        report(r, "SKIP", name, "%s", why);
    } else if (!got) {
        report(r, "FAIL", name, "%s", why);
    } else {
        msaa_compare_band(&c->m, rgba, r->width, MSAA_CSG_TOLERANCE, &b);
        share = b.band ? (double)b.over / (double)b.band : 1.0;
        pass = b.compared > 1000 && b.band > 100 && b.compared_over <= MSAA_CSG_MAX_OVER &&
               share <= MSAA_CSG_MAX_BAND_SHARE;
        report(r, pass != !!flags ? "PASS" : "FAIL", name,
               "%d samples: %ld of %ld pixels away from edges beyond %.2f of the reference at "
               "the samples (max %.3f; at most %d); silhouette band: %ld of %ld (%.2f; at most "
               "%.2f)%s", c->m.n, b.compared_over, b.compared, MSAA_CSG_TOLERANCE,
               b.compared_max, MSAA_CSG_MAX_OVER, b.over, b.band, share,
               MSAA_CSG_MAX_BAND_SHARE, flags ? " (must fail: the snap at the centre)" : "");
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

/* The techniques each profile runs (each a distinct resolve; the budget
 * of make check's time allows no more): gl45-core's GL4 goldfeather (and
 * the row at the centre that must fail), scs and interval; gl33-core's
 * GL4 goldfeather; gl21's GL2 goldfeather and scs, and its GL1 goldfeather
 * (and the row at the centre) and scs through the read-back resolve, and
 * its refusal without packed depth-stencil. */
static int cases_here(const run *r, stin_tier tier, stin_technique out[4])
{
    int n = 0;
    if (tier == STIN_TIER_GL4 && !strcmp(r->profile_name, "gl45-core")) {
        out[n++] = STIN_TECH_CSG_GOLDFEATHER;
        out[n++] = STIN_TECH_CSG_SCS;
        out[n++] = STIN_TECH_CSG_INTERVAL;
    } else if (tier == STIN_TIER_GL4 && !strcmp(r->profile_name, "gl33-core")) {
        out[n++] = STIN_TECH_CSG_GOLDFEATHER;
    } else if (tier != STIN_TIER_GL4 && !strcmp(r->profile_name, "gl21")) {
        out[n++] = STIN_TECH_CSG_GOLDFEATHER;
        out[n++] = STIN_TECH_CSG_SCS;
    }
    return n;
}

void msaa_csg_tests(run *r, stin_tier tier, const char *path)
{
    char file[1024], err[512] = "", name[64];
    const char *slash = strrchr(path, '/');
    float pos[MSAA_MAX_SAMPLES][2];
    stin_technique techs[4];
    int i, n, count = cases_here(r, tier, techs);
    int gl1 = tier == STIN_TIER_GL1 && !strcmp(r->profile_name, "gl21");
    scene s;
    csg_run c;
    if (strcmp(scene_base_name(path), "csg") || (!count && !gl1))
        return;
    snprintf(name, sizeof name, "%s/msaa-csg", stin_tier_name(tier));
    snprintf(file, sizeof file, "%.*smsaa/csg.json", slash ? (int)(slash - path + 1) : 0, path);
    if (!scene_load(file, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    memset(&c, 0, sizeof c);
    c.s = &s;
    if (s.width > r->width || s.height > r->height) {
        report(r, "SKIP", name, "the run's %dx%d is smaller than the scene's %dx%d", r->width,
               r->height, s.width, s.height);
    } else if (!scene_csg_products_build(&s, &c.prods) || c.prods.count < 1) {
        report(r, "FAIL", name, "the scene's csg list did not build");
    } else if (!stin_platform_set_samples(r->plat, MSAA_CSG_SAMPLES, err, sizeof err)) {
        report(r, "SKIP", name, "%s", err);
    } else {
        n = msaa_sample_positions(r, pos);
        if (gl1)
            refused(r, &c, tier);
        if (!n)
            report(r, "SKIP", name, "the context cannot say where its samples lie "
                                    "(glGetMultisamplefv: GL 3.2 or ARB_texture_multisample)");
        else if (!ref_build(&c, (const float(*)[2])pos, n,
                            tier == STIN_TIER_GL1 ? msaa_gl1_per_vertex(r, &s) : 0, err,
                            sizeof err))
            report(r, "FAIL", name, "reference: %s", err);
        else
            for (i = 0; i < count; i++) {
                one_case(r, &c, tier, techs[i], 0);
                if (i == 0 && (tier == STIN_TIER_GL1 || !strcmp(r->profile_name, "gl45-core")))
                    one_case(r, &c, tier, techs[i], STIN_DEBUG_CSG_SNAP_AT_CENTRE);
            }
        if (!stin_platform_set_samples(r->plat, 0, err, sizeof err))
            report(r, "FAIL", name, "back to the default framebuffer: %s", err);
    }
    msaa_ref_free(&c.m);
    scene_csg_products_free(&c.prods);
    scene_free(&s);
}
