/* SPDX-License-Identifier: MIT */
/* Capability detection (gl/caps.c). */
#ifndef STIN_CAPS_PARSE_H
#define STIN_CAPS_PARSE_H

#include "stin/stin.h"
#include "gl/gl_calls.h"

/* ---- capabilities ------------------------------------------------------- */
/* Parses what the driver reports; pure so that unit tests feed recorded strings. */
typedef struct stin__caps_input {
    const char *version;        /* GL_VERSION */
    const char *glsl_version;   /* GL_SHADING_LANGUAGE_VERSION or NULL */
    const char *extensions;     /* GL_EXTENSIONS (space separated) or NULL */
    const char *(*extension_at)(void *user, int i); /* 3.0+: glGetStringi, or NULL */
    void *extension_user;
    int extension_count;
    int core_profile;
    int max_gl_version;         /* 0 = as reported */
    uint64_t caps_mask;
    const unsigned char *loaded; /* per stin__glfn, NULL = all loaded */
} stin__caps_input;

/* Fills version, GLSL version, profile and the present/hidden bits. Limits are
 * left untouched. Returns 0 if GL_VERSION does not parse. */
int stin__caps_parse(const stin__caps_input *in, stin_caps *out);
stin_result stin__caps_detect(const stin__gl *gl, const unsigned char *loaded,
                              uint64_t caps_mask, int max_gl_version, stin_caps *caps);
/* Exact match of one token in a space-separated list. */
int stin__token_in_list(const char *list, const char *token, size_t token_len);

#endif
