/* SPDX-License-Identifier: MIT */
/*
 * stin-imagetest: the tier-by-tier image tests of one capability profile.
 * Run once per profile and platform, each in its own process (Mesa reads its
 * overrides at start-up). Prints one line per test: PASS/FAIL/SKIP name: why.
 *
 *   stin-imagetest --profile gl11 --platform egl [--size 256x192] [--out DIR] SCENE...
 *   stin-imagetest --browser DIR --cases LIST [--size WxH] [--out DIR] SCENE...
 *       compares a browser's read-backs instead (browser_test.c)
 */
#include "aov.h"
#include "compare.h"
#include "expected.h"
#include "gl_errors.h"
#include "image_test.h"
#include "reference.h"
#include "scene_gpu.h"
#include "stin/stin.h"
#include "stin/stin_debug.h"
#include "stin_platform.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

/* P: 24-bit depth resolves eye depth z to about z^2 / (near * 2^24), i.e.
 * 2.4e-4 at z = 20 with near 0.1; 1e-3 * Z + 1e-3 leaves margin for float
 * rasterisation of the same plane. At least 99.9% of covered pixels match. */
#define P_RELATIVE 1e-3
#define P_ABSOLUTE 1e-3
#define P_MIN_MATCH 0.999
/* Beauty: 8-bit framebuffer (1/255 rounding) plus float rounding of the
 * lighting model; 3/255 on at least 99.5% of compared pixels. */
#define BEAUTY_TOLERANCE (3.0 / 255.0)
/* N: stored as 8-bit 0.5 + 0.5 n, so each component is off by up to 1/255
 * (about 0.5 degrees); 2 degrees on at least 99.5% of pixels away from
 * silhouettes. */
#define NORMAL_DEGREES 2.0
#define NORMAL_MIN_MATCH 0.995
#define BEAUTY_MIN_MATCH 0.995
/* A systematic error (a wrong term of the model) shows as a mean offset long
 * before single pixels pass 3/255: the mean must stay within 1/255. */
#define BEAUTY_MAX_MEAN (1.0 / 255.0)

/* The process's CPU seconds (user + system; llvmpipe rasterises in this
 * thread under LP_NUM_THREADS=0, Embree in this process). */
static double cpu_seconds(void)
{
    struct rusage u;
    if (getrusage(RUSAGE_SELF, &u) != 0)
        return 0;
    return (double)u.ru_utime.tv_sec + u.ru_utime.tv_usec * 1e-6 + (double)u.ru_stime.tv_sec +
           u.ru_stime.tv_usec * 1e-6;
}

/* STIN_TEST_CPU=1: after each line, "# cpu S" with the CPU seconds spent
 * since the line before (the work that led to this verdict; set-up shared by
 * several lines is charged to the first), so a suite's time can be summed per
 * test (docs/testing.md, "Where make check's time goes"). */
static void report_cpu(void)
{
    static int on = -1;
    static double last;
    double now;
    if (on < 0)
        on = getenv("STIN_TEST_CPU") && strcmp(getenv("STIN_TEST_CPU"), "0");
    if (!on)
        return;
    now = cpu_seconds();
    printf("# cpu %.3f\n", now - last);
    last = now;
}

void report(run *r, const char *verdict, const char *name, const char *fmt, ...)
{
    va_list ap;
    gl_errors_flush(r, name);
    printf("%s %s/%s/%s: ", verdict, r->platform_name, r->profile_name, name);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
    report_cpu();
    fflush(stdout);
    if (!strcmp(verdict, "PASS")) r->passed++;
    else if (!strcmp(verdict, "FAIL")) r->failed++;
    else r->skipped++;
}

typedef struct log_capture {
    char last_error[512];
    unsigned errors;
    stin_log_item last_item;
} log_capture;

static void capture_log(void *user, stin_log_level level, stin_log_item item, const char *msg)
{
    log_capture *c = (log_capture *)user;
    if (level != STIN_LOG_LEVEL_ERROR)
        return;
    c->errors++;
    c->last_item = item;
    snprintf(c->last_error, sizeof c->last_error, "%s", msg);
}

static void base_desc(run *r, stin_desc *d, log_capture *lc, stin_tier tier)
{
    memset(d, 0, sizeof *d);
    memset(lc, 0, sizeof *lc);
    d->get_proc_address = stin_platform_get_proc_address;
    d->get_proc_user = r->plat;
    d->log = capture_log;
    d->log_user = lc;
    d->tier = tier;
    d->caps_mask = r->profile->caps_mask;
    d->max_gl_version = r->profile->max_gl_version;
}

