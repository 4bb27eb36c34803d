/* SPDX-License-Identifier: MIT */
/* A scene file's csg list as stin CSG products (scene_csg.c): one product
 * per entry that no later entry uses, its tree written as nodes (operands
 * before their node) over the distinct objects it names. */
#ifndef STIN_TOOLS_SCENE_CSG_H
#define STIN_TOOLS_SCENE_CSG_H

#include "scene.h"
#include "scene_gpu.h"

typedef struct scene_csg_products {
    scene_gpu_csg *products;
    int count;
    stin_csg_node *nodes;   /* every product's, one after the other */
    int *objects;
} scene_csg_products;

/* 1 on success (an empty list gives count 0); 0 out of memory. */
int scene_csg_products_build(const scene *s, scene_csg_products *out);
void scene_csg_products_free(scene_csg_products *p);

#endif
