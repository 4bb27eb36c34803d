/* SPDX-License-Identifier: MIT */
/* What the multisampled-target tests share (msaa_test.c, msaa_blend_test.c):
 * where the target's samples lie, one frame of a scene into the platform's
 * target with forced techniques, and the frame beside its reference. */
#ifndef STIN_TESTS_MSAA_SHARED_H
#define STIN_TESTS_MSAA_SHARED_H

#include "image_test.h"
#include "scene.h"

#include <stddef.h>
#include <stdint.h>

#define MSAA_MAX_SAMPLES 16

/* The target's sample positions in the pixel (0..1); 0 where the context
 * cannot say (GL 3.2 / ARB_texture_multisample). */
int msaa_sample_positions(run *r, float pos[][2]);

/* Techniques a frame forces; STIN_TECH_NONE leaves the feature's default. */
typedef struct msaa_techniques {
    stin_tier tier;
    stin_technique shadows, transparency, translucent, surface, displacement;
} msaa_techniques;

/* One frame of the scene at its own size into the platform's target, read
 * back (resolved) into rgba (the run's width per row, bottom row first).
 * 1 on success; -1 (why: the reason to SKIP) where a forced technique does
 * not run on this tier here; 0 (why) on failure. */
int msaa_render(run *r, const scene *s, const msaa_techniques *t, uint8_t *rgba, char *why,
                size_t why_size);
/* msaa_render with the deferred outline (stin_frame_desc.outline_step,
 * outline_color; step 0: none). */
int msaa_render_outlined(run *r, const scene *s, const msaa_techniques *t, float step,
                         const float color[4], uint8_t *rgba, char *why, size_t why_size);

/* msaa_render into rgba (NULL: out of memory) reported as `name` where it
 * did not render (SKIP, FAIL): 1 rendered, else 0. */
int msaa_render_reported(run *r, const scene *s, const msaa_techniques *t, uint8_t *rgba,
                         const char *name);

/* Writes the frame (left) beside the reference colour (right: w x h x 3,
 * bottom row first) as OUT/PLATFORM-PROFILE-NAME.png, where --out was given. */
void msaa_save_pair(run *r, const char *name, const uint8_t *rgba, const float *colour, int w,
                    int h);

/* Loads msaa/FILE beside the scene at `path` into s and renders into a
 * `samples`-sample target from now on: the number of samples whose
 * positions the context gives (pos), or 0 (reported as `name`: SKIP where
 * the run is too small, the target cannot be made or the positions are
 * unknown; FAIL where the scene does not load), s freed then. */
int msaa_open(run *r, const char *path, const char *file, int samples, const char *name,
              scene *s, float pos[][2]);
/* Back to the default framebuffer (FAIL as `name` where it cannot), s freed. */
void msaa_close(run *r, const char *name, scene *s);
/* The reference's per-vertex lighting of the GL1 tier here (reference.h:
 * 1, or REFERENCE_GOURAUD_SINGLE_COLOR without separate specular); 0 where
 * the tier does not run. */
int msaa_gl1_per_vertex(run *r, const scene *s);

#endif
