/* SPDX-License-Identifier: MIT */
/*
 * GLSL surface detail (src/surface/glsl.c, shaders/gl2|gl4/surface_*.glsl):
 *   gl2-shaders      (once) every file in shaders/gl2 declares #version 110
 *                    or 120 and uses no GL3+ built-in or storage qualifier;
 *   flat-normal      (scenes with normal maps) the normal maps replaced by a
 *                    constant (128,128,255) one, surface "normal", equals
 *                    surface "plain" within 1/255 on every covered pixel;
 *   parallax-down    the scene's normal-mapped object seen straight down its
 *                    normal through a 0.25-degree lens: parallax equals normal
 *                    mapping within 2/255 (the shift V.xy h' is under 0.01 texel);
 *   normal-reference normal mapping against the CPU reference (decoded normal,
 *                    interpolated tangent frame) on the normal-mapped pixels;
 *   pom-reference    parallax occlusion mapping against the CPU height-field
 *                    march along each pixel's true ray (4096 steps + 40
 *                    bisections), unshadowed, on the normal-mapped pixels;
 *   parallax-limit   offset limiting: the albedo replaced by a uv gradient
 *                    (texel (i, j) = (i, j, 0), 256 a side), ambient 1 and no
 *                    lights, so the beauty's R,G is the sampled uv'; seen at a
 *                    grazing angle with height_scale raised to 0.3, the shift
 *                    uv' - uv (the hit's uv), taken to scene units on the
 *                    tangent plane, is at most |h'| = |h scale - bias| plus the
 *                    8-bit read-back (1/256 uv a channel) on every pixel off
 *                    the gradient's seam, and is V.xy h' (so the shift is really
 *                    measured); the test also counts the pixels where the
 *                    unlimited V.xy h' / V.z would exceed the bound (it must);
 *   pom-self-shadow  hard self-shadowing: white directional light at L.N 0.2,
 *                    ambient 0, no albedo or specular; the GL factor is the
 *                    beauty with self_shadow 1 over the beauty with 0 (same
 *                    N.L), the reference marches the light ray from its pom hit
 *                    (ref_surface_pom_shadow); self_shadow off would match only
 *                    where the reference is lit, which must fail the fraction.
 * The reference comparisons filter albedo and normal map as GL does: stin's
 * mip chains built on the CPU (reference_mips_create), trilinear at GL's
 * lambda = log2(rho) from the pixel's uv derivatives (footprint below; the
 * stone wall is minified 2-4x at 256x192), the normal map's filtered length
 * widening the highlight (Toksvig) as the lit shader does. They count pixels
 * within SURF_REF_TOLERANCE; the mean bounds a systematic error.
 */
#include "aov.h"
#include "capture.h"
#include "image_test.h"
#include "reference.h"
#include "reference_surface.h"
#include "scene_variant.h"
#include "surface_footprint.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SURF_FLAT_TOLERANCE (1.0 / 255.0 + 1e-6)
/* straight down the shift V.xy h' is under 0.01 texel but not zero off the lens axis:
 * at the brick bevels (the normal map turns ~0.5 a texel) that is up to 2/255 */
#define SURF_DOWN_TOLERANCE (2.0 / 255.0 + 1e-6)
/* Measured on llvmpipe (8/255 kept): normal mapping within it on 99.99% (max
 * 0.035, one or two pixels), pom on 99.94-99.96% (max 0.16 where a pom step
 * falls differently between GL's 8-32 steps and the reference's 4096), mean
 * 0.0020; a level-0 reference gets 83%, one without Toksvig 95.6% */
#define SURF_REF_TOLERANCE (8.0 / 255.0)
#define SURF_REF_MIN_MATCH 0.99
#define SURF_REF_MAX_MEAN (1.0 / 255.0)
/* parallax-limit: the height scale is raised (SCENE_VARIANT_LIMIT_SCALE) so
 * that the 8-bit read-back of the uv (1/256 uv a channel, 0.016 scene units
 * across the 4-unit wall) is small against |h'| (up to scale / 2); pixels
 * whose hit uv lies within the margin of the gradient's repeat seam (where
 * bilinear and mip filtering mix both ends) are left out */
