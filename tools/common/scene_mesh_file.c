/* SPDX-License-Identifier: MIT */
/* Model files (OBJ, PLY, STL, glTF/glb, anything assimp reads): imported in
 * a child process (scene_model_import.c), handed back checked
 * (scene_model_wire.c). */
#include "scene_internal.h"
#include "scene_model.h"

#include <stdlib.h>
#include <string.h>

unsigned scene_import_seconds = SCENE_IMPORT_SECONDS;

int scene_model_load(const char *path, scene_model *out, char *why, size_t why_size)
{
    unsigned char *bytes;
    size_t size;
    int ok;
    memset(out, 0, sizeof *out);
    if (!scene_check_regular_file(path, why, why_size) || !scene_model_precheck(path, why, why_size))
        return 0;
    /* assimp can crash or loop on hostile files; the child takes the hit. */
    if (!scene_import(scene_model_import_work, path, &bytes, &size, why, why_size))
        return 0;
    ok = scene_model_read(bytes, size, out, why, why_size);
    free(bytes);
    return ok;
}
