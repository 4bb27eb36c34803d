/* SPDX-License-Identifier: MIT */
/* Open addressing with linear probing, FNV-1a hashes. */
#include "name_table.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static size_t hash(const char *s)
{
    uint32_t h = 2166136261u;
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 16777619u;
    return h;
}

int name_table_init(name_table *t, size_t names)
{
    size_t slots = 16;
    while (slots < 2 * names)
        slots *= 2;
    t->keys = calloc(slots, sizeof *t->keys);
    t->values = calloc(slots, sizeof *t->values);
    t->mask = slots - 1;
    if (t->keys && t->values)
        return 1;
    name_table_free(t);
    return 0;
}

void name_table_free(name_table *t)
{
    free(t->keys);
    free(t->values);
    memset(t, 0, sizeof *t);
}

/* The slot holding name, or the free one where it would go. */
static size_t slot_of(const name_table *t, const char *name)
{
    size_t i = hash(name) & t->mask;
    while (t->keys[i] && strcmp(t->keys[i], name) != 0)
        i = (i + 1) & t->mask;
    return i;
}

int name_table_find(const name_table *t, const char *name, int *value)
{
    size_t i = slot_of(t, name);
    if (!t->keys[i])
        return 0;
    *value = t->values[i];
    return 1;
}

void name_table_add(name_table *t, const char *name, int value)
{
    size_t i = slot_of(t, name);
    t->keys[i] = name;
    t->values[i] = value;
}
