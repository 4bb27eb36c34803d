/* SPDX-License-Identifier: MIT */
/* Uniform locations by table (gl/shader.c): a module lists the GLint fields
 * of its locations struct with the uniforms' names once, and one call fills
 * them for a linked program, -1 where the program has no such uniform. */
#ifndef STIN_UNIFORMS_H
#define STIN_UNIFORMS_H

#include <stddef.h>

#include "stin/stin.h"
#include "gl/gl_types.h"

typedef struct stin__uniform_name {
    size_t offset;    /* of a GLint field in the struct the table describes */
    const char *name; /* the uniform's name in the program */
} stin__uniform_name;

/* A table row: field (a member designator, "u_maps[1]" too) of type. */
#define STIN__UNIFORM(type, field, name) {offsetof(type, field), name}

/* Each of the n uniforms' location in prog into its field of *locs. */
void stin__uniform_locations(struct stin_context *ctx, GLuint prog, void *locs,
                             const stin__uniform_name *names, size_t n);
/* The same for a whole table (an array, not a pointer). */
#define STIN__LOCATE(ctx, prog, locs, table)                                                   \
    stin__uniform_locations(ctx, prog, locs, table, sizeof table / sizeof table[0])

#endif
