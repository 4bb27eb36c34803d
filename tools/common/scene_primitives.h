/* SPDX-License-Identifier: MIT */
/*
 * Tessellated primitives for scene files (scene_primitives.c). Internal to
 * the tool code; unit tests call these directly.
 *
 * Every generator fills a zeroed scene_mesh with positions, unit normals,
 * uvs and counter-clockwise (outward) triangles, centred on the origin with
 * y up. Vertices are duplicated where uvs or normals are discontinuous (uv
 * seams, box edges, cylinder caps) but seam positions are bit-identical, so
 * welding by position yields a closed mesh for box, sphere, torus and capped
 * cylinder. Each returns 1, or 0 when out of memory (the mesh is left empty).
 * Callers validate sizes and counts; the generators assume sane input.
 */
#ifndef STIN_TOOLS_SCENE_PRIMITIVES_H
#define STIN_TOOLS_SCENE_PRIMITIVES_H

#include "scene.h"

/* Allocates arrays for vertex_count vertices and triangle_count triangles. */
int scene_mesh_alloc(scene_mesh *m, uint32_t vertex_count, uint32_t triangle_count);
/* Frees the arrays and zeroes the counts; the name stays. */
void scene_mesh_release(scene_mesh *m);

/* Plane in y = 0 facing +y, size sx by sz, nx by nz quads. u runs along +x,
 * v along -z, so (t, b, n) = (+x, -z, +y) is a right-handed tangent frame. */
int scene_prim_plane(scene_mesh *m, float sx, float sz, int nx, int nz);
/* Axis-aligned box, 24 vertices (4 per face, flat normals), 12 triangles. */
int scene_prim_box(scene_mesh *m, float sx, float sy, float sz);
/* Sphere with poles on the y axis, tessellated like glutSolidSphere:
 * triangle fans at the poles and quads between, 2*slices*(stacks-1)
 * triangles. slices >= 3, stacks >= 2. */
int scene_prim_sphere(scene_mesh *m, float radius, int slices, int stacks);
/* Torus around the y axis: rings segments around the major circle, sides
 * around the tube; 2*rings*sides triangles. rings, sides >= 3. */
int scene_prim_torus(scene_mesh *m, float major_radius, float minor_radius, int rings, int sides);
/* Cylinder along y from -height/2 to height/2; slices >= 3. Caps (when
 * capped) have their own vertices with flat normals. */
int scene_prim_cylinder(scene_mesh *m, float radius, float height, int slices, int capped);

#endif
