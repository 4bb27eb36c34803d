/* SPDX-License-Identifier: MIT */
/* Frames under hostile caller state (issue 13 item 19, issue 38 item 3):
 * every state of hostile_cases.c, left set by the caller, must leave the
 * frame's colour and depth (and an exported visibility map) bit-identical
 * to a frame from GL's default state (the same commands on the same
 * driver, so no tolerance), raise no GL error, and read back after the
 * frame as the header's GL STATE says. A case set around stin_create
 * (HOSTILE_CREATE) must read back after it as the caller left it, and the
 * context's later clean frames must equal a clean context's.
 *
 * Per tier, on four-lights: with the tier's own shadow technique each case
 * alone (so a failure names the state); with every other shadow technique
 * the profile runs, all cases at once. On glass-panes and stone-wall
 * (blended draws, surface detail) and on csg/cast.json's product (beside
 * csg.json: under vdsm on GL 4.3 its crossing lists use storage buffers):
 * all cases at once. On the GL4 tier (gl33-core, gl45-core), beside
 * four-lights, on EGL: every technique of the matrix below, each case
 * alone against the technique's one clean frame. */
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
    uint8_t *map; /* the exported visibility map (export runs) */
} frame_pixels;

/* One technique of the GL4 matrix: a scene (beside four-lights.json; the
 * CSG ones draw csg/cast.json's product) with one feature forced. */
typedef struct hostile_setup {
    const char *scene;
    stin_feature feature;
    stin_technique technique;
    stin_export export;
} hostile_setup;

static const hostile_setup matrix[] = {
    {"four-lights.json", STIN_FEATURE_SHADOWS, STIN_TECH_SHADOWS_VDSM, STIN_EXPORT_NONE},
    {"four-lights.json", STIN_FEATURE_SHADOWS, STIN_TECH_SHADOWS_VDSM, STIN_EXPORT_VISIBILITY},
    {"glass-panes.json", STIN_FEATURE_TRANSLUCENT_SHADOWS, STIN_TECH_TRANSLUCENT_DEEP,
     STIN_EXPORT_NONE},
    {"glass-panes.json", STIN_FEATURE_TRANSPARENCY, STIN_TECH_TRANSPARENCY_DEPTH_PEEL,
     STIN_EXPORT_NONE},
    {"glass-panes.json", STIN_FEATURE_TRANSPARENCY, STIN_TECH_TRANSPARENCY_DUAL_PEEL,
     STIN_EXPORT_NONE},
    {"glass-panes.json", STIN_FEATURE_TRANSPARENCY, STIN_TECH_TRANSPARENCY_SORTED,
     STIN_EXPORT_NONE},
    {"displace-tess.json", STIN_FEATURE_DISPLACEMENT, STIN_TECH_DISPLACEMENT_TESS,
     STIN_EXPORT_NONE},
    {"csg/cast.json", STIN_FEATURE_CSG, STIN_TECH_CSG_SCS, STIN_EXPORT_NONE},
    {"csg/cast.json", STIN_FEATURE_CSG, STIN_TECH_CSG_GOLDFEATHER, STIN_EXPORT_NONE},
    {"csg/cast.json", STIN_FEATURE_CSG, STIN_TECH_CSG_INTERVAL, STIN_EXPORT_NONE}};

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
    const hostile_setup *setup;         /* a matrix run's (NULL: the shadow runs') */
    hostile_env env;
    frame_pixels clean, got;
    size_t pixels, map_bytes;
    char failures[1024];
    int failed;
} hostile_run;

static int draw_with(hostile_run *h, stin_context *ctx, const scene_gpu *g)
{
    stin_export ex = h->setup ? h->setup->export : STIN_EXPORT_NONE;
    return scene_gpu_frame_export(g, ctx, VIEW_W, VIEW_H, STIN_OUTPUT_BEAUTY, ex,
                                  stin_platform_framebuffer(h->r->plat)) == STIN_OK;
}

static int draw(hostile_run *h) { return draw_with(h, h->ctx, &h->g); }

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

/* The frame's colour and depth, and an export's map (at most map_bytes). */
static int read_back_of(hostile_run *h, stin_context *ctx, frame_pixels *out)
{
    stin_visibility_map info;
    const caller_gl *gl = h->env.gl;
    if (!stin_platform_read_color(h->r->plat, out->rgba) ||
        !stin_platform_read_depth(h->r->plat, out->depth))
        return 0;
    if (!h->setup || h->setup->export == STIN_EXPORT_NONE)
        return 1;
    if (stin_query_visibility_map(ctx, &info) != STIN_OK ||
        (size_t)info.width * info.height * 4 > h->map_bytes)
        return 0;
    memset(out->map, 0, h->map_bytes);
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindTexture(GL_TEXTURE_2D, info.texture);
    gl->GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out->map);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    return 1;
}

