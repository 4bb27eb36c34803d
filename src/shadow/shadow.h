/* SPDX-License-Identifier: MIT */
/* Shadow techniques: one module each behind one interface (shadow/vdsm.c,
 * shadow/volume.c, shadow/map_fixed.c, shadow/map_pcf.c, shadow/off.c),
 * each owning its state, and the light cameras the map techniques share
 * (render/light_camera.c). The frame plan (frame/frame.c) calls the hooks
 * and nothing outside a module asks which technique runs: a new technique
 * is a module (its hooks; its state in its own private header or .c, a
 * pointer in the context and a slot row), a row in
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
    /* A chunk spliced in just before glsl_chunk, chosen for the context
     * (map-pcf: how a tap reads its map). NULL hook: none. */
    const char *(*glsl_pre_chunk)(const stin_context *ctx);
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
    /* 1 where light() calls shade exactly once, the test all in the lit
     * program (fragment_test), and nothing of the technique reads the
     * frame's depth: the frame may then draw the first light's pass in the
     * ambient pass's place, with depth writes (frame/frame.c's forward
     * pass). 0: the ambient pass comes first. */
    int forward;
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
     * are (volume: STIN_DEBUG_VOLUME_SHOW). NULL: none. */
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
/* Each module's state is its own, defined where no other folder sees it:
 * volume's in shadow/volume_private.h, map-depth and map-combine's in
 * shadow/map_fixed_private.h, map-pcf's in shadow/map_pcf.c, vdsm's in
 * shadow/vdsm_private.h. Their sizes, for their slots (frame/modules.c): */
size_t stin__volume_state_bytes(const stin_desc *d);
size_t stin__map_fixed_state_bytes(const stin_desc *d);
size_t stin__map_pcf_state_bytes(const stin_desc *d);
size_t stin__vdsm_state_bytes(const stin_desc *d);
size_t stin__cast_map_state_bytes(const stin_desc *d);

/* ---- the measured choice of the exact technique (shadow/choice.c) --------- */
/* stin.h, SHADOWS: where the selection chose vdsm on auto, volumes run and
 * the context has timer queries, each frame runs vdsm or volumes (GPU-
 * extruded or CPU-built), whichever measured cheaper. Its state's size (a
 * slot of frame/modules.c) and desc.shadows.choice_frames' default. */
#define STIN__CHOICE_FRAMES 30u
size_t stin__choice_state_bytes(const stin_desc *d);
/* At stin_create after the shadows module's set-up: whether the choice
 * runs here, and if so volumes set up beside vdsm (logged where it runs,
 * and where timer queries alone are missing).
 * release gives volumes' GL objects back and leaves ctx->shadow on vdsm,
 * for the context to release as the selection's module. */
void stin__choice_init(stin_context *ctx);
void stin__choice_release(stin_context *ctx);
/* At stin_begin_frame, before the module's prepare hook: the module the
 * frame begins on (ctx->shadow where the choice is off). */
const stin__shadow_technique *stin__choice_begin(stin_context *ctx);
/* At stin_end_frame, before the plan: volumes_draw says whether volumes
 * draw this frame the same as vdsm (frame/shadow_choice.c); where not, the
 * frame goes to vdsm (ctx->shadow). Reads back what earlier frames' timers
 * hold and starts this frame's. end, after the plan: stops it and fills
 * stin_frame_stats.shadows.choice_*. */
void stin__choice_plan(stin_context *ctx, int volumes_draw);
void stin__choice_end(stin_context *ctx);

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
                              const float far_plane_object[4], int zfail);
/* 0: the following frames build every volume on the CPU although the
 * extrusion program exists; 1 (the state after init): extrude on the GPU where
 * it can. Returns whether GPU extrusion is available at all. */
int stin__volume_extrude_enable(stin_context *ctx, int on);
/* The casters an exact technique cannot cast through a map of their own
 * (shadow/cast_map.c), on the GLSL tiers and GL1 with multitexture (and
 * depth compare or texture_env_combine): volumes' CSG products and
 * displaced draws, vdsm's products where it has no storage buffers (or a
 * product passes its limits). init/release at the technique's set-up
 * (screen: for vdsm's mask). casts: draw d is cast by volumes' map, not
 * by a volume. draw, before light li's visibility: its map from the light
 * (the framebuffer `back` and the frame's viewport bound again after), the
 * choice logged once per light, or once that the products cast nothing;
 * returns whether it drew any. mark, after a volumes count
 * (stin__volume_light): the stencil made non-zero wherever that map
 * shadows the frame's surfaces; mask, after vdsm wrote light li's channel
 * of the bound screen mask: 0 there wherever the map shadows the surface
 * of its position buffer (`positions`); both leave the pass state as they
 * found it and draw nothing where draw drew none. */
