/* SPDX-License-Identifier: MIT */
/* Stencil shadow volumes (Everitt & Kilgard's robust variant): per light,
 * every caster's volume counted into the stencil buffer — z-pass where the
 * near-clip region cannot touch the caster's volume, else z-fail with caps —
 * in one pass with two-sided stencil and wrap where present, else in two
 * culled passes, increments first so clamped counts lose nothing. The far
 * plane is at infinity (nudged P_inf) or depth clamp keeps far caps. */
#include "shadow/volume_private.h"
#include "render/draw_bounds.h"

#define NO_SCISSOR(s) ((s) == NULL)

void stin__volume_sink_draw(void *user, const float *xyzw, uint32_t n, int clockwise)
{
    stin__volume_sink_state *s = (stin__volume_sink_state *)user;
    stin__pass_state ps = *stin__pass_current(s->ctx);
    ps.front_face = clockwise ? GL_CW : GL_CCW;
    stin__pass_apply(s->ctx, &ps);
    s->path->volume_draw(s->ctx, s->model, xyzw, n);
}

/* ---- frame set-up: projection ------------------------------------------- */

static int is_perspective(const float p[16])
{
    return p[3] == 0.0f && p[7] == 0.0f && p[11] == -1.0f && p[15] == 0.0f;
}

void stin__volume_projection(stin_context *ctx)
{
    ctx->volume->depth_clamp = 0;
    if (is_perspective(ctx->projection)) {
        /* Row 3 of the frustum to (eps - 1, (eps - 2) n): the far plane goes to
         * infinity and w = 0 vertices land just inside NDC z = 1. Preferred
         * over depth clamp, which ties far caps with receivers at the far
         * plane (measured: a streak of false shadow along the horizon). */
        const float eps = 2.4e-7f;
        float n = ctx->projection[14] / (ctx->projection[10] - 1.0f);
        ctx->projection[10] = eps - 1.0f;
        ctx->projection[14] = (eps - 2.0f) * n;
    } else if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_DEPTH_CLAMP)) {
        ctx->volume->depth_clamp = 1; /* orthographic: no P_inf exists */
    }
    stin__mat4_mul(ctx->view_proj, ctx->projection, ctx->frame.view);
}

size_t stin__volume_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(struct stin__volume_state);
}

/* ---- z-pass or z-fail per caster ---------------------------------------- */

typedef struct plane {
    float n[3], d; /* inside: n.x + d >= 0 */
} plane;

static float dot3(const float a[3], const float b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void plane_from(plane *pl, const float a[3], const float b[3], const float c[3],
                       const float inside[3])
{
    float e1[3], e2[3], len;
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = b[k] - a[k];
        e2[k] = c[k] - a[k];
    }
    pl->n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    pl->n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    pl->n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    len = stin__sqrtf(dot3(pl->n, pl->n));
    if (len > 0)
        for (k = 0; k < 3; k++)
            pl->n[k] /= len;
    pl->d = -dot3(pl->n, a);
    if (dot3(pl->n, inside) + pl->d < 0) {
        for (k = 0; k < 3; k++)
            pl->n[k] = -pl->n[k];
        pl->d = -pl->d;
    }
}

/* World corners of the near-plane rectangle. */
static int near_corners(const stin_context *ctx, float out[4][3])
{
    float inv[16];
    int i;
    if (!stin__mat4_invert(inv, ctx->view_proj))
        return 0;
    for (i = 0; i < 4; i++) {
        float x = (i == 1 || i == 2) ? 1.0f : -1.0f, y = i >= 2 ? 1.0f : -1.0f;
        float c[4];
        int r;
        for (r = 0; r < 4; r++) /* NDC (x, y, -1, 1) */
            c[r] = inv[r] * x + inv[4 + r] * y - inv[8 + r] + inv[12 + r];
        if (c[3] == 0.0f)
            return 0;
        for (r = 0; r < 3; r++)
            out[i][r] = c[r] / c[3];
    }
    return 1;
}

/* Everitt & Kilgard's near-clip volume: the region between the near-plane
 * rectangle and the light, as its five planes (once per light sample). A
 * caster whose bounding sphere lies outside one of them cannot put its
 * volume across the near plane: z-pass is exact. 0 planes: unknown, z-fail
 * for every caster. */
