/* SPDX-License-Identifier: MIT */
/* What stin_draw_csg would refuse of a scene's products, refused before any
 * GL (stin_csg_measure), and the capacities they need (scene_csg.h). */
#include "scene_csg.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* stin's capacities are "below 2^24" (stin_csg_settings). */
#define CAPACITY_LIMIT ((1u << 24) - 1u)
/* The normalisation's scratch grows to this at most: stin stops past 2^24
 * steps, and a step writes 2 words at most. */
#define SCRATCH_WORDS_MAX (1u << 25)

/* "csg[i].a" of an objects[] slot. */
static void operand_key(const scene_csg_products *p, int slot, char *key, size_t size)
{
    snprintf(key, size, "csg[%d].%c", p->operands[slot] / 2, p->operands[slot] % 2 ? 'b' : 'a');
}

/* An operand's material as stin_draw_csg takes it: opaque, not displaced. */
static int check_material(const scene *s, const scene_csg_products *p, int slot, char *err,
                          size_t err_size)
{
    const scene_material *m = &s->materials[s->objects[p->objects[slot]].material];
    const float *c = m->color;
    char key[48];
    operand_key(p, slot, key, sizeof key);
    /* all zero is stin's default colour, which is opaque */
    if (c[3] < 1.0f && (c[0] != 0.0f || c[1] != 0.0f || c[2] != 0.0f || c[3] != 0.0f)) {
        snprintf(err, err_size, "%s: %s: the object's material '%s' has opacity %g; stin draws "
                 "CSG operands opaque (opacity 1)", s->path, key, m->name, c[3]);
        return 0;
    }
    if (m->displace) {
        snprintf(err, err_size, "%s: %s: the object's material '%s' is displaced; stin does not "
                 "displace CSG operands", s->path, key, m->name);
        return 0;
    }
    return 1;
}

/* stin_csg_measure in a scratch grown until it is enough; -1 out of memory. */
static int measure(const scene_gpu_csg *c, uint32_t **scratch, uint32_t *words,
                   stin_csg_size *size, const char **why)
{
    stin_csg_primitive unused;
    stin_csg_desc d;
    stin_result r;
    memset(&d, 0, sizeof d);
    d.primitives = &unused; /* measured: not looked at */
    d.primitive_count = (uint32_t)c->primitive_count;
    d.nodes = c->nodes;
    d.node_count = (uint32_t)c->node_count;
    for (;;) {
        uint32_t *grown;
        r = stin_csg_measure(&d, *scratch, *words, size, why);
        if (r != STIN_ERROR_CAPACITY || size->scratch_words <= *words ||
            *words >= SCRATCH_WORDS_MAX)
            return r == STIN_OK;
        grown = realloc(*scratch, (size_t)*words * 2 * sizeof **scratch);
        if (!grown)
            return -1;
        *scratch = grown;
        *words *= 2;
    }
}

/* Raises *field to need (0 in desc is stin's default, dflt); 0 past stin's limit. */
static int raise_capacity(uint32_t *field, uint64_t need, uint32_t dflt)
{
    if (need > CAPACITY_LIMIT)
        return 0;
    if (need > (*field ? *field : dflt))
        *field = (uint32_t)need;
    return 1;
}

int scene_csg_products_check(const scene *s, const scene_csg_products *p, stin_desc *desc,
                             char *err, size_t err_size)
{
    uint64_t primitives = 0, terms = 0, literals = 0, scratch_need = 0, room;
    uint32_t words = 1u << 16, *scratch = malloc((size_t)words * sizeof *scratch);
    int i, j, ok = 1;
    if (!scratch)
        return -1;
    for (i = 0; i < p->count && ok; i++) {
        const scene_gpu_csg *c = &p->products[i];
        stin_csg_size size;
        const char *why = "";
        int measured;
        if (!c->nodes) {
            snprintf(err, err_size, "%s: csg[%d]: the product has %d nodes (operations and "
                     "distinct objects); stin takes at most %d", s->path, p->roots[i],
                     c->node_count, SCENE_CSG_NODES_MAX);
            ok = 0;
            break;
        }
        for (j = 0; j < c->primitive_count && ok; j++)
            ok = check_material(s, p, (int)(c->objects + j - p->objects), err, err_size);
        if (!ok)
            break;
        measured = measure(c, &scratch, &words, &size, &why);
        if (measured < 0) {
            free(scratch);
            return -1;
        }
        if (!measured) {
            snprintf(err, err_size, "%s: csg[%d]: stin would refuse the product: %s", s->path,
                     p->roots[i], why);
            ok = 0;
            break;
        }
        primitives += (uint64_t)c->primitive_count;
        terms += size.terms;
        literals += size.literals;
        if (size.scratch_words > scratch_need)
            scratch_need = size.scratch_words;
    }
    free(scratch);
    if (!ok)
        return 0;
    if (!raise_capacity(&desc->csg.max_primitives, primitives, 256) ||
        !raise_capacity(&desc->csg.max_terms, terms, 256))
        ok = 0;
    /* the frame's scratch is 2 (max_terms + max_literals) words */
    scratch_need = (scratch_need + 1) / 2;
    room = desc->csg.max_terms ? desc->csg.max_terms : 256u;
    if (ok && scratch_need > room + literals)
        literals = scratch_need - room;
    if (!ok || !raise_capacity(&desc->csg.max_literals, literals, 4096)) {
        snprintf(err, err_size, "%s: csg: the products need %llu primitives, %llu terms and "
                 "%llu literals a frame; stin takes fewer than 2^24 of each", s->path,
                 (unsigned long long)primitives, (unsigned long long)terms,
                 (unsigned long long)literals);
        return 0;
    }
    return 1;
}

int scene_csg_products_check_meshes(const scene_gpu *g, const scene_csg_products *p,
                                    stin_context *ctx, char *err, size_t err_size)
{
    int i;
    for (i = 0; i < p->count; i++) {
        const scene_gpu_csg *c = &p->products[i];
        int j;
        for (j = 0; c->nodes && j < c->primitive_count; j++) {
            const scene_object *o = &g->src->objects[c->objects[j]];
            stin_mesh_info info;
            char key[48];
            if (stin_query_mesh_info(ctx, g->meshes[o->mesh], &info) != STIN_OK ||
                info.closed_manifold)
                continue;
            operand_key(p, (int)(c->objects + j - p->objects), key, sizeof key);
            snprintf(err, err_size, "%s: %s: the object's mesh '%s' is not a closed 2-manifold "
                     "(%u open, %u non-manifold edges); stin takes only closed CSG operands",
                     g->src->path, key, g->src->meshes[o->mesh].name, info.open_edges,
                     info.nonmanifold_edges);
            return 0;
        }
    }
    return 1;
}
