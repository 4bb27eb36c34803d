/* SPDX-License-Identifier: MIT */
/* Shadow maps without shaders (the GL1 tier's two map techniques).
 *
 * map-depth: ARB_depth_texture + ARB_shadow. The light's depth (with polygon
 * offset) goes into a depth texture — rendered into an FBO where there is one,
 * else into the frame's own framebuffer before its clear and copied out. The
 * lit pass generates (s, t, r, q) in light clip space by eye-linear texgen and
 * the texture unit compares r/q with the stored depth (LEQUAL), LINEAR filtering
 * giving the hardware's 2x2 PCF, and modulates the light's colour. The
 * next unit tests which side of the surface the light sees against the side
 * the eye sees (shadow/map_facing.c), so an open surface seen from the side
 * the light does not reach is in shadow; with FBOs the maps are second-depth
 * maps for closed solids and one more unit keeps their terminator band
 * lit (shadow/map_terminator.c).
 *
 * map-combine: for TNT-class hardware without depth textures. The light's
 * depth is drawn as colour (a 1D ramp indexed by texgen of the light-eye
 * depth, near/far fitted to the scene so 8 bits cover it) and copied into an
 * INTENSITY8 texture. In the lit pass one unit projects the map (stored depth
 * in alpha), the next looks the fragment's own light depth up in the same
 * ramp, and texture_env_combine forms map - own + 0.5 (ADD_SIGNED with
 * ONE_MINUS_SRC_ALPHA); the alpha test GEQUAL 0.5 keeps the lit fragments.
 *
 * Spot lights get a perspective map over their cone, directional lights an
 * orthographic one fitted to the draws. Point lights get six 90-degree maps
 * drawn mid-frame where there are FBOs (map-depth), kept to their squares by
 * a mask unit; elsewhere they fall back to stencil volumes (or none) and the
 * log says so once; the CSG products cast for them as volumes cast them
 * (shadow/cast_map.c's map, marked after each count). */
#include "shadow/map_fixed_private.h"

/* The face mask's border texel lies just outside the 90-degree square: the
 * face frustum is widened so that the square's edge falls exactly between
 * the border texel and the first inner one (NEAREST sampling). */
#define FACE_MASK 256u

size_t stin__map_fixed_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(struct stin__map_fixed_state);
}

static int combine(const stin_context *ctx)
{
    return ctx->sel.choice[STIN_FEATURE_SHADOWS].technique == STIN_TECH_SHADOWS_MAP_COMBINE;
}

/* map-combine renders into its texture where FBOs and depth textures exist. */
static int combine_fbo(const stin_context *ctx)
{
    uint64_t need = STIN_CAP_BIT(STIN_CAP_FBO) | STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE);
    return combine(ctx) && (ctx->caps.present & need) == need;
}

static void create_map_texture(stin_context *ctx, GLuint *t, uint32_t size)
{
    GL(ctx, GenTextures)(1, t);
    if (combine(ctx)) {
        /* stored depths must not be averaged: nearest. Rendered into (FBO:
         * RGBA8, colour-renderable, the ramp in every channel) or copied
         * into (INTENSITY8). */
        stin__rt_texture(ctx, *t, combine_fbo(ctx) ? GL_RGBA8 : GL_INTENSITY8, GL_LUMINANCE,
                         GL_UNSIGNED_BYTE, (int)size, (int)size);
    } else {
        /* compare, then filter: LINEAR is the hardware's 2x2 PCF */
        stin__rt_shadow_map(ctx, *t, (int)size, (int)size);
        GL_ENUM(ctx, TexParameteri, GL_DEPTH_TEXTURE_MODE)(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE,
                                                           GL_INTENSITY);
    }
}

