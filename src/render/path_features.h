/* SPDX-License-Identifier: MIT */
/* What a feature adds to the lighting paths: the GLSL chunks it splices
 * into their programs with the uniforms and textures that go with them,
 * the fixed-function passes it adds, which draws a camera pass counts, and
 * the maps a light needs of its own. The frame lends each feature's hooks
 * through the context (frame/hooks.c), so neither a path nor a post stage
 * names a feature; they loop over the list or call the wrappers in
 * render/path_features.c, which answer as if no feature were there where
 * none gives a hook. */
#ifndef STIN_PATH_FEATURES_H
#define STIN_PATH_FEATURES_H

#include "stin/stin.h"
#include "render/path.h"

/* The lit program's variants: plain, or a surface feature's (surface/glsl.c)
 * normal mapping, parallax and parallax occlusion mapping. */
enum { STIN__SURF_PLAIN = 0, STIN__SURF_NORMAL, STIN__SURF_PARALLAX, STIN__SURF_POM,
       STIN__SURF_COUNT };

/* Where a feature's fragment chunks go. A program's list runs in this
 * order around the shadow technique's chunk (render/path_glsl.c). */
typedef enum stin__chunk_place {
    STIN__CHUNK_NONE = 0,
    STIN__CHUNK_SURFACE, /* before the shadow chunk: lit programs only */
    STIN__CHUNK_SEAM,    /* after it, wrapping its seam: in the flat program's
                          * shadow test too */
    STIN__CHUNK_LAYER    /* last, wrapping main's first call: lit programs
                          * that may draw a peeled layer */
} stin__chunk_place;
#define STIN__FEATURE_CHUNKS 2 /* a feature's chunks at most */

/* Every hook may be NULL: the feature adds nothing there. */
typedef struct stin__path_feature {
    /* ---- GLSL programs (render/path_glsl.c) ---- */
    stin__chunk_place place;
    /* Its chunk files (names under the tier's directory) in the lit program
     * of variant `variant`, into names; returns how many (0: none here). */
    int (*chunks)(const stin_context *ctx, int variant,
                  const char *names[STIN__FEATURE_CHUNKS]);
    /* Its uniforms' locations in every program the path builds (-1 where a
     * program lacks them). */
    void (*locate)(stin_context *ctx, stin__program *p);
    /* Its samplers' units, with a lit program's per-frame uniforms. */
    void (*units)(stin_context *ctx, const stin__program *p);
    /* Its uniforms for the pass, after the shadow technique's: in the lit
     * programs, and in the flat program where its chunk is (place SEAM). */
    void (*uniforms)(stin_context *ctx, const stin__program *p);
    /* A draw's material on lit program p of variant `variant`. */
    void (*material)(stin_context *ctx, const stin__program *p, const stin_material *m,
                     int variant);
    /* At the path's end: what material bound for the frame, unbound. */
    void (*unbind)(stin_context *ctx);
    /* The lit program's variants (one feature gives them; with none, every
     * draw is plain): the best its choice asks for; that the variant above
     * `built` failed to build (msg), the choice stepped down to `built`
     * (logged); and the variant a draw's material gets. */
    int (*variant_top)(const stin_context *ctx);
    void (*variant_failed)(stin_context *ctx, int built, const char *msg);
    int (*variant_for)(stin_context *ctx, const stin_material *m);

    /* ---- fixed-function path (render/path_fixed.c) ---- */
    /* After a material is set up (its diffuse may come from the feature). */
    void (*fixed_material)(stin_context *ctx, const stin_material *m);
    /* Before a light's opaque draws: its own passes for lights[0..count),
     * the GL lights set up as they are (depth EQUAL, the caller's stencil). */
    void (*fixed_lights)(stin_context *ctx, const stin_light_desc *lights, int count);
    /* After light batch `batch` of the unshadowed beauty drew its opaque draws. */
    void (*fixed_batch)(stin_context *ctx, int batch);

    /* ---- camera passes ---- */
    /* Which of STIN__OPAQUE / STIN__BLENDED a camera pass counts draw d in. */
    int (*camera_set)(const stin_context *ctx, const stin__draw *d);
    /* Whether the camera passes draw a peeled layer now (its chunk at work). */
    int (*in_layer)(const stin_context *ctx);

    /* ---- a light's own maps, read by the chunk (place SEAM) ---- */
    /* Lights get them this frame (then they are lit one per pass). */
    int (*maps_active)(const stin_context *ctx);
    /* Light li's, made now for the pass that follows; done: it is over. */
    void (*light)(stin_context *ctx, uint32_t li);
    void (*light_done)(stin_context *ctx);
} stin__path_feature;

/* The lent features in turn, NULL-terminated (empty where none were lent). */
const stin__path_feature *const *stin__path_features(const stin_context *ctx);

/* The variant hooks of the feature that gives them: plain where none does. */
int stin__lit_variant_top(const stin_context *ctx);
void stin__lit_variant_failed(stin_context *ctx, int built, const char *msg);
int stin__lit_variant_for(stin_context *ctx, const stin_material *m);
/* Which of STIN__OPAQUE / STIN__BLENDED a camera pass counts draw d in: the
 * first feature's answer that has one, else by the material's opacity. */
int stin__camera_set(const stin_context *ctx, const stin__draw *d);
/* Whether a peeled layer is drawn now (any feature's): its passes leave the
 * CSG faces out and its lit programs keep the layer chunk. */
int stin__in_peeled_layer(const stin_context *ctx);
/* Whether lights get maps of their own this frame (any feature's); every
 * feature's for light li made now, and done after the light's pass. */
int stin__light_maps_active(const stin_context *ctx);
void stin__light_maps_make(stin_context *ctx, uint32_t li);
void stin__light_maps_done(stin_context *ctx);

#endif
