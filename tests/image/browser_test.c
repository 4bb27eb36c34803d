/* SPDX-License-Identifier: MIT */
/*
 * The browser's frames (tests/web/run.sh): for each case the page ran
 * (tests/web/test.js), its read-backs from DIR (SCENE-CASE-beauty.rgba,
 * -normal, -vis, -depth with the depth's 24 bits packed in R, G, B, and
 * SCENE-CASE.txt: the frames' status, stin's choice and log, the frame's
 * projection) become the AOV image of a native capture, and the native
 * rows judge it against the same Embree reference with the same bounds:
 *   lighting         four-lights: position, normal, beauty (image_test.c)
 *   volume           four-lights: volume-vis (shadow_test.c)
 *   map-pcf-S-kK     four-lights: map-pcf-S-kK (pcf_test.c)
 *   coloured         glass-panes: coloured-transmittance, -between
 *                    (coloured_test.c)
 *   deep             glass-panes at tier gl4 (WebGL 2's default):
 *                    deep-transmittance, deep-own-layer (deep_test.c)
 *   lighting-gl4, volume-gl4, pom-gl4  lighting, volume and pom at tier
 *                    gl4: its GLSL ES 3.00 programs, the same rows
 *   depth-peel       glass-panes: peel-beauty (peel_test.c)
 *   normal, pom      stone-wall: normal-reference, pom-reference
 *                    (surface_test.c)
 *   parallax-down    stone-wall seen straight down (its pack
 *                    stone-wall.parallax-down, tools/common/scene_variant.h):
 *                    parallax-down against the case parallax-down-normal
 *                    (the same view by normal mapping), which has gl-clean alone
 *   parallax-limit   stone-wall's parallax-limit view (uv-gradient albedo):
 *                    parallax-limit against the reference (surface_test.c)
 *   displace         displace-plate: displace position, silhouette
 *                    (displace_test.c)
 *   scs-CASE         csg: csg-scs-CASE P and N of csg.json's product CASE
 *                    (carved, both, common) alone (csg_test.c)
 *   goldfeather-CASE csg: csg-CASE P and N, the same products by goldfeather
 *   skip-T           a technique WebGL 2 cannot run (dual-peel, vdsm,
 *                    displace-tess, interval) forced at stin's best tier: a
 *                    SKIP row with stin's refusal naming what WebGL 2 lacks;
 *                    FAIL if it ran (it would need rows of its own) or
 *                    stin_create failed without naming it
 *   webgl1           the page refuses 'webgl2' contexts (WebGL 1 alone left):
 *                    the front end's init must fail, its message naming
 *                    WebGL 2 (no frames, no gl-clean row)
 *   sweep            every scene, stin's own choice, a small front end of
 *                    its own, frames not read back: SCENE/sweep/drawn when
 *                    created, every frame STIN_OK with WebGL's error flag
 *                    clear, no error logged, and each feature stin marks
 *                    fallen back named in its log; the line lists the
 *                    log's warnings (the fall-backs of what WebGL lacks)
 * The cases run at tier gl2 unless they name gl4; their rows carry the
 * tier. And gl-clean for each: stin_create succeeded, every frame returned
 * STIN_OK with WebGL's error flag clear, no error logged, and stin chose
 * the technique the case forced.
 */
#include "aov.h"
#include "capture.h"
#include "image_test.h"
#include "scene.h"
#include "scene_variant.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef enum browser_rows {
    ROWS_LIGHTING,
    ROWS_VOLUME,
    ROWS_PCF,
    ROWS_COLOURED,
    ROWS_DEEP,
    ROWS_PEEL,
    ROWS_SURFACE,
    ROWS_DOWN,    /* against the frame of the case its `csg` field names */
    ROWS_LIMIT,
    ROWS_PAIR,    /* a frame another case compares with: gl-clean alone */
    ROWS_DISPLACE,
    ROWS_CSG,
    ROWS_REFUSAL, /* no frames: the front end's refusal of a context without WebGL 2 */
    ROWS_SWEEP,   /* frames not read back: drawn, or the fall-backs named */
    ROWS_SKIP     /* a technique WebGL 2 cannot run: stin's refusal, a SKIP with it */
} browser_rows;

