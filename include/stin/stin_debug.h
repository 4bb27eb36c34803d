/* SPDX-License-Identifier: MIT */
/*
 * Test support. libstin_checked.a (built with STIN_GL_CHECK) audits every GL
 * call against the capability profile: an entry point or enum whose
 * capability the context lacks (after desc.caps_mask) counts as a violation.
 * The release libstin.a counts nothing and reports zeros. Neither build reads
 * glGetError (that would clear the caller's errors): to see GL errors, install
 * a KHR_debug callback (the image tests do, tests/image/gl_errors.c).
 */
#ifndef STIN_DEBUG_H
#define STIN_DEBUG_H

#include "stin/stin.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct stin_debug_counters {
    uint32_t gl_violations; /* calls the profile does not allow */
    int checked;            /* 1 in the checked build */
} stin_debug_counters;

stin_debug_counters stin_debug_query_counters(const stin_context *ctx);

/* The shadow map light `light` of the last frame was tested against, for
 * looking at (both builds). Maps of spot and directional lights under
 * map-pcf, map-depth and map-combine; a point light's six faces are drawn
 * again for each point light within the frame, so none is kept
 * (STIN_ERROR_UNSUPPORTED, as for techniques without maps and lights the
 * map did not cover). STIN_ERROR_INVALID_STATE while a frame is open. The
 * texture is stin's: read it, do not change it. */
typedef struct stin_debug_map {
    uint32_t texture;   /* GL_TEXTURE_2D */
    uint32_t size;      /* texels a side the frame drew, from texel (0, 0) */
    uint32_t allocated; /* texels a side of the texture */
    int depth;          /* 1: GL_DEPTH_COMPONENT (map-pcf, map-depth); 0: map-combine's
                         * RGBA8 light-depth ramp, or map-pcf's RGBA8 map without depth
                         * textures (window depth in 24 bits: R high, B low, A 1) */
} stin_debug_map;

stin_result stin_debug_query_shadow_map(const stin_context *ctx, uint32_t light,
                                        stin_debug_map *out);

#ifdef __cplusplus
}
#endif
#endif
