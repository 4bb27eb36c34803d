/* SPDX-License-Identifier: MIT */
/* The casters' map on GL1 (shadow/cast_map.c's fixed-function side): the
 * marking pass, and without framebuffer objects the maps themselves.
 *
 * Without FBOs each light's products are drawn from the light as map-depth
 * and map-combine draw their maps (shadow/map_fixed.c): in the light
 * pre-pass, in the frame's own buffer before its clear (scissored to a
 * square the viewport holds, the products resolved in its stencil), and
 * copied into a texture per light and face: depth with shadow compare, or
 * where there are no depth textures map-combine's ramp of light depths
 * (colour, 8 bits). The marking pass tests the frame's surfaces against
 * it by eye-linear texgen: the compare's result in alpha, or the ramp's
 * stored - own + 0.5 by texture_env_combine, and the alpha test passes
 * the shadowed fragments (alpha below 0.5). A point light's six faces are
 * marked one after the other, each in its own pyramid: one more unit adds
 * 1 outside the face's square (a mask texture, 0 only inside it) and one
 * more 1 behind the face's plane (a 1D step of the distance along its
 * axis), so a fragment another face covers never passes. */
#include "shadow/cast_map_private.h"
#include "render/draw_bounds.h"

#define MASK_SIZE 4u /* the square's inner 2 x 2 texels, a border of 0 around them */

/* The units the marking pass uses after unit 0 (which the geometry pass
 * turns off): the map, map-combine's ramp, a face's square and side. */
static int test_units(const struct stin__cast_map_state *m, int faces)
{
    return 1 + m->ramp + (faces > 1 ? 2 : 0);
}

static void clamped(stin_context *ctx, GLenum target)
{
    GL(ctx, TexParameteri)(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    GL(ctx, TexParameteri)(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    GL(ctx, TexParameteri)(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    GL(ctx, TexParameteri)(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void stin__cast_fixed_init(stin_context *ctx)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    unsigned char mask[MASK_SIZE * MASK_SIZE];
    static const unsigned char front[2] = {0, 255};
    uint32_t x, y;
    if (m->ramp)
        m->ramp_texture = stin__map_ramp_create(ctx);
    if (m->copied) { /* a face's copy must fit a texture */
        m->size = ctx->desc.shadows.map_size;
        while (ctx->caps.max_texture_size > 0 && m->size > (uint32_t)ctx->caps.max_texture_size)
            m->size /= 2u;
    }
    m->face_units = ctx->caps.max_texture_units >= 1 + test_units(m, STIN__CUBE_FACES);
    if (!m->face_units)
        return;
    for (y = 0; y < MASK_SIZE; y++)
        for (x = 0; x < MASK_SIZE; x++)
            mask[y * MASK_SIZE + x] =
                x == 0 || y == 0 || x == MASK_SIZE - 1 || y == MASK_SIZE - 1 ? 0 : 255;
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, GenTextures)(1, &m->face_mask);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, m->face_mask);
    clamped(ctx, GL_TEXTURE_2D);
    stin__upload_bytes(ctx, GL_TEXTURE_2D, GL_INTENSITY8, MASK_SIZE, MASK_SIZE, GL_LUMINANCE, mask);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL(ctx, GenTextures)(1, &m->front);
    GL(ctx, BindTexture)(GL_TEXTURE_1D, m->front);
    clamped(ctx, GL_TEXTURE_1D);
    stin__upload_bytes(ctx, GL_TEXTURE_1D, GL_INTENSITY8, 2, 1, GL_LUMINANCE, front);
    GL(ctx, BindTexture)(GL_TEXTURE_1D, 0);
}

void stin__cast_fixed_release(stin_context *ctx)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    uint32_t i;
    for (i = 0; i < STIN__MAX_LIGHTS; i++)
        if (m->lights[i].copy_size)
            GL(ctx, DeleteTextures)(STIN__CUBE_FACES, m->lights[i].copies);
    if (m->face_mask)
        GL(ctx, DeleteTextures)(1, &m->face_mask);
    if (m->front)
        GL(ctx, DeleteTextures)(1, &m->front);
    if (m->ramp_texture)
        GL(ctx, DeleteTextures)(1, &m->ramp_texture);
}

void stin__cast_fixed_cell(stin_context *ctx, int cell, const float window[16],
                           const float into[16], int drew)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    stin__cast_light *c = &m->lights[m->current];
    c->faces = m->faces;
    c->copies[cell] = m->texture;
    stin__memcopy(c->window[cell], window, sizeof c->window[cell]);
    stin__memcopy(c->matrix[cell], into, sizeof c->matrix[cell]);
    if (drew)
        c->drawn |= 1u << cell;
}

