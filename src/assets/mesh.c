/* SPDX-License-Identifier: MIT */
/* Mesh creation: validation, storage in the arena, normals, tangents,
 * adjacency, and the GPU copy where buffers exist. */
#include "internal.h"

stin__mesh_slot *stin__mesh_lookup(const stin_context *ctx, stin_mesh mesh, uint32_t *slot)
{
    uint32_t s;
    if (!ctx)
        return NULL;
    s = stin__handle_resolve(&ctx->meshes[0].handle, sizeof ctx->meshes[0], ctx->desc.max_meshes,
                             ctx->handle_tag, mesh.id);
    if (s == STIN__NO_SLOT)
        return NULL;
    if (slot)
        *slot = s;
    return &ctx->meshes[s];
}

static stin_result fail(stin_context *ctx, stin_result r, stin_log_item item, const char *fmt,
                        uint32_t a, uint32_t b)
{
    stin__log(ctx, STIN_LOG_LEVEL_ERROR, item, fmt, a, b);
    return r;
}

int stin__mesh_finite(const float *v, uint32_t n, uint32_t *bad)
{
    uint32_t i;
    if (!v)
        return 1;
    for (i = 0; i < n; i++)
        if (!stin__isfinite(v[i])) {
            *bad = i;
            return 0;
        }
    return 1;
}

/* Zero area relative to the longest edge, or repeated indices. In double:
 * float positions' differences, cross products and their squares all fit
 * its range, so the test is the same at every scale (1e-30 or 1e30). */
