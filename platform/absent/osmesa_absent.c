/* SPDX-License-Identifier: MIT */
/*
 * The OSMesa backend of a build made with OSMESA=no (a machine whose GL is
 * a GPU driver and has no Mesa): asking for it is an error that says so.
 */
#include "platform_internal.h"

#include <stdio.h>

stin_osmesa *stin_osmesa_create(int width, int height, const stin_profile *profile,
                                char *err, size_t err_size)
{
    (void)width;
    (void)height;
    (void)profile;
    snprintf(err, err_size, "osmesa: this build has no OSMesa (made with OSMESA=no); use --platform egl");
    return NULL;
}

void stin_osmesa_destroy(stin_osmesa *osm) { (void)osm; }

void *stin_osmesa_get_proc(stin_osmesa *osm, const char *name)
{
    (void)osm;
    (void)name;
    return NULL;
}
