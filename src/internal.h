/* Internal declarations shared by libstin's source files. */
#ifndef STIN_INTERNAL_H
#define STIN_INTERNAL_H

#include "stin/stin.h"
#include "gl_types.h"
#include "gl_funcs.h"

#include <stdarg.h>

/* ---- GL entry points ---------------------------------------------------- */
enum { NEED_CORE = STIN_CAP_COUNT, NEED_GL30, NEED_COUNT };

typedef enum stin__glfn {
#define STIN_X_(ret, name, params, need, alt) STIN_GLFN_##name,
    STIN_GL_FUNCS(STIN_X_)
#undef STIN_X_
    STIN_GLFN_COUNT
} stin__glfn;

typedef struct stin__gl {
#define STIN_X_(ret, name, params, need, alt) ret(STIN_APIENTRY *name) params;
    STIN_GL_FUNCS(STIN_X_)
#undef STIN_X_
} stin__gl;

/* Resolves every entry point; returns the number that did not resolve.
 * loaded[i] is 1 for each entry point i that did. */
int stin__gl_load(stin__gl *gl, stin_get_proc_fn get_proc, void *user,
                  unsigned char loaded[STIN_GLFN_COUNT]);
const char *stin__glfn_name(stin__glfn fn);
int stin__glfn_need(stin__glfn fn);

/* Calls go through GL(ctx, Name)(args). The checked build first verifies that
 * the capability profile allows the entry point. */
#if defined(STIN_GL_CHECK) && STIN_GL_CHECK
void stin__gl_check_call(struct stin_context *ctx, stin__glfn fn);
void stin__gl_check_enum(struct stin_context *ctx, stin__glfn fn, GLenum e);
#define GL(ctx, name) (stin__gl_check_call((ctx), STIN_GLFN_##name), (ctx)->gl.name)
#define GL_ENUM(ctx, name, e) (stin__gl_check_enum((ctx), STIN_GLFN_##name, (e)), (ctx)->gl.name)
#else
#define GL(ctx, name) ((ctx)->gl.name)
#define GL_ENUM(ctx, name, e) ((void)(e), (ctx)->gl.name)
#endif
/* glEnable/glDisable and friends take an enum whose capability is audited. */
#define GL_ENABLE(ctx, e) GL_ENUM(ctx, Enable, e)(e)
#define GL_DISABLE(ctx, e) GL_ENUM(ctx, Disable, e)(e)
/* In checked builds, GL errors after a pass are logged and counted. */
void stin__gl_check_errors(struct stin_context *ctx, const char *where);

/* ---- logging ------------------------------------------------------------ */
void stin__log(struct stin_context *ctx, stin_log_level level, stin_log_item item,
               const char *fmt, ...);
void stin__logv(stin_log_fn fn, void *user, stin_log_level level, stin_log_item item,
                const char *fmt, va_list ap);
/* A small formatter (%s %d %u %x %lu %zu %f %%) that never touches the heap. */
size_t stin__format(char *buf, size_t size, const char *fmt, va_list ap);
size_t stin__formatf(char *buf, size_t size, const char *fmt, ...);

/* ---- memory ------------------------------------------------------------- */
typedef struct stin__arena {
    unsigned char *base;
    size_t size, used;
} stin__arena;
/* Bump allocation aligned to 16 bytes; NULL when the arena is exhausted. */
void *stin__arena_alloc(stin__arena *a, size_t bytes);
size_t stin__align16(size_t n);
void stin__memzero(void *p, size_t n);
void stin__memcopy(void *dst, const void *src, size_t n);

/* First-fit allocator of element ranges in a fixed store (vertices, triangles). */
typedef struct stin__range {
    uint32_t offset, count;
} stin__range;
typedef struct stin__range_alloc {
    stin__range *used; /* sorted by offset */
    uint32_t used_count, max_ranges;
    uint32_t capacity;
} stin__range_alloc;
void stin__range_init(stin__range_alloc *r, stin__range *storage, uint32_t max_ranges,
                      uint32_t capacity);
/* Returns 1 and the offset on success, 0 when no gap is large enough. */
int stin__range_take(stin__range_alloc *r, uint32_t count, uint32_t *offset);
void stin__range_give(stin__range_alloc *r, uint32_t offset);

