/* SPDX-License-Identifier: MIT */
/* Shadow maps with percentage-closer filtering on the GLSL tiers ("map-pcf").
 *
 * Every spot and directional light gets a depth map (an FBO with a depth
 * texture, compare mode LEQUAL, LINEAR: each tap is the hardware's 2x2 PCF)
 * drawn before the camera's passes; a point light gets six 90-degree maps,
 * drawn just before its lit pass into the cells of one shared atlas (3 x 2
 * faces: one sampler, so a fragment pays one face's taps, not every face's
 * behind a branch), and the shader picks the face by the major axis of the
 * light-to-point direction and keeps its taps inside that face's cell. A
 * face gets only the casters whose bounds meet its frustum (the rest would
 * be clipped away), and a face no visible draw's bounds reach is not drawn
 * at all (no visible point picks it). The lit
 * pass's shadow_pcf.glsl chunk shadows a point whose side the eye sees turns
 * away from the light, else projects it and averages a (2r+1)^2 kernel
 * (r = pcf_kernel / 2), each tap against its receiver plane's depth there
 * (receiver-plane bias); only a point the light grazes is pushed along its
 * geometric normal toward the eye first (normal offset: up to 1.5 texels'
 * width at the point, so a wide depth range does not inflate it at the
 * receivers near the light; none where the light meets the receiver more
 * squarely, where a push would move the shadow's edge). Maps are drawn with
 * polygon offset (the light's shadow_offset: slope-scaled bias). An area
 * light (radius > 0, spot or point) is filtered by percentage-closer soft
 * shadows instead of the kernel: a blocker search sized by the light's
 * radius in the map, then a disc of taps as wide as the penumbra the
 * blockers' mean depth gives (shadow_pcf.glsl). Without depth textures
 * (bare OpenGL ES 2.0) each map is an RGBA8 colour texture that holds the
 * casters' window depth in 24 bits (pack_depth.glsl), drawn with a depth
 * renderbuffer of its size beside it, and the taps unpack and compare it
 * (pcf_tap_depth.glsl). The test
 * is all in the lit program, so the frame may draw light 0's pass in its
 * ambient pass's place (`forward`: one camera pass for one light). */
#include "internal.h"
#include "render/draw_bounds.h"