#define SURF_LIMIT_UV_LSB (1.0 / 256.0)
#define SURF_LIMIT_MARGIN 0.12
#define SURF_LIMIT_MIN_MATCH 0.90
/* pom-self-shadow */
#define SURF_SHADOW_LIGHT_Z 0.2f
#define SURF_SHADOW_EPSILON 0.004 /* depth units: the shader's acne margin */
#define SURF_SHADOW_MIN_LIT 0.1   /* unshadowed beauty under which the ratio is noise */
#define SURF_SHADOW_TOLERANCE 0.25
#define SURF_SHADOW_MIN_MATCH 0.97

static const float *px(const image *img, int x, int y)
{
    return img->pixels + ((size_t)y * img->width + x) * AOV_CHANNELS;
}

static int has_normal_map(const scene *s)
{
    int i;
    for (i = 0; i < s->material_count; i++)
        if (s->materials[i].normal >= 0)
            return 1;
    return 0;
}

static int glsl_tier(run *r, stin_tier tier, const char *name)
{
    if (tier == STIN_TIER_GL1) {
        report(r, "SKIP", name, "tier gl1 has no GLSL surface techniques (dot3_test.c covers it)");
        return 0;
    }
    return 1;
}

/* debug: STIN_DEBUG_* flags (STIN_DEBUG_NO_DERIVATIVES: bare ES 2.0's paths) */
static int render(run *r, const scene *s, stin_tier tier, stin_technique surface, capture *c,
                  const char *name, uint64_t debug)
{
    capture_options o;
    char err[512];
    memset(&o, 0, sizeof o);
    o.tier = tier;
    o.shadows = STIN_TECH_SHADOWS_OFF;
    o.surface = surface;
    o.debug_flags = debug;
    if (!capture_render(r->plat, r->profile, s, &o, c, err, sizeof err)) {
        report(r, "FAIL", name, "%s: %s", stin_technique_name(surface), err);
        return 0;
    }
    if (c->counters.gl_violations || c->log_errors) {
        report(r, "FAIL", name, "%s: %u profile violations, %u error logs (last: %s)",
               stin_technique_name(surface), c->counters.gl_violations, c->log_errors,
               c->last_error);
        capture_free(c);
        return 0;
    }
    return 1;
}

/* Largest channel difference per covered pixel of two captures. */
static void diff(const capture *a, const capture *b, double tol, long *n, long *over, double *max)
{
    int x, y, k;
    *n = *over = 0;
    *max = 0;
    for (y = 0; y < a->img.height; y++)
        for (x = 0; x < a->img.width; x++) {
            const float *p = px(&a->img, x, y), *q = px(&b->img, x, y);
            double d = 0;
            if (!(p[AOV_Z] > 0) && !(q[AOV_Z] > 0))
                continue;
            for (k = 0; k < 3; k++)
                if (fabs(p[AOV_R + k] - q[AOV_R + k]) > d)
                    d = fabs(p[AOV_R + k] - q[AOV_R + k]);
            (*n)++;
            if (d > tol)
                (*over)++;
            if (d > *max)
                *max = d;
        }
}

/* ---- gl2-shaders ---------------------------------------------------------- */

static const char *const gl3_words[] = {"texture(", "textureLod", "textureGrad", "texelFetch",
                                        "textureSize", "textureOffset", "layout", "flat ",
                                        "gl_VertexID", "gl_InstanceID", "uint ", NULL};

