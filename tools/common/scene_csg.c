/* SPDX-License-Identifier: MIT */
/* The csg list of a scene file as products for stin_draw_csg, and what
 * stin would refuse of them checked before any GL. */
#include "scene_csg.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* stin's capacities are "below 2^24" (stin_csg_settings). */
#define CAPACITY_LIMIT ((1u << 24) - 1u)
/* The normalisation's scratch grows to this at most: stin stops past 2^24
 * steps, and a step writes 2 words at most. */
#define SCRATCH_WORDS_MAX (1u << 25)

typedef struct builder {
    const scene *s;
    stin_csg_node *nodes;
    int node_count, node_cap;
    int *objects, *operands;
    int object_count, object_cap, operand_cap;
    /* per csg entry and per object: the product that last reached it (+1)
     * and its node there */
    int *entry_seen, *entry_node, *object_seen, *object_node;
    int *order, *stack;   /* the entries of the product being built, and the walk's */
} builder;

static int grow(void **p, int *cap, int need, size_t size)
{
    void *q;
    int n = *cap ? *cap : 16;
    if (need <= *cap)
        return 1;
    while (n < need)
        n *= 2;
    q = realloc(*p, (size_t)n * size);
    if (!q)
        return 0;
    *p = q;
    *cap = n;
    return 1;
}

