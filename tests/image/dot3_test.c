/* SPDX-License-Identifier: MIT */
/*
 * DOT3 bump mapping (GL1, src/surface/dot3.c), rendered:
 *   dot3-tilt   (built-in scene, once per tier) a quad under a directional
 *               light with constant normal maps — flat, tilted 30 degrees
 *               toward +T, -T and +B — equals the analytic
 *               ambient*albedo + max(n.L, 0)*light*albedo in the tangent
 *               frame (T = +x, B = -z, N = +y) within DOT3_TILT_TOLERANCE:
 *               proves the pass runs, the frame's signs and the cube map;
 *   dot3-flat   (every scene with a normal-mapped material) its normal maps
 *               replaced by a flat (128,128,255) one equal the same scene
 *               without normal maps (plain per-vertex lighting) within
 *               DOT3_FLAT_TOLERANCE, unshadowed and under shadow volumes;
 *   gl-clean    no GL error and no call outside the profile in those frames.
 * Under a tier or profile that does not select dot3 each reports SKIP with
 * the selection's reason.
 */
#include "aov.h"
#include "capture.h"
#include "image_test.h"
#include "test_context.h"
#include "scene_primitives.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Analytic case: the cube map's 8-bit directions, the DOT3 arithmetic and
 * the modulation on 8-bit values, then the 8-bit framebuffer: measured max
 * 2.3/255 on llvmpipe; 3/255 on every covered interior pixel. */
#define DOT3_TILT_TOLERANCE (3.0 / 255.0)
/* Flat map against Gouraud: per pixel N.L (normalised interpolated L) times
 * the interpolated unlit colour against interpolated per-vertex N.L colours,
 * and the clamp of attenuation * light * albedo before the N.L factor instead
 * of after it. 3/255 on 99% of the covered pixels, mean <= 1/255. */
#define DOT3_FLAT_TOLERANCE (3.0 / 255.0)
#define DOT3_FLAT_MIN_MATCH 0.99
#define DOT3_FLAT_MAX_MEAN (1.0 / 255.0)

static void test_name(char *out, size_t size, stin_tier tier, const char *scene, const char *test)
{
    snprintf(out, size, "%s/%s/%s", stin_tier_name(tier), scene, test);
}

/* The surface technique the run's profile selects at `tier`. */
static int surface_choice(run *r, stin_tier tier, stin_choice *out)
{
    stin_desc d;
    stin_context *ctx = NULL;
    size_t size;
    void *block;
    test_desc(r, tier, &d);
    d.max_meshes = d.max_textures = d.max_draws = 1;
    d.max_vertices = d.max_triangles = d.max_mesh_triangles = 64;
    size = stin_memory_size(&d);
    block = malloc(size);
    if (!block || stin_create(&d, block, size, &ctx) != STIN_OK) {
        free(block);
        return 0;
    }
    *out = stin_query_choice(ctx, STIN_FEATURE_SURFACE);
    stin_destroy(ctx);
    free(block);
    return 1;
}

static int dot3_selected(run *r, stin_tier tier, char *why, size_t size)
{
    stin_choice c;
    if (!surface_choice(r, tier, &c)) {
        snprintf(why, size, "no context at tier %s", stin_tier_name(tier));
        return 0;
    }
    if (c.technique == STIN_TECH_SURFACE_DOT3)
        return 1;
    snprintf(why, size, "surface is %s at tier %s (%s)", stin_technique_name(c.technique),
             stin_tier_name(tier), c.reason);
    return 0;
}

static const float *px(const image *img, int x, int y)
{
    return img->pixels + ((size_t)y * img->width + x) * AOV_CHANNELS;
}

static int clean(run *r, const char *name, const capture *c)
{
    if (!c->counters.gl_violations && !c->log_errors)
        return 1;
    report(r, "FAIL", name, "%u profile violations, %u error logs (last: %s)",
           c->counters.gl_violations, c->log_errors, c->last_error);
    return 0;
}

/* ---- dot3-tilt ------------------------------------------------------------ */

static uint8_t unorm8(double x) { return (uint8_t)floor(255.0 * (0.5 + 0.5 * x) + 0.5); }

