/* SPDX-License-Identifier: MIT */
/* One set of calls for the translucent-shadows feature, whichever technique
 * runs it: the frame plan, the lit programs and the shadows techniques ask
 * here, and each technique's module answers only when it is the one set up
 * (the others are no-ops). */
#include "translucent/translucent_private.h"

stin_log_level stin__translucent_fallback_level(const stin_context *ctx, int shadows_off)
{
    int forced = ctx->desc.techniques[STIN_FEATURE_TRANSLUCENT_SHADOWS] != STIN_TECH_NONE;
    return shadows_off && !forced ? STIN_LOG_LEVEL_INFO : STIN_LOG_LEVEL_WARNING;
}

int stin__translucent_chunks(const stin_context *ctx, int variant,
                             const char *names[STIN__FEATURE_CHUNKS])
{
    const char *deep = stin__deep_chunk(ctx);
    (void)variant; /* the same lookup under every surface */
    names[0] = deep ? deep : stin__coloured_chunk(ctx);
    return names[0] != NULL;
}

static void locate(stin_context *ctx, GLuint prog, stin__translucent_locs *l,
                   const char *const names[6])
{
    l->kind = GL(ctx, GetUniformLocation)(prog, names[0]);
    l->matrix = GL(ctx, GetUniformLocation)(prog, names[1]);
    l->params = GL(ctx, GetUniformLocation)(prog, names[2]);
    l->maps[0] = GL(ctx, GetUniformLocation)(prog, names[3]);
    l->maps[1] = GL(ctx, GetUniformLocation)(prog, names[4]);
    l->face_layers = names[5] ? GL(ctx, GetUniformLocation)(prog, names[5]) : -1;
}

void stin__translucent_locate(stin_context *ctx, stin__program *p)
{
    static const char *const deep[6] = {"u_deep_kind", "u_deep_matrix", "u_deep_params",
                                        "u_deep_even", "u_deep_odd", "u_deep_face_layers"};
    static const char *const coloured[6] = {"u_coloured_kind", "u_coloured_matrix",
                                            "u_coloured_params", "u_coloured_map",
                                            "u_coloured_depth", NULL};
    locate(ctx, p->name, &p->deep, deep);
    locate(ctx, p->name, &p->coloured, coloured);
}

int stin__translucent_set(stin_context *ctx, const stin__translucent_locs *l, int kind,
                          const float *matrices, const float params[4])
{
    int i;
    if (l->kind < 0)
        return 0;
    GL(ctx, Uniform1i)(l->kind, kind);
    for (i = 0; i < 2; i++)
        GL(ctx, Uniform1i)(l->maps[i], ctx->sel.translucent_unit + i);
    if (!kind)
        return 0;
    GL(ctx, UniformMatrix4fv)(l->matrix, kind == 2 ? STIN__DEEP_FACES : 1, GL_FALSE, matrices);
    GL(ctx, Uniform4fv)(l->params, 1, params);
    return 1;
}

void stin__translucent_uniforms(stin_context *ctx, const stin__program *p)
{
    stin__deep_uniforms(ctx, p);
    stin__coloured_uniforms(ctx, p);
}

void stin__translucent_frame(stin_context *ctx)
{
    int has = 0;
    uint32_t i;
    for (i = 0; i < ctx->draw_count && !has; i++)
        has = ctx->draws[i].material.color[3] < 1.0f;
    ctx->deep->frame_transparent = ctx->deep->ready && has;
    ctx->coloured->frame_transparent = ctx->coloured->ready && has;
    ctx->deep->kind = ctx->coloured->kind = 0;
}

int stin__translucent_active(const stin_context *ctx)
{
    return stin__deep_active(ctx) || stin__coloured_active(ctx);
}

int stin__translucent_skips(const stin_context *ctx, const stin__draw *d)
{
    float a = d->material.color[3];
    if (a >= 1.0f)
        return 0;
    if (ctx->deep->ready || ctx->coloured->ready)
        return 1; /* it shadows through its map */
    return ctx->sel.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].technique ==
               STIN_TECH_TRANSLUCENT_OPAQUE &&
           a < ctx->desc.translucent.opaque_threshold;
}

void stin__translucent_light(stin_context *ctx, uint32_t li)
{
    stin__deep_light(ctx, li);
    stin__coloured_light(ctx, li);
}

void stin__translucent_light_done(stin_context *ctx)
{
    stin__deep_light_done(ctx);
    stin__coloured_light_done(ctx);
}

void stin__translucent_draw_casters(stin_context *ctx, GLint u_model, GLint u_albedo,
                                    GLint u_has_albedo_tex, const stin__displace_locs *dl)
{
    uint32_t i;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[i];
        const stin__texture_slot *t;
        if (d->material.color[3] >= 1.0f)
            continue;
        t = stin__texture_lookup(ctx, d->material.albedo);
        GL(ctx, Uniform4fv)(u_albedo, 1, d->material.color);
        GL(ctx, Uniform1i)(u_has_albedo_tex, t != NULL);
        GL(ctx, BindTexture)(GL_TEXTURE_2D, t ? t->name : 0);
        stin__glsl_submit_geometry(ctx, u_model, dl, d);
    }
}

/* 1.5 texels' width in world units per unit of the face's clip w, as
 * map-pcf's normal offset. */
static float texel_offset(const float proj[16], uint32_t size)
{
    return 1.5f * 2.0f / (proj[0] * (float)size);
}

void stin__translucent_say_area(stin_context *ctx, const stin_light_desc *l, int *said,
                                const char *technique)
{
    if (*said || !(l->radius > 0.0f) || l->type == STIN_LIGHT_DIRECTIONAL)
        return;
    stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
              "%s: transparent casters shadow area lights from their centre (hard edges); "
              "opaque casters follow the shadow technique", technique);
    *said = 1;
}

int stin__translucent_faces(stin_context *ctx, const stin_light_desc *l, uint32_t size,
                            stin__translucent_face_fn face_fn, float *normal_offset)
{
    float view[16], proj[16], n, f;
    int face;
    if (l->type != STIN_LIGHT_POINT) {
        if (!stin__light_camera(ctx, l, view, proj, &n, &f, size))
            return 0;
        face_fn(ctx, 0, view, proj);
        *normal_offset = texel_offset(proj, size);
        return 1;
    }
    for (face = 0; face < STIN__DEEP_FACES; face++) {
        stin__light_cube_face(ctx, l->position, face, view, proj);
        face_fn(ctx, face, view, proj);
    }
    *normal_offset = texel_offset(proj, size); /* every face is 90 degrees */
    return 2;
}

void stin__translucent_unbind(stin_context *ctx, int unit, GLenum target)
{
    int i;
    for (i = 0; i < 2; i++)
        stin__bind_unit(ctx, unit + i, target, 0);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
}
