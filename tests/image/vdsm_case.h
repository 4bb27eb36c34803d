/* SPDX-License-Identifier: MIT */
/*
 * What the VDSM image tests share (vdsm_test.c, vdsm_seed_test.c): a case -
 * a scene with its Embree reference - the GL4 vdsm render of it under a set
 * of steps, and its pixels' visibility against the ray cast of each pixel's
 * surface point (left from the surface as vdsm's test leaves it; pixels where
 * the reference is ambiguous counted apart: see vdsm_test.c's comment).
 */
#ifndef STIN_TESTS_VDSM_CASE_H
#define STIN_TESTS_VDSM_CASE_H

#include "capture.h"
#include "image_test.h"
#include "reference.h"

#include <stddef.h>
#include <stdint.h>

/* Pixels on a reference shadow edge that may differ: the GPU's interpolated
 * surface point is off the exact one by up to about 1e-5 of the eye
 * distance, which moves a shadow edge that far (measured: at most 4 pixels
 * of 18,002 on the spheres scenes at 256x192). */
#define VIS_EDGE_BUDGET 0.0005

/* The step sets of the chain, as debug flags (each counts its primitives). */
#define SET_SP (STIN_DEBUG_VDSM_NO_EP | STIN_DEBUG_VDSM_NO_SM | STIN_DEBUG_VDSM_NO_DC | \
                STIN_DEBUG_VDSM_COUNT)
#define SET_EP (STIN_DEBUG_VDSM_NO_SM | STIN_DEBUG_VDSM_NO_DC | STIN_DEBUG_VDSM_COUNT)
#define SET_SM (STIN_DEBUG_VDSM_NO_DC | STIN_DEBUG_VDSM_COUNT)
#define SET_ALL STIN_DEBUG_VDSM_COUNT

typedef struct vdsm_case {
    run *r;
    const scene *s;
    const char *scene_name;
    const reference *refr;
    const ref_hit *hits;
    const float *ref;        /* reference AOVs (P), rows bottom to top */
} vdsm_case;

/* "gl4/<scene>/vdsm-<test>" */
void vdsm_name(const vdsm_case *c, const char *test, char *out, size_t size);
/* The AOV pixel (x, y), y counted from the bottom as the reference's rows. */
const float *vdsm_px(const image *img, int x, int y);
/* The ray-cast visibility of a hit, left from the surface as vdsm does. */
float vdsm_truth(const vdsm_case *c, const ref_hit *h);
/* The reference's visibility (as vdsm_truth), or the object hit, changes
 * within one pixel of (x, y) (y from the bottom). */
int vdsm_on_shadow_edge(const vdsm_case *c, int x, int y);
/* Pixels whose visibility differs from the reference; ambiguous ones are
 * counted apart, and of the rest the isolated ones and those next to a
 * reference shadow edge. Compared: covered pixels whose P matches. */
long vdsm_mismatches(const vdsm_case *c, const capture *cap, long *compared, long *ambig,
                     long *isolated, long *on_edge);
/* The vdsm render with these debug flags; 0 and a FAIL under `test` when
 * it fails. */
int vdsm_render(const vdsm_case *c, uint64_t debug, capture *out, const char *test);
/* The same as a visibility frame alone (capture_options.visibility_only),
 * with a pyramid size (0: the default): for the rows that compare two
 * renders' masks and statistics, which need neither beauty nor normals. */
int vdsm_render_mask(const vdsm_case *c, uint64_t debug, uint32_t map_size, capture *out,
                     const char *test);
/* 1 where the run's context runs vdsm; else 0 and one SKIP line
 * "gl4/<scene>/vdsm-<test>" naming what it lacks (asked of stin once a run:
 * ES 3.0 and 3.1 have the GL4 tier without geometry shaders). */
int vdsm_runs_here(run *r, const char *scene_name, const char *test);
/* The reference of a case: 0 (reported under `test`) when it cannot be
 * made; close it either way. */
int vdsm_case_open(vdsm_case *c, run *r, const scene *s, const char *scene_name,
                   const char *test);
void vdsm_case_close(vdsm_case *c);

#endif
