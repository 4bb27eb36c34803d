/* SPDX-License-Identifier: MIT */
/* Lit programs specialised to a pass's lights and a draw's material
 * (src/render/lit_specialise.c) against the general program
 * (STIN_DEBUG_LIGHTING_GENERAL), on the scenes whose lights and materials take
 * every part of the equation: four-lights (point lights with and without
 * attenuation, a spot and a directional light in one batch), stone-wall
 * (an albedo map on a normal-mapped wall under a spot), deep-window (an
 * albedo map with alpha) and glass-panes (blended panes: peeled layers,
 * whose programs keep the peel chunk). Shadows off puts every light in one batch;
 * the tier's own shadows give a pass per light, one kind each.
 *
 *   lit-specialised[-shadows]  the specialised frame is the general one's
 *                              within TOLERANCE a channel, served by
 *                              specialised programs (stats), and a second
 *                              frame builds none and draws the same pixels
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_context.h"

/* Codes of 8 bits a channel. The programs compute the same expression with
 * the same operations in the same order; a compiler may still fold or fuse
 * the constant parts differently, which rounds one code either way. */
#define TOLERANCE 1

typedef struct lit_frame {
    uint8_t *rgba;
    stin_frame_stats stats[2]; /* of the first and the second frame */
    int same;                  /* the second frame's pixels are the first's */
} lit_frame;

static int wanted(const char *path)
{
    const char *n = scene_base_name(path);
    return !strcmp(n, "four-lights") || !strcmp(n, "stone-wall") || !strcmp(n, "deep-window") ||
           !strcmp(n, "glass-panes");
}

/* Two frames of the scene; 0 with err set when it did not render. */
static int render(run *r, const scene *s, stin_tier tier, stin_technique shadows, uint64_t flags,
                  lit_frame *out, char *err, size_t err_size)
{
    test_context t;
    stin_frame_desc fd;
    size_t bytes = 4u * (size_t)r->width * (size_t)r->height;
    uint8_t *second = malloc(bytes);
    int f, ok = 0;
    memset(out, 0, sizeof *out);
    out->rgba = malloc(bytes);
    if (!out->rgba || !second ||
        !test_context_create_debug(&t, r, s, tier, shadows, 0, flags)) {
        snprintf(err, err_size, "no context for the scene");
        free(second);
        return 0;
    }
    test_frame_desc(r, s, &fd);
    for (f = 0; f < 2; f++) {
        stin_result res = test_context_frame(&t, s, &fd, -1);
        if (res != STIN_OK ||
            !stin_platform_read_color(r->plat, f == 0 ? out->rgba : second)) {
            snprintf(err, err_size, "frame %d: %s", f + 1, stin_result_name(res));
            goto done;
        }
        out->stats[f] = stin_query_frame_stats(t.ctx);
    }
    out->same = memcmp(out->rgba, second, bytes) == 0;
    ok = 1;
done:
    test_context_destroy(&t);
    free(second);
    return ok;
}

/* Pixels whose largest channel difference exceeds tol, and the largest. */
static long differing(const run *r, const uint8_t *a, const uint8_t *b, int tol, int *max)
{
    size_t i, n = (size_t)r->width * (size_t)r->height;
    long over = 0;
    *max = 0;
    for (i = 0; i < n; i++) {
        int k, d = 0;
        for (k = 0; k < 3; k++) {
            int e = abs((int)a[4 * i + k] - (int)b[4 * i + k]);
            d = e > d ? e : d;
        }
        over += d > tol;
        *max = d > *max ? d : *max;
    }
    return over;
}

static void test_one(run *r, stin_tier tier, const scene *s, const char *scene_name,
                     stin_technique shadows)
{
    char name[256], err[256];
    lit_frame spec, gen;
    long over, moved;
    int max;
    snprintf(name, sizeof name, "%s/%s/lit-specialised%s", stin_tier_name(tier), scene_name,
             shadows == STIN_TECH_SHADOWS_OFF ? "" : "-shadows");
    if (tier == STIN_TIER_GL1) {
        report(r, "SKIP", name, "gl1 lights by fixed function: it has no lit programs");
        return;
    }
    if (!render(r, s, tier, shadows, 0, &spec, err, sizeof err)) {
        report(r, "FAIL", name, "specialised: %s", err);
        free(spec.rgba);
        return;
    }
    if (!render(r, s, tier, shadows, STIN_DEBUG_LIGHTING_GENERAL, &gen, err, sizeof err)) {
        report(r, "FAIL", name, "general: %s", err);
        free(spec.rgba);
        free(gen.rgba);
        return;
    }
    moved = differing(r, spec.rgba, gen.rgba, 0, &max);
    over = differing(r, spec.rgba, gen.rgba, TOLERANCE, &max);
    if (!spec.stats[0].lighting.specialised || !spec.stats[0].lighting.programs_built)
        report(r, "FAIL", name,
               "no specialised program served the first frame (%u draws, %u built)",
               spec.stats[0].lighting.specialised, spec.stats[0].lighting.programs_built);
    else if (spec.stats[1].lighting.programs_built ||
             spec.stats[1].lighting.specialised != spec.stats[0].lighting.specialised || !spec.same)
        report(r, "FAIL", name,
               "the second frame built %u programs, served %u draws (first %u), same pixels %d",
               spec.stats[1].lighting.programs_built, spec.stats[1].lighting.specialised,
               spec.stats[0].lighting.specialised, spec.same);
    else if (gen.stats[0].lighting.specialised || gen.stats[0].lighting.programs_built)
        report(r, "FAIL", name, "STIN_DEBUG_LIGHTING_GENERAL still served %u draws specialised",
               gen.stats[0].lighting.specialised);
    else
        report(r, over ? "FAIL" : "PASS", name,
               "%u programs served %u lit draws; against the general program %ld pixels over "
               "%d codes (largest %d), %ld moved at all",
               spec.stats[0].lighting.programs_built, spec.stats[0].lighting.specialised, over, TOLERANCE,
               max, moved);
    free(spec.rgba);
    free(gen.rgba);
}

void lit_tests(run *r, stin_tier tier, const char *path)
{
    scene s;
    char err[512], scene_name[128];
    if (!wanted(path) || !scene_load(path, &s, err, sizeof err))
        return; /* test_scene reports a scene that does not load */
    snprintf(scene_name, sizeof scene_name, "%s", scene_base_name(path));
    test_one(r, tier, &s, scene_name, STIN_TECH_SHADOWS_OFF);
    test_one(r, tier, &s, scene_name, STIN_TECH_NONE);
    scene_free(&s);
}
