/* SPDX-License-Identifier: MIT */
/* Meshes and textures in the caller's block (mesh*.c, assets/texture.c) and the
 * shadow-volume geometry built from them (shadow/volume_geometry.c). */
#ifndef STIN_MESH_STORE_H
#define STIN_MESH_STORE_H

#include "stin/stin.h"
#include "gl/gl_types.h"


/* ---- meshes and textures ------------------------------------------------ */
/* The head of every pooled slot (base/handle_pool.c). */
typedef struct stin__handle {
    uint32_t generation;
    int alive;
    int retired;          /* its generation reached the top: never issued again */
} stin__handle;
#define STIN__NO_SLOT 0xffffffffu
/* The context's 8-bit handle tag from its creation serial in the block and
 * the block's address. */
uint32_t stin__handle_tag(uint32_t serial, const void *block);
/* The first free slot of a pool of `count` slots `stride` bytes apart. */
uint32_t stin__handle_free_slot(const stin__handle *first, size_t stride, uint32_t count);
/* Marks slot h (index `slot` of `count`) alive with a new generation; returns its id. */
uint32_t stin__handle_issue(stin__handle *h, uint32_t slot, uint32_t count, uint32_t tag);
/* Marks h free, or retired when its generation cannot grow. */
void stin__handle_release(stin__handle *h, uint32_t count);
/* The slot a handle id names while it is alive, else STIN__NO_SLOT. */
uint32_t stin__handle_resolve(const stin__handle *first, size_t stride, uint32_t count,
                              uint32_t tag, uint32_t id);

typedef struct stin__vertex {
    float position[3];
    float normal[3];
    float uv[2];
    float tangent[4];
} stin__vertex;

/* A run of a mesh's triangles drawn with 16-bit indices of its own
 * (assets/mesh_chunks.c): its triangles, and its vertices in the vertex
 * buffer (the chunks' copies one after another). */
typedef struct stin__index_chunk {
    uint32_t first_triangle, triangle_count;
    uint32_t first_vertex, vertex_count;
} stin__index_chunk;
/* The most vertices a 16-bit chunk holds (indices 0 to 65,534). */
#define STIN__CHUNK_VERTICES 65535u

typedef struct stin__mesh_slot {
    stin__handle handle;
    uint32_t first_vertex, vertex_count;
    uint32_t first_triangle, triangle_count;
    stin_mesh_info info;
    GLuint vbo, ibo, vao;
    GLuint adj_ibo, adj_vao;  /* GL_TRIANGLES_ADJACENCY indices (0: none; vdsm, GL4 volumes) */
    float uv_edge;            /* mean uv length of its edges (displacement's coarse log) */
    float edge;               /* mean object-space length of its edges (uv_edge / edge:
                               * displacement's uv per unit, its mip level) */
    float uv_unit[2];         /* mean object length of a unit of u, of v (surface
                               * detail without derivatives) */
    int smooth;               /* some triangle's vertex normals bend away from its
                               * facet: the terminator rule applies (stin__mesh_smooth) */
    /* what stin_update_mesh needs of the creation: the caller's vertex
     * count (before subdivision), the levels, whether uvs were given (the
     * tangents follow them), and one closed piece (convex's Euler test) */
    uint32_t source_vertices, subdivide;
    int has_uvs, one_piece;
    int dynamic;              /* updated once: its vertex buffer is GL_DYNAMIC_DRAW */
    /* its element buffer's index type: GL_UNSIGNED_INT, or GL_UNSIGNED_SHORT
     * without STIN_CAP_ELEMENT_INDEX_UINT (where buffers exist), then in
     * chunk_count chunks (1: the whole mesh, its vertex buffer as stored) */
    GLenum index_type;
    uint32_t chunk_count;
    stin__index_chunk *chunks; /* its row of ctx->index_chunks */
} stin__mesh_slot;