static stin_result fixed_init(stin_context *ctx)
{
    uint32_t i, size = ctx->desc.shadows.map_size;
    int units = combine(ctx) ? 2 : 1, faces;
    /* after the surface technique's units (selection placed them) */
    ctx->map_fixed->unit = ctx->sel.shadow_unit;
    if (ctx->caps.max_texture_size > 0 && size > (uint32_t)ctx->caps.max_texture_size)
        size = stin__pow2_at_most((uint32_t)ctx->caps.max_texture_size);
    ctx->map_fixed->size = size;
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    for (i = 0; i < ctx->desc.max_lights; i++)
        create_map_texture(ctx, &ctx->map_fixed->textures[i], size);
    if (combine(ctx))
        ctx->map_fixed->ramp = stin__map_ramp_create(ctx);
    if (combine_fbo(ctx)) {
        /* the colour, each map's, is attached as it is drawn */
        GL(ctx, GenTextures)(1, &ctx->map_fixed->depth_scratch);
        stin__rt_texture(ctx, ctx->map_fixed->depth_scratch, GL_DEPTH_COMPONENT24,
                         GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, (int)size, (int)size);
        GL(ctx, GenFramebuffers)(1, &ctx->map_fixed->fbo);
        (void)stin__rt_attach(ctx, ctx->map_fixed->fbo, 0, ctx->map_fixed->depth_scratch, 0);
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, 0);
    } else if (!combine(ctx) && (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FBO))) {
        /* depth only: no colour buffer to draw or read (the side test's
         * colour, when there is one, is attached by its init) */
        GL(ctx, GenFramebuffers)(1, &ctx->map_fixed->fbo);
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->map_fixed->fbo);
        GL(ctx, DrawBuffer)(GL_NONE);
        GL(ctx, ReadBuffer)(GL_NONE);
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, 0);
    }
    if (!combine(ctx))
        stin__map_facing_init(ctx, 0);
    else /* one comparison a pass: no second-depth map without its two tests */
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                  "shadows: map-combine decides self-shadowing by the facet (terminator steps, "
                  "acne): its combiners cannot join the side and far-side tests to its depth "
                  "comparison");
    units += ctx->map_fixed->facing_test;
    /* point lights: six maps drawn mid-frame (FBOs), shared by all of them,
     * and a mask unit that keeps each face to its own 90-degree square; the
     * terminator test's unit only after these (shadows before their shape) */
    faces = ctx->map_fixed->fbo && !combine(ctx) &&
            ctx->map_fixed->unit + units + 1 <= ctx->caps.max_texture_units &&
            (FACE_MASK * FACE_MASK) <= ctx->staging_bytes + ctx->scratch_bytes;
    if (ctx->map_fixed->facing_test)
        stin__map_terminator_init(ctx, units + faces);
    for (i = 0; i < ctx->desc.max_lights; i++)
        stin__map_facing_create(ctx, i);
    if (faces) {
        unsigned char *m = ctx->staging_bytes >= FACE_MASK * FACE_MASK ? ctx->staging : ctx->scratch;
        uint32_t x, y;
        for (i = 0; i < STIN__CUBE_FACES; i++) {
            create_map_texture(ctx, &ctx->map_fixed->textures[STIN__FACE_SLOT + i], size);
            stin__map_facing_create(ctx, STIN__FACE_SLOT + i);
        }
        for (y = 0; y < FACE_MASK; y++)
            for (x = 0; x < FACE_MASK; x++)
                m[y * FACE_MASK + x] =
                    (x == 0 || y == 0 || x == FACE_MASK - 1 || y == FACE_MASK - 1) ? 0 : 255;
        GL(ctx, GenTextures)(1, &ctx->map_fixed->face_mask);
        GL(ctx, BindTexture)(GL_TEXTURE_2D, ctx->map_fixed->face_mask);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        stin__upload_bytes(ctx, GL_TEXTURE_2D, GL_LUMINANCE, FACE_MASK, FACE_MASK, GL_LUMINANCE, m);
        ctx->map_fixed->faces = 1;
    }
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    /* point lights without faces go to volumes: the CSG products cast
     * for them through volumes' own map (shadow/cast_map.c) */
    if (!ctx->map_fixed->faces)
        stin__cast_map_init(ctx, 0);
    return STIN_OK;
}

static void fixed_release(stin_context *ctx)
{
    uint32_t i;
    for (i = 0; i < STIN__MAP_SLOTS; i++)
        if (ctx->map_fixed->textures[i]) {
            GL(ctx, DeleteTextures)(1, &ctx->map_fixed->textures[i]);
            ctx->map_fixed->textures[i] = 0;
        }
    if (ctx->map_fixed->ramp)
        GL(ctx, DeleteTextures)(1, &ctx->map_fixed->ramp);
    if (ctx->map_fixed->fbo)
        GL(ctx, DeleteFramebuffers)(1, &ctx->map_fixed->fbo);
    if (ctx->map_fixed->depth_scratch)
        GL(ctx, DeleteTextures)(1, &ctx->map_fixed->depth_scratch);
    if (ctx->map_fixed->face_mask)
        GL(ctx, DeleteTextures)(1, &ctx->map_fixed->face_mask);
    stin__map_facing_release(ctx);
    stin__cast_map_release(ctx);
    stin__memzero(ctx->map_fixed, sizeof *ctx->map_fixed);
}

