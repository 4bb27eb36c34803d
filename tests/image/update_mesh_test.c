/* SPDX-License-Identifier: MIT */
/*
 * stin_update_mesh (issue 39, part 3) on a built-in scene: a closed tube
 * (flat-shaded, 12 segments x 12 slices, capped) over a floor under a low
 * sun, bent and slid along x over three frames by stin_update_mesh in one
 * context. Each frame's light-0 visibility is compared with the Embree
 * reference of that frame's geometry, per shadow technique of the tier
 * (GL1: volume, map-depth; GL2: volume, map-pcf; GL4: vdsm, volume,
 * map-pcf), on the pixels whose P matches, that the light reaches and that
 * lie farther than a band from a reference shadow edge (1 pixel for the
 * exact techniques, 3 for the maps' texels):
 *   update-TECH-N   at most 0.2% (exact) or 1% (maps) of them differ. A
 *                   caster left in its old shape or place (no upload, or
 *                   its old bounds fitting the map) differs on thousands.
 *   update-deep-N (GL4), update-coloured-N (GL2)  the tube see-through
 *                   (opacity 0.4: 0.36 through its two walls) under volumes:
 *                   the floor's visibility output within 2/255 of the
 *                   reference's transmittance on all but 1% (3-pixel band;
 *                   the tube's own pixels left out). Measured 0 on every
 *                   frame; without the upload 501 (1.5%) and 2,840 (8.1%)
 *                   on frames 1 and 2 for both.
 *   update-equals-create  after the last frame, the mesh destroyed and
 *                   created from the same data draws the same AOVs bit for
 *                   bit (the first technique of the tier).
 * Run where the paths differ and the cost stays small: gl11 (GL1 without
 * buffer objects: client arrays from the block), gl21 (GL1 with buffers,
 * GL2) and gl45-core (GL4) on EGL, gl11 on OSMesa too (its llvmpipe takes
 * 6 s for gl21's and 13 s for gl45-core's frames). Measured: 0 pixels
 * differ on every frame; without the upload, frames 1 and 2 differ on
 * 1.3-4.3% (maps, vdsm, GL4's extruded volumes) and the CPU-built volumes'
 * P misses 5,006 and 6,415 pixels (the tube drawn where it was).
 */
#include "aov.h"
#include "image_test.h"
#include "light_reach.h"
#include "reference.h"
#include "scene_primitives.h"
#include "test_context.h"
#include "vdsm_case.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SEGMENTS 12
#define SLICES 12
#define TUBE_TRIANGLES (2 * SEGMENTS * SLICES + 2 * SLICES)
#define RADIUS 0.3f
#define AXIS_Y 0.9f
#define FRAMES 3
#define LIFT 1.2f /* the last frame's rise: far past the frame before's bounds */
#define EXACT_BOUND 0.002
#define MAP_BOUND 0.01
#define MIN_SHADOWED 500 /* the tube's shadow must be in the comparison */
#define P_OFF_BOUND 0.001 /* the image tests' P bound: 99.9% */
#define P_REL 1e-3
#define P_ABS 1e-3
/* Translucent rows: the tube's opacity (below the 0.5 opaque threshold)
 * and the bound on the floor's transmittance, deep_case.h's: the 8-bit
 * output's rounding and the layers' float depth and colour. */
#define TUBE_ALPHA 0.4f
#define T_BOUND (2.0 / 255.0)

/* The tube at rest: three points a triangle, wound outward. */
static float rest[3 * 3 * TUBE_TRIANGLES];

static void ring_point(int i, int j, float out[3])
{
    double a = 2.0 * 3.14159265358979 * j / SLICES;
    out[0] = -1.0f + 2.0f * (float)i / SEGMENTS;
    out[1] = AXIS_Y + RADIUS * (float)cos(a);
    out[2] = RADIUS * (float)sin(a);
}