static int degenerate(const float *pos, const uint32_t *t)
{
    const float *a = pos + 3u * t[0], *b = pos + 3u * t[1], *c = pos + 3u * t[2];
    double e1[3], e2[3], n[3], l1, l2;
    int k;
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
        return 1;
    for (k = 0; k < 3; k++) {
        e1[k] = (double)b[k] - (double)a[k];
        e2[k] = (double)c[k] - (double)a[k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    l1 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2];
    l2 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
    if (l2 > l1)
        l1 = l2;
    return n[0] * n[0] + n[1] * n[1] + n[2] * n[2] <= 1e-14 * l1 * l1;
}

static stin_result validate(stin_context *ctx, const stin_mesh_desc *d, uint32_t *kept)
{
    uint32_t i, bad = 0, tris;
    if (!d->positions || !d->indices || d->vertex_count == 0 || d->index_count == 0 ||
        d->index_count % 3u != 0)
        return fail(ctx, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT,
                    "stin_create_mesh: need positions, vertex_count > 0 and indices with "
                    "index_count a positive multiple of 3 (got %u vertices, %u indices)",
                    d->vertex_count, d->index_count);
    if (d->subdivide > 6u)
        return fail(ctx, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT,
                    "stin_create_mesh: subdivide is %u, at most %u levels", d->subdivide, 6u);
    if (!stin__isfinite(d->weld_tolerance))
        return fail(ctx, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT,
                    "stin_create_mesh: weld_tolerance is NaN or Inf", 0, 0);
    for (i = 0; i < d->index_count; i++)
        if (d->indices[i] >= d->vertex_count)
            return fail(ctx, STIN_ERROR_INVALID_MESH, STIN_LOG_MESH_INDEX_RANGE,
                        "stin_create_mesh: index %u is out of range (vertex count %u)", i,
                        d->vertex_count);
    if (!stin__mesh_finite(d->positions, 3u * d->vertex_count, &bad))
        return fail(ctx, STIN_ERROR_INVALID_MESH, STIN_LOG_MESH_NOT_FINITE,
                    "stin_create_mesh: position of vertex %u is NaN or Inf", bad / 3u, 0);
    if (!stin__mesh_finite(d->normals, 3u * d->vertex_count, &bad))
        return fail(ctx, STIN_ERROR_INVALID_MESH, STIN_LOG_MESH_NOT_FINITE,
                    "stin_create_mesh: normal of vertex %u is NaN or Inf", bad / 3u, 0);
    if (!stin__mesh_finite(d->uvs, 2u * d->vertex_count, &bad))
        return fail(ctx, STIN_ERROR_INVALID_MESH, STIN_LOG_MESH_NOT_FINITE,
                    "stin_create_mesh: uv of vertex %u is NaN or Inf", bad / 2u, 0);
    tris = d->index_count / 3u;
    *kept = 0;
    for (i = 0; i < tris; i++)
        if (!degenerate(d->positions, d->indices + 3u * i))
            (*kept)++;
    if (*kept == 0)
        return fail(ctx, STIN_ERROR_INVALID_MESH, STIN_LOG_MESH_DEGENERATE,
                    "stin_create_mesh: all %u triangles are degenerate", tris, 0);
    return STIN_OK;
}

static void copy_vertices(stin__vertex *v, const stin_mesh_desc *d)
{
    uint32_t i;
    for (i = 0; i < d->vertex_count; i++) {
        int k;
        for (k = 0; k < 3; k++) {
            v[i].position[k] = d->positions[3u * i + k];
            v[i].normal[k] = d->normals ? d->normals[3u * i + k] : 0.0f;
        }
        v[i].uv[0] = d->uvs ? d->uvs[2u * i] : 0.0f;
        v[i].uv[1] = d->uvs ? d->uvs[2u * i + 1] : 0.0f;
        v[i].tangent[0] = v[i].tangent[1] = v[i].tangent[2] = 0.0f;
        v[i].tangent[3] = 1.0f;
    }
}

/* Given normals are normalised; a zero one takes the face-derived normal. */
void stin__mesh_fix_normals(stin__vertex *v, uint32_t n, const uint32_t *tris,
                            uint32_t tri_count, int given)
{
    uint32_t i, zero = 0;
    if (!given) {
        stin__mesh_default_normals(v, n, tris, tri_count);
        return;
    }
    for (i = 0; i < n; i++) {
        float *nv = v[i].normal;
        float l = stin__sqrtf(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
        if (l > 1e-20f) {
            nv[0] /= l;
            nv[1] /= l;
            nv[2] /= l;
        } else {
            zero++;
        }
    }
    if (zero)
        stin__mesh_default_normals(v, n, tris, tri_count); /* rare: recompute all, stay consistent */
}

static void bounds(stin_mesh_info *info, const stin__vertex *v, uint32_t n)
{
    uint32_t i;
    int k;
    for (k = 0; k < 3; k++)
        info->bounds_min[k] = info->bounds_max[k] = v[0].position[k];
    for (i = 1; i < n; i++)
        for (k = 0; k < 3; k++) {
            if (v[i].position[k] < info->bounds_min[k])
                info->bounds_min[k] = v[i].position[k];
            if (v[i].position[k] > info->bounds_max[k])
                info->bounds_max[k] = v[i].position[k];
        }
}

void stin__mesh_derive(stin_context *ctx, stin__mesh_slot *m, int uvs_changed)
{
    const stin__vertex *verts = ctx->vertices + m->first_vertex;
    const uint32_t *tris = ctx->indices + 3u * m->first_triangle;
    stin__mesh_mean_edges(verts, tris, m->triangle_count, uvs_changed ? &m->uv_edge : NULL,
                          &m->edge);
    stin__mesh_uv_units(verts, tris, m->triangle_count, m->uv_unit);
    m->smooth = stin__mesh_smooth(verts, tris, m->triangle_count);
    bounds(&m->info, verts, m->vertex_count);
}

/* Attribute layout shared by every GLSL program (see gl/shader.c). */
void stin__mesh_bind_attributes(stin_context *ctx, const stin__vertex *base)
{
    const GLsizei stride = (GLsizei)sizeof(stin__vertex);
    const char *b = (const char *)base;
    GL(ctx, VertexAttribPointer)(0, 3, GL_FLOAT, GL_FALSE, stride, b + 0);
    GL(ctx, VertexAttribPointer)(1, 3, GL_FLOAT, GL_FALSE, stride, b + 12);
    GL(ctx, VertexAttribPointer)(2, 2, GL_FLOAT, GL_FALSE, stride, b + 24);
    GL(ctx, VertexAttribPointer)(3, 4, GL_FLOAT, GL_FALSE, stride, b + 32);
}

static void vertex_data(stin_context *ctx, const stin__mesh_slot *m)
{
    GLenum usage = m->dynamic ? GL_DYNAMIC_DRAW : GL_STATIC_DRAW;
    GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, m->vbo);
    if (!stin__mesh_chunked_vertices(ctx, m, usage)) /* 16-bit chunks have their own copies */
        GL(ctx, BufferData)(GL_ARRAY_BUFFER,
                            (GLsizeiptr)(sizeof(stin__vertex) * m->vertex_count),
                            ctx->vertices + m->first_vertex, usage);
}

static void upload(stin_context *ctx, stin__mesh_slot *m)
{
    int i;
    GLuint caller_vao;
    if (!(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_VBO)))
        return; /* client arrays straight from the arena */
    caller_vao = stin__vao_begin(ctx); /* the element buffer is VAO state */
    GL(ctx, GenBuffers)(1, &m->vbo);
    GL(ctx, GenBuffers)(1, &m->ibo);
    if (ctx->sel.tier == STIN_TIER_GL4) {
        GL(ctx, GenVertexArrays)(1, &m->vao);
        GL(ctx, BindVertexArray)(m->vao);
    }
    vertex_data(ctx, m);
    GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, m->ibo);
    stin__mesh_index_data(ctx, m);
    if (m->vao) {
        for (i = 0; i < 4; i++)
            GL(ctx, EnableVertexAttribArray)((GLuint)i);
        stin__mesh_bind_attributes(ctx, NULL);
        GL(ctx, BindVertexArray)(0);
    }
    GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
    GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, 0);
    stin__vao_end(ctx, caller_vao);
}