/* ---- without FBOs: the maps in the light pre-pass ------------------------- */

/* Light c's first `faces` copies at `size` texels a side. */
static void make_copies(stin_context *ctx, stin__cast_light *c, uint32_t size, int faces)
{
    int f;
    if (c->copy_size == size && c->copy_faces >= faces)
        return;
    if (!c->copy_size)
        GL(ctx, GenTextures)(STIN__CUBE_FACES, c->copies);
    for (f = 0; f < faces; f++) {
        if (ctx->cast_map->ramp) {
            stin__rt_texture(ctx, c->copies[f], GL_INTENSITY8, GL_LUMINANCE, GL_UNSIGNED_BYTE,
                             (int)size, (int)size);
            continue;
        }
        stin__rt_shadow_map(ctx, c->copies[f], (int)size, (int)size);
        /* the compare's result in alpha too, for the alpha test */
        GL_ENUM(ctx, TexParameteri, GL_DEPTH_TEXTURE_MODE)(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE,
                                                           GL_INTENSITY);
    }
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    c->copy_size = size;
    c->copy_faces = faces;
}

/* The products into the frame's buffer at map_vp; ramp: map-combine's
 * colour cleared too, and no offset (the ramp's bias stands in for it). */
static int products(stin_context *ctx, const stin_light_desc *l, const int map_vp[4],
                    const float view[16], const float proj[16], int ramp,
                    stin__pass_state *ps)
{
    *ps = stin__pass_defaults;
    ps->depth_test = 1;
    ps->scissor = 1;
    stin__memcopy(ps->scissor_box, map_vp, sizeof ps->scissor_box);
    if (!ramp) {
        ps->color_write = 0;
        ps->polygon_offset = (unsigned char)stin__map_offset(ctx, l, &ps->offset_factor,
                                                             &ps->offset_units);
    }
    GL(ctx, Viewport)(map_vp[0], map_vp[1], map_vp[2], map_vp[3]);
    stin__pass_apply(ctx, ps);
    stin__clear_depth(ctx, 1.0);
    GL(ctx, ClearColor)(1.0f, 1.0f, 1.0f, 1.0f); /* map-combine: "nothing" is the far end */
    GL(ctx, Clear)(GL_DEPTH_BUFFER_BIT | (ramp ? GL_COLOR_BUFFER_BIT : 0u));
    return stin__casters_cast(ctx, stin__fixed_path(), view, proj, map_vp, ctx->draw_fbo, 1,
                              ps->polygon_offset ? ps->offset_factor : 0.0f,
                              ps->polygon_offset ? ps->offset_units : 0.0f);
}

int stin__cast_fixed_products(stin_context *ctx, const stin_light_desc *l, const int map_vp[4],
                              const float view[16], const float proj[16])
{
    stin__pass_state ps;
    return products(ctx, l, map_vp, view, proj, 0, &ps);
}

/* The products seen from (view, proj), whose depth spans [n, f], into the
 * frame's buffer at the viewport's corner, then into face `face`'s copy;
 * 1 if any drew. */
