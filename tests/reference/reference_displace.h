/* SPDX-License-Identifier: MIT */
/*
 * The displaced geometry of a scene, for the displacement tests: what stin's
 * "displace" draws (stin.h, displacement). Every object whose material sets
 * `displace` and has a height map gets its own mesh in world space (identity
 * transform): each vertex moved along its world normal (the inverse
 * transpose of the object's 3x3, normalised) by d = h * height_scale -
 * height_bias, h the height map's R sampled bilinearly at texel centres
 * with repeat at level 0 (reference_sample_texture: GL_LINEAR, and what the
 * shader's manual bilinear computes). Normals stay the undisplaced ones
 * (stin's vertex stage cannot see its neighbours). The result is a scene
 * for reference_create; the other objects, textures, materials, lights and
 * camera are shared with the source, which must outlive it.
 */
#ifndef STIN_TESTS_REFERENCE_DISPLACE_H
#define STIN_TESTS_REFERENCE_DISPLACE_H

#include <stddef.h>
#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 1 when some object of s is displaced. */
int reference_scene_displaces(const scene *s);
/* Fills out (free with reference_displace_free and the same source, never
 * scene_free). Returns 0 and a message in err on bad input or out of memory. */
int reference_displace(const scene *s, scene *out, char *err, size_t err_size);
/* The same with every displaced triangle split into split^2 first (split
 * >= 1; 1 is reference_displace): the points at barycentric weights
 * (a, b, c) / split of the corners' positions, normals and uvs, each
 * displaced - stin's "displace-tess" surface as its levels grow (the
 * tessellated limit). A shared edge's points are computed alike from both
 * triangles, so the split mesh has no cracks. */
int reference_displace_split(const scene *s, int split, scene *out, char *err, size_t err_size);
/* The same with the heights read from the map's mip chain
 * (reference_mips_create) as stin's vertex stage reads them with its mip
 * levels on: lambda = log2(spread x d), d the undisplaced world point's
 * distance to the eye (1 for an orthographic camera), spread = the mesh's
 * texels per unit (the map's larger side x its mean uv edge length over its
 * mean edge length over the transform's mean axis scale) over
 * pixels_per_unit (the projection's y scale x half the viewport's height),
 * sampled as reference_sample_mips does (level 0 up close, two levels
 * blended, the last one alone). lod NULL: level 0. */
typedef struct reference_displace_lod {
    double pixels_per_unit;
    int perspective;
    double eye[3];
} reference_displace_lod;
int reference_displace_ex(const scene *s, int split, const reference_displace_lod *lod,
                          scene *out, char *err, size_t err_size);
void reference_displace_free(scene *out, const scene *source);

#ifdef __cplusplus
}
#endif
#endif
