/* SPDX-License-Identifier: MIT */
/* VDSM steps SM and DC (seed 000, steps C and D): per light, a pyramid over
 * the light's view that the shadow polygons (shaders/gl4/vdsm.geom) read over
 * each triangle's footprint. Level 0 holds per texel
 *   x: a light depth no ray through the texel passes without first meeting
 *      a drawn triangle (BIG where that is not known), and
 *   y: the deepest receiver - the start of a shadow test, one per pixel of
 *      the position buffer - in the texel (-BIG where there is none);
 * each coarser level the maximum of its four children in both. SM drops a
 * triangle nearer nowhere than x (its shadow lies in theirs), DC one nearer
 * nowhere than y (nothing behind it is tested) and ends the extrusion at y.
 *
 * x is exact rather than sampled (the seed rasterised the nearest depth at
 * texel centres, so a ray between centres could miss the occluder; it also
 * let empty texels through the maximum): per draw, the light pass marks in
 * the stencil, with the draw's id, every texel an edge of its triangles'
 * outline touches (shaders/gl4/vdsm_light.geom, from the adjacency), then
 * (vdsm_light_tris.geom, from the plain triangles) writes, MIN (as a
 * MAX of negatives), each triangle at the unmarked texel centres it covers
 * with the draw's deepest point (or the triangle's own over the texel where
 * it covers the whole texel). Such a texel lies wholly inside the draw's
 * union, so the bound holds for every ray through it. Ids cycle through 255
 * values without clearing: an old mark with the same id only drops texels.
 * Receivers are the position buffer's points, so y is exact too: drawn as
 * points, or on GL 4.3 kept by atomics (shadow/vdsm_receivers.c). The map's
 * resolution changes what is culled, never the mask.
 *
 * The light's view looks at the centre of the frame's draws: from a point or
 * spot light a perspective one over the draws' box corners in front of it,
 * at most 166 degrees wide (the cone does not matter), along a directional
 * light an orthographic one over all of them. A point light needs no cube:
 * what lies outside the view or behind the light is looked up nowhere, and
 * those triangles cast as with SP and EP alone. Draws reaching behind the
 * light are not occluders in the pyramid. */
#include "shadow/vdsm_private.h"

#define BIG 1e30f
/* The light pass's marks reach this far beyond the half texel, and the
 * texel counted as covered by one triangle is grown by it: room for the
 * rasteriser's snapping and the passes' rounding. */
#define GROW_TEXELS 0.05f
/* Texels a side at most (desc.shadows.map_size beyond it: this): 2048 is
 * 96 MB of GL memory (and 16 MB for the receivers' words on GL 4.3). */
#define MAX_SIZE 2048u
/* Texels a side of the finest level drawn at least (size_to_viewport). */
#define MIN_DRAWN 256
/* Widest half angle of a perspective light view, as its tangent (83
 * degrees). */
#define MAX_TAN 8.0f
/* A perspective view's occluders lie clearly in front of the light: deeper
 * than this fraction of the deepest corner. */
#define FRONT 1e-3f

static const stin__uniform_name light_pass_uniforms[] = {
    STIN__UNIFORM(stin__vdsm_light_locs, model, "u_model"),
    STIN__UNIFORM(stin__vdsm_light_locs, vp, "u_light_vp"),
    STIN__UNIFORM(stin__vdsm_light_locs, depth, "u_depth_row"),
    STIN__UNIFORM(stin__vdsm_light_locs, light, "u_light"),
    STIN__UNIFORM(stin__vdsm_light_locs, cull_lit, "u_cull_lit"),
    STIN__UNIFORM(stin__vdsm_light_locs, size, "u_size"),
    STIN__UNIFORM(stin__vdsm_light_locs, grow, "u_grow"),
    STIN__UNIFORM(stin__vdsm_light_locs, bound, "u_bound"),
    STIN__UNIFORM(stin__vdsm_light_locs, persp, "u_perspective"),
};