static int near_clip_planes(const stin_context *ctx, const float light[4], plane out[5])
{
    float c[4][3], mid[3] = {0, 0, 0}, inside[3], apex_dir[3];
    int i, k;
    if (!near_corners(ctx, c))
        return 0;
    for (i = 0; i < 4; i++)
        for (k = 0; k < 3; k++)
            mid[k] += 0.25f * c[i][k];
    for (k = 0; k < 3; k++)
        apex_dir[k] = light[3] != 0.0f ? light[k] / light[3] - mid[k] : light[k];
    for (k = 0; k < 3; k++) /* halfway to the light: inside every plane */
        inside[k] = mid[k] + 0.5f * apex_dir[k];
    /* near plane itself, inside toward the light */
    plane_from(&out[0], c[0], c[1], c[2], inside);
    for (i = 0; i < 4; i++) {
        const float *a = c[i], *b = c[(i + 1) % 4];
        float apex[3];
        for (k = 0; k < 3; k++)
            apex[k] = light[3] != 0.0f ? light[k] / light[3] : a[k] + apex_dir[k];
        plane_from(&out[1 + i], a, b, apex, inside);
    }
    return 5;
}

static int needs_zfail(const plane *planes, int n, const float center[3], float radius)
{
    int i;
    for (i = 0; i < n; i++)
        if (dot3(planes[i].n, center) + planes[i].d < -radius)
            return 0;
    return 1;
}

/* One caster's volume, cut at the world plane far_world: extruded on the
 * GPU where it can be (not for the debug overlay, which draws with the
 * path's program), else built here. */
static void draw_caster(stin_context *ctx, const stin__path *path, const stin__draw *d,
                        const float light_world[4], const float far_world[4], int zfail,
                        int extrude)
{
    const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
    stin__volume_request r;
    stin__volume_sink_state st;
    float inv[16];
    int k;
    uint32_t tris;
    if (!stin__mat4_invert(inv, d->transform))
        return; /* a flattened caster casts nothing */
    for (k = 0; k < 4; k++)
        r.light[k] = inv[k] * light_world[0] + inv[4 + k] * light_world[1] +
                     inv[8 + k] * light_world[2] + inv[12 + k] * light_world[3];
    stin__volume_plane_to_object(far_world, d->transform, r.far_plane);
    if (extrude && stin__volume_extrude_draw(ctx, d, r.light, r.far_plane, zfail)) {
        ctx->volume->path_unbound = 1;
        return;
    }
    if (ctx->volume->path_unbound) {
        path->volume_begin(ctx);
        ctx->volume->path_unbound = 0;
    }
    r.verts = ctx->vertices + m->first_vertex;
    r.tris = ctx->indices + 3u * m->first_triangle;
    r.adjacency = ctx->adjacency + 3u * m->first_triangle;
    r.tri_count = m->triangle_count;
    r.closed = m->info.closed_manifold;
    r.caps = zfail;
    r.facing = ctx->frame_scratch;
    r.buffer = (float *)(void *)(ctx->frame_scratch + stin__align16(m->triangle_count));
    r.buffer_vertices =
        (uint32_t)((ctx->frame_scratch_bytes - stin__align16(m->triangle_count)) / 16u);
    r.buffer_vertices -= r.buffer_vertices % 3u;
    st.ctx = ctx;
    st.path = path;
    st.model = d->transform;
    r.sink = stin__volume_sink_draw;
    r.user = &st;
    tris = stin__volume_build(&r);
    ctx->stats.shadows.volume_triangles += tris;
}

static void caster_bounds(const stin_context *ctx, const stin__draw *d, float center[3],
                          float *radius)
{
    const stin_mesh_info *info = &ctx->meshes[d->mesh_slot].info;
    float c[3], corner[3], w[3], r2 = 0;
    int k, i;
    for (k = 0; k < 3; k++)
        c[k] = 0.5f * (info->bounds_min[k] + info->bounds_max[k]);
    stin__mat4_transform_point(d->transform, c, center);
    for (i = 0; i < 8; i++) {
        float dd = 0;
        for (k = 0; k < 3; k++)
            corner[k] = (i >> k) & 1 ? info->bounds_max[k] : info->bounds_min[k];
        stin__mat4_transform_point(d->transform, corner, w);
        for (k = 0; k < 3; k++)
            dd += (w[k] - center[k]) * (w[k] - center[k]);
        if (dd > r2)
            r2 = dd;
    }
    *radius = stin__sqrtf(r2) * 1.001f;
}