typedef struct stin__texture_slot {
    stin__handle handle;
    stin_texture_kind kind;
    uint32_t width, height;
    GLuint name;
    /* height maps where displacement is built: a second texture with the
     * mip chain (name keeps level 0 only, which the parallax march needs),
     * and its highest level; 0 when there is none */
    GLuint lod_name;
    uint32_t lod_top;
} stin__texture_slot;


stin__mesh_slot *stin__mesh_lookup(const stin_context *ctx, stin_mesh mesh, uint32_t *slot);
void stin__mesh_release_all(stin_context *ctx);
/* stin's own mesh: the slot after the caller's (index desc.max_meshes), its
 * vertices and triangles after theirs in the block, no handle; made at
 * stin_create by whoever needs it (CSG's near-plane cap), released with the
 * caller's. Never a shadow caster. */
#define STIN__BUILTIN_VERTICES 4u
#define STIN__BUILTIN_TRIANGLES 2u
uint32_t stin__mesh_builtin(stin_context *ctx, const stin__vertex *v, uint32_t vertex_count,
                            const uint32_t *tris, uint32_t tri_count);
void stin__texture_release_all(stin_context *ctx);
stin__texture_slot *stin__texture_lookup(const stin_context *ctx, stin_texture tex);

/* Points attributes 0..3 (position, normal, uv, tangent) at base (NULL with a VBO bound). */
void stin__mesh_bind_attributes(stin_context *ctx, const stin__vertex *base);
/* Adjacency over position-welded vertices (weld_tolerance as in
 * stin_mesh_desc; welded positions are snapped); fills info's edge counts,
 * welded_vertices and convex, welds (the vertex each was welded onto) and
 * one_piece (V - E + F = 2 over welded positions). */
stin_result stin__mesh_adjacency_build(stin_context *ctx, stin__vertex *verts,
                                       uint32_t vertex_count, float weld_tolerance,
                                       const uint32_t *tris, uint32_t tri_count,
                                       uint32_t *adjacency, uint32_t *welds,
                                       stin_mesh_info *info, int *one_piece);
/* 1 when a shared edge (adjacency) bends concave, each pair tested once
 * from its lower half-edge (stin_mesh_info.convex). */
int stin__mesh_concave_edge(const stin__vertex *verts, const uint32_t *tris,
                                  const uint32_t *adjacency, const uint32_t *welds,
                                  uint32_t tri_count);
/* The shape's derived data from the mesh's stored vertices (after
 * normals, tangents and welds): bounds, the terminator rule's smooth flag
 * and the mean edge lengths (the uv one too where uvs_changed). */
void stin__mesh_derive(stin_context *ctx, stin__mesh_slot *m, int uvs_changed);
/* 1 when all n floats of v (NULL: none) are finite, else 0 with the first
 * bad index in *bad. */
int stin__mesh_finite(const float *v, uint32_t n, uint32_t *bad);
/* Normals: given ones normalised (a zero one: all face-derived), else
 * area-weighted face normals. */
void stin__mesh_fix_normals(stin__vertex *v, uint32_t n, const uint32_t *tris,
                            uint32_t tri_count, int given);
/* The vertex buffer again from the arena (GL_DYNAMIC_DRAW once m->dynamic),
 * where the context has buffer objects. */
void stin__mesh_upload_vertices(stin_context *ctx, stin__mesh_slot *m);
/* weld[i] = the first vertex within `tolerance` of vertex i (see
 * stin_mesh_desc.weld_tolerance), using `table` (size a power of two at least
 * 2 n) as scratch; moves welded positions onto it and returns how many moved. */
uint32_t stin__weld_positions(stin__vertex *verts, uint32_t n, float tolerance, uint32_t *weld,
                              uint32_t *table, uint32_t size);
/* The integer hash welding and adjacency use. */
uint32_t stin__weld_mix(uint32_t h);
/* Bytes of scratch the adjacency build needs for these sizes. */
size_t stin__adjacency_scratch_bytes(uint32_t vertex_count, uint32_t tri_count);
/* The mean object length of a unit of u (out[0]) and of v (out[1]) over
 * the triangles whose uvs have a gradient; 1 where none has. */
