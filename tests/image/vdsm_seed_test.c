/* SPDX-License-Identifier: MIT */
/*
 * The seed's testable behaviours of VDSM (digest-000, "Testable behaviours")
 * that the scene-by-scene tests in vdsm_test.c do not already show, once per
 * run on GL4, on a built-in scene: eight spheres in a ring on a floor with a
 * point light at the ring's centre.
 *   omni-ring     (5) the light inside a ring of casters needs no light
 *                 frustum: the mask matches the ray cast as vdsm-vis asks
 *                 (nothing away from a reference shadow edge, at most 0.05%
 *                 on one), and every one of the eight spheres' directions
 *                 has its shadow on the floor (a frustum would cut some off).
 *   ep-halves     (8) on these closed spheres EP (dropping the triangles that
 *                 face the light, half of each sphere) leaves between 35% and
 *                 75% of SP's primitives (P_c). The seed's geometry shader
 *                 emitted 6 primitives a triangle, so P_c halved with the
 *                 triangles; stin's emits only the faces of a triangle's
 *                 volume that the eye sees, and the kept triangles (facing
 *                 away from the light) have more of those: measured 0.655.
 *   eye-at-light  (10) the camera at the light sees no shadow: every pixel
 *                 whose surface faces the eye faces the light, and vdsm
 *                 marks none of them shadowed - nor does the ray cast.
 * The other behaviours have their tests elsewhere: (1) exactness is
 * vdsm-vis on every scene; (2) map-size; (3) steps and chain; (4) vis on the
 * curved torus and spheres (no acne by construction); (6) vdsm-vis on
 * shadow-far, whose volumes reach past the far plane; (7) stin turns EP off
 * for open meshes, so shadow-open's single-sided quad casts (the seed's quad
 * cast nothing); (9) stin-bench --vdsm across the 18k/76k/174k scenes.
 */
#include "aov.h"
#include "scene_primitives.h"
#include "vdsm_case.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RING 8
#define RING_RADIUS 2.2f
#define BALL_RADIUS 0.5f
#define LIGHT_HEIGHT 0.6f
#define EP_LOW 0.35
#define EP_HIGH 0.75

static void identity(float m[16])
{
    int k;
    for (k = 0; k < 16; k++)
        m[k] = k % 5 == 0 ? 1.0f : 0.0f;
}

/* The ring scene; eye_at_light puts the camera at the light, looking at a
 * sphere. */
static int ring_scene(scene *s, int eye_at_light)
{
    int i;
    memset(s, 0, sizeof *s);
    snprintf(s->path, sizeof s->path, "vdsm-ring");
    s->meshes = calloc(2, sizeof *s->meshes);
    s->materials = calloc(1, sizeof *s->materials);
    s->objects = calloc(RING + 1, sizeof *s->objects);
    s->lights = calloc(1, sizeof *s->lights);
    if (!s->meshes || !s->materials || !s->objects || !s->lights)
        return 0;
    s->mesh_count = 2;
    s->material_count = 1;
    s->object_count = RING + 1;
    s->light_count = 1;
    if (!scene_prim_plane(&s->meshes[0], 14.0f, 14.0f, 4, 4) ||
        !scene_prim_sphere(&s->meshes[1], BALL_RADIUS, 24, 16))
        return 0;
    s->materials[0].color[0] = s->materials[0].color[1] = s->materials[0].color[2] = 0.7f;
    s->materials[0].color[3] = 1.0f;
    s->materials[0].shininess = 32.0f;
    s->materials[0].albedo = s->materials[0].normal = s->materials[0].height = -1;
    s->materials[0].height_scale = 0.04f;
    for (i = 0; i <= RING; i++) {
        identity(s->objects[i].transform);
        s->objects[i].mesh = i ? 1 : 0;
    }
    for (i = 1; i <= RING; i++) {
        double a = 2.0 * 3.14159265358979 * (i - 1) / RING;
        s->objects[i].transform[12] = (float)(RING_RADIUS * cos(a));
        s->objects[i].transform[13] = BALL_RADIUS;
        s->objects[i].transform[14] = (float)(RING_RADIUS * sin(a));
    }
    s->lights[0].type = SCENE_LIGHT_POINT;
    s->lights[0].position[1] = LIGHT_HEIGHT;
    s->lights[0].color[0] = s->lights[0].color[1] = s->lights[0].color[2] = 1.0f;
    s->lights[0].intensity = 1.0f;
    s->lights[0].attenuation[0] = 1.0f;
    s->lights[0].spot_cutoff_deg = 45.0f;
    s->camera.up[1] = 1.0f;
    s->camera.near_plane = 0.1f;
    s->camera.far_plane = 60.0f;
    if (eye_at_light) {
        s->camera.eye[1] = LIGHT_HEIGHT;
        s->camera.target[0] = RING_RADIUS;
        s->camera.target[1] = BALL_RADIUS;
        s->camera.fovy_deg = 80.0f;
    } else {
        s->camera.eye[1] = 9.0f;
        s->camera.eye[2] = 5.0f;
        s->camera.fovy_deg = 60.0f;
    }
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 0.1f;
    s->width = 256;
    s->height = 192;
    return 1;
}

