/* SPDX-License-Identifier: MIT */
/*
 * The measured choice of the exact technique (GL4, shadows on auto; stin.h,
 * SHADOWS) switches between vdsm and stencil volumes (GPU-extruded and
 * CPU-built) from one frame to the next; both are exact, so the picture may
 * not change. One context per scene with desc.shadows.choice_frames 1: after
 * its 8 warm-up frames every other frame is a trial, so consecutive frames
 * run different techniques (vdsm, GPU volumes, vdsm, CPU volumes, ... or,
 * once it switched, the chosen volumes between the others). FRAMES
 * visibility frames after the warm-up, light 0:
 *   choice-vis   each frame against the Embree reference with the tolerance
 *                of the technique it ran: vdsm as vdsm_test.c's vis (no
 *                pixel differs outside the ambiguous ones), volumes as
 *                shadow_test.c's vis (at most 0.1% of the compared pixels,
 *                none farther than one pixel from a reference shadow edge).
 *   choice-same  two frames of different techniques differ only on pixels
 *                within one pixel of a reference shadow edge (the
 *                reference's visibility, or the object, changes among the
 *                pixel's neighbours): 0 elsewhere. Both techniques decide a
 *                pixel by the segment from its surface point to the light,
 *                so they can disagree only where that segment grazes a
 *                silhouette - where the exact visibility changes inside the
 *                pixel's neighbourhood - or where the reference is ambiguous
 *                on both (vdsm_case.c), which is counted apart; on the edges
 *                at most VIS_EDGE_BUDGET of the image (vdsm_case.h: the
 *                interpolated surface point moves an edge by up to 1e-5 of
 *                the eye distance, and the two draw the depth with
 *                different far planes).
 *                Both follow the terminator rule (stin.h), so every frame
 *                is compared with the reference's rule and a switch must
 *                change no pixel.
 *   choice-ran   frames of at least two techniques ran, none was built a
 *                lit program after the warm-up (one shadow chunk for both),
 *                and no GL error or call outside the profile.
 * Scenes: spheres-18k (closed meshes, point light), shadow-open (open ones)
 * and spheres-18k-sun (directional): light 0 is no area light and nothing
 * is blended, CSG or displaced, so volumes draw every frame.
 */
#include "aov.h"
#include "scene_gpu.h"
#include "vdsm_case.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FRAMES 12
#define WARMUP 8 /* the choice's frames before its first trial (shadow/choice.c) */
#define VOLUME_MAX_MISMATCH 0.001

static const char *const scenes[] = {"spheres-18k", "shadow-open", "spheres-18k-sun"};

typedef struct frame_vis {
    unsigned char *vis;   /* light 0's visibility, 0 or 1 a pixel, rows bottom to top */
    uint32_t technique;   /* stin_shadow_choice */
    uint32_t trial;
} frame_vis;

static void name_of(const vdsm_case *c, const char *test, char *out, size_t size)
{
    snprintf(out, size, "gl4/%s/%s", c->scene_name, test);
}

static int chosen_scene(const char *name)
{
    size_t i;
    for (i = 0; i < sizeof scenes / sizeof scenes[0]; i++)
        if (!strcmp(name, scenes[i]))
            return 1;
    return 0;
}

/* Frame f's visibility put into the forced vdsm render's AOVs (its P and Z
 * are the surface's), for the reference comparison. */
static void with_vis(const capture *base, const frame_vis *f, int w, int h, capture *out)
{
    int x, y;
    *out = *base;
    memset(&out->img, 0, sizeof out->img);
    if (!image_alloc(&out->img, w, h, base->img.channels))
        return;
    memcpy(out->img.pixels, base->img.pixels,
           sizeof(float) * (size_t)w * h * (size_t)base->img.channels);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            ((float *)vdsm_px(&out->img, x, y))[AOV_VIS_R] = f->vis[(size_t)y * w + x];
}

