/* SPDX-License-Identifier: MIT */
/* Shadow techniques: one module each behind one interface (shadow/vdsm.c,
 * shadow/volume.c, shadow/map_fixed.c, shadow/map_pcf.c, shadow/off.c),
 * each owning its state, and the light cameras the map techniques share
 * (render/light_camera.c). The frame plan (frame/frame.c) calls the hooks
 * and nothing outside a module asks which technique runs: a new technique
 * is a module (its hooks, its state below and in the context), a row in
 * select/technique_table.c, its entry in frame/modules.c and its public
 * name in include/stin/stin.h. */
#ifndef STIN_SHADOW_H
#define STIN_SHADOW_H

#include "stin/stin.h"
#include "stin/stin_debug.h"
#include "gl/gl_types.h"
#include "render/path.h"

#define STIN__MAX_LIGHTS 32  /* desc.max_lights at most */
#define STIN__CUBE_FACES 6
/* Map slots: one per light, then the point lights' six shared faces. */
#define STIN__FACE_SLOT STIN__MAX_LIGHTS
#define STIN__MAP_SLOTS (STIN__MAX_LIGHTS + STIN__CUBE_FACES)

/* Draws light (a sample of it) with its visibility set up, at `weight` of
 * its intensity in the visibility output: the frame plan's lighting. */
typedef void (*stin__shade_fn)(stin_context *ctx, const stin__path *path,
                               const stin_light_desc *light, float weight);

/* A module's hooks, given by designated initialisers: a hook it leaves out
 * is NULL (0 for the flags), which each hook's comment says the meaning of,
 * so a new optional hook touches only the modules that have it. A module
 * carries no technique id to compare against: one may run several (map_fixed:
 * map-depth and map-combine), and frame/modules.c maps ids to modules. */
