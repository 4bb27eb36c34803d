/* SPDX-License-Identifier: MIT */
/*
 * Viewport origins: the frame drawn into viewport (DX, DY, w, h) of the
 * run's framebuffer must show there the picture the same frame shows at
 * (0, 0, w, h), w x h the run's size less (DX, DY). Every stage that keeps
 * buffers of its own addresses them by window coordinates: the CSG
 * resolve's work and result textures and its CPU staging, vdsm's position
 * buffer and mask, the shadow masks, the peeled layers, GL1 maps drawn in
 * the frame's buffer. Beauty, RGB. A pixel differs where a channel is more
 * than 2 steps apart (GL dithers by window position: 1 step where blending
 * is, measured); at most 0.1% may, for an edge whose rasterisation rounds
 * apart at the other position. On csg.json (products under the tier's
 * shadows: the GPU and the CPU resolve, vdsm, volumes, GL1 maps) and on
 * glass-panes (peeled layers, each vdsm's receiver in turn), every tier.
 */
#include "caller_gl.h"
#include "image_test.h"
#include "scene.h"
#include "scene_csg.h"
#include "test_context.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DX 37 /* not a multiple of any tile size */
#define DY 21
#define STEP 2
#define BUDGET 0.001

/* The frame into `viewport`, read back whole into rgba. */
static int draw_at(test_context *t, const run *r, const int viewport[4], uint8_t *rgba)
{
    return scene_gpu_frame_viewport(&t->g, t->ctx, viewport, STIN_OUTPUT_BEAUTY,
                                    STIN_EXPORT_NONE, stin_platform_framebuffer(r->plat)) ==
               STIN_OK &&
           stin_platform_read_color(r->plat, rgba);
}

/* Pixels of the w x h viewport at the origin in a and at (DX, DY) in b
 * (rows of the run's width) whose channels differ by more than STEP. */
static long differing(const run *r, const uint8_t *a, const uint8_t *b, int w, int h, int *most)
{
    long n = 0;
    int x, y, k;
    *most = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const uint8_t *p = a + 4 * ((size_t)y * r->width + x);
            const uint8_t *q = b + 4 * ((size_t)(y + DY) * r->width + x + DX);
            int far = 0;
            for (k = 0; k < 3; k++) {
                int d = abs((int)p[k] - (int)q[k]);
                far |= d > STEP;
                *most = d > *most ? d : *most;
            }
            n += far;
        }
    return n;
}

static void test_origin(run *r, stin_tier tier, const scene *s, const char *scene_name)
{
    int w = r->width - DX, h = r->height - DY, most;
    const int at_origin[4] = {0, 0, w, h}, moved[4] = {DX, DY, w, h};
    size_t bytes = (size_t)r->width * (size_t)r->height * 4u;
    uint8_t *a = malloc(bytes), *b = malloc(bytes);
    scene_csg_products products;
    test_context t;
    char name[160];
    long n;
    memset(&products, 0, sizeof products);
    snprintf(name, sizeof name, "%s/%s/viewport-origin", stin_tier_name(tier), scene_name);
    if (!a || !b || !scene_csg_products_build(s, &products)) {
        report(r, "FAIL", name, "out of memory");
        goto done;
    }
    if (!test_context_create(&t, r, s, tier, STIN_TECH_NONE, 0)) {
        report(r, "FAIL", name, "no stin context for the scene");
        goto done;
    }
    t.g.csg = products.products;
    t.g.csg_count = products.count;
    if (!draw_at(&t, r, at_origin, a) || !draw_at(&t, r, moved, b)) {
        report(r, "FAIL", name, "a frame or its read-back failed");
    } else {
        n = differing(r, a, b, w, h, &most);
        report(r, n <= BUDGET * w * h ? "PASS" : "FAIL", name,
               "the %dx%d frame at (%d, %d) differs from the same at (0, 0) on %ld pixels by "
               "more than %d steps (at most %.1f%% may; largest difference %d, shadows %s)",
               w, h, DX, DY, n, STEP, 100.0 * BUDGET, most,
               stin_technique_name(stin_query_choice(t.ctx, STIN_FEATURE_SHADOWS).technique));
    }
    t.g.csg = NULL;
    t.g.csg_count = 0;
    test_context_destroy(&t);
done:
    scene_csg_products_free(&products);
    free(a);
    free(b);
}