static int tilt_scene(scene *s, const double n[3])
{
    int i;
    memset(s, 0, sizeof *s);
    snprintf(s->path, sizeof s->path, "dot3-tilt");
    s->meshes = calloc(1, sizeof *s->meshes);
    s->textures = calloc(1, sizeof *s->textures);
    s->materials = calloc(1, sizeof *s->materials);
    s->objects = calloc(1, sizeof *s->objects);
    s->lights = calloc(1, sizeof *s->lights);
    if (!s->meshes || !s->textures || !s->materials || !s->objects || !s->lights)
        return 0;
    s->mesh_count = s->texture_count = s->material_count = s->object_count = s->light_count = 1;
    if (!scene_prim_plane(&s->meshes[0], 2.0f, 2.0f, 1, 1))
        return 0;
    s->textures[0].kind = SCENE_TEXTURE_NORMAL;
    s->textures[0].width = s->textures[0].height = 4;
    s->textures[0].rgba = malloc(4 * 4 * 4);
    if (!s->textures[0].rgba)
        return 0;
    for (i = 0; i < 16; i++) {
        s->textures[0].rgba[4 * i + 0] = unorm8(n[0]);
        s->textures[0].rgba[4 * i + 1] = unorm8(n[1]);
        s->textures[0].rgba[4 * i + 2] = unorm8(n[2]);
        s->textures[0].rgba[4 * i + 3] = 255;
    }
    s->materials[0].color[0] = 0.8f;
    s->materials[0].color[1] = 0.6f;
    s->materials[0].color[2] = 0.4f;
    s->materials[0].color[3] = 1.0f;
    s->materials[0].shininess = 32.0f;
    s->materials[0].albedo = s->materials[0].height = -1;
    s->materials[0].normal = 0;
    for (i = 0; i < 16; i++)
        s->objects[0].transform[i] = i % 5 == 0 ? 1.0f : 0.0f;
    s->lights[0].type = SCENE_LIGHT_DIRECTIONAL;
    s->lights[0].direction[0] = -0.4f / 1.1180340f;
    s->lights[0].direction[1] = -1.0f / 1.1180340f;
    s->lights[0].direction[2] = 0.0f;
    s->lights[0].color[0] = s->lights[0].color[1] = s->lights[0].color[2] = 1.0f;
    s->lights[0].intensity = 1.0f;
    s->lights[0].attenuation[0] = 1.0f;
    s->lights[0].spot_cutoff_deg = 45.0f;
    s->camera.eye[0] = 0.0f;
    s->camera.eye[1] = 3.0f;
    s->camera.eye[2] = 0.5f;
    s->camera.up[1] = 1.0f;
    s->camera.fovy_deg = 45.0f;
    s->camera.near_plane = 0.1f;
    s->camera.far_plane = 100.0f;
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 0.1f;
    s->width = 256;
    s->height = 192;
    return 1;
}

