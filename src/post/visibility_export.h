/* SPDX-License-Identifier: MIT */
/* The visibility map for the application's own shaders
 * (post/visibility_export.c; stin.h, VISIBILITY FOR THE APPLICATION'S SHADERS):
 * a frame stage after the lights that draws each light's visibility into a
 * channel of the screen mask, four lights at a time, and copies each group
 * into its tile of the map. */
#ifndef STIN_VISIBILITY_EXPORT_H
#define STIN_VISIBILITY_EXPORT_H

#include "stin/stin.h"
#include "gl/gl_types.h"
#include "render/path.h"

/* Bytes of the export's private state (post/visibility_export.c). */
size_t stin__export_state_bytes(const stin_desc *d);
/* The context can export (framebuffer objects, packed depth-stencil). */
int stin__export_supported(const stin_context *ctx);
/* The stage: with the frame's target bound, and bound again after. */
void stin__export_stage(stin_context *ctx, const stin__path *path, int shadowed);
void stin__export_release(stin_context *ctx);

#endif
