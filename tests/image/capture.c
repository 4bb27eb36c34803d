/* SPDX-License-Identifier: MIT */
/* A stin context per render, sized to the scene, torn down afterwards. */
#include "capture.h"
#include "aov.h"
#include "capture_cache.h"
#include "image_test.h"
#include "scene_gpu.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void capture_log_fn(void *user, stin_log_level level, stin_log_item item, const char *msg)
{
    capture *c = (capture *)user;
    if (item == STIN_LOG_FALLBACK) {
        size_t used = strlen(c->fallbacks);
        c->log_fallbacks++;
        snprintf(c->fallbacks + used, sizeof c->fallbacks - used, "%s\n", msg);
    }
    if (level != STIN_LOG_LEVEL_ERROR)
        return;
    c->log_errors++;
    snprintf(c->last_error, sizeof c->last_error, "%s", msg);
}

void capture_desc(stin_platform *plat, const stin_profile *profile, const scene *s,
                  const capture_options *o, capture *log_into, stin_desc *d)
{
    memset(d, 0, sizeof *d);
    d->get_proc_address = stin_platform_get_proc_address;
    d->get_proc_user = plat;
    d->log = capture_log_fn;
    d->log_user = log_into;
    d->tier = o->tier;
    d->caps_mask = profile->caps_mask | o->extra_mask;
    d->max_gl_version = profile->max_gl_version;
    d->techniques[STIN_FEATURE_SHADOWS] = o->shadows;
    d->techniques[STIN_FEATURE_SURFACE] = o->surface;
    d->techniques[STIN_FEATURE_DISPLACEMENT] = o->displacement;
    d->techniques[STIN_FEATURE_CSG] = o->csg_technique;
    d->displacement.guard_band = o->guard_band;
    d->displacement.tess_pixels = o->tess_pixels;
    d->techniques[STIN_FEATURE_TRANSLUCENT_SHADOWS] =
        o->translucent != STIN_TECH_NONE ? o->translucent : STIN_TECH_TRANSLUCENT_SOLID;
    d->translucent.deep_layers = o->deep_layers;
    d->translucent.deep_map_size = o->deep_map_size;
    d->translucent.deep_mono = o->deep_mono;
    d->translucent.opaque_threshold = o->opaque_threshold;
    d->debug_flags = o->debug_flags;
    d->shadows.map_size = o->shadow_map_size;
    scene_gpu_size_desc(s, d);
    if (o->csg_capacity)
        d->csg.max_primitives = d->csg.max_terms = d->csg.max_literals = o->csg_capacity;
}

/* capture_options.visibility_only: the visibility frame, its depth for P
 * and the background (the beauty frame's, for a full capture). */
static int visibility_frame(const scene_gpu *g, stin_context *ctx, stin_platform *p, image *img,
                            char *err, size_t err_size)
{
    int w = stin_platform_width(p), h = stin_platform_height(p), ok = 0;
    size_t n = (size_t)w * h;
    uint8_t *zero = calloc(n, 4), *vis = malloc(n * 4);
    float *depth = malloc(n * sizeof(float));
    float view[16], proj[16];
    stin_result r;
    if (!zero || !vis || !depth) {
        snprintf(err, err_size, "out of memory");
        goto done;
    }
    r = scene_gpu_frame(g, ctx, w, h, STIN_OUTPUT_VISIBILITY, stin_platform_framebuffer(p));
    if (r != STIN_OK) {
        snprintf(err, err_size, "frame failed: %s", stin_result_name(r));
        goto done;
    }
    scene_camera_matrices(&g->src->camera, w, h, view, proj);
    stin_query_frame_projection(ctx, proj);
    if (!stin_platform_read_data(p, vis) || !stin_platform_read_depth(p, depth)) {
        snprintf(err, err_size, "read-back failed");
        goto done;
    }
    ok = aov_assemble(w, h, zero, zero, vis, depth, view, proj, g->src->camera.eye, img, err,
                      err_size);
done:
    free(zero);
    free(vis);
    free(depth);
    return ok;
}

int capture_render(stin_platform *plat, const stin_profile *profile, const scene *s,
                   const capture_options *o, capture *out, char *err, size_t err_size)
{
    stin_desc d;
    stin_context *ctx = NULL;
    scene_gpu g;
    void *block;
    size_t size;
    int ok = 0, have_gpu = 0, keyed;
    capture_key key;
    memset(out, 0, sizeof *out);
    keyed = capture_cache_key(plat, profile, s, o, &key);
    if (keyed && capture_cache_find(&key, out))
        return 1;
    memset(out, 0, sizeof *out);
    capture_desc(plat, profile, s, o, out, &d);
    size = stin_memory_size(&d);
    block = malloc(size);
    if (!block || stin_create(&d, block, size, &ctx) != STIN_OK) {
        /* stin's own error line names stin_create already */
        snprintf(err, err_size, "%s%s",
                 strncmp(out->last_error, "stin_create:", 12) ? "stin_create: " : "",
                 out->last_error);
        goto done;
    }
    out->caps_present = stin_query_caps(ctx)->present;
    {
        int f;
        for (f = 0; f < STIN_FEATURE_COUNT; f++)
            out->choice[f] = stin_query_choice(ctx, (stin_feature)f);
    }
    out->separate_specular = (out->caps_present & STIN_CAP_BIT(STIN_CAP_SEPARATE_SPECULAR)) != 0;
    if (!scene_gpu_create(&g, s, ctx, err, err_size))
        goto done;
    have_gpu = 1;
    g.csg = o->csg;
    g.csg_count = o->csg_count;
    if (o->visibility_only ? !visibility_frame(&g, ctx, plat, &out->img, err, err_size)
                           : !aov_capture(&g, ctx, plat, &out->img, NULL, NULL, err, err_size))
        goto done;
    out->counters = stin_debug_query_counters(ctx);
    out->stats = stin_query_frame_stats(ctx);
    ok = 1;
    if (keyed)
        capture_cache_keep(&key, out);
done:
    if (have_gpu)
        scene_gpu_destroy(&g, ctx);
    if (ctx)
        stin_destroy(ctx);
    free(block);
    return ok;
}

void capture_free(capture *c) { image_free(&c->img); }

void capture_report_clean(struct run *r, const char *name, const capture *cap)
{
    if (cap->counters.gl_violations || cap->log_errors)
        report(r, "FAIL", name, "%u profile violations, %u error logs (last: %s)",
               cap->counters.gl_violations, cap->log_errors, cap->last_error);
    else
        report(r, "PASS", name, "no error logged, no call outside the profile");
}

int capture_csg_gpu_alone(const capture *cap)
{
    return strstr(cap->fallbacks, "products resolve on the GPU alone") != NULL;
}

int capture_report_gpu_alone(struct run *r, const char *name, const capture *cap,
                             const char *what)
{
    if (!capture_csg_gpu_alone(cap))
        return 0;
    if (strncmp(r->profile_name, "es", 2) == 0)
        report(r, "SKIP", name, "%s: the products resolve on the GPU alone here (no depth "
               "read-back on this OpenGL ES context)", what);
    else
        report(r, "FAIL", name, "the products resolve on the GPU alone on a desktop context");
    return 1;
}