/* Where d's volume is cut (far_world); 0 where it cannot reach the view. */
static int caster_reach(stin_context *ctx, const stin__volume_reach *reach, const stin__draw *d,
                        float far_world[4])
{
    float corners[24];
    int k;
    if (!stin__draw_world_corners(ctx, d, corners)) {
        for (k = 0; k < 4; k++)
            far_world[k] = k == 3 ? -1.0f : 0.0f; /* to infinity */
        return 1;
    }
    if (!stin__volume_reach_caster(reach, corners, far_world)) {
        ctx->stats.shadows.volume_culled_casters++;
        return 0;
    }
    if (far_world[3] != -1.0f || far_world[0] != 0.0f || far_world[1] != 0.0f ||
        far_world[2] != 0.0f)
        ctx->stats.shadows.volume_cut_casters++;
    return 1;
}

/* Stencil operations of one face: z-pass counts faces in front of the
 * surface, z-fail the ones behind it. */
static void face_ops(stin__stencil_face *f, int zfail, int back, GLenum incr, GLenum decr)
{
    f->func = GL_ALWAYS;
    f->ref = 0;
    f->mask = 0xffffffffu;
    f->fail = GL_KEEP;
    f->zfail = zfail ? (back ? incr : decr) : GL_KEEP;
    f->zpass = zfail ? GL_KEEP : (back ? decr : incr);
}

/* The stencil test of a lit pass: where the count is zero; INCR keeps a
 * second fragment at the same depth from being lit twice. */
static void lit_where_zero(stin__pass_state *ps)
{
    ps->two_sided = 0;
    ps->front.func = GL_EQUAL;
    ps->front.ref = 0;
    ps->front.mask = 0xffffffffu;
    ps->front.fail = ps->front.zfail = GL_KEEP;
    ps->front.zpass = GL_INCR;
}

void stin__volume_light(stin_context *ctx, const stin__path *path, const float light_world[4],
                        const int scissor[4])
{
    int two_sided = stin__pass_two_sided_wrap(ctx);
    GLenum incr = two_sided ? GL_INCR_WRAP : GL_INCR, decr = two_sided ? GL_DECR_WRAP : GL_DECR;
    stin__pass_state ps = stin__pass_defaults;
    uint32_t i;
    int k, n_planes;
    plane planes[5];
    stin__volume_reach reach;
    /* The frame's viewport at most: the stencil of the rest of the
     * framebuffer (other viewports of a keep_contents frame) is not ours. */
    if (NO_SCISSOR(scissor))
        scissor = ctx->frame.viewport;
    ps.depth_test = 1;
    ps.depth_write = 0;
    ps.color_write = 0;
    ps.scissor = 1;
    for (k = 0; k < 4; k++)
        ps.scissor_box[k] = scissor[k];
    ps.depth_clamp = (unsigned char)ctx->volume->depth_clamp;
    ps.stencil_test = 1;
    stin__pass_apply(ctx, &ps);
    GL(ctx, ClearStencil)(0);
    GL(ctx, Clear)(GL_STENCIL_BUFFER_BIT);
    n_planes = near_clip_planes(ctx, light_world, planes);
    stin__volume_reach_begin(ctx, light_world, &reach);
    path->volume_begin(ctx);
    ctx->volume->path_unbound = 0;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        float center[3], radius, far_world[4];
        stin__stencil_face back, front;
        int zfail;
        if (!d->shadow_caster || stin__cast_map_casts(ctx, d))
            continue; /* a transparent caster: its map or the threshold decides;
                       * a displaced one: volumes' depth map casts it */
        if (!caster_reach(ctx, &reach, d, far_world))
            continue;
        caster_bounds(ctx, d, center, &radius);
        /* z-pass counts a volume entered through its cap only where the
         * caster hides what lies behind it: a blended caster (not in the
         * depth buffer) is seen through, so it is counted z-fail, with caps */
        zfail = (ctx->desc.debug_flags & STIN_DEBUG_VOLUME_ZFAIL)   ? 1
                : (ctx->desc.debug_flags & STIN_DEBUG_VOLUME_ZPASS) ? 0
                : d->material.color[3] < 1.0f                        ? 1
                                                                    : needs_zfail(planes, n_planes, center, radius);
        if (zfail)
            ctx->stats.shadows.zfail_casters++;
        else
            ctx->stats.shadows.zpass_casters++;
        face_ops(&back, zfail, 1, incr, decr);
        face_ops(&front, zfail, 0, incr, decr);
        if (two_sided) {
            ps.cull = 0;
            ps.two_sided = 1;
            ps.front = front;
            ps.back = back;
            stin__pass_apply(ctx, &ps);
            draw_caster(ctx, path, d, light_world, far_world, zfail, 1);
        } else {
            /* Increments first (z-pass: front faces, z-fail: back faces), so a
             * clamped count never has to go below zero. */
            ps.cull = 1;
            ps.cull_face = zfail ? GL_FRONT : GL_BACK;
            ps.front = zfail ? back : front;
            stin__pass_apply(ctx, &ps);
            draw_caster(ctx, path, d, light_world, far_world, zfail, 1);
            ps.cull_face = zfail ? GL_BACK : GL_FRONT;
            ps.front = zfail ? front : back;
            stin__pass_apply(ctx, &ps);
            draw_caster(ctx, path, d, light_world, far_world, zfail, 1);
        }
    }
    path->volume_end(ctx);
    stin__volume_take_back_band(ctx, path, light_world, &reach);
    ps = *stin__pass_current(ctx);
    ps.front_face = GL_CCW;
    ps.cull = 0;
    ps.cull_face = GL_BACK;
    ps.depth_clamp = 0;
    ps.color_write = 1;
    lit_where_zero(&ps);
    stin__pass_apply(ctx, &ps);
    ctx->stats.passes++;
}