/* The same buffer name again (the vertex arrays that read it, adjacency's
 * too, stay valid): glBufferData orphans the old storage, so a frame the
 * driver still draws from the old data does not stall the update. */
void stin__mesh_upload_vertices(stin_context *ctx, stin__mesh_slot *m)
{
    GLuint caller_vao;
    if (!m->vbo)
        return; /* client arrays straight from the arena */
    caller_vao = stin__vao_begin(ctx);
    vertex_data(ctx, m);
    GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
    stin__vao_end(ctx, caller_vao);
}

static stin__index_chunk *chunk_row(const stin_context *ctx, uint32_t slot)
{
    return ctx->index_chunks + (size_t)slot * ctx->index_chunks_per_mesh;
}

static uint32_t free_slot(const stin_context *ctx)
{
    return stin__handle_free_slot(&ctx->meshes[0].handle, sizeof ctx->meshes[0],
                                  ctx->desc.max_meshes);
}

/* The kept (non-degenerate) triangles of desc into tris. */
static void keep_triangles(const stin_mesh_desc *desc, uint32_t *tris)
{
    uint32_t i, t = 0;
    for (i = 0; i < desc->index_count / 3u; i++)
        if (!degenerate(desc->positions, desc->indices + 3u * i)) {
            tris[3u * t] = desc->indices[3u * i];
            tris[3u * t + 1] = desc->indices[3u * i + 1];
            tris[3u * t + 2] = desc->indices[3u * i + 2];
            t++;
        }
}

/* The stored mesh's counts. Subdivided ones need the kept triangles'
 * edges: their indices are staged at the end of the creation scratch, the
 * edge table before them. */
