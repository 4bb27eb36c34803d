/* SPDX-License-Identifier: MIT */
/* map-depth's terminator test: no steps and no acne where a closed solid
 * turns from the light.
 *
 * The depth maps are second-depth maps for closed solids (at least the
 * margin below across: a thinner one is treated as open): they draw only
 * their faces turned away from the light (render/path_fixed.c), so a solid's
 * surface facing the light compares against its own far side and one turned
 * away against itself, lit (D). Open casters (floors, two_sided materials)
 * and CSG products keep both sides and the ordinary offset. The side map
 * holds, for an open caster, the side the light sees (shadow/map_facing.c);
 * for a solid, the light's diffuse term at its far faces' vertex normals,
 * saturated (S: 1 where the shading normal faces the light). Fixed function
 * cannot lift the lookup point per pixel, so whether a pixel is its own
 * stored surface is a second lookup of the same map with the depth pushed
 * back by `lift` (F: 1 where the stored surface lies that far behind, the
 * lit side of a solid).
 *
 * The rule is the receiver's, set per draw (ctx->lit_draw): a solid seen
 * from outside is lit where 4 D S + F >= 1/2 (the alpha test), its
 * colour times D, so the band between a facet turned from the light and a shading
 * normal turned to it is lit and the side turned from the light keeps its
 * shadow; every other receiver (open surfaces, CSG products, a solid seen
 * from inside) keeps the facet: D times the side (map_facing.c). Its units:
 * the depth test's puts D alone into alpha, the side map's multiplies it by
 * S (or the colour by the side), the next one adds F. */
#include "shadow/map_fixed_private.h"

/* F's margin: the far side must lie 1.5 texels' depth behind (a solid
 * thinner than that across is treated as open) */
#define LIFT_TEXELS 1.5f
/* the side pass's diffuse gain, GL's eight lights: S saturates at N.L = 1 / 8 */
#define FACING_GAIN 8
/* The alpha test keeps a solid's fragment where SIDE_SCALE * D * S + F >=
 * 1/2: S counts from N.L = 1 / 64 on (under the check's 0.05), D from 1/8
 * on (below that the filtered edge goes dark a little early), F from half
 * its 2x2 filter on (a fraction of a far side's texels is the surface's
 * own texels at a slope, not a far side). */
#define SIDE_SCALE 4

int stin__map_terminator_units(void) { return 1; }

void stin__map_terminator_init(stin_context *ctx, int units)
{
    struct stin__map_fixed_state *m = ctx->map_fixed;
    int need = m->unit + units + stin__map_terminator_units();
    if (need > ctx->caps.max_texture_units) {
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                  "shadows: map-depth's terminator test needs texture unit %d, after the "
                  "surface's, the map's, its side test's and point lights' faces' (%d units): "
                  "self-shadowing is decided by the facet (terminator steps, acne)",
                  need - 1, ctx->caps.max_texture_units);
        return;
    }
    m->terminator = 1;
}

/* One texel's depth in the map's window depth: for an orthographic map the
 * texel's width over the depth range, for a perspective one the texel's
 * angle, which a constant added to r turns into a margin growing with the
 * distance as the texel does. Plus twice the offset's units, in steps of
 * the 24-bit map: a perspective map's texel is a few such steps deep far
 * from the light, where the surface's own offset would pass F. */
void stin__map_terminator_lift(stin_context *ctx, uint32_t slot, const float proj[16], float n,
                               float f, float units)
{
    int ortho = proj[15] != 0.0f;
    float texel = 2.0f / (proj[0] * (float)ctx->map_fixed->used);
    float per_depth = ortho ? 1.0f / (f - n) : f * n / (f - n);
    ctx->map_fixed->lift[slot] = LIFT_TEXELS * texel * per_depth + 2.0f * units / 16777216.0f;
    ctx->map_fixed->solid_min[slot] = LIFT_TEXELS * texel * (ortho ? 1.0f : f);
}

/* The solids' colours in the side pass: their far faces lit one-sided by
 * their own normals, GL's eight lights at the light's place adding up to
 * the gain (colours above 1 may be clamped where they are given). */
static void solid_colours(stin_context *ctx, const stin_light_desc *l, const float view[16])
{
    static const float black[4] = {0, 0, 0, 1}, white[4] = {1, 1, 1, 1};
    int dir = l->type == STIN_LIGHT_DIRECTIONAL, k;
    float pos[4];
    for (k = 0; k < 3; k++)
        pos[k] = dir ? -l->direction[k] : l->position[k];
    pos[3] = dir ? 0.0f : 1.0f;
    GL(ctx, LightModeli)(GL_LIGHT_MODEL_TWO_SIDE, 0);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_DIFFUSE, white);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_EMISSION, black);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(view);
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

/* The side pass's casters, the side colours on (map_facing.c): open ones by
 * those colours, then the solids' far faces by their shading normals. */