/* ---- capabilities ------------------------------------------------------- */
/* Parses what the driver reports; pure so that unit tests feed recorded strings. */
typedef struct stin__caps_input {
    const char *version;        /* GL_VERSION */
    const char *glsl_version;   /* GL_SHADING_LANGUAGE_VERSION or NULL */
    const char *extensions;     /* GL_EXTENSIONS (space separated) or NULL */
    const char *(*extension_at)(void *user, int i); /* 3.0+: glGetStringi, or NULL */
    void *extension_user;
    int extension_count;
    int core_profile;
    int max_gl_version;         /* 0 = as reported */
    uint64_t caps_mask;
    const unsigned char *loaded; /* per stin__glfn, NULL = all loaded */
} stin__caps_input;

/* Fills version, GLSL version, profile and the present/hidden bits. Limits are
 * left untouched. Returns 0 if GL_VERSION does not parse. */
int stin__caps_parse(const stin__caps_input *in, stin_caps *out);
stin_result stin__caps_detect(const stin__gl *gl, const unsigned char *loaded,
                              uint64_t caps_mask, int max_gl_version, stin_caps *caps);
/* Exact match of one token in a space-separated list. */
int stin__token_in_list(const char *list, const char *token, size_t token_len);

/* ---- selection ---------------------------------------------------------- */
typedef struct stin__selection {
    stin_tier tier;
    stin_choice choice[STIN_FEATURE_COUNT];
} stin__selection;

/* Chooses the tier and one technique per feature. Fails (UNSUPPORTED) if a
 * forced tier or technique cannot run; writes the reason into msg. */
stin_result stin__select(const stin_caps *caps, stin_tier forced,
                         const stin_technique forced_tech[STIN_FEATURE_COUNT],
                         stin__selection *out, char *msg, size_t msg_size);
/* Capabilities a technique needs (STIN_CAP_BIT mask). */
uint64_t stin__technique_needs(stin_technique t);
stin_feature stin__technique_feature(stin_technique t);
stin_tier stin__technique_tier(stin_technique t);
/* The lighting technique a technique runs on top of (STIN_TECH_NONE: any;
 * STIN_TECH_LIGHTING_GLSL110: any GLSL lighting). */
stin_technique stin__technique_lighting(stin_technique t);
/* 1 when technique t can run with this lighting technique. */
int stin__technique_runs_with(stin_technique t, stin_technique lighting);
/* One feature's chain walk (stin__select does all features). */
stin_result stin__choose(const stin_caps *caps, stin_tier tier, stin_feature f,
                         stin_technique forced, stin_technique lighting, stin_choice *out,
                         char *msg, size_t msg_size);
uint64_t stin__tier_needs(stin_tier t);
/* Names of the bits in `bits`, comma separated. */
void stin__cap_names(uint64_t bits, char *out, size_t size);

/* ---- math --------------------------------------------------------------- */
void stin__mat4_identity(float m[16]);
void stin__mat4_mul(float out[16], const float a[16], const float b[16]);
int stin__mat4_invert(float out[16], const float m[16]);
/* Upper 3x3 of the inverse transpose, for normals. */
void stin__mat3_normal(float out[9], const float m[16]);
void stin__mat4_transform_point(const float m[16], const float p[3], float out[3]);
float stin__sqrtf(float x);
float stin__cos_deg(float degrees);
int stin__isfinite(float x);

/* ---- meshes and textures ------------------------------------------------ */
typedef struct stin__vertex {
    float position[3];
    float normal[3];
    float uv[2];
    float tangent[4];
} stin__vertex;

typedef struct stin__mesh_slot {
    uint32_t generation;
    int alive;
    uint32_t first_vertex, vertex_count;
    uint32_t first_triangle, triangle_count;
    stin_mesh_info info;
    GLuint vbo, ibo, vao;
} stin__mesh_slot;

typedef struct stin__texture_slot {
    uint32_t generation;
    int alive;
    stin_texture_kind kind;
    uint32_t width, height;
    GLuint name;
} stin__texture_slot;

/* ---- frame -------------------------------------------------------------- */
typedef struct stin__draw {
    uint32_t mesh_slot;
    float transform[16];
    stin_material material;
    float sort_depth;  /* eye-space distance of the bounds centre, for blending order */
} stin__draw;