static stin_result stored_counts(stin_context *ctx, const stin_mesh_desc *desc, uint32_t kept,
                                 uint32_t *verts, uint32_t *tris)
{
    size_t staged_bytes = 12u * (size_t)kept;
    uint32_t *staged;
    *verts = desc->vertex_count;
    *tris = kept;
    if (!desc->subdivide)
        return STIN_OK;
    if (staged_bytes > ctx->scratch_bytes)
        return STIN_ERROR_CAPACITY;
    staged = (uint32_t *)(void *)(ctx->scratch + ((ctx->scratch_bytes - staged_bytes) & ~(size_t)3));
    keep_triangles(desc, staged);
    return stin__subdivide_counts(ctx, staged, kept, desc->vertex_count, desc->subdivide,
                                  (size_t)((unsigned char *)staged - ctx->scratch), verts, tris);
}

stin_result stin_create_mesh(stin_context *ctx, const stin_mesh_desc *desc, stin_mesh *out)
{
    uint32_t kept = 0, kept0, slot, vfirst, tfirst, nv = 0, nt = 0;
    stin__mesh_slot *m;
    stin__vertex *verts;
    uint32_t *tris;
    stin_result r;
    if (out)
        out->id = 0;
    if (!ctx || !desc || !out)
        return STIN_ERROR_INVALID_ARGUMENT;
    r = validate(ctx, desc, &kept);
    if (r != STIN_OK)
        return r;
    if (kept > ctx->desc.max_mesh_triangles || desc->vertex_count > 3u * ctx->desc.max_mesh_triangles)
        return fail(ctx, STIN_ERROR_CAPACITY, STIN_LOG_POOL_FULL,
                    "stin_create_mesh: %u triangles exceed desc.max_mesh_triangles (%u)", kept,
                    ctx->desc.max_mesh_triangles);
    if (stored_counts(ctx, desc, kept, &nv, &nt) != STIN_OK || nt > ctx->desc.max_mesh_triangles ||
        nv > 3u * ctx->desc.max_mesh_triangles || nv > ctx->desc.max_vertices)
        return fail(ctx, STIN_ERROR_CAPACITY, STIN_LOG_POOL_FULL,
                    "stin_create_mesh: %u levels of subdivision make more than "
                    "desc.max_mesh_triangles (%u) triangles", desc->subdivide,
                    ctx->desc.max_mesh_triangles);
    slot = free_slot(ctx);
    if (slot == 0xffffffffu)
        return fail(ctx, STIN_ERROR_CAPACITY, STIN_LOG_POOL_FULL,
                    "stin_create_mesh: all %u mesh slots in use (desc.max_meshes)",
                    ctx->desc.max_meshes, 0);
    if (!stin__range_take(&ctx->vertex_ranges, nv, &vfirst))
        return fail(ctx, STIN_ERROR_CAPACITY, STIN_LOG_POOL_FULL,
                    "stin_create_mesh: no room for %u vertices (desc.max_vertices %u)",
                    nv, ctx->desc.max_vertices);
    if (!stin__range_take(&ctx->triangle_ranges, nt, &tfirst)) {
        stin__range_give(&ctx->vertex_ranges, vfirst);
        return fail(ctx, STIN_ERROR_CAPACITY, STIN_LOG_POOL_FULL,
                    "stin_create_mesh: no room for %u triangles (desc.max_triangles %u)", nt,
                    ctx->desc.max_triangles);
    }
    verts = ctx->vertices + vfirst;
    tris = ctx->indices + 3u * tfirst;
    keep_triangles(desc, tris);
    m = &ctx->meshes[slot];
    stin__memzero(&m->info, sizeof m->info);
    copy_vertices(verts, desc);
    stin__subdivide(ctx, verts, desc->vertex_count, tris, kept, desc->subdivide);
    kept0 = kept;
    kept = nt;
    stin__mesh_fix_normals(verts, nv, tris, kept, desc->normals != NULL);
    stin__mesh_tangents(verts, nv, tris, kept, (float *)(void *)ctx->scratch,
                        desc->uvs != NULL);
    r = stin__mesh_adjacency_build(ctx, verts, nv, desc->weld_tolerance, tris, kept,
                                   ctx->adjacency + 3u * tfirst, ctx->welds + vfirst, &m->info,
                                   &m->one_piece);
    if (r != STIN_OK) {
        stin__range_give(&ctx->vertex_ranges, vfirst);
        stin__range_give(&ctx->triangle_ranges, tfirst);
        return fail(ctx, r, STIN_LOG_POOL_FULL, "stin_create_mesh: adjacency scratch too small "
                    "for %u vertices, %u triangles", desc->vertex_count, kept);
    }
    m->first_vertex = vfirst;
    m->vertex_count = nv;
    m->first_triangle = tfirst;
    m->triangle_count = kept;
    m->source_vertices = desc->vertex_count;
    m->subdivide = desc->subdivide;
    m->has_uvs = desc->uvs != NULL;
    m->dynamic = 0;
    stin__mesh_derive(ctx, m, 1);
    m->info.vertex_count = nv;
    m->info.triangle_count = kept;
    m->info.degenerate_dropped = desc->index_count / 3u - kept0;
    m->vbo = m->ibo = m->vao = m->adj_ibo = m->adj_vao = 0;
    if (stin__mesh_index_plan(ctx, m, chunk_row(ctx, slot)) != STIN_OK) {
        stin__range_give(&ctx->vertex_ranges, vfirst);
        stin__range_give(&ctx->triangle_ranges, tfirst);
        return fail(ctx, STIN_ERROR_CAPACITY, STIN_LOG_POOL_FULL,
                    "stin_create_mesh: %u vertices need more than desc.max_mesh_triangles' "
                    "16-bit index chunks (no 32-bit element indices; %u triangles)", nv, kept);
    }
    out->id = stin__handle_issue(&m->handle, slot, ctx->desc.max_meshes, ctx->handle_tag);
    upload(ctx, m);
    stin__mesh_adjacency_buffer_upload(ctx, m);
    if (m->info.degenerate_dropped)
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_MESH_DEGENERATE,
                  "stin_create_mesh: dropped %u degenerate triangles of %u",
                  m->info.degenerate_dropped, desc->index_count / 3u);
    if (!m->info.closed_manifold)
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_MESH_NOT_MANIFOLD,
                  "stin_create_mesh: not a closed 2-manifold (%u open edges, %u non-manifold "
                  "or inconsistently oriented edges)", m->info.open_edges,
                  m->info.nonmanifold_edges);
    return STIN_OK;
}

