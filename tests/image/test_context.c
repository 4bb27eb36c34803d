/* SPDX-License-Identifier: MIT */
#include "test_context.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void test_desc(const run *r, stin_tier tier, stin_desc *d)
{
    memset(d, 0, sizeof *d);
    d->get_proc_address = stin_platform_get_proc_address;
    d->get_proc_user = r->plat;
    d->tier = tier;
    d->caps_mask = r->profile->caps_mask;
    d->max_gl_version = r->profile->max_gl_version;
}

/* The context and the scene's meshes; translucent: a forced technique of
 * translucent shadows (STIN_TECH_NONE: the tier's choice), held as shadows
 * is with `exact`. */
static int create(test_context *t, const run *r, const scene *s, stin_tier tier,
                  stin_technique shadows, stin_technique translucent, int exact,
                  uint64_t debug_flags)
{
    stin_desc d;
    size_t size;
    char err[256];
    memset(t, 0, sizeof *t);
    test_desc(r, tier, &d);
    d.techniques[STIN_FEATURE_SHADOWS] = shadows;
    d.techniques[STIN_FEATURE_TRANSLUCENT_SHADOWS] = translucent;
    d.debug_flags = debug_flags;
    scene_gpu_size_desc(s, &d);
    size = stin_memory_size(&d);
    t->block = malloc(size);
    if (!t->block || stin_create(&d, t->block, size, &t->ctx) != STIN_OK) {
        free(t->block);
        memset(t, 0, sizeof *t);
        return 0;
    }
    if ((exact && shadows != STIN_TECH_NONE &&
         stin_query_choice(t->ctx, STIN_FEATURE_SHADOWS).technique != shadows) ||
        (exact && translucent != STIN_TECH_NONE &&
         stin_query_choice(t->ctx, STIN_FEATURE_TRANSLUCENT_SHADOWS).technique != translucent) ||
        !scene_gpu_create(&t->g, s, t->ctx, err, sizeof err)) {
        stin_destroy(t->ctx);
        free(t->block);
        memset(t, 0, sizeof *t);
        return 0;
    }
    return 1;
}

int test_context_create(test_context *t, const run *r, const scene *s, stin_tier tier,
                        stin_technique shadows, int exact)
{
    return create(t, r, s, tier, shadows, STIN_TECH_NONE, exact, 0);
}

int test_context_create_debug(test_context *t, const run *r, const scene *s, stin_tier tier,
                              stin_technique shadows, int exact, uint64_t debug_flags)
{
    return create(t, r, s, tier, shadows, STIN_TECH_NONE, exact, debug_flags);
}

int test_context_create_translucent(test_context *t, const run *r, const scene *s,
                                    stin_tier tier, stin_technique shadows,
                                    stin_technique translucent)
{
    return create(t, r, s, tier, shadows, translucent, 1, 0);
}

void test_context_destroy(test_context *t)
{
    if (!t->ctx)
        return;
    scene_gpu_destroy(&t->g, t->ctx);
    stin_destroy(t->ctx);
    free(t->block);
    memset(t, 0, sizeof *t);
}

typedef struct refusal_log {
    char *why;
    size_t size;
} refusal_log;

static void keep_error(void *user, stin_log_level level, stin_log_item item, const char *msg)
{
    refusal_log *l = user;
    (void)item;
    if (level == STIN_LOG_LEVEL_ERROR)
        snprintf(l->why, l->size, "%s", msg);
}

int technique_refused(const run *r, stin_tier tier, stin_feature feature, stin_technique want,
                      char *why, size_t why_size)
{
    refusal_log l;
    stin_context *ctx = NULL;
    stin_result res;
    stin_desc d;
    void *block;
    size_t size;
    l.why = why;
    l.size = why_size;
    snprintf(why, why_size, "out of memory");
    test_desc(r, tier, &d);
    d.techniques[feature] = want;
    d.log = keep_error;
    d.log_user = &l;
    size = stin_memory_size(&d);
    block = malloc(size);
    res = block ? stin_create(&d, block, size, &ctx) : STIN_ERROR_OUT_OF_MEMORY;
    if (ctx)
        stin_destroy(ctx);
    free(block);
    return res == STIN_ERROR_UNSUPPORTED;
}

