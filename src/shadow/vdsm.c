/* SPDX-License-Identifier: MIT */
/* VDSM, view-dependent shadow maps (seed 000; shaders/gl4/vdsm*): exact hard
 * shadows at camera resolution. A frame stage draws the visible surface's
 * positions (shadow/vdsm_buffer.c). Per light, into a channel of the screen
 * mask (render/screen_mask.c): a full-screen pass writes 1 where the visible side
 * faces the light, then a geometry shader turns every triangle into the
 * faces of its shadow volume the eye sees, grown by half a pixel, and the
 * fragment stage writes 0 wherever the segment from the pixel's surface
 * point to the light hits that triangle. Steps: EP drops triangles facing
 * the light on closed meshes (the ones behind them cast the same shadow);
 * SM and DC read a light-view pyramid (shadow/vdsm_pyramid.c) to drop
 * triangles already in shadow or with nothing behind them, and to end the
 * extrusion at the deepest receiver; the growth is conservative
 * rasterisation. The steps decide each triangle in a culling pass first
 * where they can (shadow/vdsm_cull.c), so the polygons' large geometry
 * shader runs on the kept ones alone. The shadow polygons need triangles
 * alone: no adjacency, so open and non-manifold meshes cast exactly (SM's
 * occluders use it where the mesh has it). */
#include "shadow/vdsm_private.h"

size_t stin__vdsm_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(struct stin__vdsm_state);
}

GLuint stin__vdsm_program(stin_context *ctx, const char *vert, const char *geom,
                          const char *frag, const char *out1, int tessellate, char *msg,
                          size_t size)
{
    stin__program_source src;
    stin__memzero(&src, sizeof src);
    src.tessellate = tessellate;
    src.vert = vert;
    src.geom = geom;
    src.frag = frag;
    if (out1) {
        src.frag_outputs[0] = "o_position";
        src.frag_outputs[1] = out1;
    }
    return stin__program_build_source(ctx, &src, msg, size);
}

GLuint stin__vdsm_polygon_program(stin_context *ctx, const char *frag, int tessellate, char *msg,
                                  size_t size)
{
    static const char *const segment[] = {"gl4/vdsm_segment.glsl", NULL};
    static const char *const steps[] = {"gl4/vdsm_side.glsl", "gl4/vdsm_cull.glsl",
                                        "gl4/vdsm_volume.glsl", NULL};
    stin__program_source src;
    stin__memzero(&src, sizeof src);
    src.tessellate = tessellate;
    src.vert = "gl4/vdsm.vert";
    src.geom = "gl4/vdsm.geom";
    src.geom_chunks = steps;
    src.frag = frag;
    src.frag_chunks = segment;
    return stin__program_build_source(ctx, &src, msg, size);
}

/* The position buffer's program (vdsm_position.*): three outputs, position,
 * facet normal and shading normal. */
static GLuint position_program(stin_context *ctx, int tessellate, char *msg, size_t size)
{
    stin__program_source src;
    stin__memzero(&src, sizeof src);
    src.tessellate = tessellate;
    src.vert = "gl4/vdsm_position.vert";
    src.geom = "gl4/vdsm_position.geom";
    src.frag = "gl4/vdsm_position.frag";
    src.frag_outputs[0] = "o_position";
    src.frag_outputs[1] = "o_normal";
    src.frag_outputs[2] = "o_shading";
    return stin__program_build_source(ctx, &src, msg, size);
}

void stin__vdsm_delete_programs(stin_context *ctx, GLuint *a, GLuint *b, GLuint *c)
{
    GLuint *progs[3];
    int i;
    progs[0] = a;
    progs[1] = b;
    progs[2] = c;
    for (i = 0; i < 3; i++)
        if (*progs[i]) {
            GL(ctx, DeleteProgram)(*progs[i]);
            *progs[i] = 0;
        }
}