static void test_gl2_shaders(run *r)
{
    static const char *const files[] = {"flat.frag", "lit.frag", "lit.vert", "normal.frag",
                                        "shadow_none.glsl", "surface_plain.glsl",
                                        "surface_frame.glsl", "surface_normal.glsl",
                                        "surface_parallax.glsl", "surface_pom.glsl", "displace.glsl", "displace_none.glsl",
                                        "volume.vert", NULL};
    char problems[1024] = "", path[256], line[512];
    size_t used = 0;
    int i, checked = 0;
    for (i = 0; files[i]; i++) {
        FILE *f;
        int ln = 0;
        snprintf(path, sizeof path, "shaders/gl2/%s", files[i]);
        f = fopen(path, "r");
        if (!f) {
            used += (size_t)snprintf(problems + used, used < sizeof problems ? sizeof problems - used : 0,
                                     "%s unreadable; ", path);
            continue;
        }
        checked++;
        while (fgets(line, sizeof line, f)) {
            const char *code = line;
            int w;
            ln++;
            while (*code == ' ')
                code++;
            if (!strncmp(code, "//", 2))
                continue;
            if (!strncmp(code, "#version", 8) && !strstr(code, "110") && !strstr(code, "120"))
                used += (size_t)snprintf(problems + used, used < sizeof problems ? sizeof problems - used : 0,
                                         "%s:%d %s; ", path, ln, "version not 110/120");
            if (!strncmp(code, "in ", 3) || !strncmp(code, "out ", 4))
                used += (size_t)snprintf(problems + used, used < sizeof problems ? sizeof problems - used : 0,
                                         "%s:%d in/out storage; ", path, ln);
            for (w = 0; gl3_words[w]; w++) {
                const char *hit = strstr(code, gl3_words[w]);
                const char *comment = strstr(code, "//");
                if (hit && (!comment || hit < comment) &&
                    (hit == code || !(hit[-1] == '_' || (hit[-1] >= 'a' && hit[-1] <= 'z') ||
                                      (hit[-1] >= 'A' && hit[-1] <= 'Z') ||
                                      (hit[-1] >= '0' && hit[-1] <= '9'))))
                    used += (size_t)snprintf(problems + used, used < sizeof problems ? sizeof problems - used : 0,
                                             "%s:%d uses %s; ", path, ln, gl3_words[w]);
            }
        }
        fclose(f);
    }
    if (problems[0])
        report(r, "FAIL", "gl2-shaders", "%s", problems);
    else
        report(r, "PASS", "gl2-shaders", "%d files in shaders/gl2 declare #version 110/120 and "
                                         "use no GL3+ built-in or in/out storage", checked);
}

/* ---- flat-normal ---------------------------------------------------------- */

static void test_flat(run *r, stin_tier tier, const scene *s, const char *scene_name)
{
    char name[256];
    scene flat = *s;
    scene_texture *tex = calloc((size_t)s->texture_count + 1, sizeof *tex);
    capture a, b;
    long n, over;
    double max;
    int i;
    snprintf(name, sizeof name, "%s/%s/flat-normal", stin_tier_name(tier), scene_name);
    if (!tex) {
        report(r, "FAIL", name, "out of memory");
        return;
    }
    memcpy(tex, s->textures, sizeof *tex * (size_t)s->texture_count);
    for (i = 0; i < s->texture_count; i++)
        if (tex[i].kind == SCENE_TEXTURE_NORMAL) {
            size_t k, count = (size_t)tex[i].width * (size_t)tex[i].height;
            tex[i].rgba = malloc(4 * count);
            for (k = 0; tex[i].rgba && k < count; k++) {
                tex[i].rgba[4 * k] = tex[i].rgba[4 * k + 1] = 128;
                tex[i].rgba[4 * k + 2] = tex[i].rgba[4 * k + 3] = 255;
            }
        }
    flat.textures = tex;
    if (render(r, &flat, tier, STIN_TECH_SURFACE_NORMAL, &a, name, 0)) {
        if (render(r, &flat, tier, STIN_TECH_SURFACE_PLAIN, &b, name, 0)) {
            diff(&a, &b, SURF_FLAT_TOLERANCE, &n, &over, &max);
            report(r, n && !over ? "PASS" : "FAIL", name,
                   "constant (128,128,255) normal map equals plain per-pixel lighting within "
                   "1/255: %ld of %ld covered pixels over (max %.5f)", over, n, max);
            capture_free(&b);
        }
        capture_free(&a);
    }
    for (i = 0; i < s->texture_count; i++)
        if (tex[i].rgba != s->textures[i].rgba)
            free(tex[i].rgba);
    free(tex);
}

/* ---- parallax-down -------------------------------------------------------- */

void surface_down_rows(run *r, const char *name, const capture *parallax, const capture *normal)
{
    long cnt, over;
    double max;
    diff(parallax, normal, SURF_DOWN_TOLERANCE, &cnt, &over, &max);
    report(r, cnt && !over ? "PASS" : "FAIL", name,
           "seen straight down (0.25-degree lens, |V.xy| < 0.003), parallax equals normal mapping within 2/255: "
           "%ld of %ld pixels over (max %.5f)", over, cnt, max);
}

