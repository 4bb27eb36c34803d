/* SPDX-License-Identifier: MIT */
/*
 * CSG products of many primitives (issue 12: more than 255, no 8-bit
 * stencil counter overflow; scs's subtraction sequence), scenes generated
 * here:
 *   dimples     a slab minus 999 small spheres centred on its top face in
 *               a 37 x 27 grid (one term of 1000 literals), under
 *               goldfeather and scs; "apart": the spheres share no point
 *               though their window boxes meet, so scs runs its sequence
 *               once without a check; "grouped": under goldfeather at
 *               least 900 of the spheres take their passes in groups
 *               (stin_frame_stats.csg.grouped), so P above proves them;
 *   thousand    the intersection of 1000 unit spheres with centres spread
 *               over +-0.3 (one term of 1000 plain literals: scs counts
 *               them 255 a batch; STIN_DEBUG_CSG_SCS_NO_BATCH counts them in
 *               one 8-bit counter and must fail here), under scs;
 *   pockets     a box minus 31 spheres on a 6 x 6 grid in its top face,
 *               each cutting into its neighbours (stin-bench's grid n = 32),
 *               under scs and goldfeather. scs orders spheres by the eye's
 *               power, which takes every pixel through every sphere it
 *               lies in at once: "sequence" holds its runs
 *               (stin_frame_stats.csg.scs_runs) at 1, fewer than with the
 *               check off (STIN_DEBUG_CSG_SCS_NO_EARLY_STOP: every run the
 *               boxes' bound allows), with P and N the same, pixel for pixel;
 *   cycle       the box minus 3 tilted bars in a triangle, seen from above:
 *               at each corner one bar's deep end runs through the next
 *               one's high end, so each bar must come before another and
 *               no order takes every pixel through in one run. Under scs
 *               and goldfeather; "sequence" holds scs's runs at 2 or more
 *               (the check asks for a second run) and fewer than every
 *               run, with the same P and N;
 *   cluster     the intersection of 12 unit spheres with centres spread
 *               over +-0.3 minus 12 spheres of radius 0.25 around it (one
 *               term of 12 plain and 12 complemented literals), under
 *               goldfeather and scs: every goldfeather candidate meets 23
 *               others, which it counts by winding numbers in one batch
 *               where the stencil wraps both ways (plain ones negated),
 *               else by parity bits in three; "mirrored" the same with
 *               every sphere mirrored in x (its winding reversed).
 * Against the exact CSG reference with csg_test.c's bounds (P on >= 99.9%
 * of the covered pixels, N within 2 degrees on >= 99.5% away from edges),
 * desc.csg.max_primitives and csg.max_literals raised to 1000. Contexts
 * without what the technique needs report SKIP with the reason.
 */
#include "aov.h"
#include "capture.h"
#include "compare.h"
#include "image_test.h"
#include "reference.h"
#include "reference_csg.h"
#include "scene_gpu.h"
#include "test_context.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define MANY 1000
#define POCKETS 32 /* primitives: the box and 31 spheres */
#define POCKET_SIDE 6
#define CLUSTER 24 /* 12 plain spheres, then 12 complemented */
#define CYCLE 4    /* the box and 3 bars */
#define MANY_P_RELATIVE 1e-3
#define MANY_P_ABSOLUTE 1e-3
#define MANY_P_MIN_MATCH 0.999
#define MANY_NORMAL_DEGREES 2.0
#define MANY_NORMAL_MIN_MATCH 0.995

typedef enum shape { DIMPLES, THOUSAND, POCKETS_SHAPE, CLUSTER_SHAPE, CYCLE_SHAPE } shape;
static const char *const shape_names[] = {"dimples", "thousand", "pockets", "cluster", "cycle"};

static int primitives_of(shape sh)
{
    return sh == POCKETS_SHAPE   ? POCKETS
           : sh == CLUSTER_SHAPE ? CLUSTER
           : sh == CYCLE_SHAPE   ? CYCLE
                                 : MANY;
}

/* Bar k of the cycle: from triangle corner k, high (its top out of the
 * box's top face), down to corner k + 1, deep (below the face), 0.15 past
 * both: at each corner the deep end of one bar runs through the high end
 * of the next. Its matrix (column-major: the bar's x along it) as JSON. */
