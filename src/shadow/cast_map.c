/* SPDX-License-Identifier: MIT */
/* The casters stencil volumes cannot cast, cast for them through a map of
 * their own on the GLSL tiers: the CSG products (a product's volume would
 * need its resolved silhouette, not its primitives') and displaced draws
 * (volumes' silhouettes would be the undisplaced mesh's). Per light, just
 * before its volumes are counted, they go into one depth map from the light
 * (the products by csg/cast.c's resolve through render/casters.h, the
 * displaced draws by the path's depth pass), and after the count a pass
 * over the frame's surfaces, depth EQUAL, sets the stencil non-zero
 * wherever that map shadows them (map-pcf's test: its kernel and
 * receiver-plane bias, lit where half the kernel is). The lit pass, or the
 * screen mask's write, then lights only where both the volumes and the map
 * say lit. One map serves every light in turn, drawn mid-frame as map-pcf
 * draws a point light's faces. On GL1 the marking pass is the
 * fixed-function path's geometry with map-depth's or map-combine's test
 * (shadow/cast_map_fixed.c), for every kind of light; on GL 1.1 (one
 * texture unit) the map is read back and tested per pixel on the CPU
 * (shadow/cast_readback.c). vdsm without storage
 * buffers casts the products through the same map into its screen mask.
 * Frames without such casters draw nothing of it. */
#include "shadow/cast_map_private.h"

/* The map is an atlas (shadow.h's cells, cast_mark.frag's lookup): a spot
 * or directional light's map in cell 0, a point light's face f in cell f. */
typedef stin__mark_program mark_program;

size_t stin__cast_map_state_bytes(const stin_desc *d)
{
    return stin__align16(sizeof(struct stin__cast_map_state)) + stin__cast_readback_bytes(d);
}

static const stin__uniform_name mark_uniforms[] = {
    STIN__UNIFORM(mark_program, u_model, "u_model"),
    STIN__UNIFORM(mark_program, u_view_proj, "u_view_proj"),
    STIN__UNIFORM(mark_program, u_position, "u_position"),
    STIN__UNIFORM(mark_program, u_matrix, "u_cast_matrix"),
    STIN__UNIFORM(mark_program, u_params, "u_cast_params"),
    STIN__UNIFORM(mark_program, u_light, "u_cast_light"),
    STIN__UNIFORM(mark_program, u_faces, "u_cast_faces"),
    STIN__UNIFORM(mark_program, u_map, "u_shadow_map"), /* map-pcf's tap chunk's */
};

static int has(const stin_context *ctx, uint64_t need)
{
    return (ctx->caps.present & need) == need;
}

/* The map needs a framebuffer object and depth textures; without shadow
 * compare (OpenGL ES 2.0's OES_depth_texture) the GLSL test compares in
 * the shader, as map-pcf's lit programs do there. The fixed-function path's marking pass needs a second texture unit (the
 * geometry pass turns unit 0's texture off); there, without framebuffer
 * objects, the map is drawn in the frame's own buffer (its stencil for the
 * products' resolve) and copied out, as depth or as map-combine's ramp. */
static int maps_here(const stin_context *ctx)
{
    uint64_t compare = STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE) | STIN_CAP_BIT(STIN_CAP_SHADOW);
    if (stin__path_of(ctx) == stin__glsl_path())
        return has(ctx, STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE) | STIN_CAP_BIT(STIN_CAP_FBO));
    if (!has(ctx, STIN_CAP_BIT(STIN_CAP_MULTITEXTURE) | STIN_CAP_BIT(STIN_CAP_STENCIL)))
        return 0;
    return has(ctx, compare) || (has(ctx, STIN_CAP_BIT(STIN_CAP_TEXTURE_ENV_COMBINE)) &&
                                 ctx->caps.max_texture_units >= 3); /* the map and the ramp */
}

/* The map compares by its sampler (ARB_shadow, ES 3.0), else by its test. */
static int compares(const stin_context *ctx)
{
    return has(ctx, STIN_CAP_BIT(STIN_CAP_SHADOW));
}

/* The programs with the map test: volumes' marking pass (tessellated:
 * its twin for displace-tess frames, whose lit passes are tessellated), or
 * vdsm's mask pass (GL4: a screen quad over its position buffer). */
