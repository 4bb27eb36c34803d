/* SPDX-License-Identifier: MIT */
/* Shadow maps with percentage-closer filtering on the GLSL tiers ("map-pcf").
 *
 * Every spot and directional light gets a depth map (an FBO with a depth
 * texture, compare mode LEQUAL, LINEAR: each tap is the hardware's 2x2 PCF)
 * drawn before the camera's passes; a point light gets six 90-degree maps,
 * drawn just before its lit pass into six shared textures, and the shader
 * picks the face by the major axis of the light-to-point direction. The lit
 * pass's shadow_pcf.glsl chunk shadows a point whose side the eye sees turns
 * away from the light, else pushes it along its geometric normal toward the
 * eye (normal-offset bias: 1.5 texels' width at the point, so a wide depth
 * range does not inflate it at the receivers near the light), projects it,
 * and averages a (2r+1)^2 kernel (r = pcf_kernel / 2). Maps are drawn with
 * polygon offset (the light's shadow_offset: slope-scaled bias). */
#include "internal.h"

struct stin__map_pcf_state {
    GLuint textures[STIN__MAP_SLOTS];
    GLuint fbo;
    uint32_t size;
    int unit;             /* first sampler unit (STIN__SHADOW_SAMPLERS of them) */
    unsigned char valid[STIN__MAX_LIGHTS];
    float matrix[STIN__MAP_SLOTS][16];   /* world -> [0,1] map space */
    float normal_offset[STIN__MAP_SLOTS]; /* world units per unit clip w: 1.5 texels */
    /* the light being shaded: kind 0 none, 1 its map, 2 its six faces */
    int kind;
    uint32_t light;
};

size_t stin__map_pcf_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(struct stin__map_pcf_state);
}

#define FACE_SLOT STIN__FACE_SLOT

static void create_depth_texture(stin_context *ctx, GLuint *t, uint32_t size)
{
    GL(ctx, GenTextures)(1, t);
    stin__rt_shadow_map(ctx, *t, (int)size, (int)size);
}

static stin_result pcf_init(stin_context *ctx)
{
    struct stin__map_pcf_state *m = ctx->map_pcf;
    uint32_t i, size = ctx->desc.shadows.map_size;
    if (ctx->caps.max_texture_size > 0 && size > (uint32_t)ctx->caps.max_texture_size)
        size = (uint32_t)ctx->caps.max_texture_size;
    m->size = size;
    m->unit = ctx->sel.shadow_unit;
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    for (i = 0; i < ctx->desc.max_lights; i++)
        create_depth_texture(ctx, &m->textures[i], size);
    for (i = 0; i < STIN__CUBE_FACES; i++)
        create_depth_texture(ctx, &m->textures[FACE_SLOT + i], size);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL(ctx, GenFramebuffers)(1, &m->fbo);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, m->fbo);
    GL(ctx, DrawBuffer)(GL_NONE); /* depth only */
    GL(ctx, ReadBuffer)(GL_NONE);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, 0);
    stin__gl_check_errors(ctx, "pcf set-up");
    return STIN_OK;
}

static void pcf_release(stin_context *ctx)
{
    struct stin__map_pcf_state *m = ctx->map_pcf;
    uint32_t i;
    for (i = 0; i < STIN__MAP_SLOTS; i++)
        if (m->textures[i])
            GL(ctx, DeleteTextures)(1, &m->textures[i]);
    if (m->fbo)
        GL(ctx, DeleteFramebuffers)(1, &m->fbo);
    stin__memzero(m, sizeof *m);
}

static void draw_map(stin_context *ctx, uint32_t slot, const stin_light_desc *l,
                     const float view[16], const float proj[16])
{
    const struct stin__map_pcf_state *m = ctx->map_pcf;
    stin__pass_state ps = stin__pass_defaults;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, m->fbo);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D,
                                  m->textures[slot], 0);
    GL(ctx, Viewport)(0, 0, (GLsizei)m->size, (GLsizei)m->size);
    ps.depth_test = 1;
    ps.color_write = 0;
    ps.polygon_offset = (unsigned char)stin__map_offset(l, &ps.offset_factor, &ps.offset_units);
    stin__pass_apply(ctx, &ps);
    GL(ctx, ClearDepth)(1.0);
    GL(ctx, Clear)(GL_DEPTH_BUFFER_BIT);
    {
        const int map_vp[4] = {0, 0, (int)m->size, (int)m->size};
        if (stin__casters_cast(ctx, stin__path_of(ctx), view, proj, map_vp, m->fbo, 0,
                               ps.polygon_offset ? ps.offset_factor : 0.0f,
                               ps.polygon_offset ? ps.offset_units : 0.0f))
            stin__pass_apply(ctx, &ps); /* the casters' state again */
    }
    stin__path_of(ctx)->depth(ctx, view, proj);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    GL(ctx, Viewport)(ctx->frame.viewport[0], ctx->frame.viewport[1], ctx->frame.viewport[2],
                      ctx->frame.viewport[3]);
    stin__light_window_matrix(ctx->map_pcf->matrix[slot], view, proj); /* world -> [0,1] */
    ctx->stats.passes++;
}

/* 1.5 texels' width in world units per unit of the map's clip w: a texel
 * of an orthographic map (w = 1) is 2 / (proj[0] size) wide everywhere, a
 * perspective one's that times its distance along the light's axis (w), so
 * the shader's offset is 1.5 texels at each receiver, however wide the
 * depth range the map spans. */
