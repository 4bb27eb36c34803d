/* SPDX-License-Identifier: MIT */
/* OpenCSG 1.5 for the CSG section (opencsg_shim.cpp, built with g++ where
 * OpenCSG and GLEW are installed: STIN_BENCH_OPENCSG). */
#ifndef STIN_BENCH_OPENCSG_SHIM_H
#define STIN_BENCH_OPENCSG_SHIM_H

#include <stddef.h>
#include <stdint.h>

/* A primitive: a mesh (pointers kept, not copied), its column-major
 * transform, intersected (0) or subtracted (1). */
typedef struct ocsg_primitive {
    const float *positions, *normals;
    const uint32_t *indices;
    uint32_t index_count;
    float transform[16];
    int subtract;
} ocsg_primitive;

/* GLEW on the current context; 0 with the reason in err. */
int ocsg_init(char *err, size_t err_size);
/* The product every later frame draws (replaces the one before). */
void ocsg_set_product(const ocsg_primitive *p, int n);
/* One frame into `framebuffer`: cleared, OpenCSG's Goldfeather (scs 0) or
 * SCS (1), the primitives shaded depth EQUAL under one GL light. */
void ocsg_frame(unsigned framebuffer, int scs, const float view[16], const float projection[16],
                const float light[4]);
void ocsg_release(void);

#endif
