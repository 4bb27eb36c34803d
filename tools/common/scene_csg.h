/* SPDX-License-Identifier: MIT */
/* A scene file's csg list as stin CSG products (scene_csg.c): one product
 * per entry that no later entry uses, its expression written as nodes
 * (operands before their node) over the distinct objects it names. An entry
 * or object a product reaches twice is one node used twice (the tree stays
 * a DAG: an entry that unions the one before with itself k times is k + 1
 * nodes, not 2^k). */
#ifndef STIN_TOOLS_SCENE_CSG_H
#define STIN_TOOLS_SCENE_CSG_H

#include "scene.h"
#include "scene_gpu.h"

/* stin_csg_desc.node_count at most (include/stin/stin.h). */
#define SCENE_CSG_NODES_MAX 65536

typedef struct scene_csg_products {
    scene_gpu_csg *products;  /* a product of more than SCENE_CSG_NODES_MAX nodes has
                               * node_count, nodes NULL (scene_csg_products_check) */
    int count;
    int *roots;               /* per product: its csg entry */
    stin_csg_node *nodes;     /* every product's, one after the other */
    int *objects;
    int *operands;            /* per objects[] slot: 2 x entry + (0: a, 1: b) naming it first */
} scene_csg_products;

/* 1 on success (an empty list gives count 0); 0 out of memory. */
int scene_csg_products_build(const scene *s, scene_csg_products *out);
void scene_csg_products_free(scene_csg_products *p);

/* What stin_draw_csg would refuse, refused before any GL: more than
 * SCENE_CSG_NODES_MAX nodes, an operand whose material is not opaque or is
 * displaced, an expression stin_csg_measure refuses (nesting deeper than
 * 1024, more normalisation steps than stin takes). What stin's capacities
 * can hold is given room instead: desc->csg.max_primitives, max_terms and
 * max_literals raised to the products' sums (and the normalisation's
 * scratch). 0 and "FILE: csg[i]...: problem" in err otherwise (-1: out of
 * memory). */
int scene_csg_products_check(const scene *s, const scene_csg_products *p, stin_desc *desc,
                             char *err, size_t err_size);

/* After scene_gpu_create: 0 and "FILE: csg[i].a: ..." in err when an
 * operand's mesh is not a closed 2-manifold (stin_query_mesh_info). */
int scene_csg_products_check_meshes(const scene_gpu *g, const scene_csg_products *p,
                                    stin_context *ctx, char *err, size_t err_size);

#endif
