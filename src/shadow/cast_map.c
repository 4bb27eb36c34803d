/* SPDX-License-Identifier: MIT */
/* The casters stencil volumes cannot cast (the CSG products, whose volume
 * would need their resolved silhouette, not their primitives'), cast for
 * them through a map of their own on the GLSL tiers: per light, just
 * before its volumes are counted, the products go into one depth map from
 * the light (csg/cast.c's resolve, through render/casters.h), and after the
 * count a pass over the frame's surfaces, depth EQUAL, sets the stencil
 * non-zero wherever that map shadows them (map-pcf's test: its kernel and
 * receiver-plane bias, lit where half the kernel is). The lit pass, or the
 * screen mask's write, then lights only where both the volumes and the map
 * say lit. One map serves every light in turn, drawn mid-frame as map-pcf
 * draws a point light's faces. Frames without such casters draw nothing
 * of it. */
#include "internal.h"
#include "render/casters.h"
#include "render/displace_chunk.h"
#include "render/resolved.h"
#include "render/path_features.h"

/* The map is an atlas (shadow.h's cells, cast_mark.frag's lookup): a spot
 * or directional light's map in cell 0, a point light's face f in cell f. */
struct stin__cast_map_state {
    GLuint texture, fbo, program;
    GLint u_model, u_view_proj, u_matrix, u_params, u_light, u_faces, u_map;
    stin__displace_locs displace;
    uint32_t size;         /* a cell's texels a side */
    int ready;             /* the map and its pass were made at set-up */
    int drawn;             /* the map holds the casters of the light being counted */
    int faces;             /* its cells: 1, or a point light's 6 */
    float matrix[STIN__CUBE_FACES][16]; /* world -> [0,1] atlas space, per cell */
    float light[3];        /* a point light's position */
    uint32_t kernel;       /* its light's pcf_kernel */
    uint32_t said_light;   /* bit li: what casts light li's products was logged */
};

size_t stin__cast_map_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(struct stin__cast_map_state);
}

static const stin__uniform_name mark_uniforms[] = {
    STIN__UNIFORM(struct stin__cast_map_state, u_model, "u_model"),
    STIN__UNIFORM(struct stin__cast_map_state, u_view_proj, "u_view_proj"),
    STIN__UNIFORM(struct stin__cast_map_state, u_matrix, "u_cast_matrix"),
    STIN__UNIFORM(struct stin__cast_map_state, u_params, "u_cast_params"),
    STIN__UNIFORM(struct stin__cast_map_state, u_light, "u_cast_light"),
    STIN__UNIFORM(struct stin__cast_map_state, u_faces, "u_cast_faces"),
    STIN__UNIFORM(struct stin__cast_map_state, u_map, "u_cast_map"),
};

static int glsl_maps(const stin_context *ctx)
{
    const uint64_t need = STIN_CAP_BIT(STIN_CAP_FBO) | STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE) |
                          STIN_CAP_BIT(STIN_CAP_SHADOW);
    return stin__path_of(ctx) == stin__glsl_path() && (ctx->caps.present & need) == need;
}

void stin__cast_map_init(stin_context *ctx)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    const char *dir = ctx->sel.tier == STIN_TIER_GL4 ? "gl4/" : "gl2/";
    char vert[40], frag[40], msg[160];
    GLint caller_fbo[2];
    uint32_t size = ctx->desc.shadows.map_size;
    if (!glsl_maps(ctx))
        return;
    while (ctx->caps.max_texture_size > 0 && size > 1u &&
           STIN__ATLAS_COLUMNS * size > (uint32_t)ctx->caps.max_texture_size)
        size /= 2u; /* three cells across must fit */
    stin__formatf(vert, sizeof vert, "%scast_mark.vert", dir);
    stin__formatf(frag, sizeof frag, "%scast_mark.frag", dir);
    m->program = stin__program_build(ctx, vert, frag, NULL, 0, msg, sizeof msg);
    if (!m->program) {
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_SHADER_COMPILE,
                  "volume: the products' map test did not build (%s); CSG products cast no "
                  "shadow",
                  msg);
        return;
    }
    STIN__LOCATE(ctx, m->program, m, mark_uniforms);
    stin__displace_locate(ctx, m->program, 1, &m->displace);
    m->size = size;
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, GenTextures)(1, &m->texture);
    stin__rt_shadow_map(ctx, m->texture, (int)(STIN__ATLAS_COLUMNS * size), (int)(STIN__ATLAS_ROWS * size));
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    stin__framebuffer_save(ctx, caller_fbo); /* the caller's binding survives */
    GL(ctx, GenFramebuffers)(1, &m->fbo);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, m->fbo);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m->texture,
                                  0);
    GL(ctx, DrawBuffer)(GL_NONE); /* depth only */
    GL(ctx, ReadBuffer)(GL_NONE);
    stin__framebuffer_restore(ctx, caller_fbo);
    stin__gl_check_errors(ctx, "products' map set-up");
    m->ready = 1;
}

void stin__cast_map_release(stin_context *ctx)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    if (m->program)
        GL(ctx, DeleteProgram)(m->program);
    if (m->texture)
        GL(ctx, DeleteTextures)(1, &m->texture);
    if (m->fbo)
        GL(ctx, DeleteFramebuffers)(1, &m->fbo);
    stin__memzero(m, sizeof *m);
}

