/* SPDX-License-Identifier: MIT */
/*
 * STIN_DEBUG_CSG_NO_IN_PLACE's image against the default's: the
 * work buffer's merge and snap (the path interval and multisampled targets
 * always take) against the resolve in place or direct, on the scene files'
 * own products (csg.json and tests/scenes/csg/), each scene as the files
 * give it (its lights, the tier's own shadows and CSG techniques), colour
 * and depth read back. The two differ on isolated pixels only (stin.h,
 * STIN_DEBUG_CSG_NO_IN_PLACE): at most MAX_DIFFER of the covered pixels
 * may, the bound of the GPU resolve against the read-back one (csg_test.c);
 * measured at 256 x 192 0 on every scene on gl45-core and gl33-core, 1 on
 * four scenes on gl21; 1-2 of 46,695-201,416 at 512 x 384 and 640 x 480
 * on gl45-core. Below the GLSL tiers the resolve reads
 * back on both and the test SKIPs.
 */
#include "image_test.h"
#include "scene.h"
#include "scene_csg.h"
#include "test_context.h"

#include <glob.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_DIFFER 0.0005

typedef struct frame_read {
    uint8_t *rgba;
    float *depth;
    stin_frame_stats stats;
} frame_read;

/* One frame of s (its products drawn as products) on a fresh context. */
static int frame_of(run *r, stin_tier tier, const scene *s, const scene_csg_products *p,
                    uint64_t flags, frame_read *out)
{
    test_context t;
    int ok;
    if (!test_context_create_debug(&t, r, s, tier, STIN_TECH_NONE, 0, flags))
        return 0;
    t.g.csg = p->products;
    t.g.csg_count = p->count;
    ok = scene_gpu_frame(&t.g, t.ctx, r->width, r->height, STIN_OUTPUT_BEAUTY,
                         stin_platform_framebuffer(r->plat)) == STIN_OK &&
         stin_platform_read_color(r->plat, out->rgba) &&
         stin_platform_read_depth(r->plat, out->depth);
    out->stats = stin_query_frame_stats(t.ctx);
    t.g.csg = NULL;
    t.g.csg_count = 0;
    test_context_destroy(&t);
    return ok;
}

static void compare_scene(run *r, stin_tier tier, const char *path)
{
    size_t n = (size_t)r->width * (size_t)r->height, i;
    frame_read a, b;
    scene s;
    scene_csg_products p;
    char err[256], name[256];
    long differ = 0, lost = 0, covered = 0;
    memset(&p, 0, sizeof p);
    snprintf(name, sizeof name, "%s/%s/csg-no-in-place", stin_tier_name(tier),
             scene_base_name(path));
    a.rgba = malloc(n * 4);
    b.rgba = malloc(n * 4);
    a.depth = malloc(n * sizeof(float));
    b.depth = malloc(n * sizeof(float));
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        goto done_files;
    }
    if (!a.rgba || !b.rgba || !a.depth || !b.depth || !scene_csg_products_build(&s, &p)) {
        report(r, "FAIL", name, "out of memory");
        goto done;
    }
    if (!frame_of(r, tier, &s, &p, 0, &a) ||
        !frame_of(r, tier, &s, &p, STIN_DEBUG_CSG_NO_IN_PLACE, &b)) {
        report(r, "FAIL", name, "a frame or its read-back failed");
        goto done;
    }
    if (!a.stats.csg.gpu_resolves) {
        report(r, "SKIP", name, "the products resolve with read-backs here");
        goto done;
    }
    for (i = 0; i < n; i++) {
        int in_a = a.depth[i] < 1.0f, in_b = b.depth[i] < 1.0f;
        covered += in_a || in_b;
        differ += memcmp(a.rgba + 4 * i, b.rgba + 4 * i, 4) || a.depth[i] != b.depth[i];
        lost += in_a && !in_b;
    }
    report(r, differ <= MAX_DIFFER * covered && covered && b.stats.csg.gpu_resolves ? "PASS"
                                                                                   : "FAIL",
           name, "with the flag (merge and snap) the frame differs from the default's (in place "
           "%u, direct %u) on %ld of %ld covered pixels, %ld of them uncovered with the flag "
           "(need <= %.2f%%)", a.stats.csg.in_place, a.stats.csg.direct, differ, covered, lost,
           100.0 * MAX_DIFFER);
done:
    scene_csg_products_free(&p);
    scene_free(&s);
done_files:
    free(a.rgba);
    free(b.rgba);
    free(a.depth);
    free(b.depth);
}

void csg_merge_tests(run *r, stin_tier tier, const char *path)
{
    char pattern[1100];
    const char *slash;
    glob_t g;
    size_t i;
    if (strcmp(scene_base_name(path), "csg") != 0)
        return;
    if (tier == STIN_TIER_GL1) {
        report(r, "SKIP", "gl1/csg-no-in-place", "the GL1 tier resolves with read-backs");
        return;
    }
    compare_scene(r, tier, path);
    slash = strrchr(path, '/');
    snprintf(pattern, sizeof pattern, "%.*s/csg/*.json", slash ? (int)(slash - path) : 1,
             slash ? path : ".");
    if (glob(pattern, 0, NULL, &g) != 0)
        return;
    for (i = 0; i < g.gl_pathc; i++)
        compare_scene(r, tier, g.gl_pathv[i]);
    globfree(&g);
}