/* Which of the eight spheres' directions (sector around the light's foot)
 * have reference-shadowed floor pixels that vdsm shadows too. */
static int sectors_shadowed(const vdsm_case *c, const capture *cap)
{
    int w = c->r->width, h = c->r->height, x, y, seen = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const ref_hit *hit = &c->hits[(size_t)y * w + x];
            double a;
            int sector;
            if (!hit->hit || hit->object != 0 || vdsm_truth(c, hit) >= 0.5f ||
                vdsm_px(&cap->img, x, y)[AOV_VIS_R] >= 0.5f)
                continue;
            a = atan2(hit->P[2], hit->P[0]);
            sector = (int)floor(a / (2.0 * 3.14159265358979 / RING) + 0.5);
            seen |= 1 << ((sector % RING + RING) % RING);
        }
    return seen;
}

static void test_ring(run *r)
{
    scene s;
    vdsm_case c;
    capture all, sp;
    char name[256];
    long compared, ambig, isolated, edge, differ;
    int seen, n = 0, k;
    if (!ring_scene(&s, 0)) {
        report(r, "FAIL", "gl4/vdsm-ring/vdsm-omni-ring", "out of memory building the scene");
        scene_free(&s);
        return;
    }
    if (!vdsm_case_open(&c, r, &s, "vdsm-ring", "omni-ring") ||
        !vdsm_render(&c, SET_ALL, &all, "omni-ring"))
        goto done;
    differ = vdsm_mismatches(&c, &all, &compared, &ambig, &isolated, &edge);
    seen = sectors_shadowed(&c, &all);
    for (k = 0; k < RING; k++)
        n += (seen >> k) & 1;
    vdsm_name(&c, "omni-ring", name, sizeof name);
    report(r,
           compared > 0 && differ == 0 && n == RING ? "PASS" : "FAIL", name,
           "light inside a ring of %d spheres: %ld of %ld pixels differ from the ray cast (need "
           "0; %ld ambiguous not counted); shadows on the floor in %d of %d directions (need "
           "all)", RING, differ, compared, ambig, n, RING);
    if (vdsm_render(&c, SET_SP, &sp, "ep-halves")) {
        unsigned ep_count = 0;
        capture ep;
        if (vdsm_render(&c, SET_EP, &ep, "ep-halves")) {
            ep_count = ep.stats.shadows.vdsm_primitives;
            capture_free(&ep);
        }
        vdsm_name(&c, "ep-halves", name, sizeof name);
        {
            double f = sp.stats.shadows.vdsm_primitives ? (double)ep_count / sp.stats.shadows.vdsm_primitives : 0;
            report(r, f >= EP_LOW && f <= EP_HIGH ? "PASS" : "FAIL", name,
                   "primitives emitted (P_c): SP %u, SP + EP %u, ratio %.3f (need %.2f..%.2f)",
                   sp.stats.shadows.vdsm_primitives, ep_count, f, EP_LOW, EP_HIGH);
        }
        capture_free(&sp);
    }
    capture_free(&all);
done:
    vdsm_case_close(&c);
    scene_free(&s);
}

static void test_eye_at_light(run *r)
{
    scene s;
    vdsm_case c;
    capture cap;
    char name[256];
    long compared, ambig, isolated, edge, differ, dark = 0, covered = 0;
    int w = r->width, h = r->height, x, y;
    if (!ring_scene(&s, 1)) {
        report(r, "FAIL", "gl4/vdsm-ring/vdsm-eye-at-light", "out of memory building the scene");
        scene_free(&s);
        return;
    }
    if (!vdsm_case_open(&c, r, &s, "vdsm-ring", "eye-at-light") ||
        !vdsm_render(&c, SET_ALL, &cap, "eye-at-light"))
        goto done;
    differ = vdsm_mismatches(&c, &cap, &compared, &ambig, &isolated, &edge);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const float *g = vdsm_px(&cap.img, x, y);
            if (!(g[AOV_Z] > 0.0f))
                continue;
            covered++;
            dark += g[AOV_VIS_R] < 0.5f;
        }
    vdsm_name(&c, "eye-at-light", name, sizeof name);
    report(r, covered > 0 && dark == 0 && differ == 0 ? "PASS" : "FAIL", name,
           "camera at the light: %ld of %ld covered pixels shadowed (need 0), %ld differ from "
           "the ray cast (need 0)", dark, covered, differ);
    capture_free(&cap);
done:
    vdsm_case_close(&c);
    scene_free(&s);
}

void vdsm_seed_tests(run *r, stin_tier tier)
{
    static int done;
    if (tier != STIN_TIER_GL4 || done)
        return;
    done = 1;
    test_ring(r);
    test_eye_at_light(r);
    vdsm_growth_tests(r);
}