/* ---- rendering the maps -------------------------------------------------- */

int stin__map_offset(const stin_context *ctx, const stin_light_desc *l, float *factor,
                     float *units)
{
    *factor = l->shadow_offset[0];
    *units = l->shadow_offset[1];
    if (!l->shadow_offset_exact && *factor == 0.0f && *units == 0.0f) {
        *factor = 1.1f;
        *units = 4.0f;
    }
    /* 4 units of 2^-32 would be no offset at all: flat faces facing the
     * light shadowed themselves in stripes (es20-ext, 32-bit maps) */
    *units *= STIN__DEPTH24_UNIT / stin__rt_depth_unit(ctx);
    return *factor != 0.0f || *units != 0.0f;
}

static void render_one(stin_context *ctx, uint32_t slot, uint32_t li, const float view[16],
                       const float proj[16], float n, float f)
{
    const stin_light_desc *l = &ctx->lights[li];
    const int *vp = ctx->frame.viewport;
    uint32_t used = ctx->map_fixed->used;
    stin__pass_state ps = stin__pass_defaults;
    int fbo = ctx->map_fixed->fbo != 0, facing = !combine(ctx) && ctx->map_fixed->facing_test;
    int map_vp[4], cast;
    ps.depth_test = 1;
    if (fbo) {
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->map_fixed->fbo);
        GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER,
                                      combine(ctx) ? GL_COLOR_ATTACHMENT0 : GL_DEPTH_ATTACHMENT,
                                      GL_TEXTURE_2D, ctx->map_fixed->textures[slot], 0);
        GL(ctx, Viewport)(0, 0, (GLsizei)used, (GLsizei)used);
    } else {
        GL(ctx, Viewport)(vp[0], vp[1], (GLsizei)used, (GLsizei)used);
        ps.scissor = 1;
        ps.scissor_box[0] = vp[0];
        ps.scissor_box[1] = vp[1];
        ps.scissor_box[2] = ps.scissor_box[3] = (int)used;
    }
    if (!combine(ctx)) {
        ps.color_write = 0;
        ps.polygon_offset = (unsigned char)stin__map_offset(ctx, l, &ps.offset_factor, &ps.offset_units);
    }
    if (ctx->map_fixed->terminator)
        stin__map_terminator_lift(ctx, slot, proj, n, f,
                                  ps.polygon_offset ? ps.offset_units : 0.0f);
    stin__pass_apply(ctx, &ps);
    /* A point-light face's empty texels hold a depth just under 1: a point
     * behind the face has r past 1, clamped to 1, and must fail there. */
    stin__clear_depth(ctx, slot >= STIN__FACE_SLOT ? 1.0 - 1.0 / 65536.0 : 1.0);
    GL(ctx, ClearColor)(1.0f, 1.0f, 1.0f, 1.0f); /* map-combine: "nothing" is the far end */
    GL(ctx, Clear)(GL_DEPTH_BUFFER_BIT | (combine(ctx) ? GL_COLOR_BUFFER_BIT : 0u));
    /* CSG products first (csg/cast.c), in the frame's buffer where the map
     * is drawn there (its stencil), the casters after them, depth LESS */
    map_vp[0] = fbo ? 0 : vp[0];
    map_vp[1] = fbo ? 0 : vp[1];
    map_vp[2] = map_vp[3] = (int)used;
    cast = stin__casters_cast(ctx, stin__fixed_path(), view, proj, map_vp,
                              fbo ? ctx->map_fixed->fbo : ctx->draw_fbo,
                              !fbo && stin__target_has_stencil(ctx),
                              ps.polygon_offset ? ps.offset_factor : 0.0f,
                              ps.polygon_offset ? ps.offset_units : 0.0f);
    if (cast)
        stin__pass_apply(ctx, &ps);
    if (combine(ctx)) {
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
        GL_ENABLE(ctx, GL_TEXTURE_1D);
        stin__bind_unit(ctx, 0, GL_TEXTURE_1D, ctx->map_fixed->ramp);
        GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
        stin__map_ramp_texgen(ctx, n, f);
        if (cast) /* the products' surface in the ramp's colours */
            stin__casters_again(ctx, map_vp, fbo ? ctx->map_fixed->fbo : ctx->draw_fbo,
                                !fbo && stin__target_has_stencil(ctx));
    }
    stin__fixed_path()->depth(ctx, view, proj,
                              ctx->map_fixed->terminator ? STIN__DEPTH_FAR_SIDE : 0,
                              ctx->map_fixed->solid_min[slot]);
    if (combine(ctx)) {
        GL_DISABLE(ctx, GL_TEXTURE_GEN_S);
        GL_DISABLE(ctx, GL_TEXTURE_1D);
        GL(ctx, BindTexture)(GL_TEXTURE_1D, 0);
        GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE); /* GL's default */
    }
    if (fbo) {
        GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER,
                                      combine(ctx) ? GL_COLOR_ATTACHMENT0 : GL_DEPTH_ATTACHMENT,
                                      GL_TEXTURE_2D, 0, 0);
    } else {
        /* the colour (ramp) or depth of the region into the light's texture */
        GL(ctx, BindTexture)(GL_TEXTURE_2D, ctx->map_fixed->textures[slot]);
        GL(ctx, CopyTexSubImage2D)(GL_TEXTURE_2D, 0, 0, 0, vp[0], vp[1], (GLsizei)used,
                                   (GLsizei)used);
        GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    }
    ctx->stats.passes++;
    if (facing) /* its own pass: no offset may reorder the surfaces */
        stin__map_facing_draw(ctx, slot, l, view, proj);
}

