/* SPDX-License-Identifier: MIT */
/* map-depth's side test: which side of a surface the light sees.
 *
 * A depth map alone cannot tell the two sides of a sheet apart: where the
 * eye sees one side of an open surface (a shell seen through its opening, a
 * one-sided quad from behind) and the light the other, the surface is its own
 * nearest caster and passes the depth test, lit. So each map gets a side
 * pass: by two-sided lighting (emission only: white on front faces, black on
 * back faces as the light's rasteriser sees them) it writes which side of
 * the nearest surface faces the light, copied into two textures per slot.
 * It has a depth buffer of its own (with FBOs) and no polygon offset: a
 * slope-scaled offset pushes a steep front face behind the back face under
 * it near the light's silhouette and would name the wrong side there. The
 * lit pass is drawn once per side the eye sees (face culling): eye-front
 * fragments are multiplied by one map (MODULATE), eye-back ones by the
 * other. A fragment is lit only where the side the eye sees is the side the
 * light sees, the rule of the reference. Texels no surface covers are lit
 * in both maps, as the depth test lights them: a fragment reads one only
 * beside its surface's outline as the light sees it, where the light's
 * rasteriser left the texel out, or beyond it where a multisampled target
 * shades a fragment at its pixel centre outside its surface (one map with
 * a third value there, 0.5, lit a rim at half strength). The pass is
 * cleared to white and copied as it is (facing: 1 front, 0 back, 1 none);
 * then a quad on the far plane, depth GREATER, turns each texel a surface
 * covers into one minus itself (blend ONE_MINUS_DST_COLOR, ZERO) and the
 * second copy is taken (facing_back: 0 front, 1 back, 1 none). No pixel
 * transfer scale: Mesa's CopyTexSubImage through one reads zeros from a
 * window's framebuffer. A draw mirrored by its transform flips both
 * rasterisers alike; a mirrored camera (det(projection * view) > 0) swaps
 * the culled faces. GL 1.1 means only, on a texture unit after the depth
 * compare; without a spare unit the test is left out (logged). With the
 * terminator test (shadow/map_terminator.c) the side map is drawn from the
 * faces a second-depth map keeps, lit by the light (facing is INTENSITY8:
 * the solids read their side in alpha). */
#include "shadow/map_fixed_private.h"

static void create_facing_texture(stin_context *ctx, GLuint *t, uint32_t size, GLenum format)
{
    GL(ctx, GenTextures)(1, t);
    /* a side is a class, not a value: never averaged across a silhouette */
    stin__rt_texture(ctx, *t, format, GL_LUMINANCE, GL_UNSIGNED_BYTE, (int)size, (int)size);
}

void stin__map_facing_init(stin_context *ctx, int units_after)
{
    struct stin__map_fixed_state *m = ctx->map_fixed;
    if (m->unit + 1 + units_after > ctx->caps.max_texture_units) {
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                  "shadows: map-depth has no texture unit spare for its side test (%d units): "
                  "an open surface seen from the side the light does not see is lit",
                  ctx->caps.max_texture_units);
        return;
    }
    m->facing_test = 1;
    if (!m->fbo)
        return; /* drawn in the frame's own buffer, like the map */
    create_facing_texture(ctx, &m->facing_color, m->size, GL_RGBA8);
    GL(ctx, GenTextures)(1, &m->facing_depth);
    stin__rt_texture(ctx, m->facing_depth, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT,
                     GL_UNSIGNED_INT, (int)m->size, (int)m->size);
    GL(ctx, GenFramebuffers)(1, &m->facing_fbo);
    (void)stin__rt_attach(ctx, m->facing_fbo, m->facing_color, m->facing_depth, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, 0);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
}