/* The detected tier and technique per feature against the expected table. */
static void test_selection(run *r, const expected_profile *e)
{
    stin_desc d;
    log_capture lc;
    stin_context *ctx = NULL;
    size_t size;
    void *block;
    stin_result res;
    int f, ok;
    base_desc(r, &d, &lc, STIN_TIER_AUTO);
    size = stin_memory_size(&d);
    block = malloc(size);
    res = stin_create(&d, block, size, &ctx);
    if (res != STIN_OK) {
        report(r, "FAIL", "selection", "stin_create: %s (%s)", stin_result_name(res), lc.last_error);
        free(block);
        return;
    }
    ok = stin_query_tier(ctx) == e->best_tier;
    for (f = 0; f < STIN_FEATURE_COUNT; f++)
        ok &= stin_query_choice(ctx, (stin_feature)f).technique == e->technique[f];
    if (ok)
        report(r, "PASS", "selection", "tier %s, lighting %s", stin_tier_name(e->best_tier),
               stin_technique_name(e->technique[0]));
    else
        report(r, "FAIL", "selection", "got tier %s, lighting %s, shadows %s, surface %s",
               stin_tier_name(stin_query_tier(ctx)),
               stin_technique_name(stin_query_choice(ctx, STIN_FEATURE_LIGHTING).technique),
               stin_technique_name(stin_query_choice(ctx, STIN_FEATURE_SHADOWS).technique),
               stin_technique_name(stin_query_choice(ctx, STIN_FEATURE_SURFACE).technique));
    stin_destroy(ctx);
    free(block);
}

/* A tier the profile cannot run must be refused, naming what is missing. */
static void test_refusal(run *r, stin_tier tier)
{
    stin_desc d;
    log_capture lc;
    stin_context *ctx = NULL;
    size_t size;
    void *block;
    stin_result res;
    char name[64];
    snprintf(name, sizeof name, "refuse-%s", stin_tier_name(tier));
    base_desc(r, &d, &lc, tier);
    size = stin_memory_size(&d);
    block = malloc(size);
    res = stin_create(&d, block, size, &ctx);
    if (res == STIN_ERROR_UNSUPPORTED && lc.last_item == STIN_LOG_TIER_UNSUPPORTED &&
        strstr(lc.last_error, "needs "))
        report(r, "PASS", name, "%s", lc.last_error);
    else
        report(r, "FAIL", name, "expected UNSUPPORTED naming the missing capabilities, got %s (%s)",
               stin_result_name(res), lc.last_error);
    if (ctx)
        stin_destroy(ctx);
    free(block);
}

static void save_failure(run *r, const char *tier, const char *scene_name, const image *img)
{
    char path[1024], err[256];
    if (!r->out_dir)
        return;
    snprintf(path, sizeof path, "%s/%s-%s-%s-%s.exr", r->out_dir, r->platform_name,
             r->profile_name, tier, scene_name);
    if (!image_write(path, img, 0, err, sizeof err))
        fprintf(stderr, "stin-imagetest: %s\n", err);
}

const char *scene_base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    static char buf[128];
    snprintf(buf, sizeof buf, "%s", s ? s + 1 : path);
    if (strrchr(buf, '.'))
        *strrchr(buf, '.') = '\0';
    return buf;
}

