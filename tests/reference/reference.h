/* SPDX-License-Identifier: MIT */
/*
 * The exact CPU reference the image tests compare against: Embree ray casting
 * of a tools/common scene plus the library's lighting model (stin.h, LIGHTING
 * MODEL) evaluated on the CPU in double precision.
 *
 * Conventions match OpenGL rendering with scene_camera_matrices() (gluLookAt +
 * gluPerspective, aspect = width / height): pixel (x, y) counts y from the
 * BOTTOM row, samples sit at pixel centres, hits nearer than the near plane or
 * farther than the far plane (distances along the view axis) are clipped.
 * Images are row-major, bottom row first. Everything is linear colour.
 *
 * Lifetime: reference_create() snapshots the geometry (world-space positions,
 * normals, uvs, indices); it keeps a pointer to the scene and reads its camera
 * and lights at call time, so the scene must outlive the reference, and the
 * camera and lights may change between calls without rebuilding.
 */
#ifndef STIN_TESTS_REFERENCE_H
#define STIN_TESTS_REFERENCE_H

#include <stddef.h>
#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ref_hit {
    int hit;            /* 0: background (every other field is zero) */
    int object, prim;   /* scene object index, triangle index within its mesh */
    float u, v;         /* Embree barycentrics: P = (1-u-v) A + u B + v C */
    float t;            /* distance from the eye to P in world units */
    float P[3];         /* world position (barycentric interpolation of A, B, C) */
    float N[3];         /* world shading normal: interpolated vertex normals, normalised
                           (the geometric normal where those cancel or are missing) */
    float Ng[3];        /* world geometric normal, unit, facing the triangle's CCW front */
    float uv[2];        /* interpolated texture coordinates (0 without uvs) */
} ref_hit;

typedef struct reference reference;

/* Builds the Embree scene: one triangle geometry per object (geometry id =
 * object index), positions transformed to world space by the object's
 * transform, normals by the inverse transpose of its 3x3. Degenerate
 * triangles are fine (Embree never hits them). Returns NULL and a message in
 * err on bad input (mesh/material index out of range, vertex index out of
 * range, missing positions) or an Embree error. */
reference *reference_create(const scene *s, char *err, size_t err_size);
void reference_destroy(reference *r);

/* Offset a visibility ray starts from, along the geometric normal: this
 * fraction of the scene's extent (bounding-box diagonal or largest coordinate,
 * whichever is larger). */
#define REFERENCE_EPS_SCALE 1e-4

/* Primary rays through every pixel centre of a width x height image for the
 * scene camera. hits has width*height entries, row-major, bottom row first.
 * Returns 1, or 0 on bad arguments or an Embree error. */
int reference_primary(const reference *r, int width, int height, ref_hit *hits);
/* The same through the point (x + dx, y + dy) of every pixel (x, y) instead
 * of its centre: one sample position of a multisampled frame. */
int reference_primary_at(const reference *r, int width, int height, double dx, double dy,
                         ref_hit *hits);

/* The point of hit's triangle seen through window point (px, py) of a
 * width x height image (pixels from the bottom-left corner: pixel (x, y) has
 * its centre at (x + 0.5, y + 0.5)), on the triangle's plane and beyond its
 * edges where the point lies outside (barycentrics extrapolated, as GL
 * interpolates for the helper pixels of a 2x2 quad): a hit there, its uv
 * among the rest. Screen derivatives of the uv are differences of these.
 * Returns 1, or 0 for a background hit or a ray along the plane. */
int reference_hit_on_plane(const reference *r, int width, int height, const ref_hit *hit,
                           double px, double py, ref_hit *out);

/* The terminator rule stin's per-pixel techniques share (vdsm): a smooth
 * triangle's ray starts on the surface its vertex normals describe and its
 * side faces a light by its facet or its shading normal (reference_rays.c
 * smooth_start). The default (REFERENCE_FACETS_NONE). REFERENCE_FACETS_ALL
 * goes back to the facet rule for a technique that still decides
 * self-shadowing by the facet (GL1's volumes, the fixed-function maps): the
 * ray from P, facing by the facet. REFERENCE_FACETS_OPEN keeps it for the
 * objects that are not closed 2-manifolds only (stin's volumes before they
 * took the rule on open meshes: shadow/volume_band.c). */
enum { REFERENCE_FACETS_NONE = 0, REFERENCE_FACETS_ALL = 1, REFERENCE_FACETS_OPEN = 2 };
void reference_facet_terminator(reference *r, int on);

