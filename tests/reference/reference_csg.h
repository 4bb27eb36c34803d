/* SPDX-License-Identifier: MIT */
/* The exact reference of CSG products (stin_draw_csg): per pixel every hit
 * of the camera ray with each primitive (Embree, all hits along the ray),
 * classified into entries (front faces) and exits (back faces) per
 * primitive, and the product's expression evaluated from one crossing to
 * the next: the first point where it turns true is the product's surface. */
#ifndef STIN_TESTS_REFERENCE_CSG_H
#define STIN_TESTS_REFERENCE_CSG_H

#include "reference.h"
#include "stin/stin.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A product as stin_draw_csg takes it, its primitives named by scene
 * object (each a closed mesh whose front faces face out; one product's
 * primitives are distinct objects). */
typedef struct ref_csg_product {
    const int *objects;          /* scene object of primitive i */
    int primitive_count;
    const stin_csg_node *nodes;  /* the last is the root; operands before their node */
    int node_count;
} ref_csg_product;

/* Marks the products' objects as CSG primitives in r: they no longer show
 * on their own in reference_csg_primary and no longer cast on their own in
 * any visibility query (the products cast where reference_csg_cast says).
 * 0 on a bad object index or out of memory. */
#define REF_CSG_CAP_DEPTH (1.0 / 1024.0)

int reference_csg_mark(reference *r, const ref_csg_product *products, int count);

/* The products cast shadows from now on: a visibility ray is blocked where
 * it passes through a product's solid (every crossing of the ray with its
 * primitives, in/out per primitive from the whole ray, the expression true
 * between the ray's origin and the light), as stin's map techniques cast
 * them; stin's volumes cast none (keep this off for them: count 0). The
 * products must be marked (reference_csg_mark) and outlive r's use. 0 on
 * bad arguments or out of memory. */
int reference_csg_cast(reference *r, const ref_csg_product *products, int count);

/* Primary hits as reference_primary, with the products: the nearest of the
 * first unmarked object hit and each product's surface. A product's hit is
 * the hit of the primitive whose crossing makes the expression true (its
 * object and triangle; of crossings at the same distance, within 1e-6 of
 * it, the first primitive whose crossing alone would do it), with N and Ng
 * turned toward the eye where that crossing is an exit (a complemented
 * primitive's inside wall). Whether the ray starts inside a primitive is
 * its exits less its entries along the whole ray; where the product holds
 * the near plane (the camera inside the solid) its surface is the cap: the
 * point at window depth 2^-10 (stin's cap, REF_CSG_CAP_DEPTH) on the ray,
 * facing the eye, of the product's first primitive's object (triangle 0,
 * u = v = 0, no uv). product_of (width * height entries, or NULL) gets the
 * product each pixel shows, -1 for an ordinary object or the background.
 * The products' objects must be marked (reference_csg_mark). Returns 1, or
 * 0 on bad arguments, unmarked primitives, out of memory or an Embree
 * error. */
int reference_csg_primary(const reference *r, const ref_csg_product *products, int count,
                          int width, int height, ref_hit *hits, int *product_of);
/* The same through point (dx, dy) of each pixel (0..1 from its bottom-left
 * corner; 0.5, 0.5 is reference_csg_primary): a multisampled target's
 * sample positions. */
int reference_csg_primary_at(const reference *r, const ref_csg_product *products, int count,
                             int width, int height, double dx, double dy, ref_hit *hits,
                             int *product_of);

#ifdef __cplusplus
}
#endif
#endif
