/* SPDX-License-Identifier: MIT */
/* Which module runs each shadows technique. The technique table
 * (select/technique_table.c) is pure data below the feature modules, so
 * the frame, which alone may name them, owns this map. */
#include <stddef.h>

#include "internal.h"

static const struct {
    stin_technique technique;
    const stin__shadow_technique *module;
} shadow_modules[] = {
    {STIN_TECH_SHADOWS_VDSM, &stin__shadow_vdsm},
    {STIN_TECH_SHADOWS_VOLUME, &stin__shadow_volume},
    {STIN_TECH_SHADOWS_MAP_PCF, &stin__shadow_map_pcf},
    /* one module for both GL1 map techniques (a depth texture's compare or
     * a depth ramp's) */
    {STIN_TECH_SHADOWS_MAP_DEPTH, &stin__shadow_map_fixed},
    {STIN_TECH_SHADOWS_MAP_COMBINE, &stin__shadow_map_fixed},
    {STIN_TECH_SHADOWS_OFF, &stin__shadow_off},
};

/* Every module's private state, laid out after the context. */
#define SLOT(member, bytes, place) {offsetof(stin_context, member), bytes, place}
const stin__state_slot stin__state_slots[] = {
    SLOT(volume, stin__volume_state_bytes, NULL),
    SLOT(deep, stin__deep_state_bytes, NULL),
    SLOT(coloured, stin__coloured_state_bytes, NULL),
    SLOT(peel, stin__peel_state_bytes, NULL),
    SLOT(dot3, stin__dot3_state_bytes, NULL),
    SLOT(surf_glsl, stin__surf_glsl_state_bytes, NULL),
    SLOT(displace, stin__displace_state_bytes, NULL),
    SLOT(visibility, stin__export_state_bytes, NULL),
    SLOT(outline, stin__outline_state_bytes, NULL),
    SLOT(mask, stin__mask_state_bytes, NULL),
    SLOT(map_fixed, stin__map_fixed_state_bytes, NULL),
    SLOT(map_pcf, stin__map_pcf_state_bytes, NULL),
    SLOT(cast_map, stin__cast_map_state_bytes, NULL),
    SLOT(vdsm, stin__vdsm_state_bytes, NULL),
    SLOT(choice, stin__choice_state_bytes, NULL),
    SLOT(glsl, stin__glsl_state_bytes, NULL),
    SLOT(times, stin__times_state_bytes, NULL),
    SLOT(csg, stin__csg_state_bytes, stin__csg_state_place),
};
#undef SLOT
const size_t stin__state_slot_count = sizeof stin__state_slots / sizeof stin__state_slots[0];

const stin__shadow_technique *stin__shadow_technique_of(stin_technique t)
{
    size_t i;
    for (i = 0; i < sizeof shadow_modules / sizeof shadow_modules[0]; i++)
        if (shadow_modules[i].technique == t)
            return shadow_modules[i].module;
    return &stin__shadow_off;
}