static void test_down(run *r, stin_tier tier, const scene *s, const char *scene_name)
{
    char name[256];
    scene down;
    capture a, b;
    snprintf(name, sizeof name, "%s/%s/parallax-down", stin_tier_name(tier), scene_name);
    if (!scene_variant_down(s, &down)) {
        report(r, "SKIP", name, "no normal-mapped object");
        return;
    }
    if (!render(r, &down, tier, STIN_TECH_SURFACE_PARALLAX, &a, name, 0))
        return;
    if (render(r, &down, tier, STIN_TECH_SURFACE_NORMAL, &b, name, 0)) {
        surface_down_rows(r, name, &a, &b);
        capture_free(&b);
    }
    capture_free(&a);
}

/* ---- reference comparisons ------------------------------------------------ */

/* The uv the colour maps are sampled with, on hit's plane through window
 * point (px, py): moved by the technique (tech >= 0) or not (tech < 0). */
static int uv_at(const scene *s, const reference *ref, const ref_surface *rs, int w, int h,
                 const ref_hit *hit, double px, double py, int tech, double uv[2])
{
    ref_hit o;
    float rgba[4], moved[2];
    if (!reference_hit_on_plane(ref, w, h, hit, px, py, &o))
        return 0;
    moved[0] = o.uv[0];
    moved[1] = o.uv[1];
    if (tech >= 0)
        ref_surface_shade(s, rs, &o, tech, -1.0f, rgba, moved);
    uv[0] = moved[0];
    uv[1] = moved[1];
    return 1;
}

/* The derivatives GL's sampler takes for pixel (x, y) (window coordinates,
 * bottom-up): differences across the 2x2 quad holding it, on the pixel's own
 * triangle (helper pixels extend it), one level of detail per quad taken at
 * its upper-left pixel toward its right and lower neighbours (llvmpipe's
 * rasterizer runs rows top-down; GL allows coarse derivatives), or at its
 * lower-left pixel toward the one above where `low` (ANGLE on SwiftShader,
 * the browser's, measured: it draws through Vulkan, whose rows go down).
 * GL4's textureGrad is given the unmoved uv's (surface_frame.glsl:
 * tech < 0); GL2's texture2D differentiates the uv it samples, which pom
 * moves (tech >= 0), so at pom's steps the quad's pixel matters. */
int surface_footprint(const scene *s, const reference *ref, const ref_surface *rs, int w, int h,
                      int x, int y, const ref_hit *hit, int tech, int low, ref_footprint *fp)
{
    double ul[2], right[2], down[2];
    double left = (x & ~1) + 0.5, top = low ? (y & ~1) + 0.5 : (y | 1) + 0.5;
    int k;
    if (!uv_at(s, ref, rs, w, h, hit, left, top, tech, ul) ||
        !uv_at(s, ref, rs, w, h, hit, left + 1.0, top, tech, right) ||
        !uv_at(s, ref, rs, w, h, hit, left, low ? top + 1.0 : top - 1.0, tech, down))
        return 0;
    for (k = 0; k < 2; k++) {
        fp->dx[k] = right[k] - ul[k];
        fp->dy[k] = down[k] - ul[k];
    }
    return 1;
}

/* A frame's beauty against the CPU reference on the normal-mapped pixels
 * (one PASS/FAIL line; the frame drawn here or elsewhere: a browser's; low:
 * footprint's). */
