/* SPDX-License-Identifier: MIT */
/* What each capability profile must detect and choose (docs/profiles.md). */
#ifndef STIN_TESTS_EXPECTED_H
#define STIN_TESTS_EXPECTED_H

#include "stin/stin.h"

typedef struct expected_profile {
    const char *profile;
    stin_tier best_tier;
    stin_technique technique[STIN_FEATURE_COUNT]; /* chosen with the best tier */
    int tier_runs[3];                             /* gl1, gl2, gl4 can be forced */
} expected_profile;

const expected_profile *expected_find(const char *profile);

#endif
