/* SPDX-License-Identifier: MIT */
/* Frames under hostile caller state (issue 13 item 19): every state of
 * hostile_cases.c, left set by the caller, must leave the frame's colour
 * and depth bit-identical to a frame from GL's default state (the same
 * commands on the same driver, so no tolerance), and must read back after
 * the frame as the header's GL STATE says.
 *
 * Per tier, on four-lights: with the tier's own shadow technique each case
 * alone (so a failure names the state); with every other shadow technique
 * the profile runs, all cases at once. On glass-panes and stone-wall
 * (blended draws, surface detail) and on csg/cast.json's product (beside
 * csg.json: under vdsm on GL 4.3 its crossing lists use storage buffers):
 * all cases at once. */
#include "hostile_cases.h"
#include "image_test.h"
#include "test_context.h"
#include "scene.h"
#include "scene_csg.h"
#include "scene_gpu.h"
#include "stin/stin_debug.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Frames draw into a corner: the clear still covers the whole buffer. */
#define VIEW_W 128
#define VIEW_H 96
#define COLOR_VERTICES (1 << 18)

typedef struct frame_pixels {
    uint8_t *rgba;
    float *depth;
} frame_pixels;

typedef struct hostile_run {
    run *r;
    const scene *s;
    const char *scene_name;
    stin_tier tier;
    stin_context *ctx;
    void *block;
    stin_technique chosen_default; /* the tier's own shadow technique */
    scene_gpu g;
    const scene_csg_products *products; /* drawn as products (NULL: none) */
    hostile_env env;
    frame_pixels clean, got;
    size_t pixels;
    char failures[768];
    int failed;
} hostile_run;