static void cycle_bar(FILE *f, int k)
{
    const double radius = 0.55, high = 0.47, deep = 0.37, pi = 3.14159265358979;
    double a = pi / 2 + 2 * pi * k / 3, b = a + 2 * pi / 3;
    double p[3] = {radius * cos(a), high, radius * sin(a)};
    double q[3] = {radius * cos(b), deep, radius * sin(b)};
    double u[3], v[3], w[3], len = 0, up;
    int i;
    for (i = 0; i < 3; i++) {
        u[i] = q[i] - p[i];
        len += u[i] * u[i];
    }
    len = sqrt(len);
    for (i = 0; i < 3; i++)
        u[i] /= len;
    up = u[1]; /* the world's up less its part along the bar */
    v[0] = -up * u[0];
    v[1] = 1.0 - up * u[1];
    v[2] = -up * u[2];
    len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (i = 0; i < 3; i++)
        v[i] /= len;
    w[0] = u[1] * v[2] - u[2] * v[1];
    w[1] = u[2] * v[0] - u[0] * v[2];
    w[2] = u[0] * v[1] - u[1] * v[0];
    fprintf(f, "\"matrix\": [%.6f, %.6f, %.6f, 0, %.6f, %.6f, %.6f, 0, %.6f, %.6f, %.6f, 0, "
               "%.6f, %.6f, %.6f, 1]",
            u[0], u[1], u[2], v[0], v[1], v[2], w[0], w[1], w[2], 0.5 * (p[0] + q[0]),
            0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2]));
}

/* A deterministic spread in [-1, 1). */
static double spread(unsigned *state)
{
    *state = *state * 1664525u + 1013904223u;
    return (double)(*state >> 8) / 8388608.0 - 1.0;
}

