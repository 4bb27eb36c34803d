/* SPDX-License-Identifier: MIT */
/* Shadow volumes' own state (shadow/volume.c, shadow/volume_extrude.c):
 * nothing outside those two files includes this header
 * (tools/check-layers.sh). */
#ifndef STIN_SHADOW_VOLUME_PRIVATE_H
#define STIN_SHADOW_VOLUME_PRIVATE_H

#include "internal.h"
#include "shadow/volume_reach.h"

struct stin__volume_state {
    int depth_clamp;      /* volumes drawn with GL_DEPTH_CLAMP (orthographic) */
    /* GL4: extrusion by geometry shader (shadow/volume_extrude.c); 0: none */
    GLuint extrude_prog, count_query;
    GLint u_model, u_view_proj, u_light, u_far_plane, u_closed, u_caps, u_mode;
    int path_unbound; /* an extruded caster left its program bound, not the path's */
    int set_closed, set_caps, set_mode; /* the program's uniforms as last set (-1: unknown) */
    int cpu_only; /* stin__volume_extrude_enable(ctx, 0): this frame builds on the CPU */
};

#endif
