/* SPDX-License-Identifier: MIT */
/* The shadow-volume section of stin-bench.
 *
 * Per set-up two stin contexts are created on the one GL context, both forced
 * to the tier: one with desc.techniques[STIN_FEATURE_SHADOWS] = volume, one
 * with off, each with its own copy of the scene's meshes. For each light
 * count N the scene's light list is replaced (in a copy of the scene struct)
 * by N copies of its first light moved around a circle above the scene, each
 * with intensity / N, and both contexts draw that scene:
 *
 * 1. full size: whole frames (scene_gpu_frame + glFinish), shadowed and
 *    unshadowed in ABBA order, as the main tables do;
 * 2. a small viewport (64x36, in the same framebuffer), where the fill cost is
 *    next to nothing: the wall time of stin_end_frame alone (no glFinish in
 *    it; glFinish follows, untimed), ABBA again. stin hands its GL calls to
 *    the driver through the get_proc_address it was given; this section's
 *    contexts get bench_shadow_get_proc, which wraps the calls where a driver
 *    spends its time (glDrawArrays, glDrawElements, glBufferData, glClear)
 *    with a clock, so the part of stin_end_frame spent outside them — stin's
 *    own CPU work plus the cheap state calls — can be told apart. With
 *    shadows on minus shadows off that is the cost of building the volumes
 *    on the CPU (silhouette extraction, caps, per-caster set-up), measured
 *    without touching the library.
 *
 * Per side and light count the lowest set-up median is kept, as in
 * bench_run.c (and for the same reason). */
#include "bench_shadow.h"
#include "bench_time.h"
#include "cli_log.h"
#include "raw_gl.h"
#include "scene_gpu.h"
#include "stin_platform.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- GL calls with a clock ----------------------------------------------- */

typedef void (*draw_arrays_fn)(GLenum, GLint, GLsizei);
typedef void (*draw_elements_fn)(GLenum, GLsizei, GLenum, const void *);
typedef void (*buffer_data_fn)(GLenum, GLsizeiptr, const void *, GLenum);
typedef void (*clear_fn)(GLbitfield);

/* One process, one platform: the real entry points are the same for every
 * context, so plain statics do. Timing is on only inside a measured
 * stin_end_frame; otherwise a wrapper is one branch and a call. */
static struct {
    draw_arrays_fn draw_arrays;
    draw_elements_fn draw_elements;
    buffer_data_fn buffer_data, buffer_data_arb;
    clear_fn clear;
    int on;
    double ms;
} wrap;

#define TIMED(call)                                                                      \
    do {                                                                                 \
        if (wrap.on) {                                                                   \
            double t0_ = bench_now_ms();                                                 \
            call;                                                                        \
            wrap.ms += bench_now_ms() - t0_;                                             \
        } else {                                                                         \
            call;                                                                        \
        }                                                                                \
    } while (0)

static void w_draw_arrays(GLenum m, GLint f, GLsizei n) { TIMED(wrap.draw_arrays(m, f, n)); }
static void w_draw_elements(GLenum m, GLsizei n, GLenum t, const void *i)
{
    TIMED(wrap.draw_elements(m, n, t, i));
}
static void w_buffer_data(GLenum t, GLsizeiptr n, const void *d, GLenum u)
{
    TIMED(wrap.buffer_data(t, n, d, u));
}
static void w_buffer_data_arb(GLenum t, GLsizeiptr n, const void *d, GLenum u)
{
    TIMED(wrap.buffer_data_arb(t, n, d, u));
}
static void w_clear(GLbitfield m) { TIMED(wrap.clear(m)); }

/* Function and object pointers do not convert in ISO C; copy the bits. */
static void *fn_to_ptr(void (*f)(void))
{
    void *p;
    memcpy(&p, &f, sizeof p);
    return p;
}
#define STORE(slot, p) memcpy(&(slot), &(p), sizeof(p))
#define WRAP(gl_name, slot, wrapper)                                                     \
    if (!strcmp(name, gl_name)) {                                                        \
        STORE(wrap.slot, real);                                                          \
        return fn_to_ptr((void (*)(void))wrapper);                                       \
    }

void *bench_shadow_get_proc(void *user, const char *name)
{
    void *real = stin_platform_get_proc_address(user, name);
    if (!real)
        return NULL;
    WRAP("glDrawArrays", draw_arrays, w_draw_arrays)
    WRAP("glDrawElements", draw_elements, w_draw_elements)
    WRAP("glBufferData", buffer_data, w_buffer_data)
    WRAP("glBufferDataARB", buffer_data_arb, w_buffer_data_arb)
    WRAP("glClear", clear, w_clear)
    return real;
}