static void reference_rows(run *r, stin_tier tier, const scene *s, stin_technique tech,
                           int ref_tech, int low, const char *name, const capture *a)
{
    char err[512];
    reference *ref = NULL;
    ref_surface *rs = NULL;
    ref_hit *hits = NULL;
    long n = 0, over = 0;
    double sum = 0, max = 0;
    int x, y, k;
    ref = reference_create(s, err, sizeof err);
    rs = ref_surface_create(s);
    hits = malloc(sizeof *hits * (size_t)a->img.width * a->img.height);
    if (!ref || !rs || !hits || !reference_primary(ref, a->img.width, a->img.height, hits)) {
        report(r, "FAIL", name, "reference: %s", ref ? "out of memory" : err);
        goto done;
    }
    for (y = 0; y < a->img.height; y++)
        for (x = 0; x < a->img.width; x++) {
            const ref_hit *h = &hits[(size_t)(a->img.height - 1 - y) * a->img.width + x];
            const float *p = px(&a->img, x, y);
            ref_footprint fp;
            float want[4];
            double d = 0;
            if (!h->hit || !(p[AOV_Z] > 0) ||
                s->materials[s->objects[h->object].material].normal < 0)
                continue;
            if (!surface_footprint(s, ref, rs, a->img.width, a->img.height, x,
                                   a->img.height - 1 - y, h,
                                   tier == STIN_TIER_GL2 ? ref_tech : -1, low, &fp)) {
                n++; /* no footprint (a ray along the plane): counted as differing */
                over++;
                continue;
            }
            ref_surface_shade_filtered(s, rs, h, ref_tech, -1.0f, &fp, want, NULL);
            for (k = 0; k < 3; k++)
                if (fabs(p[AOV_R + k] - want[k]) > d)
                    d = fabs(p[AOV_R + k] - want[k]);
            n++;
            sum += d;
            if (d > max)
                max = d;
            if (d > SURF_REF_TOLERANCE)
                over++;
        }
    {
        double match = n ? 1.0 - (double)over / n : 0, mean = n ? sum / n : 0;
        report(r, n && match >= SURF_REF_MIN_MATCH && mean <= SURF_REF_MAX_MEAN ? "PASS" : "FAIL",
               name, "%s vs the CPU reference (stin's mip chains at GL's level of detail): within "
               "%.4f on %.2f%% of %ld mapped pixels (max %.3f, mean %.5f; need %.0f%% and mean <= "
               "%.4f)", stin_technique_name(tech), SURF_REF_TOLERANCE, 100.0 * match, n, max, mean,
               100.0 * SURF_REF_MIN_MATCH, SURF_REF_MAX_MEAN);
    }
done:
    free(hits);
    ref_surface_destroy(rs);
    if (ref)
        reference_destroy(ref);
}

static void test_reference(run *r, stin_tier tier, const scene *s, const char *scene_name,
                           stin_technique tech, int ref_tech, const char *test, uint64_t debug)
{
    char name[256];
    capture a;
    snprintf(name, sizeof name, "%s/%s/%s", stin_tier_name(tier), scene_name, test);
    if (!render(r, s, tier, tech, &a, name, debug))
        return;
    reference_rows(r, tier, s, tech, ref_tech, 0, name, &a);
    capture_free(&a);
}

void surface_frame_rows(run *r, stin_tier tier, const char *path, stin_technique tech,
                        int low, const capture *cap)
{
    scene s;
    char err[512], name[256];
    int pom = tech == STIN_TECH_SURFACE_POM;
    snprintf(name, sizeof name, "%s/%s/%s", stin_tier_name(tier), scene_base_name(path),
             pom ? "pom-reference" : "normal-reference");
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    reference_rows(r, tier, &s, tech, pom ? REF_SURFACE_POM : REF_SURFACE_NORMAL, low, name, cap);
    scene_free(&s);
}

/* ---- parallax-limit ------------------------------------------------------- */

static int near_seam(double x, double margin)
{
    double f = x - floor(x);
    return f < margin || f > 1.0 - margin;
}

