/* What the reference files share: the snapshot of the scene's geometry in
 * world space and the Embree handles. Not for users of reference.h. */
#ifndef STIN_TESTS_REFERENCE_INTERNAL_H
#define STIN_TESTS_REFERENCE_INTERNAL_H

#include <stdint.h>
#include <embree3/rtcore.h>
#include "reference.h"

typedef struct ref_object {
    uint32_t vertex_count, triangle_count;
    float *positions;   /* world, 3 per vertex, one spare float for Embree's 16-byte loads */
    float *normals;     /* world, 3 per vertex, unit or zero (singular transform, no normals) */
    float *uvs;         /* 2 per vertex, or NULL */
    uint32_t *indices;  /* 3 per triangle, validated against vertex_count */
} ref_object;

struct reference {
    const scene *s;     /* camera and lights are read from here at call time */
    RTCDevice device;
    RTCScene rtc;
    int object_count;
    ref_object *objects;
    double eps;         /* visibility ray offset, REFERENCE_EPS_SCALE * scene extent */
};

/* Fills a hit from Embree's answer (geometry id = object index). */
void ref_fill_hit(const reference *r, unsigned object, unsigned prim, float u, float v,
                  const float eye[3], ref_hit *hit);

#endif