static float texel_offset(const float proj[16], uint32_t size)
{
    return 1.5f * 2.0f / (proj[0] * (float)size);
}

/* Maps of every spot and directional light, before the camera's passes. */
static void pcf_prepass(stin_context *ctx)
{
    struct stin__map_pcf_state *m = ctx->map_pcf;
    uint32_t i;
    ctx->stats.shadows.map_size = m->size;
    for (i = 0; i < ctx->light_count && i < STIN__MAX_LIGHTS; i++) {
        const stin_light_desc *l = &ctx->lights[i];
        float view[16], proj[16], n, f;
        m->valid[i] = 0;
        if (l->type == STIN_LIGHT_POINT)
            continue; /* its faces are drawn before its own pass */
        if (!stin__light_camera(ctx, l, view, proj, &n, &f, m->size))
            continue;
        draw_map(ctx, i, l, view, proj);
        m->normal_offset[i] = texel_offset(proj, m->size);
        m->valid[i] = 1;
    }
    stin__gl_check_errors(ctx, "pcf maps");
}

/* A point light's six faces, just before its pass; 1 if drawn. */
static int draw_faces(stin_context *ctx, uint32_t li)
{
    const stin_light_desc *l = &ctx->lights[li];
    int face, any = 0;
    for (face = 0; face < STIN__CUBE_FACES; face++) {
        float view[16], proj[16];
        uint32_t slot = FACE_SLOT + (uint32_t)face;
        stin__light_cube_face(ctx, l->position, face, view, proj);
        draw_map(ctx, slot, l, view, proj);
        /* every face is 90 degrees: one offset per unit w serves the six */
        ctx->map_pcf->normal_offset[FACE_SLOT] = texel_offset(proj, ctx->map_pcf->size);
        any = 1;
    }
    return any;
}

/* The shadow test's uniforms on program p for the light being shaded:
 * kind 0 (none), 1 (the light's map) or 2 (a point light's faces). Every
 * shadow sampler sits on a unit of its own, used or not: two samplers of
 * different types on one unit are an error at draw time. */
static void pcf_uniforms(stin_context *ctx, const stin__program *p)
{
    const struct stin__map_pcf_state *m = ctx->map_pcf;
    float params[4] = {0, 0, 0, 0}, mats[STIN__SHADOW_SAMPLERS * 16];
    int i, kind = m->kind, count = kind == 2 ? STIN__SHADOW_SAMPLERS : 1;
    uint32_t li = m->light;
    if (p->u_shadow_kind < 0)
        return;
    GL(ctx, Uniform1i)(p->u_shadow_kind, kind);
    for (i = 0; i < STIN__SHADOW_SAMPLERS; i++)
        GL(ctx, Uniform1i)(p->u_shadow_maps[i], m->unit + i);
    if (kind == 0)
        return;
    for (i = 0; i < count; i++) {
        uint32_t slot = kind == 2 ? FACE_SLOT + (uint32_t)i : li;
        stin__memcopy(mats + 16 * i, m->matrix[slot], 16 * sizeof(float));
        stin__bind_unit(ctx, m->unit + i, GL_TEXTURE_2D, m->textures[slot]);
    }
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, UniformMatrix4fv)(p->u_shadow_matrix, count, GL_FALSE, mats);
    params[0] = 1.0f / (float)m->size;
    params[1] = (float)(ctx->lights[li].pcf_kernel / 2u);
    params[2] = m->normal_offset[kind == 2 ? FACE_SLOT : li];
    GL(ctx, Uniform4fv)(p->u_shadow_params, 1, params);
}

/* The lit program does the test: the light's map, or its six faces drawn
 * now (mid-frame, between the camera's passes). */
static void pcf_light(stin_context *ctx, const stin__path *path, uint32_t li, stin__shade_fn shade)
{
    struct stin__map_pcf_state *m = ctx->map_pcf;
    const stin_light_desc *l = &ctx->lights[li];
    m->light = li;
    m->kind = l->type == STIN_LIGHT_POINT ? (draw_faces(ctx, li) ? 2 : 0) : (m->valid[li] ? 1 : 0);
    shade(ctx, path, l, 1.0f);
    m->kind = 0;
}

/* Every light: the lit programs test its map (a point light's faces are
 * drawn just before its pass). */
static int pcf_fragment_test(const stin_context *ctx, uint32_t li)
{
    (void)ctx;
    (void)li;
    return 1;
}

/* A spot or directional light's map, for looking at. */
static stin_result pcf_debug_map(const stin_context *ctx, uint32_t li, stin_debug_map *out)
{
    if (!ctx->map_pcf->valid[li])
        return STIN_ERROR_UNSUPPORTED;
    out->texture = ctx->map_pcf->textures[li];
    out->size = out->allocated = ctx->map_pcf->size;
    out->depth = 1;
    return STIN_OK;
}

const stin__shadow_technique stin__shadow_map_pcf = {
    .glsl_chunk = "shadow_pcf.glsl",
    .init = pcf_init,
    .release = pcf_release,
    .light_prepass = pcf_prepass,
    .light = pcf_light,
    .uniforms = pcf_uniforms,
    .fragment_test = pcf_fragment_test,
    .debug_map = pcf_debug_map,
};