static void release(stin_context *ctx)
{
    struct stin__vdsm_state *v = ctx->vdsm;
    GLuint none = 0;
    stin__vdsm_delete_programs(ctx, &v->position_prog, &v->facing_prog, &v->polygon_prog);
    stin__vdsm_delete_programs(ctx, &v->position_tess, &v->polygon_tess, &none);
    v->tess_active = 0;
    if (v->query)
        GL(ctx, DeleteQueries)(1, &v->query);
    v->query = 0;
    stin__vdsm_pyramid_release(ctx);
    stin__vdsm_cull_release(ctx);
    stin__vdsm_csg_release(ctx);
    stin__vdsm_soft_release(ctx);
    stin__cast_map_release(ctx);
    stin__vdsm_buffer_release(ctx);
    stin__mesh_adjacency_use(ctx, NULL);
}

static const stin__uniform_name polygon_uniforms[] = {
    STIN__UNIFORM(stin__vdsm_polygon_locs, model, "u_model"),
    STIN__UNIFORM(stin__vdsm_polygon_locs, view_proj, "u_view_proj"),
    STIN__UNIFORM(stin__vdsm_polygon_locs, light, "u_light"),
    STIN__UNIFORM(stin__vdsm_polygon_locs, camera, "u_camera"),
    STIN__UNIFORM(stin__vdsm_polygon_locs, viewport, "u_viewport"),
    STIN__UNIFORM(stin__vdsm_polygon_locs, grow, "u_grow"),
    STIN__UNIFORM(stin__vdsm_polygon_locs, depth_test, "u_depth_test"),
    STIN__UNIFORM(stin__vdsm_polygon_locs, cull_lit, "u_cull_lit"),
    STIN__UNIFORM(stin__vdsm_polygon_locs, caps, "u_caps"),
    STIN__UNIFORM(stin__vdsm_polygon_locs, position, "u_position"),
    STIN__UNIFORM(stin__vdsm_polygon_locs, normal, "u_normal"),
};

void stin__vdsm_polygon_locate(stin_context *ctx, GLuint prog, stin__vdsm_polygon_locs *l)
{
    STIN__LOCATE(ctx, prog, l, polygon_uniforms);
    /* shadow polygons cast from anywhere, not only the camera's view */
    stin__displace_locate(ctx, prog, 0, &l->displace);
    stin__vdsm_pyramid_locate(ctx, prog, &l->pyramid);
}

static const stin__uniform_name position_uniforms[] = {
    STIN__UNIFORM(struct stin__vdsm_state, pos_model, "u_model"),
    STIN__UNIFORM(struct stin__vdsm_state, pos_normal_matrix, "u_normal_matrix"),
    STIN__UNIFORM(struct stin__vdsm_state, pos_view_proj, "u_view_proj"),
    STIN__UNIFORM(struct stin__vdsm_state, pos_camera, "u_camera"),
    STIN__UNIFORM(struct stin__vdsm_state, pos_csg, "u_csg"),
    STIN__UNIFORM(struct stin__vdsm_state, pos_csg_depth, "u_csg_depth"),
    STIN__UNIFORM(struct stin__vdsm_state, pos_csg_grow, "u_csg_grow"),
};

static const stin__uniform_name facing_uniforms[] = {
    STIN__UNIFORM(struct stin__vdsm_state, face_position, "u_position"),
    STIN__UNIFORM(struct stin__vdsm_state, face_normal, "u_normal"),
    STIN__UNIFORM(struct stin__vdsm_state, face_shading, "u_shading"),
    STIN__UNIFORM(struct stin__vdsm_state, face_light, "u_light"),
};

static void locate(stin_context *ctx)
{
    struct stin__vdsm_state *v = ctx->vdsm;
    STIN__LOCATE(ctx, v->position_prog, v, position_uniforms);
    STIN__LOCATE(ctx, v->facing_prog, v, facing_uniforms);
    /* the position buffer is the camera's view */
    stin__displace_locate(ctx, v->position_prog, 1, &v->pos_displace);
    stin__vdsm_polygon_locate(ctx, v->polygon_prog, &v->poly);
}

/* The technique below vdsm that runs here: the next one down the shadows
 * chain whose needs, lighting, conflicts (displacement's) and units the
 * technique table says fit beside the other choices. */
static stin_technique fallback(const stin_context *ctx)
{
    return stin__fallback(&ctx->caps, &ctx->sel, STIN_FEATURE_SHADOWS);
}

/* "displace-tess": the mesh-drawing programs again, tessellated; if they
 * do not build, displacement moves to "displace". */
