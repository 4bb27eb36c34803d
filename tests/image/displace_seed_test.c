/* SPDX-License-Identifier: MIT */
/*
 * The seed's displacement behaviour 5 (digest-002, "Testable behaviours"),
 * once per GLSL tier on a built-in scene: a plate of 16 x 16 quads with a
 * constant height map (every texel 255), height_scale 0.5, bias 0, seen at
 * a slant with nothing behind it.
 *   constant-height  every covered pixel's P lies at y = 0.5 (within 1e-4:
 *                    h = 1 exactly, so every vertex moves by 0.5 along +y),
 *                    under "displace" and, where there is tessellation,
 *                    "displace-tess"; and the coverage differs from the
 *                    undisplaced plate's (the silhouette moves), so the test
 *                    sees the displacement rather than a plate drawn at 0.5.
 *   tess-bounded     one 64 x 64 frame of the plate (512 triangles) under vdsm
 *                    and "displace-tess" with desc.displacement.tess_pixels
 *                    0.02 emits exactly the primitives (GL_PRIMITIVES_GENERATED
 *                    around the whole frame, the caller's query) of the same
 *                    frame at 1 pixel: stin raises the target to 1 pixel.
 *                    Before, the 0.02 frame tessellated 2,500 times finer
 *                    (over 120 s on llvmpipe). A count, not a clock, so a
 *                    loaded machine cannot fail it.
 * Behaviours 3 (a side view shows a bumpy silhouette) and 6 (the guard band
 * changes no pixel) are displace_test.c's silhouette and guard-band tests.
 */
#include "aov.h"
#include "caller_gl.h"
#include "capture.h"
#include "image_test.h"
#include "scene_gpu.h"
#include "scene_primitives.h"
#include "test_context.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PLATE_Y 0.5f
#define P_TOLERANCE 1e-4
#define MAP 8

static int plate_scene(scene *s)
{
    int k;
    memset(s, 0, sizeof *s);
    snprintf(s->path, sizeof s->path, "displace-constant");
    s->meshes = calloc(1, sizeof *s->meshes);
    s->materials = calloc(1, sizeof *s->materials);
    s->objects = calloc(1, sizeof *s->objects);
    s->textures = calloc(1, sizeof *s->textures);
    s->lights = calloc(1, sizeof *s->lights);
    if (!s->meshes || !s->materials || !s->objects || !s->textures || !s->lights)
        return 0;
    s->mesh_count = s->material_count = s->object_count = s->texture_count = s->light_count = 1;
    if (!scene_prim_plane(&s->meshes[0], 2.0f, 2.0f, 16, 16))
        return 0;
    s->textures[0].kind = SCENE_TEXTURE_HEIGHT;
    s->textures[0].width = s->textures[0].height = MAP;
    s->textures[0].rgba = malloc(4 * MAP * MAP);
    if (!s->textures[0].rgba)
        return 0;
    memset(s->textures[0].rgba, 255, 4 * MAP * MAP);
    s->materials[0].color[0] = s->materials[0].color[1] = s->materials[0].color[2] = 0.7f;
    s->materials[0].color[3] = 1.0f;
    s->materials[0].shininess = 32.0f;
    s->materials[0].albedo = s->materials[0].normal = -1;
    s->materials[0].height = 0;
    s->materials[0].height_scale = 0.5f;
    s->materials[0].height_bias = 0.0f;
    s->materials[0].has_height_bias = 1;
    s->materials[0].displace = 1;
    for (k = 0; k < 16; k++)
        s->objects[0].transform[k] = k % 5 == 0 ? 1.0f : 0.0f;
    s->lights[0].type = SCENE_LIGHT_DIRECTIONAL;
    s->lights[0].direction[1] = -1.0f;
    s->lights[0].color[0] = s->lights[0].color[1] = s->lights[0].color[2] = 1.0f;
    s->lights[0].intensity = 1.0f;
    s->lights[0].attenuation[0] = 1.0f;
    s->lights[0].spot_cutoff_deg = 45.0f;
    s->camera.eye[0] = 1.2f;
    s->camera.eye[1] = 1.0f;
    s->camera.eye[2] = 2.6f;
    s->camera.up[1] = 1.0f;
    s->camera.fovy_deg = 45.0f;
    s->camera.near_plane = 0.1f;
    s->camera.far_plane = 20.0f;
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 0.2f;
    s->width = 128;
    s->height = 96;
    return 1;
}

/* Covered pixels, and of them those whose P.y is off PLATE_Y. */
static long off_plane(const capture *cap, long *covered, double *worst)
{
    size_t i, n = (size_t)cap->img.width * cap->img.height;
    long off = 0;
    *covered = 0;
    *worst = 0;
    for (i = 0; i < n; i++) {
        const float *g = cap->img.pixels + i * AOV_CHANNELS;
        double d;
        if (!(g[AOV_Z] > 0.0f))
            continue;
        (*covered)++;
        d = fabs(g[AOV_PX + 1] - PLATE_Y);
        *worst = d > *worst ? d : *worst;
        off += d > P_TOLERANCE;
    }
    return off;
}

static long coverage_differs(const capture *a, const capture *b)
{
    size_t i, n = (size_t)a->img.width * a->img.height;
    long d = 0;
    for (i = 0; i < n; i++)
        d += (a->img.pixels[i * AOV_CHANNELS + AOV_Z] > 0.0f) !=
             (b->img.pixels[i * AOV_CHANNELS + AOV_Z] > 0.0f);
    return d;
}