static int ascending(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

static int push_node(builder *b, stin_csg_node n)
{
    if (!grow((void **)&b->nodes, &b->node_cap, b->node_count + 1, sizeof *b->nodes))
        return 0;
    b->nodes[b->node_count++] = n;
    return 1;
}

/* Entries reached from root (once each) into b->order, ascending: operands
 * are earlier entries, so that is an order with operands first. Counts the
 * distinct objects too. */
static int reach(builder *b, int root, int mark, int *objects)
{
    int n = 0, top = 0, k;
    *objects = 0;
    b->entry_seen[root] = mark;
    b->stack[top++] = root;
    while (top > 0) {
        int at = b->stack[--top];
        const scene_csg *e = &b->s->csg[at];
        b->order[n++] = at;
        for (k = 0; k < 2; k++) {
            int x = k ? e->b : e->a;
            if (x >= 0 && b->object_seen[x] != mark) {
                b->object_seen[x] = mark;
                ++*objects;
            } else if (x < 0 && b->entry_seen[-1 - x] != mark) {
                b->entry_seen[-1 - x] = mark; /* marked when pushed: on the stack once */
                b->stack[top++] = -1 - x;
            }
        }
    }
    qsort(b->order, (size_t)n, sizeof *b->order, ascending);
    return n;
}

/* One product's nodes from b->node_count on; 0 out of memory. */
static int emit(builder *b, int entries, int first_node, int first_object)
{
    int i, k;
    for (i = 0; i < entries; i++) {
        int at = b->order[i];
        const scene_csg *e = &b->s->csg[at];
        stin_csg_node n;
        memset(&n, 0, sizeof n);
        for (k = 0; k < 2; k++) {
            int x = k ? e->b : e->a, node;
            if (x < 0) {
                node = b->entry_node[-1 - x];
            } else if (b->object_node[x] >= first_node) { /* this product's already */
                node = b->object_node[x];
            } else {
                stin_csg_node leaf;
                int slot = b->object_count;
                if (!grow((void **)&b->objects, &b->object_cap, slot + 1, sizeof *b->objects) ||
                    !grow((void **)&b->operands, &b->operand_cap, slot + 1, sizeof *b->operands))
                    return 0;
                b->objects[slot] = x;
                b->operands[slot] = 2 * at + k;
                b->object_count++;
                memset(&leaf, 0, sizeof leaf);
                leaf.op = STIN_CSG_PRIMITIVE;
                leaf.primitive = (uint32_t)(slot - first_object);
                node = b->object_node[x] = b->node_count;
                if (!push_node(b, leaf))
                    return 0;
            }
            if (k)
                n.b = (uint32_t)(node - first_node);
            else
                n.a = (uint32_t)(node - first_node);
        }
        n.op = e->op == SCENE_CSG_UNION       ? STIN_CSG_UNION
               : e->op == SCENE_CSG_INTERSECT ? STIN_CSG_INTERSECTION
                                              : STIN_CSG_SUBTRACTION;
        b->entry_node[at] = b->node_count;
        if (!push_node(b, n))
            return 0;
    }
    return 1;
}

static void builder_free(builder *b)
{
    free(b->nodes);
    free(b->objects);
    free(b->operands);
    free(b->entry_seen);
    free(b->entry_node);
    free(b->object_seen);
    free(b->object_node);
    free(b->order);
    free(b->stack);
}

int scene_csg_products_build(const scene *s, scene_csg_products *out)
{
    builder b;
    int i, *first; /* per product: its first object and first node */
    size_t entries = (size_t)s->csg_count + 1, objects = (size_t)s->object_count + 1;
    memset(out, 0, sizeof *out);
    memset(&b, 0, sizeof b);
    b.s = s;
    out->products = calloc(entries, sizeof *out->products);
    out->roots = calloc(entries, sizeof *out->roots);
    first = calloc(2 * entries, sizeof *first);
    b.entry_seen = calloc(entries, sizeof *b.entry_seen);
    b.entry_node = calloc(entries, sizeof *b.entry_node);
    b.order = calloc(entries, sizeof *b.order);
    b.stack = calloc(entries, sizeof *b.stack);
    b.object_seen = calloc(objects, sizeof *b.object_seen);
    b.object_node = malloc(objects * sizeof *b.object_node);
    if (!out->products || !out->roots || !first || !b.entry_seen || !b.entry_node ||
        !b.order || !b.stack || !b.object_seen || !b.object_node)
        goto fail;
    for (i = 0; i < s->object_count; i++)
        b.object_node[i] = -1;
    for (i = 0; i < s->csg_count; i++) {
        scene_gpu_csg *p;
        int reached, distinct, first_node = b.node_count, first_object = b.object_count;
        if (s->csg[i].used)
            continue;
        reached = reach(&b, i, out->count + 1, &distinct);
        p = &out->products[out->count];
        out->roots[out->count] = i;
        first[2 * out->count] = first_object;
        first[2 * out->count + 1] = first_node;
        out->count++;
        if (reached + distinct > SCENE_CSG_NODES_MAX) { /* stin refuses it: not built */
            p->node_count = reached + distinct;
            first[2 * out->count - 1] = -1;
            continue;
        }
        if (!emit(&b, reached, first_node, first_object))
            goto fail;
        p->primitive_count = b.object_count - first_object;
        p->node_count = b.node_count - first_node;
    }
    for (i = 0; i < out->count; i++) { /* the arrays have stopped moving */
        scene_gpu_csg *p = &out->products[i];
        if (first[2 * i + 1] < 0)
            continue;
        p->objects = b.objects + first[2 * i];
        p->nodes = b.nodes + first[2 * i + 1];
    }
    free(first);
    out->nodes = b.nodes;
    out->objects = b.objects;
    out->operands = b.operands;
    b.nodes = NULL;
    b.objects = b.operands = NULL;
    builder_free(&b);
    return 1;
fail:
    free(first);
    builder_free(&b);
    scene_csg_products_free(out);
    return 0;
}

void scene_csg_products_free(scene_csg_products *p)
{
    free(p->products);
    free(p->roots);
    free(p->nodes);
    free(p->objects);
    free(p->operands);
    memset(p, 0, sizeof *p);
}

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
    uint64_t primitives = 0, terms = 0, literals = 0, scratch_need = 0;
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
    terms = desc->csg.max_terms ? desc->csg.max_terms : 256u;
    if (ok && scratch_need > terms + literals)
        literals = scratch_need - terms;
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