void stin__map_facing_create(stin_context *ctx, uint32_t slot)
{
    struct stin__map_fixed_state *m = ctx->map_fixed;
    if (!m->facing_test)
        return;
    /* the terminator test's solids read their side in alpha */
    create_facing_texture(ctx, &m->facing[slot], m->size,
                          m->terminator ? GL_INTENSITY8 : GL_LUMINANCE8);
    create_facing_texture(ctx, &m->facing_back[slot], m->size, GL_LUMINANCE8);
}

void stin__map_facing_release(stin_context *ctx)
{
    struct stin__map_fixed_state *m = ctx->map_fixed;
    uint32_t i;
    for (i = 0; i < STIN__MAP_SLOTS; i++) {
        if (m->facing[i])
            GL(ctx, DeleteTextures)(1, &m->facing[i]);
        if (m->facing_back[i])
            GL(ctx, DeleteTextures)(1, &m->facing_back[i]);
    }
    if (m->facing_fbo)
        GL(ctx, DeleteFramebuffers)(1, &m->facing_fbo);
    if (m->facing_color)
        GL(ctx, DeleteTextures)(1, &m->facing_color);
    if (m->facing_depth)
        GL(ctx, DeleteTextures)(1, &m->facing_depth);
}

/* The side pass's colour into texture t. */
static void copy_side(stin_context *ctx, GLuint t, int x, int y)
{
    const struct stin__map_fixed_state *m = ctx->map_fixed;
    GL(ctx, BindTexture)(GL_TEXTURE_2D, t);
    GL(ctx, CopyTexSubImage2D)(GL_TEXTURE_2D, 0, 0, 0, x, y, (GLsizei)m->used, (GLsizei)m->used);
}

/* Each texel a surface covers (its depth under the clear's 1) into one
 * minus its colour; those none covers stay white. ps: the pass's state
 * (viewport, scissor); the matrices are left at identity (the map's
 * callers load their own). */
static void invert_covered(stin_context *ctx, stin__pass_state ps)
{
    static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    static const float corner[6][3] = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1},
                                       {-1, -1, 1}, {1, 1, 1},  {-1, 1, 1}};
    int i;
    ps.depth_test = 1;
    ps.depth_func = GL_GREATER; /* window depth 1 against the clear's 1: fails */
    ps.depth_write = 0;
    ps.blend = 1;
    ps.blend_src = GL_ONE_MINUS_DST_COLOR;
    ps.blend_dst = GL_ZERO;
    ps.cull = 0;
    ps.stencil_test = 0;
    stin__pass_apply(ctx, &ps);
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, LoadMatrixf)(identity);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(identity);
    GL(ctx, Color4f)(1.0f, 1.0f, 1.0f, 1.0f);
    GL(ctx, Begin)(GL_TRIANGLES);
    for (i = 0; i < 6; i++)
        GL(ctx, Vertex3fv)(corner[i]);
    GL(ctx, End)();
}

/* Emission only, white in front and black behind: the colour is the side,
 * whatever lights are on. */
static void side_colours(stin_context *ctx, int on)
{
    static const float black[4] = {0, 0, 0, 1}, white[4] = {1, 1, 1, 1};
    if (!on) {
        GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_EMISSION, black);
        GL(ctx, LightModeli)(GL_LIGHT_MODEL_TWO_SIDE, 0);
        GL_DISABLE(ctx, GL_LIGHTING);
        return;
    }
    GL_ENABLE(ctx, GL_LIGHTING);
    GL_DISABLE(ctx, GL_COLOR_MATERIAL);
    GL(ctx, LightModeli)(GL_LIGHT_MODEL_TWO_SIDE, 1);
    GL(ctx, LightModelfv)(GL_LIGHT_MODEL_AMBIENT, black);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, black);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_SPECULAR, black);
    GL(ctx, Materialfv)(GL_FRONT, GL_EMISSION, white);
    GL(ctx, Materialfv)(GL_BACK, GL_EMISSION, black);
}