/* Geometric visibility of light `light` from a hit: 1 when the segment from P
 * (offset along Ng toward the light's side by the scene epsilon) to the light
 * position is unoccluded (directional: the ray toward -direction, to
 * infinity), else 0. Spot cones are shading, not visibility. Area lights are
 * treated as points (radius ignored; see reference_light_visibility).
 * Background hits and bad light indices give 1. */
float reference_visibility(const reference *r, const ref_hit *hit, int light);

/* 1 when the hit lies in light `light`'s terminator band under the rule:
 * its ray starts on the curved surface above the facet, the facet (the
 * side the eye sees) turns away from the light and the shading normal
 * toward it. Stin's volumes decide these pixels by the stencil count at P
 * less the mesh's own volume, not by that ray (shadow_test.c). */
int reference_terminator_band(const reference *r, const ref_hit *hit, int light);

/* As reference_visibility with the ray leaving P by `offset` world units
 * (> 0) along Ng instead of the scene epsilon: for techniques that offset
 * by less, whose exactness the scene epsilon would blur. */
float reference_visibility_offset(const reference *r, const ref_hit *hit, int light, double offset);

/* As reference_visibility for a point light at `position` (the segment from
 * the offset P to it). NULL position or a background hit gives 1. */
float reference_visibility_to(const reference *r, const ref_hit *hit, const float position[3]);

/* Transmittance of light `light` toward hit, per RGB channel: the product,
 * over every surface the segment from P (offset as reference_visibility) to
 * the light crosses, of the deep shadow maps' factor
 * reference_transmittance_factor(), and 0 at an opaque surface (material
 * opacity 1, whatever its texture) or where the side the eye sees turns away
 * from the light. A transparent surface's colour is its material colour times
 * its albedo texel (bilinear, level 0), its opacity a the material's opacity
 * times the texel's alpha (a = 0 texels cast nothing). An area light
 * averages it over the directions of reference_light_visibility. Background
 * hits and bad light indices give 1. */
void reference_transmittance(const reference *r, const ref_hit *hit, int light, float out[3]);

/* The seed's eq 5.3 (seed 001): inout *= (1 - a) clamp(1 - a + color, 0, 1)
 * per channel. Equals 1 - a for a white surface, (1 - a)^2 for a black one,
 * and no tint as a goes to 0. */
void reference_transmittance_factor(const float color[3], float a, float inout[3]);

/* An area light (radius r > 0, point or spot) is a sphere of uniform
 * radiance. Its visibility from a hit is the fraction of the light's solid
 * angle (the cone of directions from the offset P that meet the sphere,
 * half-angle asin(r / d)) that nothing blocks, integrated over
 * REFERENCE_AREA_SAMPLES directions: a spherical Fibonacci set over the
 * cone, turned about its axis by an angle hashed from P. Mean error over
 * shadow-soft's penumbra, against 4096 directions: see reference_area.c.
 * Shading uses the light at its centre with its full intensity, weighted by
 * that fraction (what stin's lit pass draws from the visibility). */
#define REFERENCE_AREA_SAMPLES 512
/* Sets the direction count of r (at least 1; 1: the light's centre, a
 * point light); for convergence checks. */
void reference_set_area_samples(reference *r, unsigned n);

/* Visibility of light `light`: for an area light the unoccluded fraction of
 * its solid angle (above; fractional in the penumbra, 0 for directions
 * under the surface's horizon); else reference_visibility(). */
float reference_light_visibility(const reference *r, const ref_hit *hit, int light);

/* Unshadowed shading with the lighting model of stin.h:
 *   per_vertex = 1 (GL1 Gouraud, GL 1.2 separate specular): the model at the
 *     triangle's three world vertices with their world normals; each vertex's
 *     primary (ambient + diffuse) and secondary (specular) colour clamped to
 *     [0,1]; both interpolated with the barycentrics; colour =
 *     primary * texture(uv) + secondary, clamped.
 *   per_vertex = 0 (GL2/GL4): the model at hit P with hit N (never flipped);
 *     colour = (ambient + diffuse) * albedo * texture(uv) + specular, clamped.
 * albedo = material.color.rgb; alpha = material.color[3]; texture = the
 * material's albedo texture (bilinear, repeat, no mipmaps) or 1. Background:
 * the scene background colour. r is only read per vertex (may be NULL per
 * pixel); a per-vertex call without the triangle in r gives NaN. */