enum { MARK, MARK_TESS, MASK };
static int build_test(stin_context *ctx, int kind, mark_program *p, char *msg, size_t size)
{
    const char *dir = ctx->sel.tier == STIN_TIER_GL4 ? "gl4/" : "gl2/";
    char vert[40], frag[40], chunk[40], tap[40];
    const char *chunks[3];
    stin__formatf(vert, sizeof vert, "%s%s", dir, kind == MASK ? "screen.vert" : "cast_mark.vert");
    stin__formatf(frag, sizeof frag, "%s%s", dir, kind == MASK ? "cast_mask.frag" : "cast_mark.frag");
    stin__formatf(tap, sizeof tap, "%s%s", dir,
                  compares(ctx) ? "pcf_tap_compare.glsl" : "pcf_tap_depth.glsl");
    stin__formatf(chunk, sizeof chunk, "%scast_test.glsl", dir);
    chunks[0] = tap;
    chunks[1] = chunk;
    chunks[2] = NULL;
    p->name = stin__program_build(ctx, vert, frag, chunks, kind == MARK_TESS, msg, size);
    if (!p->name)
        return 0;
    STIN__LOCATE(ctx, p->name, p, mark_uniforms);
    stin__displace_locate(ctx, p->name, 1, &p->displace);
    return 1;
}

/* The map and its framebuffer, once for volumes and vdsm (the measured
 * choice sets up both). */
static void make_map(stin_context *ctx)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    GLint caller_fbo[2];
    uint32_t size = ctx->desc.shadows.map_size;
    if (m->texture)
        return;
    while (ctx->caps.max_texture_size > 0 && size > 1u &&
           STIN__ATLAS_COLUMNS * size > (uint32_t)ctx->caps.max_texture_size)
        size /= 2u; /* three cells across must fit */
    m->size = size;
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, GenTextures)(1, &m->texture);
    if (m->fixed || compares(ctx))
        stin__rt_shadow_map(ctx, m->texture, (int)(STIN__ATLAS_COLUMNS * size),
                            (int)(STIN__ATLAS_ROWS * size));
    else /* read as numbers (NEAREST), unsized: OES_depth_texture's only form */
        stin__rt_texture(ctx, m->texture, GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT,
                         GL_UNSIGNED_INT, (int)(STIN__ATLAS_COLUMNS * size),
                         (int)(STIN__ATLAS_ROWS * size));
    if (m->fixed) /* the compare's result in alpha too, for the alpha test */
        GL_ENUM(ctx, TexParameteri, GL_DEPTH_TEXTURE_MODE)(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE,
                                                           GL_INTENSITY);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    stin__framebuffer_save(ctx, caller_fbo); /* the caller's binding survives */
    GL(ctx, GenFramebuffers)(1, &m->fbo);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, m->fbo);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m->texture,
                                  0);
    stin__no_colour_buffers(ctx); /* depth only */
    if (!m->fixed && !compares(ctx))
        stin__rt_depth_measure(ctx); /* the unsized texture's bits: the offset's step */
    stin__framebuffer_restore(ctx, caller_fbo);
}

/* Volumes have something to cast through the map where the frame may have
 * products or displaced draws. */
static int has_casters(const stin_context *ctx)
{
    return ctx->sel.choice[STIN_FEATURE_CSG].technique != STIN_TECH_CSG_OFF ||
           stin__displace_built(ctx);
}

void stin__cast_map_init(stin_context *ctx, int screen)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    char msg[160], why[220];
    int built;
    if (!screen && stin__path_of(ctx) != stin__glsl_path() && !maps_here(ctx) &&
        has(ctx, STIN_CAP_BIT(STIN_CAP_STENCIL)) &&
        ctx->sel.choice[STIN_FEATURE_CSG].technique != STIN_TECH_CSG_OFF) {
        stin__cast_readback_init(ctx); /* GL 1.1: no second unit for a map's test */
        return;
    }
    if (!maps_here(ctx) || !has_casters(ctx) ||
        (screen && ctx->sel.choice[STIN_FEATURE_CSG].technique == STIN_TECH_CSG_OFF))
        return; /* vdsm casts displaced draws itself */
    m->fixed = !screen && stin__path_of(ctx) != stin__glsl_path();
    m->copied = m->fixed && !has(ctx, STIN_CAP_BIT(STIN_CAP_FBO));
    m->ramp = m->copied && !has(ctx, STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE) |
                                         STIN_CAP_BIT(STIN_CAP_SHADOW));
    built = m->fixed   ? 1
            : screen ? ctx->sel.tier == STIN_TIER_GL4 && build_test(ctx, MASK, &m->mask, msg, sizeof msg)
                   : build_test(ctx, MARK, &m->mark, msg, sizeof msg) &&
                         (!stin__displace_tessellated(ctx) ||
                          build_test(ctx, MARK_TESS, &m->mark_tess, msg, sizeof msg));
    if (!built) {
        stin__formatf(why, sizeof why, "the casters' depth map test did not build (%s)", msg);
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_SHADER_COMPILE,
                  "%s: %s; CSG products cast no shadow", screen ? "vdsm" : "volume", why);
        if (!screen && stin__displace_built(ctx)) /* volumes would cast the flat mesh */
            stin__demote(ctx, STIN_FEATURE_DISPLACEMENT, STIN_TECH_DISPLACEMENT_OFF, why);
        return;
    }
    if (m->fixed)
        stin__cast_fixed_init(ctx);
    if (!m->copied)
        make_map(ctx);
}

