/* SPDX-License-Identifier: MIT */
/* Names to indices for the scene loader (name_table.c): open addressing
 * over strings the caller keeps, so that a file of n names looks each up
 * in constant time (a csg chain of 300,000 entries loaded quadratically
 * through a linear search). */
#ifndef STIN_TOOLS_NAME_TABLE_H
#define STIN_TOOLS_NAME_TABLE_H

#include <stddef.h>

typedef struct name_table {
    const char **keys;   /* NULL: a free slot */
    int *values;
    size_t mask;         /* slots - 1: a power of two, at least twice the names */
} name_table;

/* Room for `names` names; 0 out of memory. */
int name_table_init(name_table *t, size_t names);
void name_table_free(name_table *t);
/* 1 and *value when name is there. */
int name_table_find(const name_table *t, const char *name, int *value);
/* Adds name (kept by the caller, not there yet, within the room asked for). */
void name_table_add(name_table *t, const char *name, int value);

#endif