/* per_vertex = REFERENCE_GOURAUD_SINGLE_COLOR: GL 1.1 without separate
 * specular — each vertex's primary + secondary summed, clamped, interpolated,
 * and the texture modulates the whole. */
#define REFERENCE_GOURAUD_SINGLE_COLOR 2
void reference_shade(const scene *s, const reference *r, const ref_hit *hit, int per_vertex,
                     float out_rgba[4]);

/* As reference_shade, with light i's diffuse and specular terms multiplied by
 * light_weight[i] (visibility); NULL means all 1. Per vertex, the weights of
 * this pixel are applied at the three vertices before the clamp, i.e. a
 * shadowed pixel gets the Gouraud colour the triangle would have with that
 * light off (what a GL1 stencil/shadow-map pass that drops the light where
 * shadowed produces while the sum stays below 1). */
void reference_shade_weighted(const scene *s, const reference *r, const ref_hit *hit,
                              int per_vertex, const float *light_weight, float out_rgba[4]);

/* The beauty of a stencil-shadow-volume frame, pass by pass: an ambient pass
 * (ambient * albedo * texture), then per light a pass with only that light,
 * weighted by reference_light_visibility() (an area light's stin passes,
 * one per point sample at intensity / n, add up to that where no pass
 * saturates). Every pass is clamped to [0,1] on its own
 * (per vertex: at its vertices, as each GL1 pass is Gouraud-shaded), the
 * passes are added and the sum clamped at 1. A blended material (opacity < 1)
 * is drawn after the passes, unshadowed: reference_shade(). r is required
 * (NaN without it). Equals the shadowed single-pass shading wherever no pass
 * and no sum exceeds 1. */
void reference_shade_passes(const scene *s, const reference *r, const ref_hit *hit, int per_vertex,
                            float out_rgba[4]);

/* Bilinear sample of an RGBA8 texture with repeat addressing, no mipmaps,
 * texel centres at ((i + 0.5) / w, (j + 0.5) / h), rows bottom to top;
 * out in [0,1]. */
void reference_sample_texture(const scene_texture *t, float u, float v, float out_rgba[4]);

/* A texture's mip chain as stin builds it at texture creation (src/assets/texture.c;
 * the GLSL tiers keep the size): level 0 the texels, each next level the 2x2
 * box average of the one before, (a + b + c + d + 2) / 4 per channel, a side
 * of 1 staying 1, down to 1x1. normal_map: level 0's alpha is 255 and each
 * next level holds the mean of the four unit normals (n = (rgb - 128) / 127,
 * each weighted by its alpha / 255), RGB its direction as 128 + 127 n, A its
 * length (Toksvig). NULL on bad input or out of memory. */
typedef struct reference_mips reference_mips;
reference_mips *reference_mips_create(const scene_texture *t, int normal_map);
void reference_mips_destroy(reference_mips *m);
int reference_mips_levels(const reference_mips *m);
/* Level i (0 = the texels, with a normal map's alpha 255), or NULL. */
const scene_texture *reference_mips_level(const reference_mips *m, int i);

/* GL's level of detail of a 2D texture of width x height texels (GL 4.6
 * core, 8.14.1, no bias or clamp): lambda = log2(rho), rho the larger of the
 * lengths of (du/dx width, dv/dx height) and (du/dy width, dv/dy height),
 * from the uv derivatives along the window's x and y. -HUGE_VAL when both
 * derivatives are 0. */
double reference_mip_lambda(const double duv_dx[2], const double duv_dy[2], int width, int height);

/* A sample as GL_LINEAR_MIPMAP_LINEAR minification with GL_LINEAR
 * magnification and GL_REPEAT: lambda <= 0 magnifies (bilinear at level 0);
 * else levels floor(lambda) and floor(lambda) + 1, each bilinear, mixed by
 * the fraction of lambda; from the last level on, that level alone. */
void reference_sample_mips(const reference_mips *m, float u, float v, double lambda,
                           float out_rgba[4]);

/* AOV channels of reference_render, in order (the EXR names of DESIGN.md). */
enum {
    REFERENCE_CH_R = 0, REFERENCE_CH_G, REFERENCE_CH_B, REFERENCE_CH_A,
    REFERENCE_CH_PX, REFERENCE_CH_PY, REFERENCE_CH_PZ,
    REFERENCE_CH_NX, REFERENCE_CH_NY, REFERENCE_CH_NZ,
    REFERENCE_CH_Z,
    REFERENCE_CH_VIS_R, REFERENCE_CH_VIS_G, REFERENCE_CH_VIS_B,
    REFERENCE_CH_T_R, REFERENCE_CH_T_G, REFERENCE_CH_T_B,
    REFERENCE_CHANNELS
};
extern const char *const reference_channel_names[REFERENCE_CHANNELS];

