/* SPDX-License-Identifier: MIT */
#include "msaa_shared.h"
#include "reference.h"
#include "test_context.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GL_SAMPLE_POSITION_ 0x8E50

typedef void (*get_multisamplefv_fn)(unsigned pname, unsigned index, float *val);

int msaa_sample_positions(run *r, float pos[][2])
{
    get_multisamplefv_fn get = (get_multisamplefv_fn)stin_platform_get_proc_address(
        r->plat, "glGetMultisamplefv");
    int i, n = stin_platform_samples(r->plat);
    if (!get || n < 2 || n > MSAA_MAX_SAMPLES)
        return 0;
    for (i = 0; i < n; i++)
        get(GL_SAMPLE_POSITION_, (unsigned)i, pos[i]);
    return n;
}

/* A context with t's techniques, the scene made: 1, or 0 where stin_create
 * refused a forced technique or chose another for it. */
static int create(test_context *tc, run *r, const scene *s, const msaa_techniques *t)
{
    const stin_feature features[5] = {STIN_FEATURE_SHADOWS, STIN_FEATURE_TRANSPARENCY,
                                      STIN_FEATURE_TRANSLUCENT_SHADOWS, STIN_FEATURE_SURFACE,
                                      STIN_FEATURE_DISPLACEMENT};
    const stin_technique want[5] = {t->shadows, t->transparency, t->translucent, t->surface,
                                    t->displacement};
    stin_desc d;
    size_t size;
    char err[256];
    int i, ok;
    memset(tc, 0, sizeof *tc);
    test_desc(r, t->tier, &d);
    for (i = 0; i < 5; i++)
        d.techniques[features[i]] = want[i];
    scene_gpu_size_desc(s, &d);
    size = stin_memory_size(&d);
    tc->block = malloc(size);
    if (!tc->block || stin_create(&d, tc->block, size, &tc->ctx) != STIN_OK) {
        free(tc->block);
        memset(tc, 0, sizeof *tc);
        return 0;
    }
    ok = 1;
    for (i = 0; i < 5; i++)
        ok = ok && (want[i] == STIN_TECH_NONE ||
                    stin_query_choice(tc->ctx, features[i]).technique == want[i]);
    if (!ok || !scene_gpu_create(&tc->g, s, tc->ctx, err, sizeof err)) {
        stin_destroy(tc->ctx);
        free(tc->block);
        memset(tc, 0, sizeof *tc);
        return 0;
    }
    return 1;
}

int msaa_render(run *r, const scene *s, const msaa_techniques *t, uint8_t *rgba, char *why,
                size_t why_size)
{
    static const float none[4] = {0, 0, 0, 0};
    return msaa_render_outlined(r, s, t, 0.0f, none, rgba, why, why_size);
}

int msaa_render_outlined(run *r, const scene *s, const msaa_techniques *t, float step,
                         const float color[4], uint8_t *rgba, char *why, size_t why_size)
{
    test_context tc;
    stin_frame_desc fd;
    stin_result res;
    if (!create(&tc, r, s, t)) {
        snprintf(why, why_size, "%s does not run on this tier here",
                 stin_technique_name(t->displacement != STIN_TECH_NONE   ? t->displacement
                                     : t->surface != STIN_TECH_NONE      ? t->surface
                                     : t->transparency != STIN_TECH_NONE ? t->transparency
                                     : t->translucent != STIN_TECH_NONE  ? t->translucent
                                                                         : t->shadows));
        return -1;
    }
    memset(&fd, 0, sizeof fd);
    scene_camera_matrices(&s->camera, s->width, s->height, fd.view, fd.projection);
    fd.viewport[2] = s->width;
    fd.viewport[3] = s->height;
    fd.framebuffer = stin_platform_framebuffer(r->plat);
    memcpy(fd.clear_color, s->background, sizeof fd.clear_color);
    memcpy(fd.ambient, s->ambient, sizeof fd.ambient);
    fd.outline_step = step;
    memcpy(fd.outline_color, color, sizeof fd.outline_color);
    res = test_context_frame(&tc, s, &fd, -1);
    test_context_destroy(&tc);
    if (res != STIN_OK) {
        snprintf(why, why_size, "frame: %s", stin_result_name(res));
        return 0;
    }
    if (!stin_platform_read_color(r->plat, rgba)) {
        snprintf(why, why_size, "read-back failed");
        return 0;
    }
    return 1;
}

