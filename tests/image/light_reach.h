/* Where light 0 of a scene can arrive: the side of the surface the eye sees
 * faces the light, and a spot light's cone holds the point. Shadow tests
 * compare visibility only there (elsewhere no light arrives whatever the
 * technique says). */
#ifndef STIN_TESTS_LIGHT_REACH_H
#define STIN_TESTS_LIGHT_REACH_H

#include "reference.h"
#include "scene.h"

int light_reaches(const scene *s, const ref_hit *h);

#endif
