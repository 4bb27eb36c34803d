/* SPDX-License-Identifier: MIT */
/* The context and the headers of every subsystem, for libstin's sources.
 * Each subsystem's own header says what it offers; this one only puts the
 * context together. */
#ifndef STIN_INTERNAL_H
#define STIN_INTERNAL_H

#include "stin/stin.h"
#include "gl/gl_calls.h"
#include "base/base.h"
#include "gl/caps_parse.h"
#include "select/technique.h"
#include "assets/mesh_store.h"
#include "render/path.h"
#include "render/displace_chunk.h"
#include "render/screen_quad.h"
#include "render/screen_mask.h"
#include "render/casters.h"
#include "render/resolved.h"
#include "render/path_features.h"
#include "gl/pass_state.h"
#include "gl/caller_redirects.h"
#include "gl/render_target.h"
#include "gl/uniforms.h"
#include "shadow/shadow.h"
#include "surface/surface.h"
#include "post/visibility_export.h"
#include "post/outline.h"
#include "csg/csg.h"
#include "translucent/translucent.h"
#include "transparency/transparency.h"
#include "gl/stage_times.h"

typedef enum stin__frame_state { STIN__IDLE = 0, STIN__IN_FRAME } stin__frame_state;

struct stin_context {
    stin_desc desc;           /* with defaults applied */
    stin__gl gl;
    unsigned char gl_loaded[STIN_GLFN_COUNT];
    stin_caps caps;
    stin__selection sel;
    const stin__shadow_technique *shadow; /* the shadows choice's module */
    uint32_t gl_violations;   /* checked build: calls the profile does not allow */
#if defined(STIN_GL_CHECK) && STIN_GL_CHECK
    stin__gl gl_driver;       /* the driver's entry points; gl holds the ES audit's wrappers */
#endif

    /* meshes and textures (assets/mesh.c, assets/texture.c) */
    uint32_t creation_serial; /* contexts made in this block so far (kept across them) */
    uint32_t handle_tag;      /* top 8 bits of this context's handles (base/handle_pool.c) */
    stin__mesh_slot *meshes;
    stin__texture_slot *textures;
    stin__vertex *vertices;   /* max_vertices */
    uint32_t *welds;          /* max_vertices: the vertex (of its mesh) each was welded
                               * onto at creation, for stin_update_mesh */
    uint32_t *indices;        /* 3 * max_triangles */
    uint32_t *adjacency;      /* 3 * max_triangles */
    /* a row of index_chunks_per_mesh per mesh slot (assets/mesh_chunks.c) */
    stin__index_chunk *index_chunks;
    uint32_t index_chunks_per_mesh;
    stin__range_alloc vertex_ranges, triangle_ranges;
    stin__range *vertex_range_store, *triangle_range_store;
    unsigned char *scratch;   /* mesh creation: weld and edge tables */
    size_t scratch_bytes;
    unsigned char *staging;   /* texture creation */
    size_t staging_bytes;

    /* the frame (frame/frame.c) */
    stin__draw *draws;
    uint32_t *draw_order;
    stin_light_desc *lights;
    uint32_t draw_count, light_count;
    stin_frame_desc frame;
    stin__frame_state state;
    stin_frame_stats stats;
    /* Per-frame scratch, sized in layout() for the biggest mesh and used by
     * one pass at a time: shadow volumes' per-triangle facing bytes and a
     * chunk of homogeneous vertices; DOT3's per-vertex light vectors. */
    unsigned char *frame_scratch;
    size_t frame_scratch_bytes;
    float projection[16];     /* what the frame draws with (P_inf for volumes) */
    float view_proj[16];
    stin__pass_state pass;    /* what GL holds, when pass_known */
    int pass_known;
    GLenum lit_cull;          /* face the lit passes cull (0: none): map-depth's facing test */
    /* glPolygonOffset's r in the depth textures drawn into (0: 24-bit
     * depth's 2^-24), measured where they are unsized (gl/render_target.c) */
    float depth_texture_unit;
    /* before each lit draw (NULL: none): a shadow test that differs by
     * receiver (map-depth's terminator test: solids and the rest) */
    void (*lit_draw)(stin_context *ctx, const stin__draw *d);
    uint32_t units_used;      /* texture units bound this frame (bit per unit) */
    GLuint draw_fbo;          /* where the frame plan draws now: the frame's framebuffer,
                               * or the screen mask (visibility export); a module that
                               * draws elsewhere mid-frame (maps) binds it back */
    unsigned char pass_channel; /* 0, or 1-4: the draws' passes write only R, G, B or A
                                 * (a light's channel of the visibility export) */
    GLenum pass_blend[2];     /* 0, or the factors the draws' passes blend with instead
                               * (shadow/volume.c: an area light's shares in alpha) */
    const stin__draw *sorted_draw; /* "sorted", shadowed: the blended draw the shade
                                    * function lights (frame/frame.c) */
    GLuint caller_vao;        /* the caller's vertex array object, bound again at the end */
    unsigned caller_has;      /* STIN__CALLER_*: what caller_redirects.c may query */
    unsigned queries_busy;    /* STIN__QUERY_*: targets the caller's active queries hold */
    stin__caller_frame caller; /* the frame's set-aside caller state */
    struct {                  /* the frame's framebuffer (gl/framebuffer_probe.c) */
        GLuint name;          /* the one probed last (0 = default) */
        int stencil_bits, depth_bits;
        int alpha_bits;       /* of its colour: an area light's shares add up there */
        int shadows_off;      /* the shadows choice cannot run into it (frame/target.c) */
        int separate_read;    /* draw and read bindings are separate (GL 3.0, ARB_fbo) */
        int multisampled;     /* it has sample buffers (GL_SAMPLE_BUFFERS, GL 1.3) */
    } target;
    /* what the frame lends the layers below it (frame/hooks.c): extra
     * shadow casters and a resolved depth, NULL where no feature gives them;
     * what features add to the lighting paths, NULL-terminated */
    stin__casters_state casters;    /* render/casters.h */
    const stin__resolved *resolved; /* render/resolved.h */
    const stin__path_feature *const *path_features; /* render/path_features.h */