void stin__volume_light_end(stin_context *ctx)
{
    stin__pass_state ps = *stin__pass_current(ctx);
    ps.stencil_test = 0;
    ps.scissor = 0;
    stin__pass_apply(ctx, &ps);
}

/* Bounding rectangle of the light's sphere of influence on screen. */
int stin__light_scissor(const stin_context *ctx, const stin_light_desc *l, int out[4])
{
    const int *vp = ctx->frame.viewport;
    float minx = 1e30f, miny = 1e30f, maxx = -1e30f, maxy = -1e30f;
    int i, k;
    if (l->range <= 0.0f || l->type == STIN_LIGHT_DIRECTIONAL)
        return 0;
    for (i = 0; i < 8; i++) {
        float p[3], c[4];
        int r;
        for (k = 0; k < 3; k++)
            p[k] = l->position[k] + ((i >> k) & 1 ? l->range : -l->range);
        for (r = 0; r < 4; r++)
            c[r] = ctx->view_proj[r] * p[0] + ctx->view_proj[4 + r] * p[1] +
                   ctx->view_proj[8 + r] * p[2] + ctx->view_proj[12 + r];
        if (c[3] <= 1e-6f)
            return 0; /* the box reaches behind the eye: no useful bound */
        c[0] /= c[3];
        c[1] /= c[3];
        if (c[0] < minx) minx = c[0];
        if (c[0] > maxx) maxx = c[0];
        if (c[1] < miny) miny = c[1];
        if (c[1] > maxy) maxy = c[1];
    }
    minx = minx < -1 ? -1 : minx;
    miny = miny < -1 ? -1 : miny;
    maxx = maxx > 1 ? 1 : maxx;
    maxy = maxy > 1 ? 1 : maxy;
    if (maxx <= minx || maxy <= miny) {
        out[0] = vp[0];
        out[1] = vp[1];
        out[2] = out[3] = 0; /* off screen: nothing to shade */
        return 1;
    }
    out[0] = vp[0] + (int)((minx * 0.5f + 0.5f) * (float)vp[2]);
    out[1] = vp[1] + (int)((miny * 0.5f + 0.5f) * (float)vp[3]);
    out[2] = vp[0] + (int)((maxx * 0.5f + 0.5f) * (float)vp[2] + 1.0f) - out[0];
    out[3] = vp[1] + (int)((maxy * 0.5f + 0.5f) * (float)vp[3] + 1.0f) - out[1];
    return 1;
}

/* ---- the module ------------------------------------------------------------ */

/* Samples of a light: several for an area light with soft shadows. */
static uint32_t light_samples(const stin_context *ctx, const stin_light_desc *l)
{
    return l->radius > 0.0f && l->type != STIN_LIGHT_DIRECTIONAL ? ctx->desc.shadows.soft_samples
                                                                  : 1u;
}