int msaa_render_reported(run *r, const scene *s, const msaa_techniques *t, uint8_t *rgba,
                         const char *name)
{
    char why[512] = "out of memory";
    int got = rgba ? msaa_render(r, s, t, rgba, why, sizeof why) : 0;
    if (got <= 0)
        report(r, got < 0 ? "SKIP" : "FAIL", name, "%s", why);
    return got > 0;
}

void msaa_save_pair(run *r, const char *name, const uint8_t *rgba, const float *colour, int w,
                    int h)
{
    image img;
    char path[1024], err[256];
    int x, y, c;
    if (!r->out_dir || !image_alloc(&img, 2 * w, h, 3))
        return;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            for (c = 0; c < 3; c++) {
                float *row = img.pixels + 3 * (size_t)(h - 1 - y) * 2 * w;
                row[3 * x + c] = rgba[4 * ((size_t)y * r->width + x) + c] / 255.0f;
                row[3 * (w + x) + c] = colour[3 * ((size_t)y * w + x) + c];
            }
    snprintf(path, sizeof path, "%s/%s-%s-%s.png", r->out_dir, r->platform_name,
             r->profile_name, name);
    for (c = (int)strlen(r->out_dir) + 1; path[c]; c++)
        if (path[c] == '/')
            path[c] = '-';
    if (!image_write(path, &img, 0, err, sizeof err))
        fprintf(stderr, "stin-imagetest: %s\n", err);
    image_free(&img);
}

int msaa_open(run *r, const char *path, const char *file, int samples, const char *name,
              scene *s, float pos[][2])
{
    char full[1024], err[512];
    const char *slash = strrchr(path, '/');
    int n;
    snprintf(full, sizeof full, "%.*smsaa/%s", slash ? (int)(slash - path + 1) : 0, path, file);
    if (!scene_load(full, s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return 0;
    }
    if (s->width > r->width || s->height > r->height) {
        report(r, "SKIP", name, "the run's %dx%d is smaller than the scene's %dx%d", r->width,
               r->height, s->width, s->height);
        scene_free(s);
        return 0;
    }
    if (!stin_platform_set_samples(r->plat, samples, err, sizeof err)) {
        report(r, "SKIP", name, "%s", err);
        scene_free(s);
        return 0;
    }
    n = msaa_sample_positions(r, pos);
    if (!n) {
        report(r, "SKIP", name, "the context cannot say where its samples lie "
                                "(glGetMultisamplefv: GL 3.2 or ARB_texture_multisample)");
        msaa_close(r, name, s);
    }
    return n;
}

void msaa_close(run *r, const char *name, scene *s)
{
    char err[512];
    if (!stin_platform_set_samples(r->plat, 0, err, sizeof err))
        report(r, "FAIL", name, "back to the default framebuffer: %s", err);
    scene_free(s);
}

int msaa_gl1_per_vertex(run *r, const scene *s)
{
    test_context tc;
    int per_vertex = 0;
    if (test_context_create(&tc, r, s, STIN_TIER_GL1, STIN_TECH_NONE, 0)) {
        per_vertex = stin_query_caps(tc.ctx)->present & STIN_CAP_BIT(STIN_CAP_SEPARATE_SPECULAR)
                         ? 1
                         : REFERENCE_GOURAUD_SINGLE_COLOR;
        test_context_destroy(&tc);
    }
    return per_vertex;
}