void stin__mesh_uv_units(const stin__vertex *verts, const uint32_t *tris, uint32_t tri_count,
                         float out[2]);

/* Per-vertex tangents (Gram-Schmidt, handedness in w); uses scratch. */
void stin__mesh_tangents(stin__vertex *verts, uint32_t vertex_count, const uint32_t *tris,
                         uint32_t tri_count, float *scratch_bitangents, int have_uvs);
/* Subdivision (assets/mesh_subdivide.c): the vertex and triangle counts after
 * `levels` levels (CAPACITY when the edge table exceeds the scratch or a
 * count overflows), and the subdivision itself in place: verts and tris
 * have room for those counts. */
stin_result stin__subdivide_counts(struct stin_context *ctx, const uint32_t *tris,
                                   uint32_t tri_count, uint32_t vertex_count, uint32_t levels,
                                   size_t scratch_limit, uint32_t *out_vertices,
                                   uint32_t *out_triangles);
void stin__subdivide(struct stin_context *ctx, stin__vertex *verts, uint32_t vertex_count,
                     uint32_t *tris, uint32_t tri_count, uint32_t levels);
/* The midpoint vertices of an already subdivided mesh made again from its
 * source vertices (stin_update_mesh): read from the subdivided triangles'
 * order, no scratch. */
void stin__subdivide_again(stin__vertex *verts, const uint32_t *tris, uint32_t tri_count,
                           uint32_t levels);
/* Mean uv length (uv_edge NULL: not wanted) and mean object-space length
 * of the triangles' edges. */
void stin__mesh_mean_edges(const stin__vertex *verts, const uint32_t *tris, uint32_t tri_count,
                           float *uv_edge, float *edge);
/* 1 when a corner's normal leaves its triangle's facet normal by more than
 * the terminator rule's 1e-6 of the cosine (stin.h, "The terminator rule"). */
int stin__mesh_smooth(const stin__vertex *verts, const uint32_t *tris, uint32_t tri_count);
void stin__mesh_default_normals(stin__vertex *verts, uint32_t vertex_count,
                                const uint32_t *tris, uint32_t tri_count);

/* A mesh's triangles with their neighbours' far vertices (adj_ibo, drawn
 * through adj_vao), for vdsm's light pass and GL4's volume extrusion
 * (assets/mesh_adjacency_buffer.c): made at mesh creation where the shadows
 * module's set-up asked for them, deleted with the mesh. use: from now on
 * meshes get them (without: what one that cannot gets, for the log; NULL:
 * none do), so this layer need not know which technique reads them. */
void stin__mesh_adjacency_use(struct stin_context *ctx, const char *without);
void stin__mesh_adjacency_buffer_upload(struct stin_context *ctx, stin__mesh_slot *m);
void stin__mesh_adjacency_buffer_release(struct stin_context *ctx, stin__mesh_slot *m);

/* 16-bit indices (assets/mesh_chunks.c). The most chunks a mesh of
 * max_mesh_triangles may need (the row of ctx->index_chunks each slot has). */
uint32_t stin__index_chunks_max(uint32_t max_mesh_triangles);
/* Splits tris (tri_count, over vertex_count vertices) into chunks of at
 * most `limit` vertices each, greedily in triangle order; stamp and local:
 * vertex_count entries of scratch each. Returns the chunks written to out,
 * 0 when more than max_out would be needed. */
uint32_t stin__index_split(const uint32_t *tris, uint32_t tri_count, uint32_t vertex_count,
                           uint32_t limit, uint32_t *stamp, uint32_t *local,
                           stin__index_chunk *out, uint32_t max_out);
/* Chunk `chunk`'s local indices (3 per triangle) and, per local vertex, the
 * mesh vertex it copies (src), either NULL to skip; stamp_id: a value no
 * earlier chunk of this pass used (stamp zeroed before the pass's first). */
