/*
 * The CPU reference of stin's surface techniques (stin.h, surface), per hit:
 *   normal   per-pixel lighting (reference_shade's model) with the shading
 *            normal decoded from the material's normal map, n = (rgb * 255 -
 *            128) / 127, bilinear at the hit uv (level 0, no mipmaps), in the
 *            tangent frame interpolated at the hit: per-vertex tangents by
 *            mesh_tangents.c's rule (uv gradients summed per vertex,
 *            Gram-Schmidt against the normal, handedness in w), moved to
 *            world space by the object's 3x3, Gram-Schmidt against the hit
 *            normal, B = w cross(N, T);
 *   parallax uv' = uv + A (V.xy (h scale - bias)), A the triangle's exact map
 *            from tangent-plane offsets (scene units) to uv;
 *   pom      the true view ray marched through the recessed height field
 *            (h = 1 in the polygon, h = 0 at scale below) in 4096 steps,
 *            then 40 bisections: the uv where the ray meets the field.
 * Albedo and normal map are sampled at the final uv. No self-shadowing.
 */
#ifndef STIN_TESTS_REFERENCE_SURFACE_H
#define STIN_TESTS_REFERENCE_SURFACE_H

#include "reference.h"

enum { REF_SURFACE_PLAIN = 0, REF_SURFACE_NORMAL, REF_SURFACE_PARALLAX, REF_SURFACE_POM };

typedef struct ref_surface ref_surface;

/* World tangents of every object (4 floats a vertex). NULL on out of memory. */
ref_surface *ref_surface_create(const scene *s);
void ref_surface_destroy(ref_surface *rs);

/* Tangents of one mesh by mesh_tangents.c's rule: out has 4 floats a vertex. */
void ref_mesh_tangents(const scene_mesh *m, float *out);

/* Shading of a hit (unshadowed, one clamped sum as reference_shade) with the
 * surface technique (REF_SURFACE_*); a material without a normal map is
 * plain, without a height map normal at most (as stin). out_uv: the final uv
 * (may be NULL). height_bias < 0: the default scale / 2. */
void ref_surface_shade(const scene *s, const ref_surface *rs, const ref_hit *hit, int technique,
                       float height_bias, float out_rgba[4], float out_uv[2]);

#endif
