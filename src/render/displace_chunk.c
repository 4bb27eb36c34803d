/* SPDX-License-Identifier: MIT */
/* The displacement chunk of every mesh-drawing program (shaders/gl2/
 * displace.glsl, spliced in by gl/shader.c): whether programs carry it and
 * are tessellated, told to the layers below, its uniform locations, the
 * primitive its draws use, and per draw its uniforms, the height map on its
 * vertex unit and the coarse-mesh log. The feature's frame set-up and its
 * step down beside volumes are surface/displace.c's. */
#include "internal.h"

/* Average edge of a mesh in texels of a map above which VTF shows facets. */
#define COARSE_TEXELS 4.0f

/* The choice as select/ hands it down (stin__selection_hand_down). */
int stin__displace_built(const stin_context *ctx) { return ctx->vertex_chunk.displace; }

int stin__displace_tessellated(const stin_context *ctx) { return ctx->vertex_chunk.tessellate; }

void stin__displace_untessellate(stin_context *ctx, const char *why)
{
    stin__demote(ctx, STIN_FEATURE_DISPLACEMENT, STIN_TECH_DISPLACEMENT_VTF, why);
}

GLenum stin__displace_primitive(const stin__displace_locs *l)
{
    return l && l->patches ? GL_PATCHES : GL_TRIANGLES;
}

int stin__displace_active(const stin_context *ctx, const stin_material *m)
{
    return m->displace && stin__displace_built(ctx) && stin__texture_lookup(ctx, m->height_map);
}

void stin__displace_locate(stin_context *ctx, GLuint program, int camera, stin__displace_locs *out)
{
    out->map = GL(ctx, GetUniformLocation)(program, "u_displace_map");
    out->params = GL(ctx, GetUniformLocation)(program, "u_displace");
    out->size = GL(ctx, GetUniformLocation)(program, "u_displace_size");
    out->normal = GL(ctx, GetUniformLocation)(program, "u_displace_normal");
    out->clip = GL(ctx, GetUniformLocation)(program, "u_displace_clip");
    out->lod = GL(ctx, GetUniformLocation)(program, "u_displace_lod");
    out->eye = GL(ctx, GetUniformLocation)(program, "u_displace_eye");
    /* only gl4/tess.tesc declares these: the program was built tessellated */
    out->tess = GL(ctx, GetUniformLocation)(program, "u_tess");
    out->tess_eye = GL(ctx, GetUniformLocation)(program, "u_tess_eye");
    out->patches = stin__displace_tessellated(ctx) && out->tess >= 0;
    out->camera = camera;
}

void stin__displace_frame_scale(stin_context *ctx, const float tess[4], const float eye[3])
{
    stin__memcopy(ctx->vertex_chunk.tess, tess, sizeof ctx->vertex_chunk.tess);
    stin__memcopy(ctx->vertex_chunk.tess_eye, eye, sizeof ctx->vertex_chunk.tess_eye);
}

/* Once per (mesh, height map): a mesh whose edges span many texels of the
 * map shows its facets, not the relief. */
static void log_coarse(stin_context *ctx, const stin__draw *d, const stin__texture_slot *t)
{
    const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
    float texels = m->uv_edge * (float)(t->width > t->height ? t->width : t->height);
    uint32_t key = (d->mesh_slot * 2654435761u) ^ t->name, i;
    if (texels <= COARSE_TEXELS)
        return;
    for (i = 0; i < ctx->vertex_chunk.logged_count; i++)
        if (ctx->vertex_chunk.logged[i] == key)
            return;
    if (ctx->vertex_chunk.logged_count ==
        sizeof ctx->vertex_chunk.logged / sizeof ctx->vertex_chunk.logged[0])
        return;
    ctx->vertex_chunk.logged[ctx->vertex_chunk.logged_count++] = key;
    stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
              "displace: a mesh of %u vertices is coarse for its %ux%u height map (edges span "
              "%d texels on average): the relief shows only at the vertices (subdivide it: "
              "stin_mesh_desc.subdivide)", m->vertex_count, t->width, t->height, (int)texels);
}

