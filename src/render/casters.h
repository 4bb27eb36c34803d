/* SPDX-License-Identifier: MIT */
/* Extra shadow casters: surfaces a feature draws into a light's map itself,
 * beside the frame's draws (the CSG products, csg/cast.c). The frame lends
 * them to the shadow techniques through the context (frame/hooks.c), so
 * no shadow module names the feature; the techniques call the wrappers in
 * render/casters.c, which give the answers of "no extra casters" where the
 * frame lent none. */
#ifndef STIN_CASTERS_H
#define STIN_CASTERS_H

#include "stin/stin.h"
#include "gl/gl_types.h"
#include "render/path.h"

/* A literal names a primitive of its product: index * 2, + 1 complemented
 * (the term takes its outside). */
#define STIN__CSG_LITERAL(primitive, complemented) ((primitive) * 2u + ((complemented) ? 1u : 0u))
#define STIN__CSG_PRIMITIVE_OF(literal) ((literal) >> 1)
#define STIN__CSG_COMPLEMENTED(literal) ((literal) & 1u)

/* A caster a technique walks itself (vdsm: per pixel along the light's
 * segment): its primitives, and its shape as a sum of terms, each a product
 * of literals. */
typedef struct stin__caster_product {
    const stin__draw *primitives;
    uint32_t primitive_count, term_count;
    uint32_t index;           /* which of the frame's, for term() */
} stin__caster_product;

typedef struct stin__casters {
    /* Whether there are any to cast this frame. */
    int (*wanted)(const stin_context *ctx);
    /* After a light's map is cleared (viewport map_vp of framebuffer
     * map_fbo; in_place: the frame's own, whose stencil they may use) and
     * before the ordinary casters go in with depth LESS: their surface seen
     * from the light (view, proj), pushed back by the light's slope-scaled
     * offset (factor, units as glPolygonOffset), into the map's depth.
     * Returns 1 when it drew any. */
    int (*cast)(stin_context *ctx, const stin__path *path, const float view[16],
                const float proj[16], const int map_vp[4], GLuint map_fbo, int in_place,
                float factor, float units);
    /* The last cast's surface again into `target` (bound), unbiased, and
     * drawn there depth EQUAL with the fixed path's colour state (a map
     * technique's second map of the same light); nothing if it drew none. */
    void (*again)(stin_context *ctx, const int map_vp[4], GLuint target, int in_place);
    /* Logs once that they cast no shadow `why` (a technique or light that
     * cannot take them); nothing when there are none. */
    void (*none)(stin_context *ctx, const char *why);
    /* The frame's product i into out; 0 past the last. term: term t of
     * product p, its literals (count of them). */
    int (*product)(const stin_context *ctx, uint32_t i, stin__caster_product *out);
    const uint32_t *(*term)(const stin_context *ctx, const stin__caster_product *p, uint32_t t,
                            uint32_t *count);
} stin__casters;

/* What the context holds: the lent hooks (NULL: none lent, every answer
 * is "nothing to cast") and whether the last cast drew any. */
typedef struct stin__casters_state {
    const stin__casters *hooks;
    int drew;
} stin__casters_state;

int stin__casters_wanted(const stin_context *ctx);
int stin__casters_cast(stin_context *ctx, const stin__path *path, const float view[16],
                       const float proj[16], const int map_vp[4], GLuint map_fbo, int in_place,
                       float factor, float units);
void stin__casters_again(stin_context *ctx, const int map_vp[4], GLuint target, int in_place);
void stin__casters_none(stin_context *ctx, const char *why);
int stin__casters_product(const stin_context *ctx, uint32_t i, stin__caster_product *out);
const uint32_t *stin__casters_term(const stin_context *ctx, const stin__caster_product *p,
                                   uint32_t t, uint32_t *count);
/* The last cast drew some (again has something to draw). */
int stin__casters_drew(const stin_context *ctx);

#endif