void stin__cast_map_init(stin_context *ctx, int screen);
void stin__cast_map_release(stin_context *ctx);
int stin__cast_map_casts(const stin_context *ctx, const stin__draw *d);
int stin__cast_map_draw(stin_context *ctx, const stin__path *path, uint32_t li, GLuint back,
                        int screen);
void stin__cast_map_mark(stin_context *ctx);
void stin__cast_map_mask(stin_context *ctx, int channel, GLuint positions);
/* GL1 without framebuffer objects (shadow/cast_map_fixed.c): volumes' light
 * pre-pass, every light's map drawn in the frame's buffer before its clear
 * and copied out (draw then finds it made). */
void stin__cast_map_prepass(stin_context *ctx);
/* The same for the point lights alone: map-depth and map-combine without
 * faces, which hand those to volumes (shadow/map_fixed.c). */
void stin__cast_map_prepass_points(stin_context *ctx);
/* After a light's last sample: stencil test and scissor off. */
void stin__volume_light_end(stin_context *ctx);
/* The frame's projection with the far plane at infinity (perspective) or
 * depth clamp (orthographic), for volumes: a prepare hook. */
void stin__volume_projection(stin_context *ctx);
/* Screen rectangle a light of finite range can touch; 0 when unbounded. */
int stin__light_scissor(const stin_context *ctx, const stin_light_desc *l, int out[4]);
/* The slope-scaled polygon offset of a light's map pass (its shadow_offset,
 * default 1.1 / 4, its units in 24-bit depth's steps: scaled to the maps'
 * own step, stin__rt_depth_unit); returns 0 where the light asks for none
 * (shadow_offset_exact with both 0). */
int stin__map_offset(const stin_context *ctx, const stin_light_desc *l, float *factor,
                     float *units);

/* map-depth's side test (shadow/map_facing.c). init decides it (a unit
 * after the depth compare's, `units_after` more kept for later units) and
 * makes its FBO; create makes slot's texture. draw renders slot's side map
 * right after its depth map, under the same viewport (and, without FBOs,
 * scissor). bind/unbind put slot's test on its unit; shade draws the lit
 * pass once per side the eye sees. */
void stin__map_facing_init(stin_context *ctx, int units_after);
void stin__map_facing_create(stin_context *ctx, uint32_t slot);
void stin__map_facing_release(stin_context *ctx);
void stin__map_facing_draw(stin_context *ctx, uint32_t slot, const stin_light_desc *l,
                           const float view[16], const float proj[16]);
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
/* One texture_env_combine stage: operation, sources and operands for RGB
 * and alpha (a second source of 0 is unused); set makes it the active
 * unit's environment (shadow/map_combine.c). */
typedef struct stin__combine_stage {
    GLenum rgb, rgb_src[2], rgb_op[2];
    GLenum alpha, alpha_src[2], alpha_op[2];
} stin__combine_stage;
void stin__combine_set(stin_context *ctx, const stin__combine_stage *c);
/* map-combine's depth as colour (shadow/map_combine.c): the 1D INTENSITY8
 * ramp of 256 steps (created), its texgen of light-eye depth over [n, f]
 * on the active unit (the modelview left the identity), and the plane of
 * a receiver's own ramp coordinate in world space, biased nearer for the
 * 8-bit steps and slopes over a texel of a map `texels` wide. */
GLuint stin__map_ramp_create(stin_context *ctx);
void stin__map_ramp_texgen(stin_context *ctx, float n, float f);
void stin__map_ramp_plane(const stin_light_desc *l, const float view[16], const float proj[16],
                          float n, float f, uint32_t texels, float plane[4]);
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
/* An atlas of a point light's six faces: 3 x 2 cells, face f in column
 * f % 3, row f / 3 (the lookups' clamps agree). into_cell: a window matrix
 * (above) scaled and moved into cell `cell` (rows 0 and 1). */
#define STIN__ATLAS_COLUMNS 3u
#define STIN__ATLAS_ROWS 2u
void stin__light_into_cell(float m[16], int cell);
/* The view and projection of a spot or directional light and the depth range
 * [n, f] it spans; 0 for a point light or when nothing is in front. map_size
 * snaps a directional map to whole texels (0: no snapping). */
int stin__light_camera(const stin_context *ctx, const stin_light_desc *l, float view[16],
                       float proj[16], float *n, float *f, uint32_t map_size);

#endif
