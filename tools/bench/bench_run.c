/* SPDX-License-Identifier: MIT */
/* Per set-up: both renderers built afresh, warm-up, an image check that the
 * raw loop draws what stin draws, then the timed frames in ABBA order (stin,
 * raw, raw, stin, ...) so that drift and noise fall on both sides equally;
 * glFinish ends each frame so that its time includes the rasterisation it
 * caused.
 * Why several set-ups: on llvmpipe a program object sometimes runs 1.6-2x
 * slower for its whole life (seen on the raw side as often as on stin's, with
 * one render thread too: placement of JIT code or data, not stin). A fresh
 * set-up re-rolls that, and the lowest set-up median per side drops it. */
#include "bench_run.h"
#include "bench_time.h"
#include "cli_log.h"
#include "raw.h"
#include "scene_gpu.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Two images agree where no channel differs by more than this (GLSL tiers
 * compute the eye position in a different float order than stin). */
#define CHANNEL_TOLERANCE 2
#define MAX_MISMATCH 0.001

typedef struct pair {
    const bench_settings *b;
    stin_context *ctx;
    scene_gpu gpu;
    raw_renderer raw;
} pair;

/* What one set-up measured. */
typedef struct setup_result {
    double stin_ms, raw_ms;
    double mismatch;
    int max_diff;
} setup_result;

/* Milliseconds for one finished stin frame, negative on failure. */
static double stin_frame(const pair *p)
{
    double t0 = bench_now_ms();
    stin_result r = scene_gpu_frame(&p->gpu, p->ctx, p->b->width, p->b->height,
                                    STIN_OUTPUT_BEAUTY, stin_platform_framebuffer(p->b->plat));
    p->b->gl->Finish();
    return r == STIN_OK ? bench_now_ms() - t0 : -1.0;
}

static double raw_frame_ms(const pair *p)
{
    double t0 = bench_now_ms();
    raw_frame(&p->raw, p->b->width, p->b->height);
    p->b->gl->Finish();
    return bench_now_ms() - t0;
}

/* Reads back one frame of each and compares them. */
static int compare_images(const pair *p, setup_result *out, char *err, size_t err_size)
{
    size_t n = (size_t)p->b->width * (size_t)p->b->height, i, bad = 0;
    uint8_t *a = malloc(4 * n), *c = malloc(4 * n);
    int ok = 0, k;
    if (!a || !c) {
        snprintf(err, err_size, "out of memory");
        goto done;
    }
    if (stin_frame(p) < 0 || !stin_platform_read_color(p->b->plat, a)) {
        snprintf(err, err_size, "stin frame or its read-back failed");
        goto done;
    }
    raw_frame(&p->raw, p->b->width, p->b->height);
    if (!stin_platform_read_color(p->b->plat, c)) {
        snprintf(err, err_size, "raw loop: GL error in the frame or its read-back");
        goto done;
    }
    out->max_diff = 0;
    for (i = 0; i < n; i++) {
        int worst = 0;
        for (k = 0; k < 4; k++) {
            int d = abs((int)a[4 * i + k] - (int)c[4 * i + k]);
            worst = d > worst ? d : worst;
        }
        out->max_diff = worst > out->max_diff ? worst : out->max_diff;
        bad += worst > CHANNEL_TOLERANCE;
    }
    out->mismatch = (double)bad / (double)n;
    ok = out->mismatch <= MAX_MISMATCH;
    if (!ok)
        snprintf(err, err_size, "the raw loop's image differs from stin's in %.3f%% of the "
                 "pixels (max channel difference %d): it does not draw the same thing",
                 100.0 * out->mismatch, out->max_diff);
done:
    free(a);
    free(c);
    return ok;
}

static int measure(const pair *p, setup_result *out, char *err, size_t err_size)
{
    const bench_settings *b = p->b;
    size_t n = (size_t)b->frames;
    double *ts = calloc(n, sizeof *ts), *tr = calloc(n, sizeof *tr);
    int k, ok = 0;
    if (!ts || !tr) {
        snprintf(err, err_size, "out of memory");
        goto done;
    }
    for (k = 0; k < b->frames; k++) {
        if (k % 2 == 0) {
            ts[k] = stin_frame(p);
            tr[k] = raw_frame_ms(p);
        } else {
            tr[k] = raw_frame_ms(p);
            ts[k] = stin_frame(p);
        }
        if (ts[k] < 0) {
            snprintf(err, err_size, "stin frame failed");
            goto done;
        }
    }
    if (b->verbose) {
        /* In run order, so that drift and outliers can be told apart. */
        fprintf(stderr, "stin-bench: frame ms (stin/raw):");
        for (k = 0; k < b->frames; k++)
            fprintf(stderr, " %.1f/%.1f", ts[k], tr[k]);
        fprintf(stderr, "\n");
    }
    out->stin_ms = bench_median(ts, n);
    out->raw_ms = bench_median(tr, n);
    ok = 1;
done:
    free(ts);
    free(tr);
    return ok;
}