void surface_limit_rows(run *r, const char *name, const scene *g, int mi, const capture *a)
{
    char err[512];
    reference *ref;
    ref_surface *rs;
    ref_hit *hits;
    const double bias = 0.5 * SCENE_VARIANT_LIMIT_SCALE, e = SURF_LIMIT_UV_LSB;
    const double tol_h = SCENE_VARIANT_LIMIT_SCALE / 255.0;
    long cnt = 0, over = 0, agree = 0, unl_over = 0;
    double max_ratio = 0, max_tight = 0, max_excess = -1e30, max_tol = 0, max_unl = 0, min_vz = 1, max_shift = 0;
    int x, y, i, k;
    ref = reference_create(g, err, sizeof err);
    rs = ref_surface_create(g);
    hits = malloc(sizeof *hits * (size_t)a->img.width * a->img.height);
    if (!ref || !rs || !hits || !reference_primary(ref, a->img.width, a->img.height, hits)) {
        report(r, "FAIL", name, "reference: %s", ref ? "out of memory" : err);
        goto done;
    }
    for (y = 0; y < a->img.height; y++)
        for (x = 0; x < a->img.width; x++) {
            const ref_hit *h = &hits[(size_t)(a->img.height - 1 - y) * a->img.width + x];
            const float *p = px(&a->img, x, y);
            double hp, vt[3], duv[2], off[2], q[2], shift, tol = 0, lim, vxy, dev;
            if (!h->hit || !(p[AOV_Z] > 0) || g->objects[h->object].material != mi ||
                near_seam(h->uv[0], SURF_LIMIT_MARGIN) || near_seam(h->uv[1], SURF_LIMIT_MARGIN) ||
                !ref_surface_parallax_terms(g, rs, h, -1.0f, &hp, vt))
                continue;
            for (k = 0; k < 2; k++) { /* the sampled uv, unwrapped to the hit's period */
                double us = (p[AOV_R + k] * 255.0 + 0.5) / 256.0;
                us += floor(h->uv[k] - us + 0.5);
                duv[k] = us - h->uv[k];
            }
            if (!ref_surface_uv_to_plane(g, rs, h, duv, off))
                continue;
            for (i = 0; i < 2; i++) { /* 8-bit uv error (+-e, +-e) in scene units */
                double qe[2] = {e, i ? -e : e};
                ref_surface_uv_to_plane(g, rs, h, qe, q);
                if (sqrt(q[0] * q[0] + q[1] * q[1]) > tol)
                    tol = sqrt(q[0] * q[0] + q[1] * q[1]);
            }
            tol += tol_h;
            shift = sqrt(off[0] * off[0] + off[1] * off[1]);
            lim = fabs(hp);
            cnt++;
            if (shift > lim + tol)
                over++;
            if (shift - lim > max_excess)
                max_excess = shift - lim;
            if (tol > max_tol)
                max_tol = tol;
            if (shift > max_shift)
                max_shift = shift;
            if (lim >= 0.5 * bias && shift / lim > max_ratio)
                max_ratio = shift / lim;
            if (shift / (lim + tol) > max_tight)
                max_tight = shift / (lim + tol);
            dev = hypot(off[0] - vt[0] * hp, off[1] - vt[1] * hp);
            if (dev <= tol)
                agree++;
            /* what the unlimited offset V.xy h' / V.z would shift by here */
            vxy = hypot(vt[0], vt[1]);
            if (vt[2] < min_vz)
                min_vz = vt[2];
            if (vxy / (vt[2] > 1e-3 ? vt[2] : 1e-3) * lim > lim + tol)
                unl_over++;
            if (lim >= 0.5 * bias && vxy / (vt[2] > 1e-3 ? vt[2] : 1e-3) > max_unl)
                max_unl = vxy / (vt[2] > 1e-3 ? vt[2] : 1e-3);
        }
    {
        double match = cnt ? (double)agree / cnt : 0;
        report(r, cnt && !over && match >= SURF_LIMIT_MIN_MATCH && unl_over ? "PASS" : "FAIL",
               name, "parallax uv shift read back through a uv-gradient albedo (ambient 1, no "
               "lights, height_scale %.2f, grazing view V.z >= %.3f): |shift| <= |h'| + tol on "
               "%ld of %ld pixels (%ld over; max |shift| / (|h'| + tol) %.3f; max |shift| / |h'| %.3f "
               "where |h'| >= bias/2, max "
               "|shift| - |h'| %.4f, max |shift| %.4f; tol = 1/256 uv a channel in scene units + "
               "scale/255, up to %.4f); shift equals V.xy h' within tol on %.2f%% (need %.0f%%); "
               "the unlimited V.xy h' / V.z would exceed the bound on %ld pixels (up to %.2f |h'|)",
               SCENE_VARIANT_LIMIT_SCALE, min_vz, cnt - over, cnt, over, max_tight, max_ratio, max_excess, max_shift,
               max_tol, 100.0 * match, 100.0 * SURF_LIMIT_MIN_MATCH, unl_over, max_unl);
    }
done:
    free(hits);
    ref_surface_destroy(rs);
    if (ref)
        reference_destroy(ref);
}

