/* SPDX-License-Identifier: MIT */
/*
 * OSMesa backend: Mesa's software rasteriser rendering into a heap buffer.
 * Compatibility contexts take the driver's best version (the profile's
 * MESA_GL_VERSION_OVERRIDE lowers it); core contexts ask for the version.
 */
#include "platform_internal.h"

#include <GL/osmesa.h>
#include <stdlib.h>

struct stin_osmesa {
    OSMesaContext context;
    unsigned char *pixels; /* width * height * 4, what OSMesa renders into */
};

static void context_attribs(const stin_profile *profile, int *a)
{
    int n = 0;
    a[n++] = OSMESA_FORMAT;
    a[n++] = OSMESA_RGBA;
    a[n++] = OSMESA_DEPTH_BITS;
    a[n++] = 24;
    a[n++] = OSMESA_STENCIL_BITS;
    a[n++] = 8;
    a[n++] = OSMESA_ACCUM_BITS;
    a[n++] = 0;
    a[n++] = OSMESA_PROFILE;
    if (profile && profile->core) {
        a[n++] = OSMESA_CORE_PROFILE;
        a[n++] = OSMESA_CONTEXT_MAJOR_VERSION;
        a[n++] = profile->gl_major;
        a[n++] = OSMESA_CONTEXT_MINOR_VERSION;
        a[n++] = profile->gl_minor;
    } else {
        a[n++] = OSMESA_COMPAT_PROFILE;
    }
    a[n] = 0;
}

void stin_osmesa_destroy(stin_osmesa *osm)
{
    if (!osm)
        return;
    if (osm->context) {
        /* Release the current binding before the context and buffer go. */
        if (OSMesaGetCurrentContext() == osm->context)
            OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
        OSMesaDestroyContext(osm->context);
    }
    free(osm->pixels);
    free(osm);
}

stin_osmesa *stin_osmesa_create(int width, int height, const stin_profile *profile, char *err,
                                size_t err_size)
{
    int attribs[24];
    stin_osmesa *osm = calloc(1, sizeof *osm);
    if (!osm)
        goto oom;
    osm->pixels = malloc((size_t)width * (size_t)height * 4u);
    if (!osm->pixels)
        goto oom;
    context_attribs(profile, attribs);
    osm->context = OSMesaCreateContextAttribs(attribs, NULL);
    if (!osm->context) {
        stin_platform_errorf(err, err_size,
                             "OSMesa: OSMesaCreateContextAttribs failed for a %s %d.%d "
                             "context (profile %s)",
                             profile && profile->core ? "core" : "compatibility",
                             profile ? profile->gl_major : 0, profile ? profile->gl_minor : 0,
                             profile ? profile->name : "none");
        goto fail;
    }
    if (!OSMesaMakeCurrent(osm->context, osm->pixels, GL_UNSIGNED_BYTE, width, height)) {
        stin_platform_errorf(err, err_size, "OSMesa: OSMesaMakeCurrent(%dx%d) failed", width,
                             height);
        goto fail;
    }
    /* Row 0 at the bottom, as glReadPixels returns it. */
    OSMesaPixelStore(OSMESA_Y_UP, 1);
    return osm;
oom:
    stin_platform_errorf(err, err_size, "OSMesa: out of memory for a %dx%d buffer", width,
                         height);
fail:
    stin_osmesa_destroy(osm);
    return NULL;
}

void *stin_osmesa_get_proc(stin_osmesa *osm, const char *name)
{
    (void)osm;
    return stin_platform_fn_to_ptr((stin_platform_fn)OSMesaGetProcAddress(name));
}