typedef enum stin__frame_state { STIN__IDLE = 0, STIN__IN_FRAME } stin__frame_state;

/* GLSL programs of one tier. */
enum { STIN__PROG_LIT = 0, STIN__PROG_NORMAL, STIN__PROG_FLAT, STIN__PROG_VOLUME, STIN__PROG_COUNT };
#define STIN__LIGHTS_PER_PASS 8
typedef struct stin__program {
    GLuint name;
    GLint u_model, u_view_proj, u_normal_matrix, u_eye, u_ambient, u_albedo, u_specular,
        u_shininess, u_light_count, u_lights, u_albedo_tex, u_has_albedo_tex, u_color;
    /* surface chunks (surface_glsl.c): samplers and (scale, bias, min, max steps) */
    GLint u_normal_tex, u_height_tex, u_surface, u_self_shadow;
    /* map-pcf chunk (shadow_map_glsl.c) */
    GLint u_shadow_kind, u_shadow_matrix, u_shadow_params, u_shadow_maps[6];
    uint32_t frame_serial;   /* ctx->glsl_surface.serial its per-frame uniforms have */
} stin__program;

/* GLSL surface variants of the lit program: one program each (surface_glsl.c). */
enum { STIN__SURF_PLAIN = 0, STIN__SURF_NORMAL, STIN__SURF_PARALLAX, STIN__SURF_POM,
       STIN__SURF_COUNT };
#define STIN__SURF_LOG_KEYS 32

struct stin_context {
    stin_desc desc;           /* with defaults applied */
    stin__gl gl;
    unsigned char gl_loaded[STIN_GLFN_COUNT];
    stin_caps caps;
    stin__selection sel;
    uint32_t gl_violations;   /* checked build: calls the profile does not allow */
    uint32_t gl_errors;       /* checked build: glGetError results */

    stin__mesh_slot *meshes;
    stin__texture_slot *textures;
    stin__vertex *vertices;   /* max_vertices */
    uint32_t *indices;        /* 3 * max_triangles */
    uint32_t *adjacency;      /* 3 * max_triangles */
    stin__range_alloc vertex_ranges, triangle_ranges;
    stin__range *vertex_range_store, *triangle_range_store;
    unsigned char *scratch;   /* mesh creation: weld and edge tables */
    size_t scratch_bytes;
    unsigned char *staging;   /* texture creation */
    size_t staging_bytes;

    stin__draw *draws;
    uint32_t *draw_order;
    stin_light_desc *lights;
    uint32_t draw_count, light_count;
    stin_frame_desc frame;
    stin__frame_state state;
    stin_frame_stats stats;

    stin__program programs[STIN__PROG_COUNT];
    uint32_t bound_mesh;      /* mesh slot whose arrays are bound, UINT32_MAX = none */
    float projection[16];     /* what the frame draws with (P_inf for volumes) */
    int pcf_kind;             /* the shadow test of the lit pass being drawn (map-pcf) */
    uint32_t pcf_light;
    float view_proj[16];
    int volume_depth_clamp;   /* volumes drawn with GL_DEPTH_CLAMP */
    int volume_infinite;      /* projection moved the far plane to infinity */
    GLuint volume_vbo, volume_vao; /* GL4: streamed volume vertices */
    struct {
        GLuint textures[38];  /* per light slot, then 6 shared cube faces for point lights */
        GLuint ramp;          /* map-combine: 1D ramp of light depth */
        GLuint fbo;           /* with FBOs: render straight into the texture */
        GLuint depth_scratch; /* map-combine with FBOs: the depth buffer of its pass */
        uint32_t size;        /* allocated texels a side */
        uint32_t used;        /* rendered this frame (no FBO: bounded by the viewport) */
        int unit;             /* first texture unit of the shadow test */
        unsigned char valid[38];
        float texgen[38][16]; /* world -> shadow-map texture coordinates (rows s t r q) */
        float ramp_plane[38][4]; /* world -> ramp coordinate (map-combine) */
        int faces;            /* point lights get six maps (needs FBOs: drawn mid-frame) */
        GLuint face_mask;     /* 1 inside a face's 90-degree square, 0 outside */
        int face_active;
        int said_point, said_area;
    } maps;
    int lights_per_pass;
    struct {
        /* lit programs per surface variant; [STIN__SURF_PLAIN] is unused (the
         * plain one is programs[STIN__PROG_LIT]) */
        stin__program lit[STIN__SURF_COUNT];
        int best;             /* best variant built (STIN__SURF_*) */
        const stin__program *current; /* lit program in use this pass, NULL = other */
        uint32_t serial;      /* bumped when the per-frame lit uniforms change */
        float packed[4 * 4 * STIN__LIGHTS_PER_PASS]; /* the lights last uploaded */
        int light_n, with_ambient;
        int units_bound;      /* units 1-2 hold textures this frame */
        uint32_t logged[STIN__SURF_LOG_KEYS]; /* per-material step-downs already logged */
        uint32_t logged_count;
    } glsl_surface;
    struct {
        GLuint cube;          /* normalisation cube map; 0 = DOT3 not in use */
        GLenum dot3_rgb;      /* GL_DOT3_RGB (1.3/ARB) or GL_DOT3_RGB_EXT */
        int units;            /* texture units (3 without an albedo texture, 4 with) */
        int warned_scratch;   /* a mesh too big for the scratch was logged */
    } dot3;
};