void test_frame_desc(const run *r, const scene *s, stin_frame_desc *fd)
{
    memset(fd, 0, sizeof *fd);
    scene_camera_matrices(&s->camera, r->width, r->height, fd->view, fd->projection);
    fd->viewport[2] = r->width;
    fd->viewport[3] = r->height;
    fd->framebuffer = stin_platform_framebuffer(r->plat);
    memcpy(fd->ambient, s->ambient, sizeof fd->ambient);
}

static stin_result add_light(test_context *t, const scene *s, int i)
{
    stin_light_desc l;
    scene_gpu_light(&s->lights[i], &l);
    return stin_add_light(t->ctx, &l);
}

stin_result test_context_frame(test_context *t, const scene *s, const stin_frame_desc *fd,
                               int first)
{
    stin_result res = stin_begin_frame(t->ctx, fd);
    int i;
    if (res != STIN_OK)
        return res;
    if (first >= 0 && first < s->light_count)
        res = add_light(t, s, first);
    for (i = 0; i < s->light_count && res == STIN_OK; i++)
        if (i != first)
            res = add_light(t, s, i);
    for (i = 0; i < s->object_count && res == STIN_OK; i++)
        res = stin_draw(t->ctx, t->g.meshes[s->objects[i].mesh], s->objects[i].transform,
                        &t->g.materials[s->objects[i].material]);
    if (res != STIN_OK) {
        stin_end_frame(t->ctx);
        return res;
    }
    return stin_end_frame(t->ctx);
}

int capture_forced(run *r, const scene *s, const capture_options *o, stin_feature feature,
                   stin_technique want, capture *out, const char *name)
{
    char err[512];
    if (!capture_render(r->plat, r->profile, s, o, out, err, sizeof err)) {
        report(r, strstr(err, " needs ") ? "SKIP" : "FAIL", name, "render failed: %s", err);
        return 0;
    }
    if (want && out->choice[feature].technique != want) {
        report(r, "SKIP", name, "%s does not run here (%s)", stin_technique_name(want),
               out->choice[feature].reason);
        capture_free(out);
        return 0;
    }
    return 1;
}

int test_context_forced(test_context *t, run *r, const scene *s, const capture_options *o,
                        stin_feature feature, stin_technique want, capture *log,
                        const char *name)
{
    stin_desc d;
    size_t size;
    char err[512];
    memset(t, 0, sizeof *t);
    memset(log, 0, sizeof *log);
    capture_desc(r->plat, r->profile, s, o, log, &d);
    size = stin_memory_size(&d);
    t->block = malloc(size);
    if (!t->block || stin_create(&d, t->block, size, &t->ctx) != STIN_OK) {
        snprintf(err, sizeof err, "stin_create: %.*s", (int)sizeof err - 14, log->last_error);
        report(r, strstr(err, " needs ") ? "SKIP" : "FAIL", name, "render failed: %s", err);
        free(t->block);
        memset(t, 0, sizeof *t);
        return 0;
    }
    if (!scene_gpu_create(&t->g, s, t->ctx, err, sizeof err)) {
        report(r, "FAIL", name, "render failed: %s", err);
        stin_destroy(t->ctx);
        free(t->block);
        memset(t, 0, sizeof *t);
        return 0;
    }
    t->g.csg = o->csg;
    t->g.csg_count = o->csg_count;
    if (want && stin_query_choice(t->ctx, feature).technique != want) {
        report(r, "SKIP", name, "%s does not run here (%s)", stin_technique_name(want),
               stin_query_choice(t->ctx, feature).reason);
        test_context_destroy(t);
        return 0;
    }
    return 1;
}
