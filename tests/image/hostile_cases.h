/* SPDX-License-Identifier: MIT */
/* Caller states a frame must neither inherit nor (beyond the header's list)
 * change: the cases of the hostile-state test (hostile_test.c). */
#ifndef STIN_TESTS_HOSTILE_CASES_H
#define STIN_TESTS_HOSTILE_CASES_H

#include "caller_gl.h"

#include <stddef.h>

typedef struct hostile_env {
    const caller_gl *gl;
    int version;     /* the profile's GL version, major * 10 + minor */
    int compat;      /* a compatibility context (fixed function) */
    int gl1;         /* the frame runs the GL1 tier */
    int fixed_units; /* fixed-function texture units */
    int width, height;
    GLuint texture;  /* 1x1 red */
    GLuint program;  /* a linked program writing red */
    GLuint sampler;  /* nearest filtering, clamped */
    GLuint storage;  /* a shader storage buffer (GL 4.3) */
    /* after the frame: the storage-buffer bindings a technique of stin's
     * used (bits 0-2 the indexed points, bit 3 the generic binding): those
     * read 0, the others the caller's */
    unsigned storage_used;
    const float *colors; /* a colour array longer than any test mesh */
} hostile_env;

typedef struct hostile_case {
    const char *name;
    GLenum cap;      /* enabled by the case (0: none) */
    int version;     /* needs this GL version */
    int compat;      /* needs a compatibility context */
    void (*set)(hostile_env *e);   /* the state besides the enable */
    void (*reset)(hostile_env *e); /* back to GL's defaults */
    /* 1 when the state after the frame reads as documented; NULL: the
     * enable is off after the frame (or the caller's, per the case) */
    int (*after)(hostile_env *e, char *got, size_t size);
} hostile_case;

extern const hostile_case hostile_cases[];
extern const size_t hostile_case_count;

int hostile_applies(const hostile_case *c, const hostile_env *e);
void hostile_set(const hostile_case *c, hostile_env *e);
void hostile_reset(const hostile_case *c, hostile_env *e);
/* After a frame: 1 if the state is as the header says, else `got` says what it read. */
int hostile_after(const hostile_case *c, hostile_env *e, char *got, size_t size);

#endif
