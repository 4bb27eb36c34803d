/* SPDX-License-Identifier: MIT */
/* The csg list of a scene file as products for stin_draw_csg. */
#include "scene_csg.h"

#include <stdlib.h>
#include <string.h>

typedef struct builder {
    const scene *s;
    stin_csg_node *nodes;
    int node_count, node_cap;
    int *objects;
    int object_count, object_cap;
    int first_object;     /* this product's objects start here */
    int ok;
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

/* The index of a new node (operands emitted first); -1 out of memory. */
static int emit(builder *b, int operand)
{
    stin_csg_node n;
    memset(&n, 0, sizeof n);
    if (operand >= 0) { /* an object: a primitive of the product, once */
        int i;
        for (i = b->first_object; i < b->object_count && b->objects[i] != operand; i++)
            ;
        if (i == b->object_count) {
            if (!grow((void **)&b->objects, &b->object_cap, i + 1, sizeof *b->objects))
                return -1;
            b->objects[b->object_count++] = operand;
        }
        n.op = STIN_CSG_PRIMITIVE;
        n.primitive = (uint32_t)(i - b->first_object);
    } else {
        const scene_csg *e = &b->s->csg[-1 - operand];
        int a = emit(b, e->a), c = a < 0 ? -1 : emit(b, e->b);
        if (c < 0)
            return -1;
        n.op = e->op == SCENE_CSG_UNION       ? STIN_CSG_UNION
               : e->op == SCENE_CSG_INTERSECT ? STIN_CSG_INTERSECTION
                                              : STIN_CSG_SUBTRACTION;
        n.a = (uint32_t)a;
        n.b = (uint32_t)c;
    }
    if (!grow((void **)&b->nodes, &b->node_cap, b->node_count + 1, sizeof *b->nodes))
        return -1;
    b->nodes[b->node_count] = n;
    return b->node_count++;
}

int scene_csg_products_build(const scene *s, scene_csg_products *out)
{
    builder b;
    int i, first_node, *first; /* per product: its first object and first node */
    memset(out, 0, sizeof *out);
    memset(&b, 0, sizeof b);
    b.s = s;
    out->products = calloc((size_t)s->csg_count + 1, sizeof *out->products);
    first = calloc(2 * (size_t)s->csg_count + 1, sizeof *first);
    if (!out->products || !first) {
        free(out->products);
        free(first);
        memset(out, 0, sizeof *out);
        return 0;
    }
    for (i = 0; i < s->csg_count; i++) {
        scene_gpu_csg *p;
        if (s->csg[i].used)
            continue;
        first_node = b.node_count;
        b.first_object = b.object_count;
        /* each node's operands are emitted before it: local indices */
        if (emit(&b, -1 - i) < 0) {
            free(b.nodes);
            free(b.objects);
            free(out->products);
            free(first);
            memset(out, 0, sizeof *out);
            return 0;
        }
        first[2 * out->count] = b.first_object;
        first[2 * out->count + 1] = first_node;
        p = &out->products[out->count++];
        p->primitive_count = b.object_count - b.first_object;
        p->node_count = b.node_count - first_node;
    }
    for (i = 0; i < out->count; i++) { /* the arrays have stopped moving */
        scene_gpu_csg *p = &out->products[i];
        int fo = first[2 * i], fn = first[2 * i + 1], k;
        /* node operands are indices into the whole array: make them local */
        for (k = 0; k < p->node_count; k++)
            if (b.nodes[fn + k].op != STIN_CSG_PRIMITIVE) {
                b.nodes[fn + k].a -= (uint32_t)fn;
                b.nodes[fn + k].b -= (uint32_t)fn;
            }
        p->objects = b.objects + fo;
        p->nodes = b.nodes + fn;
    }
    free(first);
    out->nodes = b.nodes;
    out->objects = b.objects;
    return 1;
}

void scene_csg_products_free(scene_csg_products *p)
{
    free(p->products);
    free(p->nodes);
    free(p->objects);
    memset(p, 0, sizeof *p);
}
