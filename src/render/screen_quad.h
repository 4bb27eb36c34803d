/* SPDX-License-Identifier: MIT */
/* The full-viewport quad every screen pass draws (render/screen_quad.c). */
#ifndef STIN_SCREEN_QUAD_H
#define STIN_SCREEN_QUAD_H

#include "stin/stin.h"

/* The quad through the bound program: two triangles covering the viewport
 * at clip depth 0, as vertex attribute 0 (xyzw). GL4 streams them through
 * the volume arrays (core profiles have no client arrays); GL2 reads them
 * from client memory with the mesh attributes 1-3 off meanwhile. No mesh's
 * arrays are bound afterwards. */
void stin__screen_quad(stin_context *ctx);
/* The same six vertices (xyzw) at clip depth 0, or on the far plane (far
 * 1), for a pass that draws them its own way (the screen mask's, through
 * the path's volume draw). */
const float *stin__screen_quad_vertices(int far);

#endif