static int copy_face(stin_context *ctx, const stin_light_desc *l, stin__cast_light *c, int face,
                     const float view[16], const float proj[16], float n, float f)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    const int *vp = ctx->frame.viewport;
    const int map_vp[4] = {vp[0], vp[1], (int)m->copy_size, (int)m->copy_size};
    stin__pass_state ps;
    int drew = products(ctx, l, map_vp, view, proj, m->ramp, &ps);
    stin__light_window_matrix(c->matrix[face], view, proj);
    if (!drew)
        return 0;
    stin__pass_apply(ctx, &ps);
    if (m->ramp) { /* the products' surface in the ramp's colours */
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
        GL_ENABLE(ctx, GL_TEXTURE_1D);
        stin__bind_unit(ctx, 0, GL_TEXTURE_1D, m->ramp_texture);
        GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
        stin__map_ramp_texgen(ctx, n, f);
        stin__casters_again(ctx, map_vp, ctx->draw_fbo, 1);
        GL_DISABLE(ctx, GL_TEXTURE_GEN_S);
        GL_DISABLE(ctx, GL_TEXTURE_1D);
        GL(ctx, BindTexture)(GL_TEXTURE_1D, 0);
        GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE); /* GL's default */
        stin__map_ramp_plane(l, view, proj, n, f, m->copy_size, c->ramp[face]);
    }
    GL(ctx, BindTexture)(GL_TEXTURE_2D, c->copies[face]);
    GL(ctx, CopyTexSubImage2D)(GL_TEXTURE_2D, 0, 0, 0, map_vp[0], map_vp[1], map_vp[2],
                               map_vp[3]);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    ctx->stats.passes++;
    return 1;
}

#define FOCUS_MARGIN 2.0f /* texels of the focused map kept clear around the products */

/* The light's map focused on the products: proj cropped to the rectangle
 * their bounds cover (a margin of clear texels round them, so a lookup
 * clamped to the edge reads no product), and map-combine's 8 bits spread
 * over their depths within [n, f] (a step of margin each side: a receiver
 * nearer reads as lit, one farther as the ramp's end, behind whatever
 * product the map holds). Unchanged where a primitive's bounds tell
 * nothing or reach behind the light. */
void stin__cast_fixed_focus(const stin_context *ctx, uint32_t size, const float view[16],
                            float proj[16], float *n, float *f)
{
    stin__caster_product p;
    float lo = *f, hi = *n, box[4] = {1, 1, -1, -1}, corners[24], vp[16], margin;
    float crop[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, out[16];
    uint32_t i, k;
    int c, a;
    stin__mat4_mul(vp, proj, view);
    for (i = 0; stin__casters_product(ctx, i, &p); i++)
        for (k = 0; k < p.primitive_count; k++) {
            if (!stin__draw_world_corners(ctx, &p.primitives[k], corners))
                return;
            for (c = 0; c < 8; c++) {
                const float *w = corners + 3 * c;
                float d = -(view[2] * w[0] + view[6] * w[1] + view[10] * w[2] + view[14]);
                float q = vp[3] * w[0] + vp[7] * w[1] + vp[11] * w[2] + vp[15];
                if (q <= 0.0f)
                    return;
                for (a = 0; a < 2; a++) {
                    float x = (vp[a] * w[0] + vp[4 + a] * w[1] + vp[8 + a] * w[2] + vp[12 + a]) / q;
                    box[a] = x < box[a] ? x : box[a];
                    box[2 + a] = x > box[2 + a] ? x : box[2 + a];
                }
                lo = d < lo ? d : lo;
                hi = d > hi ? d : hi;
            }
        }
    if (hi <= lo || box[2] <= box[0] || box[3] <= box[1])
        return;
    for (a = 0; a < 2; a++) { /* the margin in the focused map's texels, within [-1, 1] */
        float texel = (box[2 + a] - box[a]) / ((float)size - 2.0f * FOCUS_MARGIN);
        float x0 = box[a] - FOCUS_MARGIN * texel, x1 = box[2 + a] + FOCUS_MARGIN * texel;
        x0 = x0 > -1.0f ? x0 : -1.0f;
        x1 = x1 < 1.0f ? x1 : 1.0f;
        crop[5 * a] = 2.0f / (x1 - x0);
        crop[12 + a] = -(x1 + x0) / (x1 - x0);
    }
    stin__mat4_mul(out, crop, proj);
    stin__memcopy(proj, out, sizeof out);
    margin = (hi - lo) / 128.0f;
    *n = lo - margin > *n ? lo - margin : *n;
    *f = hi + margin < *f ? hi + margin : *f;
}

/* A perspective projection's depth range. */
static void depth_range(const float proj[16], float *n, float *f)
{
    *n = proj[14] / (proj[10] - 1.0f);
    *f = proj[14] / (proj[10] + 1.0f);
}

/* Light li's map, each face of a point light's. */
static void copy_light(stin_context *ctx, uint32_t li)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    const stin_light_desc *l = &ctx->lights[li];
    stin__cast_light *c = &m->lights[li];
    float view[16], proj[16], n, f;
    int face;
    c->drawn = 0;
    c->faces = l->type == STIN_LIGHT_POINT ? STIN__CUBE_FACES : 1;
    if (c->faces > 1 && !m->face_units)
        return; /* said by stin__cast_map_draw */
    make_copies(ctx, c, m->copy_size, c->faces);
    if (c->faces == 1) {
        if (!stin__light_camera(ctx, l, view, proj, &n, &f, m->copy_size))
            return;
        stin__cast_fixed_focus(ctx, m->copy_size, view, proj, &n, &f);
        if (copy_face(ctx, l, c, 0, view, proj, n, f))
            c->drawn = 1u;
        return;
    }
    for (face = 0; face < STIN__CUBE_FACES; face++) {
        stin__light_cube_face(ctx, l->position, face, view, proj);
        depth_range(proj, &n, &f);
        stin__light_window_matrix(c->window[face], view, proj); /* the face's own square */
        stin__cast_fixed_focus(ctx, m->copy_size, view, proj, &n, &f);
        if (copy_face(ctx, l, c, face, view, proj, n, f))
            c->drawn |= 1u << face;
    }
}