struct stin__map_pcf_state {
    GLuint textures[STIN__MAX_LIGHTS];
    GLuint atlas;         /* a point light's six faces, STIN__ATLAS_COLUMNS x STIN__ATLAS_ROWS cells */
    GLuint fbo;
    uint32_t size;        /* a spot or directional map's texels a side */
    uint32_t face_size;   /* a face's: size, halved while the atlas exceeds the limit */
    int unit;             /* the sampler's unit */
    unsigned char valid[STIN__MAX_LIGHTS];
    float matrix[STIN__MAP_SLOTS][16];   /* world -> [0,1] map space */
    float normal_offset[STIN__MAP_SLOTS]; /* world units per unit clip w: 1.5 texels */
    /* an area light's taps' spread: texels per unit of window depth per
     * unit of radius (0: an orthographic map), window depth per unit of
     * 1 / distance, and 1 / proj[0] (soft_spread) */
    float spread[STIN__MAP_SLOTS][3];
    /* how the lit programs read the maps: 1 they compare (ARB_shadow), 0
     * they are depth textures read as numbers, compared in the shader */
    int compare;
    /* no depth textures: the maps are colour, their depth packed; the depth
     * test's renderbuffers, a map's size and the atlas's */
    int packed;
    GLuint depth_rb[2];
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

/* A map: a comparing depth texture, or without shadow compare one read as a
 * number (nearest texels: the shader filters its compares itself), its
 * internal format unsized as OES_depth_texture requires (format, internal
 * format and GL_UNSIGNED_INT: ES 2.0's only depth-texture form); without
 * depth textures an RGBA8 one (unsized: ES 2.0's form) the depth is packed
 * into. */
static void create_depth_texture(stin_context *ctx, GLuint *t, uint32_t w, uint32_t h)
{
    GL(ctx, GenTextures)(1, t);
    if (ctx->map_pcf->packed)
        stin__rt_texture(ctx, *t, GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, (int)w, (int)h);
    else if (ctx->map_pcf->compare)
        stin__rt_shadow_map(ctx, *t, (int)w, (int)h);
    else
        stin__rt_texture(ctx, *t, GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT,
                         (int)w, (int)h);
}

/* The lit programs' tap (shaders/gl2/pcf_tap_*.glsl): the sampler's compare
 * where there is one, else the shader's. */
static const char *pcf_tap_chunk(const stin_context *ctx)
{
    return ctx->caps.present & STIN_CAP_BIT(STIN_CAP_SHADOW) ? "pcf_tap_compare.glsl"
                                                             : "pcf_tap_depth.glsl";
}

static stin_result pcf_init(stin_context *ctx)
{
    struct stin__map_pcf_state *m = ctx->map_pcf;
    uint32_t i, size = ctx->desc.shadows.map_size;
    if (ctx->caps.max_texture_size > 0 && size > (uint32_t)ctx->caps.max_texture_size)
        size = (uint32_t)ctx->caps.max_texture_size;
    m->size = size;
    m->face_size = size;
    while (ctx->caps.max_texture_size > 0 && m->face_size > 1u &&
           STIN__ATLAS_COLUMNS * m->face_size > (uint32_t)ctx->caps.max_texture_size)
        m->face_size /= 2u; /* three faces across must fit */
    m->unit = ctx->sel.shadow_unit;
    m->packed = !(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE));
    m->compare = !m->packed && (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_SHADOW)) != 0;
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    for (i = 0; i < ctx->desc.max_lights; i++)
        create_depth_texture(ctx, &m->textures[i], size, size);
    create_depth_texture(ctx, &m->atlas, STIN__ATLAS_COLUMNS * m->face_size,
                         STIN__ATLAS_ROWS * m->face_size);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL(ctx, GenFramebuffers)(1, &m->fbo);
    if (m->packed) { /* every attachment of an ES 2.0 framebuffer has one size */
        m->depth_rb[0] = stin__rt_depth_renderbuffer(ctx, (int)size, (int)size);
        m->depth_rb[1] = stin__rt_depth_renderbuffer(ctx, (int)(STIN__ATLAS_COLUMNS * m->face_size),
                                                     (int)(STIN__ATLAS_ROWS * m->face_size));
        return STIN_OK;
    }
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, m->fbo);
    stin__no_colour_buffers(ctx); /* depth only */
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, 0);
    return STIN_OK;
}

static void pcf_release(stin_context *ctx)
{
    struct stin__map_pcf_state *m = ctx->map_pcf;
    uint32_t i;
    for (i = 0; i < STIN__MAX_LIGHTS; i++)
        if (m->textures[i])
            GL(ctx, DeleteTextures)(1, &m->textures[i]);
    if (m->atlas)
        GL(ctx, DeleteTextures)(1, &m->atlas);
    if (m->fbo)
        GL(ctx, DeleteFramebuffers)(1, &m->fbo);
    for (i = 0; i < 2u; i++)
        if (m->depth_rb[i])
            GL(ctx, DeleteRenderbuffers)(1, &m->depth_rb[i]);
    stin__memzero(m, sizeof *m);
}

/* Where a map pass draws: a texture, the rectangle of it, whether to
 * clear the texture first (an atlas is cleared once for all its faces),
 * and which of the casters (keep NULL: all). */
typedef struct map_target {
    GLuint texture;
    int rect[4];
    int clear;
    stin__draw_keep_fn keep;
    const void *user;
} map_target;

/* Attaches t's map (a packed one with its depth renderbuffer), or with
 * texture 0 detaches it. */
