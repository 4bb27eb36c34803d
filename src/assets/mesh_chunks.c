/* SPDX-License-Identifier: MIT */
/* 16-bit element indices, for GL without 32-bit ones (OpenGL ES 2.0 and
 * WebGL 1 without OES_element_index_uint: STIN_CAP_ELEMENT_INDEX_UINT).
 *
 * A mesh of at most 65,535 vertices keeps its vertex buffer as it is and
 * gets its indices narrowed. A bigger one is split into chunks: runs of
 * consecutive triangles, each closed before a triangle whose new vertices
 * would take it past 65,535, each with its own vertices (in the order the
 * chunk first uses them, so a vertex on a seam is copied into every chunk
 * that uses it) and 16-bit indices local to them. The GPU copy is the
 * chunks' vertices one after another and their indices in triangle order,
 * so chunk c draws 3 n_c indices from byte 6 t_c with the attributes moved
 * to its first vertex: every triangle drawn once, the same triangles in
 * the same order. The block's own copy (the arena's vertices and 32-bit
 * triangles) is unchanged, so everything that reads the mesh on the CPU
 * sees the same mesh. Scratch only (the creation scratch: no heap); the
 * chunk table is the mesh slot's row of ctx->index_chunks. */
#include "internal.h"

uint32_t stin__index_chunks_max(uint32_t max_mesh_triangles)
{
    /* every chunk but the last holds more than limit - 3 vertices, and
     * the chunks hold at most 3 per triangle between them */
    return (uint32_t)(3ull * max_mesh_triangles / (STIN__CHUNK_VERTICES - 2u)) + 1u;
}

/* Numbers triangle t's corners in chunk `stamp_id` (first use first):
 * local[v] once stamp[v] says v is in it; returns the new vertices. */
static uint32_t number_corners(const uint32_t *tri, uint32_t stamp_id, uint32_t *stamp,
                               uint32_t *local, uint32_t *count, uint32_t *src)
{
    uint32_t k, fresh = 0;
    for (k = 0; k < 3u; k++) {
        uint32_t v = tri[k];
        if (stamp[v] == stamp_id)
            continue;
        stamp[v] = stamp_id;
        if (src)
            src[*count] = v;
        local[v] = (*count)++;
        fresh++;
    }
    return fresh;
}

/* How many of t's corners chunk stamp_id does not hold yet. */
static uint32_t new_corners(const uint32_t *tri, uint32_t stamp_id, const uint32_t *stamp)
{
    uint32_t k, n = 0;
    for (k = 0; k < 3u; k++)
        n += stamp[tri[k]] != stamp_id &&
             (k == 0u || tri[k] != tri[0]) && (k < 2u || tri[k] != tri[1]);
    return n;
}

uint32_t stin__index_split(const uint32_t *tris, uint32_t tri_count, uint32_t vertex_count,
                           uint32_t limit, uint32_t *stamp, uint32_t *local,
                           stin__index_chunk *out, uint32_t max_out)
{
    uint32_t t, c = 0, count = 0, vertices = 0;
    if (limit < 3u || max_out == 0u)
        return 0;
    stin__memzero(stamp, sizeof *stamp * vertex_count);
    out[0].first_triangle = out[0].first_vertex = 0;
    for (t = 0; t < tri_count; t++) {
        if (count + new_corners(tris + 3u * t, c + 1u, stamp) > limit) {
            out[c].triangle_count = t - out[c].first_triangle;
            out[c].vertex_count = count;
            vertices += count;
            if (++c == max_out)
                return 0;
            out[c].first_triangle = t;
            out[c].first_vertex = vertices;
            count = 0;
        }
        (void)number_corners(tris + 3u * t, c + 1u, stamp, local, &count, NULL);
    }
    out[c].triangle_count = tri_count - out[c].first_triangle;
    out[c].vertex_count = count;
    return c + 1u;
}