void stin__map_facing_draw(stin_context *ctx, uint32_t slot, const stin_light_desc *l,
                           const float view[16], const float proj[16])
{
    struct stin__map_fixed_state *m = ctx->map_fixed;
    stin__pass_state ps = *stin__pass_current(ctx); /* the map pass's viewport and scissor */
    const int *vp = ctx->frame.viewport;
    int x = m->fbo ? 0 : vp[0], y = m->fbo ? 0 : vp[1];
    if (m->fbo)
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, m->facing_fbo);
    ps.depth_test = ps.depth_write = ps.color_write = 1;
    ps.depth_func = GL_LESS;
    ps.polygon_offset = 0;
    ps.color_only = 0;
    stin__pass_apply(ctx, &ps);
    stin__clear_depth(ctx, 1.0);
    GL(ctx, ClearColor)(1.0f, 1.0f, 1.0f, 1.0f); /* no surface: lit in both copies */
    GL(ctx, Clear)(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    side_colours(ctx, 1);
    if (stin__casters_drew(ctx)) {
        /* a CSG product's surface the light sees is its outside, whichever
         * side of a primitive makes it (csg/cast.c): white */
        static const float white[4] = {1, 1, 1, 1}, black[4] = {0, 0, 0, 1};
        const int map_vp[4] = {x, y, (int)m->used, (int)m->used};
        GL(ctx, Materialfv)(GL_BACK, GL_EMISSION, white);
        stin__casters_again(ctx, map_vp, m->fbo ? m->facing_fbo : ctx->draw_fbo,
                            !m->fbo && stin__target_has_stencil(ctx));
        GL(ctx, Materialfv)(GL_BACK, GL_EMISSION, black);
    }
    if (m->terminator)
        stin__map_terminator_side_draw(ctx, slot, l, view, proj);
    else
        stin__fixed_path()->depth(ctx, view, proj, 0, 0.0f);
    side_colours(ctx, 0);
    copy_side(ctx, m->facing[slot], x, y);
    invert_covered(ctx, ps);
    copy_side(ctx, m->facing_back[slot], x, y);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    ctx->stats.passes++;
}

void stin__map_facing_bind(stin_context *ctx, uint32_t slot)
{
    struct stin__map_fixed_state *m = ctx->map_fixed;
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)m->unit + 1u));
    GL_ENABLE(ctx, GL_TEXTURE_2D);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, m->facing[slot]);
    stin__map_texgen(ctx, m->texgen[slot], 0);
    m->slot = slot;
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
}

void stin__map_facing_unbind(stin_context *ctx)
{
    stin__map_unit_off(ctx, ctx->map_fixed->unit + 1);
}

/* The window's front faces are the surface's front (the side its
 * counter-clockwise normal points to) as the eye sees it, unless the
 * camera mirrors: every standard projection has a negative determinant. */
static int camera_mirrored(const stin_context *ctx)
{
    return stin__mat4_det(ctx->projection) * stin__mat4_det(ctx->frame.view) > 0.0;
}

void stin__map_facing_shade(stin_context *ctx, const stin__path *path, const stin_light_desc *l,
                            stin__shade_fn shade)
{
    const struct stin__map_fixed_state *m = ctx->map_fixed;
    GLenum unit = (GLenum)(GL_TEXTURE0 + (GLenum)m->unit + 1u);
    int mirrored = camera_mirrored(ctx), side;
    if (!m->facing_test) {
        shade(ctx, path, l, 1.0f);
        return;
    }
    for (side = 0; side < 2; side++) { /* 0: the eye sees front faces, 1: back faces */
        GL(ctx, ActiveTexture)(unit);
        if (m->terminator) {
            stin__map_terminator_side(ctx, side);
        } else { /* the colour times the map of the eye's side */
            GL(ctx, BindTexture)(GL_TEXTURE_2D, side ? m->facing_back[m->slot] : m->facing[m->slot]);
            GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        }
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
        ctx->lit_cull = (side == 0) != mirrored ? GL_BACK : GL_FRONT;
        shade(ctx, path, l, 1.0f);
    }
    ctx->lit_cull = 0;
}
