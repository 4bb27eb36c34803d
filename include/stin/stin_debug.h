/* SPDX-License-Identifier: MIT */
/*
 * Test support. libstin_checked.a (built with STIN_GL_CHECK) audits every GL
 * call against the capability profile: an entry point or enum whose
 * capability the context lacks (after desc.caps_mask) counts as a violation,
 * and glGetError is read after every pass. The release libstin.a counts
 * nothing and reports zeros.
 */
#ifndef STIN_DEBUG_H
#define STIN_DEBUG_H

#include "stin/stin.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct stin_debug_counters {
    uint32_t gl_violations; /* calls the profile does not allow */
    uint32_t gl_errors;     /* glGetError results seen */
    int checked;            /* 1 in the checked build */
} stin_debug_counters;

stin_debug_counters stin_debug_query_counters(const stin_context *ctx);

#ifdef __cplusplus
}
#endif
#endif
