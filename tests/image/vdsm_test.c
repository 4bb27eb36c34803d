/* SPDX-License-Identifier: MIT */
/*
 * VDSM ("vdsm", GL4) against the Embree visibility reference, light 0:
 *   vis        no pixel differs from the ray-cast visibility of its
 *              surface point (an area light made a point at its centre:
 *              soft_test.c measures vdsm's soft pass). Not counted, and
 *              reported: pixels where the
 *              reference is ambiguous (vdsm_case.c) - its answer changes
 *              when the ray origin moves along the surface by 1e-5 of the
 *              light's and the eye's distance (a shadow ray grazing an
 *              edge), the surface is within 1e-4 of edge-on to the light,
 *              the ray cast from the point stin shaded (its P output) gives
 *              stin's answer, or the pixel's centre lies within 1/256
 *              pixel (the rasterizer's vertex snap) of an edge of the
 *              triangle the camera ray hit, so the GPU may have drawn the
 *              triangle across it. Compared: covered pixels whose P
 *              matches the reference's.
 *   no-grow    the same count without conservative growth (the seed's
 *              isolated lit pixels): it may not come out lower than with it.
 *   steps      SP alone (EP, SM and DC off) gives the identical mask to
 *              SP + EP on every pixel away from a reference shadow edge
 *              (open meshes have EP off anyway), and at most 0.05% differ on
 *              one: EP changes which triangles a grazing segment is tested
 *              against, and which of two that share an edge it hits is
 *              rounding.
 *   chain      SP + EP, + SM and + SM + DC give pixel-identical masks,
 *              tolerance 0: SM drops only triangles whose every shadowed
 *              pixel a nearer drawn triangle shadows too (tested against the
 *              same segment), DC only what no pixel's test can hit, so no
 *              test on any pixel changes. Reports each set's primitive count
 *              (the seed's P_c).
 *   depth-test the full chain with and without the shadow faces' depth test
 *              against the visible surface give pixel-identical masks
 *              (tolerance 0): a face it drops lies behind the surface, where
 *              the eye ray has not yet entered the volume, so no test it
 *              skips could hit.
 *   cull-pass  the full chain culled first into a buffer by transform
 *              feedback and drawn from it (the default on GL 3.2+ without
 *              tessellated draws), and in one geometry shader
 *              (STIN_DEBUG_VDSM_ONE_PASS), give pixel-identical masks
 *              (tolerance 0) and emit the same primitives: both run the same
 *              tests on the same world points. The default render must have
 *              drawn every light from a culling pass that kept some faces
 *              and no more than 4 a triangle, the one-pass render from none.
 *   culls      (spheres scenes) SM and DC each emit fewer primitives than
 *              the step set before them: a cull that drops nothing fails.
 *   map-size   the light pyramid at 64 texels a side gives the mask of the
 *              default 1024, pixel for pixel (tolerance 0): the resolution
 *              changes what is culled, not the mask.
 *   gl-clean   no GL error, no call outside the profile.
 * Once per run, on a built-in scene (the eye inside a closed box lit from
 * outside, so the floor's inside faces the light through the lid):
 *   two-sided  with the box's material two-sided (EP off for it) the mask
 *              matches the ray cast as in vis; with it one-sided EP drops
 *              the lid, which faces the light, and the floor shows lit - that
 *              render must differ (the flag is what makes it right).
 */
#include "aov.h"
#include "vdsm_case.h"
#include "scene_primitives.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SMALL_MAP 64 /* texels a side of the small light pyramid (map-size) */

static void test_clean(const vdsm_case *c, const capture *cap)
{
    char name[256];
    vdsm_name(c, "gl-clean", name, sizeof name);
    capture_report_clean(c->r, name, cap);
}

static long test_vis(const vdsm_case *c, const capture *cap)
{
    long compared, ambig, isolated, edge, differ = vdsm_mismatches(c, cap, &compared, &ambig, &isolated,
                                                              &edge);
    char name[256];
    vdsm_name(c, "vis", name, sizeof name);
    report(c->r, compared > 0 && differ == 0 ? "PASS" : "FAIL", name,
           "visibility differs from the ray cast on %ld of %ld pixels (need 0), %ld of them next "
           "to a reference shadow edge, %ld isolated; not counted: %ld where the reference is "
           "ambiguous", differ, compared, edge, isolated, ambig);
    return differ;
}

