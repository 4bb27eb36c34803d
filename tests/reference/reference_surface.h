/* SPDX-License-Identifier: MIT */
/*
 * The CPU reference of stin's surface techniques (stin.h, surface), per hit:
 *   normal   per-pixel lighting (reference_shade's model) with the shading
 *            normal decoded from the material's normal map, n = (rgb * 255 -
 *            128) / 127, sampled at the hit uv (see below), in the
 *            tangent frame interpolated at the hit: per-vertex tangents by
 *            assets/mesh_tangents.c's rule (uv gradients summed per vertex,
 *            Gram-Schmidt against the normal, handedness in w), moved to
 *            world space by the object's 3x3, Gram-Schmidt against the hit
 *            normal, B = w cross(N, T);
 *   parallax uv' = uv + A (V.xy (h scale - bias)), A the triangle's exact map
 *            from tangent-plane offsets (scene units) to uv;
 *   pom      the true view ray marched through the recessed height field
 *            (h = 1 in the polygon, h = 0 at scale below) in 4096 steps,
 *            then 40 bisections: the uv where the ray meets the field.
 * Albedo and normal map are sampled at the final uv: bilinear at level 0
 * (ref_surface_shade), or through stin's mip chains at the level GL picks
 * for the pixel's footprint (ref_surface_shade_filtered), the normal map's
 * filtered length widening the highlight as the lit shader does (Toksvig).
 * Height maps have level 0 only, as in stin. No self-shadowing in
 * ref_surface_shade; ref_surface_pom_shadow marches the light ray on its own.
 */
#ifndef STIN_TESTS_REFERENCE_SURFACE_H
#define STIN_TESTS_REFERENCE_SURFACE_H

#include "reference.h"

enum { REF_SURFACE_PLAIN = 0, REF_SURFACE_NORMAL, REF_SURFACE_PARALLAX, REF_SURFACE_POM };

typedef struct ref_surface ref_surface;

/* World tangents of every object (4 floats a vertex). NULL on out of memory. */
ref_surface *ref_surface_create(const scene *s);
void ref_surface_destroy(ref_surface *rs);

/* Tangents of one mesh by assets/mesh_tangents.c's rule: out has 4 floats a vertex. */
void ref_mesh_tangents(const scene_mesh *m, float *out);

/* Shading of a hit (unshadowed, one clamped sum as reference_shade) with the
 * surface technique (REF_SURFACE_*); a material without a normal map is
 * plain, without a height map normal at most (as stin). out_uv: the final uv
 * (may be NULL). height_bias < 0: the default scale / 2. */
void ref_surface_shade(const scene *s, const ref_surface *rs, const ref_hit *hit, int technique,
                       float height_bias, float out_rgba[4], float out_uv[2]);

/* What chooses the mip level of a pixel's samples: the screen derivatives of
 * the uv the sampler is given (per window pixel along x and along y). */
typedef struct ref_footprint {
    double dx[2], dy[2];
} ref_footprint;

/* ref_surface_shade with albedo and normal map filtered as GL filters stin's
 * textures (GL_LINEAR_MIPMAP_LINEAR over the chains of reference_mips_create,
 * lambda from fp by reference_mip_lambda); fp NULL: ref_surface_shade. */
void ref_surface_shade_filtered(const scene *s, const ref_surface *rs, const ref_hit *hit,
                                int technique, float height_bias, const ref_footprint *fp,
                                float out_rgba[4], float out_uv[2]);

/* Parallax terms of a hit with a normal and a height map: h' = h(uv) scale -
 * bias in scene units (h bilinear at the hit uv, level 0; height_bias < 0:
 * scale / 2) and vt, the unit vector to the eye in the tangent frame (T, B,
 * N). 0 (outputs untouched) for a hit without both maps. */
int ref_surface_parallax_terms(const scene *s, const ref_surface *rs, const ref_hit *hit,
                               float height_bias, double *h_prime, double vt[3]);

/* The tangent-plane offset (scene units along T and B) whose uv change at the
 * hit's triangle is duv (the inverse of the parallax map A). 0 without both
 * maps or for a degenerate uv map. */
int ref_surface_uv_to_plane(const scene *s, const ref_surface *rs, const ref_hit *hit,
                            const double duv[2], double out[2]);

/* POM self-shadowing (hard) of a hit toward the unit direction to_light
 * (world): the view ray is marched to the field as in pom; from that point
 * (depth d, 0..1 of the scale) the ray toward the light climbs to the
 * polygon in ceil(4096 d) steps and the hit is shadowed (0) where the field
 * at some step lies more than epsilon (depth units) above the ray; 1 where
 * it stays below, where d = 0 (the top) or without both maps; 0 toward a
 * light under the polygon. out_uv / out_depth (may be NULL): the pom hit. */
float ref_surface_pom_shadow(const scene *s, const ref_surface *rs, const ref_hit *hit,
                             const float to_light[3], double epsilon, float out_uv[2],
                             float *out_depth);

#endif
