/* SPDX-License-Identifier: MIT */
/* stin_update_mesh: a mesh's vertices replaced between frames, its
 * topology kept. The same steps as creation in the same order (normals,
 * tangents, then the creation's welds snapped), so an update equals
 * destroying and creating the mesh; adjacency, welding and the index
 * buffers are not redone.
 * Who reads positions, and why nothing else needs refreshing: every
 * technique reads the shape each frame, from the block (volumes' CPU
 * extrusion, GL1 client arrays, DOT3's light vectors, the fixed path's
 * terminator band, vdsm's parity test for CSG lights) or from the vertex
 * buffer (the lit passes, maps, deep and coloured maps, vdsm and GL4's
 * extrusion through the adjacency vertex array, which reads the same
 * buffer name). What is kept per mesh is redone here: bounds (draw
 * culling, volumes' reach, the light cameras' fit, CSG's rectangles and
 * boxes, deep's fit), convexity (scs), the smooth flag (the terminator
 * rule, the measured choice) and the mean edge length (displacement's mip
 * level). Welds keep the adjacency buffer's far vertices bit-equal. */
#include "internal.h"

static stin_result refuse(stin_context *ctx, stin_result r, stin_log_item item, const char *fmt,
                          uint32_t a, uint32_t b)
{
    stin__log(ctx, STIN_LOG_LEVEL_ERROR, item, fmt, a, b);
    return r;
}

static stin_result validate(stin_context *ctx, const stin__mesh_slot *m,
                            const stin_mesh_update_desc *d)
{
    uint32_t bad = 0, n = d->vertex_count;
    if (!d->positions || n != m->source_vertices)
        return refuse(ctx, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT,
                      "stin_update_mesh: need positions for the mesh's %u vertices (got %u: "
                      "vertex_count must equal the creation's)", m->source_vertices, n);
    if (d->tangents && m->subdivide)
        return refuse(ctx, STIN_ERROR_INVALID_ARGUMENT, STIN_LOG_BAD_ARGUMENT,
                      "stin_update_mesh: tangents given for a mesh subdivided %u levels at "
                      "creation (its midpoints' tangents are recomputed: give none)",
                      m->subdivide, 0);
    if (!stin__mesh_finite(d->positions, 3u * n, &bad))
        return refuse(ctx, STIN_ERROR_INVALID_MESH, STIN_LOG_MESH_NOT_FINITE,
                      "stin_update_mesh: position of vertex %u is NaN or Inf", bad / 3u, 0);
    if (!stin__mesh_finite(d->normals, 3u * n, &bad))
        return refuse(ctx, STIN_ERROR_INVALID_MESH, STIN_LOG_MESH_NOT_FINITE,
                      "stin_update_mesh: normal of vertex %u is NaN or Inf", bad / 3u, 0);
    if (!stin__mesh_finite(d->tangents, 4u * n, &bad))
        return refuse(ctx, STIN_ERROR_INVALID_MESH, STIN_LOG_MESH_NOT_FINITE,
                      "stin_update_mesh: tangent of vertex %u is NaN or Inf", bad / 4u, 0);
    return STIN_OK;
}

/* The source vertices' new positions and raw normals, as creation copies
 * them (tangents cleared; uvs stay). */
static void copy_source(stin__vertex *v, const stin_mesh_update_desc *d)
{
    uint32_t i;
    int k;
    for (i = 0; i < d->vertex_count; i++) {
        for (k = 0; k < 3; k++) {
            v[i].position[k] = d->positions[3u * i + k];
            v[i].normal[k] = d->normals ? d->normals[3u * i + k] : 0.0f;
            v[i].tangent[k] = 0.0f;
        }
        v[i].tangent[3] = 1.0f;
    }
}

static void given_tangents(stin__vertex *v, const float *t, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        v[i].tangent[0] = t[4u * i];
        v[i].tangent[1] = t[4u * i + 1];
        v[i].tangent[2] = t[4u * i + 2];
        v[i].tangent[3] = t[4u * i + 3] < 0.0f ? -1.0f : 1.0f;
    }
}

/* Welded vertices onto the first of their group, as creation snapped them. */
static void snap_welds(stin__vertex *v, const uint32_t *welds, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; i++)
        if (welds[i] != i)
            stin__memcopy(v[i].position, v[welds[i]].position, sizeof v[i].position);
}

stin_result stin_update_mesh(stin_context *ctx, stin_mesh mesh, const stin_mesh_update_desc *desc)
{
    stin__mesh_slot *m;
    stin__vertex *verts;
    const uint32_t *tris;
    stin_result r;
    if (!ctx || !desc)
        return STIN_ERROR_INVALID_ARGUMENT;
    m = stin__mesh_lookup(ctx, mesh, NULL);
    if (!m)
        return refuse(ctx, STIN_ERROR_INVALID_HANDLE, STIN_LOG_BAD_HANDLE,
                      "stin_update_mesh: stale or unknown mesh handle 0x%x", mesh.id, 0);
    if (ctx->state == STIN__IN_FRAME) /* the frame's draws were taken against this shape */
        return refuse(ctx, STIN_ERROR_INVALID_STATE, STIN_LOG_FRAME_STATE,
                      "stin_update_mesh: a frame is open and its draws may use this mesh; "
                      "update it after stin_end_frame", 0, 0);
    r = validate(ctx, m, desc);
    if (r != STIN_OK)
        return r;
    verts = ctx->vertices + m->first_vertex;
    tris = ctx->indices + 3u * m->first_triangle;
    copy_source(verts, desc);
    stin__subdivide_again(verts, tris, m->triangle_count, m->subdivide);
    stin__mesh_fix_normals(verts, m->vertex_count, tris, m->triangle_count,
                           desc->normals != NULL);
    if (desc->tangents)
        given_tangents(verts, desc->tangents, m->vertex_count);
    else
        stin__mesh_tangents(verts, m->vertex_count, tris, m->triangle_count,
                            (float *)(void *)ctx->scratch, m->has_uvs);
    snap_welds(verts, ctx->welds + m->first_vertex, m->vertex_count);
    stin__mesh_derive(ctx, m, 0); /* uvs as created */
    m->info.convex = m->info.closed_manifold && m->one_piece &&
                     !stin__mesh_concave_edge(verts, tris,
                                              ctx->adjacency + 3u * m->first_triangle,
                                              ctx->welds + m->first_vertex, m->triangle_count);
    m->dynamic = 1;
    stin__mesh_upload_vertices(ctx, m);
    return STIN_OK;
}