static void build_tessellated(stin_context *ctx)
{
    struct stin__vdsm_state *v = ctx->vdsm;
    char msg[160], why[220];
    GLuint none = 0;
    msg[0] = '\0';
    v->position_tess = position_program(ctx, 1, msg, sizeof msg);
    if (v->position_tess)
        v->polygon_tess = stin__vdsm_polygon_program(ctx, "gl4/vdsm.frag", 1, msg, sizeof msg);
    if (v->polygon_tess)
        return;
    stin__vdsm_delete_programs(ctx, &v->position_tess, &v->polygon_tess, &none);
    stin__formatf(why, sizeof why, "vdsm's tessellated programs failed to build (%s)", msg);
    stin__displace_untessellate(ctx, why);
}

void stin__vdsm_tessellate(stin_context *ctx, int on)
{
    struct stin__vdsm_state *v = ctx->vdsm;
    GLuint t;
    if (!on == !v->tess_active || !v->polygon_tess)
        return;
    t = v->position_prog;
    v->position_prog = v->position_tess;
    v->position_tess = t;
    t = v->polygon_prog;
    v->polygon_prog = v->polygon_tess;
    v->polygon_tess = t;
    v->tess_active = on;
    locate(ctx);
}

static stin_result vdsm_init(stin_context *ctx)
{
    struct stin__vdsm_state *v = ctx->vdsm;
    char msg[160], why[200];
    stin__memzero(v, sizeof *v);
    if (!stin__mask_usable(ctx)) {
        stin__demote(ctx, STIN_FEATURE_SHADOWS, fallback(ctx),
                     "vdsm writes into the screen mask, which needs a texture unit beyond the "
                     "surface's");
        return STIN_OK;
    }
    msg[0] = '\0';
    v->position_prog = position_program(ctx, 0, msg, sizeof msg);
    if (v->position_prog)
        v->facing_prog = stin__vdsm_program(ctx, "gl4/screen.vert", NULL,
                                            "gl4/vdsm_facing.frag", NULL, 0, msg, sizeof msg);
    if (v->facing_prog)
        v->polygon_prog = stin__vdsm_polygon_program(ctx, "gl4/vdsm.frag", 0, msg, sizeof msg);
    if (!v->polygon_prog) {
        release(ctx);
        stin__formatf(why, sizeof why, "its shaders failed to build (%s)", msg);
        stin__demote(ctx, STIN_FEATURE_SHADOWS, fallback(ctx), why);
        return STIN_OK;
    }
    locate(ctx);
    if (stin__displace_tessellated(ctx))
        build_tessellated(ctx);
    stin__vdsm_pyramid_init(ctx);
    stin__vdsm_cull_init(ctx);
    stin__vdsm_csg_init(ctx);
    stin__cast_map_init(ctx, 1);
    if (ctx->desc.debug_flags & STIN_DEBUG_VDSM_COUNT)
        GL(ctx, GenQueries)(1, &v->query);
    /* step SM's occluders: the light pass reads each edge's neighbour */
    stin__mesh_adjacency_use(ctx, "it casts, but does not count as an occluder for step SM");
    return STIN_OK;
}

static void vdsm_prepass(stin_context *ctx) { stin__vdsm_buffer_draw(ctx); }

/* The light as a homogeneous world point: position (w 1) or the direction
 * toward it (w 0); an area light's centre. */
static void light_point(const stin_light_desc *l, float out[4])
{
    int k;
    for (k = 0; k < 3; k++)
        out[k] = l->type == STIN_LIGHT_DIRECTIONAL ? -l->direction[k] : l->position[k];
    out[3] = l->type == STIN_LIGHT_DIRECTIONAL ? 0.0f : 1.0f;
}

/* EP may drop a draw's light-facing triangles where the step is on, the
 * mesh is closed (an open one's back may be missing) and its material is
 * not two-sided (the eye may see a closed mesh from inside). */
int stin__vdsm_cull_lit(const stin_context *ctx, const stin__draw *d)
{
    return !(ctx->desc.debug_flags & STIN_DEBUG_VDSM_NO_EP) && !d->material.two_sided &&
           ctx->meshes[d->mesh_slot].info.closed_manifold;
}

/* Whether the shadow polygons test their depth against the visible
 * surface's: the position buffer's own depth (its draws' nearest), so a
 * face behind it is not shaded. Where the buffer's depth is not the
 * surface tested (a peeled layer's points, products' faces) it lies behind
 * it: the test then passes more, never less. */