/* ---- lights -------------------------------------------------------------- */

/* n copies of the scene's first light on a circle around the vertical axis
 * through the camera target, at the light's height and distance from that
 * axis; copy 0 is the light itself. Intensity / n keeps the image's
 * brightness where it was. */
static void make_lights(const scene *s, int n, scene_light *out)
{
    const scene_light *l = &s->lights[0];
    float cx = s->camera.target[0], cz = s->camera.target[2];
    float dx = l->position[0] - cx, dz = l->position[2] - cz;
    float r = sqrtf(dx * dx + dz * dz), a0 = atan2f(dz, dx);
    float intensity = l->intensity > 0.0f ? l->intensity : 1.0f;
    int i;
    if (r < 1e-3f) {
        r = 1.0f;
        a0 = 0.0f;
    }
    for (i = 0; i < n; i++) {
        float a = a0 + 6.2831853f * (float)i / (float)n;
        out[i] = *l;
        if (i > 0) {
            out[i].position[0] = cx + r * cosf(a);
            out[i].position[2] = cz + r * sinf(a);
        }
        out[i].intensity = intensity / (float)n;
    }
}

/* ---- one set-up ----------------------------------------------------------- */

typedef struct side {
    stin_context *ctx;
    void *block;
    scene_gpu gpu;
    int made;
} side;

typedef struct setup {
    const shadow_settings *st;
    scene sc;                          /* the scene with the light list replaced */
    scene_light lights[SHADOW_MAX_LIGHTS];
    side vol, off;
    cli_log log;
} setup;

static int side_create(setup *u, side *sd, stin_tier tier, stin_technique shadows,
                       const scene *s, char *err, size_t err_size)
{
    const bench_settings *b = u->st->b;
    stin_desc desc;
    size_t bytes;
    stin_result r;
    bench_desc_init(b, &desc);
    desc.get_proc_address = bench_shadow_get_proc;
    desc.log = cli_log_fn;
    desc.log_user = &u->log;
    desc.tier = tier;
    desc.techniques[STIN_FEATURE_SHADOWS] = shadows;
    if (shadows == STIN_TECH_SHADOWS_VOLUME && u->st->cpu_volumes)
        desc.debug_flags |= STIN_DEBUG_VOLUME_CPU;
    desc.max_lights = SHADOW_MAX_LIGHTS;
    scene_gpu_size_desc(s, &desc);
    bytes = stin_memory_size(&desc);
    if (!(sd->block = malloc(bytes))) {
        snprintf(err, err_size, "cannot allocate %zu bytes for stin", bytes);
        return 0;
    }
    r = stin_create(&desc, sd->block, bytes, &sd->ctx);
    if (r != STIN_OK) {
        snprintf(err, err_size, "stin_create (tier %s, shadows %s): %s", stin_tier_name(tier),
                 stin_technique_name(shadows), stin_result_name(r));
        free(sd->block);
        sd->block = NULL;
        return 0;
    }
    if (stin_query_choice(sd->ctx, STIN_FEATURE_SHADOWS).technique != shadows) {
        snprintf(err, err_size, "tier %s: shadows are not '%s'", stin_tier_name(tier),
                 stin_technique_name(shadows));
        return 0;
    }
    if (!scene_gpu_create(&sd->gpu, &u->sc, sd->ctx, err, err_size))
        return 0;
    sd->made = 1;
    return 1;
}

static void side_destroy(side *sd)
{
    if (sd->made)
        scene_gpu_destroy(&sd->gpu, sd->ctx);
    if (sd->ctx)
        stin_destroy(sd->ctx);
    free(sd->block);
    memset(sd, 0, sizeof *sd);
}

/* A whole frame at full size, glFinish included; negative on failure. */
static double full_frame(const setup *u, const side *sd)
{
    const bench_settings *b = u->st->b;
    double t0 = bench_now_ms();
    stin_result r = scene_gpu_frame(&sd->gpu, sd->ctx, b->width, b->height, STIN_OUTPUT_BEAUTY,
                                    stin_platform_framebuffer(b->plat));
    b->gl->Finish();
    return r == STIN_OK ? bench_now_ms() - t0 : -1.0;
}

