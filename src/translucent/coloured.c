/* SPDX-License-Identifier: MIT */
/* Coloured shadow maps ("coloured", GL2 and up): deep's fallback.
 *
 * Per light, just before its lit pass, the transparent casters are drawn
 * from the light twice into one atlas (faces of translucent.deep_map_size, three across
 * and two down; spot and directional lights use face 0, fitted as the
 * shadow maps are; point lights six 90-degree faces): first their depth
 * alone (LESS: the nearest transparent surface per texel), then, with no
 * depth test, their eq 5.3 factors (1 - a) clamp(1 - a + c, 0, 1) into an
 * RGBA8 map cleared to white, blended as dst * src, so the texel holds the
 * product of every transparent surface on its ray in any order. The lit
 * pass (shaders/gl2/translucent_coloured.glsl) takes the product where the
 * point lies behind the nearest transparent depth and 1 in front of it.
 * That is exact unless a transparent caster lies behind the point on its
 * ray (a receiver between two panes takes both). No opaque depth is drawn:
 * a transparent caster behind an opaque one only tints points the shadows
 * technique already darkened fully (opaque casters stay its). */
#include "translucent/translucent_private.h"

#define ATLAS_COLUMNS 3
#define ATLAS_ROWS 2

static int chosen(const stin_context *ctx)
{
    return ctx->sel.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].technique ==
           STIN_TECH_TRANSLUCENT_COLOURED;
}

static int gl4(const stin_context *ctx)
{
    return ctx->sel.choice[STIN_FEATURE_LIGHTING].technique == STIN_TECH_LIGHTING_GLSL150;
}

size_t stin__coloured_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(stin__coloured_state);
}

/* (Built before the set-up: with shadows off it will fall back.) */
const char *stin__coloured_chunk(const stin_context *ctx)
{
    return chosen(ctx) && ctx->shadow && ctx->shadow->light ? "translucent_coloured.glsl" : NULL;
}

void stin__coloured_release(stin_context *ctx)
{
    stin__coloured_state *s = ctx->coloured;
    if (s->color)
        GL(ctx, DeleteTextures)(1, &s->color);
    if (s->depth)
        GL(ctx, DeleteTextures)(1, &s->depth);
    if (s->fbo)
        GL(ctx, DeleteFramebuffers)(1, &s->fbo);
    if (s->program)
        GL(ctx, DeleteProgram)(s->program);
    stin__memzero(s, sizeof *s);
}

/* The atlases and the framebuffer; "" or why they cannot be made. */
static const char *make_targets(stin_context *ctx)
{
    stin__coloured_state *s = ctx->coloured;
    GLsizei w = (GLsizei)(ATLAS_COLUMNS * s->size), h = (GLsizei)(ATLAS_ROWS * s->size);
    GLenum status;
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, GenTextures)(1, &s->color);
    stin__rt_texture(ctx, s->color, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, w, h);
    GL(ctx, GenTextures)(1, &s->depth);
    stin__rt_texture(ctx, s->depth, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, w,
                     h);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL(ctx, GenFramebuffers)(1, &s->fbo);
    status = stin__rt_attach(ctx, s->fbo, s->color, s->depth, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, 0);
    return status == GL_FRAMEBUFFER_COMPLETE ? "" : "its RGBA8 + depth framebuffer is incomplete";
}

static const stin__uniform_name cast_uniforms[] = {
    STIN__UNIFORM(stin__coloured_state, u_model, "u_model"),
    STIN__UNIFORM(stin__coloured_state, u_view_proj, "u_view_proj"),
    STIN__UNIFORM(stin__coloured_state, u_albedo, "u_albedo"),
    STIN__UNIFORM(stin__coloured_state, u_albedo_tex, "u_albedo_tex"),
    STIN__UNIFORM(stin__coloured_state, u_has_albedo_tex, "u_has_albedo_tex"),
};

static int make_program(stin_context *ctx, char *msg, size_t size)
{
    stin__coloured_state *s = ctx->coloured;
    stin__program_source src;
    stin__memzero(&src, sizeof src);
    src.vert = gl4(ctx) ? "gl4/deep_peel.vert" : "gl2/coloured_cast.vert";
    src.frag = gl4(ctx) ? "gl4/coloured_cast.frag" : "gl2/coloured_cast.frag";
    s->program = stin__program_build_source(ctx, &src, msg, size);
    if (!s->program)
        return 0;
    STIN__LOCATE(ctx, s->program, s, cast_uniforms);
    stin__displace_locate(ctx, s->program, 0, &s->displace);
    return 1;
}

