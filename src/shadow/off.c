/* SPDX-License-Identifier: MIT */
/* Shadows off: the module with no hooks. */
#include "internal.h"

const stin__shadow_technique stin__shadow_off = {
    .technique = STIN_TECH_SHADOWS_OFF,
};