    /* lighting paths */
    stin__program programs[STIN__PROG_COUNT];
    uint32_t bound_mesh;      /* mesh slot whose arrays are bound, UINT32_MAX = none */
    unsigned char warned_split_band; /* a split mesh's band was left out (logged once) */
    /* streamed volume vertices (and quads): on GL4 with a vertex array of
     * its own; on OpenGL ES 3.0+ without (GL2 tier), where WebGL 2 has no
     * client arrays; volume_ibo streams indices on both (WebGL binds no
     * buffer as both vertex and index data) */
    GLuint volume_vbo, volume_vao, volume_ibo;
    struct {                  /* the displacement choice as the layers below render
                               * read it (stin__selection_hand_down), the frame's
                               * scale as the chunk reads it, and its log
                               * (render/displace_chunk.c) */
        int displace;         /* vertex stages splice displace.glsl, not
                               * displace_none.glsl (gl/shader.c), and height maps
                               * get a mip chain for it (assets/texture.c) */
        int tessellate;       /* programs asked to tessellate are (gl/shader.c) */
        float tess[4];        /* the frame's u_tess (gl4/tess.tesc); [0] and [3] serve
                               * the mip level too (stin__displace_frame_scale) */
        float tess_eye[3];    /* the camera's eye */
        uint32_t logged[16];  /* coarse meshes already logged (mesh slot, height map) */
        uint32_t logged_count;
    } vertex_chunk;
    /* Meshes get adjacency buffers for the shadows module that asked
     * (stin__mesh_adjacency_use): what a mesh without one gets, for the
     * log; NULL: none do. */
    const char *adjacency_use;
    int lights_per_pass;

    /* Module-private state: each module defines its struct in its own
     * folder (a *_private.h no other folder includes) and says its size; the
     * frame lays them out in the caller's block (stin__state_slots). */
    struct stin__volume_state *volume;
    struct stin__deep_state *deep;    /* translucent shadows' deep maps (translucent/deep.c) */
    struct stin__coloured_state *coloured; /* their colour maps (translucent/coloured.c) */
    struct stin__peel_state *peel; /* transparency's camera layers (transparency/peel.c) */
    struct stin__dot3_state *dot3; /* DOT3 bump mapping (surface/dot3.c) */
    struct stin__surf_glsl_state *surf_glsl; /* GLSL surface detail (surface/glsl.c) */
    struct stin__displace_state *displace; /* displacement's frame (surface/displace.c) */
    struct stin__export_state *visibility; /* the visibility map (post/visibility_export.c) */
    struct stin__outline_state *outline;   /* the deferred outline (post/outline.c) */
    struct stin__mask_state *mask;           /* render/screen_mask.c */
    struct stin__map_fixed_state *map_fixed; /* shadow/map_fixed_private.h */
    struct stin__map_pcf_state *map_pcf;     /* shadow/map_pcf.c */
    struct stin__cast_map_state *cast_map;   /* volumes' products map (shadow/cast_map.c) */
    struct stin__vdsm_state *vdsm;           /* shadow/vdsm_private.h */
    struct stin__choice_state *choice;       /* vdsm or volumes by cost (shadow/choice.c) */
    struct stin__glsl_state *glsl;           /* the GLSL path's (render/glsl_private.h) */
    struct stin__stage_times *times;         /* gl/stage_times_private.h */
    struct stin__csg_state *csg;             /* CSG products (csg/csg_private.h) */
};

