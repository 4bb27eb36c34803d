/* SPDX-License-Identifier: MIT */
/*
 * One model file (OBJ/MTL, glTF/glb, PLY, ... through assimp) as the scene
 * loader takes it: its meshes in their own coordinates, one part per
 * (node, mesh) pair with the node's accumulated transform and the mesh's
 * material, the materials, and their decoded textures. Internal to
 * tools/common and its tests.
 *
 * The import runs in a child process (isolate.h): scene_model_import_work
 * builds the model there and scene_model_write streams it; the parent reads
 * it back with scene_model_read, which trusts nothing (sizes, indices, finite
 * numbers).
 */
#ifndef STIN_TOOLS_SCENE_MODEL_H
#define STIN_TOOLS_SCENE_MODEL_H

#include "scene.h"

#include <stddef.h>
#include <stdint.h>

typedef enum scene_alpha_mode {
    SCENE_ALPHA_OPAQUE = 0, /* glTF OPAQUE, or no mode (OBJ d = 1) */
    SCENE_ALPHA_BLEND,      /* glTF BLEND, or OBJ d < 1: opacity kept, stin blends */
    SCENE_ALPHA_MASK        /* glTF MASK: stin has no alpha test, drawn opaque */
} scene_alpha_mode;

typedef struct scene_model_part {
    uint32_t mesh;          /* index into the model's meshes */
    int32_t material;       /* index into the model's materials, -1 = none */
    float transform[16];    /* column-major, node -> model file */
} scene_model_part;

typedef struct scene_model_material {
    char name[SCENE_NAME_MAX];
    float color[4];         /* linear base colour (glTF factor, OBJ Kd) and alpha */
    float specular[3];      /* OBJ Ks; 0 for glTF */
    float shininess;        /* OBJ Ns, clamped to [0, 128] */
    int32_t albedo, normal; /* index into the model's textures, -1 = none */
    int32_t alpha_mode;     /* scene_alpha_mode */
} scene_model_material;

/* Parts at most (node x mesh pairs) and node nesting at most. */
#define SCENE_MODEL_PARTS_MAX 1000000
#define SCENE_MODEL_DEPTH_MAX 256

typedef struct scene_model {
    scene_mesh *meshes; uint32_t mesh_count;
    scene_model_part *parts; uint32_t part_count;
    scene_model_material *materials; uint32_t material_count;
    scene_texture *textures; uint32_t texture_count;
    char *warnings;         /* "" or lines ending '\n': what was left out */
} scene_model;

/* Loads path in a child process. On failure writes a reason (no file name)
 * into why and returns 0 with *out empty. */
int scene_model_load(const char *path, scene_model *out, char *why, size_t why_size);
void scene_model_free(scene_model *m);

/* Child side: the importer's work for isolate_run (arg: the path). */
int scene_model_import_work(void *arg, int fd, char *why, size_t why_size);

/* Appends one line (a '\n' is added) to m->warnings. 0 when out of memory. */
int scene_model_warn(scene_model *m, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Streams m to fd (child) / rebuilds it from the bytes, checked (parent). */
int scene_model_write(int fd, const scene_model *m);
int scene_model_read(const unsigned char *bytes, size_t size, scene_model *out, char *why,
                     size_t why_size);

/* Child side, scene_model_materials.c: the material `index` of the assimp
 * scene `ai` (a const struct aiScene *) appended to m with its textures
 * decoded; model_path resolves external texture files. Returns the new
 * material's index, or -1 for assimp's default material (none in the file),
 * or -2 when out of memory. */
int32_t scene_model_add_material(scene_model *m, const void *ai, unsigned index,
                                 const char *model_path);

#endif
