/* SPDX-License-Identifier: MIT */
/* A mesh's adjacency buffer: its triangles in GL_TRIANGLES_ADJACENCY order
 * and a vertex array that draws them, for the shadow passes that look
 * across each edge.
 *
 * VDSM's light pass (shadow/vdsm_pyramid.c) must know, for every edge, on
 * which side of it the neighbouring triangle lies in the light's view: an
 * edge with no neighbour beyond it bounds the union of the triangles; GL4's
 * volume extrusion (shadow/volume_extrude.c) must know whether the
 * neighbour faces the light. So each mesh gets a GL_TRIANGLES_ADJACENCY
 * index buffer (triangle vertices interleaved with the far vertex of the
 * neighbour across each edge, from the mesh's adjacency) and a vertex array
 * that draws it. An open or non-manifold edge, or one whose neighbour runs
 * it the same way (the two disagree on which side is out), gets the
 * triangle's own third vertex: the edge then counts as an outline for vdsm,
 * and the extrusion draws a side quad on it from each triangle (a facing
 * test of a neighbour read in the wrong order would be inverted). Only
 * where the shadows module asked (stin__mesh_adjacency_use: vdsm, the
 * extruding volume technique): 24 bytes of GL memory per triangle. */
#include "internal.h"

#define NO_TRI 0xffffffffu

static int same_point(const stin__vertex *verts, uint32_t a, uint32_t b)
{
    const float *p = verts[a].position, *q = verts[b].position;
    return p[0] == q[0] && p[1] == q[1] && p[2] == q[2]; /* welded: snapped bit-equal */
}

/* The vertex of triangle n beyond t's edge e, or own. n may border t on
 * more than one edge (a sliver folded onto its neighbour): the edge is the
 * one with e's endpoints, so both triangles pick the same pair. One that
 * runs e the same way round (orientation flips there) gives own as well. */
static uint32_t far_vertex(const stin__vertex *verts, const uint32_t *tris, const uint32_t *adj,
                           uint32_t t, uint32_t e, uint32_t n, uint32_t own)
{
    uint32_t a = tris[3u * t + e], b = tris[3u * t + (e + 1u) % 3u];
    int j;
    if (n == NO_TRI || n == t)
        return own;
    for (j = 0; j < 3; j++) {
        uint32_t p = tris[3u * n + (uint32_t)j], q = tris[3u * n + (uint32_t)(j + 1) % 3u];
        if (adj[3u * n + (uint32_t)j] != t)
            continue;
        if (same_point(verts, p, b) && same_point(verts, q, a))
            return tris[3u * n + (uint32_t)(j + 2) % 3u];
        if (same_point(verts, p, a) && same_point(verts, q, b))
            return own; /* oriented the other way */
    }
    return own;
}

void stin__mesh_adjacency_use(stin_context *ctx, const char *without)
{
    ctx->adjacency_use = without;
}

void stin__mesh_adjacency_buffer_upload(stin_context *ctx, stin__mesh_slot *m)
{
    const uint32_t *tris = ctx->indices + 3u * m->first_triangle;
    const uint32_t *adj = ctx->adjacency + 3u * m->first_triangle;
    const stin__vertex *verts = ctx->vertices + m->first_vertex;
    uint32_t *out = (uint32_t *)(void *)ctx->scratch, t;
    size_t bytes = sizeof(uint32_t) * 6u * m->triangle_count;
    GLuint caller_vao;
    if (!m->vao || !ctx->adjacency_use)
        return;
    if (m->chunk_count > 1u) { /* one draw of the whole mesh: no 16-bit chunks */
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                  "%s: a mesh of %u vertices has no adjacency indices without 32-bit element "
                  "indices: %s",
                  stin_technique_name(ctx->sel.choice[STIN_FEATURE_SHADOWS].technique),
                  m->vertex_count, ctx->adjacency_use);
        return;
    }
    if (bytes > ctx->scratch_bytes || !m->triangle_count) {
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                  "%s: no scratch for a mesh's adjacency indices: %s",
                  stin_technique_name(ctx->sel.choice[STIN_FEATURE_SHADOWS].technique),
                  ctx->adjacency_use);
        return;
    }
    for (t = 0; t < m->triangle_count; t++) {
        int e;
        for (e = 0; e < 3; e++) {
            uint32_t own = tris[3u * t + (uint32_t)(e + 2) % 3u];
            out[6u * t + 2u * (uint32_t)e] = tris[3u * t + (uint32_t)e];
            out[6u * t + 2u * (uint32_t)e + 1u] =
                far_vertex(verts, tris, adj, t, (uint32_t)e, adj[3u * t + (uint32_t)e], own);
        }
    }
    if (m->index_type == GL_UNSIGNED_SHORT) { /* narrowed in place, front to back */
        uint16_t *narrow = (uint16_t *)(void *)out;
        for (t = 0; t < 6u * m->triangle_count; t++)
            narrow[t] = (uint16_t)out[t];
        bytes /= 2u;
    }
    caller_vao = stin__vao_begin(ctx);
    GL(ctx, GenBuffers)(1, &m->adj_ibo);
    GL(ctx, GenVertexArrays)(1, &m->adj_vao);
    GL(ctx, BindVertexArray)(m->adj_vao);
    GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, m->vbo);
    GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, m->adj_ibo);
    GL(ctx, BufferData)(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)bytes, out, GL_STATIC_DRAW);
    GL(ctx, EnableVertexAttribArray)(0);
    GL(ctx, VertexAttribPointer)(0, 3, GL_FLOAT, GL_FALSE, (GLsizei)sizeof(stin__vertex), NULL);
    GL(ctx, BindVertexArray)(0);
    GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
    GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, 0);
    stin__vao_end(ctx, caller_vao);
}

void stin__mesh_adjacency_buffer_release(stin_context *ctx, stin__mesh_slot *m)
{
    if (m->adj_ibo)
        GL(ctx, DeleteBuffers)(1, &m->adj_ibo);
    if (m->adj_vao)
        GL(ctx, DeleteVertexArrays)(1, &m->adj_vao);
    m->adj_ibo = m->adj_vao = 0;
}
