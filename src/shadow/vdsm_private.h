/* SPDX-License-Identifier: MIT */
/* vdsm's own state and the functions its files share (shadow/vdsm*.c):
 * nothing outside src/shadow/ includes this header (tools/check-layers.sh). */
#ifndef STIN_SHADOW_VDSM_PRIVATE_H
#define STIN_SHADOW_VDSM_PRIVATE_H

#include "internal.h"

/* Where a program reads the pyramid (vdsm_cull.glsl, u_depth_row of
 * vdsm_side.glsl); -1 where it does not. */
typedef struct stin__vdsm_pyramid_locs {
    GLint sm, dc, vp, depth, pyramid, size, top;
} stin__vdsm_pyramid_locs;

/* The light pass's uniforms (vdsm_light.glsl), in each of its two programs. */
typedef struct stin__vdsm_light_locs {
    GLint model, vp, depth, light, cull_lit, size, grow, bound, persp;
} stin__vdsm_light_locs;

/* VDSM steps SM and DC (shadow/vdsm_pyramid.c): per light, a pyramid over
 * the light's view of the scene - the occluders' depth bound and the deepest
 * receiver per texel, maxima up the levels - that the shadow polygons read
 * to drop triangles and to stop their extrusion. */
typedef struct stin__vdsm_pyramid {
    GLuint fbo, accum, levels;  /* accumulation (MAX-blended) and the pyramid, RG32F */
    GLuint stencil;             /* the light pass's per-draw outline marks */
    GLuint points;              /* a vertex array without arrays: one point per pixel */
    GLuint light_prog, receiver_prog, reduce_prog;
    GLuint tris_prog;           /* the light pass's triangles (light_prog: its marks) */
    int alloc;                  /* texels a side allocated (desc.shadows.map_size, <= 2048) */
    int size, top;              /* this frame's level 0 side (<= alloc); its 1 x 1 level */
    int usable;                 /* programs and framebuffer are there */
    int ready;                  /* this light's pyramid is drawn (else SM and DC are off) */
    int perspective;            /* the light's view is a perspective one */
    float front;                /* occluders lie deeper than this (behind: no triangle) */
    float view_proj[16];        /* world -> the light's clip space */
    float depth_row[4];         /* world -> light depth */
    stin__vdsm_light_locs marks, tris; /* light_prog's and tris_prog's */
    stin__displace_locs tris_displace;
    GLint r_position, r_normal, r_shading, r_light, r_vp, r_depth, r_rect;
    GLint d_source, d_first;
    /* GL 4.3 (shadow/vdsm_receivers.c): the receivers by atomics, per texel
     * the deepest one's ordered bits in a storage buffer (0: none) */
    GLuint deepest, atomic_prog, first_prog;
    GLint a_position, a_normal, a_shading, a_light, a_vp, a_depth, a_size, f_source, f_size;
    int said_no_view, said_failed;
} stin__vdsm_pyramid;

/* vdsm's shadows of CSG products (shadow/vdsm_csg.c): per light and
 * product, per-pixel lists of the crossings of each pixel's segment to the
 * light in shader storage buffers (heads, node pool, the normal form's
 * term masks), walked by a screen pass. */
#define STIN__VDSM_CSG_MAX_PRIMITIVES 128u /* a bit each in the walk's state */
#define STIN__VDSM_CSG_MAX_TERMS 64u
typedef struct stin__vdsm_csg {
    GLuint append_prog, walk_prog;
    GLuint buffers[3];          /* heads, nodes, terms (0: not built) */
    GLint a_model, a_view_proj, a_light, a_camera, a_viewport, a_grow, a_caps, a_position,
        a_normal, a_primitive, a_mirrored, a_frame;
    GLint w_terms, w_light_inside, w_frame, w_clear;
    stin__displace_locs displace;
    uint32_t pixels, capacity;  /* heads and pool nodes allocated */
    uint64_t bytes;             /* GL memory of the three buffers */
    int cleared;                /* the heads are all 0 */
    int terms_made;
    int said_limits, said_pool;
} stin__vdsm_csg;
void stin__vdsm_csg_init(stin_context *ctx);
void stin__vdsm_csg_release(stin_context *ctx);
int stin__vdsm_csg_ready(const stin_context *ctx);
/* It walks every product of the frame (ready, and each within its limits):
 * else the products cast through the casters' map (shadow/cast_map.c). */
int stin__vdsm_csg_walks_all(const stin_context *ctx);
/* Light (homogeneous world point) shadowed by every product that fits,
 * into channel `channel` of the bound mask, after the light's polygons. */
void stin__vdsm_csg_cast(stin_context *ctx, const float light[4], int channel);