static void locate_light(stin_context *ctx, GLuint prog, stin__vdsm_light_locs *l)
{
    STIN__LOCATE(ctx, prog, l, light_pass_uniforms);
}

static const stin__uniform_name receiver_uniforms[] = {
    STIN__UNIFORM(stin__vdsm_pyramid, r_position, "u_position"),
    STIN__UNIFORM(stin__vdsm_pyramid, r_normal, "u_normal"),
    STIN__UNIFORM(stin__vdsm_pyramid, r_shading, "u_shading"),
    STIN__UNIFORM(stin__vdsm_pyramid, r_light, "u_light"),
    STIN__UNIFORM(stin__vdsm_pyramid, r_vp, "u_light_vp"),
    STIN__UNIFORM(stin__vdsm_pyramid, r_depth, "u_depth_row"),
    STIN__UNIFORM(stin__vdsm_pyramid, r_rect, "u_rect"),
};

static const stin__uniform_name reduce_uniforms[] = {
    STIN__UNIFORM(stin__vdsm_pyramid, d_source, "u_source"),
    STIN__UNIFORM(stin__vdsm_pyramid, d_first, "u_first"),
};

static void locate(stin_context *ctx)
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    locate_light(ctx, p->light_prog, &p->marks);
    locate_light(ctx, p->tris_prog, &p->tris);
    stin__displace_locate(ctx, p->tris_prog, 0, &p->tris_displace);
    STIN__LOCATE(ctx, p->receiver_prog, p, receiver_uniforms);
    STIN__LOCATE(ctx, p->reduce_prog, p, reduce_uniforms);
}

static const stin__uniform_name pyramid_uniforms[] = {
    STIN__UNIFORM(stin__vdsm_pyramid_locs, sm, "u_sm"),
    STIN__UNIFORM(stin__vdsm_pyramid_locs, dc, "u_dc"),
    STIN__UNIFORM(stin__vdsm_pyramid_locs, vp, "u_light_vp"),
    STIN__UNIFORM(stin__vdsm_pyramid_locs, depth, "u_depth_row"),
    STIN__UNIFORM(stin__vdsm_pyramid_locs, pyramid, "u_pyramid"),
    STIN__UNIFORM(stin__vdsm_pyramid_locs, size, "u_pyramid_size"),
    STIN__UNIFORM(stin__vdsm_pyramid_locs, top, "u_pyramid_top"),
};

void stin__vdsm_pyramid_locate(stin_context *ctx, GLuint prog, stin__vdsm_pyramid_locs *l)
{
    STIN__LOCATE(ctx, prog, l, pyramid_uniforms);
}

static void float_texture(stin_context *ctx, GLuint tex, int levels, int size)
{
    int k;
    GL(ctx, BindTexture)(GL_TEXTURE_2D, tex);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                           levels > 1 ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
    for (k = 0; k < levels; k++) {
        int s = size >> k;
        GL_ENUM(ctx, TexImage2D, GL_RG32F)(GL_TEXTURE_2D, k, (GLint)GL_RG32F, s, s, 0, GL_RG,
                                           GL_FLOAT, NULL);
    }
}

void stin__vdsm_pyramid_release(stin_context *ctx)
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    GLuint none = 0;
    stin__vdsm_delete_programs(ctx, &p->light_prog, &p->receiver_prog, &p->reduce_prog);
    stin__vdsm_delete_programs(ctx, &p->tris_prog, &none, &none);
    if (p->fbo)
        GL(ctx, DeleteFramebuffers)(1, &p->fbo);
    if (p->points)
        GL(ctx, DeleteVertexArrays)(1, &p->points);
    if (p->accum)
        GL(ctx, DeleteTextures)(1, &p->accum);
    if (p->levels)
        GL(ctx, DeleteTextures)(1, &p->levels);
    if (p->stencil)
        GL(ctx, DeleteTextures)(1, &p->stencil);
    p->fbo = p->accum = p->levels = p->stencil = p->points = 0;
    p->usable = p->ready = 0;
    stin__vdsm_receivers_release(ctx);
}

