/* SPDX-License-Identifier: MIT */
#include "scene_context.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

scene_context_step scene_context_create(scene_context *c, const scene *s,
                                        const scene_csg_products *products, stin_desc *desc,
                                        stin_result *result, char *err, size_t err_size)
{
    size_t bytes;
    memset(c, 0, sizeof *c);
    *result = STIN_OK;
    if (s) {
        int fits = scene_csg_products_check(s, products, desc, err, err_size);
        if (fits < 0) {
            snprintf(err, err_size, "out of memory");
            return SCENE_CONTEXT_MEMORY;
        }
        if (!fits || !scene_gpu_size_desc_checked(s, desc, err, err_size))
            return SCENE_CONTEXT_SCENE;
    }
    bytes = stin_memory_size(desc);
    c->block = malloc(bytes);
    if (!c->block) {
        snprintf(err, err_size, "cannot allocate %zu bytes for the stin context", bytes);
        return SCENE_CONTEXT_MEMORY;
    }
    *result = stin_create(desc, c->block, bytes, &c->ctx);
    if (*result != STIN_OK) {
        snprintf(err, err_size, "cannot create the stin context (%s)", stin_result_name(*result));
        scene_context_close(c);
        return SCENE_CONTEXT_CREATE;
    }
    return SCENE_CONTEXT_OK;
}

scene_context_step scene_context_load(scene_context *c, const scene *s,
                                      const scene_csg_products *products, char *err,
                                      size_t err_size)
{
    if (!scene_gpu_create(&c->gpu, s, c->ctx, err, err_size))
        return SCENE_CONTEXT_MESHES;
    c->have_gpu = 1;
    if (!scene_csg_products_check_meshes(&c->gpu, products, c->ctx, err, err_size))
        return SCENE_CONTEXT_OPERANDS;
    c->gpu.csg = products->products; /* the file's csg list: its objects drawn as products */
    c->gpu.csg_count = products->count;
    return SCENE_CONTEXT_OK;
}

scene_context_step scene_context_open(scene_context *c, const scene *s,
                                      const scene_csg_products *products, stin_desc *desc,
                                      stin_result *result, char *err, size_t err_size)
{
    scene_context_step step = scene_context_create(c, s, products, desc, result, err, err_size);
    if (step == SCENE_CONTEXT_OK && (step = scene_context_load(c, s, products, err, err_size)))
        scene_context_close(c);
    return step;
}

void scene_context_close(scene_context *c)
{
    if (c->have_gpu)
        scene_gpu_destroy(&c->gpu, c->ctx);
    if (c->ctx)
        stin_destroy(c->ctx);
    free(c->block);
    memset(c, 0, sizeof *c);
}
