/* SPDX-License-Identifier: MIT */
#include "technique_option.h"

#include <stdio.h>
#include <string.h>

int technique_option_parse(const char *program, const char *name, stin_feature f,
                           stin_technique *out)
{
    int t;
    char off[64];
    *out = STIN_TECH_NONE;
    if (!name || !strcmp(name, "auto"))
        return 1;
    if (!strcmp(name, "off")) {
        snprintf(off, sizeof off, "%s-off", stin_feature_name(f));
        name = off;
    }
    if (f == STIN_FEATURE_SHADOWS && !strcmp(name, "map")) {
        *out = STIN_TECH_SHADOWS_MAP_DEPTH; /* technique_option_narrow_map */
        return 1;
    }
    for (t = 1; t < STIN_TECH_COUNT; t++) {
        stin_technique tech = (stin_technique)t;
        if (!strcmp(stin_technique_name(tech), name) && stin_technique_feature(tech) == f) {
            *out = tech;
            return 1;
        }
    }
    fprintf(stderr, "%s: unknown %s technique '%s'; this build knows: auto%s", program,
            stin_feature_name(f), name, f == STIN_FEATURE_SHADOWS ? ", map" : "");
    for (t = 1; t < STIN_TECH_COUNT; t++)
        if (stin_technique_feature((stin_technique)t) == f)
            fprintf(stderr, ", %s", stin_technique_name((stin_technique)t));
    fprintf(stderr, "\n");
    return 0;
}

void technique_option_narrow_map(stin_get_proc_fn get_proc, void *user, stin_desc *desc)
{
    stin_caps caps;
    uint64_t depth = STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE) | STIN_CAP_BIT(STIN_CAP_SHADOW);
    if (stin_detect_caps(get_proc, user, desc->caps_mask, desc->max_gl_version, &caps) ==
            STIN_OK &&
        (caps.present & depth) != depth)
        desc->techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_MAP_COMBINE;
}