/* A program of the light pass: geometry shader geom (its marks or its
 * triangles) with the chunk both share. */
static GLuint light_program(stin_context *ctx, const char *geom, char *msg, size_t size)
{
    static const char *const view[] = {"gl4/vdsm_light.glsl", NULL};
    stin__program_source src;
    stin__memzero(&src, sizeof src);
    src.vert = "gl4/vdsm.vert";
    src.geom = geom;
    src.geom_chunks = view;
    src.frag = "gl4/vdsm_light.frag";
    return stin__program_build_source(ctx, &src, msg, size);
}

void stin__vdsm_pyramid_init(stin_context *ctx)
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    char msg[160];
    GLenum status;
    int size = (int)(ctx->desc.shadows.map_size < MAX_SIZE ? ctx->desc.shadows.map_size : MAX_SIZE);
    msg[0] = '\0';
    p->light_prog = light_program(ctx, "gl4/vdsm_light.geom", msg, sizeof msg);
    if (p->light_prog)
        p->tris_prog = light_program(ctx, "gl4/vdsm_light_tris.geom", msg, sizeof msg);
    if (p->tris_prog)
        p->receiver_prog = stin__vdsm_program(ctx, "gl4/vdsm_receiver.vert", NULL,
                                              "gl4/vdsm_receiver.frag", NULL, 0, msg, sizeof msg);
    if (p->receiver_prog)
        p->reduce_prog = stin__vdsm_program(ctx, "gl4/screen.vert", NULL,
                                            "gl4/vdsm_reduce.frag", NULL, 0, msg, sizeof msg);
    if (!p->reduce_prog) {
        stin__vdsm_pyramid_release(ctx);
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "vdsm: the light-view pyramid's shaders failed to build (%s): steps SM and "
                  "DC are off", msg);
        return;
    }
    locate(ctx);
    p->alloc = p->size = size;
    for (p->top = 0; (1 << p->top) < size; p->top++)
        ;
    GL(ctx, GenFramebuffers)(1, &p->fbo);
    GL(ctx, GenVertexArrays)(1, &p->points);
    GL(ctx, GenTextures)(1, &p->accum);
    GL(ctx, GenTextures)(1, &p->levels);
    GL(ctx, GenTextures)(1, &p->stencil);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    float_texture(ctx, p->accum, 1, size);
    float_texture(ctx, p->levels, p->top + 1, size);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, p->stencil);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    GL_ENUM(ctx, TexImage2D, GL_DEPTH24_STENCIL8)(GL_TEXTURE_2D, 0, (GLint)GL_DEPTH24_STENCIL8,
                                                  size, size, 0, GL_DEPTH_STENCIL,
                                                  GL_UNSIGNED_INT_24_8, NULL);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, p->fbo);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, p->accum,
                                  0);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, p->stencil,
                                  0);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                                  p->stencil, 0);
    status = GL(ctx, CheckFramebufferStatus)(GL_FRAMEBUFFER);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        stin__vdsm_pyramid_release(ctx);
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "vdsm: the light-view pyramid's framebuffer is incomplete (0x%x): steps SM "
                  "and DC are off", (unsigned)status);
        return;
    }
    p->usable = 1;
    (void)stin__vdsm_receivers_init(ctx); /* where it is not: the points */
}

/* ---- the light's view ----------------------------------------------------- */

static float absf(float x) { return x < 0.0f ? -x : x; }

/* Corner `corner` (0..7) of draw d's bounds, in world space. */
static void draw_corner(const stin_context *ctx, const stin__draw *d, int corner, float out[3])
{
    const stin_mesh_info *info = &ctx->meshes[d->mesh_slot].info;
    float q[3];
    int k;
    for (k = 0; k < 3; k++)
        q[k] = (corner >> k) & 1 ? info->bounds_max[k] : info->bounds_min[k];
    stin__mat4_transform_point(d->transform, q, out);
}

