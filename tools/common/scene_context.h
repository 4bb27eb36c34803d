/* SPDX-License-Identifier: MIT */
/* A loaded scene in a stin context of its own: the caller's desc sized for
 * the scene and its csg products, the block allocated, the context created,
 * the meshes and textures made and the products checked against them.
 * stin-render does this once; the viewer again whenever a forced tier or
 * technique changes (a stin context's choices are fixed at creation). */
#ifndef STIN_TOOLS_SCENE_CONTEXT_H
#define STIN_TOOLS_SCENE_CONTEXT_H

#include "scene.h"
#include "scene_csg.h"
#include "scene_gpu.h"
#include "stin/stin.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct scene_context {
    void *block;
    stin_context *ctx;
    scene_gpu gpu;      /* its csg: the products given to scene_context_open */
    int have_gpu;
} scene_context;

/* Where scene_context_open stopped. */
typedef enum scene_context_step {
    SCENE_CONTEXT_OK = 0,
    SCENE_CONTEXT_SCENE,   /* the scene does not fit stin's limits (bad input) */
    SCENE_CONTEXT_MEMORY,  /* the block could not be allocated */
    SCENE_CONTEXT_CREATE,  /* stin_create failed: *result says how (its log says why) */
    SCENE_CONTEXT_MESHES   /* a mesh, texture or csg operand was refused (bad input) */
} scene_context_step;

/* desc: the caller's (get_proc_address, log, tier, techniques, ...),
 * raised here to what s and products need. On failure everything made is
 * released, err holds "FILE: ..." and *result stin_create's result (or
 * STIN_OK where stin_create was not reached or succeeded). */
scene_context_step scene_context_open(scene_context *c, const scene *s,
                                      const scene_csg_products *products, stin_desc *desc,
                                      stin_result *result, char *err, size_t err_size);
void scene_context_close(scene_context *c);

#ifdef __cplusplus
}
#endif
#endif