void render_rows(run *r, stin_tier tier, const char *scene_name, const scene *s,
                 const image *img, int per_vertex)
{
    reference *ref = NULL;
    ref_hit *hits = NULL;
    float *refimg = NULL;
    char err[512], name[192];
    compare_result cr;
    compare_tolerance tol = {P_RELATIVE, P_ABSOLUTE, BEAUTY_TOLERANCE, NORMAL_DEGREES};
    double p_match, b_match;
    snprintf(name, sizeof name, "%s/%s/position", stin_tier_name(tier), scene_name);
    ref = reference_create(s, err, sizeof err);
    hits = malloc(sizeof *hits * (size_t)r->width * r->height);
    refimg = malloc(sizeof(float) * REFERENCE_CHANNELS * (size_t)r->width * r->height);
    if (!ref || !hits || !refimg || !reference_primary(ref, r->width, r->height, hits) ||
        !reference_render(s, ref, r->width, r->height, per_vertex, refimg)) {
        report(r, "FAIL", name, "reference: %s", ref ? "render failed" : err);
        goto done;
    }
    compare_render(s, img, refimg, hits, &tol, &cr);
    p_match = cr.covered ? 1.0 - (double)(cr.p_mismatch + cr.coverage_mismatch) / cr.covered : 0;
    report(r, p_match >= P_MIN_MATCH && cr.covered ? "PASS" : "FAIL", name,
           "P matches on %.4f%% of %ld covered pixels (coverage differs on %ld, P on %ld; "
           "need %.1f%%)", 100.0 * p_match, cr.covered, cr.coverage_mismatch, cr.p_mismatch,
           100.0 * P_MIN_MATCH);
    snprintf(name, sizeof name, "%s/%s/normal", stin_tier_name(tier), scene_name);
    {
        double n_match = cr.normal_compared ? 1.0 - (double)cr.normal_over / cr.normal_compared : 0;
        report(r, n_match >= NORMAL_MIN_MATCH ? "PASS" : "FAIL", name,
               "N within %.1f deg on %.3f%% of %ld pixels (max %.2f deg; need %.1f%%)",
               NORMAL_DEGREES, 100.0 * n_match, cr.normal_compared, cr.normal_max_deg,
               100.0 * NORMAL_MIN_MATCH);
    }
    snprintf(name, sizeof name, "%s/%s/beauty", stin_tier_name(tier), scene_name);
    if (!cr.beauty_compared) {
        report(r, "SKIP", name, "no opaque untextured pixel to compare (textured and "
                                "transparent surfaces are not in the unshadowed reference)");
    } else {
        b_match = 1.0 - (double)cr.beauty_over / cr.beauty_compared;
        report(r, b_match >= BEAUTY_MIN_MATCH && cr.beauty_mean <= BEAUTY_MAX_MEAN ? "PASS" : "FAIL",
               name, "%s shading within %.4f on %.3f%% of %ld pixels (max %.4f, mean %.5f; "
               "need %.1f%% and mean <= 1/255)",
               per_vertex == 2 ? "per-vertex (single colour)" : per_vertex ? "per-vertex" : "per-pixel", BEAUTY_TOLERANCE, 100.0 * b_match,
               cr.beauty_compared, cr.beauty_max, cr.beauty_mean, 100.0 * BEAUTY_MIN_MATCH);
        if (b_match < BEAUTY_MIN_MATCH || cr.beauty_mean > BEAUTY_MAX_MEAN)
            save_failure(r, stin_tier_name(tier), scene_name, img);
    }
    if (p_match < P_MIN_MATCH)
        save_failure(r, stin_tier_name(tier), scene_name, img);
done:
    free(hits);
    free(refimg);
    if (ref)
        reference_destroy(ref);
}