void stin__cast_map_release(stin_context *ctx)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    if (m->mark.name)
        GL(ctx, DeleteProgram)(m->mark.name);
    if (m->mark_tess.name)
        GL(ctx, DeleteProgram)(m->mark_tess.name);
    if (m->mask.name)
        GL(ctx, DeleteProgram)(m->mask.name);
    if (m->texture)
        GL(ctx, DeleteTextures)(1, &m->texture);
    if (m->fbo)
        GL(ctx, DeleteFramebuffers)(1, &m->fbo);
    stin__cast_fixed_release(ctx);
    stin__memzero(m, sizeof *m);
}

/* A displaced caster: the map casts it. */
static int displaced(const stin_context *ctx, const stin__draw *d, const void *user)
{
    (void)user;
    return stin__displace_active(ctx, &d->material);
}

int stin__cast_map_casts(const stin_context *ctx, const stin__draw *d)
{
    return ctx->cast_map->mark.name && displaced(ctx, d, NULL);
}

/* Whether the frame has displaced casters. */
static int displaced_casters(const stin_context *ctx)
{
    uint32_t i;
    for (i = 0; i < ctx->draw_count; i++)
        if (ctx->draws[i].shadow_caster && displaced(ctx, &ctx->draws[i], NULL))
            return 1;
    return 0;
}

/* Says once per light what the map casts for it, or once that the
 * products cast nothing. */
static void say(stin_context *ctx, uint32_t li, int screen, int products, int displaced_draws)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    if (!m->texture && !m->copied && !m->cpu) {
        const char *why =
            screen ? "under vdsm without GL 4.3's shader storage buffers (the \"compute "
                     "shaders\" capability), which its per-pixel lists of crossings need, nor "
                     "a GLSL depth map to cast them"
            : stin__path_of(ctx) == stin__glsl_path()
                ? "into shadow volumes (a product's volume needs its resolved silhouette, not "
                  "its primitives'; a depth map to cast them needs framebuffer objects and depth "
                  "textures)"
                : "into shadow volumes (a product's volume needs its resolved silhouette, not "
                  "its primitives'; a depth map to cast them on GL1 needs multitexture and "
                  "either depth textures with shadow compare or texture_env_combine)";
        stin__casters_none(ctx, why);
        return;
    }
    if (li < 32u && !(m->said_light & (1u << li))) {
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                  "%s: %s cast through %s (%u%s) for light %u", screen ? "vdsm" : "volume",
                  products && displaced_draws ? "CSG products and displaced casters"
                  : products                  ? "CSG products"
                                              : "displaced casters",
                  m->cpu ? "read-backs" : m->ramp ? "map-combine" : m->fixed ? "map-depth" : "map-pcf",
                  (unsigned)(m->cpu ? m->cpu_size : m->copied ? m->copy_size : m->size),
                  m->cpu      ? ", the light's depth images tested on the CPU per pixel"
                  : m->copied ? ", drawn before the frame's clear"
                              : "",
                  (unsigned)li);
        m->said_light |= 1u << li;
    }
}

/* The casters from the light (view, proj) into cell `cell`; 1 if any drew. */
static int draw_cell(stin_context *ctx, const stin__path *path, const stin_light_desc *l,
                     int cell, const float view[16], const float proj[16])
{
    struct stin__cast_map_state *m = ctx->cast_map;
    stin__pass_state ps = stin__pass_defaults;
    float factor = 0.0f, units = 0.0f, window[16];
    int s = (int)m->size, drew;
    const int rect[4] = {(cell % (int)STIN__ATLAS_COLUMNS) * s,
                         (cell / (int)STIN__ATLAS_COLUMNS) * s, s, s};
    GL(ctx, Viewport)(rect[0], rect[1], rect[2], rect[3]);
    ps.depth_test = 1;
    ps.color_write = 0;
    ps.polygon_offset = (unsigned char)stin__map_offset(ctx, l, &factor, &units);
    ps.offset_factor = factor;
    ps.offset_units = units;
    stin__pass_apply(ctx, &ps);
    stin__light_window_matrix(window, view, proj);
    stin__memcopy(m->matrix[cell], window, sizeof window);
    stin__light_into_cell(m->matrix[cell], cell);
    drew = stin__casters_cast(ctx, path, view, proj, rect, m->fbo, 0, factor, units);
    if (drew)
        stin__pass_apply(ctx, &ps); /* the products' resolve left its own state */
    if (m->fixed)
        stin__cast_fixed_cell(ctx, cell, window, m->matrix[cell], drew);
    return (m->displaced && stin__glsl_depth_kept(ctx, view, proj, displaced, NULL) > 0) || drew;
}