static void test_no_grow(const vdsm_case *c, long with_growth)
{
    capture b;
    long compared, ambig, isolated, edge, differ;
    char name[256];
    vdsm_name(c, "no-grow", name, sizeof name);
    if (!vdsm_render(c, STIN_DEBUG_VDSM_NO_GROW, &b, "no-grow"))
        return;
    differ = vdsm_mismatches(c, &b, &compared, &ambig, &isolated, &edge);
    report(c->r, differ >= with_growth ? "PASS" : "FAIL", name,
           "without conservative growth %ld of %ld pixels differ (%ld isolated), with it %ld",
           differ, compared, isolated, with_growth);
    capture_free(&b);
}

/* Pixels whose visibility differs between two renders; *edge counts
 * those on a reference shadow edge (not in the return value). */
static long differ(const vdsm_case *c, const capture *a, const capture *b, long *edge)
{
    long n = 0;
    int x, y, w = c->r->width, h = c->r->height;
    *edge = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            if (vdsm_px(&a->img, x, y)[AOV_VIS_R] != vdsm_px(&b->img, x, y)[AOV_VIS_R]) {
                if (vdsm_on_shadow_edge(c, x, y))
                    (*edge)++;
                else
                    n++;
                if (getenv("STIN_TEST_VERBOSE"))
                    fprintf(stderr, "  vdsm masks differ at pixel %d,%d: %.3f, %.3f\n", x,
                            h - 1 - y, vdsm_px(&a->img, x, y)[AOV_VIS_R],
                            vdsm_px(&b->img, x, y)[AOV_VIS_R]);
            }
    return n;
}

static void test_steps(const vdsm_case *c, const capture *sp, const capture *ep)
{
    char name[256];
    long edge, n = differ(c, sp, ep, &edge);
    int w = c->r->width, h = c->r->height;
    vdsm_name(c, "steps", name, sizeof name);
    report(c->r, n == 0 && edge <= VIS_EDGE_BUDGET * w * h ? "PASS" : "FAIL", name,
           "SP alone and SP + EP differ on %ld of %d pixels away from a reference shadow edge "
           "(must be 0) and on %ld on one (at most %.2f%%: which triangle a grazing segment "
           "hits first is rounding)", n, w * h, edge, 100.0 * VIS_EDGE_BUDGET);
}

/* SP + EP against + SM and + SM + DC: tolerance 0 anywhere. */
static void test_chain(const vdsm_case *c, const capture *sp, const capture *ep,
                       const capture *sm, const capture *all)
{
    char name[256];
    long e1, e2, n1 = differ(c, ep, sm, &e1), n2 = differ(c, ep, all, &e2);
    vdsm_name(c, "chain", name, sizeof name);
    report(c->r, n1 + e1 + n2 + e2 == 0 ? "PASS" : "FAIL", name,
           "against SP + EP, + SM differs on %ld pixels and + SM + DC on %ld (must be 0); "
           "primitives emitted: SP %u, + EP %u, + SM %u, + DC %u", n1 + e1, n2 + e2,
           sp->stats.shadows.vdsm_primitives, ep->stats.shadows.vdsm_primitives, sm->stats.shadows.vdsm_primitives,
           all->stats.shadows.vdsm_primitives);
}

static void test_culls(const vdsm_case *c, const capture *ep, const capture *sm,
                       const capture *all)
{
    char name[256];
    uint32_t p_ep = ep->stats.shadows.vdsm_primitives, p_sm = sm->stats.shadows.vdsm_primitives,
             p_all = all->stats.shadows.vdsm_primitives;
    vdsm_name(c, "culls", name, sizeof name);
    if (!p_ep) {
        report(c->r, "SKIP", name, "the context counted no primitives (no queries)");
        return;
    }
    report(c->r, p_sm < p_ep && p_all < p_sm ? "PASS" : "FAIL", name,
           "primitives: SP + EP %u, + SM %u (%.1f%%), + DC %u (%.1f%%); each must be fewer",
           p_ep, p_sm, 100.0 * p_sm / p_ep, p_all, 100.0 * p_all / p_ep);
}

static void test_map_size(const vdsm_case *c, const capture *all)
{
    capture b;
    char name[256];
    long edge, n;
    vdsm_name(c, "map-size", name, sizeof name);
    if (!vdsm_render_mask(c, SET_ALL, SMALL_MAP, &b, "map-size"))
        return;
    n = differ(c, all, &b, &edge);
    report(c->r, n + edge == 0 ? "PASS" : "FAIL", name,
           "a %d-texel pyramid and the default one give masks differing on %ld pixels (must "
           "be 0); primitives emitted with each: %u and %u", SMALL_MAP, n + edge,
           b.stats.shadows.vdsm_primitives, all->stats.shadows.vdsm_primitives);
    capture_free(&b);
}

