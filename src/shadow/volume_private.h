/* SPDX-License-Identifier: MIT */
/* Shadow volumes' own state (shadow/volume.c, shadow/volume_extrude.c,
 * shadow/volume_band.c): nothing outside the shadow folder includes this
 * header (tools/check-layers.sh). */
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

/* A volume built on the CPU (stin__volume_build) goes to the path's
 * volume_draw, its winding set per chunk (shadow/volume.c). */
typedef struct stin__volume_sink_state {
    stin_context *ctx;
    const stin__path *path;
    const float *model;
} stin__volume_sink_state;
void stin__volume_sink_draw(void *user, const float *xyzw, uint32_t n, int clockwise);

/* After a light sample's volumes are counted: each smooth opaque caster's
 * terminator band takes back the count its own volume gives it there
 * (shadow/volume_band.c; stin.h, the terminator rule under volumes). */
void stin__volume_take_back_band(stin_context *ctx, const stin__path *path,
                                 const float light_world[4], const stin__volume_reach *reach);

#endif
