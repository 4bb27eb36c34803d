/* SPDX-License-Identifier: MIT */
/*
 * Multisampled targets (issue 39), displacement: msaa/displace.json (a
 * plate raised into blocks by a checker height map, at a grazing angle)
 * drawn by "displace" and "displace-tess" (GL4, vdsm shadows) into a 4x
 * target, against the displaced Embree reference (reference_displace.h)
 * cast and shaded at the target's sample positions as msaa_test.c's
 * (msaa_ref_build; facets kept: the displaced draws keep the undisplaced
 * normals, which do not describe their surface). The band check catches a
 * displaced outline resolved from a single-sampled frame or a depth pass
 * that is not the lit pass's (a rim of the undisplaced surface). GL2's
 * "displace" runs with shadows off against the reference unshadowed
 * (below: what its shadows add is map-pcf's, not multisampling's).
 */
#include "msaa_common.h"
#include "reference_displace.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DISP_MSAA_SAMPLES 4
/* msaa_test.c's: a sample of a lit surface in four is 0.08 or more. */
#define DISP_MSAA_TOLERANCE 0.03
/* Of the band's 897 pixels: measured 3 (max 0.095), where the blocks'
 * steps meet the outline (a step's vertex lies up to height_scale / 512
 * off: the bilinear weights' 8-bit fractions, displace_test.c); a
 * single-sampled frame resolved puts 277 over. GL2 (shadows off): 3 of
 * 1,006 (max 0.20), single-sampled 305 (max 0.59). */
#define DISP_MSAA_MAX_BAND_OVER 6
/* Of the rest (the blocks' steps inside the plate, one object): measured
 * 1 of 17,080 (max 0.19), for the same reason; GL2 1 of 18,194. */
#define DISP_MSAA_MAX_OVER_FRACTION 0.01

typedef struct disp_msaa_case {
    stin_tier tier;
    stin_technique displacement, shadows;
} disp_msaa_case;

typedef struct disp_row {
    const scene *ds;
    int unshadowed;
    const float (*pos)[2];
} disp_row;

/* The displaced scene cast and shaded at the samples, its facets kept. */
static int ref_build(const void *ctx, msaa_ref *m, char *err, size_t err_size)
{
    const disp_row *dr = ctx;
    m->unshadowed = dr->unshadowed;
    return msaa_ref_build(dr->ds, REFERENCE_FACETS_ALL, 0, dr->pos, m->n, m, err, err_size);
}

static void one_case(run *r, const scene *s, const scene *ds, const disp_msaa_case *dc,
                     const float pos[][2], int n)
{
    static const msaa_bounds bounds = {DISP_MSAA_TOLERANCE, DISP_MSAA_MAX_BAND_OVER,
                                       DISP_MSAA_MAX_OVER_FRACTION};
    msaa_techniques tech = {dc->tier,       dc->shadows,    STIN_TECH_NONE,
                            STIN_TECH_NONE, STIN_TECH_NONE, dc->displacement};
    disp_row dr;
    char name[128];
    dr.ds = ds;
    dr.unshadowed = dc->shadows == STIN_TECH_SHADOWS_OFF;
    dr.pos = pos;
    snprintf(name, sizeof name, "%s/msaa-%s-%s", stin_tier_name(dc->tier),
             stin_technique_name(dc->displacement), stin_technique_name(dc->shadows));
    msaa_row(r, s, &tech, name, n, ref_build, &dr, &bounds);
}

/* From displace-plate: GL4 on gl45-core, GL2 on gl21. GL2's "displace"
 * runs with shadows off: its shadows (map-pcf; volumes cast displaced
 * draws through the same filtered map) move the plate's shadow edge on the
 * floor past the band's one-pixel exclusion (measured 18 band and 80
 * other pixels over; 10 and 37 leaving out 3 pixels about every edge),
 * and light the blocks' shadowed walls near the outline, which a
 * single-sampled frame against the reference at the pixel centres shows
 * alike (the same 5 pixels, up to 0.15): map-pcf's, not multisampling's
 * (displace_test.c's shadow-map-pcf holds it to map-pcf's bound). */
void msaa_displace_tests(run *r, stin_tier tier, const char *path)
{
    static const disp_msaa_case cases[] = {
        {STIN_TIER_GL4, STIN_TECH_DISPLACEMENT_VTF, STIN_TECH_SHADOWS_VDSM},
        {STIN_TIER_GL4, STIN_TECH_DISPLACEMENT_TESS, STIN_TECH_SHADOWS_VDSM},
        {STIN_TIER_GL2, STIN_TECH_DISPLACEMENT_VTF, STIN_TECH_SHADOWS_OFF},
    };
    float pos[MSAA_MAX_SAMPLES][2];
    char name[64], err[512];
    scene s, ds;
    size_t i;
    int n;
    if (tier == STIN_TIER_GL1 || strcmp(scene_base_name(path), "displace-plate") ||
        strcmp(r->profile_name, tier == STIN_TIER_GL4 ? "gl45-core" : "gl21"))
        return;
    snprintf(name, sizeof name, "%s/msaa-displace", stin_tier_name(tier));
    n = msaa_open(r, path, "displace.json", DISP_MSAA_SAMPLES, name, &s, pos);
    if (!n)
        return;
    if (!reference_displace(&s, &ds, err, sizeof err)) {
        report(r, "FAIL", name, "reference: %s", err);
        msaa_close(r, name, &s);
        return;
    }
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
        if (cases[i].tier == tier)
            one_case(r, &s, &ds, &cases[i], (const float(*)[2])pos, n);
    reference_displace_free(&ds, &s);
    msaa_close(r, name, &s);
}
