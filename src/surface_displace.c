/* SPDX-License-Identifier: MIT */
/* Displacement "displace" (GL2/GL4): vertex texture fetch of the material's
 * height map in every vertex stage that draws meshes (shaders/gl2/
 * displace.glsl, spliced in by shader.c), so the lit, ambient, flat and
 * normal passes, shadow-map depth and vdsm's buffers all see one displaced
 * surface. Here: the per-draw uniforms, the height map's vertex unit, the
 * step down beside stencil volumes and the coarse-mesh log. */
#include "internal.h"

/* Average edge of a mesh in texels of a map above which VTF shows facets. */
#define COARSE_TEXELS 4.0f

int stin__displace_built(const stin_context *ctx)
{
    return ctx->sel.choice[STIN_FEATURE_DISPLACEMENT].technique == STIN_TECH_DISPLACEMENT_VTF;
}

void stin__displace_init(stin_context *ctx)
{
    ctx->displace.logged_count = 0;
    if (stin__displace_built(ctx) &&
        ctx->sel.choice[STIN_FEATURE_SHADOWS].technique == STIN_TECH_SHADOWS_VOLUME)
        stin__demote(ctx, STIN_FEATURE_DISPLACEMENT, STIN_TECH_DISPLACEMENT_OFF,
                     "shadows fell back to volume, whose silhouettes are the undisplaced "
                     "mesh's: displaced draws would cast the flat mesh's shadow");
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
    out->camera = camera;
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
    for (i = 0; i < ctx->displace.logged_count; i++)
        if (ctx->displace.logged[i] == key)
            return;
    if (ctx->displace.logged_count == sizeof ctx->displace.logged / sizeof ctx->displace.logged[0])
        return;
    ctx->displace.logged[ctx->displace.logged_count++] = key;
    stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
              "displace: a mesh of %u vertices is coarse for its %ux%u height map (edges span "
              "%d texels on average): the relief shows only at the vertices (subdivide it: "
              "stin_mesh_desc.subdivide)", m->vertex_count, t->width, t->height, (int)texels);
}

void stin__displace_draw(stin_context *ctx, const stin__displace_locs *l, const stin__draw *d)
{
    const stin__texture_slot *t;
    float p[4] = {0.0f, 0.0f, 0.0f, -1.0f}, size[4], nm[9];
    if (!l || l->params < 0)
        return;
    t = stin__displace_active(ctx, &d->material) ? stin__texture_lookup(ctx, d->material.height_map)
                                                 : NULL;
    if (!t) {
        GL(ctx, Uniform4fv)(l->params, 1, p);
        return;
    }
    log_coarse(ctx, d, t);
    p[0] = d->material.height_scale;
    p[1] = d->material.height_bias;
    p[2] = 1.0f;
    if (l->camera && !(ctx->desc.debug_flags & STIN_DEBUG_DISPLACE_NO_GUARD))
        p[3] = ctx->desc.displace_guard_band;
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
    GL(ctx, Uniform1i)(l->map, ctx->sel.displace_unit);
    stin__bind_unit(ctx, ctx->sel.displace_unit, GL_TEXTURE_2D, t->name);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
}