typedef struct stin__shadow_technique {
    /* The GLSL lit and flat programs' shadow chunk (shaders/gl2), defining
     * vec3 shadow_transmittance(int light). */
    const char *glsl_chunk;
    /* Set-up at stin_create (GL objects) and their release; init may demote. */
    stin_result (*init)(stin_context *ctx);
    void (*release)(stin_context *ctx);
    /* At stin_begin_frame: the camera projection the frame draws with
     * (ctx->projection holds the caller's). It may not depend on the frame's
     * lights, which come later: stin_query_frame_projection is valid from
     * begin on, for the application's own draws into the same depth buffer. */
    void (*prepare)(stin_context *ctx);
    /* Light pre-passes (maps): before the frame's target is bound and
     * cleared, since without FBOs they draw in the frame's own buffer. */
    void (*light_prepass)(stin_context *ctx);
    /* Light li's visibility: sets it up and calls shade once per sub-pass
     * (samples, faces). NULL: the technique casts no shadows. */
    void (*light)(stin_context *ctx, const stin__path *path, uint32_t li, stin__shade_fn shade);
    /* GLSL: the chunk's uniforms and samplers on program p for the light
     * being shaded (none outside light()). NULL: nothing to set. */
    void (*uniforms)(stin_context *ctx, const stin__program *p);
    /* Per-light visibility as data (render/screen_mask.c): writes light li's
     * visibility into channel `channel` of the bound screen mask and returns
     * 1, or returns 0 and leaves the light to light(). NULL: never. */
    int (*mask)(stin_context *ctx, const stin__path *path, uint32_t li, int channel);
    /* 1: mask() tests against the frame's depth in the mask's own buffer,
     * which stin__mask_begin draws there once a frame (a geometry pass);
     * 0: it brings its own depth (vdsm: the position buffer's). */
    int mask_depth;
    /* "displace-tess" (surface/displace.c): on for a frame with displaced
     * draws, its own mesh-drawing programs swapped for tessellated ones;
     * off after it. NULL: it has none. */
    void (*tessellate)(stin_context *ctx, int on);
    /* 1 where light() tests light li per fragment of the lit pass itself
     * (a map), so a draw lit on its own without the frame's depth (sorted
     * blended draws) is shadowed too; 0 where li's shadows are not such a
     * test. NULL: no light's are (volumes and masks count or mask against
     * the nearest opaque surface). */
    int (*fragment_test)(const stin_context *ctx, uint32_t li);
    /* Right after the CSG resolve (frame/frame.c), the products' depth and
     * faces in place and before any pass reads them: what the technique drew
     * of the frame's surfaces in its light pre-pass (vdsm: the position
     * buffer) gets the products' surfaces too. NULL: nothing to add. */
    void (*after_csg)(stin_context *ctx, const stin__path *path);
    /* Peeled layers of a shadowed frame (frame/frame.c's blended draws
     * under depth-peel and dual-peel), each lit by the per-light stages of
     * the opaque draws. layers_begin, once before the first layer: 0 lights
     * the layers unshadowed, and neither of the other two is called.
     * layer, before the lights of each layer that has any, that layer's
     * depth attached to ctx->draw_fbo: whatever the technique reads as the
     * receivers (vdsm: the position buffer) becomes the layer's. layers_end,
     * after the last layer: the frame's own receivers back for the stages
     * after the blended draws (the visibility export). NULL: the technique
     * needs nothing per layer (layers_begin: the layers are shadowed). */
    int (*layers_begin)(stin_context *ctx);
    void (*layer)(stin_context *ctx);
    void (*layers_end)(stin_context *ctx, const stin__path *path);
    /* After a shadowed frame's lighting and blended draws, before the
     * visibility export (frame/frame.c): a picture the caller's debug flags
     * ask for, drawn over the frame's colour, the frame's stats left as they
     * are (volume: STIN_DEBUG_SHOW_VOLUMES). NULL: none. */
    void (*debug_overlay)(stin_context *ctx, const stin__path *path);
    /* stin_debug_query_shadow_map (frame/debug.c), between frames: light
     * li's map of the last frame into *out (zeroed by the caller) and
     * STIN_OK, or STIN_ERROR_UNSUPPORTED where none is kept (a point light's
     * faces, a light the maps did not cover). NULL: the technique keeps no
     * maps. */
    stin_result (*debug_map)(const stin_context *ctx, uint32_t li, stin_debug_map *out);
} stin__shadow_technique;

extern const stin__shadow_technique stin__shadow_volume, stin__shadow_map_fixed,
    stin__shadow_map_pcf, stin__shadow_off, stin__shadow_vdsm;

/* ---- module state --------------------------------------------------------- */
typedef struct stin__map_fixed_state {
    GLuint textures[STIN__MAP_SLOTS];
    GLuint ramp;          /* map-combine: 1D ramp of light depth */
    GLuint fbo;           /* with FBOs: render straight into the texture */
    GLuint depth_scratch; /* map-combine with FBOs: the depth buffer of its pass */
    GLuint face_mask;     /* 1 inside a face's 90-degree square, 0 outside */
    /* map-depth's side maps: per slot, which side of the nearest surface the
     * light sees (LUMINANCE8: 1 front, 0 back), copied from the colour of a
     * pass of their own (with FBOs: facing_fbo, RGBA8 colour and a depth) */
    GLuint facing[STIN__MAP_SLOTS];
    GLuint facing_fbo, facing_color, facing_depth;
    int facing_test;      /* 1: the lit passes test the side (a unit was spare) */
    uint32_t size;        /* allocated texels a side */
    uint32_t used;        /* rendered this frame (no FBO: bounded by the viewport) */
    int unit;             /* first texture unit of the shadow test */
    int faces;            /* point lights get six maps (needs FBOs: drawn mid-frame) */
    unsigned char valid[STIN__MAX_LIGHTS];
    float texgen[STIN__MAP_SLOTS][16];   /* world -> map texture coordinates (rows s t r q) */
    float ramp_plane[STIN__MAP_SLOTS][4]; /* world -> ramp coordinate (map-combine) */
    int said_point, said_area;
} stin__map_fixed_state;