/* The draw's mip parameters (displace.glsl's u_displace_lod): texels of the
 * map one pixel spans at eye distance 1 - the mesh's texels per unit (its
 * mean uv edge over its mean edge, times the map's size, over the
 * transform's mean axis scale) over the pixels a unit spans there - and the
 * highest level; level 0 alone without the chain or with NO_MIP. */
static void lod_params(const stin_context *ctx, const stin__draw *d,
                       const stin__texture_slot *t, float out[4])
{
    const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
    const float *x = d->transform;
    float scale = (stin__sqrtf(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) +
                   stin__sqrtf(x[4] * x[4] + x[5] * x[5] + x[6] * x[6]) +
                   stin__sqrtf(x[8] * x[8] + x[9] * x[9] + x[10] * x[10])) / 3.0f;
    float size = (float)(t->width > t->height ? t->width : t->height);
    float per_unit = m->edge > 0.0f && scale > 0.0f ? size * m->uv_edge / (m->edge * scale) : 0.0f;
    int on = t->lod_name && !(ctx->desc.debug_flags & STIN_DEBUG_DISPLACE_NO_MIP) &&
             ctx->vertex_chunk.tess[0] > 0.0f && per_unit > 0.0f;
    out[0] = on ? per_unit / ctx->vertex_chunk.tess[0] : 0.0f;
    out[1] = on ? (float)t->lod_top : 0.0f;
    out[2] = ctx->vertex_chunk.tess[3];
    out[3] = 0.0f;
}

void stin__displace_draw(stin_context *ctx, const stin__displace_locs *l, const stin__draw *d)
{
    const stin__texture_slot *t;
    float p[4] = {0.0f, 0.0f, 0.0f, -1.0f}, size[4], nm[9], lod[4];
    if (!l || l->params < 0)
        return;
    t = d && stin__displace_active(ctx, &d->material)
            ? stin__texture_lookup(ctx, d->material.height_map)
            : NULL;
    if (!t) {
        GL(ctx, Uniform4fv)(l->params, 1, p);
        return;
    }
    if (!l->patches) /* tessellation adds the vertices */
        log_coarse(ctx, d, t);
    p[0] = d->material.height_scale;
    p[1] = d->material.height_bias;
    p[2] = 1.0f;
    if (l->camera && !(ctx->desc.debug_flags & STIN_DEBUG_DISPLACE_NO_GUARD))
        p[3] = ctx->desc.displacement.guard_band;
    size[0] = (float)t->width;
    size[1] = (float)t->height;
    size[2] = ctx->desc.debug_flags & STIN_DEBUG_DISPLACE_MANUAL_BILINEAR ? 1.0f : 0.0f;
    size[3] = 0.0f;
    stin__mat3_normal(nm, d->transform);
    GL(ctx, Uniform4fv)(l->params, 1, p);
    GL(ctx, Uniform4fv)(l->size, 1, size);
    GL(ctx, UniformMatrix3fv)(l->normal, 1, GL_FALSE, nm);
    if (l->clip >= 0)
        GL(ctx, UniformMatrix4fv)(l->clip, 1, GL_FALSE, ctx->view_proj);
    lod_params(ctx, d, t, lod);
    GL(ctx, Uniform4fv)(l->lod, 1, lod);
    GL(ctx, Uniform3fv)(l->eye, 1, ctx->vertex_chunk.tess_eye);
    if (l->patches) {
        GL(ctx, Uniform4fv)(l->tess, 1, ctx->vertex_chunk.tess);
        GL(ctx, Uniform3fv)(l->tess_eye, 1, ctx->vertex_chunk.tess_eye);
    }
    GL(ctx, Uniform1i)(l->map, ctx->sel.displace_unit);
    stin__bind_unit(ctx, ctx->sel.displace_unit, GL_TEXTURE_2D, lod[1] > 0.0f ? t->lod_name : t->name);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
}
