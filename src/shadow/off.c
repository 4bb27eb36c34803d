/* SPDX-License-Identifier: MIT */
/* Shadows off: the module with no hooks. */
#include "internal.h"

/* light NULL: it casts no shadows; every other hook NULL too. */
const stin__shadow_technique stin__shadow_off = {
    .light = NULL,
};