typedef struct stin__map_pcf_state {
    GLuint textures[STIN__MAP_SLOTS];
    GLuint fbo;
    uint32_t size;
    int unit;             /* first sampler unit (STIN__SHADOW_SAMPLERS of them) */
    unsigned char valid[STIN__MAX_LIGHTS];
    float matrix[STIN__MAP_SLOTS][16];   /* world -> [0,1] map space */
    float normal_offset[STIN__MAP_SLOTS]; /* world units per unit clip w: 1.5 texels */
    /* the light being shaded: kind 0 none, 1 its map, 2 its six faces */
    int kind;
    uint32_t light;
} stin__map_pcf_state;

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
    int alloc;                  /* texels a side allocated (desc.shadow_map_size, <= 2048) */
    int size, top;              /* this frame's level 0 side (<= alloc); its 1 x 1 level */
    int usable;                 /* programs and framebuffer are there */
    int ready;                  /* this light's pyramid is drawn (else SM and DC are off) */
    int perspective;            /* the light's view is a perspective one */
    float front;                /* occluders lie deeper than this (behind: no triangle) */
    float view_proj[16];        /* world -> the light's clip space */
    float depth_row[4];         /* world -> light depth */
    stin__vdsm_light_locs marks, tris; /* light_prog's and tris_prog's */
    stin__displace_locs tris_displace;
    GLint r_position, r_normal, r_light, r_vp, r_depth, r_rect;
    GLint d_source, d_first;
    /* GL 4.3 (shadow/vdsm_receivers.c): the receivers by atomics, per texel
     * the deepest one's ordered bits in a storage buffer (0: none) */
    GLuint deepest, atomic_prog, first_prog;
    GLint a_position, a_normal, a_light, a_vp, a_depth, a_size, f_source, f_size;
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

typedef struct stin__vdsm_state {
    GLuint fbo, position, normal, depth;
    int width, height;      /* allocated texels (0: not yet) */
    GLuint position_prog, facing_prog, polygon_prog, query;
    GLuint position_tess, polygon_tess; /* "displace-tess": the two, tessellated */
    int tess_active;        /* they are swapped into position_prog and polygon_prog */
    GLint pos_model, pos_view_proj, pos_camera, pos_csg, pos_csg_depth;
    GLint face_position, face_normal, face_light;
    stin__vdsm_polygon_locs poly; /* polygon_prog's (the one-pass program) */
    stin__displace_locs pos_displace; /* position_prog's displacement chunk */
    stin__vdsm_cull culling;
    float camera[4];        /* world: the eye (w 1) or the direction toward it (w 0) */
    int ready;              /* this frame's position buffer is drawn */
    int said_area, said_failed, said_layer, said_unshadowed_layers;
    stin__vdsm_pyramid pyramid;
    stin__vdsm_csg csg;
} stin__vdsm_state;

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
int stin__vdsm_cull_lit(const stin_context *ctx, const stin__draw *d);

/* ---- shared by the modules ------------------------------------------------ */
/* One light (sample) of stencil shadow volumes: leaves the stencil test set to
 * pass where the light is visible (shadow/volume.c; map-fixed's point lights). */
void stin__volume_light(stin_context *ctx, const stin__path *path, const float light_world[4],
                        const int scissor[4]);
/* GL4's extrusion by geometry shader (shadow/volume_extrude.c): init builds
 * its program where the context has the GL4 path and geometry shaders and
 * STIN_DEBUG_VOLUME_CPU is clear; draw draws one caster's volume for a light
 * in object space and returns 1, or 0 where the mesh has no adjacency
 * indices (the CPU builds it then). */
void stin__volume_extrude_init(stin_context *ctx);
void stin__volume_extrude_release(stin_context *ctx);
int stin__volume_extrude_draw(stin_context *ctx, const stin__draw *d, const float light_object[4],
                              int zfail);