/* Viewports past the context's limits: stin_begin_frame refuses each with
 * STIN_ERROR_INVALID_ARGUMENT and no GL error pending (before, a far
 * corner past GL_MAX_TEXTURE_SIZE returned STIN_OK with GL_INVALID_VALUE
 * and left the screen mask and position buffer unusable; an origin of
 * 0x7fff0000 aborted the process in the driver), and the context's next
 * ordinary frame is bit for bit a fresh context's first (the same
 * commands on the same driver: no tolerance). */
static int refuses_limits(test_context *t, const run *r, const caller_gl *gl, char *why,
                          size_t size)
{
    const stin_caps *c = stin_query_caps(t->ctx);
    const int bad[3][4] = {{c->max_texture_size - 32, 0, 64, 64},
                           {0x7fff0000, 0, 64, 64},
                           {0, 0, c->max_viewport_dims[0] + 1, 64}};
    int i;
    for (i = 0; i < 3; i++) {
        stin_result res = scene_gpu_frame_viewport(&t->g, t->ctx, bad[i], STIN_OUTPUT_BEAUTY,
                                                   STIN_EXPORT_NONE,
                                                   stin_platform_framebuffer(r->plat));
        GLenum e = gl->GetError();
        if (res != STIN_ERROR_INVALID_ARGUMENT || e != GL_NO_ERROR) {
            snprintf(why, size, "viewport (%d, %d, %d, %d): %s, GL error 0x%x pending",
                     bad[i][0], bad[i][1], bad[i][2], bad[i][3], stin_result_name(res), e);
            return 0;
        }
    }
    return 1;
}

static void test_limits(run *r, stin_tier tier, const scene *s, const char *scene_name)
{
    const int whole[4] = {0, 0, r->width, r->height};
    size_t bytes = (size_t)r->width * (size_t)r->height * 4u;
    uint8_t *fresh = malloc(bytes), *after = malloc(bytes);
    test_context t;
    caller_gl gl;
    char name[160], why[160] = "";
    caller_gl_load(&gl, r->plat);
    snprintf(name, sizeof name, "%s/%s/viewport-limits", stin_tier_name(tier), scene_name);
    if (!fresh || !after || !test_context_create(&t, r, s, tier, STIN_TECH_NONE, 0)) {
        report(r, "FAIL", name, "out of memory or no stin context for the scene");
        goto done;
    }
    if (!draw_at(&t, r, whole, fresh)) {
        report(r, "FAIL", name, "the fresh context's frame failed");
    } else {
        test_context_destroy(&t);
        if (!test_context_create(&t, r, s, tier, STIN_TECH_NONE, 0)) {
            report(r, "FAIL", name, "no second stin context");
            goto done;
        }
        if (!refuses_limits(&t, r, &gl, why, sizeof why))
            report(r, "FAIL", name, "%s", why);
        else if (!draw_at(&t, r, whole, after))
            report(r, "FAIL", name, "the frame after the refusals failed");
        else
            report(r, memcmp(fresh, after, bytes) ? "FAIL" : "PASS", name,
                   "three viewports past the limits refused, no GL error; the next frame %s a "
                   "fresh context's", memcmp(fresh, after, bytes) ? "differs from" : "equals");
    }
    test_context_destroy(&t);
done:
    free(fresh);
    free(after);
}

void viewport_tests(run *r, stin_tier tier, const char *path)
{
    const char *base = scene_base_name(path);
    scene s;
    char err[256];
    if (strcmp(base, "csg") && strcmp(base, "glass-panes"))
        return;
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", "viewport-origin", "%s", err);
        return;
    }
    test_origin(r, tier, &s, base);
    if (!strcmp(base, "csg"))
        test_limits(r, tier, &s, base);
    scene_free(&s);
}