static void attach_map(stin_context *ctx, GLuint texture)
{
    const struct stin__map_pcf_state *m = ctx->map_pcf;
    if (!m->packed) {
        GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture,
                                      0);
        if (texture && !m->compare)
            stin__rt_depth_measure(ctx); /* the unsized texture's bits: the offset's step */
        return;
    }
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture,
                                  0);
    GL(ctx, FramebufferRenderbuffer)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                     !texture              ? 0
                                     : texture == m->atlas ? m->depth_rb[1]
                                                           : m->depth_rb[0]);
}

/* The casters drawn into the map's rectangle from the light (view, proj),
 * the texture cleared first where asked; the frame's framebuffer and
 * viewport back after. Returns the draws drawn. */
static uint32_t draw_map(stin_context *ctx, const map_target *t, const stin_light_desc *l,
                         const float view[16], const float proj[16])
{
    const struct stin__map_pcf_state *m = ctx->map_pcf;
    stin__pass_state ps = stin__pass_defaults;
    uint32_t drawn;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, m->fbo);
    attach_map(ctx, t->texture);
    GL(ctx, Viewport)(t->rect[0], t->rect[1], t->rect[2], t->rect[3]);
    ps.depth_test = 1;
    ps.color_write = (unsigned char)m->packed;
    ps.polygon_offset = (unsigned char)stin__map_offset(ctx, l, &ps.offset_factor, &ps.offset_units);
    stin__pass_apply(ctx, &ps);
    if (t->clear) {
        stin__clear_depth(ctx, 1.0);
        if (m->packed) /* white: depth 1 packed, nothing cast */
            GL(ctx, ClearColor)(1.0f, 1.0f, 1.0f, 1.0f);
        GL(ctx, Clear)(GL_DEPTH_BUFFER_BIT | (m->packed ? GL_COLOR_BUFFER_BIT : 0u));
    }
    if (stin__casters_cast(ctx, stin__path_of(ctx), view, proj, t->rect, m->fbo, 0,
                           ps.polygon_offset ? ps.offset_factor : 0.0f,
                           ps.polygon_offset ? ps.offset_units : 0.0f))
        stin__pass_apply(ctx, &ps); /* the casters' state again */
    drawn = stin__glsl_depth_kept(ctx, view, proj, t->keep, t->user);
    attach_map(ctx, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    GL(ctx, Viewport)(ctx->frame.viewport[0], ctx->frame.viewport[1], ctx->frame.viewport[2],
                      ctx->frame.viewport[3]);
    ctx->stats.passes++;
    return drawn;
}

/* 1.5 texels' width in world units per unit of the map's clip w (the
 * normal offset of a grazed receiver, shadow_pcf.glsl): a texel
 * of an orthographic map (w = 1) is 2 / (proj[0] size) wide everywhere, a
 * perspective one's that times its distance along the light's axis (w), so
 * the shader's offset is 1.5 texels at each receiver, however wide the
 * depth range the map spans. */
static float texel_offset(const float proj[16], uint32_t size)
{
    return 1.5f * 2.0f / (proj[0] * (float)size);
}

/* How an area light's taps spread in a perspective map of size texels:
 * window depth is 0.5 proj[14] / w plus a constant (w the distance along
 * the axis), and the ray from a receiver at w_r to a point r u of the
 * light's disc (u in the unit disc) crosses w_b 0.5 proj[0] r (1 / w_b -
 * 1 / w_r) u away in [0,1]: proj[0] size / -proj[14] texels per unit of
 * window depth per unit of radius (x), -0.5 proj[14] window depth per unit
 * of 1 / w (y), and 1 / proj[0] (z) for the receiver's slope. An
 * orthographic map (a directional light: no radius) spreads nothing. */
static void soft_spread(float out[3], const float proj[16], uint32_t size)
{
    int perspective = proj[11] != 0.0f && proj[14] != 0.0f;
    out[0] = perspective ? proj[0] * (float)size / -proj[14] : 0.0f;
    out[1] = -0.5f * proj[14];
    out[2] = 1.0f / proj[0];
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
        {
            const map_target t = {m->textures[i], {0, 0, (int)m->size, (int)m->size}, 1, NULL,
                                  NULL};
            (void)draw_map(ctx, &t, l, view, proj);
        }
        stin__light_window_matrix(m->matrix[i], view, proj); /* world -> [0,1] */
        m->normal_offset[i] = texel_offset(proj, m->size);
        soft_spread(m->spread[i], proj, m->size);
        m->valid[i] = 1;
    }
}