void stin__index_chunk_fill(const uint32_t *tris, const stin__index_chunk *chunk,
                            uint32_t stamp_id, uint32_t *stamp, uint32_t *local,
                            uint16_t *indices, uint32_t *src);
/* Decides m's index type and chunks (row: its table row) before upload;
 * CAPACITY when the creation scratch cannot hold the split. */
stin_result stin__mesh_index_plan(struct stin_context *ctx, stin__mesh_slot *m,
                                  stin__index_chunk *row);
/* m's indices into the bound element buffer, in its index type. */
void stin__mesh_index_data(struct stin_context *ctx, const stin__mesh_slot *m);
/* A chunked mesh's vertices into the bound array buffer (1), or 0 when m is
 * not chunked and its stored vertices are the buffer's. */
int stin__mesh_chunked_vertices(struct stin_context *ctx, const stin__mesh_slot *m, GLenum usage);
/* Points the draw's vertex attributes at base (a buffer offset). */
typedef void (*stin__rebase_fn)(struct stin_context *ctx, const stin__vertex *base);
/* All of m's triangles from the bound element buffer (client_indices: the
 * arena's, without buffers), chunk by chunk where it is split: rebase moves
 * the attributes to each chunk's vertices and back to the first after
 * (NULL: the caller cannot, the whole index range is drawn). */
void stin__mesh_draw(struct stin_context *ctx, const stin__mesh_slot *m, GLenum mode,
                     const void *client_indices, stin__rebase_fn rebase);

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
    /* object space: the plane the volume is cut at (far points on it), or
     * (0, 0, 0, -1): far points at infinity */
    float far_plane[4];
    float *buffer;         /* chunk of 4-float vertices */
    uint32_t buffer_vertices;
    unsigned char *facing; /* tri_count bytes of scratch */
    stin__volume_sink sink;
    void *user;
} stin__volume_request;
/* Emits the volume through r->sink; returns the triangles emitted. */
uint32_t stin__volume_build(const stin__volume_request *r);
int stin__triangle_faces_light(const float *a, const float *b, const float *c, const float l[4]);

/* The caller's bindings around stin's uploads and draws (gl/caller_bindings.c).
 * vao_begin binds vertex array 0 where there are VAOs, so buffer and
 * pointer calls do not land in the caller's; it returns the caller's,
 * which vao_end binds again. unpack_begin makes rows tight (alignment 1,
 * no row length or skips, no pixel unpack buffer); unpack_end restores.
 * pack_begin and pack_end do the same for read-backs into client memory. */
GLuint stin__vao_begin(struct stin_context *ctx);
void stin__vao_end(struct stin_context *ctx, GLuint saved);
#define STIN__UNPACK_STORE 4
#define STIN__PIXEL_TRANSFER 14
typedef struct stin__unpack_saved {
    GLint store[STIN__UNPACK_STORE]; /* alignment, row length, skip rows, skip pixels */
    GLint buffer;                    /* the bound pixel unpack (pack) buffer */
    /* a compatibility context's pixel transfer (scales, biases, maps, index
     * shift and offset), which scales what is read and drawn */
    float transfer[STIN__PIXEL_TRANSFER];
} stin__unpack_saved;
void stin__unpack_begin(struct stin_context *ctx, stin__unpack_saved *s);
void stin__unpack_end(struct stin_context *ctx, const stin__unpack_saved *s);
void stin__pack_begin(struct stin_context *ctx, stin__unpack_saved *s);
void stin__pack_end(struct stin_context *ctx, const stin__unpack_saved *s);

/* Uploads one level of 8-bit texels, tightly packed (stin__unpack_begin
 * for the call, the caller's state restored); a 1D target ignores h. */
void stin__upload_level(stin_context *ctx, GLenum target, GLint level, GLenum internal_format,
                        uint32_t w, uint32_t h, GLenum format, const void *pixels);
void stin__upload_bytes(stin_context *ctx, GLenum target, GLenum internal_format, uint32_t w,
                        uint32_t h, GLenum format, const void *pixels);

#endif
