/* SPDX-License-Identifier: MIT */
/* map-depth's terminator test: no steps and no acne where a surface turns
 * from the light.
 *
 * The depth maps are second-depth maps: closed meshes draw only their faces
 * turned away from the light (render/path_fixed.c), so a surface facing the
 * light compares against its own far side and one turned away against
 * itself, lit (D). The side pass draws the same faces, coloured by the
 * light's diffuse term at the vertex normals, saturated (S: 1 where the
 * shading normal faces the light). Fixed function cannot lift the lookup
 * point per pixel, so whether a pixel is its own stored surface is a second
 * lookup of the same map with the depth pushed back by `lift` (F: 1 where
 * the stored surface lies that far behind, the lit side of a solid). A
 * fragment the eye sees from the front is lit by D * min(1, F + S), from
 * the back by D * (1 - S) (an open surface's side test): the
 * side turned from the light keeps its shadow where its shading normal
 * turns away too, the terminator band between facet and shading normal
 * is lit. The depth test's unit puts D alone into alpha, the side map's
 * multiplies it by the side, two units after those add F and multiply the
 * colour by the sum and the fragment's own alpha (a translucent draw keeps
 * its opacity). */
#include "shadow/map_fixed_private.h"

/* F's margin: the far side must lie 1.5 texels' depth behind (a solid
 * thinner than that is lit on its facing side by S alone) */
#define LIFT_TEXELS 1.5f
/* the side pass's diffuse gain, GL's eight lights: S saturates at N.L = 1 / 8 */
#define FACING_GAIN 8

int stin__map_terminator_units(void) { return 2; }

/* F cannot tell an open surface's own steep back, which the light sees
 * through an opening, from a solid's far side: frames with an open caster
 * (or a CSG product, drawn by its nearest surface) keep the facet. */
int stin__map_terminator_frame(const stin_context *ctx)
{
    uint32_t i;
    if (stin__casters_wanted(ctx))
        return 0;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[i];
        if (d->shadow_caster &&
            (d->material.two_sided || !ctx->meshes[d->mesh_slot].info.closed_manifold))
            return 0;
    }
    return 1;
}

/* One texel's depth in the map's window depth: for an orthographic map the
 * texel's width over the depth range, for a perspective one the texel's
 * angle, which a constant added to r turns into a margin growing with the
 * distance as the texel does. */
void stin__map_terminator_lift(stin_context *ctx, uint32_t slot, const float proj[16], float n,
                               float f)
{
    float texel = 2.0f / (proj[0] * (float)ctx->map_fixed->used);
    float per_depth = proj[15] != 0.0f ? 1.0f / (f - n) : f * n / (f - n);
    ctx->map_fixed->lift[slot] = LIFT_TEXELS * texel * per_depth;
}

void stin__map_terminator_side_colours(stin_context *ctx, const stin_light_desc *l,
                                       const float view[16])
{
    static const float black[4] = {0, 0, 0, 1}, white[4] = {1, 1, 1, 1};
    int dir = l->type == STIN_LIGHT_DIRECTIONAL, k;
    float pos[4];
    for (k = 0; k < 3; k++)
        pos[k] = dir ? -l->direction[k] : l->position[k];
    pos[3] = dir ? 0.0f : 1.0f;
    /* one-sided: the faces turned away lit by their own normals */
    GL(ctx, LightModeli)(GL_LIGHT_MODEL_TWO_SIDE, 0);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_DIFFUSE, white);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_EMISSION, black);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(view);
    /* GL's eight lights at the light's place add up to the gain (colours
     * above 1 may be clamped where they are given) */
    for (k = 0; k < FACING_GAIN; k++) {
        GLenum id = (GLenum)(GL_LIGHT0 + k);
        GL(ctx, Lightfv)(id, GL_POSITION, pos);
        GL(ctx, Lightfv)(id, GL_DIFFUSE, white);
        GL(ctx, Lightfv)(id, GL_AMBIENT, black);
        GL(ctx, Lightfv)(id, GL_SPECULAR, black);
        GL(ctx, Lightf)(id, GL_SPOT_CUTOFF, 180.0f);
        GL(ctx, Lightf)(id, GL_CONSTANT_ATTENUATION, 1.0f);
        GL(ctx, Lightf)(id, GL_LINEAR_ATTENUATION, 0.0f);
        GL(ctx, Lightf)(id, GL_QUADRATIC_ATTENUATION, 0.0f);
        GL_ENABLE(ctx, id);
    }
}