stin_desc stin__desc_defaults(const stin_desc *desc);

/* Mesh internals. */
stin__mesh_slot *stin__mesh_lookup(const stin_context *ctx, stin_mesh mesh, uint32_t *slot);
void stin__mesh_release_all(stin_context *ctx);
void stin__texture_release_all(stin_context *ctx);
stin__texture_slot *stin__texture_lookup(const stin_context *ctx, stin_texture tex);

/* Points attributes 0..3 (position, normal, uv, tangent) at base (NULL with a VBO bound). */
void stin__mesh_bind_attributes(stin_context *ctx, const stin__vertex *base);
/* Adjacency over position-welded vertices; fills info's edge counts. */
stin_result stin__mesh_adjacency_build(stin_context *ctx, const stin__vertex *verts,
                                       uint32_t vertex_count, const uint32_t *tris,
                                       uint32_t tri_count, uint32_t *adjacency,
                                       stin_mesh_info *info);
/* Bytes of scratch the adjacency build needs for these sizes. */
size_t stin__adjacency_scratch_bytes(uint32_t vertex_count, uint32_t tri_count);
/* Per-vertex tangents (Gram-Schmidt, handedness in w); uses scratch. */
void stin__mesh_tangents(stin__vertex *verts, uint32_t vertex_count, const uint32_t *tris,
                         uint32_t tri_count, float *scratch_bitangents, int have_uvs);
void stin__mesh_default_normals(stin__vertex *verts, uint32_t vertex_count,
                                const uint32_t *tris, uint32_t tri_count);

/* ---- shadow volumes ----------------------------------------------------- */
/* clockwise: the triangles are wound clockwise toward their outside (front
 * face CW for this batch). */
typedef void (*stin__volume_sink)(void *user, const float *xyzw, uint32_t vertex_count,
                                  int clockwise);
typedef struct stin__volume_request {
    const stin__vertex *verts;
    const uint32_t *tris, *adjacency;
    uint32_t tri_count;
    int closed;            /* classic volume of a closed 2-manifold caster */
    int caps;              /* light and dark caps (z-fail) */
    float light[4];        /* object space; w = 1 point, w = 0 directional (toward the light) */
    float *buffer;         /* chunk of 4-float vertices */
    uint32_t buffer_vertices;
    unsigned char *facing; /* tri_count bytes of scratch */
    stin__volume_sink sink;
    void *user;
} stin__volume_request;
/* Emits the volume through r->sink; returns the triangles emitted. */
uint32_t stin__volume_build(const stin__volume_request *r);
int stin__triangle_faces_light(const float *a, const float *b, const float *c, const float l[4]);

/* ---- passes ------------------------------------------------------------- */
/* Which draws a pass covers. */
enum { STIN__OPAQUE = 1, STIN__BLENDED = 2, STIN__ALL = 3 };

