/* SPDX-License-Identifier: MIT */
/* Translucent shadows: how casters with opacity below 1 shadow. "deep"
 * (translucent/deep.c) is deep shadow maps, peeled per light just before
 * its lit pass and read by the lit programs through the
 * shadow_transmittance() seam (shaders/gl4/translucent_deep.glsl).
 * "coloured" (translucent/coloured.c) is one colour map per light, made at
 * the same point and read through the same seam
 * (shaders/gl2/translucent_coloured.glsl). "opaque" needs nothing: casters
 * at or above the threshold cast like opaque ones, the rest not at all;
 * "translucent-solid" (forced only) casts them all. translucent/translucent.c hands the
 * frame plan and the shadows techniques one set of calls for all four. */
#ifndef STIN_TRANSLUCENT_H
#define STIN_TRANSLUCENT_H

#include "stin/stin.h"
#include "gl/gl_types.h"
#include "render/path.h"
#include "render/path_features.h"

#define STIN__DEEP_FACES 6
#define STIN__DEEP_MAX_LAYERS 16 /* desc.translucent.deep_layers at most */

/* The uniforms of one lookup chunk (translucent/translucent.c): the samplers on the
 * selection's translucent units (used or not, so a fallen-back technique's
 * samplers stay off the other units), then, for a light with a map (kind
 * not 0), its face matrices and params. Returns whether the maps are to be
 * bound (kind not 0). */
int stin__translucent_set(struct stin_context *ctx, const stin__translucent_locs *l, int kind,
                          const float *matrices, const float params[4]);

/* Slices per face of each ping-pong texture for `layers` layers. */
uint32_t stin__deep_slices(uint32_t layers);
/* Bytes of deep's and coloured's private state (translucent/translucent_private.h). */
size_t stin__deep_state_bytes(const stin_desc *d);
size_t stin__coloured_state_bytes(const stin_desc *d);
/* The lit programs' chunk after the shadow technique's ("translucent_deep.glsl")
 * when deep is the choice, else NULL. */
const char *stin__deep_chunk(const struct stin_context *ctx);
/* Set-up after the shadow module's (textures, framebuffer, program, query):
 * a failure, or shadows that are off, falls back to translucent-solid
 * (logged). */
void stin__deep_init(struct stin_context *ctx);
void stin__deep_release(struct stin_context *ctx);
/* A lit or flat program's lookup uniforms, set per pass (located by
 * translucent/translucent.c). */
void stin__deep_uniforms(struct stin_context *ctx, const stin__program *p);
/* 1 when lights get deep maps this frame (they are then lit one per pass). */
int stin__deep_active(const struct stin_context *ctx);
/* Light li's deep map, peeled now (the frame's target bound back after),
 * for the lit pass that follows; done: the pass is over. No-ops when
 * deep is not active. */
void stin__deep_light(struct stin_context *ctx, uint32_t li);
void stin__deep_light_done(struct stin_context *ctx);

/* As deep's calls above, for "coloured". */
const char *stin__coloured_chunk(const struct stin_context *ctx);
void stin__coloured_init(struct stin_context *ctx);
void stin__coloured_release(struct stin_context *ctx);
void stin__coloured_uniforms(struct stin_context *ctx, const stin__program *p);
int stin__coloured_active(const struct stin_context *ctx);
void stin__coloured_light(struct stin_context *ctx, uint32_t li);
void stin__coloured_light_done(struct stin_context *ctx);

/* The log level of a map technique's fall-back: INFO where shadows are off
 * (the caller's choice rules every map out) and the technique was only the
 * tier's default, else WARNING. */
stin_log_level stin__translucent_fallback_level(const struct stin_context *ctx, int shadows_off);

/* The translucent-shadows technique in use, whichever it is
 * (translucent/translucent.c); the paths call these as its hooks
 * (render/path_features.h, lent by frame/hooks.c). Its chunk wrapping the
 * shadow chunk's seam, in names: 1, or 0 without one. */
int stin__translucent_chunks(const struct stin_context *ctx, int variant,
                             const char *names[STIN__FEATURE_CHUNKS]);
void stin__translucent_locate(struct stin_context *ctx, stin__program *p);
void stin__translucent_uniforms(struct stin_context *ctx, const stin__program *p);
/* At the frame's light pre-passes: whether any draw is transparent (a
 * frame without one makes no map). */
void stin__translucent_frame(struct stin_context *ctx);
/* 1 when lights get maps of their own this frame (lit one per pass). */
int stin__translucent_active(const struct stin_context *ctx);
/* 1 when the shadows technique leaves draw d out: a transparent caster that
 * a deep or colour map carries, or under "opaque" one below the threshold. */
int stin__translucent_skips(const struct stin_context *ctx, const stin__draw *d);
void stin__translucent_light(struct stin_context *ctx, uint32_t li);
void stin__translucent_light_done(struct stin_context *ctx);

/* What deep and coloured share (translucent/translucent.c). */
/* The transparent draws, in the caller's order, through the bound program:
 * colour and albedo texture (on unit 0) per draw. */
void stin__translucent_draw_casters(struct stin_context *ctx, GLint u_model, GLint u_albedo,
                                    GLint u_has_albedo_tex, const stin__displace_locs *dl);
/* Light l's faces (fitted as the shadow maps are; six 90-degree ones for a
 * point light), each handed to face_fn with its view and projection, and
 * the lookup's normal offset (1.5 texels per unit clip w). Returns the kind:
 * 1 one face, 2 six, 0 nothing in front of a spot or directional light. */
typedef void (*stin__translucent_face_fn)(struct stin_context *ctx, int face,
                                          const float view[16], const float proj[16]);
int stin__translucent_faces(struct stin_context *ctx, const stin_light_desc *l, uint32_t size,
                            stin__translucent_face_fn face_fn, float *normal_offset);
/* Once per context and technique (*said): light l is an area light, whose
 * transparent casters' map is drawn from its centre (hard edges). */
void stin__translucent_say_area(struct stin_context *ctx, const stin_light_desc *l, int *said,
                                const char *technique);
/* Nothing on the two units from `unit` (target's binding); unit 0 active. */
void stin__translucent_unbind(struct stin_context *ctx, int unit, GLenum target);

#endif
