/* SPDX-License-Identifier: MIT */
/*
 * 16-bit element indices (OpenGL ES 2.0 without OES_element_index_uint):
 * spheres-18k-spot with its floor made a 270 x 270 grid (72,900 vertices,
 * 144,722 triangles: one mesh over 65,535 vertices) rendered by stin's own
 * choice with STIN_CAP_ELEMENT_INDEX_UINT hidden, so the floor is drawn in
 * 16-bit chunks (assets/mesh_chunks.c), and without it hidden (one 32-bit
 * draw). "index16": the masked frame must equal the unmasked one in every
 * AOV value (the same triangles from the same vertex values in the same
 * order rasterise identically), and its P must equal the Embree first hit
 * on at least 99.9% of covered pixels within 1e-3 Z + 1e-3 (the position
 * test's bound). Mesa accepts 32-bit indices whatever the mask says, so the
 * index type itself is held by test_index16 on the fake GL; this row holds
 * the split's geometry: a chunk drawn from the wrong vertices or left out
 * moves or drops floor pixels. Runs on gl21's GL2 tier and gl45-core's GL4
 * tier (on EGL and OSMesa).
 */
#include "aov.h"
#include "capture.h"
#include "image_test.h"
#include "reference.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GRID 270u

/* The floor (a flat quad) again as a GRID x GRID grid over the same
 * rectangle, facing the same way. */
static int subdivide_floor(scene_mesh *m)
{
    float lo[3], hi[3], n[3];
    uint32_t i, x, z, nv = GRID * GRID, nt = 2u * (GRID - 1u) * (GRID - 1u), t = 0;
    int k, axis = 0;
    float *pos, *nor, *uv;
    uint32_t *idx;
    for (k = 0; k < 3; k++) {
        lo[k] = hi[k] = m->positions[k];
        n[k] = m->normals[k];
    }
    for (i = 1; i < m->vertex_count; i++)
        for (k = 0; k < 3; k++) {
            lo[k] = fminf(lo[k], m->positions[3u * i + k]);
            hi[k] = fmaxf(hi[k], m->positions[3u * i + k]);
        }
    for (k = 1; k < 3; k++) /* the flat axis */
        if (hi[k] - lo[k] < hi[axis] - lo[axis])
            axis = k;
    pos = malloc(sizeof(float) * 3u * nv);
    nor = malloc(sizeof(float) * 3u * nv);
    uv = malloc(sizeof(float) * 2u * nv);
    idx = malloc(sizeof(uint32_t) * 3u * nt);
    if (!pos || !nor || !uv || !idx) {
        free(pos);
        free(nor);
        free(uv);
        free(idx);
        return 0;
    }
    for (z = 0; z < GRID; z++)
        for (x = 0; x < GRID; x++) {
            uint32_t v = z * GRID + x;
            float s = (float)x / (float)(GRID - 1u), r = (float)z / (float)(GRID - 1u);
            int a = (axis + 1) % 3, b = (axis + 2) % 3;
            pos[3u * v + (uint32_t)axis] = lo[axis];
            pos[3u * v + (uint32_t)a] = lo[a] + s * (hi[a] - lo[a]);
            pos[3u * v + (uint32_t)b] = lo[b] + r * (hi[b] - lo[b]);
            for (k = 0; k < 3; k++)
                nor[3u * v + (uint32_t)k] = n[k];
            uv[2u * v] = s;
            uv[2u * v + 1u] = r;
        }
    for (z = 0; z + 1u < GRID; z++)
        for (x = 0; x + 1u < GRID; x++) {
            uint32_t v = z * GRID + x, q[6] = {v, v + 1u, v + GRID, v + 1u, v + GRID + 1u, v + GRID};
            /* (a, b) axes' cross product is +axis: wind to match n */
            int flip = n[axis] < 0.0f;
            for (k = 0; k < 6; k += 3) {
                idx[t++] = q[k];
                idx[t++] = flip ? q[k + 2] : q[k + 1];
                idx[t++] = flip ? q[k + 1] : q[k + 2];
            }
        }
    free(m->positions);
    free(m->normals);
    free(m->uvs);
    free(m->indices);
    m->positions = pos;
    m->normals = nor;
    m->uvs = uv;
    m->indices = idx;
    m->vertex_count = nv;
    m->triangle_count = nt;
    return 1;
}