/* Every light's map, or the point lights' alone. */
static void prepass(stin_context *ctx, int points_only)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    const int *vp = ctx->frame.viewport;
    uint32_t li, fit = (uint32_t)(vp[2] < vp[3] ? vp[2] : vp[3]);
    for (li = 0; li < STIN__MAX_LIGHTS; li++)
        m->lights[li].drawn = 0;
    if (!m->copied || !stin__casters_wanted(ctx) || !stin__target_has_stencil(ctx) || fit < 1u)
        return;
    m->copy_size = fit < m->size ? stin__pow2_at_most(fit) : m->size; /* drawn where the frame is */
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, PushMatrix)();
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, PushMatrix)();
    GL(ctx, EnableClientState)(GL_VERTEX_ARRAY); /* the fixed path's draws, before its begin */
    GL_DISABLE(ctx, GL_LIGHTING);
    for (li = 0; li < ctx->light_count && li < STIN__MAX_LIGHTS; li++)
        if (!points_only || ctx->lights[li].type == STIN_LIGHT_POINT)
            copy_light(ctx, li);
    GL(ctx, DisableClientState)(GL_VERTEX_ARRAY);
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, PopMatrix)();
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, PopMatrix)();
    GL(ctx, Viewport)(vp[0], vp[1], vp[2], vp[3]);
}

void stin__cast_map_prepass(stin_context *ctx) { prepass(ctx, 0); }

void stin__cast_map_prepass_points(stin_context *ctx) { prepass(ctx, 1); }

/* ---- the marking pass ------------------------------------------------------ */

/* Rows of a window matrix (column-major), for the texgen planes. */
static void rows_of(float rows[16], const float m[16])
{
    int r, k;
    for (r = 0; r < 4; r++)
        for (k = 0; k < 4; k++)
            rows[4 * r + k] = m[4 * k + r];
}

/* Adds 1 - the unit's texture to the alpha (the colour passed on). */
static void add_outside(stin_context *ctx)
{
    const stin__combine_stage outside = {GL_REPLACE, {GL_PREVIOUS, 0}, {GL_SRC_COLOR, 0},
                                         GL_ADD, {GL_PREVIOUS, GL_TEXTURE},
                                         {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA}};
    stin__combine_set(ctx, &outside);
}

static void unit_on(stin_context *ctx, int unit, GLenum target, GLuint texture)
{
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)unit));
    GL_ENABLE(ctx, target);
    GL(ctx, BindTexture)(target, texture);
}

/* A 2D unit (its R too) or a 1D one (S alone) back off. */
static void unit_off(stin_context *ctx, int unit, GLenum target)
{
    if (target == GL_TEXTURE_2D)
        stin__map_unit_off(ctx, unit);
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)unit));
    if (target == GL_TEXTURE_2D) {
        GL_DISABLE(ctx, GL_TEXTURE_GEN_R);
        return;
    }
    GL_DISABLE(ctx, GL_TEXTURE_GEN_S);
    GL(ctx, BindTexture)(GL_TEXTURE_1D, 0);
    GL_DISABLE(ctx, GL_TEXTURE_1D);
    GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