/* After a light's last sample: stencil test and scissor off. */
void stin__volume_light_end(stin_context *ctx);
/* The frame's projection with the far plane at infinity (perspective) or
 * depth clamp (orthographic), for volumes: a prepare hook. */
void stin__volume_projection(stin_context *ctx);
/* Bytes of volume's private state (shadow/volume_private.h). */
size_t stin__volume_state_bytes(const stin_desc *d);
/* Screen rectangle a light of finite range can touch; 0 when unbounded. */
int stin__light_scissor(const stin_context *ctx, const stin_light_desc *l, int out[4]);
/* The slope-scaled polygon offset of a light's map pass (its shadow_offset,
 * default 1.1 / 4); returns 0 when the light turns offsets off. */
int stin__map_offset(const stin_light_desc *l, float *factor, float *units);

/* map-depth's side test (shadow/map_facing.c). init decides it (a unit
 * after the depth compare's, `units_after` more kept for later units) and
 * makes its FBO; create makes slot's texture. draw renders slot's side map
 * right after its depth map, under the same viewport (and, without FBOs,
 * scissor). bind/unbind put slot's test on its unit; shade draws the lit
 * pass once per side the eye sees. */
void stin__map_facing_init(stin_context *ctx, int units_after);
void stin__map_facing_create(stin_context *ctx, uint32_t slot);
void stin__map_facing_release(stin_context *ctx);
void stin__map_facing_draw(stin_context *ctx, uint32_t slot, const float view[16],
                           const float proj[16]);
void stin__map_facing_bind(stin_context *ctx, uint32_t slot);
void stin__map_facing_unbind(stin_context *ctx);
void stin__map_facing_shade(stin_context *ctx, const stin__path *path, const stin_light_desc *l,
                            stin__shade_fn shade);
/* Eye-linear texgen of s, t, (r,) q from rows (world -> texture, given under
 * the camera's view) on the active unit; R is disabled when !with_r. */
void stin__map_texgen(stin_context *ctx, const float *rows, int with_r);
/* A projected 2D unit back off: texgen S, T, Q and the texture disabled,
 * nothing bound, environment MODULATE; unit 0 active after. */
void stin__map_unit_off(stin_context *ctx, int unit);
/* map-depth / map-combine: 1 if light li is shadowed by a map test on the
 * lit pass this frame (its map, or a point light's faces), 0 where its
 * shadows are stencil volumes or none. */
int stin__map_fixed_maps_light(const stin_context *ctx, uint32_t li);

/* Light cameras for shadow maps (render/light_camera.c). */
void stin__light_look_along(float m[16], const float eye[3], const float dir[3]);
void stin__light_fit(const stin_context *ctx, const float view[16], int receivers_only,
                     float *near_d, float *far_d, float *half_width, float center_out[3]);
void stin__light_perspective(float m[16], float fovy_deg, float n, float f);
/* Face `face` (+x, -x, +y, -y, +z, -z) of a point light at `position`: a
 * 90-degree view along the axis, its depth range fitted to every caster in
 * it (an empty face gets [1e-3, 1]), near at least 1e-3 of far, so the
 * lookups' major-axis face pick meets the faces without seams. */
void stin__light_cube_face(const stin_context *ctx, const float position[3], int face,
                           float view[16], float proj[16]);
/* world -> [0,1] window coordinates of a light camera: bias * proj * view. */
void stin__light_window_matrix(float out[16], const float view[16], const float proj[16]);
/* The view and projection of a spot or directional light and the depth range
 * [n, f] it spans; 0 for a point light or when nothing is in front. map_size
 * snaps a directional map to whole texels (0: no snapping). */
int stin__light_camera(const stin_context *ctx, const stin_light_desc *l, float view[16],
                       float proj[16], float *n, float *f, uint32_t map_size);

#endif
