/* SPDX-License-Identifier: MIT */
/*
 * Internals shared by the scene loader's files: the JSON reading helpers
 * (scene_json_util.c), mesh files (scene_mesh_file.c) and textures
 * (scene_texture.c). Not for use outside tools/common and its tests.
 */
#ifndef STIN_TOOLS_SCENE_INTERNAL_H
#define STIN_TOOLS_SCENE_INTERNAL_H

#include <cJSON.h>

#include "image_io.h"
#include "isolate.h"
#include "scene.h"

/* Largest magnitude any number in a scene file may have; bigger values are
 * almost always typos and would overflow float maths downstream. */
#define SCENE_NUMBER_LIMIT 1e6

/* Lights one frame can take: stin_desc.max_lights is "at most 32"
 * (include/stin/stin.h). More is an error at load, naming the file. */
#define SCENE_LIGHTS_MAX 32

/* Error sink for one scene file. Every helper that fails writes
 * "FILE: WHERE: problem" into err and returns 0. */
typedef struct scene_parser {
    const char *file;
    char *err;
    size_t err_size;
} scene_parser;

/* Allowed range of a number member. */
typedef enum scene_range {
    SCENE_ANY = 0,     /* finite, |x| <= SCENE_NUMBER_LIMIT */
    SCENE_POSITIVE,    /* > 0 */
    SCENE_NONNEGATIVE, /* >= 0 */
    SCENE_UNIT         /* [0, 1] */
} scene_range;

#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
int scene_fail(scene_parser *p, const char *where, const char *fmt, ...);

/* "where.key", or just "key" when where is empty; truncates to size. */
void scene_join(char *out, size_t size, const char *where, const char *key);

/* Fails unless v is a JSON object whose keys are all in the NULL-terminated
 * list `allowed` (and none repeats). */
int scene_check_object(scene_parser *p, const cJSON *v, const char *where,
                       const char *const *allowed);
/* Fails unless obj has member key. */
int scene_require(scene_parser *p, const cJSON *obj, const char *key, const char *where);

/* Optional members: when key is absent *out keeps its value (the default). */
int scene_get_number(scene_parser *p, const cJSON *obj, const char *key, const char *where,
                     scene_range range, float *out);
int scene_get_int(scene_parser *p, const cJSON *obj, const char *key, const char *where,
                  int lo, int hi, int *out);
int scene_get_vector(scene_parser *p, const cJSON *obj, const char *key, const char *where,
                     int n, scene_range range, float *out);
int scene_get_bool(scene_parser *p, const cJSON *obj, const char *key, const char *where,
                   int *out);
/* Copies a string member; fails if it does not fit in size (with its NUL)
 * or is empty. */
int scene_get_string(scene_parser *p, const cJSON *obj, const char *key, const char *where,
                     char *out, size_t size);

/* Joins a path from a scene file with the directory of that file (absolute
 * paths are kept). 0 if it does not fit. */
int scene_resolve_path(const char *scene_file, const char *rel, char *out, size_t size);

/* Model and texture files are decoded in a child process (isolate.h) that
 * gets this long and may hand back this many bytes. */
#define SCENE_IMPORT_SECONDS 60
#define SCENE_IMPORT_BYTES_MAX ((size_t)2 << 30)
/* The limit in force, SCENE_IMPORT_SECONDS unless a test or the fuzzer
 * shortens it. */
extern unsigned scene_import_seconds;
/* Runs work (a decoder of the file at path) in a child under those limits,
 * as isolate_run; where scene_import_memo is set, a file decoded before
 * whose device, inode, size and modification time are unchanged gets a copy
 * of the bytes it gave then, and no child. */
int scene_import(isolate_work work, const char *path, unsigned char **out, size_t *out_size,
                 char *why, size_t why_size);

/* Fails (reason in why) unless path names a regular file: a device or FIFO
 * would feed a decoder forever. */
int scene_check_regular_file(const char *path, char *why, size_t why_size);
/* Cheap checks of a model file before any importer sees it: rejects what is
 * known to make assimp loop (a PLY header without end_header). */
int scene_model_precheck(const char *path, char *why, size_t why_size);

/* scene_load() of text already in memory (size bytes, text[size] == '\0')
 * as if read from path; relative file names resolve against path. For the
 * fuzzer, which has no file. */
int scene_load_text(const char *path, const char *text, size_t size, scene *out, char *err,
                    size_t err_size);

/* Texels a side of a texture, at most (files, procedural, embedded). */
#define SCENE_TEXTURE_SIZE_MAX 8192

/* img (rows top first, 1-4 channels) -> RGBA8 rows bottom first into out
 * (4 * width * height bytes): 1 and 2 channels are grey (+ alpha), a
 * missing alpha is opaque; linearise decodes sRGB colour (not alpha). */
void scene_image_to_rgba8(const image *img, int linearise, uint8_t *out);

/* The defaults of docs/scene-format.md; the name is kept. */
void scene_material_defaults(scene_material *m);

/* out = a * b, column-major 4x4; out may alias a or b. */
void scene_mat4_mul(const float a[16], const float b[16], float out[16]);

/* Builds texture `json` (member of "textures" at where) into *out.
 * `done` holds the `done_count` textures built before it, which
 * normal_from_height may name. out->name must be set by the caller. */
int scene_texture_build(scene_parser *p, const cJSON *json, const char *where,
                        const scene_texture *done, int done_count, scene_texture *out);

#endif
