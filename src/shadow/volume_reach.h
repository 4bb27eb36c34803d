/* SPDX-License-Identifier: MIT */
/* How far each shadow volume of a light sample must reach, and which reach
 * the view at all (shadow/volume_reach.c): pure geometry, no GL. */
#ifndef STIN_SHADOW_VOLUME_REACH_H
#define STIN_SHADOW_VOLUME_REACH_H

#include "internal.h"

/* A light sample's reach (shadow/volume_reach.c): the visible receivers'
 * world box (the eye in it) and the camera's frustum. */
typedef struct stin__volume_reach {
    int bounded; /* 0: every volume to infinity (STIN_DEBUG_VOLUME_UNBOUNDED, a
                  * keep_contents frame, or a receiver without usable bounds) */
    float light[4];
    float box_min[3], box_max[3];
    float camera[6][4];
} stin__volume_reach;

void stin__volume_reach_begin(const stin_context *ctx, const float light_world[4],
                              stin__volume_reach *r);
/* A caster (its world box's corners): 0 where its volume cannot reach the
 * view (skip it); else 1 and the world plane its volume is cut at, inside
 * where plane . (x, 1) <= 0: every visible receiver and the eye lie inside.
 * (0, 0, 0, -1) cuts nothing: the volume goes to infinity. */
int stin__volume_reach_caster(const stin__volume_reach *r, const float corners[24],
                              float far_plane[4]);
void stin__volume_plane_to_object(const float plane[4], const float model[16], float out[4]);

#endif