int stin__cast_map_draw(stin_context *ctx, const stin__path *path, uint32_t li, GLuint back,
                        int screen)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    const stin_light_desc *l = &ctx->lights[li];
    stin__pass_state saved = *stin__pass_current(ctx);
    float view[16], proj[16], n, f;
    int face, products = stin__casters_wanted(ctx), displaced_draws;
    m->drawn = 0;
    m->current = li;
    if (m->cpu && !screen) {
        m->drawn = products && stin__cast_readback_draw(ctx, li);
        if (products)
            say(ctx, li, screen, 1, 0);
        return m->drawn;
    }
    if (!(screen ? m->mask.name : m->mark.name || m->fixed)) {
        if (products)
            say(ctx, li, screen, 1, 0);
        return 0;
    }
    if (m->fixed && l->type == STIN_LIGHT_POINT && !m->face_units) {
        /* each face marks its own pyramid: a unit each for its square and side */
        stin__casters_none(ctx, "from point lights under shadow volumes on the GL1 tier "
                                "without two texture units beside the map test's");
        return 0;
    }
    if (m->copied) { /* drawn in the light pre-pass */
        m->drawn = li < STIN__MAX_LIGHTS && m->lights[li].drawn;
        if (products)
            say(ctx, li, screen, 1, 0);
        return m->drawn;
    }
    m->displaced = !screen && !m->fixed; /* vdsm casts displaced draws itself; GL1 has none */
    displaced_draws = m->displaced && displaced_casters(ctx);
    if (!products && !displaced_draws)
        return 0;
    if (l->type != STIN_LIGHT_POINT && !stin__light_camera(ctx, l, view, proj, &n, &f, m->size))
        return 0;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, m->fbo);
    stin__pass_apply(ctx, &stin__pass_defaults); /* depth writes on for the clear */
    stin__clear_depth(ctx, 1.0);
    GL(ctx, Clear)(GL_DEPTH_BUFFER_BIT);
    if (m->fixed)
        m->lights[li].drawn = 0;
    if (l->type == STIN_LIGHT_POINT) {
        m->faces = STIN__CUBE_FACES;
        stin__memcopy(m->light, l->position, sizeof m->light);
        for (face = 0; face < STIN__CUBE_FACES; face++) {
            stin__light_cube_face(ctx, l->position, face, view, proj);
            m->drawn |= draw_cell(ctx, path, l, face, view, proj);
        }
    } else {
        m->faces = 1;
        m->drawn = draw_cell(ctx, path, l, 0, view, proj);
    }
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, back);
    GL(ctx, Viewport)(ctx->frame.viewport[0], ctx->frame.viewport[1], ctx->frame.viewport[2],
                      ctx->frame.viewport[3]);
    if (m->fixed) { /* the resolve from the light left its projection */
        GL(ctx, MatrixMode)(GL_PROJECTION);
        GL(ctx, LoadMatrixf)(ctx->projection);
        GL(ctx, MatrixMode)(GL_MODELVIEW);
    }
    stin__pass_apply(ctx, &saved);
    ctx->stats.passes++;
    m->kernel = l->pcf_kernel;
    say(ctx, li, screen, products, displaced_draws);
    return m->drawn;
}

/* One surface through the marking program p, or the fixed-function path
 * (p NULL). */
static void submit(stin_context *ctx, const mark_program *p, const stin__draw *d)
{
    if (p)
        stin__glsl_submit_geometry(ctx, p->u_model, &p->displace, d);
    else
        stin__fixed_path()->geometry(ctx, d);
}

void stin__cast_map_receivers(stin_context *ctx, const mark_program *p)
{
    const stin__draw *faces;
    uint32_t i, count;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        if (stin__camera_set(ctx, d) & STIN__OPAQUE)
            submit(ctx, p, d);
    }
    if (stin__in_peeled_layer(ctx))
        return; /* a layer's surfaces are its blended draws alone */
    faces = stin__resolved_faces(ctx, &count);
    for (i = 0; i < count; i++) {
        stin__pass_state saved;
        if (!stin__resolved_face_begin(ctx, &faces[i], &saved))
            continue;
        submit(ctx, p, &faces[i]);
        stin__resolved_face_end(ctx, &saved);
    }
}

