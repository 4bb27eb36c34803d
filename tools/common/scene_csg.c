/* SPDX-License-Identifier: MIT */
/* The csg list of a scene file as products for stin_draw_csg (no stin:
 * the fuzz target builds them too; scene_csg_check.c checks them). */
#include "scene_csg.h"

#include <stdlib.h>
#include <string.h>

typedef struct builder {
    const scene *s;
    stin_csg_node *nodes;
    int node_count, node_cap;
    int *objects, *operands;
    int object_count, object_cap, operand_cap;
    /* per csg entry and per object: the product that last reached it (+1)
     * and its node there */
    int *entry_seen, *entry_node, *object_seen, *object_node, *object_slot;
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
 * are earlier entries, so that is an order with operands first. The objects'
 * primitive slots go in the order a walk a before b first meets them (a
 * tree's leaves left to right, as when products were expanded). Returns the
 * entries; *objects: the objects. */
static int reach(builder *b, int root, int mark, int *objects)
{
    int n = 0, top = 0;
    *objects = 0;
    b->entry_seen[root] = mark;
    b->stack[top++] = -1 - root; /* operand codes: an object, or -1 - an entry */
    while (top > 0) {
        int x = b->stack[--top];
        const scene_csg *e;
        if (x >= 0) {
            if (b->object_seen[x] != mark) {
                b->object_seen[x] = mark;
                b->object_slot[x] = (*objects)++;
            }
            continue;
        }
        b->order[n++] = -1 - x;
        e = &b->s->csg[-1 - x];
        if (e->b >= 0 || b->entry_seen[-1 - e->b] != mark) {
            if (e->b < 0)
                b->entry_seen[-1 - e->b] = mark; /* marked when pushed: pushed once */
            b->stack[top++] = e->b;
        }
        if (e->a >= 0 || b->entry_seen[-1 - e->a] != mark) {
            if (e->a < 0)
                b->entry_seen[-1 - e->a] = mark;
            b->stack[top++] = e->a;
        }
    }
    qsort(b->order, (size_t)n, sizeof *b->order, ascending);
    return n;
}

/* One product's nodes from b->node_count on, its objects[] from
 * first_object on (objects of them); 0 out of memory. */
static int emit(builder *b, int entries, int first_node, int first_object, int objects)
{
    int i, k;
    if (!grow((void **)&b->objects, &b->object_cap, first_object + objects, sizeof *b->objects) ||
        !grow((void **)&b->operands, &b->operand_cap, first_object + objects,
              sizeof *b->operands))
        return 0;
    b->object_count = first_object + objects;
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
                int slot = first_object + b->object_slot[x];
                b->objects[slot] = x;
                b->operands[slot] = 2 * at + k;
                memset(&leaf, 0, sizeof leaf);
                leaf.op = STIN_CSG_PRIMITIVE;
                leaf.primitive = (uint32_t)b->object_slot[x];
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
    free(b->object_slot);
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
    b.stack = calloc(3 * entries, sizeof *b.stack); /* each entry once, and its two operands */
    b.object_seen = calloc(objects, sizeof *b.object_seen);
    b.object_node = malloc(objects * sizeof *b.object_node);
    b.object_slot = calloc(objects, sizeof *b.object_slot);
    if (!out->products || !out->roots || !first || !b.entry_seen || !b.entry_node ||
        !b.order || !b.stack || !b.object_seen || !b.object_node || !b.object_slot)
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
        if (!emit(&b, reached, first_node, first_object, distinct))
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