void stin__index_chunk_fill(const uint32_t *tris, const stin__index_chunk *chunk,
                            uint32_t stamp_id, uint32_t *stamp, uint32_t *local,
                            uint16_t *indices, uint32_t *src)
{
    uint32_t t, k, count = 0;
    for (t = 0; t < chunk->triangle_count; t++) {
        const uint32_t *tri = tris + 3u * (chunk->first_triangle + t);
        (void)number_corners(tri, stamp_id, stamp, local, &count, src);
        if (indices)
            for (k = 0; k < 3u; k++)
                indices[3u * t + k] = (uint16_t)local[tri[k]];
    }
}

/* ---- the GPU copy ---------------------------------------------------------- */

/* Scratch, carved: per vertex its chunk stamp and local number, then room
 * for a chunk's indices and the vertices' sources, then vertex staging. */
typedef struct chunk_scratch {
    uint32_t *stamp, *local, *src;
    uint16_t *indices;
    stin__vertex *staging;
    uint32_t staging_vertices;
} chunk_scratch;

static int carve(stin_context *ctx, const stin__mesh_slot *m, chunk_scratch *s)
{
    size_t most = 0, used, v = m->vertex_count;
    uint32_t c;
    for (c = 0; c < m->chunk_count; c++)
        if (m->chunks[c].triangle_count > most)
            most = m->chunks[c].triangle_count;
    used = stin__align16(8u * v) + stin__align16(6u * most) + stin__align16(4u * 3u * most);
    if (used + sizeof(stin__vertex) > ctx->scratch_bytes)
        return 0;
    s->stamp = (uint32_t *)(void *)ctx->scratch;
    s->local = s->stamp + v;
    s->indices = (uint16_t *)(void *)(ctx->scratch + stin__align16(8u * v));
    s->src = (uint32_t *)(void *)(ctx->scratch + stin__align16(8u * v) + stin__align16(6u * most));
    s->staging = (stin__vertex *)(void *)(ctx->scratch + used);
    s->staging_vertices = (uint32_t)((ctx->scratch_bytes - used) / sizeof(stin__vertex));
    return 1;
}

/* The chunks' vertices into the bound array buffer (storage made), through
 * the staging area a piece at a time; their indices into the bound element
 * buffer where `indices`. */
static void chunk_data(stin_context *ctx, const stin__mesh_slot *m, const chunk_scratch *s,
                       int indices)
{
    const uint32_t *tris = ctx->indices + 3u * m->first_triangle;
    const stin__vertex *verts = ctx->vertices + m->first_vertex;
    uint32_t c, i, n;
    stin__memzero(s->stamp, sizeof(uint32_t) * m->vertex_count);
    for (c = 0; c < m->chunk_count; c++) {
        const stin__index_chunk *k = &m->chunks[c];
        stin__index_chunk_fill(tris, k, c + 1u, s->stamp, s->local,
                               indices ? s->indices : NULL, s->src);
        for (i = 0; i < k->vertex_count; i += n) {
            uint32_t j;
            n = k->vertex_count - i < s->staging_vertices ? k->vertex_count - i
                                                          : s->staging_vertices;
            for (j = 0; j < n; j++)
                s->staging[j] = verts[s->src[i + j]];
            GL(ctx, BufferSubData)(GL_ARRAY_BUFFER,
                                   (GLintptr)(sizeof(stin__vertex) * (k->first_vertex + i)),
                                   (GLsizeiptr)(sizeof(stin__vertex) * n), s->staging);
        }
        if (indices)
            GL(ctx, BufferSubData)(GL_ELEMENT_ARRAY_BUFFER, (GLintptr)(6u * k->first_triangle),
                                   (GLsizeiptr)(6u * k->triangle_count), s->indices);
    }
}

static uint32_t gpu_vertices(const stin__mesh_slot *m)
{
    const stin__index_chunk *last = &m->chunks[m->chunk_count - 1u];
    return last->first_vertex + last->vertex_count;
}

