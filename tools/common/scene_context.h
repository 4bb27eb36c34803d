/* SPDX-License-Identifier: MIT */
/* A loaded scene in a stin context of its own: the caller's desc sized for
 * the scene and its csg products, the block allocated, the context created
 * (scene_context_create), then the meshes and textures made and the
 * products checked against them (scene_context_load). stin-render does this
 * once; the viewer again whenever a forced tier or technique changes (a
 * stin context's choices are fixed at creation). */
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
    scene_gpu gpu;      /* after scene_context_load; its csg: the products given */
    int have_gpu;
} scene_context;

/* Where a step stopped. */
typedef enum scene_context_step {
    SCENE_CONTEXT_OK = 0,
    SCENE_CONTEXT_SCENE,    /* the scene does not fit stin's limits (bad input) */
    SCENE_CONTEXT_MEMORY,   /* the block could not be allocated */
    SCENE_CONTEXT_CREATE,   /* stin_create failed: *result says how (its log says why) */
    SCENE_CONTEXT_MESHES,   /* stin refused a mesh or texture (bad input) */
    SCENE_CONTEXT_OPERANDS  /* a csg operand is not a closed 2-manifold (bad input) */
} scene_context_step;

/* desc: the caller's (get_proc_address, log, tier, techniques, ...),
 * raised here to what s and products need (s NULL: no scene, the context
 * alone). *result: stin_create's. On failure nothing is left to close; err
 * holds "FILE: where: problem" for SCENE, the problem alone for MEMORY
 * and CREATE ("cannot create the stin context (unsupported by this
 * context)"), for the caller to prefix. */
scene_context_step scene_context_create(scene_context *c, const scene *s,
                                        const scene_csg_products *products, stin_desc *desc,
                                        stin_result *result, char *err, size_t err_size);
/* s's meshes, textures and products (which must outlive c) in c's context.
 * On failure ("FILE: ..." in err) the context stays for the caller to ask
 * what it chose; scene_context_close releases it. */
scene_context_step scene_context_load(scene_context *c, const scene *s,
                                      const scene_csg_products *products, char *err,
                                      size_t err_size);
/* Both; on failure everything is released. */
scene_context_step scene_context_open(scene_context *c, const scene *s,
                                      const scene_csg_products *products, stin_desc *desc,
                                      stin_result *result, char *err, size_t err_size);
void scene_context_close(scene_context *c);

#ifdef __cplusplus
}
#endif
#endif