static void test_parallax_limit(run *r, stin_tier tier, const scene *s, const char *scene_name)
{
    char name[256];
    scene g;
    capture a;
    int mi;
    snprintf(name, sizeof name, "%s/%s/parallax-limit", stin_tier_name(tier), scene_name);
    if (scene_variant_parallax_object(s) < 0) {
        report(r, "SKIP", name, "no object with normal and height maps");
        return;
    }
    if (!scene_variant_limit(s, &g, &mi)) {
        report(r, "FAIL", name, "out of memory");
        return;
    }
    if (render(r, &g, tier, STIN_TECH_SURFACE_PARALLAX, &a, name, 0)) {
        surface_limit_rows(r, name, &g, mi, &a);
        capture_free(&a);
    }
    scene_variant_free(&g, s);
}

/* ---- pom-self-shadow ------------------------------------------------------ */

static void test_pom_shadow(run *r, stin_tier tier, const scene *s, const char *scene_name)
{
    char name[256], err[512];
    scene g = *s;
    scene_material *mat = NULL;
    scene_light light;
    capture on, off;
    reference *ref = NULL;
    ref_surface *rs = NULL;
    ref_hit *hits = NULL;
    float c[3], n[3], t[3], b[3], l[3], len;
    long cnt = 0, agree = 0, agree_off = 0, gl_dark = 0, ref_dark = 0;
    int o, mi, x, y, k, have_on = 0, have_off = 0;
    snprintf(name, sizeof name, "%s/%s/pom-self-shadow", stin_tier_name(tier), scene_name);
    o = scene_variant_parallax_object(s);
    if (o < 0 || !scene_variant_mapped(s, c, n)) {
        report(r, "SKIP", name, "no object with normal and height maps");
        return;
    }
    mi = s->objects[o].material;
    mat = calloc((size_t)s->material_count, sizeof *mat);
    if (!mat) {
        report(r, "FAIL", name, "out of memory");
        return;
    }
    memcpy(mat, s->materials, sizeof *mat * (size_t)s->material_count);
    mat[mi].albedo = -1; /* beauty = N.L * shadow: white, no specular */
    for (k = 0; k < 4; k++)
        mat[mi].color[k] = 1.0f;
    for (k = 0; k < 3; k++)
        mat[mi].specular[k] = 0.0f;
    mat[mi].self_shadow = 1;
    scene_variant_plane(n, t, b);
    /* a grazing white directional light (L.N = SURF_SHADOW_LIGHT_Z), from
     * above and the side: brick ledges shadow the mortar under them */
    for (k = 0; k < 3; k++)
        l[k] = SURF_SHADOW_LIGHT_Z * n[k] + 0.6f * t[k] + 0.8f * b[k] * 1.0f;
    len = sqrtf(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    memset(&light, 0, sizeof light);
    light.type = SCENE_LIGHT_DIRECTIONAL;
    for (k = 0; k < 3; k++) {
        l[k] /= len;
        light.direction[k] = -l[k];
        light.color[k] = 1.0f;
    }
    light.intensity = 1.0f;
    light.attenuation[0] = 1.0f;
    light.spot_cutoff_deg = 45.0f;
    g.materials = mat;
    g.lights = &light;
    g.light_count = 1;
    for (k = 0; k < 3; k++)
        g.ambient[k] = 0.0f;
    if (!render(r, &g, tier, STIN_TECH_SURFACE_POM, &on, name, 0))
        goto done;
    have_on = 1;
    mat[mi].self_shadow = 0;
    if (!render(r, &g, tier, STIN_TECH_SURFACE_POM, &off, name, 0))
        goto done;
    have_off = 1;
    mat[mi].self_shadow = 1;
    ref = reference_create(&g, err, sizeof err);
    rs = ref_surface_create(&g);
    hits = malloc(sizeof *hits * (size_t)on.img.width * on.img.height);
    if (!ref || !rs || !hits || !reference_primary(ref, on.img.width, on.img.height, hits)) {
        report(r, "FAIL", name, "reference: %s", ref ? "out of memory" : err);
        goto done;
    }
    for (y = 0; y < on.img.height; y++)
        for (x = 0; x < on.img.width; x++) {
            const ref_hit *h = &hits[(size_t)(on.img.height - 1 - y) * on.img.width + x];
            const float *p = px(&on.img, x, y), *q = px(&off.img, x, y);
            double gl, want;
            if (!h->hit || !(p[AOV_Z] > 0) || !(q[AOV_Z] > 0) ||
                s->objects[h->object].material != mi || q[AOV_R] < SURF_SHADOW_MIN_LIT)
                continue;
            gl = p[AOV_R] / q[AOV_R]; /* the same N.L either way: the shadow factor */
            want = ref_surface_pom_shadow(&g, rs, h, l, SURF_SHADOW_EPSILON, NULL, NULL);
            cnt++;
            if (fabs(gl - want) <= SURF_SHADOW_TOLERANCE)
                agree++;
            if (fabs(1.0 - want) <= SURF_SHADOW_TOLERANCE)
                agree_off++;
            if (gl < 0.5)
                gl_dark++;
            if (want < 0.5)
                ref_dark++;
        }
    {
        double match = cnt ? (double)agree / cnt : 0, match_off = cnt ? (double)agree_off / cnt : 0;
        report(r, cnt && match >= SURF_SHADOW_MIN_MATCH && match_off < SURF_SHADOW_MIN_MATCH ? "PASS"
                                                                                               : "FAIL",
               name, "hard pom self-shadow factor (beauty with / without self_shadow, ambient 0, "
               "white directional light at L.N %.2f) vs the CPU march toward the light from the "
               "reference pom hit: within %.2f on %.2f%% of %ld lit mapped pixels (need %.0f%%; "
               "shadowed: GL %.2f%%, reference %.2f%%); self_shadow off would match on %.2f%%",
               SURF_SHADOW_LIGHT_Z, SURF_SHADOW_TOLERANCE, 100.0 * match, cnt,
               100.0 * SURF_SHADOW_MIN_MATCH, cnt ? 100.0 * gl_dark / cnt : 0.0,
               cnt ? 100.0 * ref_dark / cnt : 0.0, 100.0 * match_off);
    }
done:
    free(hits);
    ref_surface_destroy(rs);
    if (ref)
        reference_destroy(ref);
    if (have_on)
        capture_free(&on);
    if (have_off)
        capture_free(&off);
    free(mat);
}

void surface_tests(run *r, stin_tier tier, const char *path)
{
    static int shaders_done;
    scene s;
    char err[512], scene_name[128], name[256];
    if (!shaders_done) {
        shaders_done = 1;
        test_gl2_shaders(r);
    }
    if (!scene_load(path, &s, err, sizeof err))
        return; /* test_scene reported it */
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    if (has_normal_map(&s)) {
        snprintf(name, sizeof name, "%s/%s/surface", stin_tier_name(tier), scene_name);
        if (glsl_tier(r, tier, name)) {
            test_flat(r, tier, &s, scene_name);
            test_down(r, tier, &s, scene_name);
            test_reference(r, tier, &s, scene_name, STIN_TECH_SURFACE_NORMAL, REF_SURFACE_NORMAL,
                           "normal-reference", 0);
            test_reference(r, tier, &s, scene_name, STIN_TECH_SURFACE_POM, REF_SURFACE_POM,
                           "pom-reference", 0);
            /* the same bounds without derivatives (bare ES 2.0's GLSL):
             * the tangent attribute's frame, the mesh's mean uv scale;
             * once, on gl21 on egl */
            if (tier == STIN_TIER_GL2 && !strcmp(r->profile_name, "gl21") &&
                !strcmp(r->platform_name, "egl")) {
                test_reference(r, tier, &s, scene_name, STIN_TECH_SURFACE_NORMAL,
                               REF_SURFACE_NORMAL, "normal-reference-no-derivatives",
                               STIN_DEBUG_NO_DERIVATIVES);
                test_reference(r, tier, &s, scene_name, STIN_TECH_SURFACE_POM, REF_SURFACE_POM,
                               "pom-reference-no-derivatives", STIN_DEBUG_NO_DERIVATIVES);
            }
            test_parallax_limit(r, tier, &s, scene_name);
            test_pom_shadow(r, tier, &s, scene_name);
        }
    }
    scene_free(&s);
}