typedef struct browser_case {
    const char *name;     /* as test.js names it */
    const char *scene;    /* the scene it is for (tests/web/test.js agrees); NULL: every one */
    stin_technique tech;  /* the technique it forces: stin must have chosen it */
    browser_rows rows;
    uint32_t map_size;
    int kernel;
    const char *csg;      /* ROWS_CSG: csg_test.c's case (the page draws that product alone);
                             ROWS_DOWN: the case it is compared with */
    stin_tier tier;       /* the tier test.js forces (its rows', and their names') */
} browser_case;

static const browser_case cases[] = {
    {"lighting", "four-lights", STIN_TECH_SHADOWS_OFF, ROWS_LIGHTING, 0, 0, NULL, STIN_TIER_GL2},
    {"volume", "four-lights", STIN_TECH_SHADOWS_VOLUME, ROWS_VOLUME, 0, 0, NULL, STIN_TIER_GL2},
    {"map-pcf-1024-k3", "four-lights", STIN_TECH_SHADOWS_MAP_PCF, ROWS_PCF, 1024, 3, NULL, STIN_TIER_GL2},
    {"coloured", "glass-panes", STIN_TECH_TRANSLUCENT_COLOURED, ROWS_COLOURED, 0, 0, NULL, STIN_TIER_GL2},
    {"deep", "glass-panes", STIN_TECH_TRANSLUCENT_DEEP, ROWS_DEEP, 0, 0, NULL, STIN_TIER_GL4},
    {"lighting-gl4", "four-lights", STIN_TECH_SHADOWS_OFF, ROWS_LIGHTING, 0, 0, NULL, STIN_TIER_GL4},
    {"volume-gl4", "four-lights", STIN_TECH_SHADOWS_VOLUME, ROWS_VOLUME, 0, 0, NULL, STIN_TIER_GL4},
    {"pom-gl4", "stone-wall", STIN_TECH_SURFACE_POM, ROWS_SURFACE, 0, 0, NULL, STIN_TIER_GL4},
    {"depth-peel", "glass-panes", STIN_TECH_TRANSPARENCY_DEPTH_PEEL, ROWS_PEEL, 0, 0, NULL, STIN_TIER_GL2},
    {"normal", "stone-wall", STIN_TECH_SURFACE_NORMAL, ROWS_SURFACE, 0, 0, NULL, STIN_TIER_GL2},
    {"pom", "stone-wall", STIN_TECH_SURFACE_POM, ROWS_SURFACE, 0, 0, NULL, STIN_TIER_GL2},
    {"parallax-down", "stone-wall", STIN_TECH_SURFACE_PARALLAX, ROWS_DOWN, 0, 0, "parallax-down-normal", STIN_TIER_GL2},
    {"parallax-down-normal", "stone-wall", STIN_TECH_SURFACE_NORMAL, ROWS_PAIR, 0, 0, NULL, STIN_TIER_GL2},
    {"parallax-limit", "stone-wall", STIN_TECH_SURFACE_PARALLAX, ROWS_LIMIT, 0, 0, NULL, STIN_TIER_GL2},
    {"displace", "displace-plate", STIN_TECH_DISPLACEMENT_VTF, ROWS_DISPLACE, 0, 0, NULL, STIN_TIER_GL2},
    {"scs-carved", "csg", STIN_TECH_CSG_SCS, ROWS_CSG, 0, 0, "carved", STIN_TIER_GL2},
    {"scs-both", "csg", STIN_TECH_CSG_SCS, ROWS_CSG, 0, 0, "both", STIN_TIER_GL2},
    {"scs-common", "csg", STIN_TECH_CSG_SCS, ROWS_CSG, 0, 0, "common", STIN_TIER_GL2},
    {"goldfeather-carved", "csg", STIN_TECH_CSG_GOLDFEATHER, ROWS_CSG, 0, 0, "carved", STIN_TIER_GL2},
    {"goldfeather-both", "csg", STIN_TECH_CSG_GOLDFEATHER, ROWS_CSG, 0, 0, "both", STIN_TIER_GL2},
    {"goldfeather-common", "csg", STIN_TECH_CSG_GOLDFEATHER, ROWS_CSG, 0, 0, "common", STIN_TIER_GL2},
    {"skip-dual-peel", "glass-panes", STIN_TECH_TRANSPARENCY_DUAL_PEEL, ROWS_SKIP, 0, 0, NULL, STIN_TIER_GL2},
    {"skip-vdsm", "four-lights", STIN_TECH_SHADOWS_VDSM, ROWS_SKIP, 0, 0, NULL, STIN_TIER_GL2},
    {"skip-displace-tess", "displace-tess", STIN_TECH_DISPLACEMENT_TESS, ROWS_SKIP, 0, 0, NULL, STIN_TIER_GL2},
    {"skip-interval", "csg", STIN_TECH_CSG_INTERVAL, ROWS_SKIP, 0, 0, NULL, STIN_TIER_GL2},
    {"webgl1", "four-lights", STIN_TECH_NONE, ROWS_REFUSAL, 0, 0, NULL, STIN_TIER_GL2},
    {"sweep", NULL, STIN_TECH_NONE, ROWS_SWEEP, 0, 0, NULL, STIN_TIER_GL2},
};