/* What a lighting path (fixed function or GLSL) offers the pass schedule. */
typedef struct stin__path {
    void (*begin)(stin_context *ctx);
    void (*end)(stin_context *ctx);
    /* Ambient light only, depth LESS with writes; colour masked when depth_only. */
    void (*ambient)(stin_context *ctx, int which, int depth_only);
    /* Opaque draws lit by this one light, added with depth EQUAL; the stencil
     * state the caller set applies. */
    void (*lit)(stin_context *ctx, const stin_light_desc *light);
    /* Draws in one colour, added with depth EQUAL (the visibility output). */
    void (*flat)(stin_context *ctx, int which, const float color[4]);
    /* Shadow-volume triangles: homogeneous object-space vertices. */
    void (*volume_begin)(stin_context *ctx);
    void (*volume_draw)(stin_context *ctx, const float model[16], const float *xyzw, uint32_t n);
    /* (FrontFace is set by the caller around volume_draw.) */
    void (*volume_end)(stin_context *ctx);
    /* All lights in batches without shadows: the unshadowed beauty. */
    void (*batches)(stin_context *ctx, int which);
    /* World normals as 0.5 + 0.5 n. */
    void (*normals)(stin_context *ctx);
} stin__path;

stin_result stin__fixed_init(stin_context *ctx);
const stin__path *stin__fixed_path(void);
stin_result stin__glsl_init(stin_context *ctx, stin_tier tier, char *msg, size_t msg_size);
void stin__glsl_release(stin_context *ctx);
const stin__path *stin__glsl_path(void);
/* One light (sample) of stencil shadow volumes: leaves the stencil test set to
 * pass where the light is visible. */
void stin__volume_light(stin_context *ctx, const stin__path *path, const float light_world[4],
                        const int scissor[4]);
/* Everything that differs per frame for shadow volumes is chosen here. */
void stin__volume_frame_setup(stin_context *ctx);
/* Light cameras for shadow maps (shadow_light_camera.c). */
void stin__light_look_along(float m[16], const float eye[3], const float dir[3]);
void stin__light_fit(const stin_context *ctx, const float view[16], int receivers_only,
                     float *near_d, float *far_d, float *half_width, float center_out[3]);
void stin__light_perspective(float m[16], float fovy_deg, float n, float f);
/* The view and projection of a spot or directional light and the depth range
 * [n, f] it spans; 0 for a point light or when nothing is in front. map_size
 * snaps a directional map to whole texels (0: no snapping). */
int stin__light_camera(const stin_context *ctx, const stin_light_desc *l, float view[16],
                       float proj[16], float *n, float *f, uint32_t map_size);

/* GLSL shadow maps with PCF (shadow_map_glsl.c). */
int stin__pcf_active(const stin_context *ctx);
stin_result stin__pcf_init(stin_context *ctx);
/* Maps of every spot and directional light (before the camera's passes). */
void stin__pcf_render(stin_context *ctx);
/* A point light's six faces, just before its pass; 1 if drawn. */
int stin__pcf_point(stin_context *ctx, uint32_t light);
/* The shadow test's uniforms for program p: kind 0 none, 1 light's map, 2 faces. */
void stin__pcf_apply(stin_context *ctx, const stin__program *p, int kind, uint32_t light);
/* Every draw's depth with the volume program (path_glsl.c): shadow maps. */
void stin__glsl_draw_depth(stin_context *ctx, const float view_proj[16]);

/* Fixed-function shadow maps (shadow_map_fixed.c). */
int stin__maps_active(const stin_context *ctx);
stin_result stin__maps_init(stin_context *ctx);
void stin__maps_release(stin_context *ctx);
/* Renders every spot and directional light's map (before the camera's clear). */
void stin__maps_render(stin_context *ctx);
/* 1 if light i has a map this frame; binds its test onto the shadow units. */
int stin__maps_bind(stin_context *ctx, uint32_t light);
void stin__maps_unbind(stin_context *ctx);
/* Point lights with FBOs: renders cube face f (0..5: +x -x +y -y +z -z) of
 * light i into the shared face map, binds its test and clips drawing to the
 * face's frustum. 0 when the face sees nothing. stin__maps_face_end undoes it. */
int stin__maps_face(stin_context *ctx, uint32_t light, int face);
void stin__maps_face_end(stin_context *ctx);
/* Draws every draw's geometry with the current projection and ctx->frame.view
 * (path_fixed.c), no materials: shadow-map casters. */