static void test_scene(run *r, stin_tier tier, const char *path)
{
    scene s;
    scene_gpu g;
    stin_desc d;
    log_capture lc;
    stin_context *ctx = NULL;
    image img;
    void *block = NULL;
    char err[512], name[192], scene_name[128];
    int have_gpu = 0, per_vertex = 0;
    stin_debug_counters dc;
    size_t size;

    memset(&img, 0, sizeof img);
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    snprintf(name, sizeof name, "%s/%s", stin_tier_name(tier), scene_name);
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    base_desc(r, &d, &lc, tier);
    d.techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_OFF; /* the unshadowed contract */
    scene_gpu_size_desc(&s, &d);
    size = stin_memory_size(&d);
    block = malloc(size);
    if (stin_create(&d, block, size, &ctx) != STIN_OK) {
        report(r, "FAIL", name, "stin_create: %s", lc.last_error);
        goto done;
    }
    if (!scene_gpu_create(&g, &s, ctx, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        goto done;
    }
    have_gpu = 1;
    if (tier == STIN_TIER_GL1) /* Gouraud; GL 1.1 has no separate specular colour */
        per_vertex = (stin_query_caps(ctx)->present & STIN_CAP_BIT(STIN_CAP_SEPARATE_SPECULAR))
                         ? 1
                         : REFERENCE_GOURAUD_SINGLE_COLOR;
    if (!aov_capture(&g, ctx, r->plat, &img, NULL, NULL, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        goto done;
    }
    dc = stin_debug_query_counters(ctx);
    snprintf(name, sizeof name, "%s/%s/gl-clean", stin_tier_name(tier), scene_name);
    if (dc.gl_violations || lc.errors)
        report(r, "FAIL", name, "%u profile violations, %u error logs (last: %s)",
               dc.gl_violations, lc.errors, lc.last_error);
    else
        report(r, "PASS", name, "no error logged, no call outside the profile%s",
               dc.checked ? "" : " (unchecked build)");
    render_rows(r, tier, scene_name, &s, &img, per_vertex);
done:
    image_free(&img);
    if (have_gpu)
        scene_gpu_destroy(&g, ctx);
    if (ctx)
        stin_destroy(ctx);
    free(block);
    scene_free(&s);
}

int main(int argc, char **argv)
{
    run r;
    stin_platform_desc pd;
    const expected_profile *e;
    char err[512];
    int i, first_scene = argc, t;
    char *displaced;
    const stin_tier tiers[3] = {STIN_TIER_GL1, STIN_TIER_GL2, STIN_TIER_GL4};
    const char *browser_dir = NULL, *browser_cases = "", *only_tiers = NULL;
    memset(&r, 0, sizeof r);
    /* every scene is loaded again by each test file and tier: its model and
     * image files are decoded (a fork of this large process) once */
    scene_import_memo = 1;
    r.width = 256;
    r.height = 192;
    r.platform_name = "egl";
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--profile") && i + 1 < argc) r.profile_name = argv[++i];
        else if (!strcmp(argv[i], "--platform") && i + 1 < argc) r.platform_name = argv[++i];
        else if (!strcmp(argv[i], "--out") && i + 1 < argc) r.out_dir = argv[++i];
        else if (!strcmp(argv[i], "--browser") && i + 1 < argc) browser_dir = argv[++i];
        else if (!strcmp(argv[i], "--cases") && i + 1 < argc) browser_cases = argv[++i];
        else if (!strcmp(argv[i], "--tiers") && i + 1 < argc) only_tiers = argv[++i];
        else if (!strcmp(argv[i], "--size") && i + 1 < argc) {
            if (sscanf(argv[++i], "%dx%d", &r.width, &r.height) != 2) return 2;
        } else {
            first_scene = i;
            break;
        }
    }
    if (browser_dir) { /* read-backs of a browser's frames (browser_test.c) */
        r.platform_name = "chromium";
        r.profile_name = "webgl2";
        for (i = first_scene; i < argc; i++)
            browser_tests(&r, browser_dir, browser_cases, argv[i]);
        return 0;
    }
    memset(&pd, 0, sizeof pd);
    if (!r.profile_name || !(r.profile = stin_profile_find(r.profile_name)) ||
        !(e = expected_find(r.profile_name)) ||
        !stin_platform_kind_from_name(r.platform_name, &pd.kind)) {
        fprintf(stderr, "usage: stin-imagetest --profile NAME --platform egl|osmesa "
                        "[--size WxH] [--out DIR] [--tiers gl1,gl2,gl4] SCENE...\n");
        return 2;
    }
    pd.width = r.width;
    pd.height = r.height;
    pd.profile = r.profile;
    r.plat = stin_platform_create(&pd, err, sizeof err);
    if (!r.plat) {
        report(&r, "SKIP", "context", "no %s context for this profile: %s", r.platform_name, err);
        return 0;
    }
    gl_errors_arm(&r);
    test_selection(&r, e);
    displaced = calloc((size_t)argc, 1); /* once per scene, not per tier */
    for (i = first_scene; displaced && i < argc; i++)
        displaced[i] = (char)displace_scene(argv[i]);
    for (t = 0; t < 3; t++) {
        /* --tiers: a suite of some tiers alone (the selection row runs in each) */
        if (only_tiers && !strstr(only_tiers, stin_tier_name(tiers[t])))
            continue;
        if (!e->tier_runs[t]) {
            test_refusal(&r, tiers[t]);
            continue;
        }
        update_mesh_tests(&r, tiers[t]);
        for (i = first_scene; i < argc; i++) {
            if (displaced && displaced[i]) {
                displace_tests(&r, tiers[t], argv[i]);
                msaa_displace_tests(&r, tiers[t], argv[i]);
                continue;
            }
            test_scene(&r, tiers[t], argv[i]);
            shadow_tests(&r, tiers[t], argv[i]);
            soft_tests(&r, tiers[t], argv[i]);
            vdsm_tests(&r, tiers[t], argv[i]);
            choice_tests(&r, tiers[t], argv[i]);
            map_tests(&r, tiers[t], argv[i]);
            pcf_tests(&r, tiers[t], argv[i]);
            index16_tests(&r, tiers[t], argv[i]);
            model_tests(&r, tiers[t], argv[i]);
            surface_tests(&r, tiers[t], argv[i]);
            lit_tests(&r, tiers[t], argv[i]);
            dot3_tests(&r, tiers[t], argv[i]);
            hostile_tests(&r, tiers[t], argv[i]);
            composite_tests(&r, tiers[t], argv[i]);
            visibility_tests(&r, tiers[t], argv[i]);
            terminator_tests(&r, tiers[t], argv[i]);
            outline_tests(&r, tiers[t], argv[i]);
            csg_tests(&r, tiers[t], argv[i]);
            csg_merge_tests(&r, tiers[t], argv[i]);
            deep_tests(&r, tiers[t], argv[i]);
            coloured_tests(&r, tiers[t], argv[i]);
            peel_tests(&r, tiers[t], argv[i]);
            viewport_tests(&r, tiers[t], argv[i]);
            msaa_tests(&r, tiers[t], argv[i]);
            msaa_csg_tests(&r, tiers[t], argv[i]);
            msaa_blend_tests(&r, tiers[t], argv[i]);
            msaa_surface_tests(&r, tiers[t], argv[i]);
            msaa_outline_tests(&r, tiers[t], argv[i]);
            error_kept_tests(&r, tiers[t], argv[i]);
            srgb_tests(&r, tiers[t], argv[i]);
        }
    }
    free(displaced);
    gl_errors_finish(&r);
    stin_platform_destroy(r.plat);
    return 0;
}