static void test_tilt(run *r, stin_tier tier)
{
    /* tilts in the tangent frame (T, B, N) */
    const double t30 = 0.5, c30 = 0.86602540378;
    const struct { const char *name; double n[3]; } cases[] = {
        {"flat", {0, 0, 1}}, {"+T", {t30, 0, c30}}, {"-T", {-t30, 0, c30}}, {"+B", {0, t30, c30}}};
    const stin_technique shadows[2] = {STIN_TECH_SHADOWS_OFF, STIN_TECH_SHADOWS_VOLUME};
    char name[200], why[256], detail[1024] = "";
    double worst = 0;
    size_t used = 0;
    int c, sh, ok = 1, all_clean = 1;
    test_name(name, sizeof name, tier, "builtin", "dot3-tilt");
    if (!dot3_selected(r, tier, why, sizeof why)) {
        report(r, "SKIP", name, "%s", why);
        return;
    }
    for (c = 0; c < 4; c++)
        for (sh = 0; sh < 2; sh++) {
            scene s;
            capture cap;
            capture_options o;
            char err[512], cname[256];
            double L[3] = {0.4, 1.0, 0.0}, Lts[3], len, nb[3], ndotl = 0, expect[3], max = 0;
            long n = 0;
            int x, y, k;
            if (!tilt_scene(&s, cases[c].n)) {
                report(r, "FAIL", name, "out of memory");
                scene_free(&s);
                return;
            }
            /* the tangent-space light vector and the map as the combiner reads it */
            len = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
            Lts[0] = L[0] / len;  /* T = +x */
            Lts[1] = -L[2] / len; /* B = -z */
            Lts[2] = L[1] / len;  /* N = +y */
            for (k = 0; k < 3; k++) {
                nb[k] = 2.0 * (unorm8(cases[c].n[k]) / 255.0 - 0.5);
                ndotl += nb[k] * Lts[k];
            }
            for (k = 0; k < 3; k++) {
                double v = s.ambient[k] * s.materials[0].color[k] +
                           (ndotl > 0 ? ndotl : 0) * s.materials[0].color[k];
                expect[k] = v > 1 ? 1 : v;
            }
            memset(&o, 0, sizeof o);
            o.tier = tier;
            o.shadows = shadows[sh];
            if (!capture_render(r->plat, r->profile, &s, &o, &cap, err, sizeof err)) {
                report(r, "FAIL", name, "%s: %s", cases[c].name, err);
                scene_free(&s);
                return;
            }
            snprintf(cname, sizeof cname, "%s/gl-clean", name);
            all_clean &= clean(r, cname, &cap);
            for (y = 0; y < cap.img.height; y++)
                for (x = 0; x < cap.img.width; x++) {
                    const float *p = px(&cap.img, x, y);
                    if (!(p[AOV_Z] > 0) || fabs(p[AOV_PX]) > 0.9 || fabs(p[AOV_PZ]) > 0.9)
                        continue; /* the quad's interior only */
                    n++;
                    for (k = 0; k < 3; k++)
                        if (fabs(p[AOV_R + k] - expect[k]) > max)
                            max = fabs(p[AOV_R + k] - expect[k]);
                }
            if (!n || max > DOT3_TILT_TOLERANCE)
                ok = 0;
            if (max > worst)
                worst = max;
            if (sh == 0 && used < sizeof detail)
                used += (size_t)snprintf(detail + used, sizeof detail - used,
                                         "%s%s n.L %.3f max %.4f on %ld px", used ? "; " : "",
                                         cases[c].name, ndotl, max, n);
            capture_free(&cap);
            scene_free(&s);
        }
    if (all_clean) {
        snprintf(why, sizeof why, "%s/gl-clean", name);
        report(r, "PASS", why, "no GL error, no call outside the profile");
    }
    report(r, ok ? "PASS" : "FAIL", name,
           "constant normal maps equal ambient + max(n.L,0) light albedo within %.4f "
           "(worst %.4f, unshadowed and volume schedules): %s", DOT3_TILT_TOLERANCE, worst, detail);
}

/* ---- dot3-flat ------------------------------------------------------------ */

static int has_normal_map(const scene *s)
{
    int i;
    for (i = 0; i < s->material_count; i++)
        if (s->materials[i].normal >= 0)
            return 1;
    return 0;
}

int dot3_flat_scenes(const scene *s, scene *flat, scene *plain)
{
    scene_texture *tex = calloc((size_t)s->texture_count + 1, sizeof *tex);
    scene_material *mat = calloc((size_t)s->material_count + 1, sizeof *mat);
    int i, ok = tex && mat;
    *flat = *plain = *s;
    flat->textures = tex;
    plain->materials = mat;
    if (!ok)
        return 0;
    memcpy(tex, s->textures, sizeof *tex * (size_t)s->texture_count);
    for (i = 0; i < s->texture_count; i++)
        if (tex[i].kind == SCENE_TEXTURE_NORMAL) {
            size_t k, count = (size_t)tex[i].width * (size_t)tex[i].height;
            tex[i].rgba = malloc(4 * count);
            if (!tex[i].rgba)
                return 0;
            for (k = 0; k < count; k++) {
                tex[i].rgba[4 * k] = tex[i].rgba[4 * k + 1] = 128;
                tex[i].rgba[4 * k + 2] = tex[i].rgba[4 * k + 3] = 255;
            }
        }
    memcpy(mat, s->materials, sizeof *mat * (size_t)s->material_count);
    for (i = 0; i < s->material_count; i++)
        mat[i].normal = -1;
    return 1;
}