static int run_pair(pair *p, stin_tier tier, const scene *s, setup_result *out, char *err,
                    size_t err_size)
{
    const bench_settings *b = p->b;
    const stin_caps *caps = stin_query_caps(p->ctx);
    raw_config cfg;
    GLenum e;
    int k, ok;
    if (!scene_gpu_create(&p->gpu, s, p->ctx, err, err_size))
        return 0;
    memset(&cfg, 0, sizeof cfg);
    cfg.tier = tier;
    cfg.es_glsl = caps->es ? 100 * caps->glsl_major + 10 * caps->glsl_minor : 0;
    cfg.use_vbo = (caps->present & STIN_CAP_BIT(STIN_CAP_VBO)) != 0;
    cfg.separate_specular = (caps->present & STIN_CAP_BIT(STIN_CAP_SEPARATE_SPECULAR)) != 0;
    cfg.shader_dir = b->shader_dir;
    if (!raw_create(&p->raw, b->gl, s, &cfg, err, err_size)) {
        scene_gpu_destroy(&p->gpu, p->ctx);
        return 0;
    }
    /* Warm-up: driver shader variants, caches and buffer residency settle. */
    for (k = 0; k < b->warmup; k++) {
        if (stin_frame(p) < 0) {
            snprintf(err, err_size, "stin frame failed");
            break;
        }
        raw_frame_ms(p);
    }
    ok = k == b->warmup && compare_images(p, out, err, err_size) &&
         measure(p, out, err, err_size);
    if (ok && (e = b->gl->GetError()) != 0) {
        snprintf(err, err_size, "GL error 0x%x during the timed frames", e);
        ok = 0;
    }
    raw_destroy(&p->raw);
    scene_gpu_destroy(&p->gpu, p->ctx);
    return ok;
}

static int one_setup(const bench_settings *b, stin_tier tier, const scene *s, setup_result *out,
                     char *err, size_t err_size)
{
    cli_log log;
    stin_desc desc;
    pair p;
    void *block;
    size_t bytes;
    stin_result r;
    int ok;
    memset(out, 0, sizeof *out);
    memset(&p, 0, sizeof p);
    p.b = b;
    memset(&log, 0, sizeof log);
    log.program = "stin-bench";
    log.verbose = b->verbose;
    bench_desc_init(b, &desc);
    desc.log = cli_log_fn;
    desc.log_user = &log;
    desc.tier = tier;
    /* The raw loop draws no shadows: compare the unshadowed path (the default
     * would pick stencil volumes wherever there is a stencil buffer). */
    desc.techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_OFF;
    scene_gpu_size_desc(s, &desc);
    bytes = stin_memory_size(&desc);
    if (!(block = malloc(bytes))) {
        snprintf(err, err_size, "cannot allocate %zu bytes for stin", bytes);
        return 0;
    }
    r = stin_create(&desc, block, bytes, &p.ctx);
    if (r != STIN_OK) {
        snprintf(err, err_size, "stin_create (tier %s): %s", stin_tier_name(tier),
                 stin_result_name(r));
        free(block);
        return 0;
    }
    ok = run_pair(&p, tier, s, out, err, err_size);
    if (ok && log.errors) {
        snprintf(err, err_size, "stin logged %u error(s)", log.errors);
        ok = 0;
    }
    stin_destroy(p.ctx);
    free(block);
    return ok;
}

void bench_desc_init(const bench_settings *b, stin_desc *desc)
{
    memset(desc, 0, sizeof *desc);
    desc->get_proc_address = stin_platform_get_proc_address;
    desc->get_proc_user = b->plat;
    desc->caps_mask = b->caps_mask;
    desc->max_gl_version = b->max_gl_version;
}

int bench_run(const bench_settings *b, stin_tier tier, const scene *s, bench_result *out,
              char *err, size_t err_size)
{
    int j;
    memset(out, 0, sizeof *out);
    out->triangles = scene_triangle_count(s);
    for (j = 0; j < b->setups; j++) {
        setup_result r;
        if (!one_setup(b, tier, s, &r, err, err_size))
            return 0;
        if (b->verbose)
            fprintf(stderr, "stin-bench: set-up %d: medians stin %.2f ms, raw %.2f ms; images "
                    "differ in %.4f%% of the pixels, max %d/255\n", j + 1, r.stin_ms, r.raw_ms,
                    100.0 * r.mismatch, r.max_diff);
        if (j == 0 || r.stin_ms < out->stin_ms)
            out->stin_ms = r.stin_ms;
        if (j == 0 || r.raw_ms < out->raw_ms)
            out->raw_ms = r.raw_ms;
        if (r.mismatch > out->mismatch)
            out->mismatch = r.mismatch;
        if (r.max_diff > out->max_diff)
            out->max_diff = r.max_diff;
    }
    return 1;
}