static void one(run *r, stin_tier tier, const scene *s, stin_technique t, const capture *flat)
{
    capture_options o;
    capture cap;
    char err[512], name[256];
    long covered, off, moved;
    double worst;
    snprintf(name, sizeof name, "%s/displace-constant/%s-constant-height", stin_tier_name(tier),
             stin_technique_name(t));
    memset(&o, 0, sizeof o);
    o.tier = tier;
    o.shadows = STIN_TECH_SHADOWS_OFF;
    o.displacement = t;
    if (!capture_render(r->plat, r->profile, s, &o, &cap, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    off = off_plane(&cap, &covered, &worst);
    moved = coverage_differs(&cap, flat);
    report(r, covered > 0 && off == 0 && moved > 0 ? "PASS" : "FAIL", name,
           "height 1 x scale 0.5: %ld of %ld covered pixels off y = 0.5 by more than 1e-4 "
           "(need 0; largest %.2g); coverage differs from the flat plate's on %ld (need > 0)",
           off, covered, worst, moved);
    capture_free(&cap);
}

/* One 64 x 64 frame of the plate under vdsm and displace-tess at
 * tess_pixels, inside the caller's GL_PRIMITIVES_GENERATED query: 1 with
 * *count and the target stin took; 0 (why) where the frame cannot run,
 * -1 where the profile runs no vdsm with displace-tess. */
static int tess_frame(run *r, const scene *s, float tess_pixels, GLuint *count, float *taken,
                      char *why, size_t why_size)
{
    static const int viewport[4] = {0, 0, 64, 64};
    caller_gl gl;
    test_context t;
    stin_desc d;
    size_t size;
    GLuint query = 0;
    stin_result res;
    caller_gl_load(&gl, r->plat);
    if (!gl.GenQueries || !gl.BeginQuery || !gl.EndQuery || !gl.GetQueryObjectuiv ||
        !gl.DeleteQueries) {
        snprintf(why, why_size, "no query entry points");
        return 0;
    }
    memset(&t, 0, sizeof t);
    test_desc(r, STIN_TIER_GL4, &d);
    d.techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_VDSM;
    d.techniques[STIN_FEATURE_DISPLACEMENT] = STIN_TECH_DISPLACEMENT_TESS;
    d.displacement.tess_pixels = tess_pixels;
    scene_gpu_size_desc(s, &d);
    size = stin_memory_size(&d);
    t.block = malloc(size);
    if (!t.block || stin_create(&d, t.block, size, &t.ctx) != STIN_OK) {
        free(t.block);
        return -1;
    }
    if (!scene_gpu_create(&t.g, s, t.ctx, why, why_size)) {
        test_context_destroy(&t);
        return 0;
    }
    *taken = stin_query_desc(t.ctx).displacement.tess_pixels;
    gl.GenQueries(1, &query);
    gl.BeginQuery(GL_PRIMITIVES_GENERATED, query);
    res = scene_gpu_frame_viewport(&t.g, t.ctx, viewport, STIN_OUTPUT_BEAUTY, STIN_EXPORT_NONE,
                                   stin_platform_framebuffer(r->plat));
    gl.EndQuery(GL_PRIMITIVES_GENERATED);
    gl.GetQueryObjectuiv(query, GL_QUERY_RESULT, count);
    gl.DeleteQueries(1, &query);
    test_context_destroy(&t);
    if (res != STIN_OK) {
        snprintf(why, why_size, "frame: %s", stin_result_name(res));
        return 0;
    }
    return 1;
}

static void tess_bounded(run *r, const scene *s)
{
    const char *name = "gl4/displace-constant/tess-bounded";
    char why[256] = "";
    GLuint fine = 0, pixel = 0;
    float fine_taken = 0, pixel_taken = 0;
    int got = tess_frame(r, s, 1.0f, &pixel, &pixel_taken, why, sizeof why);
    if (got < 0) {
        report(r, "SKIP", name, "the profile runs no vdsm with displace-tess");
        return;
    }
    if (got)
        got = tess_frame(r, s, 0.02f, &fine, &fine_taken, why, sizeof why);
    if (got <= 0) {
        report(r, "FAIL", name, "%s", why);
        return;
    }
    report(r, fine == pixel && pixel > 0 && fine_taken >= 1.0f ? "PASS" : "FAIL", name,
           "a 64x64 vdsm frame of 512 triangles at tess_pixels 0.02 (taken as %.2f) emitted "
           "%u primitives; at 1 pixel %u (need equal)", (double)fine_taken, fine, pixel);
}

void displace_seed_tests(run *r, stin_tier tier, uint64_t caps)
{
    static unsigned done;
    scene s;
    capture flat;
    capture_options o;
    char err[512];
    if (tier == STIN_TIER_GL1 || (done & (1u << tier)))
        return;
    done |= 1u << tier;
    if (!plate_scene(&s)) {
        report(r, "FAIL", "displace-constant", "out of memory building the scene");
        scene_free(&s);
        return;
    }
    memset(&o, 0, sizeof o);
    o.tier = tier;
    o.shadows = STIN_TECH_SHADOWS_OFF;
    o.displacement = STIN_TECH_DISPLACEMENT_OFF;
    if (!capture_render(r->plat, r->profile, &s, &o, &flat, err, sizeof err)) {
        report(r, "FAIL", "displace-constant", "%s", err);
        scene_free(&s);
        return;
    }
    one(r, tier, &s, STIN_TECH_DISPLACEMENT_VTF, &flat);
    if (tier == STIN_TIER_GL4 && (caps & STIN_CAP_BIT(STIN_CAP_TESSELLATION))) {
        one(r, tier, &s, STIN_TECH_DISPLACEMENT_TESS, &flat);
        tess_bounded(r, &s);
    }
    capture_free(&flat);
    scene_free(&s);
}
