/* SPDX-License-Identifier: MIT */
/* The lighting paths (render/path_fixed.c: GL1 fixed function; render/path_glsl.c: GL2 and
 * GL4 GLSL) and what the frame plan asks of them. */
#ifndef STIN_PATH_H
#define STIN_PATH_H

#include "stin/stin.h"
#include "gl/gl_types.h"


typedef struct stin__draw {
    uint32_t mesh_slot;
    float transform[16];
    stin_material material;
    float sort_depth;  /* eye-space distance of the bounds centre, for blending order */
    unsigned char csg; /* 0; or a CSG primitive's faces on the resolved depth, drawn
                        * depth EQUAL: STIN__CSG_FRONT, STIN__CSG_BACK (normals flipped),
                        * STIN__CSG_CAP (the near plane's cut, csg/near.c) */
    unsigned char shadow_caster; /* set by the frame before its first pass: 1 when the
                                  * shadows technique draws it as a caster; 0 for a
                                  * transparent one whose shadow the translucent-shadows
                                  * technique's map or the opacity threshold decides */
} stin__draw;
enum { STIN__CSG_FRONT = 1, STIN__CSG_BACK = 2, STIN__CSG_CAP = 3 };

/* 1 when draw d is a closed solid: a closed manifold mesh whose material is
 * not two_sided, not a CSG product's face, at least min_size across along
 * each axis of its mesh's bounds in the world (render/path_fixed.c). */
int stin__draw_solid(const stin_context *ctx, const stin__draw *d, float min_size);
/* The path's depth() casters: closed solids (stin__draw_solid, at least
 * solid_min across) draw only the faces turned away from the view
 * (second-depth maps; the rest keep both sides), and either kind may be
 * left out. */
enum { STIN__DEPTH_FAR_SIDE = 1, STIN__DEPTH_SOLIDS_ONLY = 2, STIN__DEPTH_OPEN_ONLY = 4 };

/* The displacement chunk's uniforms in a program that draws meshes
 * (render/displace_chunk.c); camera: the program draws through the frame's
 * camera (the guard band applies), not from a light. */
typedef struct stin__displace_locs {
    GLint map, params, size, normal, clip, lod, eye, tess, tess_eye;
    int camera;
    int patches;  /* the program is tessellated: its draws are GL_PATCHES of 3 */
} stin__displace_locs;

/* A translucent-shadows lookup chunk's uniforms (translucent/translucent.c): the kind
 * of map the light has (0 none, 1 one face, 2 six), the faces' matrices,
 * the technique's params, its two samplers and (deep) the layers each face
 * holds. */
typedef struct stin__translucent_locs {
    GLint kind, matrix, params, maps[2], face_layers;
} stin__translucent_locs;

/* GLSL programs of one tier. */
enum {
    STIN__PROG_LIT = 0,
    STIN__PROG_NORMAL,
    STIN__PROG_FLAT,
    STIN__PROG_VOLUME,
    STIN__PROG_BAND,
    /* shadow-map depth packed into colour (no depth textures: map-pcf) */
    STIN__PROG_PACKED_DEPTH,
    STIN__PROG_COUNT
};
#define STIN__LIGHTS_PER_PASS 8
typedef struct stin__program {
    GLuint name;
    GLint u_model, u_view_proj, u_normal_matrix, u_terminator, u_eye, u_ambient, u_albedo, u_specular,
        u_shininess, u_light_count, u_lights, u_albedo_tex, u_has_albedo_tex, u_color;
    /* the draw's mesh's object lengths of a unit of u and of v
     * (surface_frame.glsl without derivatives) */
    GLint u_uv_unit;
    /* surface chunks (surface/glsl.c): samplers and (scale, bias, min, max steps) */
    GLint u_normal_tex, u_height_tex, u_surface, u_self_shadow;
    /* map-pcf chunk (shadow/map_pcf.c): one sampler, a light's map or a
     * point light's atlas of six faces; the screen mask's chunk reuses them
     * but the area light's spread */
    GLint u_shadow_kind, u_shadow_matrix, u_shadow_params, u_shadow_map, u_shadow_soft;
    GLint u_shadow_depth; /* the mask's depth, for multisampled targets (screen_mask.c) */
    /* the translucent-shadows lookup chunks (translucent/translucent.c): deep's even/odd
     * layers, coloured's transmittance and nearest-depth atlases */
    stin__translucent_locs deep, coloured;
    /* peel chunk (transparency/peel.c): previous layer's depth, opaque depth, params */
    GLint u_peel_previous, u_peel_opaque, u_peel_params;
    stin__displace_locs displace; /* the vertex stage's displacement chunk */
    uint32_t frame_serial;   /* the GLSL path's serial its per-frame uniforms have */
} stin__program;