/* The scene as JSON into a temporary file, loaded. */
static int make_scene(shape sh, scene *s, char *err, size_t err_size)
{
    char path[64];
    unsigned state = 12345u;
    int fd, i, ok;
    FILE *f;
    snprintf(path, sizeof path, "/tmp/stin-csg-many-XXXXXX");
    fd = mkstemp(path);
    if (fd < 0 || !(f = fdopen(fd, "w"))) {
        snprintf(err, err_size, "cannot write a temporary scene");
        return 0;
    }
    if (sh == CYCLE_SHAPE) {
        /* 0.953 between corners, 0.1 down: each bar 0.15 longer each way */
        double along = sqrt(3.0 * 0.55 * 0.55 + 0.1 * 0.1) + 0.3;
        /* from above, so the rays leave a bar through its bottom */
        fprintf(f, "{\"camera\": {\"eye\": [0, 4, 1], \"target\": [0, 0, 0], \"fovy\": 40},\n"
                   "\"meshes\": {\"box\": {\"primitive\": \"box\", \"size\": [2, 1, 2]},\n"
                   "  \"bar\": {\"primitive\": \"box\", \"size\": [%.6f, 0.16, 0.16]}},\n"
                   "\"materials\": {\"m\": {\"color\": [0.7, 0.7, 0.8]}},\n"
                   "\"objects\": [{\"name\": \"box\", \"mesh\": \"box\", \"material\": \"m\"}",
                along);
        for (i = 0; i < 3; i++) {
            fprintf(f, ", {\"name\": \"bar%d\", \"mesh\": \"bar\", \"material\": \"m\", ", i);
            cycle_bar(f, i);
            fprintf(f, "}\n");
        }
    } else if (sh == POCKETS_SHAPE)
        fprintf(f, "{\"camera\": {\"eye\": [0, 2, 4], \"target\": [0, 0, 0], \"fovy\": 45},\n"
                   "\"meshes\": {\"box\": {\"primitive\": \"box\", \"size\": [2, 1, 2]},\n"
                   "  \"ball\": {\"primitive\": \"sphere\", \"radius\": %.6f, \"slices\": 24, "
                   "\"stacks\": 16}},\n"
                   "\"materials\": {\"m\": {\"color\": [0.7, 0.7, 0.8]}},\n"
                   "\"objects\": [{\"name\": \"box\", \"mesh\": \"box\", \"material\": \"m\"}",
                0.6 * 1.8 / POCKET_SIDE); /* past half the step: neighbours intersect */
    else if (sh == DIMPLES)
        fprintf(f, "{\"camera\": {\"eye\": [0, 4.2, 2.6], \"target\": [0, 0, 0.1], \"fovy\": 45},\n"
                   "\"meshes\": {\"slab\": {\"primitive\": \"box\", \"size\": [4, 0.4, 3]},\n"
                   "  \"ball\": {\"primitive\": \"sphere\", \"radius\": 0.045, \"slices\": 10, "
                   "\"stacks\": 6}},\n"
                   "\"materials\": {\"m\": {\"color\": [0.7, 0.7, 0.8]}},\n"
                   "\"objects\": [{\"name\": \"slab\", \"mesh\": \"slab\", \"material\": \"m\"}");
    else
        fprintf(f, "{\"camera\": {\"eye\": [0, 1.5, 5.5], \"target\": [0, 0, 0], \"fovy\": 40},\n"
                   "\"meshes\": {\"ball\": {\"primitive\": \"sphere\", \"radius\": 1.0, "
                   "\"slices\": 16, \"stacks\": 12},\n"
                   "  \"bead\": {\"primitive\": \"sphere\", \"radius\": 0.25, "
                   "\"slices\": 16, \"stacks\": 12}},\n"
                   "\"materials\": {\"m\": {\"color\": [0.7, 0.7, 0.8]}},\n"
                   "\"objects\": [");
    for (i = sh == THOUSAND || sh == CLUSTER_SHAPE ? 0 : 1;
         sh != CYCLE_SHAPE && i < primitives_of(sh); i++) {
        double x, y, z;
        int bead = sh == CLUSTER_SHAPE && i >= CLUSTER / 2;
        if (bead) { /* on the blob's surface, which reaches about 0.7 out */
            double len;
            x = spread(&state);
            y = spread(&state);
            z = spread(&state);
            len = sqrt(x * x + y * y + z * z) + 1e-9;
            x *= 0.75 / len;
            y *= 0.75 / len;
            z *= 0.75 / len;
        } else if (sh == POCKETS_SHAPE) {
            double step = 1.8 / POCKET_SIDE;
            x = -0.9 + step * (0.5 + (i - 1) % POCKET_SIDE);
            y = 0.5;
            z = -0.9 + step * (0.5 + (i - 1) / POCKET_SIDE);
        } else if (sh == DIMPLES) {
            x = -1.85 + 3.7 * ((i - 1) % 37) / 36.0;
            y = 0.2;
            z = -1.3 + 2.6 * ((i - 1) / 37) / 26.0;
        } else {
            x = 0.3 * spread(&state);
            y = 0.3 * spread(&state);
            z = 0.3 * spread(&state);
        }
        fprintf(f, "%s{\"name\": \"b%d\", \"mesh\": \"%s\", \"material\": \"m\", "
                   "\"translate\": [%.6f, %.6f, %.6f]}\n",
                i ? ", " : "", i, bead ? "bead" : "ball", x, y, z);
    }
    fprintf(f, "],\n\"lights\": [{\"type\": \"point\", \"position\": [2, 6, 3]}]}\n");
    fclose(f);
    ok = scene_load(path, s, err, err_size);
    unlink(path);
    return ok;
}

/* Primitive i is object i, nested to the right so the reference's
 * evaluation stops early: dimples slab - (b1 u (b2 u ... b999)) (pockets
 * alike), thousand b0 n (b1 n ... b999); stin's normal form is one term
 * either way. */
static void set_node(stin_csg_node *node, stin_csg_op op, int a, int b)
{
    node->op = op;
    node->primitive = 0;
    node->a = (uint32_t)a;
    node->b = (uint32_t)b;
}