/* One light sample as a homogeneous world position (w = 0: toward the light). */
static void sample_light(const stin_light_desc *l, uint32_t i, uint32_t n, stin_light_desc *out,
                         float world[4])
{
    *out = *l;
    if (l->type == STIN_LIGHT_DIRECTIONAL) {
        world[0] = -l->direction[0];
        world[1] = -l->direction[1];
        world[2] = -l->direction[2];
        world[3] = 0.0f;
        return;
    }
    stin_light_sample(l, i, n, out->position);
    out->intensity = l->intensity * stin__light_sample_weight(i, n);
    world[0] = out->position[0];
    world[1] = out->position[1];
    world[2] = out->position[2];
    world[3] = 1.0f;
}

static stin_result volume_init(stin_context *ctx)
{
    stin__volume_extrude_init(ctx);
    stin__cast_map_init(ctx, 0);
    return STIN_OK;
}

static void volume_release(stin_context *ctx)
{
    stin__volume_extrude_release(ctx);
    stin__cast_map_release(ctx);
}

static void volume_prepare(stin_context *ctx) { stin__volume_projection(ctx); }

/* Where an area light is shaded without the screen mask, a lit pass a
 * sample at intensity / n rounds each pass to the target's 8 bits, and the
 * roundings add up in bands (up to n / 2 steps). Where the frame draws into
 * its own target and that has 8 alpha bits, the samples' shares (whole
 * 255ths, stin__light_sample_weight) add up in destination alpha instead,
 * exactly, and the light is shaded once at its centre, scaled by them. */
static int shares_in_alpha(const stin_context *ctx, uint32_t n)
{
    return n > 1 && ctx->pass_channel == 0 && ctx->target.alpha_bits >= 8 &&
           ctx->draw_fbo == ctx->frame.framebuffer;
}

/* Alpha-only flat pass over the opaque draws' visible surfaces, blended
 * src * alpha + dst * dst_factor (the pass's stencil test applies). */
static void alpha_pass(stin_context *ctx, const stin__path *path, const stin_light_desc *l,
                       float alpha, GLenum dst_factor)
{
    float color[4];
    color[0] = color[1] = color[2] = 0.0f;
    color[3] = alpha;
    ctx->pass_channel = 4;
    ctx->pass_blend[0] = GL_ONE;
    ctx->pass_blend[1] = dst_factor;
    path->flat(ctx, STIN__OPAQUE, color, l);
    ctx->pass_channel = 0;
    ctx->pass_blend[0] = ctx->pass_blend[1] = 0;
}

/* The stencil cleared in `rect` and set to pass each pixel once (EQUAL 0,
 * INCR: coplanar fragments shaded once), as stin__volume_light leaves it. */
static void once_a_pixel(stin_context *ctx, const int rect[4])
{
    stin__pass_state ps = *stin__pass_current(ctx);
    int k;
    ps.scissor = 1;
    for (k = 0; k < 4; k++)
        ps.scissor_box[k] = rect[k];
    ps.stencil_test = 1;
    ps.stencil_write_mask = 0xffu;
    stin__pass_apply(ctx, &ps);
    GL(ctx, ClearStencil)(0);
    GL(ctx, Clear)(GL_STENCIL_BUFFER_BIT);
    lit_where_zero(&ps);
    stin__pass_apply(ctx, &ps);
}

static void shares_light(stin_context *ctx, const stin__path *path, const stin_light_desc *l,
                         uint32_t n, const int *scissor, stin__shade_fn shade)
{
    uint32_t s;
    alpha_pass(ctx, path, l, 0.0f, GL_ZERO); /* the shares start at 0 */
    for (s = 0; s < n; s++) {
        stin_light_desc one;
        float world[4];
        sample_light(l, s, n, &one, world);
        stin__volume_light(ctx, path, world, scissor);
        stin__cast_map_mark(ctx);
        alpha_pass(ctx, path, &one, stin__light_sample_weight(s, n), GL_ONE);
    }
    once_a_pixel(ctx, scissor ? scissor : ctx->frame.viewport);
    ctx->pass_blend[0] = GL_DST_ALPHA;
    ctx->pass_blend[1] = GL_ONE;
    shade(ctx, path, l, 1.0f);
    ctx->pass_blend[0] = ctx->pass_blend[1] = 0;
    stin__volume_light_end(ctx);
    alpha_pass(ctx, path, l, 1.0f, GL_ONE); /* opaque again (it saturates) */
}

/* Per light sample: its volumes counted into the stencil, then the sample
 * shaded where the count is zero, within the light's scissor. */