/* The light's view: from the light (or along it) toward the centre of the
 * box around every draw's bounds. Orthographic views cover every box;
 * perspective ones the boxes' corners in front of the light, at most
 * MAX_TAN wide: what lies outside is looked up nowhere (the footprint test
 * of vdsm.geom) and casts as without the steps. z is unused (0): the passes
 * draw at z 0, nothing is clipped by depth. 0 where there is no view. */
static int fit(stin__vdsm_pyramid *p, const stin_context *ctx, const float light[4])
{
    float view[16], proj[16], lo[3], hi[3], c[3], dir[3], eye[3];
    float len = 0.0f, reach = 0.0f, zmax = 0.0f;
    float spread = 0.0f; /* the widest corner: tangent (perspective) or offset */
    int persp = light[3] != 0.0f, pass, k, corner;
    uint32_t i;
    if (!ctx->draw_count)
        return 0;
    for (k = 0; k < 3; k++) {
        lo[k] = BIG;
        hi[k] = -BIG;
    }
    for (i = 0; i < ctx->draw_count; i++)
        for (corner = 0; corner < 8; corner++) {
            float w[3];
            draw_corner(ctx, &ctx->draws[i], corner, w);
            for (k = 0; k < 3; k++) {
                lo[k] = w[k] < lo[k] ? w[k] : lo[k];
                hi[k] = w[k] > hi[k] ? w[k] : hi[k];
            }
        }
    for (k = 0; k < 3; k++) {
        c[k] = 0.5f * (lo[k] + hi[k]);
        reach += (hi[k] - c[k]) * (hi[k] - c[k]);
        dir[k] = persp ? c[k] - light[k] : -light[k];
        len += dir[k] * dir[k];
    }
    reach = stin__sqrtf(reach) * 1.01f + 1e-6f;
    len = stin__sqrtf(len);
    if (!(len > 0.0f))
        return 0; /* a point light at the centre: no way to look */
    for (k = 0; k < 3; k++) {
        dir[k] /= len;
        eye[k] = persp ? light[k] : c[k] - dir[k] * 2.0f * reach;
    }
    stin__light_look_along(view, eye, dir);
    /* pass 0: the deepest corner; pass 1: the spread of those clearly in front */
    for (pass = 0; pass < 2; pass++)
        for (i = 0; i < ctx->draw_count; i++)
            for (corner = 0; corner < 8; corner++) {
                float w[3], e[3], z;
                draw_corner(ctx, &ctx->draws[i], corner, w);
                stin__mat4_transform_point(view, w, e);
                z = -e[2];
                if (pass == 0) {
                    zmax = z > zmax ? z : zmax;
                    continue;
                }
                if (persp && !(z > FRONT * zmax))
                    continue;
                e[0] = absf(e[0]);
                e[1] = absf(e[1]);
                if (persp) {
                    e[0] /= z;
                    e[1] /= z;
                }
                spread = e[0] > spread ? e[0] : spread;
                spread = e[1] > spread ? e[1] : spread;
            }
    if (!(zmax > 0.0f))
        return 0;
    spread = spread * 1.01f + 1e-6f * (persp ? 1.0f : reach);
    if (persp && spread > MAX_TAN)
        spread = MAX_TAN;
    stin__memzero(proj, sizeof proj);
    proj[0] = proj[5] = 1.0f / spread;
    if (persp)
        proj[11] = -1.0f; /* w = -z */
    else
        proj[15] = 1.0f;
    stin__mat4_mul(p->view_proj, proj, view);
    /* depth = -z in the light's eye space */
    for (k = 0; k < 4; k++)
        p->depth_row[k] = -view[4 * k + 2];
    p->perspective = persp;
    p->front = persp ? FRONT * zmax : -BIG;
    return 1;
}