/* World -> texture: bias/scale into the used corner of the texture, then the
 * light's projection and view. Rows are the texgen planes. */
static void store_texgen(stin_context *ctx, uint32_t slot, uint32_t li, const float view[16],
                         const float proj[16], float n, float f)
{
    float vp[16], bias[16], m[16];
    float scale = (float)ctx->map_fixed->used / (float)ctx->map_fixed->size;
    int r, c;
    stin__mat4_mul(vp, proj, view);
    stin__mat4_identity(bias);
    bias[0] = bias[5] = 0.5f * scale;
    bias[12] = bias[13] = 0.5f * scale;
    bias[10] = bias[14] = 0.5f;
    stin__mat4_mul(m, bias, vp);
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++)
            ctx->map_fixed->texgen[slot][4 * r + c] = m[4 * c + r];
    stin__map_ramp_plane(&ctx->lights[li], view, proj, n, f, ctx->map_fixed->used,
                         ctx->map_fixed->ramp_plane[slot]);
}

/* Every spot and directional light's map, before the camera's clear. */
static void fixed_prepass(stin_context *ctx)
{
    uint32_t i;
    const int *vp = ctx->frame.viewport;
    uint32_t limit = ctx->map_fixed->size;
    if (!ctx->map_fixed->fbo) { /* drawn in the frame's own framebuffer */
        uint32_t fit = (uint32_t)(vp[2] < vp[3] ? vp[2] : vp[3]);
        if (fit < limit)
            limit = stin__pow2_at_most(fit);
    }
    ctx->map_fixed->used = limit;
    ctx->stats.shadows.map_size = limit;
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, PushMatrix)();
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, PushMatrix)();
    GL(ctx, EnableClientState)(GL_VERTEX_ARRAY);
    if (ctx->map_fixed->terminator) /* the side pass lights the vertex normals */
        GL(ctx, EnableClientState)(GL_NORMAL_ARRAY);
    GL_DISABLE(ctx, GL_LIGHTING);
    for (i = 0; i < ctx->light_count && i < STIN__MAX_LIGHTS; i++) {
        const stin_light_desc *l = &ctx->lights[i];
        float view[16], proj[16], n, f;
        ctx->map_fixed->valid[i] = 0;
        /* before the point lights' test: their faces, and the volumes that
         * stand in without faces, are drawn from the centre too */
        if (l->radius > 0.0f && !ctx->map_fixed->said_area) {
            stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                      "shadows: shadow maps treat area lights as points (hard shadows)");
            ctx->map_fixed->said_area = 1;
        }
        if (l->type == STIN_LIGHT_POINT) {
            if (!ctx->map_fixed->said_point && !ctx->map_fixed->faces) {
                stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                          "shadows: point lights need six depth maps drawn mid-frame (map-depth "
                          "with framebuffer objects); here they use %s",
                          stin__target_has_stencil(ctx) ? "stencil volumes"
                                                                               : "no shadows");
                ctx->map_fixed->said_point = 1;
            }
            continue;
        }
        if (!stin__light_camera(ctx, l, view, proj, &n, &f, ctx->map_fixed->used))
            continue;
        render_one(ctx, i, i, view, proj, n, f);
        store_texgen(ctx, i, i, view, proj, n, f);
        ctx->map_fixed->valid[i] = 1;
    }
    GL(ctx, DisableClientState)(GL_VERTEX_ARRAY);
    GL(ctx, DisableClientState)(GL_NORMAL_ARRAY);
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, PopMatrix)();
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, PopMatrix)();
    if (ctx->map_fixed->fbo)
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    if (!ctx->map_fixed->faces) /* the products' maps of the point lights volumes take */
        stin__cast_map_prepass_points(ctx);
}

