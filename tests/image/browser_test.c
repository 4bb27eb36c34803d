/* SPDX-License-Identifier: MIT */
/*
 * The browser's frames (tests/web/run.sh): for each case the page ran
 * (tests/web/test.js), its read-backs from DIR (SCENE-CASE-beauty.rgba,
 * -normal, -vis, -depth with the depth's 24 bits packed in R, G, B, and
 * SCENE-CASE.txt: the frames' status, stin's choice and log, the frame's
 * projection) become the AOV image of a native capture, and the native
 * rows judge it against the same Embree reference with the same bounds:
 *   lighting         gl-clean, position, normal, beauty (image_test.c)
 *   volume           gl-clean, volume-vis (shadow_test.c)
 *   map-pcf-S-kK     map-pcf-S-kK (pcf_test.c)
 * gl-clean here: stin_create succeeded, every frame returned STIN_OK with
 * WebGL's error flag clear, no error logged, and stin chose the technique
 * the case forced.
 */
#include "aov.h"
#include "capture.h"
#include "image_test.h"
#include "scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct browser_case {
    const char *name;     /* as test.js names it */
    stin_technique shadows;
    uint32_t map_size;
    int kernel;
} browser_case;

static const browser_case cases[] = {
    {"lighting", STIN_TECH_SHADOWS_OFF, 0, 0},
    {"volume", STIN_TECH_SHADOWS_VOLUME, 0, 0},
    {"map-pcf-1024-k3", STIN_TECH_SHADOWS_MAP_PCF, 1024, 3},
};

static unsigned char *read_all(const char *path, size_t expect)
{
    FILE *f = fopen(path, "rb");
    unsigned char *data = malloc(expect + 1);
    size_t n = f && data ? fread(data, 1, expect + 1, f) : 0;
    if (f)
        fclose(f);
    if (n != expect) {
        free(data);
        return NULL;
    }
    return data;
}

/* The case's text: 1 when created and every frame succeeded; the frame's
 * projection, stin's shadow technique and the log's errors. */
static int read_meta(const char *path, float proj[16], stin_technique *shadows, capture *cap,
                     char *why, size_t why_size)
{
    FILE *f = fopen(path, "r");
    char line[1024];
    int ok = f != NULL, k;
    snprintf(why, why_size, "%s", f ? "" : "no result from the browser");
    *shadows = STIN_TECH_NONE;
    while (f && fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = '\0';
        if (!strcmp(line, "created 0")) {
            ok = 0;
            snprintf(why, why_size, "stin_create failed");
        } else if (!strncmp(line, "frame ", 6) && line[strlen(line) - 1] != '1') {
            ok = 0;
            snprintf(why, why_size, "%.400s: not STIN_OK, or a WebGL error after it", line);
        } else if (!strncmp(line, "projection ", 11)) {
            char *p = line + 11;
            for (k = 0; k < 16; k++)
                proj[k] = strtof(p, &p);
        } else if (!strncmp(line, "choice shadows ", 15)) {
            *shadows = stin_technique_from_name(line + 15);
        } else if (!strncmp(line, "log error: ", 11)) {
            cap->log_errors++;
            snprintf(cap->last_error, sizeof cap->last_error, "%.400s", line + 11);
        }
    }
    if (f)
        fclose(f);
    return ok;
}

/* The AOV image of one case from its files; 0 with why on anything missing. */
static int load_case(run *r, const char *dir, const char *scene_name, const scene *s,
                     const browser_case *bc, capture *cap, char *why, size_t why_size)
{
    static const char *const outputs[4] = {"beauty", "normal", "vis", "depth"};
    unsigned char *px[4] = {NULL, NULL, NULL, NULL};
    size_t n = (size_t)r->width * r->height, i;
    float view[16], proj[16], *depth = malloc(n * sizeof(float));
    char path[1024];
    stin_technique chosen;
    int ok = 0, k;
    memset(cap, 0, sizeof *cap);
    /* the file's camera; the projection the frame drew with replaces it */
    scene_camera_matrices(&s->camera, r->width, r->height, view, proj);
    snprintf(path, sizeof path, "%s/%s-%s.txt", dir, scene_name, bc->name);
    if (!depth || !read_meta(path, proj, &chosen, cap, why, why_size))
        goto done;
    cap->choice[STIN_FEATURE_SHADOWS].technique = chosen;
    if (chosen != bc->shadows) {
        snprintf(why, why_size, "not drawn by %s (%s)", stin_technique_name(bc->shadows),
                 stin_technique_name(chosen));
        goto done;
    }
    for (k = 0; k < 4; k++) {
        snprintf(path, sizeof path, "%s/%s-%s-%s.rgba", dir, scene_name, bc->name, outputs[k]);
        if (!(px[k] = read_all(path, n * 4))) {
            snprintf(why, why_size, "%.400s: missing or not %dx%d RGBA8", path, r->width, r->height);
            goto done;
        }
    }
    for (i = 0; i < n; i++) /* 24 bits, most significant in R (platform/web/stin_web.c) */
        depth[i] = (float)(((uint32_t)px[3][4 * i] << 16 | (uint32_t)px[3][4 * i + 1] << 8 |
                            px[3][4 * i + 2]) / 16777215.0);
    ok = aov_assemble(r->width, r->height, px[0], px[1], px[2], depth, view, proj, s->camera.eye,
                      &cap->img, why, why_size);
done:
    for (k = 0; k < 4; k++)
        free(px[k]);
    free(depth);
    return ok;
}

void browser_tests(run *r, const char *dir, const char *list, const char *path)
{
    scene s;
    char err[512], scene_name[128], name[256], why[512];
    size_t i;
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", scene_name, "%s", err);
        return;
    }
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const browser_case *bc = &cases[i];
        capture cap;
        size_t len = strlen(bc->name);
        const char *at = strstr(list, bc->name);
        if (!at || (at[len] != '\0' && at[len] != ','))
            continue;
        snprintf(name, sizeof name, "gl2/%s/%s/gl-clean", scene_name, bc->name);
        if (!load_case(r, dir, scene_name, &s, bc, &cap, why, sizeof why)) {
            report(r, "FAIL", name, "%s", why);
            capture_free(&cap);
            continue;
        }
        if (cap.log_errors)
            report(r, "FAIL", name, "%u error logs (last: %s)", cap.log_errors, cap.last_error);
        else
            report(r, "PASS", name, "created, every frame STIN_OK with WebGL's error flag clear, "
                                    "no error logged, drawn by %s",
                   stin_technique_name(bc->shadows));
        if (bc->shadows == STIN_TECH_SHADOWS_OFF)
            render_rows(r, STIN_TIER_GL2, scene_name, &s, &cap.img, 0);
        else if (bc->shadows == STIN_TECH_SHADOWS_VOLUME)
            shadow_vis_rows(r, STIN_TIER_GL2, path, &cap);
        else
            pcf_rows(r, STIN_TIER_GL2, path, bc->map_size, bc->kernel, &cap);
        capture_free(&cap);
    }
    scene_free(&s);
}