void stin__coloured_init(stin_context *ctx)
{
    stin__coloured_state *s = ctx->coloured;
    char msg[160], why[220];
    const char *fail = "";
    uint32_t largest = ctx->caps.max_texture_size > 0 ? (uint32_t)ctx->caps.max_texture_size : 0;
    if (!chosen(ctx))
        return;
    stin__memzero(s, sizeof *s);
    s->size = ctx->desc.translucent.deep_map_size;
    while (largest && s->size > 1 && ATLAS_COLUMNS * s->size > largest)
        s->size /= 2u; /* three faces across must fit the largest texture */
    s->unit = ctx->sel.translucent_unit;
    msg[0] = '\0';
    if (!ctx->shadow->light)
        fail = "shadows are off, so no light is shadowed";
    else if (!make_program(ctx, msg, sizeof msg))
        fail = "its caster program failed to build";
    else
        fail = make_targets(ctx);
    if (fail[0]) {
        stin__formatf(why, sizeof why, "coloured: %s%s%s%s", fail, msg[0] ? " (" : "", msg,
                      msg[0] ? ")" : "");
        stin__coloured_release(ctx);
        stin__demote_at(ctx, stin__translucent_fallback_level(ctx, !ctx->shadow->light),
                        STIN_FEATURE_TRANSLUCENT_SHADOWS, STIN_TECH_TRANSLUCENT_OPAQUE, why);
        return;
    }
    s->ready = 1;
}

void stin__coloured_uniforms(stin_context *ctx, const stin__program *p)
{
    const stin__coloured_state *s = ctx->coloured;
    float params[4];
    params[0] = (float)s->size;
    params[1] = s->normal_offset;
    params[2] = (ctx->desc.debug_flags & STIN_DEBUG_COLOURED_NO_DEPTH) ? 0.0f : 1.0f;
    params[3] = 0.0f;
    if (!stin__translucent_set(ctx, &p->coloured, s->kind, &s->matrix[0][0], params))
        return;
    stin__bind_unit(ctx, s->unit, GL_TEXTURE_2D, s->color);
    stin__bind_unit(ctx, s->unit + 1, GL_TEXTURE_2D, s->depth);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
}

int stin__coloured_active(const stin_context *ctx)
{
    return ctx->coloured->ready && ctx->coloured->frame_transparent;
}

static void draw_transparent(stin_context *ctx)
{
    const stin__coloured_state *s = ctx->coloured;
    stin__translucent_draw_casters(ctx, s->u_model, s->u_albedo, s->u_has_albedo_tex, &s->displace);
}

/* One face into its cell of the atlas: the nearest depth, then the product. */
static void draw_face(stin_context *ctx, int face, const float view[16], const float proj[16])
{
    stin__coloured_state *s = ctx->coloured;
    stin__pass_state ps = stin__pass_defaults;
    float view_proj[16];
    stin__mat4_mul(view_proj, proj, view);
    stin__light_window_matrix(s->matrix[face], view, proj);
    GL(ctx, UniformMatrix4fv)(s->u_view_proj, 1, GL_FALSE, view_proj);
    GL(ctx, Viewport)((GLint)((uint32_t)(face % ATLAS_COLUMNS) * s->size),
                      (GLint)((uint32_t)(face / ATLAS_COLUMNS) * s->size), (GLsizei)s->size,
                      (GLsizei)s->size);
    ps.depth_test = 1; /* LESS with writes: the nearest transparent surface */
    ps.color_write = 0;
    stin__pass_apply(ctx, &ps);
    draw_transparent(ctx);
    ps.depth_test = 0; /* every surface's factor, multiplied in */
    ps.depth_write = 0;
    ps.color_write = 1;
    ps.blend = 1;
    ps.blend_src = GL_ZERO;
    ps.blend_dst = GL_SRC_COLOR;
    stin__pass_apply(ctx, &ps);
    draw_transparent(ctx);
    ctx->stats.passes += 2;
}

void stin__coloured_light(stin_context *ctx, uint32_t li)
{
    stin__coloured_state *s = ctx->coloured;
    stin__pass_state ps = stin__pass_defaults;
    s->kind = 0;
    if (!stin__coloured_active(ctx) || li >= ctx->light_count)
        return;
    stin__translucent_say_area(ctx, &ctx->lights[li], &s->said_area, "coloured");
    stin__translucent_unbind(ctx, s->unit, GL_TEXTURE_2D); /* neither atlas sampled while drawn */
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->fbo);
    GL(ctx, Viewport)(0, 0, (GLsizei)(ATLAS_COLUMNS * s->size), (GLsizei)(ATLAS_ROWS * s->size));
    stin__pass_apply(ctx, &ps); /* writes on, no scissor: the clear covers the atlas */
    GL(ctx, ClearColor)(1.0f, 1.0f, 1.0f, 1.0f);
    stin__clear_depth(ctx, 1.0);
    GL(ctx, Clear)(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    GL(ctx, UseProgram)(s->program);
    stin__lit_program_forget(ctx); /* the lit program is no longer current */
    ctx->bound_mesh = 0xffffffffu;
    GL(ctx, Uniform1i)(s->u_albedo_tex, 0);
    s->kind = stin__translucent_faces(ctx, &ctx->lights[li], s->size, draw_face, &s->normal_offset);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    GL(ctx, Viewport)(ctx->frame.viewport[0], ctx->frame.viewport[1], ctx->frame.viewport[2],
                      ctx->frame.viewport[3]);
    ctx->bound_mesh = 0xffffffffu;
}

void stin__coloured_light_done(stin_context *ctx)
{
    stin__coloured_state *s = ctx->coloured;
    if (!s->kind)
        return;
    s->kind = 0;
    stin__translucent_unbind(ctx, s->unit, GL_TEXTURE_2D);
}
