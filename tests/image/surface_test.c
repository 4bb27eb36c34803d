/*
 * GLSL surface detail (src/surface_glsl.c, shaders/gl2|gl4/surface_*.glsl):
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
 *                    bisections), unshadowed, on the normal-mapped pixels.
 * The reference comparisons count pixels within SURF_REF_TOLERANCE: the
 * reference samples albedo and normal map at level 0 while GL filters
 * mipmaps (the stone wall is minified 2-4x at 256x192), so brick edges,
 * bevels and mortar lines, where the maps change within a pixel, differ;
 * the fraction required is what that leaves (measured on llvmpipe, see
 * SURF_REF_MIN_MATCH) and the mean bounds a systematic error.
 */
#include "aov.h"
#include "capture.h"
#include "image_test.h"
#include "reference.h"
#include "reference_surface.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SURF_FLAT_TOLERANCE (1.0 / 255.0 + 1e-6)
/* straight down the shift V.xy h' is under 0.01 texel but not zero off the lens axis:
 * at the brick bevels (the normal map turns ~0.5 a texel) that is up to 2/255 */
#define SURF_DOWN_TOLERANCE (2.0 / 255.0 + 1e-6)
#define SURF_REF_TOLERANCE (8.0 / 255.0)
#define SURF_REF_MIN_MATCH 0.80
#define SURF_REF_MAX_MEAN (6.0 / 255.0)

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

static int render(run *r, const scene *s, stin_tier tier, stin_technique surface, capture *c,
                  const char *name)
{
    capture_options o;
    char err[512];
    memset(&o, 0, sizeof o);
    o.tier = tier;
    o.shadows = STIN_TECH_SHADOWS_OFF;
    o.surface = surface;
    if (!capture_render(r->plat, r->profile, s, &o, c, err, sizeof err)) {
        report(r, "FAIL", name, "%s: %s", stin_technique_name(surface), err);
        return 0;
    }
    if (c->counters.gl_violations || c->counters.gl_errors || c->log_errors) {
        report(r, "FAIL", name, "%s: %u profile violations, %u GL errors, %u error logs (last: %s)",
               stin_technique_name(surface), c->counters.gl_violations, c->counters.gl_errors,
               c->log_errors, c->last_error);
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
                                        "surface_parallax.glsl", "surface_pom.glsl",
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
    if (render(r, &flat, tier, STIN_TECH_SURFACE_NORMAL, &a, name)) {
        if (render(r, &flat, tier, STIN_TECH_SURFACE_PLAIN, &b, name)) {
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

/* The first normal-mapped object's centre and world normal (its mesh's first
 * vertex normal through the transform). */
static int mapped_object(const scene *s, float centre[3], float normal[3])
{
    int o, k;
    for (o = 0; o < s->object_count; o++) {
        const scene_material *m = &s->materials[s->objects[o].material];
        const scene_mesh *me = &s->meshes[s->objects[o].mesh];
        const float *x = s->objects[o].transform;
        float len;
        if (m->normal < 0 || !me->vertex_count)
            continue;
        for (k = 0; k < 3; k++) {
            centre[k] = x[12 + k];
            normal[k] = x[k] * me->normals[0] + x[4 + k] * me->normals[1] + x[8 + k] * me->normals[2];
        }
        len = sqrtf(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        for (k = 0; k < 3; k++)
            normal[k] /= len;
        return 1;
    }
    return 0;
}

static void test_down(run *r, stin_tier tier, const scene *s, const char *scene_name)
{
    char name[256];
    scene down = *s;
    float c[3], n[3];
    capture a, b;
    long cnt, over;
    double max;
    int k;
    snprintf(name, sizeof name, "%s/%s/parallax-down", stin_tier_name(tier), scene_name);
    if (!mapped_object(s, c, n)) {
        report(r, "SKIP", name, "no normal-mapped object");
        return;
    }
    for (k = 0; k < 3; k++) {
        down.camera.eye[k] = c[k] + 160.0f * n[k];
        down.camera.target[k] = c[k];
    }
    down.camera.up[0] = fabsf(n[1]) > 0.9f ? 1.0f : 0.0f;
    down.camera.up[1] = fabsf(n[1]) > 0.9f ? 0.0f : 1.0f;
    down.camera.up[2] = 0.0f;
    down.camera.fovy_deg = 0.25f;
    down.camera.near_plane = 150.0f;
    down.camera.far_plane = 170.0f;
    if (!render(r, &down, tier, STIN_TECH_SURFACE_PARALLAX, &a, name))
        return;
    if (render(r, &down, tier, STIN_TECH_SURFACE_NORMAL, &b, name)) {
        diff(&a, &b, SURF_DOWN_TOLERANCE, &cnt, &over, &max);
        report(r, cnt && !over ? "PASS" : "FAIL", name,
               "seen straight down (0.25-degree lens, |V.xy| < 0.003), parallax equals normal mapping within 2/255: "
               "%ld of %ld pixels over (max %.5f)", over, cnt, max);
        capture_free(&b);
    }
    capture_free(&a);
}

/* ---- reference comparisons ------------------------------------------------ */

static void test_reference(run *r, stin_tier tier, const scene *s, const char *scene_name,
                           stin_technique tech, int ref_tech, const char *test)
{
    char name[256], err[512];
    capture a;
    reference *ref = NULL;
    ref_surface *rs = NULL;
    ref_hit *hits = NULL;
    long n = 0, over = 0;
    double sum = 0, max = 0;
    int x, y, k;
    snprintf(name, sizeof name, "%s/%s/%s", stin_tier_name(tier), scene_name, test);
    if (!render(r, s, tier, tech, &a, name))
        return;
    ref = reference_create(s, err, sizeof err);
    rs = ref_surface_create(s);
    hits = malloc(sizeof *hits * (size_t)a.img.width * a.img.height);
    if (!ref || !rs || !hits || !reference_primary(ref, a.img.width, a.img.height, hits)) {
        report(r, "FAIL", name, "reference: %s", ref ? "out of memory" : err);
        goto done;
    }
    for (y = 0; y < a.img.height; y++)
        for (x = 0; x < a.img.width; x++) {
            const ref_hit *h = &hits[(size_t)(a.img.height - 1 - y) * a.img.width + x];
            const float *p = px(&a.img, x, y);
            float want[4];
            double d = 0;
            if (!h->hit || !(p[AOV_Z] > 0) ||
                s->materials[s->objects[h->object].material].normal < 0)
                continue;
            ref_surface_shade(s, rs, h, ref_tech, -1.0f, want, NULL);
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
               name, "%s vs the CPU reference: within %.4f on %.2f%% of %ld mapped pixels (max "
               "%.3f, mean %.5f; need %.0f%% and mean <= %.4f: level-0 reference vs GL mipmaps "
               "at brick edges)", stin_technique_name(tech), SURF_REF_TOLERANCE, 100.0 * match, n,
               max, mean, 100.0 * SURF_REF_MIN_MATCH, SURF_REF_MAX_MEAN);
    }
done:
    free(hits);
    ref_surface_destroy(rs);
    if (ref)
        reference_destroy(ref);
    capture_free(&a);
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
                           "normal-reference");
            test_reference(r, tier, &s, scene_name, STIN_TECH_SURFACE_POM, REF_SURFACE_POM,
                           "pom-reference");
        }
    }
    scene_free(&s);
}
