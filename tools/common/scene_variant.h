/* SPDX-License-Identifier: MIT */
/*
 * The surface tests' views of a normal-mapped scene (tests/image/surface_test.c),
 * built once here so that the native tests and the browser's scene packs
 * (stin-scene-pack --variants) draw the same scene:
 *   parallax-down   the camera straight down the object's normal through a
 *                   0.25-degree lens (parallax's shift V.xy h' under 0.01 texel);
 *   parallax-limit  a grazing camera, the albedo a 256 x 256 uv gradient
 *                   (texel (i, j) = (i, j, 0)), ambient 1 and no lights, no
 *                   specular, height_scale raised to SCENE_VARIANT_LIMIT_SCALE:
 *                   the beauty's R, G is the uv parallax sampled.
 * A variant shares the source scene's meshes and textures: it lives no longer
 * than the source, and scene_variant_free (not scene_free) releases it.
 */
#ifndef STIN_SCENE_VARIANT_H
#define STIN_SCENE_VARIANT_H

#include "scene.h"

/* raised so that the 8-bit read-back of the uv (1/256 uv a channel) is
 * small against |h'| (up to scale / 2) */
#define SCENE_VARIANT_LIMIT_SCALE 0.3f

/* The first normal-mapped object's centre and world normal; 0 if none. */
int scene_variant_mapped(const scene *s, float centre[3], float normal[3]);
/* The first object with normal and height maps and uvs; -1 if none. */
int scene_variant_parallax_object(const scene *s);
/* Unit vectors t, b in the plane of unit n, and n x t = b (grazing views). */
void scene_variant_plane(const float n[3], float t[3], float b[3]);
/* 0 (out untouched) when s has no such object (or, for limit, no memory);
 * limit's *material is the object's material, whose albedo is the gradient. */
int scene_variant_down(const scene *s, scene *out);
int scene_variant_limit(const scene *s, scene *out, int *material);
/* A variant by name ("parallax-down", "parallax-limit"); 0 if none or unknown. */
int scene_variant_make(const scene *s, const char *name, scene *out);
/* Frees what v holds of its own (not what it shares with its source s). */
void scene_variant_free(scene *v, const scene *s);

#endif
