/* SPDX-License-Identifier: MIT */
/* OpenCSG 1.5 for the CSG section (opencsg_shim.cpp, built with g++ where
 * OpenCSG and GLEW are installed: STIN_BENCH_OPENCSG). */
#ifndef STIN_BENCH_OPENCSG_SHIM_H
#define STIN_BENCH_OPENCSG_SHIM_H

#include <stddef.h>
#include <stdint.h>

/* A primitive: a mesh (pointers kept, not copied), its column-major
 * transform, intersected (0) or subtracted (1), and its bounding box in
 * normalised device coordinates (min x, y, z, max x, y, z; -1..1 where a
 * corner lies behind the eye). */
typedef struct ocsg_primitive {
    const float *positions, *normals;
    const uint32_t *indices;
    uint32_t index_count;
    float transform[16];
    int subtract;
    float ndc_box[6];
} ocsg_primitive;

/* OpenCSG's strategies for many primitives (its DepthComplexityAlgorithm):
 * none (the primitives' convexity bounds Goldfeather's layers, SCS runs its
 * sequence once per batch), occlusion queries (stop when a pass changes
 * nothing), depth complexity sampling (the stencil counts the most layers
 * first). */
enum {
    OCSG_CONVEXITY_ONLY,
    OCSG_OCCLUSION_QUERY,
    OCSG_DEPTH_COMPLEXITY_SAMPLING,
    OCSG_STRATEGIES
};

/* GLEW on the current context; 0 with the reason in err. */
int ocsg_init(char *err, size_t err_size);
/* The product every later frame draws (replaces the one before). */
void ocsg_set_product(const ocsg_primitive *p, int n);
/* One frame into `framebuffer`: cleared, OpenCSG's Goldfeather (scs 0) or
 * SCS (1) with a strategy (OCSG_*), the primitives shaded depth EQUAL per
 * pixel as stin shades them, one point light. */
void ocsg_frame(unsigned framebuffer, int scs, int strategy, const float view[16],
                const float projection[16], const float light[4]);
void ocsg_release(void);

#endif