/* scene_gpu_frame at the small viewport with stin_end_frame timed on its own:
 * its wall time and the part outside the wrapped GL calls. glFinish after,
 * untimed, so that frames do not overlap. 0 on failure. */
static int small_frame(const setup *u, const side *sd, double *end_ms, double *cpu_ms)
{
    const bench_settings *b = u->st->b;
    const scene *s = &u->sc;
    stin_frame_desc fd;
    double t0, t1;
    stin_result r;
    int i;
    memset(&fd, 0, sizeof fd);
    scene_camera_matrices(&s->camera, u->st->small_w, u->st->small_h, fd.view, fd.projection);
    fd.viewport[2] = u->st->small_w;
    fd.viewport[3] = u->st->small_h;
    fd.framebuffer = stin_platform_framebuffer(b->plat);
    memcpy(fd.clear_color, s->background, sizeof fd.clear_color);
    memcpy(fd.ambient, s->ambient, sizeof fd.ambient);
    if (stin_begin_frame(sd->ctx, &fd) != STIN_OK)
        return 0;
    for (i = 0; i < s->light_count; i++) {
        stin_light_desc l;
        scene_gpu_light(&s->lights[i], &l);
        stin_add_light(sd->ctx, &l);
    }
    for (i = 0; i < s->object_count; i++) {
        const scene_object *o = &s->objects[i];
        stin_draw(sd->ctx, sd->gpu.meshes[o->mesh], o->transform,
                  &sd->gpu.materials[o->material]);
    }
    wrap.ms = 0.0;
    wrap.on = 1;
    t0 = bench_now_ms();
    r = stin_end_frame(sd->ctx);
    t1 = bench_now_ms();
    wrap.on = 0;
    b->gl->Finish();
    *end_ms = t1 - t0;
    *cpu_ms = *end_ms - wrap.ms;
    return r == STIN_OK;
}

/* ABBA over `frames` pairs; per side the median of what was timed. */
typedef struct medians {
    double vol_ms, off_ms, vol_cpu_ms, off_cpu_ms;
} medians;

static int abba(const setup *u, int small, int frames, medians *out, char *err,
                size_t err_size)
{
    size_t n = (size_t)frames;
    double *tv = calloc(n, sizeof *tv), *to = calloc(n, sizeof *to);
    double *cv = calloc(n, sizeof *cv), *co = calloc(n, sizeof *co);
    int k, ok = 0;
    if (!tv || !to || !cv || !co) {
        snprintf(err, err_size, "out of memory");
        goto done;
    }
    for (k = 0; k < frames; k++) {
        int j, good = 1;
        for (j = 0; j < 2; j++) {
            int vol_now = (k % 2 == 0) == (j == 0); /* vol, off | off, vol | ... */
            const side *sd = vol_now ? &u->vol : &u->off;
            double *t = vol_now ? &tv[k] : &to[k], *c = vol_now ? &cv[k] : &co[k];
            if (small) {
                good &= small_frame(u, sd, t, c);
            } else {
                *t = full_frame(u, sd);
                *c = 0.0;
                good &= *t >= 0.0;
            }
        }
        if (!good) {
            snprintf(err, err_size, "stin frame failed");
            goto done;
        }
    }
    if (u->st->b->verbose) {
        fprintf(stderr, "stin-bench: %s ms (volume/off):",
                small ? "stin_end_frame" : "full frame");
        for (k = 0; k < frames; k++)
            fprintf(stderr, " %.2f/%.2f", tv[k], to[k]);
        fprintf(stderr, "\n");
    }
    out->vol_ms = bench_median(tv, n);
    out->off_ms = bench_median(to, n);
    out->vol_cpu_ms = bench_median(cv, n);
    out->off_cpu_ms = bench_median(co, n);
    ok = 1;
done:
    free(tv);
    free(to);
    free(cv);
    free(co);
    return ok;
}


