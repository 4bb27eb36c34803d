/* SPDX-License-Identifier: MIT */
/*
 * The named entries of a scene's "meshes" while the scene loads: each entry
 * is a list of parts (a scene mesh, a material, a transform). A primitive is
 * one part; a model file is one part per (node, mesh) pair, with the node's
 * transform and the file's material for that mesh (scene_model.h). An
 * object of the entry becomes one scene object per part. Internal to
 * scene_json.c and scene_entries.c.
 */
#ifndef STIN_TOOLS_SCENE_ENTRIES_H
#define STIN_TOOLS_SCENE_ENTRIES_H

#include "scene_internal.h"
#include "scene_model.h"

typedef struct scene_part {
    int mesh;              /* index into scene.meshes */
    int material;          /* index into scene.materials; -1: the object's */
    float transform[16];   /* part -> entry coordinates */
} scene_part;

typedef struct scene_entry {
    char name[SCENE_NAME_MAX];
    int first_part, part_count;
} scene_entry;

typedef struct scene_entries {
    scene_entry *entries; int entry_count;
    scene_part *parts; int part_count, part_cap;
    int mesh_cap;
    /* Models whose materials and textures join the scene's after the
     * scene's own (so a model cannot shadow a name the file uses). */
    scene_model *models; int *model_entry; int model_count;
} scene_entries;

/* Appends a primitive (its arrays move into the scene) as entry `name`. */
int scene_entries_add_mesh(scene_parser *p, scene_entries *e, scene *s, const char *name,
                           scene_mesh *m);
/* Loads model file `full` (`rel` as the scene names it) as entry `name`;
 * where is the scene path of its "file" key, for messages and warnings. */
int scene_entries_add_model(scene_parser *p, scene_entries *e, scene *s, const char *name,
                            const char *where, const char *full, const char *rel);
/* After the scene's own materials: the models' textures and materials join
 * the scene and their parts point at them. */
int scene_entries_add_materials(scene_parser *p, scene_entries *e, scene *s);
/* Index of the entry called name, -1 if none. */
int scene_entries_find(const scene_entries *e, const char *name);
void scene_entries_free(scene_entries *e);

/* Appends one warning line (FILE: where: text) to s->warnings. */
int scene_warn(scene_parser *p, scene *s, const char *where, const char *text);

#endif