static void make_product(shape sh, int *objects, stin_csg_node *nodes)
{
    int i, n = primitives_of(sh);
    for (i = 0; i < n; i++) {
        objects[i] = i;
        nodes[i].op = STIN_CSG_PRIMITIVE;
        nodes[i].primitive = (uint32_t)i;
        nodes[i].a = nodes[i].b = 0;
    }
    if (sh == CLUSTER_SHAPE) { /* (b0 n ... b11) - (b12 u ... b23), the root last */
        int half = n / 2, k = n, beads = n - 1, blob = half - 1;
        for (i = n - 2; i >= half; i--, k++) {
            set_node(&nodes[k], STIN_CSG_UNION, i, beads);
            beads = k;
        }
        for (i = half - 2; i >= 0; i--, k++) {
            set_node(&nodes[k], STIN_CSG_INTERSECTION, i, blob);
            blob = k;
        }
        set_node(&nodes[k], STIN_CSG_SUBTRACTION, blob, beads);
        return;
    }
    /* node n + j joins primitive n - 2 - j with the node before it (the
     * last primitive at first) */
    for (i = 0; i < n - 1; i++) {
        stin_csg_node *node = &nodes[n + i];
        int last = i == n - 2, carve = sh != THOUSAND;
        node->op = !last ? (carve ? STIN_CSG_UNION : STIN_CSG_INTERSECTION)
                         : (carve ? STIN_CSG_SUBTRACTION : STIN_CSG_INTERSECTION);
        node->primitive = 0;
        node->a = (uint32_t)(n - 2 - i);
        node->b = i == 0 ? (uint32_t)(n - 1) : (uint32_t)(n + i - 1);
    }
}

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

/* The P and N channels of two captures differ nowhere. */
static int same_surface(const image *a, const image *b, long *differ)
{
    static const char *const names[] = {"P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z"};
    long i;
    int k;
    *differ = 0;
    if (a->width != b->width || a->height != b->height)
        return 0;
    for (i = 0; i < (long)a->width * a->height; i++)
        for (k = 0; k < 6; k++) {
            int ca = image_channel(a, names[k]), cb = image_channel(b, names[k]);
            if (ca < 0 || cb < 0)
                return 0;
            if (a->pixels[i * a->channels + ca] != b->pixels[i * b->channels + cb]) {
                (*differ)++;
                break;
            }
        }
    return 1;
}

/* scs's sequence against every run the boxes' bound allows (the same
 * surface, pixel for pixel): pockets, spheres in their power order from the
 * eye, in one run (every pixel through every sphere it lies in); cycle,
 * whose bars must each come before another, in a second run the check
 * asks for, and no more. */
static void sequence_check(run *r, const scene *s, capture_options *o, const capture *checked,
                           const char *name, shape sh)
{
    capture all;
    long differ = 0;
    unsigned runs = checked->stats.csg.scs_runs, every, least = sh == CYCLE_SHAPE ? 2u : 1u;
    unsigned most = sh == CYCLE_SHAPE ? 0xffffffffu : 1u;
    int same;
    if (capture_report_gpu_alone(r, name, checked, "scs counts no runs"))
        return;
    o->debug_flags = STIN_DEBUG_CSG_SCS_NO_EARLY_STOP;
    if (!capture_forced(r, s, o, STIN_FEATURE_CSG, STIN_TECH_CSG_SCS, &all, name))
        return;
    every = all.stats.csg.scs_runs;
    same = same_surface(&checked->img, &all.img, &differ);
    report(r, runs >= least && runs <= most && runs < every && same && differ == 0 ? "PASS"
                                                                                   : "FAIL",
           name, "%u runs with the check, %u without (need %u <= runs%s < %u); P and N differ "
           "on %ld pixels (need 0)",
           runs, every, least, most == 1u ? " <= 1," : "", every, same ? differ : -1L);
    capture_free(&all);
}

/* The capture's P and N against the reference: name ends in "/P" (its
 * last letter becomes N for the second line). */
static void report_surface(run *r, const scene *s, shape sh, const capture *cap,
                           const float *refimg, const ref_hit *hits, char *name)
{
    compare_tolerance tol = {MANY_P_RELATIVE, MANY_P_ABSOLUTE, 1.0, MANY_NORMAL_DEGREES};
    compare_result cr;
    double match;
    compare_render(s, &cap->img, refimg, hits, &tol, &cr);
    match = cr.covered ? 1.0 - (double)(cr.p_mismatch + cr.coverage_mismatch) / cr.covered : 0;
    report(r, cr.covered && match >= MANY_P_MIN_MATCH ? "PASS" : "FAIL", name,
           "%d primitives: P matches the CSG reference on %.3f%% of %ld covered pixels "
           "(coverage differs on %ld, P on %ld; need %.1f%%; %u passes)", primitives_of(sh),
           100.0 * match, cr.covered, cr.coverage_mismatch, cr.p_mismatch,
           100.0 * MANY_P_MIN_MATCH, cap->stats.passes);
    name[strlen(name) - 1] = 'N';
    csg_report_normals(r, name, &cr, MANY_NORMAL_DEGREES, MANY_NORMAL_MIN_MATCH);
}

