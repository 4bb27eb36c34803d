/* SPDX-License-Identifier: MIT */
/* What the deep and coloured image tests share (deep_test.c,
 * coloured_test.c): a case - a scene, its Embree reference and the
 * translucent-shadows technique under test - and checks of its renders'
 * visibility output against the reference's transmittance (T.R T.G T.B). */
#ifndef STIN_TESTS_DEEP_CASE_H
#define STIN_TESTS_DEEP_CASE_H

#include "capture.h"
#include "image_test.h"
#include "reference.h"

#include <stddef.h>

#define T_TOLERANCE (2.0 / 255.0)
#define T_MIN_MATCH 0.995
#define MIN_PARTIAL 100
#define MIN_CLASS 50

typedef struct deep_case {
    run *r;
    const scene *s;
    const char *scene_name;
    const float *ref;
    const ref_hit *hits;
    stin_tier tier;
    uint32_t map_size, layers;
    int band;
    stin_technique tech;  /* deep or coloured: the render must keep it */
    const char *tag;      /* the tests' name prefix: "deep", "coloured" */
    int skip_transparent; /* 1: pixels of transparent surfaces are not compared */
} deep_case;

/* c for scene s at tier: technique t (its tag), deep's sizes (2048
 * texels a face on deep-stack's one face, `stack`, with a one-pixel band;
 * 512 elsewhere, whose texels span up to about three pixels here), every
 * layer (layers 0: the default). */
void deep_case_init(deep_case *c, run *r, stin_tier tier, const scene *s, const char *scene_name,
                    stin_technique t, int stack);
/* The reference's pixel and the capture's (x, y from the bottom). */
const float *deep_ref_px(const deep_case *c, int x, int y);
const float *deep_gl_px(const deep_case *c, const capture *cap, int x, int y);
int deep_is_transparent(const deep_case *c, const ref_hit *hit);
/* A pixel the comparison counts: covered, the light reaches it, away from
 * transmittance edges, the render's surface the reference's (and not a
 * transparent surface when the case skips them). */
int deep_comparable(const deep_case *c, const capture *cap, int x, int y);
/* 1 when the visibility channels are within tol of expect. */
int deep_within(const float *g, const float *expect, double tol);
/* One PASS/FAIL line each: T within 2/255 on 99.5% of the comparable
 * pixels (with >= 100 in partial shadow); the seed's classes of T; pane
 * pixels the reference sees unshadowed within 2/255 of 1. */
void deep_test_transmittance(const deep_case *c, const capture *cap, const char *name);
void deep_test_values(const deep_case *c, const capture *cap, const char *name);
void deep_test_own_layer(const deep_case *c, const capture *cap, const char *name);
/* Point lights: T within 2/255 on 99.5% of the pixels beside a seam of the
 * light's cube faces (>= 100 of them), where a lookup may stray into the
 * neighbouring face. */
void deep_test_seams(const deep_case *c, const capture *cap, const char *name);
/* Pane pixels the reference sees unshadowed (n), and those within 2/255
 * of 1 (good). */
void deep_own_layer_counts(const deep_case *c, const capture *cap, long *n, long *good);
/* Below the technique's tier: a SKIP line (tier X skip_why), then forcing
 * it must be refused with `expect` in the message (a PASS/FAIL line). */
void deep_refusal(run *r, stin_tier tier, const char *scene_name, const scene *s,
                  stin_technique t, const char *skip_why, const char *expect);
/* The case's technique forced with shadows off: nothing is shadowed, so it
 * falls back to `expect` at set-up, saying why (a PASS/FAIL line). */
void deep_test_shadows_off(const deep_case *c, const char *name, stin_technique expect);
/* Pixels whose beauty or visibility differ between two captures. */
long deep_differing(const capture *a, const capture *b);
/* A render with the case's technique (a FAIL line and 0 when it fell
 * back); the case's options. */
int deep_render(const deep_case *c, const scene *s, const capture_options *o, capture *cap,
                const char *name);
void deep_options(const deep_case *c, capture_options *o);
/* The reference's AOVs and primary hits of the case's scene; 0 with a
 * message in err. Free with deep_free_reference. */
int deep_make_reference(deep_case *c, reference **ref, char *err, size_t err_size);
void deep_free_reference(deep_case *c, reference *ref);

#endif