/* Which draws a pass covers. */
enum { STIN__OPAQUE = 1, STIN__BLENDED = 2, STIN__ALL = 3 };

/* What a lighting path (fixed function or GLSL) offers the frame plan. */
typedef struct stin__path {
    void (*begin)(stin_context *ctx);
    void (*end)(stin_context *ctx);
    /* Ambient light only, depth LESS with writes; colour masked when depth_only. */
    void (*ambient)(stin_context *ctx, int which, int depth_only);
    /* Opaque draws lit by this one light, added with depth EQUAL; the stencil
     * state the shadow technique set applies. */
    void (*lit)(stin_context *ctx, const stin_light_desc *light);
    /* Draws in one colour times the shadow test of `light` where the shader
     * does it (NULL: none), added with depth EQUAL: the visibility output. */
    void (*flat)(stin_context *ctx, int which, const float color[4], const stin_light_desc *light);
    /* Shadow-volume triangles: homogeneous object-space vertices. */
    void (*volume_begin)(stin_context *ctx);
    void (*volume_draw)(stin_context *ctx, const float model[16], const float *xyzw, uint32_t n);
    /* (FrontFace is set by the caller around volume_draw.) */
    void (*volume_end)(stin_context *ctx);
    /* All lights in batches without shadows: the unshadowed beauty. */
    void (*batches)(stin_context *ctx, int which);
    /* World normals as 0.5 + 0.5 n. */
    void (*normals)(stin_context *ctx);
    /* Every draw's depth seen through view_proj (light views, matrices
     * restored after), no materials: shadow-map casters. casters: 0, or
     * STIN__DEPTH_* flags with their solid_min (the fixed-function maps'). */
    void (*depth)(stin_context *ctx, const float view[16], const float proj[16], int casters,
                  float solid_min);
    /* Opaque draws lit by lights[0..n) in one additive pass; light i reads
     * channel i of the screen mask where one is bound (render/screen_mask.c). NULL:
     * the path has no masks (fixed function). */
    void (*lit_lights)(stin_context *ctx, const stin_light_desc *lights, int n);
    /* A draw's geometry alone through the camera, rasterised as the lit
     * passes rasterise it (equal depths), between geometry_begin and _end;
     * the render state is the caller's (csg/goldfeather.c). */
    void (*geometry_begin)(stin_context *ctx);
    void (*geometry)(stin_context *ctx, const stin__draw *d);
    void (*geometry_end)(stin_context *ctx);
    /* One blended draw of "sorted" lit pass by pass, so the shadow technique
     * can test each light (transparency/sorted.c): light NULL is its ambient
     * pass over the frame (SRC_ALPHA / ONE_MINUS_SRC_ALPHA, depth LESS with
     * writes), else that light added at the draw's opacity with depth EQUAL,
     * the technique's test applying as in path->lit. */
    void (*blended_one)(stin_context *ctx, const stin__draw *d, const stin_light_desc *light);
    /* Opaque draws lit by the ambient light and this one light in one pass,
     * depth LESS with writes: the ambient pass and the light's lit pass at
     * once, for a shadow technique that tests the light per fragment of
     * the lit program (frame/frame.c's forward pass). NULL: the path has
     * none (fixed function: its test takes passes of its own). */
    void (*lit_ambient)(stin_context *ctx, const stin_light_desc *light);
    /* The fragments of d's triangles tris[0..3n) (indices into its mesh)
     * in the terminator band of the light at `light` (world position, w 1,
     * or direction toward it, w 0): facet turned away from it, shading
     * normal toward it; the others discarded, depth EQUAL, the stencil
     * state the caller's (shadow/volume.c). Fixed function tells them by
     * triangle on the CPU and by the alpha test (render/terminator_fixed.c). */
    void (*terminator_band)(stin_context *ctx, const stin__draw *d, const float light[4],
                            const uint32_t *tris, uint32_t n);
} stin__path;

const stin__path *stin__fixed_path(void);
stin_result stin__glsl_init(stin_context *ctx, stin_tier tier, char *msg, size_t msg_size);
void stin__glsl_release(stin_context *ctx);
const stin__path *stin__glsl_path(void);
/* A draw's mesh through the bound program, its transform in u_model, its
 * displacement through dl (NULL: the program has no displacement chunk). */
void stin__glsl_submit_geometry(stin_context *ctx, GLint u_model, const stin__displace_locs *dl,
                                const stin__draw *d);
/* Which draws a light's depth pass draws (map-pcf's point-light faces:
 * only the casters whose bounds meet the face's frustum); NULL keeps every
 * caster. */
typedef int (*stin__draw_keep_fn)(const stin_context *ctx, const stin__draw *d, const void *user);
/* The GLSL path's depth pass (path->depth) over the casters keep accepts;
 * returns how many it drew. */