/* dimples under scs: its spheres lie apart (0.01 between their boxes), but
 * their window boxes meet their neighbours' (1 + 8 others at most), so only
 * the world rule lets the sequence run once with no check (measured with
 * the rule off: 2 runs' bound, 1 check a frame). */
static void apart_check(run *r, const capture *cap, const char *name)
{
    unsigned runs = cap->stats.csg.scs_runs, checks = cap->stats.csg.scs_checks;
    report(r, runs == 1u && checks == 0u ? "PASS" : "FAIL", name,
           "subtracted spheres apart in the world: %u run%s and %u check%s (need 1 and 0)", runs,
           runs == 1u ? "" : "s", checks, checks == 1u ? "" : "s");
}

/* dimples under goldfeather: spheres two grid steps apart lie apart in the
 * window, so their candidates share passes in groups; P above is then the
 * proof that the groups resolve the product exactly. */
static void grouped_check(run *r, const capture *cap, const char *name)
{
    unsigned grouped = cap->stats.csg.grouped;
    report(r, grouped >= 9 * MANY / 10 ? "PASS" : "FAIL", name,
           "%u of %d subtracted spheres took their passes in groups (need >= %d)", grouped,
           MANY - 1, 9 * MANY / 10);
}

/* The cluster again with every sphere mirrored in x about its centre (the
 * same UV sphere, its winding reversed): the mirrored faces' front is GL's
 * back, which goldfeather's winding numbers, scs's one-pass marks and its
 * check must follow. Against the same reference, with the same bounds. */
static void mirror_check(run *r, scene *s, const capture_options *o, stin_technique tech,
                         const float *refimg, const ref_hit *hits, const char *stem)
{
    capture mirrored;
    char name[256];
    int i, k;
    snprintf(name, sizeof name, "%s-mirrored/P", stem);
    for (i = 0; i < s->object_count; i++)
        for (k = 0; k < 3; k++)
            s->objects[i].transform[k] = -s->objects[i].transform[k];
    if (!capture_forced(r, s, o, STIN_FEATURE_CSG, tech, &mirrored, name))
        return;
    report_surface(r, s, CLUSTER_SHAPE, &mirrored, refimg, hits, name);
    capture_free(&mirrored);
}