/* Face `face` of light c's test on units 1.., the alpha below 0.5 where
 * its map shadows the fragment; returns the last unit. */
static int bind_face(stin_context *ctx, const stin__cast_light *c, int face)
{
    const struct stin__cast_map_state *m = ctx->cast_map;
    float rows[16];
    int unit = 1;
    rows_of(rows, c->matrix[face]);
    unit_on(ctx, unit, GL_TEXTURE_2D, c->copies[face]);
    stin__map_texgen(ctx, rows, !m->ramp);
    GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE); /* the stored depth */
    if (m->ramp) { /* stored - own + 0.5 */
        const stin__combine_stage compare = {GL_REPLACE, {GL_PREVIOUS, 0}, {GL_SRC_COLOR, 0},
                                             GL_ADD_SIGNED, {GL_PREVIOUS, GL_TEXTURE},
                                             {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA}};
        unit_on(ctx, ++unit, GL_TEXTURE_1D, m->ramp_texture);
        GL(ctx, TexGeni)(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        GL(ctx, TexGenfv)(GL_S, GL_EYE_PLANE, c->ramp[face]);
        GL_ENABLE(ctx, GL_TEXTURE_GEN_S);
        stin__combine_set(ctx, &compare);
    }
    if (c->faces > 1) {
        /* the square: the window's [0, 1] onto the mask's inner texels */
        const float inner[16] = {0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 1, 0, 0.25f, 0.25f, 0, 1};
        float square[16], side[4];
        stin__mat4_mul(square, inner, c->window[face]);
        rows_of(rows, square);
        unit_on(ctx, ++unit, GL_TEXTURE_2D, m->face_mask);
        stin__map_texgen(ctx, rows, 0);
        add_outside(ctx);
        /* the side: the distance along the face's axis (the window's q)
         * + 0.5 picks the step's texel 1 in front of the light */
        stin__memcopy(side, rows + 12, sizeof side);
        side[3] += 0.5f;
        unit_on(ctx, ++unit, GL_TEXTURE_1D, m->front);
        GL(ctx, TexGeni)(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        GL(ctx, TexGenfv)(GL_S, GL_EYE_PLANE, side);
        GL_ENABLE(ctx, GL_TEXTURE_GEN_S);
        add_outside(ctx);
    }
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    return unit;
}

static void unbind_face(stin_context *ctx, const stin__cast_light *c)
{
    const struct stin__cast_map_state *m = ctx->cast_map;
    int unit = 1;
    unit_off(ctx, unit, GL_TEXTURE_2D);
    if (m->ramp)
        unit_off(ctx, ++unit, GL_TEXTURE_1D);
    if (c->faces > 1) {
        unit_off(ctx, ++unit, GL_TEXTURE_2D);
        unit_off(ctx, ++unit, GL_TEXTURE_1D);
    }
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
}

void stin__cast_fixed_mark(stin_context *ctx)
{
    const struct stin__cast_map_state *m = ctx->cast_map;
    const stin__cast_light *c = &m->lights[m->current];
    const stin__path *path = stin__fixed_path();
    int face;
    path->geometry_begin(ctx);
    GL_ENABLE(ctx, GL_ALPHA_TEST);
    GL(ctx, AlphaFunc)(GL_LESS, 0.5f);
    for (face = 0; face < c->faces; face++) {
        if (!(c->drawn & (1u << face)))
            continue; /* nothing there shadows */
        GL(ctx, MatrixMode)(GL_MODELVIEW);
        GL(ctx, LoadMatrixf)(ctx->frame.view); /* planes given in world space */
        (void)bind_face(ctx, c, face);
        stin__cast_map_receivers(ctx, NULL);
        unbind_face(ctx, c);
    }
    path->geometry_end(ctx);
    GL_DISABLE(ctx, GL_ALPHA_TEST);
    GL(ctx, AlphaFunc)(GL_ALWAYS, 0.0f);
}