/* VDSM (shadow/vdsm.c): the position buffer - per pixel the visible
 * surface's world position and its facet normal - and the programs that
 * turn each triangle into shadow polygons over it. */
/* The uniforms of a program that draws shadow polygons or culls for them
 * (vdsm.geom, vdsm_cull.geom, vdsm_fed.geom); -1 where it has none. */
typedef struct stin__vdsm_polygon_locs {
    GLint model, view_proj, light, camera, viewport, grow, depth_test, cull_lit, caps, position,
        normal;
    stin__displace_locs displace;
    stin__vdsm_pyramid_locs pyramid;
} stin__vdsm_polygon_locs;

/* vdsm's culling pass (shadow/vdsm_cull.c): per light, EP, SM and DC in a
 * small geometry shader whose kept faces (a triangle's side faces and own
 * face the eye sees) transform feedback writes to a buffer, one point each;
 * the shadow-polygon program then draws those alone, in one draw (from
 * the feedback object where the context has them, else by the count a
 * query read back). */
typedef struct stin__vdsm_cull {
    GLuint cull_prog, fed_prog;
    GLuint buffer, vao;         /* the kept faces, 48 bytes each; the fed pass's arrays */
    GLuint feedback, query;     /* feedback object (or 0); primitives-written query (or 0) */
    uint32_t capacity;          /* faces the buffer holds */
    uint32_t oversized;         /* light passes in a row it held over 4x their need */
    stin__vdsm_polygon_locs cull, fed;
    int usable;
    uint32_t kept;              /* faces kept by the last light's pass, where counted */
} stin__vdsm_cull;

/* Area lights (shadow/vdsm_soft.c): the 64-segment program and its
 * resolve, built at the first area light, and the bits' RG32UI target (on
 * OpenGL ES: an R32UI image twice as wide, cleared through fbo, ORed into
 * with depth_fbo bound). */
typedef struct stin__vdsm_soft {
    GLuint prog, resolve_prog, fbo, bits, depth_fbo;
    int width, height;      /* allocated texels (the position buffer's) */
    int built;              /* tried: prog is 0 where that failed */
    int image;              /* the bits are ORed by image atomics, not glLogicOp */
    stin__vdsm_polygon_locs poly;
    GLint radius, lo, hi, resolve_bits;
} stin__vdsm_soft;
/* Whether this light's soft pass can run (programs, target, an
 * untessellated frame); the mask stays bound. The pass, after the light's
 * facing pass, into mask channel `channel` (light: its centre, w 1). */
int stin__vdsm_soft_available(stin_context *ctx);
void stin__vdsm_soft_draw(stin_context *ctx, const stin_light_desc *l, const float light[4],
                          int channel);
void stin__vdsm_soft_release(stin_context *ctx);

struct stin__vdsm_state {
    GLuint fbo, position, normal, shading, depth;
    int width, height;      /* allocated texels (0: not yet) */
    GLuint position_prog, facing_prog, polygon_prog, query;
    GLuint position_tess, polygon_tess; /* "displace-tess": the two, tessellated */
    int tess_active;        /* they are swapped into position_prog and polygon_prog */
    GLint pos_model, pos_normal_matrix, pos_view_proj, pos_camera, pos_csg, pos_csg_depth,
        pos_csg_grow;
    GLint face_position, face_normal, face_shading, face_light;
    stin__vdsm_polygon_locs poly; /* polygon_prog's (the one-pass program) */
    stin__displace_locs pos_displace; /* position_prog's displacement chunk */
    stin__vdsm_cull culling;
    float camera[4];        /* world: the eye (w 1) or the direction toward it (w 0) */
    int ready;              /* this frame's position buffer is drawn */
    int said_area, said_failed, said_layer, said_unshadowed_layers;
    stin__vdsm_pyramid pyramid;
    stin__vdsm_csg csg;
    stin__vdsm_soft soft;
};

/* The position buffer stage and its release (shadow/vdsm_buffer.c);
 * buffer_csg adds the CSG products' surfaces after their resolve
 * (stin__shadow_vdsm's after_csg). */
void stin__vdsm_buffer_draw(stin_context *ctx);
void stin__vdsm_buffer_csg(stin_context *ctx, const stin__path *path);
/* Peeled layers (shadow/vdsm_buffer.c; stin__shadow_vdsm's layers_begin,
 * layer and layers_end): lit unshadowed under
 * STIN_DEBUG_PEEL_VDSM_UNSHADOWED; a layer's surface as the buffer (during
 * the layer's lights, its depth texture on ctx->draw_fbo); the opaque
 * surfaces again after the layers where the visibility export reads them. */