/* Program p's map test uniforms for the light the map holds, the map on
 * unit 0. */
static void test_uniforms(stin_context *ctx, const mark_program *p)
{
    const struct stin__cast_map_state *m = ctx->cast_map;
    float params[4] = {0, 0, 0, 0};
    GL(ctx, UniformMatrix4fv)(p->u_matrix, m->faces, GL_FALSE, m->matrix[0]);
    GL(ctx, Uniform3fv)(p->u_light, 1, m->light);
    GL(ctx, Uniform1i)(p->u_faces, m->faces);
    params[0] = 1.0f / (float)(STIN__ATLAS_COLUMNS * m->size);
    params[1] = (float)(m->kernel / 2u);
    params[3] = 1.0f / (float)(STIN__ATLAS_ROWS * m->size);
    GL(ctx, Uniform4fv)(p->u_params, 1, params);
    GL(ctx, Uniform1i)(p->u_map, 0);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, m->texture);
}

/* The pass state of the marking pass: the frame's surfaces depth EQUAL,
 * the stencil set where a fragment passes. */
static stin__pass_state mark_state(const stin_context *ctx)
{
    stin__pass_state ps = *stin__pass_current(ctx);
    ps.depth_test = 1;
    ps.depth_func = GL_EQUAL;
    ps.depth_write = 0;
    ps.color_write = 0;
    ps.blend = 0;
    ps.cull = 0;
    ps.depth_clamp = 0;
    ps.polygon_offset = 0;
    ps.front_face = GL_CCW;
    ps.stencil_test = 1;
    ps.two_sided = 0;
    /* any non-zero count reads as shadowed; the top bit never wraps a count to 0 */
    ps.front.func = GL_ALWAYS;
    ps.front.ref = 0x80;
    ps.front.mask = 0xffffffffu;
    ps.front.fail = ps.front.zfail = GL_KEEP;
    ps.front.zpass = GL_REPLACE;
    return ps;
}

void stin__cast_map_mark(stin_context *ctx)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    const mark_program *p = stin__glsl_tessellated(ctx) ? &m->mark_tess : &m->mark;
    stin__pass_state saved = *stin__pass_current(ctx), ps;
    if (!m->drawn)
        return;
    ps = mark_state(ctx);
    if (m->cpu) { /* written by glDrawPixels: no depth test */
        ps.depth_test = 0;
        stin__pass_apply(ctx, &ps);
        stin__cast_readback_mark(ctx);
        stin__pass_apply(ctx, &saved);
        ctx->stats.passes++;
        return;
    }
    stin__pass_apply(ctx, &ps);
    if (m->fixed) {
        stin__cast_fixed_mark(ctx);
        stin__pass_apply(ctx, &saved);
        ctx->stats.passes++;
        return;
    }
    GL(ctx, UseProgram)(p->name);
    stin__lit_program_forget(ctx);
    GL(ctx, UniformMatrix4fv)(p->u_view_proj, 1, GL_FALSE, ctx->view_proj);
    test_uniforms(ctx, p);
    /* the height map's sampler off the map's unit even where no receiver
     * is displaced: WebGL refuses a draw whose sampler2D and
     * sampler2DShadow share a unit */
    if (p->displace.map >= 0)
        GL(ctx, Uniform1i)(p->displace.map, ctx->sel.displace_unit);
    ctx->bound_mesh = 0xffffffffu;
    stin__cast_map_receivers(ctx, p);
    ctx->bound_mesh = 0xffffffffu;
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    stin__pass_apply(ctx, &saved);
    ctx->stats.passes++;
}

void stin__cast_map_mask(stin_context *ctx, int channel, GLuint positions)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    stin__pass_state saved = *stin__pass_current(ctx), ps = stin__pass_defaults;
    if (!m->drawn)
        return;
    ps.depth_write = 0;
    ps.color_only = (unsigned char)(channel + 1);
    stin__pass_apply(ctx, &ps);
    GL(ctx, UseProgram)(m->mask.name);
    stin__lit_program_forget(ctx);
    test_uniforms(ctx, &m->mask);
    stin__bind_unit(ctx, 1, GL_TEXTURE_2D, positions);
    GL(ctx, Uniform1i)(m->mask.u_position, 1);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    stin__screen_quad(ctx);
    stin__pass_apply(ctx, &saved);
    ctx->stats.passes++;
}