/* Fills out (width*height*REFERENCE_CHANNELS floats, pixel-interleaved, rows
 * bottom to top) with R,G,B,A (reference_shade, unshadowed), P, N, Z = |P - eye|
 * vis.R/G/B = reference_light_visibility() of light 0 (1 with no lights;
 * fractional for an area light; any surface blocks it) and T.R/G/B =
 * reference_transmittance() of light 0 (transparent surfaces let their share
 * through). Background pixels:
 * RGBA = scene background, P = N = Z = 0, vis = T = 1. s must be the scene r was
 * created from. Returns 1, or 0 on bad arguments, out of memory or an Embree
 * error. All reference queries are read-only: threads may share r. */
int reference_render(const scene *s, const reference *r, int width, int height, int per_vertex,
                     float *out);

/* reference_render with flags:
 * REFERENCE_RENDER_SHADOWED makes the beauty shadowed in one clamped sum:
 *   every light weighted by reference_light_visibility() (as
 *   reference_shade_weighted; an area light at its centre, weighted by its
 *   unoccluded fraction).
 * REFERENCE_RENDER_PER_LIGHT_PASSES (implies shadowed) makes the beauty the
 *   sum of separately clamped passes, reference_shade_passes(): what a
 *   stencil-volume frame draws, including the unshadowed blended draws. */
#define REFERENCE_RENDER_SHADOWED 1u
#define REFERENCE_RENDER_PER_LIGHT_PASSES 2u
/* REFERENCE_RENDER_COMPOSITE makes R,G,B,A the camera composite,
 *   reference_composite_pixel() (with SHADOWED or TRANSMITTANCE lighting for
 *   every layer, per-pixel or per-vertex as per_vertex, never per-light
 *   passes); the other channels stay the first hit's. */
#define REFERENCE_RENDER_COMPOSITE 4u
/* REFERENCE_RENDER_TRANSMITTANCE (with COMPOSITE) lights every layer through
 *   reference_transmittance() of each light, per RGB channel (an area
 *   light at its centre, weighted by its mean transmittance): what a frame with deep
 *   shadow maps shows. */
#define REFERENCE_RENDER_TRANSMITTANCE 8u
/* Where reference_csg_cast has set products, the primary hits show them
 *   (reference_csg_primary) and they cast (reference_csg.h). */
int reference_render_ex(const scene *s, const reference *r, int width, int height, int per_vertex,
                        unsigned flags, float *out);

/* The camera composite of window pixel (x, y) (from the bottom-left) of a
 * width x height image: the ray through its centre, clipped to [near, far]
 * as reference_primary, visits every surface up to the first opaque one
 * (material opacity 1) or the background, at most 256. Each transparent
 * surface, of opacity a = material opacity times its albedo texel's alpha,
 * is shaded as reference_shade (unshadowed), as reference_render_ex
 * SHADOWED (reference_light_visibility of every light) or per channel through
 * the lights' transmittance (flags REFERENCE_RENDER_TRANSMITTANCE), both
 * sides alike (back faces are shaded with their own normal), and blended
 * under the ones in front: C += T a c, T *= 1 - a from C = 0, T = 1; then
 * out = C + T * (the opaque hit shaded the same way, or the background).
 * out[3] = 1 - T (1 - alpha behind); part (NULL: not wanted) receives
 * the transparent surfaces' part alone, (C, T), to put over another image
 * of what lies behind. CSG primitives are not handled (scenes with CSG are
 * out of its scope). Returns the number of transparent surfaces crossed
 * (the depth complexity peeling needs), -1 on bad arguments or out of
 * memory. */
int reference_composite_pixel(const scene *s, const reference *r, int width, int height, int x,
                              int y, int per_vertex, unsigned flags, float out_rgba[4],
                              float part[4]);
/* The same through window point (px, py) instead of a pixel centre: one
 * sample position of a multisampled frame (tests/image/msaa_blend_test.c). */
int reference_composite_at(const scene *s, const reference *r, int width, int height, double px,
                           double py, int per_vertex, unsigned flags, float out_rgba[4],
                           float part[4]);

#ifdef __cplusplus
}
#endif
#endif