int stin__vdsm_buffer_layers_begin(stin_context *ctx);
void stin__vdsm_buffer_layer(stin_context *ctx);
void stin__vdsm_buffer_layers_end(stin_context *ctx, const stin__path *path);
void stin__vdsm_buffer_release(stin_context *ctx);
/* The pyramid (shadow/vdsm_pyramid.c): programs and textures at set-up
 * (a failure leaves SM and DC off, logged); per light, with the screen mask
 * bound, draws it and binds the mask again, returning 1 where its
 * receivers' pass also wrote the light's facing pass into mask channel
 * `channel`; then the shadow-polygon program's uniforms (bound program) for
 * that light. */
void stin__vdsm_pyramid_init(stin_context *ctx);
void stin__vdsm_pyramid_release(stin_context *ctx);
int stin__vdsm_pyramid_draw(stin_context *ctx, const float light[4], int channel);
/* A program's pyramid uniforms: located, and set (bound program) for the
 * light drawn last. */
void stin__vdsm_pyramid_locate(stin_context *ctx, GLuint prog, stin__vdsm_pyramid_locs *l);
void stin__vdsm_pyramid_uniforms(stin_context *ctx, const stin__vdsm_pyramid_locs *l);
/* The receivers by storage-buffer atomics (shadow/vdsm_receivers.c), where
 * the context has them: set up after the pyramid (0 where not), one light's
 * pass (from the pyramid's framebuffer, back to it; the light's facing pass
 * into mask channel `channel` too), and level 0 of the pyramid from them
 * and the occluders' accumulation. */
int stin__vdsm_receivers_init(stin_context *ctx);
void stin__vdsm_receivers_release(stin_context *ctx);
void stin__vdsm_receivers_draw(stin_context *ctx, const float light[4], int channel);
void stin__vdsm_receivers_first_level(stin_context *ctx);
/* "displace-tess": swaps the tessellated position-buffer and shadow-polygon
 * programs in (on) or out, their uniforms located again; nothing without
 * them (shadow/vdsm.c: stin__shadow_vdsm's tessellate). */
void stin__vdsm_tessellate(stin_context *ctx, int on);
/* Shared by the vdsm files (shadow/vdsm.c): a program of embedded shaders
 * (geom may be NULL; out1 names a second output after o_position;
 * tessellate as in stin__program_source), and the
 * deletion of three programs (each set to 0). */
GLuint stin__vdsm_program(stin_context *ctx, const char *vert, const char *geom,
                          const char *frag, const char *out1, int tessellate, char *msg,
                          size_t size);
/* A shadow-polygon program: vdsm.vert and vdsm.geom with fragment stage
 * frag, which has the segment test's chunk (vdsm_segment.glsl). */
GLuint stin__vdsm_polygon_program(stin_context *ctx, const char *frag, int tessellate, char *msg,
                                  size_t size);
void stin__vdsm_delete_programs(stin_context *ctx, GLuint *a, GLuint *b, GLuint *c);
/* A polygon or culling program's uniforms located (shadow/vdsm.c); the
 * light's uniforms set on the bound one; the frame's casting draws through
 * it, each with its EP and caps uniforms and triangles. */
void stin__vdsm_polygon_locate(stin_context *ctx, GLuint prog, stin__vdsm_polygon_locs *l);
void stin__vdsm_polygon_uniforms(stin_context *ctx, const stin__vdsm_polygon_locs *l,
                                 const float light[4]);
void stin__vdsm_draw_casters(stin_context *ctx, const stin__vdsm_polygon_locs *l);
/* The culling pass (shadow/vdsm_cull.c): programs and buffer at set-up (a
 * failure logs and leaves the one-pass program); whether this frame culls
 * first (not with tessellated draws or STIN_DEBUG_VDSM_ONE_PASS; its buffer
 * grown to the frame's casting triangles); one
 * light's pass, which leaves the fed program bound and returns 0 where
 * nothing was kept; the kept triangles' draw through it. */
void stin__vdsm_cull_init(stin_context *ctx);
void stin__vdsm_cull_release(stin_context *ctx);
int stin__vdsm_cull_on(stin_context *ctx);
int stin__vdsm_cull_pass(stin_context *ctx, const float light[4]);
void stin__vdsm_cull_draw(stin_context *ctx);
/* 1 when EP may drop a draw's light-facing triangles (shadow/vdsm.c). */
/* 1 when the shadow polygons test their depth against the visible
 * surface's (depth clamping there, not switched off for measurement). */
int stin__vdsm_depth_tested(const stin_context *ctx);
int stin__vdsm_cull_lit(const stin_context *ctx, const stin__draw *d);

#endif