static int one_setup(const shadow_settings *st, stin_tier tier, const scene *s, int first,
                     shadow_row *rows, char *err, size_t err_size)
{
    const bench_settings *b = st->b;
    setup *u = calloc(1, sizeof *u);
    int i, k, ok = 0;
    GLenum e;
    if (!u) {
        snprintf(err, err_size, "out of memory");
        return 0;
    }
    u->st = st;
    u->sc = *s;
    u->log.program = "stin-bench";
    u->log.verbose = b->verbose;
    make_lights(s, 1, u->lights);
    u->sc.lights = u->lights;
    u->sc.light_count = 1;
    if (!side_create(u, &u->vol, tier, STIN_TECH_SHADOWS_VOLUME, s, err, err_size) ||
        !side_create(u, &u->off, tier, STIN_TECH_SHADOWS_OFF, s, err, err_size))
        goto done;
    for (i = 0; i < st->count_n; i++) {
        shadow_row *row = &rows[i];
        stin_frame_stats fs;
        medians full, small;
        make_lights(s, st->light_counts[i], u->lights);
        u->sc.light_count = st->light_counts[i];
        /* The full warm-up before the first count; one frame per side before
         * the others (new shader variants for the light count settle in it). */
        for (k = 0; k < (i == 0 && b->warmup > 1 ? b->warmup : 1); k++)
            if (full_frame(u, &u->vol) < 0 || full_frame(u, &u->off) < 0) {
                snprintf(err, err_size, "stin frame failed");
                goto done;
            }
        /* The last warm-up frame's statistics: the same every frame. */
        fs = stin_query_frame_stats(u->vol.ctx);
        if (fs.lights != (uint32_t)st->light_counts[i] ||
            (fs.shadows.volume_triangles == 0 && fs.shadows.volume_gpu_casters == 0)) {
            snprintf(err, err_size, "the shadowed frame drew %u lights and %u volume triangles "
                     "(expected %d lights and some volumes)", fs.lights,
                     fs.shadows.volume_triangles, st->light_counts[i]);
            goto done;
        }
        if (!abba(u, 0, st->frames, &full, err, err_size))
            goto done;
        if (!small_frame(u, &u->vol, &small.vol_ms, &small.vol_cpu_ms) ||
            !small_frame(u, &u->off, &small.off_ms, &small.off_cpu_ms) ||
            !abba(u, 1, st->small_frames, &small, err, err_size))
            goto done;
        if (b->verbose)
            fprintf(stderr, "stin-bench: %d light(s): full medians volume %.2f off %.2f ms; "
                    "end_frame at %dx%d volume %.3f (outside GL %.3f) off %.3f (%.3f) ms\n",
                    st->light_counts[i], full.vol_ms, full.off_ms, st->small_w, st->small_h,
                    small.vol_ms, small.vol_cpu_ms, small.off_ms, small.off_cpu_ms);
        row->lights = st->light_counts[i];
        row->volume_triangles = fs.shadows.volume_triangles;
        row->gpu_casters = fs.shadows.volume_gpu_casters;
        row->passes = fs.passes;
        row->zpass_casters = fs.shadows.zpass_casters;
        row->zfail_casters = fs.shadows.zfail_casters;
        bench_keep_min(&row->vol_ms, full.vol_ms, first);
        bench_keep_min(&row->off_ms, full.off_ms, first);
        bench_keep_min(&row->vol_end_ms, small.vol_ms, first);
        bench_keep_min(&row->off_end_ms, small.off_ms, first);
        bench_keep_min(&row->vol_cpu_ms, small.vol_cpu_ms, first);
        bench_keep_min(&row->off_cpu_ms, small.off_cpu_ms, first);
    }
    if ((e = b->gl->GetError()) != 0) {
        snprintf(err, err_size, "GL error 0x%x during the shadow frames", e);
        goto done;
    }
    if (u->log.errors) {
        snprintf(err, err_size, "stin logged %u error(s)", u->log.errors);
        goto done;
    }
    ok = 1;
done:
    side_destroy(&u->vol);
    side_destroy(&u->off);
    free(u);
    return ok;
}

int bench_shadow_run(const shadow_settings *st, stin_tier tier, const scene *s,
                     shadow_row *rows, char *err, size_t err_size)
{
    int j, i;
    memset(rows, 0, (size_t)st->count_n * sizeof *rows);
    if (s->light_count < 1) {
        snprintf(err, err_size, "%s: the scene has no light to copy", s->path);
        return 0;
    }
    for (i = 0; i < st->count_n; i++)
        if (st->light_counts[i] < 1 || st->light_counts[i] > SHADOW_MAX_LIGHTS) {
            snprintf(err, err_size, "light counts are 1..%d", SHADOW_MAX_LIGHTS);
            return 0;
        }
    for (j = 0; j < st->setups; j++)
        if (!one_setup(st, tier, s, j == 0, rows, err, err_size))
            return 0;
    return 1;
}