stin_desc stin__desc_defaults(const stin_desc *desc);
/* A module's private state in the caller's block (frame/modules.c): where
 * the context keeps the pointer, its size for a desc (defaults applied) and,
 * optionally, how it lays out its own arrays behind it. stin_create zeroes
 * it before place. */
typedef struct stin__state_slot {
    size_t offset;                            /* offsetof(stin_context, member) */
    size_t (*bytes)(const stin_desc *d);
    void (*place)(void *state, const stin_desc *d); /* NULL: nothing to place */
} stin__state_slot;
extern const stin__state_slot stin__state_slots[];
extern const size_t stin__state_slot_count;
/* The module of a shadows technique, off for anything else (frame/modules.c). */
const stin__shadow_technique *stin__shadow_technique_of(stin_technique t);
/* The measured choice around a frame (frame/shadow_choice.c): begin, at
 * stin_begin_frame before the prepare hook, swaps in the module the frame
 * begins on; plan, before the frame plan, weighs whether volumes draw this
 * frame's lights and draws the same as vdsm and starts its timer; end,
 * after the plan, stops it. */
void stin__frame_choice_begin(stin_context *ctx);
void stin__frame_choice_plan(stin_context *ctx);
void stin__frame_choice_end(stin_context *ctx);

/* Texture staging (assets/texture.c): the regions a texture's levels are built in. */
#define STIN__MAX_TEXELS (1ull << 30) /* 32-bit byte offsets, 4 a texel */
typedef struct stin__staging_plan {
    uint64_t region_a, region_b, derived, total;
} stin__staging_plan;
stin__staging_plan stin__plan_staging(uint32_t w, uint32_t h, int mips, int staged0,
                                      uint64_t derived_bytes);
uint32_t stin__pot_at_least(uint32_t n);
/* Around a frame (frame/state.c): save what the header promises to give back,
 * then restore it and reset the rest to the documented defaults. */
void stin__state_save(stin_context *ctx);
void stin__state_restore(stin_context *ctx);
/* At stin_create, once the features have chosen (frame/hooks.c): the
 * services the frame lends the layers below it (ctx->casters, ->resolved). */
void stin__hooks_install(stin_context *ctx);
/* Before the lighting path's set-up, which builds the features' chunks into
 * its programs (frame/hooks.c): ctx->path_features. */
void stin__hooks_install_paths(stin_context *ctx);
/* Caller state no pass sets (gl/caller_state.c): defaults sets GL's defaults
 * for every tier; fixed_begin, after the attribute push, does the same for
 * what the fixed pipeline mixes in (texture matrices get a stack level) and
 * fixed_end, before the pop, gives the texture matrices back. */
void stin__caller_state_defaults(stin_context *ctx);
void stin__caller_state_fixed_begin(stin_context *ctx);
void stin__caller_state_fixed_end(stin_context *ctx);

/* The frame's framebuffer (gl/framebuffer_probe.c). target_init, at
 * stin_create after detection: the default framebuffer's bits, and the
 * stencil capability if it or the bound one has a stencil buffer.
 * target_probe, at begin and end of a frame: `name` must be a complete
 * framebuffer object (else a logged INVALID_ARGUMENT); reads its bits when
 * it is not the one probed last. The caller's binding is kept.
 * target_check (frame/target.c): the probe, then whether this frame's
 * shadows run into it (logged when that changes). */
void stin__framebuffer_bits(const stin__gl *gl, int core, GLuint bound, int *stencil, int *depth);
void stin__target_init(stin_context *ctx);
stin_result stin__target_probe(stin_context *ctx, GLuint name, const char *call);
stin_result stin__target_check(stin_context *ctx, GLuint name, const char *call);
/* The caller's draw and read framebuffers (contexts with FBOs), to be bound
 * again after a probe or a set-up that binds its own. */
void stin__framebuffer_save(stin_context *ctx, GLint saved[2]);
void stin__framebuffer_restore(stin_context *ctx, const GLint saved[2]);
/* The frame's framebuffer has a stencil buffer (and stencil is not masked). */
int stin__target_has_stencil(const stin_context *ctx);

#endif
