/* SPDX-License-Identifier: MIT */
/*
 * A loaded scene handed to libstin: meshes and textures created in a stin
 * context, and one frame of it submitted. Shared by stin-render, stin-bench
 * and the image tests so that all three draw a scene the same way.
 */
#ifndef STIN_TOOLS_SCENE_GPU_H
#define STIN_TOOLS_SCENE_GPU_H

#include "scene.h"
#include "stin/stin.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A CSG product of scene objects (stin_draw_csg): primitive i is object
 * objects[i] (its mesh, transform and material); the last node is the root. */
typedef struct scene_gpu_csg {
    const int *objects;
    int primitive_count;
    const stin_csg_node *nodes;
    int node_count;
} scene_gpu_csg;

typedef struct scene_gpu {
    const scene *src;
    stin_mesh *meshes;      /* one per scene mesh */
    stin_texture *textures; /* one per scene texture */
    stin_material *materials;
    /* CSG products drawn in each frame (NULL: none; the caller's, set after
     * scene_gpu_create); their objects are not drawn on their own */
    const scene_gpu_csg *csg;
    int csg_count;
    /* the frames' outline (stin_frame_desc.outline_step and outline_color;
     * 0: none; the caller's, set after scene_gpu_create) */
    float outline_step;
    float outline_color[4];
} scene_gpu;

/* The stin_desc capacities this scene needs (meshes, draws, lights, vertices,
 * textures); fields already set larger are kept. Returns 0 and writes
 * "FILE: where: problem" when the scene needs more than stin_create accepts
 * (the capacities then stop at the first such field). */
int scene_gpu_size_desc_checked(const scene *s, stin_desc *desc, char *err, size_t err_size);
/* The same for callers whose scenes are known to fit. */
void scene_gpu_size_desc(const scene *s, stin_desc *desc);
/* A scene mesh as stin_create_mesh takes it, and its positions and normals
 * as stin_update_mesh does (the arrays stay the scene's). */
stin_mesh_desc scene_gpu_mesh_desc(const scene_mesh *m);
stin_mesh_update_desc scene_gpu_mesh_update_desc(const scene_mesh *m);
/* Creates every mesh and texture; on failure writes a message and releases
 * what was created. 1 on success. */
int scene_gpu_create(scene_gpu *g, const scene *s, stin_context *ctx, char *err, size_t err_size);
void scene_gpu_destroy(scene_gpu *g, stin_context *ctx);
/* begin -> lights -> draws -> end for one frame into the current framebuffer. */
stin_result scene_gpu_frame(const scene_gpu *g, stin_context *ctx, int width, int height,
                            stin_output output, uint32_t framebuffer);
/* The same with the lights' visibility exported (stin_frame_desc.export_visibility). */
stin_result scene_gpu_frame_export(const scene_gpu *g, stin_context *ctx, int width, int height,
                                   stin_output output, stin_export ex, uint32_t framebuffer);
/* The same into viewport (x, y, width, height) of the framebuffer, the
 * camera's aspect the viewport's. */
stin_result scene_gpu_frame_viewport(const scene_gpu *g, stin_context *ctx,
                                     const int viewport[4], stin_output output, stin_export ex,
                                     uint32_t framebuffer);
/* Converts a scene light to stin's. */
void scene_gpu_light(const scene_light *in, stin_light_desc *out);

#ifdef __cplusplus
}
#endif
#endif