uint32_t stin__glsl_depth_kept(stin_context *ctx, const float view[16], const float proj[16],
                               stin__draw_keep_fn keep, const void *user);
/* The chosen lighting technique's path. */
const stin__path *stin__path_of(const stin_context *ctx);
/* A material checked and its defaults applied, into *out (render/material.c;
 * stin_draw's rules, stin_draw_csg's too); errors are logged as `call`'s,
 * the item `dropped`, and *r holds the result returned. */
stin_result stin__material_prepare(stin_context *ctx, const char *call, const char *dropped,
                                   const stin_material *material, stin_material *out,
                                   stin_result *r);

/* frag_chunks: NULL or a NULL-terminated list of embedded files spliced in
 * at the fragment shader's "// @chunks" line (its functions). The program
 * draws meshes; tessellate as in stin__program_source (draw with
 * stin__displace_primitive). */
GLuint stin__program_build(stin_context *ctx, const char *vert, const char *frag,
                           const char *const *frag_chunks, int tessellate, char *msg,
                           size_t size);
/* The lit program of a surface variant with frag_defines (NULL: the general
 * one) into p, located; 0 on failure (msg). tess: the tessellated twin;
 * layer: with the chunks of a peeled layer (render/path_features.h; the
 * general programs have them). */
int stin__glsl_build_lit(stin_context *ctx, int variant, int tess, int layer,
                         const char *frag_defines, stin__program *p, char *msg, size_t size);
/* The key of a light batch: its count and which parts of the equation its
 * lights need (directional, positional, spot cone, attenuation). */
uint32_t stin__lit_lights_key(const stin_light_desc *lights, int n);
/* Specialised lit programs kept at most (render/lit_specialise.c). */
#define STIN__LIT_CACHE 32
/* The program to shade a draw of surface variant `variant` (its general
 * program `general`) under the batch lights_key, with an albedo texture or
 * not, in a peeled layer or not: the specialised one, built on first use
 * (outside a peeled layer without the peel chunk, whose discard costs the
 * early depth test and whose fetch runs on masked lanes); general where
 * STIN_DEBUG_LIGHTING_GENERAL is set, where every slot served this frame, or
 * where its build failed. */
const stin__program *stin__lit_specialised(stin_context *ctx, const stin__program *general,
                                           int variant, uint32_t lights_key, int albedo_tex);
/* A new frame: slots that served none of it may be replaced. */
void stin__lit_cache_frame(stin_context *ctx);
void stin__lit_cache_release(stin_context *ctx);
/* A pass that bound its own program: the lit program is bound again (and
 * its per-draw uniforms set) before the next lit draw. */
void stin__lit_program_forget(stin_context *ctx);
/* Per-frame lit uniforms changed (a peeled layer's, a mask's): every lit
 * program uploads them again at its next use. */
void stin__lit_uniforms_stale(stin_context *ctx);
/* Swaps the tessellated programs in (on) or out; nothing without them. */
void stin__glsl_tessellate(stin_context *ctx, int on);
/* The tessellated programs are in use (a frame with displaced draws). */
int stin__glsl_tessellated(const stin_context *ctx);
/* The best surface variant whose lit program built (STIN__SURF_*). */
int stin__glsl_best_variant(const stin_context *ctx);
/* Bytes of the GLSL path's private state (render/glsl_private.h; a slot of
 * frame/modules.c). */
size_t stin__glsl_state_bytes(const stin_desc *d);
/* A program's stages by embedded file name: geom NULL for none; frag_outputs
 * names the fragment outputs bound to draw buffers 0, 1, ... (GL 3.0; NULL
 * entries end the list, all NULL: the single output). */
#define STIN__MAX_FRAG_OUTPUTS 3
typedef struct stin__program_source {
    const char *vert, *geom, *frag; /* frag NULL: none (a feedback-only program) */
    const char *const *frag_chunks;
    const char *const *geom_chunks; /* as frag_chunks, for geom */
    /* NULL, or the vertex inputs bound to locations 0, 1, ... in place of
     * the mesh layout's (a_position, a_normal, a_uv, a_tangent) */
    const char *const *attributes;
    /* NULL, or the outputs transform feedback captures, interleaved */
    const char *const *feedback;
    const char *frag_defines; /* NULL or "#define ..." lines after frag's #version */
    const char *frag_outputs[STIN__MAX_FRAG_OUTPUTS];
    /* 1: a program that draws displaced meshes through vert (which has the
     * chunk line): with "displace-tess", vert becomes the tessellation
     * evaluation stage behind gl4/tess.vert and gl4/tess.tesc */
    int tessellate;
} stin__program_source;
GLuint stin__program_build_source(stin_context *ctx, const stin__program_source *src, char *msg,
                                  size_t size);
/* Embedded shader source by file name ("gl2/lit.vert"), NULL if unknown. */
const char *stin__shader_source(const char *name);

#endif