/* ---- the lit pass's shadow test ----------------------------------------- */

void stin__map_texgen(stin_context *ctx, const float *rows, int with_r)
{
    static const GLenum coord[4] = {GL_S, GL_T, GL_R, GL_Q};
    static const GLenum gen[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
                                  GL_TEXTURE_GEN_Q};
    int i;
    for (i = 0; i < 4; i++) {
        if (i == 2 && !with_r) {
            GL_DISABLE(ctx, GL_TEXTURE_GEN_R);
            continue;
        }
        GL(ctx, TexGeni)(coord[i], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        GL(ctx, TexGenfv)(coord[i], GL_EYE_PLANE, rows + 4 * i);
        GL_ENABLE(ctx, gen[i]);
    }
}

void stin__map_unit_off(stin_context *ctx, int unit)
{
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)unit));
    GL_DISABLE(ctx, GL_TEXTURE_GEN_S);
    GL_DISABLE(ctx, GL_TEXTURE_GEN_T);
    GL_DISABLE(ctx, GL_TEXTURE_GEN_Q);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
}

static void bind_slot(stin_context *ctx, uint32_t li);

/* 1 if light li has a map this frame; binds its test onto the shadow units. */
static int bind_light(stin_context *ctx, uint32_t li)
{
    if (li >= STIN__MAX_LIGHTS || !ctx->map_fixed->valid[li])
        return 0;
    bind_slot(ctx, li);
    return 1;
}

static void bind_slot(stin_context *ctx, uint32_t li)
{
    GLenum u = (GLenum)(GL_TEXTURE0 + (GLenum)ctx->map_fixed->unit);
    /* planes are given in world space: specify them under the camera's view,
     * whose inverse GL applies, so any draw's eye coordinates map back */
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(ctx->frame.view);
    GL(ctx, ActiveTexture)(u);
    GL_ENABLE(ctx, GL_TEXTURE_2D);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, ctx->map_fixed->textures[li]);
    stin__map_texgen(ctx, ctx->map_fixed->texgen[li], !combine(ctx));
    if (!combine(ctx)) {
        GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        if (ctx->map_fixed->facing_test)
            stin__map_facing_bind(ctx, li);
        if (ctx->map_fixed->terminator)
            stin__map_terminator_bind(ctx, li);
    } else {
        /* colour passed on, the stored depth into alpha */
        const stin__combine_stage stored = {GL_REPLACE, {GL_PREVIOUS, 0}, {GL_SRC_COLOR, 0},
                                      GL_REPLACE, {GL_TEXTURE, 0}, {GL_SRC_ALPHA, 0}};
        const stin__combine_stage compare = {GL_REPLACE, {GL_PREVIOUS, 0}, {GL_SRC_COLOR, 0},
                                       GL_ADD_SIGNED, {GL_PREVIOUS, GL_TEXTURE},
                                       {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA}};
        stin__combine_set(ctx, &stored);
        /* next unit: stored - own + 0.5 into alpha, colour passed on */
        GL(ctx, ActiveTexture)(u + 1u);
        GL_ENABLE(ctx, GL_TEXTURE_1D);
        GL(ctx, BindTexture)(GL_TEXTURE_1D, ctx->map_fixed->ramp);
        GL(ctx, TexGeni)(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        GL(ctx, TexGenfv)(GL_S, GL_EYE_PLANE, ctx->map_fixed->ramp_plane[li]);
        GL_ENABLE(ctx, GL_TEXTURE_GEN_S);
        stin__combine_set(ctx, &compare);
        GL_ENABLE(ctx, GL_ALPHA_TEST);
        GL(ctx, AlphaFunc)(GL_GEQUAL, 0.5f);
    }
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    /* the shadow must darken the specular term too: one colour through the units */
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_SEPARATE_SPECULAR))
        GL_ENUM(ctx, LightModeli, GL_LIGHT_MODEL_COLOR_CONTROL)(GL_LIGHT_MODEL_COLOR_CONTROL,
                                                                GL_SINGLE_COLOR);
}