stin_result stin_query_mesh_info(const stin_context *ctx, stin_mesh mesh, stin_mesh_info *out)
{
    const stin__mesh_slot *m = stin__mesh_lookup(ctx, mesh, NULL);
    if (!out)
        return STIN_ERROR_INVALID_ARGUMENT;
    if (!m)
        return STIN_ERROR_INVALID_HANDLE;
    *out = m->info;
    return STIN_OK;
}

stin_result stin_query_mesh_adjacency(const stin_context *ctx, stin_mesh mesh, uint32_t t,
                                uint32_t out_neighbours[3])
{
    const stin__mesh_slot *m = stin__mesh_lookup(ctx, mesh, NULL);
    int k;
    if (!out_neighbours)
        return STIN_ERROR_INVALID_ARGUMENT;
    if (!m)
        return STIN_ERROR_INVALID_HANDLE;
    if (t >= m->triangle_count)
        return STIN_ERROR_INVALID_ARGUMENT;
    for (k = 0; k < 3; k++)
        out_neighbours[k] = ctx->adjacency[3u * (m->first_triangle + t) + (uint32_t)k];
    return STIN_OK;
}

stin_result stin_query_mesh_tangent(const stin_context *ctx, stin_mesh mesh, uint32_t vertex,
                              float out_tangent[4])
{
    const stin__mesh_slot *m = stin__mesh_lookup(ctx, mesh, NULL);
    if (!out_tangent)
        return STIN_ERROR_INVALID_ARGUMENT;
    if (!m)
        return STIN_ERROR_INVALID_HANDLE;
    if (vertex >= m->vertex_count)
        return STIN_ERROR_INVALID_ARGUMENT;
    stin__memcopy(out_tangent, ctx->vertices[m->first_vertex + vertex].tangent, 4 * sizeof(float));
    return STIN_OK;
}