/* The light depths of a draw's bounds: the nearest and the deepest corner. */
static void draw_depths(const stin__vdsm_pyramid *p, const stin_context *ctx,
                        const stin__draw *d, float *nearest, float *deepest)
{
    int corner, k;
    *nearest = BIG;
    *deepest = -BIG;
    for (corner = 0; corner < 8; corner++) {
        float w[3], z = p->depth_row[3];
        draw_corner(ctx, d, corner, w);
        for (k = 0; k < 3; k++)
            z += p->depth_row[k] * w[k];
        *nearest = z < *nearest ? z : *nearest;
        *deepest = z > *deepest ? z : *deepest;
    }
}

/* ---- the passes ----------------------------------------------------------- */

/* Per draw: its outline into the stencil with its id, then its triangles
 * where the stencil does not hold that id (ps: the MAX-blended state). */
/* The light pass's uniforms for this light on program prog (bound). */
static void light_uniforms(stin_context *ctx, GLuint prog, const stin__vdsm_light_locs *l,
                           const float light[4])
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    GL(ctx, UseProgram)(prog);
    GL(ctx, UniformMatrix4fv)(l->vp, 1, GL_FALSE, p->view_proj);
    GL(ctx, Uniform4fv)(l->depth, 1, p->depth_row);
    GL(ctx, Uniform4fv)(l->light, 1, light);
    GL(ctx, Uniform1f)(l->size, (float)p->size);
    GL(ctx, Uniform1f)(l->grow, GROW_TEXELS);
    GL(ctx, Uniform1i)(l->persp, p->perspective);
}

/* A draw's uniforms on the light pass's program prog, made current. */
static void light_draw(stin_context *ctx, GLuint prog, const stin__vdsm_light_locs *l,
                       const stin__draw *d, float deepest)
{
    GL(ctx, UseProgram)(prog);
    GL(ctx, UniformMatrix4fv)(l->model, 1, GL_FALSE, d->transform);
    GL(ctx, Uniform1i)(l->cull_lit, stin__vdsm_cull_lit(ctx, d));
    GL(ctx, Uniform1f)(l->bound, deepest);
}

static void occluders(stin_context *ctx, const float light[4], stin__pass_state ps)
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    uint32_t i;
    int id = 0;
    light_uniforms(ctx, p->tris_prog, &p->tris, light);
    light_uniforms(ctx, p->light_prog, &p->marks, light);
    ps.stencil_test = 1;
    ps.two_sided = 0;
    ps.stencil_write_mask = 0xffu;
    ps.front.mask = 0xffu;
    ps.front.fail = ps.front.zfail = GL_KEEP;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
        GLsizei count = (GLsizei)(6u * m->triangle_count);
        float nearest, deepest;
        /* not an occluder here, it still casts: no adjacency, or displaced
         * (its bounds, and so its depth range, are the flat mesh's) */
        if (!m->adj_vao || stin__displace_active(ctx, &d->material) ||
            !d->shadow_caster)
            continue; /* (a transparent caster its map or the threshold decides) */
        draw_depths(p, ctx, d, &nearest, &deepest);
        if (!(nearest > p->front))
            continue; /* reaches behind the light: its projection is no triangle */
        id = id % 255 + 1;
        /* the outline's marks (adjacency), then the triangles off them */
        light_draw(ctx, p->light_prog, &p->marks, d, deepest);
        GL(ctx, BindVertexArray)(m->adj_vao);
        ctx->bound_mesh = 0xffffffffu;
        ps.color_write = 0;
        ps.front.func = GL_ALWAYS;
        ps.front.ref = id;
        ps.front.zpass = GL_REPLACE;
        stin__pass_apply(ctx, &ps);
        GL(ctx, DrawElements)(GL_TRIANGLES_ADJACENCY, count, m->index_type, NULL);
        light_draw(ctx, p->tris_prog, &p->tris, d, deepest);
        ps.color_write = 1;
        ps.front.func = GL_NOTEQUAL;
        ps.front.zpass = GL_KEEP;
        stin__pass_apply(ctx, &ps);
        stin__glsl_submit_geometry(ctx, p->tris.model, &p->tris_displace, d);
    }
    GL(ctx, BindVertexArray)(0);
    ctx->bound_mesh = 0xffffffffu;
    ps.stencil_test = 0;
    ps.color_write = 1;
    stin__pass_apply(ctx, &ps);
}