/* (b - a) x (c - a): the facet normal, its length twice the area. */
static void facet(const float *a, const float *b, const float *c, double n[3])
{
    double e1[3], e2[3];
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = (double)b[k] - a[k];
        e2[k] = (double)c[k] - a[k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

/* Triangle a, b, c into t, wound so that its facet faces `out`. */
static void put(float *t, const float a[3], const float b[3], const float c[3], const float out[3])
{
    double n[3];
    facet(a, b, c, n);
    memcpy(t, a, 3 * sizeof(float));
    if (n[0] * out[0] + n[1] * out[1] + n[2] * out[2] >= 0.0) {
        memcpy(t + 3, b, 3 * sizeof(float));
        memcpy(t + 6, c, 3 * sizeof(float));
    } else {
        memcpy(t + 3, c, 3 * sizeof(float));
        memcpy(t + 6, b, 3 * sizeof(float));
    }
}

static void make_rest(void)
{
    float *t = rest;
    int i, j;
    for (i = 0; i < SEGMENTS; i++)
        for (j = 0; j < SLICES; j++) {
            float p00[3], p10[3], p11[3], p01[3], out[3];
            ring_point(i, j, p00);
            ring_point(i + 1, j, p10);
            ring_point(i + 1, j + 1, p11);
            ring_point(i, j + 1, p01);
            out[0] = 0.0f;
            out[1] = p00[1] + p11[1] - 2.0f * AXIS_Y;
            out[2] = p00[2] + p11[2];
            put(t, p00, p10, p11, out);
            put(t + 9, p00, p11, p01, out);
            t += 18;
        }
    for (i = 0; i <= SEGMENTS; i += SEGMENTS)
        for (j = 0; j < SLICES; j++) {
            float c[3], a[3], b[3], out[3] = {i ? 1.0f : -1.0f, 0.0f, 0.0f};
            ring_point(i, j, a);
            ring_point(i, j + 1, b);
            c[0] = a[0];
            c[1] = AXIS_Y;
            c[2] = 0.0f;
            put(t, c, a, b, out);
            t += 9;
        }
}

/* Frame f's tube: bent by f x 0.7 radians over its length (its ends
 * rising), slid by 0.35 f along x, the last frame lifted by LIFT; facet
 * normals. */
static void pose(scene_mesh *m, int f)
{
    double angle = 0.7 * f, radius = angle > 0.0 ? 2.0 / angle : 0.0;
    uint32_t v, t;
    for (v = 0; v < 3u * TUBE_TRIANGLES; v++) {
        const float *p = rest + 3 * v;
        float *o = m->positions + 3 * v;
        if (angle > 0.0) {
            double phi = p[0] / radius, d = radius - (p[1] - AXIS_Y);
            o[0] = (float)(d * sin(phi)) + 0.35f * (float)f;
            o[1] = (float)(AXIS_Y + radius - d * cos(phi)) + LIFT * (float)(f / 2);
        } else {
            o[0] = p[0];
            o[1] = p[1];
        }
        o[2] = p[2];
    }
    for (t = 0; t < TUBE_TRIANGLES; t++) {
        const float *a = m->positions + 9 * t;
        double n[3], l;
        int k;
        facet(a, a + 3, a + 6, n);
        l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (v = 0; v < 3; v++)
            for (k = 0; k < 3; k++)
                m->normals[9 * t + 3 * v + (uint32_t)k] = (float)(n[k] / l);
    }
}

static int bend_scene(scene *s)
{
    int k;
    uint32_t i;
    memset(s, 0, sizeof *s);
    snprintf(s->path, sizeof s->path, "update-mesh");
    s->meshes = calloc(2, sizeof *s->meshes);
    s->materials = calloc(2, sizeof *s->materials);
    s->objects = calloc(2, sizeof *s->objects);
    s->lights = calloc(1, sizeof *s->lights);
    if (!s->meshes || !s->materials || !s->objects || !s->lights)
        return 0;
    s->mesh_count = s->object_count = 2;
    s->material_count = 2;
    s->light_count = 1;
    if (!scene_prim_plane(&s->meshes[0], 6.0f, 6.0f, 1, 1) ||
        !scene_mesh_alloc(&s->meshes[1], 3u * TUBE_TRIANGLES, TUBE_TRIANGLES))
        return 0;
    memset(s->meshes[1].uvs, 0, 2 * sizeof(float) * 3u * TUBE_TRIANGLES);
    for (i = 0; i < 3u * TUBE_TRIANGLES; i++)
        s->meshes[1].indices[i] = i;
    make_rest();
    pose(&s->meshes[1], 0);
    s->materials[0].color[0] = s->materials[0].color[1] = s->materials[0].color[2] = 0.7f;
    s->materials[0].color[3] = 1.0f;
    s->materials[0].shininess = 16.0f;
    s->materials[0].albedo = s->materials[0].normal = s->materials[0].height = -1;
    s->materials[1] = s->materials[0]; /* the translucent rows' tube */
    s->materials[1].color[3] = TUBE_ALPHA;
    for (i = 0; i < 2; i++) {
        s->objects[i].mesh = (int)i;
        for (k = 0; k < 16; k++)
            s->objects[i].transform[k] = k % 5 == 0 ? 1.0f : 0.0f;
    }
    s->lights[0].type = SCENE_LIGHT_DIRECTIONAL;
    s->lights[0].direction[0] = 0.45f;
    s->lights[0].direction[1] = -0.85f;
    s->lights[0].direction[2] = -0.27f;
    s->lights[0].color[0] = s->lights[0].color[1] = s->lights[0].color[2] = 1.0f;
    s->lights[0].intensity = 1.0f;
    s->lights[0].attenuation[0] = 1.0f;
    s->lights[0].spot_cutoff_deg = 45.0f;
    s->camera.eye[0] = 0.5f;
    s->camera.eye[1] = 3.0f;
    s->camera.eye[2] = 3.2f;
    s->camera.target[0] = 0.6f;
    s->camera.up[1] = 1.0f;
    s->camera.fovy_deg = 45.0f;
    s->camera.near_plane = 0.1f;
    s->camera.far_plane = 30.0f;
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 0.2f;
    s->width = 256;
    s->height = 192;
    return 1;
}

static int p_matches(const float *g, const ref_hit *h)
{
    double d = 0.0;
    int k;
    for (k = 0; k < 3; k++)
        d += (g[AOV_PX + k] - h->P[k]) * (g[AOV_PX + k] - h->P[k]);
    return sqrt(d) <= P_REL * h->t + P_ABS;
}

/* Light-0 visibility of a capture against the reference of the scene as
 * it is now: pixels differing, of those compared. translucent: the tube is
 * see-through, its own pixels are left out and the floor's transmittance
 * must be within T_BOUND (else lit and shadowed must agree). 0 when the
 * reference cannot be made (err says why). */
static int compare_frame(const scene *s, const image *img, int band, int translucent,
                         long *differ, long *compared, long *shadowed, long *p_off, char *err,
                         size_t err_size)
{
    int w = img->width, h = img->height, x, y, ok = 0;
    reference *ref = reference_create(s, err, err_size);
    ref_hit *hits = calloc((size_t)w * h, sizeof *hits);
    float *refimg = malloc(sizeof(float) * REFERENCE_CHANNELS * (size_t)w * h);
    *differ = *compared = *shadowed = *p_off = 0;
    if (ref && hits && refimg && reference_primary(ref, w, h, hits) &&
        reference_render(s, ref, w, h, 0, refimg)) {
        ok = 1;
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++) {
                const ref_hit *hit = &hits[(size_t)y * w + x];
                const float *g = vdsm_px(img, x, y);
                float truth = refimg[((size_t)y * w + x) * REFERENCE_CHANNELS +
                                     (translucent ? REFERENCE_CH_T_R : REFERENCE_CH_VIS_R)];
                if (!hit->hit || (translucent && hit->object == 1))
                    continue;
                if (!p_matches(g, hit)) {
                    (*p_off)++; /* the surface drawn is not this frame's */
                    continue;
                }
                if (!light_reaches(s, hit) || near_shadow_edge(hits, refimg, w, h, x, y, band))
                    continue;
                (*compared)++;
                *shadowed += truth < 0.5f;
                *differ += translucent ? fabs(g[AOV_VIS_R] - truth) > T_BOUND
                                       : (g[AOV_VIS_R] >= 0.5f) != (truth >= 0.5f);
            }
    } else if (ref) {
        snprintf(err, err_size, "the reference's rays failed");
    }
    free(refimg);
    free(hits);
    reference_destroy(ref);
    return ok;
}

static stin_result update(test_context *tc, const scene *s)
{
    stin_mesh_update_desc u = scene_gpu_mesh_update_desc(&s->meshes[1]);
    return stin_update_mesh(tc->ctx, tc->g.meshes[1], &u);
}

/* The last frame again with the tube destroyed and created from the same
 * data: the AOVs must be the same bytes. */
static void equals_create(run *r, stin_tier tier, test_context *tc, const scene *s,
                          const image *updated)
{
    char name[128], err[512];
    image again;
    stin_mesh_desc md;
    long differ = 0;
    size_t i, n = (size_t)updated->width * updated->height * AOV_CHANNELS;
    snprintf(name, sizeof name, "%s/update-mesh/update-equals-create", stin_tier_name(tier));
    stin_destroy_mesh(tc->ctx, tc->g.meshes[1]);
    md = scene_gpu_mesh_desc(&s->meshes[1]);
    memset(&again, 0, sizeof again);
    if (stin_create_mesh(tc->ctx, &md, &tc->g.meshes[1]) != STIN_OK ||
        !aov_capture(&tc->g, tc->ctx, r->plat, &again, NULL, NULL, err, sizeof err)) {
        report(r, "FAIL", name, "could not create and draw the mesh again");
        return;
    }
    for (i = 0; i < n; i++)
        differ += memcmp(&updated->pixels[i], &again.pixels[i], sizeof(float)) != 0;
    report(r, differ == 0 ? "PASS" : "FAIL", name,
           "%ld of %zu AOV values differ between the updated mesh and the created one (need 0)",
           differ, n);
    image_free(&again);
}

/* tech: a shadows technique for the opaque tube, or a translucent-shadows
 * one ("deep", "coloured": their maps' texels, so the maps' band and bound)
 * for the see-through tube, volumes for the opaque casters (none). */
static void one_technique(run *r, stin_tier tier, scene *s, stin_technique tech, int first)
{
    int translucent = tech == STIN_TECH_TRANSLUCENT_DEEP || tech == STIN_TECH_TRANSLUCENT_COLOURED;
    int exact = tech == STIN_TECH_SHADOWS_VDSM || tech == STIN_TECH_SHADOWS_VOLUME, f, band = exact ? 1 : 3;
    double bound = exact ? EXACT_BOUND : MAP_BOUND;
    test_context tc;
    char name[128], err[512];
    image img;
    int made;
    pose(&s->meshes[1], 0);
    s->objects[1].material = translucent;
    snprintf(name, sizeof name, "%s/update-mesh/update-%s", stin_tier_name(tier),
             stin_technique_name(tech));
    made = translucent ? test_context_create_translucent(&tc, r, s, tier,
                                                         STIN_TECH_SHADOWS_VOLUME, tech)
                       : test_context_create(&tc, r, s, tier, tech, 1);
    if (!made) { /* each listed one runs there */
        report(r, "FAIL", name, "no context running %s, or the scene could not be made",
               stin_technique_name(tech));
        return;
    }
    memset(&img, 0, sizeof img);
    for (f = 0; f < FRAMES; f++) {
        long differ = 0, compared = 0, shadowed = 0, p_off = 0;
        char frame_name[160];
        snprintf(frame_name, sizeof frame_name, "%s-%d", name, f);
        pose(&s->meshes[1], f);
        image_free(&img);
        if ((f > 0 && update(&tc, s) != STIN_OK) ||
            !aov_capture(&tc.g, tc.ctx, r->plat, &img, NULL, NULL, err, sizeof err)) {
            report(r, "FAIL", frame_name, "update or capture failed");
            break;
        }
        if (!compare_frame(s, &img, band, translucent, &differ, &compared, &shadowed, &p_off, err,
                           sizeof err)) {
            report(r, "FAIL", frame_name, "%s", err);
            break;
        }
        report(r, shadowed >= MIN_SHADOWED && differ <= bound * compared &&
                          p_off <= P_OFF_BOUND * compared ? "PASS" : "FAIL",
               frame_name,
               "light-0 visibility differs from this frame's reference%s on %ld of %ld pixels "
               "(%.3f%%; bound %.1f%%, %d-pixel edge band; %ld shadowed, at least %d); P off "
               "this frame's surface on %ld (at most 0.1%%)",
               translucent ? " by more than 2/255" : "", differ, compared, 100.0 * differ / (compared ? compared : 1), 100.0 * bound, band,
               shadowed, MIN_SHADOWED, p_off);
        if (f == FRAMES - 1 && first)
            equals_create(r, tier, &tc, s, &img);
    }
    image_free(&img);
    test_context_destroy(&tc);
}

void update_mesh_tests(run *r, stin_tier tier)
{
    static const stin_technique gl11[] = {STIN_TECH_SHADOWS_VOLUME, STIN_TECH_NONE};
    static const stin_technique gl1[] = {STIN_TECH_SHADOWS_VOLUME, STIN_TECH_SHADOWS_MAP_DEPTH,
                                         STIN_TECH_NONE};
    static const stin_technique gl2[] = {STIN_TECH_SHADOWS_VOLUME, STIN_TECH_SHADOWS_MAP_PCF,
                                         STIN_TECH_TRANSLUCENT_COLOURED, STIN_TECH_NONE};
    static const stin_technique gl4[] = {STIN_TECH_SHADOWS_VDSM, STIN_TECH_SHADOWS_VOLUME,
                                         STIN_TECH_SHADOWS_MAP_PCF, STIN_TECH_TRANSLUCENT_DEEP,
                                         STIN_TECH_NONE};
    const stin_technique *list;
    const char *p = r->profile_name;
    scene s;
    int i;
    if (tier == STIN_TIER_GL1 && !strcmp(p, "gl11"))
        list = gl11; /* no depth textures: volumes only */
    else if (strcmp(r->platform_name, "egl"))
        return; /* OSMesa: the client-array path only (its GL2 and GL4 cost seconds) */
    else if (tier == STIN_TIER_GL1 && !strcmp(p, "gl21"))
        list = gl1;
    else if (tier == STIN_TIER_GL2 && !strcmp(p, "gl21"))
        list = gl2;
    else if (tier == STIN_TIER_GL4 && !strcmp(p, "gl45-core"))
        list = gl4;
    else
        return;
    if (!bend_scene(&s)) {
        report(r, "FAIL", "update-mesh", "out of memory for the built-in scene");
        scene_free(&s);
        return;
    }
    for (i = 0; list[i] != STIN_TECH_NONE; i++)
        one_technique(r, tier, &s, list[i], i == 0);
    scene_free(&s);
}
