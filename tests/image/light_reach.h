/* SPDX-License-Identifier: MIT */
/* Where light 0 of a scene can arrive: the side of the surface the eye sees
 * faces the light, and a spot light's cone holds the point. Shadow tests
 * compare visibility only there (elsewhere no light arrives whatever the
 * technique says). */
#ifndef STIN_TESTS_LIGHT_REACH_H
#define STIN_TESTS_LIGHT_REACH_H

#include "reference.h"
#include "scene.h"

int light_reaches(const scene *s, const ref_hit *h);

/* 1 where the reference visibility of light 0 (the vis channel of ref, a
 * reference_render image of w x h) or the object hit changes within band
 * pixels of (x, y): a shadow map's texels blur edges over that band. */
int near_shadow_edge(const ref_hit *hits, const float *ref, int w, int h, int x, int y, int band);

#endif
