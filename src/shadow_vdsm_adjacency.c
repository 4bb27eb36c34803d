/* SPDX-License-Identifier: MIT */
/* VDSM's light pass (shadow_vdsm_pyramid.c) must know, for every edge, on
 * which side of it the neighbouring triangle lies in the light's view: an
 * edge with no neighbour beyond it bounds the union of the triangles. So
 * each mesh gets a GL_TRIANGLES_ADJACENCY index buffer (triangle vertices
 * interleaved with the far vertex of the neighbour across each edge, from
 * the mesh's adjacency) and a vertex array that draws it. An open or
 * non-manifold edge gets the triangle's own third vertex: the same side, so
 * the edge counts as an outline. Only where vdsm is the shadow technique:
 * 24 bytes of GL memory per triangle. */
#include "internal.h"

#define NO_TRI 0xffffffffu

/* The vertex of triangle n not on its edge back to triangle t, or own. */
static uint32_t far_vertex(const uint32_t *tris, const uint32_t *adj, uint32_t t, uint32_t n,
                           uint32_t own)
{
    int j;
    if (n == NO_TRI || n == t)
        return own;
    for (j = 0; j < 3; j++)
        if (adj[3u * n + (uint32_t)j] == t)
            return tris[3u * n + (uint32_t)(j + 2) % 3u];
    return own;
}

void stin__vdsm_mesh_upload(stin_context *ctx, stin__mesh_slot *m)
{
    const uint32_t *tris = ctx->indices + 3u * m->first_triangle;
    const uint32_t *adj = ctx->adjacency + 3u * m->first_triangle;
    uint32_t *out = (uint32_t *)(void *)ctx->scratch, t;
    size_t bytes = sizeof(uint32_t) * 6u * m->triangle_count;
    GLuint caller_vao;
    if (!m->vao || ctx->sel.choice[STIN_FEATURE_SHADOWS].technique != STIN_TECH_SHADOWS_VDSM)
        return;
    if (bytes > ctx->scratch_bytes || !m->triangle_count) {
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                  "vdsm: no scratch for a mesh's adjacency indices: it casts, but does not "
                  "count as an occluder for step SM");
        return;
    }
    for (t = 0; t < m->triangle_count; t++) {
        int e;
        for (e = 0; e < 3; e++) {
            uint32_t own = tris[3u * t + (uint32_t)(e + 2) % 3u];
            out[6u * t + 2u * (uint32_t)e] = tris[3u * t + (uint32_t)e];
            out[6u * t + 2u * (uint32_t)e + 1u] =
                far_vertex(tris, adj, t, adj[3u * t + (uint32_t)e], own);
        }
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

void stin__vdsm_mesh_release(stin_context *ctx, stin__mesh_slot *m)
{
    if (m->adj_ibo)
        GL(ctx, DeleteBuffers)(1, &m->adj_ibo);
    if (m->adj_vao)
        GL(ctx, DeleteVertexArrays)(1, &m->adj_vao);
    m->adj_ibo = m->adj_vao = 0;
}