static void receivers(stin_context *ctx, const float light[4])
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    const int *vp = ctx->frame.viewport;
    GL(ctx, UseProgram)(p->receiver_prog);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, ctx->vdsm->position);
    stin__bind_unit(ctx, 1, GL_TEXTURE_2D, ctx->vdsm->normal);
    stin__bind_unit(ctx, 2, GL_TEXTURE_2D, ctx->vdsm->shading);
    GL(ctx, Uniform1i)(p->r_position, 0);
    GL(ctx, Uniform1i)(p->r_normal, 1);
    GL(ctx, Uniform1i)(p->r_shading, 2);
    GL(ctx, Uniform4fv)(p->r_light, 1, light);
    GL(ctx, UniformMatrix4fv)(p->r_vp, 1, GL_FALSE, p->view_proj);
    GL(ctx, Uniform4fv)(p->r_depth, 1, p->depth_row);
    {
        float rect[4];
        int k;
        for (k = 0; k < 4; k++)
            rect[k] = (float)vp[k];
        GL(ctx, Uniform4fv)(p->r_rect, 1, rect);
    }
    GL(ctx, BindVertexArray)(p->points);
    GL(ctx, DrawArrays)(GL_POINTS, 0, (GLsizei)vp[2] * vp[3]);
    GL(ctx, BindVertexArray)(0);
    ctx->bound_mesh = 0xffffffffu;
}

/* Level 0 from the accumulation, then each level from the one below it
 * (read through its base level, so no level is read while drawn into). */
static void reduce(stin_context *ctx)
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    int k;
    GL(ctx, UseProgram)(p->reduce_prog);
    GL(ctx, Uniform1i)(p->d_source, 0);
    for (k = 0; k <= p->top; k++) {
        int s = p->size >> k;
        GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                      p->levels, k);
        GL(ctx, Viewport)(0, 0, s, s);
        if (k == 0 && p->deepest) { /* the receivers came by atomics */
            stin__vdsm_receivers_first_level(ctx);
            GL(ctx, UseProgram)(p->reduce_prog);
            continue;
        }
        GL(ctx, Uniform1i)(p->d_first, k == 0);
        if (k == 0) {
            stin__bind_unit(ctx, 0, GL_TEXTURE_2D, p->accum);
        } else {
            stin__bind_unit(ctx, 0, GL_TEXTURE_2D, p->levels);
            GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, k - 1);
            GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, k - 1);
        }
        stin__screen_quad(ctx);
    }
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, p->levels);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, p->top);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
}

/* Level 0's side for viewport vp: the power of two nearest half its larger
 * side, at least 256 and at most the allocation. A finer level costs its
 * clear and reduction in fill and culls few more triangles; a coarser one
 * than 256 culls markedly fewer (docs/benchmarks.md, "The pyramid sized to
 * the viewport"). The mask is the same at any size. */
static void size_to_viewport(stin__vdsm_pyramid *p, const int vp[4])
{
    int want = (vp[2] > vp[3] ? vp[2] : vp[3]) / 2;
    int s = p->alloc < MIN_DRAWN ? p->alloc : MIN_DRAWN;
    while (s < p->alloc && s * 3 < want * 2) /* 2s is nearer want than s is */
        s *= 2;
    p->size = s;
    for (p->top = 0; (1 << p->top) < s; p->top++)
        ;
}

