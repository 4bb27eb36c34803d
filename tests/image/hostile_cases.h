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
    int es;          /* an OpenGL ES context: version is the ES version */
    int gl1;         /* the frame runs the GL1 tier */
    int fixed_units; /* fixed-function texture units */
    int width, height;
    GLuint texture;  /* 1x1 red */
    GLuint program;  /* a linked program writing red */
    GLuint sampler;  /* nearest filtering, clamped */
    GLuint storage;  /* a shader storage buffer (GL 4.3) */
    GLuint buffer;   /* a 64-byte buffer: pixel unpack, pack, query, array (GL 1.5+) */
    GLuint query;    /* a query object (occlusion queries) */
    GLuint pipeline; /* a program pipeline drawing red (GL 4.1, separate shader objects) */
    GLuint array_texture; /* a 1x1x1 2D-array texture (GL 3.0) */
    GLuint vao;      /* a vertex array object (GL 3.0) */
    /* extensions that bring a state to an older version */
    int ext_query_buffer, ext_pipeline, ext_clamp, ext_provoking;
    /* after the frame: the storage-buffer bindings a technique of stin's
     * used (bits 0-2 the indexed points, bit 3 the generic binding): those
     * read 0, the others the caller's */
    unsigned storage_used;
    const float *colors; /* a colour array longer than any test mesh */
} hostile_env;

/* When a case is set: around a frame (the context made clean), or around
 * stin_create and the first frames (then taken away before a clean frame). */
enum { HOSTILE_FRAME = 1, HOSTILE_CREATE = 2 };

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
    unsigned when;   /* HOSTILE_FRAME, HOSTILE_CREATE or both */
    /* whether the context has the state (NULL: version and compat decide) */
    int (*available)(const hostile_env *e);
    /* after stin_create: 1 when the state reads as the caller left it
     * (NULL: `after`) */
    int (*after_create)(hostile_env *e, char *got, size_t size);
} hostile_case;

extern const hostile_case hostile_cases[];
extern const size_t hostile_case_count;

int hostile_applies(const hostile_case *c, const hostile_env *e);
/* The caller's objects the cases bind, made and deleted on the current context. */
void hostile_objects_make(hostile_env *e, int core);
void hostile_objects_free(hostile_env *e);
void hostile_set(const hostile_case *c, hostile_env *e);
void hostile_reset(const hostile_case *c, hostile_env *e);
/* After a frame: 1 if the state is as the header says, else `got` says what it read. */
int hostile_after(const hostile_case *c, hostile_env *e, char *got, size_t size);
int hostile_after_create(const hostile_case *c, hostile_env *e, char *got, size_t size);

#endif