static void test_vis(const vdsm_case *c, const capture *base, const frame_vis *f, int k)
{
    static const char *const tech[] = {"off", "vdsm", "GPU volumes", "CPU volumes"};
    int w = c->r->width, h = c->r->height, ok;
    long compared, ambig, isolated, edge, differ;
    capture cap;
    char name[256], test[64];
    with_vis(base, f, w, h, &cap);
    snprintf(test, sizeof test, "choice-vis-%d", k);
    name_of(c, test, name, sizeof name);
    if (!cap.img.pixels) {
        report(c->r, "FAIL", name, "out of memory");
        return;
    }
    differ = vdsm_mismatches(c, &cap, &compared, &ambig, &isolated, &edge);
    if (f->technique == STIN_SHADOW_CHOICE_VDSM)
        ok = differ == 0;
    else
        ok = differ - edge == 0 && differ <= VOLUME_MAX_MISMATCH * compared;
    report(c->r, compared > 0 && f->technique != STIN_SHADOW_CHOICE_OFF && ok ? "PASS" : "FAIL",
           name,
           "%s%s: visibility differs from the ray cast on %ld of %ld pixels, %ld of them on a "
           "reference shadow edge (vdsm: need 0; volumes: at most 0.1%%, all on an edge); not "
           "counted: %ld where the reference is ambiguous",
           tech[f->technique < 4 ? f->technique : 0], f->trial ? " (trial)" : "", differ,
           compared, edge, ambig);
    image_free(&cap.img);
}

/* Every pair of frames of different techniques. */
static void test_same(const vdsm_case *c, const frame_vis *f, int n)
{
    int w = c->r->width, h = c->r->height, a, b, x, y, pairs = 0;
    long off_edge = 0, on_edge = 0, worst_edge = 0;
    char name[256];
    for (a = 0; a < n; a++)
        for (b = a + 1; b < n; b++) {
            long edge = 0;
            if (f[a].technique == f[b].technique)
                continue;
            pairs++;
            for (y = 0; y < h; y++)
                for (x = 0; x < w; x++) {
                    size_t i = (size_t)y * w + x;
                    if (f[a].vis[i] == f[b].vis[i])
                        continue;
                    if (vdsm_on_shadow_edge(c, x, y))
                        edge++;
                    else
                        off_edge++;
                    if (getenv("STIN_TEST_VERBOSE"))
                        fprintf(stderr, "  frames %d and %d differ at pixel %d,%d\n", a, b, x,
                                h - 1 - y);
                }
            on_edge += edge;
            worst_edge = edge > worst_edge ? edge : worst_edge;
        }
    name_of(c, "choice-same", name, sizeof name);
    report(c->r, pairs > 0 && off_edge == 0 && worst_edge <= VIS_EDGE_BUDGET * w * h ? "PASS"
                                                                                    : "FAIL",
           name,
           "%d pairs of frames of different techniques: %ld differing pixels away from a "
           "reference shadow edge (need 0), %ld on one (at most %ld a pair, need <= %.0f)",
           pairs, off_edge, on_edge, worst_edge, VIS_EDGE_BUDGET * w * h);
}