/* ---- a point light's faces ------------------------------------------------ */

/* Face f's four side planes (its 90-degree pyramid from the light; near
 * and far left out: the depth range covers every caster): inside where the
 * face's axis component of p - light is at least the other two's size. */
static void face_planes(const float light[3], int face, float planes[4][4])
{
    int axis = face / 2, i, k;
    float sign = face % 2 ? -1.0f : 1.0f;
    for (i = 0; i < 4; i++) {
        int other = (axis + 1 + i / 2) % 3;
        float n[3] = {0, 0, 0};
        n[axis] = sign;
        n[other] = i % 2 ? -1.0f : 1.0f;
        for (k = 0; k < 3; k++)
            planes[i][k] = n[k];
        planes[i][3] = -(n[0] * light[0] + n[1] * light[1] + n[2] * light[2]);
    }
}

/* The faces (bit f) some visible point may pick: those a draw's bounds
 * meet inside the camera's frustum. A draw whose bounds tell nothing, or
 * the CSG products (their faces are not the frame's draws), keep all six. */
static unsigned faces_seen(const stin_context *ctx, const float light[3])
{
    float cam[6][4], planes[STIN__CUBE_FACES][4][4];
    unsigned seen = 0;
    uint32_t i;
    int face;
    if (stin__casters_wanted(ctx))
        return 0x3fu;
    stin__frustum_planes(ctx->view_proj, cam);
    for (face = 0; face < STIN__CUBE_FACES; face++)
        face_planes(light, face, planes[face]);
    for (i = 0; i < ctx->draw_count && seen != 0x3fu; i++) {
        float corners[24];
        if (!stin__draw_world_corners(ctx, &ctx->draws[i], corners))
            return 0x3fu;
        if (!stin__points_meet(corners, 8, cam[0], 6))
            continue;
        for (face = 0; face < STIN__CUBE_FACES; face++)
            if (stin__points_meet(corners, 8, planes[face][0], 4))
                seen |= 1u << face;
    }
    return seen;
}

/* A face's casters: those whose bounds meet its pyramid (user: its planes). */
static int in_face(const stin_context *ctx, const stin__draw *d, const void *user)
{
    float corners[24];
    if (!stin__draw_world_corners(ctx, d, corners))
        return 1;
    return stin__points_meet(corners, 8, (const float *)user, 4);
}

/* A point light's faces, just before its pass, each into its cell of the
 * atlas with only its own casters; the cells of faces no visible point
 * picks are left cleared (the lookups' clamp keeps every tap of a picked
 * face inside its own cell). The whole atlas is cleared once: on llvmpipe
 * a clear scissored to each cell cost more than the faces' drawing. */
static void draw_faces(stin_context *ctx, uint32_t li)
{
    struct stin__map_pcf_state *m = ctx->map_pcf;
    const stin_light_desc *l = &ctx->lights[li];
    unsigned seen = faces_seen(ctx, l->position);
    int face, s = (int)m->face_size, first = 1;
    for (face = 0; face < STIN__CUBE_FACES; face++) {
        float view[16], proj[16], planes[4][4];
        map_target t;
        if (!(seen & (1u << face)))
            continue;
        face_planes(l->position, face, planes);
        t.texture = m->atlas;
        t.clear = first;
        first = 0;
        t.rect[0] = (face % (int)STIN__ATLAS_COLUMNS) * s;
        t.rect[1] = (face / (int)STIN__ATLAS_COLUMNS) * s;
        t.rect[2] = t.rect[3] = s;
        t.keep = in_face;
        t.user = planes[0];
        stin__light_cube_face(ctx, l->position, face, view, proj);
        ctx->stats.shadows.map_face_casters += draw_map(ctx, &t, l, view, proj);
        ctx->stats.shadows.map_faces++;
        stin__light_window_matrix(m->matrix[FACE_SLOT + (uint32_t)face], view, proj);
        stin__light_into_cell(m->matrix[FACE_SLOT + (uint32_t)face], face);
        soft_spread(m->spread[FACE_SLOT + (uint32_t)face], proj, m->face_size);
        /* every face is 90 degrees: one offset per unit w serves the six */
        m->normal_offset[FACE_SLOT] = texel_offset(proj, m->face_size);
    }
}