static void test_depth_test(const vdsm_case *c, const capture *all)
{
    capture b;
    char name[256];
    long edge, n;
    vdsm_name(c, "depth-test", name, sizeof name);
    if (!vdsm_render_mask(c, SET_ALL | STIN_DEBUG_VDSM_NO_DEPTH_TEST, 0, &b, "depth-test"))
        return;
    n = differ(c, all, &b, &edge);
    report(c->r, n + edge == 0 ? "PASS" : "FAIL", name,
           "the shadow faces with and without their depth test give masks differing on %ld "
           "pixels (must be 0)", n + edge);
    capture_free(&b);
}

static void test_cull_pass(const vdsm_case *c, const capture *all)
{
    capture b;
    char name[256];
    long edge, n;
    const stin_frame_stats *f = &all->stats, *o;
    int ok;
    vdsm_name(c, "cull-pass", name, sizeof name);
    if (!vdsm_render_mask(c, SET_ALL | STIN_DEBUG_VDSM_ONE_PASS, 0, &b, "cull-pass"))
        return;
    o = &b.stats;
    n = differ(c, all, &b, &edge);
    ok = n + edge == 0 && f->shadows.vdsm_cull_passes > 0 && o->shadows.vdsm_cull_passes == 0 &&
         f->shadows.vdsm_primitives == o->shadows.vdsm_primitives && f->shadows.vdsm_kept_faces > 0 &&
         f->shadows.vdsm_kept_faces <= 4 * f->triangles * f->shadows.vdsm_cull_passes;
    report(c->r, ok ? "PASS" : "FAIL", name,
           "culled first and in one pass the masks differ on %ld pixels (must be 0); "
           "primitives emitted %u and %u (must be equal); %u culling passes kept %u "
           "faces (the frame draws %u triangles)", n + edge, f->shadows.vdsm_primitives,
           o->shadows.vdsm_primitives, f->shadows.vdsm_cull_passes, f->shadows.vdsm_kept_faces, f->triangles);
    capture_free(&b);
}

/* The chain's renders of one case and the tests on them: visibility
 * frames alone, the full set's again among them (beauty and normal frames
 * drew every light for rows that read light 0's mask: they took about half
 * of these rows' time on spheres-174k). */
static void chain_tests(const vdsm_case *c)
{
    capture all, sp, ep, sm;
    int spheres = !strncmp(c->scene_name, "spheres", 7);
    if (!vdsm_render_mask(c, SET_ALL, 0, &all, "chain"))
        return;
    if (!vdsm_render_mask(c, SET_SP, 0, &sp, "steps")) {
        capture_free(&all);
        return;
    }
    if (vdsm_render_mask(c, SET_EP, 0, &ep, "steps")) {
        test_steps(c, &sp, &ep);
        if (vdsm_render_mask(c, SET_SM, 0, &sm, "chain")) {
            test_chain(c, &sp, &ep, &sm, &all);
            if (spheres)
                test_culls(c, &ep, &sm, &all);
            capture_free(&sm);
        }
        capture_free(&ep);
    }
    capture_free(&sp);
    test_map_size(c, &all);
    test_depth_test(c, &all);
    test_cull_pass(c, &all);
    capture_free(&all);
}

/* The eye inside a closed 6 x 4 x 6 box (two-sided or not) with a ball on
 * its floor, a point light above the box. */