int stin__vdsm_pyramid_draw(stin_context *ctx, const float light[4], int channel)
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    uint64_t flags = ctx->desc.debug_flags;
    int sm = !(flags & STIN_DEBUG_VDSM_NO_SM), dc = !(flags & STIN_DEBUG_VDSM_NO_DC);
    stin__pass_state saved = *stin__pass_current(ctx), ps = saved;
    const int *vp = ctx->frame.viewport;
    p->ready = 0;
    if (!p->usable || !(sm || dc))
        return 0;
    if (!fit(p, ctx, light)) {
        if (!p->said_no_view)
            stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                      "vdsm: a point light at the centre of the draws' bounds has no light "
                      "view: steps SM and DC are off for it");
        p->said_no_view = 1;
        return 0;
    }
    size_to_viewport(p, vp);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, p->fbo);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, p->accum,
                                  0);
    GL(ctx, Viewport)(0, 0, p->size, p->size);
    ps.depth_test = ps.depth_write = ps.stencil_test = ps.blend = ps.cull = 0;
    ps.depth_clamp = ps.polygon_offset = 0;
    /* the clear (and everything after it) within this frame's level 0 */
    ps.scissor = p->size < p->alloc;
    ps.scissor_box[0] = ps.scissor_box[1] = 0;
    ps.scissor_box[2] = ps.scissor_box[3] = p->size;
    ps.color_write = 1;
    ps.color_only = 0;
    ps.stencil_write_mask = 0xffffffffu;
    stin__pass_apply(ctx, &ps);
    GL(ctx, ClearColor)(-BIG, -BIG, 0.0f, 0.0f);
    GL(ctx, ClearStencil)(0);
    GL(ctx, Clear)(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    /* MAX blending; ADD again after, the equation every other pass draws
     * with (the frame set it at its start: gl/caller_state.c) */
    ps.blend = 1;
    ps.blend_src = ps.blend_dst = GL_ONE;
    stin__pass_apply(ctx, &ps);
    GL(ctx, BlendEquationSeparate)(GL_MAX, GL_MAX);
    stin__lit_program_forget(ctx);
    if (sm)
        occluders(ctx, light, ps);
    if (dc && !p->atomic_prog)
        receivers(ctx, light);
    GL(ctx, BlendEquationSeparate)(GL_FUNC_ADD, GL_FUNC_ADD);
    ps.blend = 0;
    stin__pass_apply(ctx, &ps);
    if (dc && p->atomic_prog)
        stin__vdsm_receivers_draw(ctx, light, channel);
    reduce(ctx);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, stin__mask_target_of(ctx).fbo);
    GL(ctx, Viewport)(vp[0], vp[1], vp[2], vp[3]);
    stin__pass_apply(ctx, &saved);
    ctx->stats.passes += 2u + (uint32_t)sm + (uint32_t)dc;
    p->ready = 1;
    return dc && p->atomic_prog; /* the receivers' pass wrote the facing channel */
}

void stin__vdsm_pyramid_uniforms(stin_context *ctx, const stin__vdsm_pyramid_locs *l)
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    uint64_t flags = ctx->desc.debug_flags;
    int on = p->ready;
    GL(ctx, Uniform1i)(l->sm, on && !(flags & STIN_DEBUG_VDSM_NO_SM));
    GL(ctx, Uniform1i)(l->dc, on && !(flags & STIN_DEBUG_VDSM_NO_DC));
    if (!on)
        return;
    if (l->pyramid >= 0) {
        stin__bind_unit(ctx, 2, GL_TEXTURE_2D, p->levels);
        GL(ctx, Uniform1i)(l->pyramid, 2);
    }
    GL(ctx, UniformMatrix4fv)(l->vp, 1, GL_FALSE, p->view_proj);
    GL(ctx, Uniform4fv)(l->depth, 1, p->depth_row);
    GL(ctx, Uniform1f)(l->size, (float)p->size);
    GL(ctx, Uniform1i)(l->top, p->top);
}