static void unbind(stin_context *ctx)
{
    GLenum u = (GLenum)(GL_TEXTURE0 + (GLenum)ctx->map_fixed->unit);
    GL(ctx, ActiveTexture)(u);
    GL_DISABLE(ctx, GL_TEXTURE_GEN_S);
    GL_DISABLE(ctx, GL_TEXTURE_GEN_T);
    GL_DISABLE(ctx, GL_TEXTURE_GEN_R);
    GL_DISABLE(ctx, GL_TEXTURE_GEN_Q);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    if (!combine(ctx) && ctx->map_fixed->facing_test)
        stin__map_facing_unbind(ctx);
    if (!combine(ctx) && ctx->map_fixed->terminator)
        stin__map_terminator_unbind(ctx);
    if (combine(ctx)) {
        GL(ctx, ActiveTexture)(u + 1u);
        GL_DISABLE(ctx, GL_TEXTURE_GEN_S);
        GL(ctx, BindTexture)(GL_TEXTURE_1D, 0);
        GL_DISABLE(ctx, GL_TEXTURE_1D);
        GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        GL_DISABLE(ctx, GL_ALPHA_TEST);
    }
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_SEPARATE_SPECULAR))
        GL_ENUM(ctx, LightModeli, GL_LIGHT_MODEL_COLOR_CONTROL)(GL_LIGHT_MODEL_COLOR_CONTROL,
                                                                GL_SEPARATE_SPECULAR_COLOR);
}

/* ---- point lights: six 90-degree maps ------------------------------------ */