int stin__vdsm_depth_tested(const stin_context *ctx)
{
    return !(ctx->desc.debug_flags & STIN_DEBUG_VDSM_NO_DEPTH_TEST) &&
           (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_DEPTH_CLAMP));
}

/* The mask's framebuffer with the position buffer's depth in place of its
 * own depth-stencil (on), or back (off). */
static void surface_depth(stin_context *ctx, int on)
{
    GLuint depth = on ? ctx->vdsm->depth : stin__mask_target_of(ctx).depth_stencil;
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                                  on ? 0u : depth, 0);
}

void stin__vdsm_polygon_uniforms(stin_context *ctx, const stin__vdsm_polygon_locs *l,
                                 const float light[4])
{
    const int *vp = ctx->frame.viewport;
    float viewport[4];
    viewport[0] = (float)vp[0];
    viewport[1] = (float)vp[1];
    viewport[2] = (float)vp[2];
    viewport[3] = (float)vp[3];
    GL(ctx, UniformMatrix4fv)(l->view_proj, 1, GL_FALSE, ctx->view_proj);
    GL(ctx, Uniform4fv)(l->light, 1, light);
    GL(ctx, Uniform4fv)(l->camera, 1, ctx->vdsm->camera);
    GL(ctx, Uniform4fv)(l->viewport, 1, viewport);
    GL(ctx, Uniform1f)(l->grow, ctx->desc.debug_flags & STIN_DEBUG_VDSM_NO_GROW ? 0.0f : 0.5f);
    GL(ctx, Uniform1i)(l->depth_test, stin__vdsm_depth_tested(ctx));
    GL(ctx, Uniform1i)(l->position, 0);
    GL(ctx, Uniform1i)(l->normal, 1);
    stin__vdsm_pyramid_uniforms(ctx, &l->pyramid);
}

void stin__vdsm_draw_casters(stin_context *ctx, const stin__vdsm_polygon_locs *l)
{
    uint32_t i;
    int culled = -1;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        int c = stin__vdsm_cull_lit(ctx, d);
        if (!d->shadow_caster)
            continue; /* a transparent caster: its map or the threshold decides */
        if (c != culled)
            GL(ctx, Uniform1i)(l->cull_lit, c);
        culled = c;
        /* a blended caster is not in the depth buffer: what lies behind it shows */
        GL(ctx, Uniform1i)(l->caps, d->material.color[3] < 1.0f);
        stin__glsl_submit_geometry(ctx, l->model, &l->displace, d);
    }
}

/* The light's shadow polygons: culled first into a buffer and drawn from
 * it, or culled and drawn in one geometry shader. */
static void polygons(stin_context *ctx, const float light[4])
{
    struct stin__vdsm_state *v = ctx->vdsm;
    const stin__pass_state before = *stin__pass_current(ctx);
    stin__pass_state ps = before;
    int tested = stin__vdsm_depth_tested(ctx), fed = stin__vdsm_cull_on(ctx), counted;
    if (fed && !stin__vdsm_cull_pass(ctx, light))
        return; /* no triangle casts */
    if (!fed) {
        GL(ctx, UseProgram)(v->polygon_prog);
        stin__vdsm_polygon_uniforms(ctx, &v->poly, light);
    }
    if (tested) {
        /* depth LESS, not written, unclipped by the near and far planes;
         * pulled toward the eye by a pixel's slope and 4 steps against the
         * rounding of both depths where the surface point lies just inside */
        ps.depth_test = ps.depth_clamp = ps.polygon_offset = 1;
        ps.depth_func = GL_LESS;
        ps.offset_factor = -1.0f;
        ps.offset_units = -4.0f;
        surface_depth(ctx, 1);
        stin__pass_apply(ctx, &ps);
    }
    counted = v->query && stin__query_begin(ctx, STIN__QUERY_PRIMITIVES, GL_PRIMITIVES_GENERATED,
                                            v->query);
    if (fed)
        stin__vdsm_cull_draw(ctx);
    else
        stin__vdsm_draw_casters(ctx, &v->poly);
    if (counted) {
        GLuint n = 0;
        GL(ctx, EndQuery)(GL_PRIMITIVES_GENERATED);
        GL(ctx, GetQueryObjectuiv)(v->query, GL_QUERY_RESULT, &n);
        ctx->stats.shadows.vdsm_primitives += n;
    }
    if (tested) {
        surface_depth(ctx, 0);
        stin__pass_apply(ctx, &before);
    }
}