static int inside_box_scene(scene *s, int two_sided)
{
    int i;
    memset(s, 0, sizeof *s);
    snprintf(s->path, sizeof s->path, "vdsm-inside-box");
    s->meshes = calloc(2, sizeof *s->meshes);
    s->materials = calloc(2, sizeof *s->materials);
    s->objects = calloc(2, sizeof *s->objects);
    s->lights = calloc(1, sizeof *s->lights);
    if (!s->meshes || !s->materials || !s->objects || !s->lights)
        return 0;
    s->mesh_count = s->material_count = s->object_count = 2;
    s->light_count = 1;
    if (!scene_prim_box(&s->meshes[0], 6.0f, 4.0f, 6.0f) ||
        !scene_prim_sphere(&s->meshes[1], 0.6f, 16, 12))
        return 0;
    for (i = 0; i < 2; i++) {
        int k;
        scene_material *m = &s->materials[i];
        m->color[0] = m->color[1] = m->color[2] = 0.7f;
        m->color[3] = 1.0f;
        m->shininess = 32.0f;
        m->albedo = m->normal = m->height = -1;
        m->height_scale = 0.04f;
        for (k = 0; k < 16; k++)
            s->objects[i].transform[k] = k % 5 == 0 ? 1.0f : 0.0f;
        s->objects[i].mesh = s->objects[i].material = i;
    }
    s->materials[0].two_sided = two_sided;
    s->objects[1].transform[12] = 0.8f;
    s->objects[1].transform[13] = -1.4f;
    s->lights[0].type = SCENE_LIGHT_POINT;
    s->lights[0].position[0] = 0.7f;
    s->lights[0].position[1] = 6.0f;
    s->lights[0].position[2] = 0.4f;
    s->lights[0].color[0] = s->lights[0].color[1] = s->lights[0].color[2] = 1.0f;
    s->lights[0].intensity = 1.0f;
    s->lights[0].attenuation[0] = 1.0f;
    s->lights[0].spot_cutoff_deg = 45.0f;
    s->camera.eye[0] = -1.0f;
    s->camera.eye[1] = 1.0f;
    s->camera.eye[2] = 2.5f;
    s->camera.target[1] = -1.5f;
    s->camera.up[1] = 1.0f;
    s->camera.fovy_deg = 70.0f;
    s->camera.near_plane = 0.1f;
    s->camera.far_plane = 50.0f;
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 0.1f;
    s->width = 256;
    s->height = 192;
    return 1;
}

static void test_two_sided(run *r)
{
    scene s[2];
    vdsm_case c;
    capture cap;
    char name[256];
    long compared = 0, shown = 0, ambig, isolated, edge, right = -1, wrong = -1;
    int i;
    for (i = 0; i < 2; i++) {
        if (!inside_box_scene(&s[i], i == 0)) {
            snprintf(name, sizeof name, "gl4/vdsm-inside-box/vdsm-two-sided");
            report(r, "FAIL", name, "out of memory building the scene");
            goto done;
        }
    }
    for (i = 0; i < 2; i++) {
        long n;
        if (!vdsm_case_open(&c, r, &s[i], "vdsm-inside-box", "two-sided")) {
            vdsm_case_close(&c);
            goto done;
        }
        if (!vdsm_render(&c, 0, &cap, "two-sided")) {
            vdsm_case_close(&c);
            goto done;
        }
        n = vdsm_mismatches(&c, &cap, &compared, &ambig, &isolated, &edge);
        if (i == 0) {
            right = n == 0 ? n : -1 - n;
            shown = compared;
        }
        else
            wrong = n;
        capture_free(&cap);
        vdsm_case_close(&c);
    }
    vdsm_name(&c, "two-sided", name, sizeof name);
    report(r, right >= 0 && wrong > 0 ? "PASS" : "FAIL", name,
           "eye inside a closed box lit from outside: with its material two-sided %ld of %ld "
           "pixels differ from the ray cast (need 0), one-sided "
           "(EP drops the lid) %ld (must be more than 0)",
           right >= 0 ? right : -1 - right, shown, wrong);
done:
    scene_free(&s[0]);
    scene_free(&s[1]);
}

void vdsm_tests(run *r, stin_tier tier, const char *path)
{
    static int box_done;
    scene s;
    capture cap;
    vdsm_case c;
    char err[512], scene_name[128];
    if (tier != STIN_TIER_GL4)
        return;
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    if (!vdsm_runs_here(r, scene_name, "tests"))
        return;
    if (!box_done) {
        box_done = 1;
        test_two_sided(r);
    }
    vdsm_seed_tests(r, tier);
    if (!scene_load(path, &s, err, sizeof err))
        return; /* test_scene reported it */
    /* the tests below prove the exact segment to one point: an area light
     * is tested at its centre, its soft pass is soft_test.c's */
    if (s.light_count)
        s.lights[0].radius = 0.0f;
    if (s.light_count && vdsm_case_open(&c, r, &s, scene_name, "vis") &&
        vdsm_render(&c, SET_ALL, &cap, "vis")) {
        test_clean(&c, &cap);
        test_no_grow(&c, test_vis(&c, &cap));
        capture_free(&cap);
        chain_tests(&c);
    }
    if (s.light_count)
        vdsm_case_close(&c);
    scene_free(&s);
}