/* Says once per light what casts its products, or once that nothing does. */
static void say(stin_context *ctx, uint32_t li, int cast)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    if (!cast) {
        stin__casters_none(ctx, "into shadow volumes (a product's volume needs its resolved "
                                "silhouette, not its primitives'; this context has no GLSL "
                                "depth map to cast them)");
        return;
    }
    if (li < 32u && !(m->said_light & (1u << li))) {
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                  "volume: CSG products cast through map-pcf (%u) for light %u",
                  (unsigned)m->size, (unsigned)li);
        m->said_light |= 1u << li;
    }
}

/* The casters from the light (view, proj) into cell `cell`; 1 if any drew. */
static int draw_cell(stin_context *ctx, const stin__path *path, const stin_light_desc *l,
                     int cell, const float view[16], const float proj[16])
{
    struct stin__cast_map_state *m = ctx->cast_map;
    stin__pass_state ps = stin__pass_defaults;
    float factor = 0.0f, units = 0.0f;
    int s = (int)m->size;
    const int rect[4] = {(cell % (int)STIN__ATLAS_COLUMNS) * s, (cell / (int)STIN__ATLAS_COLUMNS) * s, s, s};
    GL(ctx, Viewport)(rect[0], rect[1], rect[2], rect[3]);
    ps.depth_test = 1;
    ps.color_write = 0;
    ps.polygon_offset = (unsigned char)stin__map_offset(l, &factor, &units);
    ps.offset_factor = factor;
    ps.offset_units = units;
    stin__pass_apply(ctx, &ps);
    stin__light_window_matrix(m->matrix[cell], view, proj);
    stin__light_into_cell(m->matrix[cell], cell);
    return stin__casters_cast(ctx, path, view, proj, rect, m->fbo, 0, factor, units);
}

int stin__cast_map_draw(stin_context *ctx, const stin__path *path, uint32_t li, GLuint back)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    const stin_light_desc *l = &ctx->lights[li];
    stin__pass_state saved = *stin__pass_current(ctx);
    float view[16], proj[16], n, f;
    int face;
    m->drawn = 0;
    if (!stin__casters_wanted(ctx))
        return 0;
    if (!m->ready) {
        say(ctx, li, 0);
        return 0;
    }
    if (l->type != STIN_LIGHT_POINT && !stin__light_camera(ctx, l, view, proj, &n, &f, m->size))
        return 0;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, m->fbo);
    stin__pass_apply(ctx, &stin__pass_defaults); /* depth writes on for the clear */
    GL(ctx, ClearDepth)(1.0);
    GL(ctx, Clear)(GL_DEPTH_BUFFER_BIT);
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
    stin__pass_apply(ctx, &saved);
    ctx->stats.passes++;
    m->kernel = l->pcf_kernel;
    say(ctx, li, 1);
    return m->drawn;
}

/* The frame's surfaces (its opaque draws and the products' faces) through
 * the marking program, depth EQUAL. */
static void draw_receivers(stin_context *ctx)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    const stin__draw *faces;
    uint32_t i, count;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        if (stin__camera_set(ctx, d) & STIN__OPAQUE)
            stin__glsl_submit_geometry(ctx, m->u_model, &m->displace, d);
    }
    faces = stin__resolved_faces(ctx, &count);
    for (i = 0; i < count; i++) {
        stin__pass_state saved;
        if (!stin__resolved_face_begin(ctx, &faces[i], &saved))
            continue;
        stin__glsl_submit_geometry(ctx, m->u_model, &m->displace, &faces[i]);
        stin__resolved_face_end(ctx, &saved);
    }
}

void stin__cast_map_mark(stin_context *ctx)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    stin__pass_state saved = *stin__pass_current(ctx), ps = saved;
    float params[4] = {0, 0, 0, 0};
    if (!m->drawn)
        return;
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
    stin__pass_apply(ctx, &ps);
    GL(ctx, UseProgram)(m->program);
    stin__lit_program_forget(ctx);
    GL(ctx, UniformMatrix4fv)(m->u_view_proj, 1, GL_FALSE, ctx->view_proj);
    GL(ctx, UniformMatrix4fv)(m->u_matrix, m->faces, GL_FALSE, m->matrix[0]);
    GL(ctx, Uniform3fv)(m->u_light, 1, m->light);
    GL(ctx, Uniform1i)(m->u_faces, m->faces);
    params[0] = 1.0f / (float)(STIN__ATLAS_COLUMNS * m->size);
    params[1] = (float)(m->kernel / 2u);
    params[3] = 1.0f / (float)(STIN__ATLAS_ROWS * m->size);
    GL(ctx, Uniform4fv)(m->u_params, 1, params);
    GL(ctx, Uniform1i)(m->u_map, 0);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, m->texture);
    ctx->bound_mesh = 0xffffffffu;
    draw_receivers(ctx);
    ctx->bound_mesh = 0xffffffffu;
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    stin__pass_apply(ctx, &saved);
    ctx->stats.passes++;
}
