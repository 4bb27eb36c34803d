/* SPDX-License-Identifier: MIT */
/* What the reference files share: the snapshot of the scene's geometry in
 * world space and the Embree handles. Not for users of reference.h. */
#ifndef STIN_TESTS_REFERENCE_INTERNAL_H
#define STIN_TESTS_REFERENCE_INTERNAL_H

#include <stdint.h>
#include <embree3/rtcore.h>
#include "reference.h"
#include "reference_cache.h"

typedef struct ref_object {
    uint32_t vertex_count, triangle_count;
    float *positions;   /* world, 3 per vertex, one spare float for Embree's 16-byte loads */
    float *normals;     /* world, 3 per vertex, unit or zero (singular transform, no normals) */
    float *uvs;         /* 2 per vertex, or NULL */
    uint32_t *indices;  /* 3 per triangle, validated against vertex_count */
    int closed;         /* a closed 2-manifold (ref_object_closed) */
} ref_object;

/* 1 when o is a closed, consistently oriented 2-manifold after welding
 * vertices at equal positions (reference_closed.c). */
int ref_object_closed(const ref_object *o);

struct reference {
    const scene *s;     /* camera and lights are read from here at call time */
    RTCDevice device;
    RTCScene rtc;
    int object_count;
    ref_object *objects;
    double eps;         /* visibility ray offset, REFERENCE_EPS_SCALE * scene extent */
    unsigned area_samples; /* directions an area light is integrated with, REFERENCE_AREA_SAMPLES */
    int facet_terminator; /* REFERENCE_FACETS_*: which triangles decide by their facet */
    unsigned char *csg_primitive; /* per object, or NULL: 1 for a CSG primitive, which
                                   * neither shows on its own nor casts (reference_csg.h) */
    struct ref_csg_cast *csg_cast; /* products that cast (reference_csg_cast), or NULL */
    int snapshot_hashed;          /* objects' hash taken (reference_cache.h: cache on) */
    uint64_t snapshot_hash[2];
};

/* The inverse transpose of a column-major transform's 3x3, up to scale
 * (normals are renormalised), row-major: n[r * 3 + c]. */
void ref_normal_matrix(const float m[16], double n[9]);

/* Fills a hit from Embree's answer (geometry id = object index). */
void ref_fill_hit(const reference *r, unsigned object, unsigned prim, float u, float v,
                  const float eye[3], ref_hit *hit);

/* eps or -eps: the offset along hit's Ng that leaves the surface on the
 * side the eye sees, so a visibility ray cannot hit its own triangle. */
double ref_eye_side(const reference *r, const ref_hit *hit, double eps);
/* Where hit's shadow rays start and which normal decides its facing, by the
 * terminator rule (reference_rays.c); side: +-1, the side the eye sees. */
void ref_smooth_start(const reference *r, const ref_hit *hit, double side, double org[3],
                      double facing[3]);

/* 1 for an area light: radius > 0, not directional. */
int ref_is_area_light(const scene_light *l);
/* Directions light l is integrated with: r's area_samples for an area
 * light, else 1. */
unsigned ref_area_sample_count(const reference *r, const scene_light *l);
/* The cone of directions from P onto area light l's sphere (half-angle
 * asin(r / d)), with the basis and turn its directions are laid out by
 * (reference_area.c). ref_area_cone_of gives 0 when P lies on or inside the
 * sphere. */
typedef struct ref_area_cone {
    double P[3], axis[3], e1[3], e2[3], d, r, cos_max, turn;
} ref_area_cone;
int ref_area_cone_of(const scene_light *l, const float P[3], ref_area_cone *cone);
/* Where direction k of n of the cone meets the light's sphere. */
void ref_area_cone_point(const ref_area_cone *cone, unsigned k, unsigned n, double out[3]);

/* reference_light_visibility of every light of r's scene from hit, into
 * weight (light_count entries). */
void ref_light_weights(const reference *r, const ref_hit *hit, float *weight);

/* Shading of hit with an explicit light list (weights as in
 * reference_shade_weighted). passes = 0: one clamped sum (ambient + all lights);
 * passes = 1: an ambient pass plus one pass per light, each clamped on its own
 * (per vertex too), summed and clamped. */
void ref_shade_lights(const scene *s, const reference *r, const ref_hit *hit, int per_vertex,
                      const scene_light *lights, int light_count, const float *weight,
                      int passes, float out_rgba[4]);
/* ref_shade_lights of a hit with its material and albedo texel given (the
 * surface reference filters the maps and widens the highlight itself). */
void ref_shade_material(const scene *s, const reference *r, const ref_hit *hit, int per_vertex,
                        const scene_material *m, const float tex[4], const scene_light *lights,
                        int light_count, const float *weight, int passes, float out_rgba[4]);

/* The camera's frame for a width x height image: basis f, s, u and the
 * half extents tx, ty of the image plane at distance 1. 0 on a bad camera. */
typedef struct ref_camera_frame {
    double f[3], s[3], u[3], tx, ty;
} ref_camera_frame;
int ref_frame_of(const scene_camera *cam, int width, int height, ref_camera_frame *cf);
/* The primary ray's direction through window point (px, py) (pixels from
 * the bottom-left corner), unnormalised with a forward component of 1: t
 * along it is the distance along the view axis, [near, far] GL's clipping. */
void ref_window_dir(const ref_camera_frame *cf, int width, int height, double px, double py,
                    double dir[3]);

/* An intersection context whose rays pass through CSG primitives (they do
 * not cast: stin's shadow techniques do not draw CSG products from the
 * lights); a plain context when the reference has none. */
typedef struct ref_csg_context {
    struct RTCIntersectContext rtc; /* first: Embree hands the filter this pointer */
    const reference *r;
} ref_csg_context;
void ref_csg_context_init(const reference *r, ref_csg_context *ctx);
/* Whether the ray from org along unit dir passes through a casting product
 * before distance dist (INFINITY: to infinity): 1, 0, or -1 when the
 * crossings outgrew the list or memory ran out. */
int ref_csg_blocks(const reference *r, const float org[3], const float dir[3], double dist);
void ref_csg_cast_free(struct ref_csg_cast *c);
/* The CSG state of r for a cache key (reference_cache.h): the marks and
 * the casting products' contents. */
void ref_csg_hash_state(const reference *r, ref_hasher *h);
struct ref_csg_product;
/* Products' contents (primitives' objects, nodes) for a cache key. */
void ref_csg_hash_products(ref_hasher *h, const struct ref_csg_product *products, int count);
/* Primary hits with the casting products shown (reference_csg_primary of
 * them); 0 where none are set or on failure. */
int ref_csg_primary_cast(const reference *r, int width, int height, ref_hit *hits);

#endif
