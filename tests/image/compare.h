/* SPDX-License-Identifier: MIT */
/*
 * Comparison of a stin render (the AOV image of tools/common/aov.h) with the
 * Embree reference (tests/reference/reference.h) of the same scene and camera.
 */
#ifndef STIN_TESTS_COMPARE_H
#define STIN_TESTS_COMPARE_H

#include "image_io.h"
#include "reference.h"
#include "scene.h"

typedef struct compare_tolerance {
    double p_relative;   /* |P_gl - P_ref| <= p_relative * Z + p_absolute */
    double p_absolute;
    double beauty;       /* per channel, linear [0,1] */
    double normal_deg;   /* angle between N and the reference shading normal */
} compare_tolerance;

typedef struct compare_result {
    long covered;            /* pixels covered in the render or the reference */
    long coverage_mismatch;  /* covered in one only */
    long p_mismatch;         /* covered in both, P off by more than the tolerance */
    double p_max_error;      /* largest |dP| / (Z tolerance) seen among matches */
    long beauty_compared;    /* opaque, untextured, away from silhouettes, P matching */
    long beauty_over;        /* of those, any channel off by more than the tolerance */
    double beauty_max;       /* largest channel difference among compared pixels */
    double beauty_mean;      /* mean channel difference among compared pixels */
    long vis_compared, vis_mismatch; /* visibility of light 0 on matching pixels */
    long normal_compared, normal_over; /* N off by more than the angle tolerance */
    double normal_max_deg;
} compare_result;

/* gl: rows top to bottom (file order); ref and hits: rows bottom to top. */
void compare_render(const scene *s, const image *gl, const float *ref, const ref_hit *hits,
                    const compare_tolerance *tol, compare_result *out);

#endif