/* Renders the warm-up and FRAMES visibility frames of an auto context. */
static int run_frames(const vdsm_case *c, frame_vis *f, unsigned *programs, capture *logged,
                      stin_debug_counters *counters, char *err, size_t err_size)
{
    stin_desc d;
    stin_context *ctx = NULL;
    scene_gpu g;
    void *block = NULL;
    unsigned char *rgba;
    int w = c->r->width, h = c->r->height, k, ok = 0, have_gpu = 0;
    size_t size, i;
    rgba = malloc((size_t)w * h * 4);
    memset(&d, 0, sizeof d);
    d.get_proc_address = stin_platform_get_proc_address;
    d.get_proc_user = c->r->plat;
    d.log = capture_log_fn;
    d.log_user = logged;
    d.tier = STIN_TIER_GL4;
    d.caps_mask = c->r->profile->caps_mask;
    d.max_gl_version = c->r->profile->max_gl_version;
    d.shadows.choice_frames = 1;
    scene_gpu_size_desc(c->s, &d);
    size = stin_memory_size(&d);
    block = size ? malloc(size) : NULL;
    if (!rgba || !block || stin_create(&d, block, size, &ctx) != STIN_OK) {
        snprintf(err, err_size, "stin_create: %.200s", logged->last_error);
        goto done;
    }
    if (!scene_gpu_create(&g, c->s, ctx, err, err_size))
        goto done;
    have_gpu = 1;
    for (k = -WARMUP; k < FRAMES; k++) {
        stin_frame_stats st;
        if (scene_gpu_frame(&g, ctx, w, h, STIN_OUTPUT_VISIBILITY,
                            stin_platform_framebuffer(c->r->plat)) != STIN_OK ||
            !stin_platform_read_color(c->r->plat, rgba)) {
            snprintf(err, err_size, "frame %d failed: %.200s", k, logged->last_error);
            goto done;
        }
        st = stin_query_frame_stats(ctx);
        if (k < 0)
            continue;
        *programs += st.lighting.programs_built;
        f[k].technique = st.shadows.choice_frame;
        f[k].trial = st.shadows.choice_trial;
        for (i = 0; i < (size_t)w * h; i++)
            f[k].vis[i] = rgba[4 * i] >= 128;
    }
    *counters = stin_debug_query_counters(ctx);
    ok = 1;
done:
    if (have_gpu)
        scene_gpu_destroy(&g, ctx);
    if (ctx)
        stin_destroy(ctx);
    free(block);
    free(rgba);
    return ok;
}

static void test_ran(const vdsm_case *c, const frame_vis *f, unsigned programs,
                     const capture *logged, const stin_debug_counters *counters)
{
    unsigned ran[4] = {0, 0, 0, 0};
    int k, kinds = 0;
    int clean = !logged->log_errors && !counters->gl_violations;
    char name[256];
    for (k = 0; k < FRAMES; k++)
        ran[f[k].technique < 4 ? f[k].technique : 0]++;
    for (k = 1; k < 4; k++)
        kinds += ran[k] > 0;
    name_of(c, "choice-ran", name, sizeof name);
    report(c->r, kinds >= 2 && !ran[0] && !programs && clean ? "PASS" : "FAIL",
           name,
           "frames of vdsm %u, GPU volumes %u, CPU volumes %u, no choice %u (need two "
           "techniques); lit programs built after the warm-up %u (need 0); %u error logs "
           "(last: %s), %u profile violations",
           ran[1], ran[2], ran[3], ran[0], programs, logged->log_errors, logged->last_error,
           counters->gl_violations);
}

void choice_tests(run *r, stin_tier tier, const char *path)
{
    scene s;
    vdsm_case c;
    capture base;
    frame_vis f[FRAMES];
    capture logged;
    stin_debug_counters counters;
    unsigned programs = 0;
    char err[512], scene_name[128], name[256];
    int k, w = r->width, h = r->height;
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    if (tier != STIN_TIER_GL4 || !chosen_scene(scene_name) ||
        !vdsm_runs_here(r, scene_name, "choice"))
        return;
    if (!scene_load(path, &s, err, sizeof err))
        return; /* test_scene reported it */
    memset(f, 0, sizeof f);
    memset(&c, 0, sizeof c); /* closed whether or not it opened */
    memset(&logged, 0, sizeof logged);
    memset(&counters, 0, sizeof counters);
    for (k = 0; k < FRAMES; k++)
        if (!(f[k].vis = malloc((size_t)w * h)))
            goto done;
    if (!s.light_count || !vdsm_case_open(&c, r, &s, scene_name, "choice") ||
        !vdsm_render(&c, 0, &base, "choice"))
        goto done;
    if (!run_frames(&c, f, &programs, &logged, &counters, err, sizeof err)) {
        name_of(&c, "choice", name, sizeof name);
        report(r, "FAIL", name, "%s", err);
    } else {
        for (k = 0; k < FRAMES; k++)
            test_vis(&c, &base, &f[k], k);
        test_same(&c, f, FRAMES);
        test_ran(&c, f, programs, &logged, &counters);
    }
    capture_free(&base);
done:
    vdsm_case_close(&c);
    for (k = 0; k < FRAMES; k++)
        free(f[k].vis);
    scene_free(&s);
}