static void run_many(run *r, stin_tier tier, shape sh, stin_technique tech, uint64_t debug)
{
    static int objects[MANY];
    static stin_csg_node nodes[2 * MANY - 1];
    char err[512], name[256];
    scene s;
    capture cap;
    capture_options o;
    scene_gpu_csg product;
    ref_csg_product rp;
    reference *ref = NULL;
    ref_hit *hits = NULL;
    float *refimg = NULL;
    int w = r->width, h = r->height, have_cap = 0;
    double ms;
    size_t i;
    snprintf(name, sizeof name, "%s/csg-%s-%s%s/P", stin_tier_name(tier),
             stin_technique_name(tech), shape_names[sh],
             debug ? "-no-batch" : "");
    if (!make_scene(sh, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    make_product(sh, objects, nodes);
    product.objects = rp.objects = objects;
    product.primitive_count = rp.primitive_count = (uint32_t)primitives_of(sh);
    product.nodes = rp.nodes = nodes;
    product.node_count = rp.node_count = (uint32_t)(2 * primitives_of(sh) - 1);
    memset(&o, 0, sizeof o);
    o.tier = tier;
    o.csg = &product;
    o.csg_count = 1;
    o.csg_technique = tech;
    o.csg_capacity = MANY;
    o.debug_flags = debug;
    /* the camera's resolve alone in the stats and times: volumes (a
     * default) resolve the product from each light too, to cast it */
    o.shadows = STIN_TECH_SHADOWS_OFF;
    ms = now_ms();
    if (!capture_forced(r, &s, &o, STIN_FEATURE_CSG, tech, &cap, name))
        goto done;
    have_cap = 1;
    ms = now_ms() - ms;
    ref = reference_create(&s, err, sizeof err);
    hits = calloc((size_t)w * h, sizeof *hits);
    refimg = calloc((size_t)w * h * REFERENCE_CHANNELS, sizeof *refimg);
    if (!ref || !hits || !refimg || !reference_csg_mark(ref, &rp, 1) ||
        !reference_csg_primary(ref, &rp, 1, w, h, hits, NULL)) {
        report(r, "FAIL", name, "reference failed: %s", ref ? "out of memory or embree" : err);
        goto done;
    }
    for (i = 0; i < (size_t)w * h; i++) {
        float *p = refimg + i * REFERENCE_CHANNELS;
        int k;
        if (!hits[i].hit)
            continue;
        reference_shade(&s, NULL, &hits[i], 0, p + REFERENCE_CH_R);
        for (k = 0; k < 3; k++) {
            p[REFERENCE_CH_PX + k] = hits[i].P[k];
            p[REFERENCE_CH_NX + k] = hits[i].N[k];
        }
        p[REFERENCE_CH_Z] = hits[i].t;
    }
    /* the whole capture: context, meshes, the AOV frames (each resolves) */
    printf("INFO %s/%s/%.*s: capture %.0f ms, %u passes a frame\n", r->platform_name,
           r->profile_name, (int)strlen(name) - 2, name, ms, cap.stats.passes);
    report_surface(r, &s, sh, &cap, refimg, hits, name);
    strcpy(name + strlen(name) - 1, "gl-clean");
    capture_report_clean(r, name, &cap);
    if (sh == DIMPLES && tech == STIN_TECH_CSG_SCS) {
        strcpy(name + strlen(name) - 8, "apart");
        apart_check(r, &cap, name);
    }
    if (sh == DIMPLES && tech == STIN_TECH_CSG_GOLDFEATHER) {
        strcpy(name + strlen(name) - 8, "grouped");
        grouped_check(r, &cap, name);
    }
    if ((sh == POCKETS_SHAPE || sh == CYCLE_SHAPE) && tech == STIN_TECH_CSG_SCS) {
        strcpy(name + strlen(name) - 8, "sequence");
        sequence_check(r, &s, &o, &cap, name, sh);
    }
    if (sh == CLUSTER_SHAPE) {
        name[strlen(name) - 9] = '\0'; /* the stem before "/gl-clean" */
        mirror_check(r, &s, &o, tech, refimg, hits, name);
    }
done:
    if (have_cap)
        capture_free(&cap);
    free(refimg);
    free(hits);
    reference_destroy(ref);
    scene_free(&s);
}

void csg_many_tests(run *r, stin_tier tier)
{
    run_many(r, tier, DIMPLES, STIN_TECH_CSG_SCS, 0);
    run_many(r, tier, DIMPLES, STIN_TECH_CSG_GOLDFEATHER, 0);
    run_many(r, tier, THOUSAND, STIN_TECH_CSG_SCS, 0);
    run_many(r, tier, POCKETS_SHAPE, STIN_TECH_CSG_SCS, 0);
    run_many(r, tier, POCKETS_SHAPE, STIN_TECH_CSG_GOLDFEATHER, 0);
    run_many(r, tier, CLUSTER_SHAPE, STIN_TECH_CSG_GOLDFEATHER, 0);
    run_many(r, tier, CLUSTER_SHAPE, STIN_TECH_CSG_SCS, 0);
    run_many(r, tier, CYCLE_SHAPE, STIN_TECH_CSG_SCS, 0);
    run_many(r, tier, CYCLE_SHAPE, STIN_TECH_CSG_GOLDFEATHER, 0);
    if (getenv("STIN_CSG_BREAK_BATCH")) /* the proof that batching matters: must FAIL */
        run_many(r, tier, THOUSAND, STIN_TECH_CSG_SCS, STIN_DEBUG_CSG_SCS_NO_BATCH);
}