static const float face_axis[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                      {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

static float face_fov_deg(void)
{
    /* atan(x) for x = 128 / 127 near 1: 45 degrees + (x - 1) / 2 radians to
     * first order, plenty for one texel */
    double x = (double)(FACE_MASK / 2u) / (double)(FACE_MASK / 2u - 1u);
    double half = 45.0 + ((x - 1.0) / (1.0 + x * 1.0) ) * 57.29577951308232;
    return (float)(2.0 * half);
}

/* The face mask's unit: after the map test's (and the side test's). */
static int mask_unit(const stin_context *ctx)
{
    return ctx->map_fixed->unit +
           (combine(ctx) ? 2
                         : 1 + ctx->map_fixed->facing_test +
                               ctx->map_fixed->terminator * stin__map_terminator_units());
}

/* Point lights with FBOs: renders cube face f (0..5: +x -x +y -y +z -z) of
 * light li into the shared face map, binds its test and keeps drawing to the
 * face's square (mask unit). 0 when the face sees nothing; face_end undoes it. */
static int face_begin(stin_context *ctx, uint32_t li, int face)
{
    const stin_light_desc *l = &ctx->lights[li];
    const float *ax = face_axis[face];
    float view[16], proj[16], n, f, half, center[3];
    uint32_t slot = STIN__FACE_SLOT + (uint32_t)face;
    if (!ctx->map_fixed->faces || l->type != STIN_LIGHT_POINT)
        return 0;
    stin__light_look_along(view, l->position, ax);
    stin__light_fit(ctx, view, 0, &n, &f, &half, center);
    if (f <= 0.0f)
        return 0; /* nothing in front of this face */
    if (n < f * 1e-3f)
        n = f * 1e-3f;
    /* tan(fov/2) = (N/2) / (N/2 - 1): the 90-degree square ends on a texel edge */
    stin__light_perspective(proj, face_fov_deg(), n, f);
    ctx->map_fixed->used = ctx->map_fixed->size;
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    GL_DISABLE(ctx, GL_LIGHTING);
    render_one(ctx, slot, li, view, proj, n, f);
    store_texgen(ctx, slot, li, view, proj, n, f);
    /* back to the frame */
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    GL(ctx, Viewport)(ctx->frame.viewport[0], ctx->frame.viewport[1], ctx->frame.viewport[2],
                      ctx->frame.viewport[3]);
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, LoadMatrixf)(ctx->projection);
    /* No clip planes: they would change the passes' vertex processing and
     * break the depth EQUAL test. The mask keeps the face to its square;
     * behind the face the depth is past 1 and fails the comparison. */
    bind_slot(ctx, slot);
    {
        GLenum mu = (GLenum)(GL_TEXTURE0 + (GLenum)mask_unit(ctx));
        GL(ctx, ActiveTexture)(mu);
        GL_ENABLE(ctx, GL_TEXTURE_2D);
        GL(ctx, BindTexture)(GL_TEXTURE_2D, ctx->map_fixed->face_mask);
        stin__map_texgen(ctx, ctx->map_fixed->texgen[slot], 0);
        const stin__combine_stage mask = {GL_MODULATE, {GL_PREVIOUS, GL_TEXTURE},
                                    {GL_SRC_COLOR, GL_SRC_COLOR}, GL_REPLACE, {GL_PREVIOUS, 0},
                                    {GL_SRC_ALPHA, 0}};
        stin__combine_set(ctx, &mask);
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    }
    return 1;
}

static void face_end(stin_context *ctx)
{
    unbind(ctx);
    stin__map_unit_off(ctx, mask_unit(ctx));
}

/* ---- the module ------------------------------------------------------------ */

/* Point lights without faces fall back to volumes, whose projection the
 * faces' passes are drawn with too; lights come after the projection is
 * fixed, so every frame uses it. */
static void fixed_prepare(stin_context *ctx) { stin__volume_projection(ctx); }

/* The light's map test on the lit pass; a point light's six faces each
 * light their own pyramid, or its stencil volumes where there are no faces. */
static void fixed_light(stin_context *ctx, const stin__path *path, uint32_t li,
                        stin__shade_fn shade)
{
    const stin_light_desc *l = &ctx->lights[li];
    int mapped = bind_light(ctx, li), face;
    if (!mapped && l->type == STIN_LIGHT_POINT && ctx->map_fixed->faces) {
        for (face = 0; face < STIN__CUBE_FACES; face++)
            if (face_begin(ctx, li, face)) {
                stin__map_facing_shade(ctx, path, l, shade);
                face_end(ctx);
            }
        return;
    }
    if (!mapped && l->type == STIN_LIGHT_POINT && stin__target_has_stencil(ctx)) {
        float world[4];
        world[0] = l->position[0];
        world[1] = l->position[1];
        world[2] = l->position[2];
        world[3] = 1.0f;
        /* the products as volumes cast them: their map, marked after the count */
        (void)stin__cast_map_draw(ctx, path, li, ctx->draw_fbo, 0);
        stin__volume_light(ctx, path, world, NULL);
        stin__cast_map_mark(ctx);
    }
    if (mapped && !combine(ctx))
        stin__map_facing_shade(ctx, path, l, shade);
    else
        shade(ctx, path, l, 1.0f);
    if (mapped)
        unbind(ctx);
    stin__volume_light_end(ctx);
}

int stin__map_fixed_maps_light(const stin_context *ctx, uint32_t li)
{
    return li < STIN__MAX_LIGHTS &&
           (ctx->map_fixed->valid[li] ||
            (ctx->lights[li].type == STIN_LIGHT_POINT && ctx->map_fixed->faces));
}

/* A spot or directional light's map, for looking at: map-depth's depth
 * texture or map-combine's RGBA8 ramp (one module runs both, so the kind is
 * the selection's, not the module's). Without FBOs only `used` texels a
 * side were drawn (bounded by the viewport). */
static stin_result fixed_debug_map(const stin_context *ctx, uint32_t li, stin_debug_map *out)
{
    if (!ctx->map_fixed->valid[li])
        return STIN_ERROR_UNSUPPORTED;
    out->texture = ctx->map_fixed->textures[li];
    out->size = ctx->map_fixed->used;
    out->allocated = ctx->map_fixed->size;
    out->depth = !combine(ctx);
    return STIN_OK;
}

const stin__shadow_technique stin__shadow_map_fixed = {
    .init = fixed_init,
    .release = fixed_release,
    .prepare = fixed_prepare,
    .light_prepass = fixed_prepass,
    .light = fixed_light,
    .fragment_test = stin__map_fixed_maps_light,
    .debug_map = fixed_debug_map,
};