/* The view of the scene (scene_variant.h) the case's page drew, packed of
 * its own (tests/web/test.js), or NULL: the scene file's. */
static const char *case_variant(const browser_case *bc)
{
    return bc->rows == ROWS_LIMIT ? "parallax-limit"
         : bc->rows == ROWS_DOWN || bc->rows == ROWS_PAIR ? "parallax-down"
                                                            : NULL;
}

/* name is one of list's comma-separated words */
static int in_list(const char *list, const char *name)
{
    size_t len = strlen(name);
    const char *at = list;
    while ((at = strstr(at, name)) != NULL) {
        if ((at == list || at[-1] == ',') && (at[len] == '\0' || at[len] == ','))
            return 1;
        at += len;
    }
    return 0;
}

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
 * projection, stin's choice per feature and the log's errors. */
static int read_meta(const char *path, float proj[16], capture *cap, char *why, size_t why_size)
{
    FILE *f = fopen(path, "r");
    char line[1024];
    int ok = f != NULL, k;
    snprintf(why, why_size, "%s", f ? "" : "no result from the browser");
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
        } else if (!strncmp(line, "choice ", 7)) { /* "choice FEATURE TECHNIQUE[ (fell back)]" */
            char *feature = line + 7, *tech = strchr(feature, ' ');
            if (!tech)
                continue;
            *tech++ = '\0';
            tech[strcspn(tech, " ")] = '\0';
            for (k = 0; k < STIN_FEATURE_COUNT; k++)
                if (!strcmp(feature, stin_feature_name((stin_feature)k)))
                    cap->choice[k].technique = stin_technique_from_name(tech);
        } else if (!strncmp(line, "log error: ", 11)) {
            cap->log_errors++;
            snprintf(cap->last_error, sizeof cap->last_error, "%.400s", line + 11);
        }
    }
    if (f)
        fclose(f);
    return ok;
}

/* The AOV image of one case from its files and its beauty read-back (the
 * caller frees it); 0 with why on anything missing. */