void dot3_flat_free(scene *flat, scene *plain, const scene *s)
{
    int i;
    if (flat->textures)
        for (i = 0; i < s->texture_count; i++)
            if (flat->textures[i].rgba != s->textures[i].rgba)
                free(flat->textures[i].rgba);
    free(flat->textures);
    free(plain->materials);
}

static void test_flat(run *r, stin_tier tier, const scene *s, const char *scene_name)
{
    const stin_technique shadows[2] = {STIN_TECH_SHADOWS_OFF, STIN_TECH_SHADOWS_VOLUME};
    char name[200], why[256], detail[512] = "";
    scene flat, plain;
    int sh, ok = 1, all_clean = 1, made = dot3_flat_scenes(s, &flat, &plain);
    size_t used = 0;
    test_name(name, sizeof name, tier, scene_name, "dot3-flat");
    if (!dot3_selected(r, tier, why, sizeof why)) {
        report(r, "SKIP", name, "%s", why);
        goto done;
    }
    if (!made) {
        report(r, "FAIL", name, "out of memory");
        goto done;
    }
    for (sh = 0; sh < 2; sh++) {
        capture a, b;
        capture_options o;
        char err[512], cname[256];
        long n = 0, over = 0;
        double max = 0, sum = 0, mean;
        int x, y, k;
        memset(&o, 0, sizeof o);
        o.tier = tier;
        o.shadows = shadows[sh];
        if (!capture_render(r->plat, r->profile, &flat, &o, &a, err, sizeof err)) {
            report(r, "FAIL", name, "%s", err);
            goto done;
        }
        if (!capture_render(r->plat, r->profile, &plain, &o, &b, err, sizeof err)) {
            report(r, "FAIL", name, "%s", err);
            capture_free(&a);
            goto done;
        }
        snprintf(cname, sizeof cname, "%s/gl-clean", name);
        all_clean &= clean(r, cname, &a);
        for (y = 0; y < a.img.height; y++)
            for (x = 0; x < a.img.width; x++) {
                const float *p = px(&a.img, x, y), *q = px(&b.img, x, y);
                double d = 0;
                if (!(p[AOV_Z] > 0) && !(q[AOV_Z] > 0))
                    continue;
                for (k = 0; k < 3; k++)
                    if (fabs(p[AOV_R + k] - q[AOV_R + k]) > d)
                        d = fabs(p[AOV_R + k] - q[AOV_R + k]);
                n++;
                sum += d;
                if (d > max)
                    max = d;
                if (d > DOT3_FLAT_TOLERANCE + 1e-6)
                    over++;
            }
        mean = n ? sum / n : 0;
        if (!n || over > (1.0 - DOT3_FLAT_MIN_MATCH) * n || mean > DOT3_FLAT_MAX_MEAN)
            ok = 0;
        used += (size_t)snprintf(detail + used, sizeof detail - used,
                                 "%s%s: %ld of %ld px over (max %.4f, mean %.5f)", used ? "; " : "",
                                 sh ? "volumes" : "unshadowed", over, n, max, mean);
        capture_free(&a);
        capture_free(&b);
    }
    if (all_clean) {
        snprintf(why, sizeof why, "%s/gl-clean", name);
        report(r, "PASS", why, "no GL error, no call outside the profile");
    }
    report(r, ok ? "PASS" : "FAIL", name,
           "flat (128,128,255) normal maps equal plain per-vertex lighting within %.4f on %.0f%% "
           "of covered pixels, mean <= 1/255: %s", DOT3_FLAT_TOLERANCE, 100.0 * DOT3_FLAT_MIN_MATCH,
           detail);
done:
    dot3_flat_free(&flat, &plain, s);
}

void dot3_tests(run *r, stin_tier tier, const char *path)
{
    static int tilt_done[5];
    scene s;
    char err[512], scene_name[128];
    if ((unsigned)tier < 5 && !tilt_done[tier]) {
        tilt_done[tier] = 1;
        test_tilt(r, tier);
    }
    if (!scene_load(path, &s, err, sizeof err))
        return; /* test_scene reported it */
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    if (has_normal_map(&s))
        test_flat(r, tier, &s, scene_name);
    scene_free(&s);
}