/* The caller's objects the cases bind: a red texture, a program, a sampler. */
static void make_objects(hostile_env *e, const caller_gl *gl, int core)
{
    static const GLubyte texel[4] = {255, 0, 0, 255};
    gl->GenTextures(1, &e->texture);
    gl->BindTexture(GL_TEXTURE_2D, e->texture);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    if (e->version >= 20)
        e->program = caller_gl_flat_program(gl, core, 1.0f, 0.0f, 0.0f);
    if (e->version >= 43 && gl->GenBuffers && gl->BindBufferBase && gl->GetIntegeri_v) {
        gl->GenBuffers(1, &e->storage);
        gl->BindBuffer(GL_SHADER_STORAGE_BUFFER, e->storage);
        gl->BufferData(GL_SHADER_STORAGE_BUFFER, 64, NULL, GL_DYNAMIC_DRAW);
        gl->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    }
    if (e->version >= 33 && gl->GenSamplers) {
        gl->GenSamplers(1, &e->sampler);
        gl->SamplerParameteri(e->sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl->SamplerParameteri(e->sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl->SamplerParameteri(e->sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl->SamplerParameteri(e->sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    while (gl->GetError() != GL_NO_ERROR) {
    }
}

static void free_objects(hostile_env *e, const caller_gl *gl)
{
    gl->DeleteTextures(1, &e->texture);
    if (e->program)
        gl->DeleteProgram(e->program);
    if (e->sampler)
        gl->DeleteSamplers(1, &e->sampler);
    if (e->storage)
        gl->DeleteBuffers(1, &e->storage);
}

static int draw(hostile_run *h)
{
    return scene_gpu_frame(&h->g, h->ctx, VIEW_W, VIEW_H, STIN_OUTPUT_BEAUTY,
                           stin_platform_framebuffer(h->r->plat)) == STIN_OK;
}

/* Read back with the caller's state undone: pixel transfer and the like
 * apply to the test's own glReadPixels. */
/* The storage-buffer bindings the frame's techniques used (stin.h GL
 * STATE): deep's early-stop flag on GL 4.3 (point 0), vdsm's CSG lists
 * (points 0-2) and receivers (point 0), each through the generic binding
 * too. */
static unsigned storage_used(const hostile_run *h)
{
    stin_frame_stats st = stin_query_frame_stats(h->ctx);
    const stin_caps *caps = stin_query_caps(h->ctx);
    unsigned used = 0;
    if (st.translucent.deep_faces && (caps->present & STIN_CAP_BIT(STIN_CAP_COMPUTE)))
        used |= 1u | 8u;
    if (st.shadows.vdsm_csg_casts)
        used |= 7u | 8u;
    if (st.shadows.vdsm_atomic_receivers)
        used |= 1u | 8u;
    return used;
}

static int read_back(hostile_run *h, frame_pixels *out)
{
    return stin_platform_read_color(h->r->plat, out->rgba) &&
           stin_platform_read_depth(h->r->plat, out->depth);
}

static long differing(const hostile_run *h)
{
    long n = 0;
    size_t i;
    for (i = 0; i < h->pixels; i++)
        n += memcmp(h->clean.rgba + 4 * i, h->got.rgba + 4 * i, 4) != 0 ||
             h->clean.depth[i] != h->got.depth[i];
    return n;
}

static void note_failure(hostile_run *h, const char *fmt, ...)
{
    size_t len = strlen(h->failures);
    va_list ap;
    va_start(ap, fmt);
    if (len + 8 < sizeof h->failures)
        vsnprintf(h->failures + len, sizeof h->failures - len, fmt, ap);
    va_end(ap);
    h->failed++;
}

/* One frame with cases [first, last) set; 1 if it matched and the state
 * read back as documented. */
static void frame_under(hostile_run *h, const hostile_case *only)
{
    size_t i;
    long diff;
    char got[160];
    const caller_gl *gl = h->env.gl;
    while (gl->GetError() != GL_NO_ERROR) {
    }
    for (i = 0; i < hostile_case_count; i++)
        if ((!only || only == &hostile_cases[i]) && hostile_applies(&hostile_cases[i], &h->env))
            hostile_set(&hostile_cases[i], &h->env);
    if (gl->GetError() != GL_NO_ERROR) {
        note_failure(h, "%s: the test could not set the state (GL error); ",
                     only ? only->name : "all");
        return;
    }
    if (!draw(h))
        note_failure(h, "%s: the frame failed; ", only ? only->name : "all");
    h->env.storage_used = storage_used(h);
    for (i = 0; i < hostile_case_count; i++) {
        const hostile_case *c = &hostile_cases[i];
        if ((only && only != c) || !hostile_applies(c, &h->env))
            continue;
        got[0] = '\0';
        if (!hostile_after(c, &h->env, got, sizeof got))
            note_failure(h, "%s left %s; ", c->name, got);
    }
    for (i = hostile_case_count; i-- > 0;)
        if ((!only || only == &hostile_cases[i]) && hostile_applies(&hostile_cases[i], &h->env))
            hostile_reset(&hostile_cases[i], &h->env);
    if (!read_back(h, &h->got)) {
        note_failure(h, "%s: the read-back failed; ", only ? only->name : "all");
        return;
    }
    diff = differing(h);
    if (diff)
        note_failure(h, "%s: %ld pixels differ; ", only ? only->name : "all", diff);
}

static void destroy(hostile_run *h)
{
    stin_destroy(h->ctx);
    free(h->block);
    h->block = NULL;
    h->ctx = NULL;
}

static int create(hostile_run *h, stin_technique shadows)
{
    stin_desc d;
    size_t size;
    test_desc(h->r, h->tier, &d);
    d.techniques[STIN_FEATURE_SHADOWS] = shadows;
    /* frames compare bit for bit, so one technique draws them all: the
     * measured choice would run vdsm and volumes by turns (both have runs
     * of their own below) */
    d.debug_flags |= STIN_DEBUG_SHADOW_CHOICE_OFF;
    scene_gpu_size_desc(h->s, &d);
    size = stin_memory_size(&d);
    h->block = malloc(size);
    if (!h->block || stin_create(&d, h->block, size, &h->ctx) != STIN_OK) {
        free(h->block);
        h->block = NULL;
        h->ctx = NULL;
        return 0;
    }
    if (shadows != STIN_TECH_NONE &&
        stin_query_choice(h->ctx, STIN_FEATURE_SHADOWS).technique != shadows) {
        destroy(h); /* fell back: another technique's run covers it */
        return 0;
    }
    return 1;
}

static void run_technique(hostile_run *h, stin_technique shadows, int one_by_one)
{
    char name[160], err[256];
    size_t i;
    stin_debug_counters k;
    const stin_caps *caps;
    int cases = 0;
    if (!create(h, shadows))
        return; /* not a technique of this tier and profile */
    if (shadows == STIN_TECH_NONE) {
        h->chosen_default = stin_query_choice(h->ctx, STIN_FEATURE_SHADOWS).technique;
    } else if (shadows == h->chosen_default) {
        destroy(h); /* run above */
        return;
    }
    snprintf(name, sizeof name, "%s/%s/hostile-%s", stin_tier_name(h->tier), h->scene_name,
             stin_technique_name(stin_query_choice(h->ctx, STIN_FEATURE_SHADOWS).technique));
    if (!scene_gpu_create(&h->g, h->s, h->ctx, err, sizeof err)) {
        report(h->r, "FAIL", name, "%s", err);
        destroy(h);
        return;
    }
    if (h->products) {
        h->g.csg = h->products->products;
        h->g.csg_count = h->products->count;
    }
    caps = stin_query_caps(h->ctx);
    h->env.version = caps->gl_major * 10 + caps->gl_minor;
    h->env.compat = (caps->present & STIN_CAP_BIT(STIN_CAP_FIXED_FUNCTION)) != 0;
    /* a GL 1.1 caller has one unit, whatever the emulating driver has */
    h->env.fixed_units = caps->present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE)
                             ? caps->max_texture_units
                             : 1;
    h->env.gl1 = stin_query_tier(h->ctx) == STIN_TIER_GL1;
    h->failures[0] = '\0';
    h->failed = 0;
    for (i = 0; i < hostile_case_count; i++)
        cases += hostile_applies(&hostile_cases[i], &h->env);
    /* the second clean frame is the reference: the first may set up caches */
    if (!draw(h) || !draw(h) || !read_back(h, &h->clean)) {
        report(h->r, "FAIL", name, "the clean frame failed");
    } else {
        if (one_by_one) {
            for (i = 0; i < hostile_case_count; i++)
                if (hostile_applies(&hostile_cases[i], &h->env))
                    frame_under(h, &hostile_cases[i]);
        } else {
            frame_under(h, NULL);
        }
        k = stin_debug_query_counters(h->ctx);
        if (k.gl_violations)
            note_failure(h, "%u calls outside the profile; ", k.gl_violations);
        if (h->failed)
            report(h->r, "FAIL", name, "%s", h->failures);
        else
            report(h->r, "PASS", name,
                   "%d caller states %s: colour and depth identical to the clean frame, "
                   "state after the frame as documented",
                   cases, one_by_one ? "one at a time" : "all at once");
    }
    scene_gpu_destroy(&h->g, h->ctx);
    destroy(h);
}

void hostile_tests(run *r, stin_tier tier, const char *path)
{
    static const stin_technique others[] = {
        STIN_TECH_SHADOWS_OFF,       STIN_TECH_SHADOWS_VOLUME,    STIN_TECH_SHADOWS_MAP_DEPTH,
        STIN_TECH_SHADOWS_MAP_COMBINE, STIN_TECH_SHADOWS_MAP_PCF, STIN_TECH_SHADOWS_VDSM};
    const char *base = scene_base_name(path), *slash = strrchr(path, '/');
    int all = !strcmp(base, "four-lights"), csg = !strcmp(base, "csg");
    hostile_run h;
    scene s;
    scene_csg_products products;
    caller_gl gl;
    char err[256], cast[512];
    size_t i, n = (size_t)r->width * r->height;
    float *colors;
    if (!all && !csg && strcmp(base, "glass-panes") && strcmp(base, "stone-wall"))
        return;
    memset(&h, 0, sizeof h);
    memset(&products, 0, sizeof products);
    h.r = r;
    h.tier = tier;
    h.scene_name = csg ? "csg-cast" : base;
    snprintf(cast, sizeof cast, "%.*scsg/cast.json", slash ? (int)(slash - path + 1) : 0, path);
    if (!scene_load(csg ? cast : path, &s, err, sizeof err)) {
        report(r, "FAIL", "hostile", "%s", err);
        return;
    }
    if (csg && !scene_csg_products_build(&s, &products)) {
        report(r, "FAIL", "hostile", "csg/cast.json: out of memory");
        scene_free(&s);
        return;
    }
    h.products = csg ? &products : NULL;
    h.s = &s;
    caller_gl_load(&gl, r->plat);
    h.env.gl = &gl;
    h.env.width = r->width;
    h.env.height = r->height;
    h.pixels = n;
    colors = calloc((size_t)COLOR_VERTICES * 4, sizeof *colors);
    h.clean.rgba = malloc(n * 4);
    h.got.rgba = malloc(n * 4);
    h.clean.depth = malloc(n * sizeof(float));
    h.got.depth = malloc(n * sizeof(float));
    if (colors && h.clean.rgba && h.got.rgba && h.clean.depth && h.got.depth) {
        for (i = 0; i < (size_t)COLOR_VERTICES * 4; i++)
            colors[i] = (i & 3) == 0 || (i & 3) == 3 ? 1.0f : 0.0f;
        h.env.colors = colors;
        h.env.version = 11;
        if (create(&h, STIN_TECH_NONE)) { /* the context's version decides the objects */
            const stin_caps *c = stin_query_caps(h.ctx);
            h.env.version = c->gl_major * 10 + c->gl_minor;
            destroy(&h);
        }
        make_objects(&h.env, &gl, r->profile->core);
        run_technique(&h, STIN_TECH_NONE, all);
        for (i = 0; all && i < sizeof others / sizeof others[0]; i++)
            run_technique(&h, others[i], 0);
        free_objects(&h.env, &gl);
    }
    free(colors);
    free(h.clean.rgba);
    free(h.got.rgba);
    free(h.clean.depth);
    free(h.got.depth);
    scene_csg_products_free(&products);
    scene_free(&s);
}
