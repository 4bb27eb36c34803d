/* SPDX-License-Identifier: MIT */
/*
 * Multisampled targets (issue 39), surface detail: msaa/wall.json (a
 * normal- and height-mapped panel at slants against the background) drawn
 * by normal mapping, parallax (offset limiting) and parallax occlusion
 * mapping on GL2 and GL4 into a 4x target, shadows off (the surface
 * reference is unshadowed). The reference takes each sample's surface to
 * the pixel centre on its plane (where multisampling shades, once a pixel) and shades it there as
 * surface_test.c does (stin's mip chains at the pixel's footprint), the
 * background elsewhere, box-filtered as the resolve. The silhouette band
 * (msaa_compare_band) catches an outline shaded at the wrong uv or a
 * resolve of a single-sampled frame.
 */
#include "msaa_common.h"
#include "reference_surface.h"
#include "surface_footprint.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SURF_MSAA_SAMPLES 4
/* surface_test.c's bound (8/255: where a pom step falls differently between
 * GL's 8-32 steps and the reference's 4096, the mip level's rounding). */
#define SURF_MSAA_TOLERANCE (8.0 / 255.0)
/* Of the band's 980 pixels: measured 2-3 (max 0.22) on GL2 and GL4, both
 * techniques; a single-sampled frame resolved puts 220 over (max 0.49). */
#define SURF_MSAA_MAX_BAND_OVER 3
#define SURF_MSAA_MAX_OVER_FRACTION 0.01

typedef struct surf_row {
    const scene *s;
    stin_tier tier;
    int ref_tech;
    const float (*pos)[2];
} surf_row;

/* Each sample shaded at its surface's point at the pixel centre. */
static int ref_build(const void *ctx, msaa_ref *m, char *err, size_t err_size)
{
    const surf_row *sr = ctx;
    const scene *s = sr->s;
    stin_tier tier = sr->tier;
    int ref_tech = sr->ref_tech;
    const float(*pos)[2] = sr->pos;
    reference *ref = reference_create(s, err, err_size);
    ref_surface *rs = ref_surface_create(s);
    size_t px = (size_t)m->w * m->h, i;
    float last[MSAA_MAX_SAMPLES][4];
    int k, ok = ref && rs && msaa_ref_alloc(m, m->n);
    for (k = 0; ok && k < m->n; k++)
        ok = reference_primary_at(ref, m->w, m->h, pos[k][0], pos[k][1], m->hits + px * k);
    for (i = 0; ok && i < px; i++)
        for (k = 0; k < m->n; k++) {
            int x = (int)(i % (size_t)m->w), y = (int)(i / (size_t)m->w), j;
            const ref_hit *h = &m->hits[px * k + i];
            ref_hit c = *h;
            ref_footprint fp;
            float rgba[4] = {s->background[0], s->background[1], s->background[2], 0};
            m->vis[px * k + i] = 0.0f;
            /* a triangle shades once a pixel: an earlier sample's colour
             * (GL2's pom footprint marches 4 rays: 5.1 CPU s without) */
            for (j = 0; j < k; j++) {
                const ref_hit *o = &m->hits[px * j + i];
                if (h->hit && o->hit && o->object == h->object && o->prim == h->prim)
                    break;
            }
            if (j < k) {
                memcpy(rgba, last[j], sizeof rgba);
            } else if (h->hit) {
                /* the quad's lower-left pixel as its corner: llvmpipe's
                 * multisampled path (measured: the upper-left puts GL2's
                 * pom, which differentiates the uv it moved, off on 38
                 * interior and 28 band pixels; GL4's textureGrad does not
                 * care) */
                reference_hit_on_plane(ref, m->w, m->h, h, x + 0.5, y + 0.5, &c);
                ref_surface_shade_filtered(
                    s, rs, &c, ref_tech, -1.0f,
                    surface_footprint(s, ref, rs, m->w, m->h, x, y, &c,
                                      tier == STIN_TIER_GL2 ? ref_tech : -1, 1, &fp)
                        ? &fp
                        : NULL,
                    rgba, NULL);
            }
            memcpy(last[k], rgba, sizeof rgba);
            m->colour[3 * i] += rgba[0] / (float)m->n;
            m->colour[3 * i + 1] += rgba[1] / (float)m->n;
            m->colour[3 * i + 2] += rgba[2] / (float)m->n;
        }
    if (!ok && err[0] == '\0')
        snprintf(err, err_size, "reference: out of memory");
    ref_surface_destroy(rs);
    if (ref)
        reference_destroy(ref);
    return ok;
}

