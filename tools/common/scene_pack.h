/* SPDX-License-Identifier: MIT */
/*
 * A loaded scene as one flat, little-endian block ("scene pack"): what the
 * browser front end (platform/web) draws. The native loader (JSON, model
 * files through assimp, procedural and image textures) does all the work
 * once, so the browser draws exactly the triangles and texels the Embree
 * reference sees, and neither cJSON, assimp nor OpenImageIO has to be
 * compiled to WebAssembly.
 *
 * Layout: the magic "STINPACK", a version, the sizes of the pointer-free
 * structs (a reader built with another layout refuses the block), the
 * scene's own fields, then per mesh its counts, name and arrays, per texture
 * its fields and texels, and the materials, objects, lights and csg list as
 * their structs. Every array starts on a 4-byte boundary.
 */
#ifndef STIN_TOOLS_SCENE_PACK_H
#define STIN_TOOLS_SCENE_PACK_H

#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Bytes scene_pack_write needs for s. */
size_t scene_pack_size(const scene *s);
/* Writes s into out (scene_pack_size(s) bytes). */
void scene_pack_write(const scene *s, unsigned char *out);
/* Reads a pack. The scene's arrays point into data, which must stay alive
 * and 4-byte aligned; release with scene_pack_release (not scene_free).
 * 0 on a malformed block, with err saying why. */
int scene_pack_read(const unsigned char *data, size_t size, scene *out, char *err, size_t err_size);
void scene_pack_release(scene *s);

#ifdef __cplusplus
}
#endif
#endif
