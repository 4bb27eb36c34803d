/* SPDX-License-Identifier: MIT */
/* libFuzzer target: model and texture files. The first byte picks the file
 * type (its extension), the rest is the file; it goes through the loader's
 * own path (checks, the decoder in a child process, the hand-over back). */
#include "scene.h"
#include "scene_internal.h"
#include "scene_model.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* glb last: the committed inputs keep their types (first byte % count). */
static const char *const types[] = { "obj", "ply", "stl", "off", "gltf", "png", "exr", "ppm", "glb" };
#define TYPE_COUNT (sizeof types / sizeof types[0])
#define FIRST_IMAGE 5
#define MODEL_AGAIN 8

/* One file per process (libFuzzer may run jobs side by side). */
static int write_input(const uint8_t *data, size_t size, const char *ext, char *path, size_t path_size)
{
    const char *dir = getenv("TMPDIR");
    FILE *f;
    int ok;
    snprintf(path, path_size, "%s/stin-fuzz-%ld.%s", dir && dir[0] ? dir : "/tmp", (long)getpid(), ext);
    if (!(f = fopen(path, "wb")))
        return 0;
    ok = fwrite(data, 1, size, f) == size;
    return fclose(f) == 0 && ok;
}

static void load_texture(const char *path)
{
    char json[1200], err[1024];
    cJSON *obj;
    scene_parser p;
    scene_texture t;
    memset(&t, 0, sizeof t);
    snprintf(json, sizeof json, "{\"file\": \"%s\"}", path);
    obj = cJSON_Parse(json);
    p.file = "fuzz.json";
    p.err = err;
    p.err_size = sizeof err;
    err[0] = '\0';
    if (scene_texture_build(&p, obj, "textures.t", NULL, 0, &t))
        free(t.rgba);
    else if (!err[0] || strchr(err, '\n'))
        abort();
    cJSON_Delete(obj);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[512], why[512];
    unsigned type;
    scene_model m;
    if (size < 1 || size > (1 << 20))
        return 0;
    type = data[0] % TYPE_COUNT;
    if (!write_input(data + 1, size - 1, types[type], path, sizeof path))
        return 0;
    scene_import_seconds = 5;
    if (type >= FIRST_IMAGE && type < MODEL_AGAIN) {
        load_texture(path);
    } else {
        why[0] = '\0';
        if (scene_model_load(path, &m, why, sizeof why))
            scene_model_free(&m);
        else if (!why[0])
            abort();
    }
    unlink(path);
    return 0;
}