void stin__map_terminator_bind(stin_context *ctx, uint32_t slot)
{
    /* the colour times it, the alpha times the fragment's own */
    static const stin__combine_stage apply = {GL_MODULATE, {GL_PREVIOUS, GL_PREVIOUS},
                                              {GL_SRC_COLOR, GL_SRC_ALPHA}, GL_MODULATE,
                                              {GL_PREVIOUS, GL_PRIMARY_COLOR},
                                              {GL_SRC_ALPHA, GL_SRC_ALPHA}};
    /* the depth test: the colour times it, the test alone into alpha */
    static const stin__combine_stage tested = {GL_MODULATE, {GL_PREVIOUS, GL_TEXTURE},
                                               {GL_SRC_COLOR, GL_SRC_COLOR}, GL_REPLACE,
                                               {GL_TEXTURE, 0}, {GL_SRC_ALPHA, 0}};
    struct stin__map_fixed_state *m = ctx->map_fixed;
    float rows[16];
    GLenum u = (GLenum)(GL_TEXTURE0 + (GLenum)m->unit + 2u);
    stin__memcopy(rows, m->texgen[slot], sizeof rows);
    rows[11] += m->lift[slot];
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)m->unit));
    stin__map_combine(ctx, &tested);
    GL(ctx, ActiveTexture)(u);
    GL_ENABLE(ctx, GL_TEXTURE_2D);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, m->textures[slot]);
    stin__map_texgen(ctx, rows, 1); /* its stage: per side the eye sees */
    GL(ctx, ActiveTexture)(u + 1u); /* its texture is not read: any enables the stage */
    GL_ENABLE(ctx, GL_TEXTURE_2D);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, m->facing[slot]);
    stin__map_combine(ctx, &apply);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
}

/* The side unit (active): the colour passed on, the alpha (the depth test)
 * times the side (back: 1 - side). F only for the side the eye sees from
 * the front: a closed mesh is seen from outside, and a surface seen from
 * behind is open, its own stored surface, whose full offset F's margin
 * need not exceed. */
void stin__map_terminator_side(stin_context *ctx, int back)
{
    /* a frame without the test: the side map's own test, the alpha kept */
    const stin__combine_stage plain = {GL_MODULATE, {GL_PREVIOUS, GL_TEXTURE},
                                       {GL_SRC_COLOR, back ? GL_ONE_MINUS_SRC_COLOR : GL_SRC_COLOR},
                                       GL_REPLACE, {GL_PREVIOUS, 0}, {GL_SRC_ALPHA, 0}};
    const stin__combine_stage side = {GL_REPLACE, {GL_PREVIOUS, 0}, {GL_SRC_COLOR, 0}, GL_MODULATE,
                                      {GL_TEXTURE, GL_PREVIOUS},
                                      {back ? GL_ONE_MINUS_SRC_ALPHA : GL_SRC_ALPHA, GL_SRC_ALPHA}};
    const stin__combine_stage lifted = {GL_REPLACE, {GL_PREVIOUS, 0}, {GL_SRC_COLOR, 0},
                                        back ? GL_REPLACE : GL_ADD, {GL_PREVIOUS, GL_TEXTURE},
                                        {GL_SRC_ALPHA, GL_SRC_ALPHA}};
    if (!ctx->map_fixed->lifted) {
        stin__map_combine(ctx, &plain);
        return;
    }
    stin__map_combine(ctx, &side);
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)ctx->map_fixed->unit + 2u));
    stin__map_combine(ctx, &lifted);
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)ctx->map_fixed->unit + 1u));
}

void stin__map_terminator_unbind(stin_context *ctx)
{
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)ctx->map_fixed->unit));
    GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)ctx->map_fixed->unit + 2u));
    GL_DISABLE(ctx, GL_TEXTURE_GEN_R);
    stin__map_unit_off(ctx, ctx->map_fixed->unit + 2);
    stin__map_unit_off(ctx, ctx->map_fixed->unit + 3);
}