void index16_tests(run *r, stin_tier tier, const char *path)
{
    scene s;
    capture masked, plain;
    capture_options o;
    reference *ref = NULL;
    ref_hit *hits = NULL;
    char err[512], name[256];
    int i, w = r->width, h = r->height, have_masked = 0, have_plain = 0;
    long covered = 0, p_ok = 0, differ = 0;
    size_t n;
    if (!((tier == STIN_TIER_GL2 && !strcmp(r->profile_name, "gl21")) ||
          (tier == STIN_TIER_GL4 && !strcmp(r->profile_name, "gl45-core"))) ||
        strcmp(scene_base_name(path), "spheres-18k-spot"))
        return;
    snprintf(name, sizeof name, "%s/spheres-18k-spot/index16", stin_tier_name(tier));
    if (!scene_load(path, &s, err, sizeof err))
        return;
    for (i = 0; i < s.mesh_count; i++)
        if (!strcmp(s.meshes[i].name, "floor") && !subdivide_floor(&s.meshes[i])) {
            report(r, "FAIL", name, "set-up: out of memory");
            goto done;
        }
    memset(&o, 0, sizeof o);
    o.tier = tier;
    o.extra_mask = STIN_CAP_BIT(STIN_CAP_ELEMENT_INDEX_UINT);
    ref = reference_create(&s, err, sizeof err);
    hits = malloc(sizeof *hits * (size_t)w * h);
    if (!ref || !hits || !reference_primary(ref, w, h, hits) ||
        !(have_masked = capture_render(r->plat, r->profile, &s, &o, &masked, err, sizeof err))) {
        report(r, "FAIL", name, "set-up: %s", err);
        goto done;
    }
    o.extra_mask = 0;
    if (!(have_plain = capture_render(r->plat, r->profile, &s, &o, &plain, err, sizeof err))) {
        report(r, "FAIL", name, "set-up: %s", err);
        goto done;
    }
    if (masked.caps_present & STIN_CAP_BIT(STIN_CAP_ELEMENT_INDEX_UINT)) {
        report(r, "FAIL", name, "the mask did not hide 32-bit element indices");
        goto done;
    }
    n = (size_t)w * h * AOV_CHANNELS;
    for (i = 0; (size_t)i < n; i++)
        differ += masked.img.pixels[i] != plain.img.pixels[i] &&
                  !(isnan(masked.img.pixels[i]) && isnan(plain.img.pixels[i]));
    for (i = 0; i < w * h; i++) {
        int x = i % w, y = i / w, k;
        const ref_hit *hit = &hits[i];
        const float *g = masked.img.pixels + ((size_t)(h - 1 - y) * w + x) * AOV_CHANNELS;
        double d2 = 0;
        if (!hit->hit)
            continue;
        covered++;
        for (k = 0; k < 3; k++)
            d2 += (g[AOV_PX + k] - hit->P[k]) * (g[AOV_PX + k] - hit->P[k]);
        p_ok += g[AOV_Z] > 0.0f && sqrt(d2) <= 1e-3 * hit->t + 1e-3;
    }
    if (masked.counters.gl_violations || masked.log_errors)
        report(r, "FAIL", name, "%u profile violations, %u error logs (last: %s)",
               masked.counters.gl_violations, masked.log_errors, masked.last_error);
    else
        report(r, differ == 0 && covered > 0 && p_ok * 1000 >= covered * 999 ? "PASS" : "FAIL",
               name,
               "a %u-vertex floor in 16-bit chunks (%s): %ld AOV values differ from the 32-bit "
               "frame (none may); P matches the reference on %ld of %ld covered pixels "
               "(%.3f%%, at least 99.9%%)", GRID * GRID,
               stin_technique_name(masked.choice[STIN_FEATURE_SHADOWS].technique), differ, p_ok,
               covered, covered ? 100.0 * p_ok / covered : 0.0);
done:
    if (have_masked)
        capture_free(&masked);
    if (have_plain)
        capture_free(&plain);
    free(hits);
    if (ref)
        reference_destroy(ref);
    scene_free(&s);
}
