/* SPDX-License-Identifier: MIT */
/* Shadows off: the module with no hooks, and the lookup of a technique's module. */
#include "internal.h"

const stin__shadow_technique stin__shadow_off = {
    STIN_TECH_SHADOWS_OFF, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, 0,
    NULL,
};

const stin__shadow_technique *stin__shadow_technique_of(stin_technique t)
{
    const stin__technique_row *r = stin__technique_row_of(t);
    return r && r->shadow ? r->shadow : &stin__shadow_off;
}
