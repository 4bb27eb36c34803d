/* SPDX-License-Identifier: MIT */
/* Shadows off: the module with no hooks. */
#include "internal.h"

const stin__shadow_technique stin__shadow_off = {
    STIN_TECH_SHADOWS_OFF, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, 0,
    NULL, NULL,
};