static int load_case(run *r, const char *dir, const char *scene_name, const scene *s,
                     const browser_case *bc, capture *cap, unsigned char **beauty, char *why,
                     size_t why_size)
{
    static const char *const outputs[4] = {"beauty", "normal", "vis", "depth"};
    unsigned char *px[4] = {NULL, NULL, NULL, NULL};
    size_t n = (size_t)r->width * r->height, i;
    float view[16], proj[16], *depth = malloc(n * sizeof(float));
    char path[1024];
    stin_technique chosen;
    int ok = 0, k;
    memset(cap, 0, sizeof *cap);
    *beauty = NULL;
    /* the file's camera; the projection the frame drew with replaces it */
    scene_camera_matrices(&s->camera, r->width, r->height, view, proj);
    snprintf(path, sizeof path, "%s/%s-%s.txt", dir, scene_name, bc->name);
    if (!depth || !read_meta(path, proj, cap, why, why_size))
        goto done;
    chosen = cap->choice[stin_technique_feature(bc->tech)].technique;
    if (chosen != bc->tech) {
        snprintf(why, why_size, "not drawn by %s (%s)", stin_technique_name(bc->tech),
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
    if (ok) {
        *beauty = px[0];
        px[0] = NULL;
    }
done:
    for (k = 0; k < 4; k++)
        free(px[k]);
    free(depth);
    return ok;
}

/* webgl1: "init 0" and a message naming WebGL 2 (one PASS/FAIL line). */
static void refusal_row(run *r, const char *dir, const char *scene_name)
{
    char path[1024], line[1024], message[600] = "";
    int init = -1;
    FILE *f;
    snprintf(path, sizeof path, "%s/%s-webgl1.txt", dir, scene_name);
    f = fopen(path, "r");
    while (f && fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = '\0';
        if (!strncmp(line, "init ", 5))
            init = atoi(line + 5);
        else if (!strncmp(line, "message ", 8))
            snprintf(message, sizeof message, "%.500s", line + 8);
    }
    if (f)
        fclose(f);
    report(r, init == 0 && strstr(message, "needs WebGL 2") ? "PASS" : "FAIL", "webgl1/refused",
           "no WebGL 2 context (the page refused 'webgl2', WebGL 1 left): front end init %s, "
           "message \"%s\" (must fail and name WebGL 2)",
           init < 0 ? "gave no result" : init ? "succeeded" : "failed", message);
}

/* sweep: one PASS/FAIL line from SCENE-sweep.txt. */
static void sweep_row(run *r, const char *dir, const char *scene_name)
{
    char path[1024], line[1024], name[256], named[1024] = "", why[512] = "";
    char fell[STIN_FEATURE_COUNT][64];
    int created = -1, frames = 0, k, falls = 0;
    FILE *f;
    snprintf(path, sizeof path, "%s/%s-sweep.txt", dir, scene_name);
    snprintf(name, sizeof name, "%s/sweep/drawn", scene_name);
    f = fopen(path, "r");
    while (f && fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = '\0';
        if (!strncmp(line, "created ", 8))
            created = atoi(line + 8);
        else if (!strncmp(line, "frame ", 6) && (++frames, line[strlen(line) - 1] != '1'))
            snprintf(why, sizeof why, "%.400s: not STIN_OK, or a WebGL error after it", line);
        else if (!strncmp(line, "log error: ", 11))
            snprintf(why, sizeof why, "error logged: %.400s", line + 11);
        if (!strncmp(line, "choice ", 7) && strstr(line, "(fell back)") && falls < STIN_FEATURE_COUNT)
            snprintf(fell[falls++], sizeof fell[0], "%.*s", (int)strcspn(line + 7, " "), line + 7);
        if (!strncmp(line, "log warning: ", 13) && strlen(named) < sizeof named - 1)
            snprintf(named + strlen(named), sizeof named - strlen(named), "%s%s",
                     named[0] ? "; " : "", line + 13);
    }
    if (f)
        fclose(f);
    /* a feature that fell back must be named: "FEATURE: ... falls back", or
     * stin_create's choice "FEATURE: TECHNIQUE (fallback: WHY)" */
    for (k = 0; k < falls && !why[0]; k++) {
        int found = 0;
        f = fopen(path, "r");
        while (f && fgets(line, sizeof line, f))
            found |= !strncmp(line, "log ", 4) && strstr(line, fell[k]) != NULL &&
                 (strstr(line, "falls back") != NULL || strstr(line, "(fallback: ") != NULL);
        if (f)
            fclose(f);
        if (!found)
            snprintf(why, sizeof why, "%s fell back and the log does not say why", fell[k]);
    }
    if (created != 1 || frames != 3 || why[0])
        report(r, "FAIL", name, "%s", created < 0  ? "no result from the browser"
                                       : !created ? "stin_create failed"
                                       : why[0]   ? why
                                                  : "not every frame drawn");
    else
        report(r, "PASS", name, "drawn: every frame STIN_OK, no WebGL error, no error logged; "
                                "fall-backs in stin's log: %s", named[0] ? named : "none");
}

/* skip-T: one SKIP line with stin's reason, or a FAIL line. */
static void skip_row(run *r, const char *dir, const char *scene_name, const browser_case *bc)
{
    char path[1024], name[256], why[512];
    const char *t = stin_technique_name(bc->tech);
    float proj[16];
    capture cap;
    int created;
    memset(&cap, 0, sizeof cap);
    snprintf(path, sizeof path, "%s/%s-%s.txt", dir, scene_name, bc->name);
    snprintf(name, sizeof name, "gl2/%s/%s", scene_name, t);
    created = read_meta(path, proj, &cap, why, sizeof why);
    if (!created && strstr(cap.last_error, t) && strstr(cap.last_error, "needs"))
        report(r, "SKIP", name, "WebGL 2 cannot run it: %s", cap.last_error);
    else if (created && cap.choice[stin_technique_feature(bc->tech)].technique == bc->tech)
        report(r, "FAIL", name, "%s runs on WebGL 2 here: it needs browser rows of its own", t);
    else
        report(r, "FAIL", name, "forced %s neither ran nor was refused naming it (%s; %s)", t,
               why[0] ? why : "created", cap.last_error[0] ? cap.last_error : "no error logged");
}

/* parallax-down against its pair's frame (the same view, normal mapping). */
static void down_rows(run *r, const char *dir, const char *scene_name, const scene *s,
                      const browser_case *bc, const capture *cap)
{
    char name[256], why[512];
    const browser_case *pair = NULL;
    unsigned char *beauty = NULL;
    capture other;
    size_t i;
    snprintf(name, sizeof name, "gl2/%s/parallax-down", scene_name);
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
        if (!strcmp(cases[i].name, bc->csg))
            pair = &cases[i];
    if (pair && load_case(r, dir, scene_name, s, pair, &other, &beauty, why, sizeof why))
        surface_down_rows(r, name, cap, &other);
    else
        report(r, "FAIL", name, "%s: %s", bc->csg, pair ? why : "no such case");
    free(beauty);
    capture_free(&other);
}

/* The native rows of the case's technique on the browser's frame. */
static void case_rows(run *r, const browser_case *bc, const char *dir, const char *path,
                      const char *scene_name, const scene *s, const capture *cap,
                      const unsigned char *beauty)
{
    char name[256];
    stin_tier tier = bc->tier;
    switch (bc->rows) {
    case ROWS_LIGHTING: render_rows(r, tier, scene_name, s, &cap->img, 0); break;
    case ROWS_VOLUME: shadow_vis_rows(r, tier, path, cap); break;
    case ROWS_PCF: pcf_rows(r, tier, path, bc->map_size, bc->kernel, cap); break;
    case ROWS_COLOURED: coloured_frame_rows(r, tier, path, cap); break;
    case ROWS_DEEP: deep_frame_rows(r, tier, path, cap); break;
    case ROWS_PEEL: peel_frame_rows(r, tier, path, beauty, bc->tech); break;
    case ROWS_SURFACE: /* ANGLE draws upside down: a quad's derivatives from its lower row */
        surface_frame_rows(r, tier, path, bc->tech, 1, cap);
        break;
    case ROWS_DOWN: down_rows(r, dir, scene_name, s, bc, cap); break;
    case ROWS_LIMIT:
        snprintf(name, sizeof name, "gl2/%s/parallax-limit", scene_name);
        surface_limit_rows(r, name, s, s->objects[scene_variant_parallax_object(s)].material, cap);
        break;
    case ROWS_PAIR: break; /* down_rows reads it */
    case ROWS_DISPLACE: displace_frame_rows(r, STIN_TIER_GL2, path, cap); break;
    case ROWS_CSG: csg_frame_rows(r, STIN_TIER_GL2, path, bc->csg, bc->tech, cap); break;
    case ROWS_REFUSAL: /* browser_tests: refusal_row, sweep_row, skip_row */
    case ROWS_SWEEP:
    case ROWS_SKIP: break;
    }
}

void browser_tests(run *r, const char *dir, const char *list, const char *path)
{
    scene s, view;
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
        unsigned char *beauty;
        if (!in_list(list, bc->name) || (bc->scene && strcmp(bc->scene, scene_name) != 0))
            continue;
        if (bc->rows == ROWS_REFUSAL || bc->rows == ROWS_SWEEP) {
            (bc->rows == ROWS_SWEEP ? sweep_row : refusal_row)(r, dir, scene_name);
            continue;
        }
        if (bc->rows == ROWS_SKIP) {
            skip_row(r, dir, scene_name, bc);
            continue;
        }
        snprintf(name, sizeof name, "%s/%s/%s/gl-clean", stin_tier_name(bc->tier),
                 scene_name, bc->name);
        view = s;
        if (case_variant(bc) && !scene_variant_make(&s, case_variant(bc), &view)) {
            report(r, "FAIL", name, "no %s view of the scene", case_variant(bc));
            continue;
        }
        if (!load_case(r, dir, scene_name, &view, bc, &cap, &beauty, why, sizeof why)) {
            report(r, "FAIL", name, "%s", why);
            capture_free(&cap);
            scene_variant_free(&view, &s);
            continue;
        }
        if (cap.log_errors)
            report(r, "FAIL", name, "%u error logs (last: %s)", cap.log_errors, cap.last_error);
        else
            report(r, "PASS", name, "created, every frame STIN_OK with WebGL's error flag clear, "
                                    "no error logged, drawn by %s",
                   stin_technique_name(bc->tech));
        case_rows(r, bc, dir, path, scene_name, &view, &cap, beauty);
        free(beauty);
        capture_free(&cap);
        scene_variant_free(&view, &s);
    }
    scene_free(&s);
}