/* The shadow test's uniforms on program p for the light being shaded:
 * kind 0 (none), 1 (the light's map) or 2 (a point light's atlas). The
 * one sampler is set on its unit even with no map: a sampler of another
 * type left on a unit it shares is an error at draw time. */
static void pcf_uniforms(stin_context *ctx, const stin__program *p)
{
    const struct stin__map_pcf_state *m = ctx->map_pcf;
    float params[4] = {0, 0, 0, 0}, mats[STIN__CUBE_FACES * 16], soft[STIN__CUBE_FACES * 3];
    int i, kind = m->kind, count = kind == 2 ? STIN__CUBE_FACES : 1;
    uint32_t li = m->light;
    if (p->u_shadow_kind < 0)
        return;
    GL(ctx, Uniform1i)(p->u_shadow_kind, kind);
    GL(ctx, Uniform1i)(p->u_shadow_map, m->unit);
    if (kind == 0)
        return;
    for (i = 0; i < count; i++) {
        uint32_t slot = kind == 2 ? FACE_SLOT + (uint32_t)i : li;
        stin__memcopy(mats + 16 * i, m->matrix[slot], 16 * sizeof(float));
        /* radius 0: no spread, the kernel's exact path */
        soft[3 * i] = ctx->lights[li].radius * m->spread[slot][0];
        soft[3 * i + 1] = m->spread[slot][1];
        soft[3 * i + 2] = m->spread[slot][2];
    }
    stin__bind_unit(ctx, m->unit, GL_TEXTURE_2D, kind == 2 ? m->atlas : m->textures[li]);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, UniformMatrix4fv)(p->u_shadow_matrix, count, GL_FALSE, mats);
    /* a texel's width (x) and height (w) in the texture's [0,1] */
    params[0] = 1.0f / (float)(kind == 2 ? STIN__ATLAS_COLUMNS * m->face_size : m->size);
    params[3] = 1.0f / (float)(kind == 2 ? STIN__ATLAS_ROWS * m->face_size : m->size);
    params[1] = (float)(ctx->lights[li].pcf_kernel / 2u);
    params[2] = m->normal_offset[kind == 2 ? FACE_SLOT : li];
    GL(ctx, Uniform4fv)(p->u_shadow_params, 1, params);
    GL(ctx, Uniform3fv)(p->u_shadow_soft, count, soft);
}

/* The lit program does the test: the light's map, or its six faces drawn
 * now (mid-frame, between the camera's passes). */
static void pcf_light(stin_context *ctx, const stin__path *path, uint32_t li, stin__shade_fn shade)
{
    struct stin__map_pcf_state *m = ctx->map_pcf;
    const stin_light_desc *l = &ctx->lights[li];
    m->light = li;
    if (l->type == STIN_LIGHT_POINT) {
        draw_faces(ctx, li);
        m->kind = 2;
    } else {
        m->kind = m->valid[li] ? 1 : 0;
    }
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
    out->depth = !ctx->map_pcf->packed; /* packed: RGBA8, 24 bits of depth in RGB */
    return STIN_OK;
}

const stin__shadow_technique stin__shadow_map_pcf = {
    .glsl_chunk = "shadow_pcf.glsl",
    .glsl_pre_chunk = pcf_tap_chunk,
    .init = pcf_init,
    .release = pcf_release,
    .light_prepass = pcf_prepass,
    .light = pcf_light,
    .uniforms = pcf_uniforms,
    .fragment_test = pcf_fragment_test,
    .forward = 1,
    .debug_map = pcf_debug_map,
};