static void delete_arrays(stin_context *ctx, stin__mesh_slot *m)
{
    if (m->vbo)
        GL(ctx, DeleteBuffers)(1, &m->vbo);
    if (m->ibo)
        GL(ctx, DeleteBuffers)(1, &m->ibo);
    if (m->vao)
        GL(ctx, DeleteVertexArrays)(1, &m->vao);
    m->vbo = m->ibo = m->vao = 0;
}

static void release(stin_context *ctx, stin__mesh_slot *m)
{
    delete_arrays(ctx, m);
    stin__mesh_adjacency_buffer_release(ctx, m);
    stin__range_give(&ctx->vertex_ranges, m->first_vertex);
    stin__range_give(&ctx->triangle_ranges, m->first_triangle);
    stin__handle_release(&m->handle, ctx->desc.max_meshes);
    m->vbo = m->ibo = m->vao = 0;
}

void stin_destroy_mesh(stin_context *ctx, stin_mesh mesh)
{
    stin__mesh_slot *m = stin__mesh_lookup(ctx, mesh, NULL);
    if (!m) {
        if (ctx && mesh.id)
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_BAD_HANDLE,
                      "stin_destroy_mesh: stale or unknown handle 0x%x", mesh.id);
        return;
    }
    if (ctx->state == STIN__IN_FRAME) { /* queued draws still name it */
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FRAME_STATE,
                  "%s: a frame is open and its draws may use this %s; destroy it after "
                  "stin_end_frame", "stin_destroy_mesh", "mesh");
        return;
    }
    release(ctx, m);
}

void stin__mesh_release_all(stin_context *ctx)
{
    uint32_t i;
    stin__mesh_slot *own = &ctx->meshes[ctx->desc.max_meshes];
    for (i = 0; i < ctx->desc.max_meshes; i++)
        if (ctx->meshes[i].handle.alive)
            release(ctx, &ctx->meshes[i]);
    delete_arrays(ctx, own);
    stin__memzero(own, sizeof *own);
}

uint32_t stin__mesh_builtin(stin_context *ctx, const stin__vertex *v, uint32_t vertex_count,
                            const uint32_t *tris, uint32_t tri_count)
{
    uint32_t slot = ctx->desc.max_meshes, i;
    stin__mesh_slot *m = &ctx->meshes[slot];
    if (vertex_count > STIN__BUILTIN_VERTICES || tri_count > STIN__BUILTIN_TRIANGLES)
        return STIN__NO_SLOT;
    stin__memzero(m, sizeof *m);
    m->first_vertex = ctx->desc.max_vertices;
    m->first_triangle = ctx->desc.max_triangles;
    m->vertex_count = m->info.vertex_count = vertex_count;
    m->triangle_count = m->info.triangle_count = tri_count;
    for (i = 0; i < vertex_count; i++)
        ctx->vertices[m->first_vertex + i] = v[i];
    for (i = 0; i < 3u * tri_count; i++)
        ctx->indices[3u * m->first_triangle + i] = tris[i];
    bounds(&m->info, ctx->vertices + m->first_vertex, vertex_count);
    (void)stin__mesh_index_plan(ctx, m, chunk_row(ctx, slot)); /* 4 vertices: one chunk */
    upload(ctx, m);
    return slot;
}