int stin__mesh_chunked_vertices(stin_context *ctx, const stin__mesh_slot *m, GLenum usage)
{
    chunk_scratch s;
    if (m->chunk_count < 2u)
        return 0;
    if (!carve(ctx, m, &s))
        return 1; /* measured at creation: cannot happen for a mesh that was made */
    GL(ctx, BufferData)(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(stin__vertex) * gpu_vertices(m)),
                        NULL, usage);
    chunk_data(ctx, m, &s, 0);
    return 1;
}

stin_result stin__mesh_index_plan(stin_context *ctx, stin__mesh_slot *m, stin__index_chunk *row)
{
    const uint32_t *tris = ctx->indices + 3u * m->first_triangle;
    uint32_t v = m->vertex_count;
    m->chunks = row;
    m->chunk_count = 1;
    row[0].first_triangle = row[0].first_vertex = 0;
    row[0].triangle_count = m->triangle_count;
    row[0].vertex_count = v;
    m->index_type = GL_UNSIGNED_INT;
    if ((ctx->caps.present & STIN_CAP_BIT(STIN_CAP_ELEMENT_INDEX_UINT)) ||
        !(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_VBO)))
        return STIN_OK; /* 32-bit, or client arrays (desktop GL 1.x, which has them) */
    m->index_type = GL_UNSIGNED_SHORT;
    if (v <= STIN__CHUNK_VERTICES)
        return STIN_OK;
    if (8u * (size_t)v > ctx->scratch_bytes)
        return STIN_ERROR_CAPACITY;
    m->chunk_count = stin__index_split(tris, m->triangle_count, v, STIN__CHUNK_VERTICES,
                                       (uint32_t *)(void *)ctx->scratch,
                                       (uint32_t *)(void *)ctx->scratch + v, row,
                                       ctx->index_chunks_per_mesh);
    if (m->chunk_count == 0u) {
        m->chunk_count = 1;
        return STIN_ERROR_CAPACITY;
    }
    {
        chunk_scratch s;
        return carve(ctx, m, &s) ? STIN_OK : STIN_ERROR_CAPACITY;
    }
}

void stin__mesh_index_data(stin_context *ctx, const stin__mesh_slot *m)
{
    const uint32_t *tris = ctx->indices + 3u * m->first_triangle;
    size_t n = 3u * (size_t)m->triangle_count, i;
    if (m->index_type == GL_UNSIGNED_INT) {
        GL(ctx, BufferData)(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(4u * n), tris, GL_STATIC_DRAW);
    } else if (m->chunk_count < 2u) {
        uint16_t *narrow = (uint16_t *)(void *)ctx->scratch; /* 6 bytes a triangle: fits */
        for (i = 0; i < n; i++)
            narrow[i] = (uint16_t)tris[i];
        GL(ctx, BufferData)(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(2u * n), narrow,
                            GL_STATIC_DRAW);
    } else {
        chunk_scratch s;
        (void)carve(ctx, m, &s); /* stin__mesh_index_plan measured it */
        GL(ctx, BufferData)(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(2u * n), NULL, GL_STATIC_DRAW);
        chunk_data(ctx, m, &s, 1);
    }
}

/* ---- drawing --------------------------------------------------------------- */

void stin__mesh_draw(stin_context *ctx, const stin__mesh_slot *m, GLenum mode,
                     const void *client_indices, stin__rebase_fn rebase)
{
    uint32_t c;
    if (m->chunk_count < 2u || !rebase) {
        GL(ctx, DrawElements)(mode, (GLsizei)(3u * m->triangle_count), m->index_type,
                              client_indices);
        return;
    }
    for (c = 0; c < m->chunk_count; c++) {
        const stin__index_chunk *k = &m->chunks[c];
        /* buffer offsets, as GL takes them */
        rebase(ctx, (const stin__vertex *)(uintptr_t)(sizeof(stin__vertex) * k->first_vertex));
        GL(ctx, DrawElements)(mode, (GLsizei)(3u * k->triangle_count), GL_UNSIGNED_SHORT,
                              (const void *)(uintptr_t)(6u * (size_t)k->first_triangle));
    }
    rebase(ctx, NULL); /* the first chunk's pointers: what the mesh's binding left */
}