static void volume_shadow_light(stin_context *ctx, const stin__path *path, uint32_t li,
                                stin__shade_fn shade)
{
    const stin_light_desc *l = &ctx->lights[li];
    uint32_t s, n = light_samples(ctx, l);
    int rect[4], scissored = stin__light_scissor(ctx, l, rect);
    if (scissored && (rect[2] <= 0 || rect[3] <= 0))
        return; /* the light touches nothing on screen */
    (void)stin__cast_map_draw(ctx, path, li, ctx->draw_fbo, 0);
    if (shares_in_alpha(ctx, n)) {
        shares_light(ctx, path, l, n, scissored ? rect : NULL, shade);
        return;
    }
    for (s = 0; s < n; s++) {
        stin_light_desc one;
        float world[4];
        sample_light(l, s, n, &one, world);
        stin__volume_light(ctx, path, world, scissored ? rect : NULL);
        stin__cast_map_mark(ctx);
        shade(ctx, path, &one, stin__light_sample_weight(s, n));
    }
    stin__volume_light_end(ctx);
}

/* STIN_DEBUG_VOLUME_SHOW: each light's volumes over the frame's colour,
 * a faint orange added per face, so their overlaps show. */
static void volume_debug_overlay(stin_context *ctx, const stin__path *path)
{
    static const float tint[4] = {0.10f, 0.05f, 0.0f, 1.0f};
    stin__pass_state ps = stin__pass_defaults;
    stin_shadows_stats counted = ctx->stats.shadows;
    uint32_t li, i;
    if (!(ctx->desc.debug_flags & STIN_DEBUG_VOLUME_SHOW))
        return;
    ps.depth_test = 1;
    ps.depth_write = 0;
    ps.blend = 1;
    ps.blend_src = ps.blend_dst = GL_ONE;
    ps.depth_clamp = (unsigned char)ctx->volume->depth_clamp;
    stin__pass_apply(ctx, &ps);
    path->volume_begin(ctx);
    if (path == stin__glsl_path())
        GL(ctx, Uniform4fv)(ctx->programs[STIN__PROG_VOLUME].u_color, 1, tint);
    else
        GL(ctx, Color4f)(tint[0], tint[1], tint[2], tint[3]);
    for (li = 0; li < ctx->light_count; li++) {
        stin_light_desc one;
        stin__volume_reach reach;
        float world[4], far_world[4];
        sample_light(&ctx->lights[li], 0, 1, &one, world);
        stin__volume_reach_begin(ctx, world, &reach);
        for (i = 0; i < ctx->draw_count; i++) {
            const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
            if (!stin__cast_map_casts(ctx, d) && caster_reach(ctx, &reach, d, far_world))
                draw_caster(ctx, path, d, world, far_world, 1, 0);
        }
    }
    path->volume_end(ctx);
    ctx->stats.shadows = counted; /* a picture, not the frame's work */
}

/* A light into a mask channel: per sample its volumes counted in the
 * mask's stencil, then the sample's share added where the count is zero
 * (an area light's samples sum to its visible fraction, lit once at its
 * centre by the pass that reads the mask). */
static int volume_mask(stin_context *ctx, const stin__path *path, uint32_t li, int channel)
{
    const stin_light_desc *l = &ctx->lights[li];
    stin_light_desc one;
    float world[4];
    uint32_t s, n = light_samples(ctx, l);
    int rect[4], scissored = stin__light_scissor(ctx, l, rect);
    if (scissored && (rect[2] <= 0 || rect[3] <= 0))
        return 1; /* the light touches nothing on screen: its channel stays 0 */
    (void)stin__cast_map_draw(ctx, path, li, stin__mask_target_of(ctx).fbo, 0);
    for (s = 0; s < n; s++) {
        sample_light(l, s, n, &one, world);
        stin__volume_light(ctx, path, world, scissored ? rect : NULL);
        stin__cast_map_mark(ctx);
        stin__mask_write(ctx, path, channel, stin__light_sample_weight(s, n));
    }
    stin__volume_light_end(ctx);
    return 1;
}

const stin__shadow_technique stin__shadow_volume = {
    .glsl_chunk = "shadow_mask.glsl",
    .init = volume_init,
    .release = volume_release,
    .prepare = volume_prepare,
    .light_prepass = stin__cast_map_prepass, /* GL1 without FBOs: the products' maps */
    .light = volume_shadow_light,
    .uniforms = stin__mask_uniforms,
    .mask = volume_mask,
    .mask_depth = 1, /* the volumes' stencil counts against the frame's depth */
    .debug_overlay = volume_debug_overlay,
};
