/* SPDX-License-Identifier: MIT */
/* Transparency: how the camera sees blended draws (material opacity < 1).
 * "depth-peel" (transparency/peel.c) peels them front to back, one layer of
 * surfaces per pass, and lights each layer as the frame lights its opaque
 * surfaces (the frame plan runs its lighting stages once per layer, the
 * layer standing in for the opaque draws; under vdsm its position buffer
 * is made from each layer first); "dual-peel" (transparency/dual_peel.c,
 * GL4) finds two layers per geometry pass, the nearest and the farthest
 * left, and lights each through the same stages; "sorted"
 * (transparency/sorted.c) draws them whole, per object far to near,
 * shadowed under the map techniques. */
#ifndef STIN_TRANSPARENCY_H
#define STIN_TRANSPARENCY_H

#include "stin/stin.h"
#include "gl/gl_types.h"
#include "render/path.h"
#include "render/path_features.h"

#define STIN__PEEL_MAX_LAYERS 64 /* desc.transparency.layers at most */

/* Bytes of the peels' and sorted's private state (transparency/transparency_private.h). */
size_t stin__peel_state_bytes(const stin_desc *d);

/* The lit programs' chunk after the others ("peel.glsl", "dual_peel.glsl")
 * in names when a peel is the choice: 1, else 0. The GLSL path calls this,
 * locate, uniforms and camera_set as the transparency's hooks
 * (render/path_features.h, lent by frame/hooks.c). */
int stin__peel_chunks(const struct stin_context *ctx, int variant,
                      const char *names[STIN__FEATURE_CHUNKS]);
/* Set-up after the lighting path (textures come with the first frame, the
 * size of its viewport): a failure falls back to "sorted" (logged). */
void stin__peel_init(struct stin_context *ctx);
void stin__peel_release(struct stin_context *ctx);
/* A lit program's peel uniforms: located once, set per pass. */
void stin__peel_locate(struct stin_context *ctx, stin__program *p);
void stin__peel_uniforms(struct stin_context *ctx, const stin__program *p);

/* Which of STIN__OPAQUE / STIN__BLENDED a camera pass counts draw d in:
 * while a layer is peeled its blended draws are the pass's "opaque" ones
 * (lit like them) and the opaque draws are in no set. */
int stin__peel_camera_set(const struct stin_context *ctx, const stin__draw *d);
/* 1 while a layer is drawn (the path's in_layer hook). */
int stin__peel_in_layer(const struct stin_context *ctx);

/* The frame's peeling, in the frame plan's blended stage:
 *   if (stin__peel_begin(ctx, path))
 *       while (stin__peel_layer_begin(ctx)) {
 *           path->ambient(ctx, STIN__OPAQUE, 0);   depth, ambient, opacity
 *           if (stin__peel_layer_lights(ctx))      something was peeled
 *               ... the frame's lighting stages ...
 *           stin__peel_layer_end(ctx);
 *       }
 *   stin__peel_end(ctx);
 * begin returns 0 (draw them sorted) when depth-peel is not set up or the
 * frame has no blended draw; layer_begin 0 when the layers are done (the
 * cap, or the last pass drew nothing). */
int stin__peel_begin(struct stin_context *ctx, const stin__path *path);
int stin__peel_layer_begin(struct stin_context *ctx);
int stin__peel_layer_lights(struct stin_context *ctx);
void stin__peel_layer_end(struct stin_context *ctx);
void stin__peel_end(struct stin_context *ctx);

/* depth-peel's pieces that dual-peel shares (transparency/peel.c). */
void stin__peel_screen_texture(struct stin_context *ctx, GLuint tex, GLenum format, int w, int h);
void stin__peel_attach(struct stin_context *ctx, GLuint color, GLuint depth);
void stin__peel_clear(struct stin_context *ctx, float r, float g, float b, float a, int depth);
/* The last quad's target and state, shared by both peels (transparency/peel.c). */
void stin__peel_over_frame(struct stin_context *ctx);
void stin__peel_composite_done(struct stin_context *ctx);
/* Into a multisampled target with a stencil (transparency/peel_coverage.c):
 * marks the samples the blended draws cover in front of the opaque ones
 * (their depth written, per sample) and sets the state for the last quad
 * to colour those samples alone; 1 when it did (s->coverage), 0 where the
 * target is single-sampled or has no stencil. _done after the quad. */
int stin__peel_coverage(struct stin_context *ctx);
void stin__peel_coverage_done(struct stin_context *ctx);
/* The layer's lights texture as the peel framebuffer's colour, cleared. */
void stin__peel_lights_target(struct stin_context *ctx);
/* The samples the query counted since stin__peel_count_begin (1 without a query). */
void stin__peel_count_begin(struct stin_context *ctx);
GLuint stin__peel_count_end(struct stin_context *ctx);

/* "dual-peel" (transparency/dual_peel.c): what the stin__peel_* calls above
 * turn to when it is the choice (set-up: after depth-peel's, with its
 * composite program; size: its textures at w x h). */
int stin__dual_init(struct stin_context *ctx, char *msg, size_t size);
void stin__dual_release(struct stin_context *ctx);
GLenum stin__dual_size(struct stin_context *ctx, int w, int h); /* its framebuffer's status */
void stin__dual_uniforms(struct stin_context *ctx, const stin__program *p);
void stin__dual_begin(struct stin_context *ctx);
int stin__dual_layer_begin(struct stin_context *ctx);
int stin__dual_layer_lights(struct stin_context *ctx);
void stin__dual_layer_end(struct stin_context *ctx);
void stin__dual_end(struct stin_context *ctx);

/* "sorted": once per context, at the first frame with blended draws, the
 * warning that it is exact only for separate convex objects. */
void stin__sorted_frame(struct stin_context *ctx);
/* "sorted" in a shadowed frame: 1 where the shadows technique tests a map
 * per fragment in the lit pass (map-pcf; GL1's map-depth and map-combine),
 * so each blended draw can be lit light by light with its shadows; 0 (said
 * once, with the reason) where it cannot: volumes and screen masks (vdsm)
 * hold the nearest opaque surface's visibility, not each object's. */
int stin__sorted_shadowed(struct stin_context *ctx);
/* Whether light li's pass on a sorted draw gets the technique's test (GL1
 * map techniques: a point light without faces has volumes; said once). */
int stin__sorted_light_shadowed(struct stin_context *ctx, uint32_t li);

#endif