/* Light li's visibility into mask channel `channel`. */
static int vdsm_mask(stin_context *ctx, const stin__path *path, uint32_t li, int channel)
{
    struct stin__vdsm_state *v = ctx->vdsm;
    const stin_light_desc *l = &ctx->lights[li];
    stin__pass_state ps = *stin__pass_current(ctx);
    float light[4];
    int faced, soft;
    if (!v->ready)
        return 0;
    soft = l->radius > 0.0f && l->type != STIN_LIGHT_DIRECTIONAL;
    if (soft && !stin__vdsm_soft_available(ctx)) {
        soft = 0;
        if (!v->said_area)
            stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                      "vdsm: area lights cast hard shadows from their centre in tessellated "
                      "frames, without their programs, or without glLogicOp and image atomics "
                      "(OpenGL ES below 3.2)");
        v->said_area = 1;
    }
    light_point(l, light);
    stin__mask_depth_from(ctx, v->depth); /* its mask's surfaces are the buffer's */
    faced = stin__vdsm_pyramid_draw(ctx, light, channel);
    ps.depth_test = ps.depth_write = ps.stencil_test = ps.blend = ps.cull = 0;
    ps.scissor = ps.depth_clamp = ps.polygon_offset = 0;
    ps.color_write = 1;
    ps.color_only = (unsigned char)(channel + 1);
    stin__pass_apply(ctx, &ps);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, v->position);
    stin__bind_unit(ctx, 1, GL_TEXTURE_2D, v->normal);
    stin__bind_unit(ctx, 2, GL_TEXTURE_2D, v->shading);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    stin__lit_program_forget(ctx);
    if (!faced) { /* else the pyramid's receivers wrote it */
        GL(ctx, UseProgram)(v->facing_prog);
        GL(ctx, Uniform1i)(v->face_position, 0);
        GL(ctx, Uniform1i)(v->face_normal, 1);
        GL(ctx, Uniform1i)(v->face_shading, 2);
        GL(ctx, Uniform4fv)(v->face_light, 1, light);
        stin__screen_quad(ctx);
        ctx->stats.passes++;
    }
    if (soft) {
        stin__vdsm_soft_draw(ctx, l, light, channel);
    } else {
        polygons(ctx, light);
        ctx->stats.passes++;
    }
    stin__vdsm_csg_cast(ctx, light, channel);
    /* the products it cannot walk: through the casters' map */
    if (!stin__vdsm_csg_walks_all(ctx) &&
        stin__cast_map_draw(ctx, path, li, stin__mask_target_of(ctx).fbo, 1))
        stin__cast_map_mask(ctx, channel, v->position);
    return 1;
}

/* Without the mask (its framebuffer failed) vdsm has nowhere to write:
 * the light is drawn unshadowed, and the log says so once. */
static void vdsm_light(stin_context *ctx, const stin__path *path, uint32_t li,
                       stin__shade_fn shade)
{
    if (!ctx->vdsm->said_failed)
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FALLBACK,
                  "vdsm: no screen mask or position buffer this frame: lights are drawn "
                  "without shadows");
    ctx->vdsm->said_failed = 1;
    shade(ctx, path, &ctx->lights[li], 1.0f);
}

const stin__shadow_technique stin__shadow_vdsm = {
    .glsl_chunk = "shadow_mask.glsl",
    .init = vdsm_init,
    .release = release,
    .light_prepass = vdsm_prepass,
    .light = vdsm_light,
    .uniforms = stin__mask_uniforms,
    .mask = vdsm_mask,
    /* the polygons test the position buffer's depth: the mask's is never read */
    .mask_depth = 0,
    .tessellate = stin__vdsm_tessellate,
    .after_csg = stin__vdsm_buffer_csg,
    .layers_begin = stin__vdsm_buffer_layers_begin,
    .layer = stin__vdsm_buffer_layer,
    .layers_end = stin__vdsm_buffer_layers_end,
};