void stin__fixed_draw_geometry(stin_context *ctx);
/* Screen rectangle a light of finite range can touch; 0 when unbounded. */
int stin__light_scissor(const stin_context *ctx, const stin_light_desc *l, int out[4]);
/* ---- surface: DOT3 bump mapping on the fixed-function path (surface_dot3.c) ----
 * Draws whose material has a normal map get their diffuse term per pixel from
 * the normal map; the fixed-function passes keep their ambient and specular
 * (set_material blacks out their diffuse through stin__dot3_material). */
/* Creates the cube map when the technique is selected; a context without the
 * texture units or staging falls back to plain (an error if it was forced). */
stin_result stin__dot3_init(stin_context *ctx);
void stin__dot3_release(stin_context *ctx);
/* 1 when this (opaque) material is drawn with DOT3 in the lit passes. */
int stin__dot3_bumped(const stin_context *ctx, const stin_material *m);
/* Called by the fixed path's set_material: diffuse off for bumped materials. */
void stin__dot3_material(stin_context *ctx, const stin_material *m);
/* Adds the DOT3 diffuse of the opaque bumped draws for the GL lights
 * 0..count-1 (set up as lights[0..count-1]), one additive pass per light
 * (depth EQUAL), under the caller's stencil test and scissor; the stencil
 * operations are KEEP meanwhile, so a caller that increments where it lights
 * calls this before its own draws of the same light. */
void stin__dot3_lights(stin_context *ctx, const stin_light_desc *lights, int count);
/* As stin__dot3_lights for light batch `batch` of fixed_batches, whose lights
 * set_batch has just set up; restores the batch's scene ambient. */
void stin__dot3_batch(stin_context *ctx, int batch);
/* Per-vertex tangent-space light vectors (xyz, unnormalised) and the normal
 * that points the fixed-function lighting at the light (xyz), 6 floats a
 * vertex, for an object with transform `model` and a light at light_world
 * (w = 1 point, w = 0 direction toward the light). */
void stin__dot3_light_vectors(const stin__vertex *v, uint32_t n, const float model[16],
                              const float light_world[4], float *out);
/* Direction of the cube-map face (0..5 = +X -X +Y -Y +Z -Z) at texture
 * coordinates (s, t), unnormalised; and a face as RGBA8 0.5 + 0.5 n. */
void stin__dot3_cube_direction(int face, float s, float t, float out[3]);
void stin__dot3_cube_face(int face, uint32_t size, unsigned char *rgba);

/* ---- surface: GLSL normal / parallax / POM chunks (surface_glsl.c) --------
 * The lit program is built once per surface variant, from the context's
 * surface choice down to plain; a variant that fails to build lowers the
 * best one (logged). */
/* Variant of a technique (plain for dot3/plain/none). */
int stin__surf_variant_of(stin_technique t);
stin_technique stin__surf_technique_of(int variant);
/* The chunk files of a variant for directory dir ("gl2/"): writes up to 3
 * names into names (each 40 bytes) and a NULL-terminated list into list,
 * shadow_chunk last. */
void stin__surf_chunks(int variant, const char *dir, const char *shadow_chunk,
                       char names[3][40], const char *list[4]);
/* The variant a draw's material gets (logs a step down once per material). */
int stin__surf_variant_for(stin_context *ctx, const stin_material *m);
/* Uniform locations of the surface chunks. */
void stin__surf_locate(stin_context *ctx, stin__program *p);
/* Sampler units (once per program use). */
void stin__surf_units(stin_context *ctx, const stin__program *p);
/* Per-draw: binds the normal and height maps to units 1 and 2, uploads the
 * material's height scale, bias, steps and self-shadow mode. */
void stin__surf_material(stin_context *ctx, const stin__program *p, const stin_material *m,
                         int variant);
/* Unbinds units 1 and 2 after a frame that bound them; unit 0 active. */
void stin__surf_unbind(stin_context *ctx);

/* Restores the GL state the header promises after a frame. */
void stin__state_restore(stin_context *ctx);
/* frag_chunks: NULL or a NULL-terminated list of embedded files spliced in
 * at the fragment shader's "// @chunks" line (its functions). */
GLuint stin__program_build(stin_context *ctx, const char *vert, const char *frag,
                           const char *const *frag_chunks, char *msg, size_t size);
/* Embedded shader source by file name ("gl2/lit.vert"), NULL if unknown. */
const char *stin__shader_source(const char *name);

#endif