static int read_back(hostile_run *h, frame_pixels *out) { return read_back_of(h, h->ctx, out); }

static long differing(const hostile_run *h)
{
    long n = 0;
    size_t i;
    for (i = 0; i < h->pixels; i++)
        n += memcmp(h->clean.rgba + 4 * i, h->got.rgba + 4 * i, 4) != 0 ||
             h->clean.depth[i] != h->got.depth[i];
    if (h->setup && h->setup->export != STIN_EXPORT_NONE)
        for (i = 0; i < h->map_bytes / 4; i++)
            n += memcmp(h->clean.map + 4 * i, h->got.map + 4 * i, 4) != 0;
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

static int applies_to_frame(const hostile_case *c, const hostile_env *e)
{
    return (c->when & HOSTILE_FRAME) && hostile_applies(c, e);
}

/* One frame with one case set (NULL: all); a failure is noted. */
static void frame_under(hostile_run *h, const hostile_case *only)
{
    size_t i;
    long diff;
    char got[160];
    const caller_gl *gl = h->env.gl;
    GLenum error;
    while (gl->GetError() != GL_NO_ERROR) {
    }
    for (i = 0; i < hostile_case_count; i++)
        if ((!only || only == &hostile_cases[i]) && applies_to_frame(&hostile_cases[i], &h->env))
            hostile_set(&hostile_cases[i], &h->env);
    if (gl->GetError() != GL_NO_ERROR) {
        note_failure(h, "%s: the test could not set the state (GL error); ",
                     only ? only->name : "all");
        return;
    }
    if (!draw(h))
        note_failure(h, "%s: the frame failed; ", only ? only->name : "all");
    error = gl->GetError();
    if (error != GL_NO_ERROR)
        note_failure(h, "%s: a GL error (0x%x pending); ", only ? only->name : "all",
                     (unsigned)error);
    h->env.storage_used = storage_used(h);
    for (i = 0; i < hostile_case_count; i++) {
        const hostile_case *c = &hostile_cases[i];
        if ((only && only != c) || !applies_to_frame(c, &h->env))
            continue;
        got[0] = '\0';
        if (!hostile_after(c, &h->env, got, sizeof got))
            note_failure(h, "%s left %s; ", c->name, got);
    }
    for (i = hostile_case_count; i-- > 0;)
        if ((!only || only == &hostile_cases[i]) && applies_to_frame(&hostile_cases[i], &h->env))
            hostile_reset(&hostile_cases[i], &h->env);
    if (!read_back(h, &h->got)) {
        note_failure(h, "%s: the read-back failed; ", only ? only->name : "all");
        return;
    }
    diff = differing(h);
    if (diff)
        note_failure(h, "%s: %ld pixels differ; ", only ? only->name : "all", diff);
}

static void destroy_context(stin_context **ctx, void **block)
{
    stin_destroy(*ctx);
    free(*block);
    *block = NULL;
    *ctx = NULL;
}

static void destroy(hostile_run *h) { destroy_context(&h->ctx, &h->block); }

/* A context with the run's technique forced (the setup's feature, else
 * `shadows`); 0 when the tier cannot have it (another run covers that). */
static int create_context(hostile_run *h, stin_technique shadows, stin_context **ctx,
                          void **block)
{
    stin_desc d;
    size_t size;
    stin_feature feature = h->setup ? h->setup->feature : STIN_FEATURE_SHADOWS;
    stin_technique want = h->setup ? h->setup->technique : shadows;
    test_desc(h->r, h->tier, &d);
    d.techniques[feature] = want;
    /* frames compare bit for bit, so one technique draws them all: the
     * measured choice would run vdsm and volumes by turns (both have runs
     * of their own below) */
    d.debug_flags |= STIN_DEBUG_SHADOW_CHOICE_OFF;
    scene_gpu_size_desc(h->s, &d);
    size = stin_memory_size(&d);
    *block = malloc(size);
    if (!*block || stin_create(&d, *block, size, ctx) != STIN_OK) {
        free(*block);
        *block = NULL;
        *ctx = NULL;
        return 0;
    }
    if (want != STIN_TECH_NONE && stin_query_choice(*ctx, feature).technique != want) {
        destroy_context(ctx, block); /* fell back: another technique's run covers it */
        return 0;
    }
    return 1;
}

static int create(hostile_run *h, stin_technique shadows)
{
    return create_context(h, shadows, &h->ctx, &h->block);
}

static int scene_objects(hostile_run *h, scene_gpu *g, stin_context *ctx, char *err,
                         size_t size)
{
    if (!scene_gpu_create(g, h->s, ctx, err, size))
        return 0;
    if (h->products) {
        g->csg = h->products->products;
        g->csg_count = h->products->count;
    }
    return 1;
}

/* Case c set around stin_create, its meshes and its first two frames, then
 * taken away: it must read back after stin_create as the caller left it,
 * and the next frame must equal the clean context's. */
static void create_under(hostile_run *h, const hostile_case *c)
{
    stin_context *ctx = NULL;
    void *block = NULL;
    scene_gpu g;
    char got[160], err[256];
    const caller_gl *gl = h->env.gl;
    int made;
    while (gl->GetError() != GL_NO_ERROR) {
    }
    hostile_set(c, &h->env);
    made = create_context(h, STIN_TECH_NONE, &ctx, &block);
    got[0] = '\0';
    if (made && !hostile_after_create(c, &h->env, got, sizeof got))
        note_failure(h, "%s at stin_create left %s; ", c->name, got);
    if (made && gl->GetError() != GL_NO_ERROR)
        note_failure(h, "%s: a GL error after stin_create; ", c->name);
    if (made && !scene_objects(h, &g, ctx, err, sizeof err)) {
        note_failure(h, "%s: %s; ", c->name, err);
        destroy_context(&ctx, &block);
        made = 0;
    }
    if (made) {
        if (!draw_with(h, ctx, &g) || !draw_with(h, ctx, &g))
            note_failure(h, "%s: a first frame failed; ", c->name);
    }
    hostile_reset(c, &h->env);
    if (!made) {
        note_failure(h, "%s: stin_create failed under it; ", c->name);
        return;
    }
    if (!draw_with(h, ctx, &g) || !read_back_of(h, ctx, &h->got)) {
        note_failure(h, "%s: the clean frame after it failed; ", c->name);
    } else {
        long diff = differing(h);
        if (diff)
            note_failure(h, "%s at stin_create: %ld pixels of a later clean frame differ; ",
                         c->name, diff);
    }
    scene_gpu_destroy(&g, ctx);
    destroy_context(&ctx, &block);
}

static void run_label(const hostile_run *h, char *name, size_t size)
{
    const stin_choice c = stin_query_choice(
        h->ctx, h->setup ? h->setup->feature : STIN_FEATURE_SHADOWS);
    snprintf(name, size, "%s/%s/hostile-%s%s", stin_tier_name(h->tier), h->scene_name,
             stin_technique_name(c.technique),
             h->setup && h->setup->export != STIN_EXPORT_NONE ? "-export" : "");
}

static void run_technique(hostile_run *h, stin_technique shadows, int one_by_one)
{
    char name[160], err[256];
    size_t i;
    stin_debug_counters k;
    const stin_caps *caps;
    int cases = 0;
    if (h->setup && h->setup->feature == STIN_FEATURE_SHADOWS &&
        h->setup->technique == h->chosen_default && h->setup->export == STIN_EXPORT_NONE)
        return; /* the tier's own shadow technique: run case by case above */
    if (!create(h, shadows)) { /* not a technique of this tier and profile */
        if (h->setup)
            report(h->r, "SKIP", "hostile", "%s: the context cannot run %s", h->scene_name,
                   stin_technique_name(h->setup->technique));
        return;
    }
    if (!h->setup && shadows == STIN_TECH_NONE) {
        h->chosen_default = stin_query_choice(h->ctx, STIN_FEATURE_SHADOWS).technique;
    } else if (!h->setup && shadows == h->chosen_default) {
        destroy(h); /* run above */
        return;
    }
    run_label(h, name, sizeof name);
    if (!scene_objects(h, &h->g, h->ctx, err, sizeof err)) {
        report(h->r, "FAIL", name, "%s", err);
        destroy(h);
        return;
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
                if (applies_to_frame(&hostile_cases[i], &h->env))
                    frame_under(h, &hostile_cases[i]);
        } else {
            frame_under(h, NULL);
        }
        k = stin_debug_query_counters(h->ctx);
        if (k.gl_violations)
            note_failure(h, "%u calls outside the profile; ", k.gl_violations);
        for (i = 0; one_by_one && i < hostile_case_count; i++)
            if ((hostile_cases[i].when & HOSTILE_CREATE) &&
                hostile_applies(&hostile_cases[i], &h->env))
                create_under(h, &hostile_cases[i]);
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

/* The extensions that bring a case's state to an older version. */
static void env_extensions(hostile_run *h)
{
    h->env.ext_query_buffer = stin_query_extension(h->ctx, "GL_ARB_query_buffer_object");
    h->env.ext_pipeline = stin_query_extension(h->ctx, "GL_ARB_separate_shader_objects");
    h->env.ext_clamp = stin_query_extension(h->ctx, "GL_ARB_color_buffer_float");
    h->env.ext_provoking = stin_query_extension(h->ctx, "GL_ARB_provoking_vertex") ||
                           stin_query_extension(h->ctx, "GL_EXT_provoking_vertex");
}

/* The matrix's run of one setup: its scene (and product) loaded beside `dir`. */
static void run_setup(hostile_run *h, const hostile_setup *setup, const char *dir, int dir_len)
{
    char path[512], err[256];
    scene s;
    scene_csg_products products;
    int csg = setup->feature == STIN_FEATURE_CSG;
    snprintf(path, sizeof path, "%.*s%s", dir_len, dir, setup->scene);
    memset(&products, 0, sizeof products);
    if (!scene_load(path, &s, err, sizeof err)) {
        report(h->r, "FAIL", "hostile", "%s", err);
        return;
    }
    if (csg && !scene_csg_products_build(&s, &products)) {
        report(h->r, "FAIL", "hostile", "%s: out of memory", setup->scene);
        scene_free(&s);
        return;
    }
    h->s = &s;
    h->products = csg ? &products : NULL;
    h->setup = setup;
    h->scene_name = csg ? "csg-cast" : scene_base_name(path);
    run_technique(h, STIN_TECH_NONE, 1);
    h->setup = NULL;
    h->products = NULL;
    h->s = NULL;
    scene_csg_products_free(&products);
    scene_free(&s);
}

void hostile_tests(run *r, stin_tier tier, const char *path)
{
    static const stin_technique others[] = {
        STIN_TECH_SHADOWS_OFF,       STIN_TECH_SHADOWS_VOLUME,    STIN_TECH_SHADOWS_MAP_DEPTH,
        STIN_TECH_SHADOWS_MAP_COMBINE, STIN_TECH_SHADOWS_MAP_PCF, STIN_TECH_SHADOWS_VDSM};
    const char *base = scene_base_name(path), *slash = strrchr(path, '/');
    int all = !strcmp(base, "four-lights"), csg = !strcmp(base, "csg");
    int dir_len = slash ? (int)(slash - path + 1) : 0;
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
    snprintf(cast, sizeof cast, "%.*scsg/cast.json", dir_len, path);
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
    h.map_bytes = n * 16; /* four lights' tiles of the frame's size at most */
    colors = calloc((size_t)COLOR_VERTICES * 4, sizeof *colors);
    h.clean.rgba = malloc(n * 4);
    h.got.rgba = malloc(n * 4);
    h.clean.depth = malloc(n * sizeof(float));
    h.got.depth = malloc(n * sizeof(float));
    h.clean.map = malloc(h.map_bytes);
    h.got.map = malloc(h.map_bytes);
    if (colors && h.clean.rgba && h.got.rgba && h.clean.depth && h.got.depth && h.clean.map &&
        h.got.map) {
        for (i = 0; i < (size_t)COLOR_VERTICES * 4; i++)
            colors[i] = (i & 3) == 0 || (i & 3) == 3 ? 1.0f : 0.0f;
        h.env.colors = colors;
        h.env.version = 11;
        h.env.es = r->profile->es;
        if (create(&h, STIN_TECH_NONE)) { /* the context's version decides the objects */
            const stin_caps *c = stin_query_caps(h.ctx);
            h.env.version = c->gl_major * 10 + c->gl_minor;
            env_extensions(&h);
            destroy(&h);
        }
        hostile_objects_make(&h.env, caller_gl_dialect(r->profile));
        run_technique(&h, STIN_TECH_NONE, all);
        for (i = 0; all && i < sizeof others / sizeof others[0]; i++)
            run_technique(&h, others[i], 0);
        /* The matrix on EGL only: the state it sets is the GL context's,
         * which Mesa keeps in the same code under both platforms (the runs
         * above cover both); it holds the suite's time (make check). Not on
         * ES: its techniques' states are the desktop matrix's, and it would
         * add a minute to es32's suite. */
        for (i = 0; all && tier == STIN_TIER_GL4 && !r->profile->es &&
                    !strcmp(r->platform_name, "egl") &&
                    i < sizeof matrix / sizeof matrix[0];
             i++)
            run_setup(&h, &matrix[i], path, dir_len);
        hostile_objects_free(&h.env);
    }
    free(colors);
    free(h.clean.rgba);
    free(h.got.rgba);
    free(h.clean.depth);
    free(h.got.depth);
    free(h.clean.map);
    free(h.got.map);
    scene_csg_products_free(&products);
    scene_free(&s);
}
