/* SPDX-License-Identifier: MIT */
/* A stin context for one test: created for the run's profile at a tier
 * with a forced shadow technique, sized for a scene, the scene's meshes and
 * textures made; and one frame of that scene. */
#ifndef STIN_TESTS_TEST_CONTEXT_H
#define STIN_TESTS_TEST_CONTEXT_H

#include "capture.h"
#include "image_test.h"
#include "scene.h"
#include "scene_gpu.h"

typedef struct test_context {
    stin_context *ctx;
    void *block;
    scene_gpu g;
} test_context;

/* A desc for the run's profile at `tier` (capacities left for the caller). */
void test_desc(const run *r, stin_tier tier, stin_desc *d);
/* 1 on success. 0 when the profile cannot run it (stin_create refused it)
 * or, with `exact`, when the forced shadow technique fell back to another
 * (that one's own run covers it), or when the scene could not be made. */
int test_context_create(test_context *t, const run *r, const scene *s, stin_tier tier,
                        stin_technique shadows, int exact);
/* The same with desc.debug_flags (STIN_DEBUG_*). */
int test_context_create_debug(test_context *t, const run *r, const scene *s, stin_tier tier,
                              stin_technique shadows, int exact, uint64_t debug_flags);
/* test_context_create (exact) with a forced translucent-shadows technique
 * too, which must be the one chosen. */
int test_context_create_translucent(test_context *t, const run *r, const scene *s,
                                    stin_tier tier, stin_technique shadows,
                                    stin_technique translucent);
void test_context_destroy(test_context *t);
/* 1 where stin_create refuses `want` forced at `tier` on the run's context
 * (why: its reason, the capability it names), else 0: how a family of
 * rows learns once that its technique does not run here (vdsm on ES 3.0,
 * which has the GL4 tier but no geometry shaders). */
int technique_refused(const run *r, stin_tier tier, stin_feature feature, stin_technique want,
                      char *why, size_t why_size);

/* The scene camera's frame into the platform's framebuffer at the run's
 * size, the scene's ambient, cleared to 0. */
void test_frame_desc(const run *r, const scene *s, stin_frame_desc *fd);
/* begin (fd), the scene's lights - light `first` moved to the front when
 * >= 0 - and draws, end. STIN_OK or the first error. */
stin_result test_context_frame(test_context *t, const scene *s, const stin_frame_desc *fd,
                               int first);

/* One capture with a forced technique: 1 when it rendered and `feature`
 * runs `want` (want 0: any). A refused forced technique (stin_create's
 * "needs") and a demotion report SKIP with the reason, any other failure
 * FAIL; nothing is left to free then. */
int capture_forced(run *r, const scene *s, const capture_options *o, stin_feature feature,
                   stin_technique want, capture *out, const char *name);
/* capture_forced's context without its frames: made from capture_desc for
 * o, with the same SKIP and FAIL lines (`log` keeps its log), for a test
 * that draws only the frames it reads. 1 when `feature` runs `want`. */
int test_context_forced(test_context *t, run *r, const scene *s, const capture_options *o,
                        stin_feature feature, stin_technique want, capture *log,
                        const char *name);

#endif