static void one_case(run *r, const scene *s, stin_tier tier, stin_technique surface,
                     int ref_tech, const float pos[][2], int n)
{
    static const msaa_bounds bounds = {SURF_MSAA_TOLERANCE, SURF_MSAA_MAX_BAND_OVER,
                                       SURF_MSAA_MAX_OVER_FRACTION};
    msaa_techniques tech = {tier, STIN_TECH_SHADOWS_OFF, STIN_TECH_NONE, STIN_TECH_NONE,
                            surface, STIN_TECH_NONE};
    surf_row sr;
    char name[128];
    sr.s = s;
    sr.tier = tier;
    sr.ref_tech = ref_tech;
    sr.pos = pos;
    snprintf(name, sizeof name, "%s/msaa-%s", stin_tier_name(tier), stin_technique_name(surface));
    msaa_row(r, s, &tech, name, n, ref_build, &sr, &bounds);
}

/* GL1's dot3 has no reference of its own: with its normal maps flat it
 * draws what per-vertex lighting draws (dot3_test.c's dot3-flat: 3/255 on
 * 99% of the pixels), so the flat panel into the 4x target against the
 * reference of the panel without normal maps, lit per vertex as GL1's
 * passes, at the samples. msaa_test.c's tolerance: a sample of the lit
 * panel in four is 0.1 or more. Of the band's 980 pixels: measured 2 (max
 * 0.24, as the GL2 rows' 2-3); a single-sampled frame resolved puts 220
 * over (max 0.50). */
#define DOT3_MSAA_TOLERANCE 0.03
#define DOT3_MSAA_MAX_BAND_OVER 3

typedef struct dot3_row {
    const scene *plain;
    int per_vertex;
    const float (*pos)[2];
} dot3_row;

static int dot3_ref_build(const void *ctx, msaa_ref *m, char *err, size_t err_size)
{
    const dot3_row *dr = ctx;
    return msaa_ref_build(dr->plain, REFERENCE_FACETS_ALL, dr->per_vertex, dr->pos, m->n, m, err,
                          err_size);
}

static void dot3_case(run *r, scene *s, const float pos[][2], int n)
{
    static const msaa_bounds bounds = {DOT3_MSAA_TOLERANCE, DOT3_MSAA_MAX_BAND_OVER,
                                       SURF_MSAA_MAX_OVER_FRACTION};
    msaa_techniques tech = {STIN_TIER_GL1,           STIN_TECH_SHADOWS_OFF, STIN_TECH_NONE,
                            STIN_TECH_NONE,          STIN_TECH_SURFACE_DOT3, STIN_TECH_NONE};
    scene flat, plain;
    dot3_row dr;
    char name[64];
    int i;
    snprintf(name, sizeof name, "%s/msaa-%s", stin_tier_name(STIN_TIER_GL1),
             stin_technique_name(STIN_TECH_SURFACE_DOT3));
    /* a plain brick colour: the reference reads the albedo map at level 0,
     * GL1 at its mip level (minified bricks: 1,625 pixels inside the panel
     * up to 0.25 apart, not multisampling's matter) */
    for (i = 0; i < s->material_count; i++) {
        s->materials[i].albedo = -1;
        s->materials[i].color[0] = 0.6f;
        s->materials[i].color[1] = 0.3f;
        s->materials[i].color[2] = 0.2f;
    }
    if (!dot3_flat_scenes(s, &flat, &plain)) {
        report(r, "FAIL", name, "out of memory");
    } else {
        dr.plain = &plain;
        dr.per_vertex = msaa_gl1_per_vertex(r, s);
        dr.pos = pos;
        msaa_row(r, &flat, &tech, name, n, dot3_ref_build, &dr, &bounds);
    }
    dot3_flat_free(&flat, &plain, s);
}

/* From stone-wall: GL1 (dot3) and GL2 on gl21, GL4 on the core profiles
 * (one run a tier). */
void msaa_surface_tests(run *r, stin_tier tier, const char *path)
{
    float pos[MSAA_MAX_SAMPLES][2];
    char name[64];
    scene s;
    int n, here = tier != STIN_TIER_GL4 ? !strcmp(r->profile_name, "gl21")
                  : tier == STIN_TIER_GL4
                      ? !strcmp(r->profile_name, "gl45-core") ||
                            !strcmp(r->profile_name, "gl33-core")
                      : 0;
    if (!here || strcmp(scene_base_name(path), "stone-wall"))
        return;
    snprintf(name, sizeof name, "%s/msaa-surface", stin_tier_name(tier));
    n = msaa_open(r, path, "wall.json", SURF_MSAA_SAMPLES, name, &s, pos);
    if (!n)
        return;
    if (tier == STIN_TIER_GL1) {
        dot3_case(r, &s, (const float(*)[2])pos, n);
        msaa_close(r, name, &s);
        return;
    }
    one_case(r, &s, tier, STIN_TECH_SURFACE_NORMAL, REF_SURFACE_NORMAL, (const float(*)[2])pos,
             n);
    one_case(r, &s, tier, STIN_TECH_SURFACE_PARALLAX, REF_SURFACE_PARALLAX,
             (const float(*)[2])pos, n);
    one_case(r, &s, tier, STIN_TECH_SURFACE_POM, REF_SURFACE_POM, (const float(*)[2])pos, n);
    msaa_close(r, name, &s);
}