void stin__map_terminator_side_draw(stin_context *ctx, uint32_t slot, const stin_light_desc *l,
                                    const float view[16], const float proj[16])
{
    float min = ctx->map_fixed->solid_min[slot];
    stin__fixed_path()->depth(ctx, view, proj, STIN__DEPTH_FAR_SIDE | STIN__DEPTH_OPEN_ONLY, min);
    solid_colours(ctx, l, view);
    stin__fixed_path()->depth(ctx, view, proj, STIN__DEPTH_FAR_SIDE | STIN__DEPTH_SOLIDS_ONLY, min);
}

/* The side and F units (side active on entry, unit 0 on return) for a
 * receiver lit by the terminator rule (solid) or by the facet. */
static void receiver_units(stin_context *ctx, int solid)
{
    struct stin__map_fixed_state *m = ctx->map_fixed;
    int back = m->eye_back;
    /* the facet: the colour times the map of the eye's side, alpha kept */
    static const stin__combine_stage facet = {GL_MODULATE, {GL_PREVIOUS, GL_TEXTURE},
                                              {GL_SRC_COLOR, GL_SRC_COLOR}, GL_REPLACE,
                                              {GL_PREVIOUS, 0}, {GL_SRC_ALPHA, 0}};
    static const stin__combine_stage side = {GL_REPLACE, {GL_PREVIOUS, 0}, {GL_SRC_COLOR, 0},
                                             GL_MODULATE, {GL_TEXTURE, GL_PREVIOUS},
                                             {GL_SRC_ALPHA, GL_SRC_ALPHA}};
    static const stin__combine_stage kept = {GL_REPLACE, {GL_PREVIOUS, 0}, {GL_SRC_COLOR, 0},
                                             GL_REPLACE, {GL_PREVIOUS, 0}, {GL_SRC_ALPHA, 0}};
    static const stin__combine_stage lifted = {GL_REPLACE, {GL_PREVIOUS, 0}, {GL_SRC_COLOR, 0},
                                               GL_ADD, {GL_PREVIOUS, GL_TEXTURE},
                                               {GL_SRC_ALPHA, GL_SRC_ALPHA}};
    GL(ctx, BindTexture)(GL_TEXTURE_2D, back ? m->facing_back[m->slot] : m->facing[m->slot]);
    stin__combine_set(ctx, solid ? &side : &facet);
    GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_ALPHA_SCALE, solid ? SIDE_SCALE : 1);
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)m->unit + 2u));
    stin__combine_set(ctx, solid ? &lifted : &kept);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    if (solid)
        GL_ENABLE(ctx, GL_ALPHA_TEST);
    else
        GL_DISABLE(ctx, GL_ALPHA_TEST);
    m->receiver = solid;
}

static void lit_draw(stin_context *ctx, const stin__draw *d)
{
    const struct stin__map_fixed_state *m = ctx->map_fixed;
    int solid = !m->eye_back && stin__draw_solid(ctx, d, m->solid_min[m->slot]);
    if (solid == m->receiver)
        return;
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)m->unit + 1u));
    receiver_units(ctx, solid);
}

void stin__map_terminator_bind(stin_context *ctx, uint32_t slot)
{
    /* the depth test: the colour times it, the test alone into alpha */
    static const stin__combine_stage tested = {GL_MODULATE, {GL_PREVIOUS, GL_TEXTURE},
                                               {GL_SRC_COLOR, GL_SRC_COLOR}, GL_REPLACE,
                                               {GL_TEXTURE, 0}, {GL_SRC_ALPHA, 0}};
    struct stin__map_fixed_state *m = ctx->map_fixed;
    float rows[16];
    GLenum u = (GLenum)(GL_TEXTURE0 + (GLenum)m->unit + 2u);
    stin__memcopy(rows, m->texgen[slot], sizeof rows);
    rows[11] += m->lift[slot];
    m->slot = slot;
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)m->unit));
    stin__combine_set(ctx, &tested);
    GL(ctx, ActiveTexture)(u);
    GL_ENABLE(ctx, GL_TEXTURE_2D);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, m->textures[slot]);
    stin__map_texgen(ctx, rows, 1);
    GL(ctx, AlphaFunc)(GL_GEQUAL, 0.5f); /* SIDE_SCALE * D * S + F */
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
}

/* The side the eye sees for the draws that follow (side unit active): each
 * draw's receiver sets the units (ctx->lit_draw), the facet's until then
 * (a pass that draws without the hook). */
void stin__map_terminator_side(stin_context *ctx, int back)
{
    ctx->map_fixed->eye_back = back;
    receiver_units(ctx, 0);
    ctx->lit_draw = lit_draw;
}

void stin__map_terminator_unbind(stin_context *ctx)
{
    ctx->lit_draw = NULL;
    GL_DISABLE(ctx, GL_ALPHA_TEST);
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)ctx->map_fixed->unit + 1u));
    GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 1);
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)ctx->map_fixed->unit));
    GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)ctx->map_fixed->unit + 2u));
    GL_DISABLE(ctx, GL_TEXTURE_GEN_R);
    stin__map_unit_off(ctx, ctx->map_fixed->unit + 2);
}
