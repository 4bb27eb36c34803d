/* SPDX-License-Identifier: MIT */
/* World bounds of the frame's draws and the camera's frustum as planes, for
 * the features that skip work nothing visible can see (render/draw_bounds.c). */
#ifndef STIN_RENDER_DRAW_BOUNDS_H
#define STIN_RENDER_DRAW_BOUNDS_H

#include "render/path.h"

struct stin_context;

/* The eight world corners of a draw's mesh bounds; 0 where the bounds tell
 * nothing (a displaced draw moves its vertices on the GPU). */
int stin__draw_world_corners(const struct stin_context *ctx, const stin__draw *d, float out[24]);

/* The six planes of view_proj's frustum (Gribb-Hartmann rows; inside:
 * a x + b y + c z + d >= 0). An infinite far plane comes out as (0, 0, 0, d):
 * no plane, which stin__points_meet skips. */
void stin__frustum_planes(const float view_proj[16], float planes[6][4]);

/* 1 unless every one of the n points lies outside one of the planes: the
 * convex hull of the points may meet the region the planes bound. A margin
 * keeps points grazing a plane in (conservative is what callers need). */
int stin__points_meet(const float *xyz, int n, const float *planes, int plane_count);

#endif
