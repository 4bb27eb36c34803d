/* Stencil shadow volumes (Everitt & Kilgard's robust variant): per light,
 * every caster's volume counted into the stencil buffer — z-pass where the
 * near-clip region cannot touch the caster's volume, else z-fail with caps —
 * in one pass with two-sided stencil and wrap where present, else in two
 * culled passes, increments first so clamped counts lose nothing. The far
 * plane is at infinity (nudged P_inf) or depth clamp keeps far caps. */
#include "internal.h"

#define NO_SCISSOR(s) ((s) == NULL)

typedef struct volume_sink_state {
    stin_context *ctx;
    const stin__path *path;
    const float *model;
} volume_sink_state;

static void sink(void *user, const float *xyzw, uint32_t n, int clockwise)
{
    volume_sink_state *s = (volume_sink_state *)user;
    if (clockwise)
        GL(s->ctx, FrontFace)(GL_CW);
    s->path->volume_draw(s->ctx, s->model, xyzw, n);
    if (clockwise)
        GL(s->ctx, FrontFace)(GL_CCW);
}

/* ---- frame set-up: projection ------------------------------------------- */

static int is_perspective(const float p[16])
{
    return p[3] == 0.0f && p[7] == 0.0f && p[11] == -1.0f && p[15] == 0.0f;
}

static int point_lights(const stin_context *ctx)
{
    uint32_t i;
    for (i = 0; i < ctx->light_count; i++)
        if (ctx->lights[i].type == STIN_LIGHT_POINT)
            return 1;
    return 0;
}

void stin__volume_frame_setup(stin_context *ctx)
{
    stin__memcopy(ctx->projection, ctx->frame.projection, sizeof ctx->projection);
    ctx->volume_depth_clamp = 0;
    ctx->volume_infinite = 0;
    if ((ctx->sel.choice[STIN_FEATURE_SHADOWS].technique == STIN_TECH_SHADOWS_VOLUME ||
         (stin__maps_active(ctx) && point_lights(ctx))) &&
        ctx->light_count > 0) {
        if (is_perspective(ctx->projection)) {
            /* Row 3 of the frustum to (eps - 1, (eps - 2) n): the far plane goes to
             * infinity and w = 0 vertices land just inside NDC z = 1. Preferred
             * over depth clamp, which ties far caps with receivers at the far
             * plane (measured: a streak of false shadow along the horizon). */
            const float eps = 2.4e-7f;
            float n = ctx->projection[14] / (ctx->projection[10] - 1.0f);
            ctx->projection[10] = eps - 1.0f;
            ctx->projection[14] = (eps - 2.0f) * n;
            ctx->volume_infinite = 1;
        } else if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_DEPTH_CLAMP)) {
            ctx->volume_depth_clamp = 1; /* orthographic: no P_inf exists */
        }
    }
    stin__mat4_mul(ctx->view_proj, ctx->projection, ctx->frame.view);
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
 * rectangle and the light. A caster whose bounding sphere lies outside one of
 * its planes cannot put its volume across the near plane: z-pass is exact. */
static int needs_zfail(const stin_context *ctx, const float light[4], const float center[3],
                       float radius)
{
    float c[4][3], mid[3] = {0, 0, 0}, inside[3], apex_dir[3];
    plane pl;
    int i, k;
    if (!near_corners(ctx, c))
        return 1;
    for (i = 0; i < 4; i++)
        for (k = 0; k < 3; k++)
            mid[k] += 0.25f * c[i][k];
    for (k = 0; k < 3; k++)
        apex_dir[k] = light[3] != 0.0f ? light[k] / light[3] - mid[k] : light[k];
    for (k = 0; k < 3; k++) /* halfway to the light: inside every plane */
        inside[k] = mid[k] + 0.5f * apex_dir[k];
    /* near plane itself, inside toward the light */
    plane_from(&pl, c[0], c[1], c[2], inside);
    if (dot3(pl.n, center) + pl.d < -radius)
        return 0;
    for (i = 0; i < 4; i++) {
        const float *a = c[i], *b = c[(i + 1) % 4];
        float apex[3];
        for (k = 0; k < 3; k++)
            apex[k] = light[3] != 0.0f ? light[k] / light[3] : a[k] + apex_dir[k];
        plane_from(&pl, a, b, apex, inside);
        if (dot3(pl.n, center) + pl.d < -radius)
            return 0;
    }
    return 1;
}

/* ---- stencil state ------------------------------------------------------ */

static void stencil_op(stin_context *ctx, GLenum fail, GLenum zfail, GLenum zpass)
{
    GLenum audited = zfail != GL_KEEP ? zfail : zpass;
    GL_ENUM(ctx, StencilOp, audited)(fail, zfail, zpass);
}

/* Ops for back and front faces: z-pass counts faces in front of the
 * surface, z-fail the ones behind it. */
static void ops_for(int zfail, int back, GLenum incr, GLenum decr, GLenum out[3])
{
    out[0] = GL_KEEP;
    out[1] = zfail ? (back ? incr : decr) : GL_KEEP;
    out[2] = zfail ? GL_KEEP : (back ? decr : incr);
}

static void draw_caster(stin_context *ctx, const stin__path *path, const stin__draw *d,
                        const float light_world[4], int zfail)
{
    const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
    stin__volume_request r;
    volume_sink_state st;
    float inv[16];
    int k;
    uint32_t tris;
    if (!stin__mat4_invert(inv, d->transform))
        return; /* a flattened caster casts nothing */
    for (k = 0; k < 4; k++)
        r.light[k] = inv[k] * light_world[0] + inv[4 + k] * light_world[1] +
                     inv[8 + k] * light_world[2] + inv[12 + k] * light_world[3];
    r.verts = ctx->vertices + m->first_vertex;
    r.tris = ctx->indices + 3u * m->first_triangle;
    r.adjacency = ctx->adjacency + 3u * m->first_triangle;
    r.tri_count = m->triangle_count;
    r.closed = m->info.closed_manifold;
    r.caps = zfail;
    r.facing = ctx->scratch;
    r.buffer = (float *)(void *)(ctx->scratch + stin__align16(m->triangle_count));
    r.buffer_vertices = (uint32_t)((ctx->scratch_bytes - stin__align16(m->triangle_count)) / 16u);
    r.buffer_vertices -= r.buffer_vertices % 3u;
    st.ctx = ctx;
    st.path = path;
    st.model = d->transform;
    r.sink = sink;
    r.user = &st;
    tris = stin__volume_build(&r);
    ctx->stats.shadow_volume_triangles += tris;
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

void stin__volume_light(stin_context *ctx, const stin__path *path, const float light_world[4],
                        const int scissor[4])
{
    uint64_t caps = ctx->caps.present;
    int two_sided = (caps & STIN_CAP_BIT(STIN_CAP_STENCIL_WRAP)) &&
                    (caps & (STIN_CAP_BIT(STIN_CAP_STENCIL_TWO_SIDE) |
                             STIN_CAP_BIT(STIN_CAP_SEPARATE_STENCIL)));
    GLenum incr = two_sided ? GL_INCR_WRAP : GL_INCR, decr = two_sided ? GL_DECR_WRAP : GL_DECR;
    uint32_t i;
    /* The frame's viewport at most: the stencil of the rest of the
     * framebuffer (other viewports of a no_clear frame) is not ours. */
    if (NO_SCISSOR(scissor))
        scissor = ctx->frame.viewport;
    GL_ENABLE(ctx, GL_SCISSOR_TEST);
    GL(ctx, Scissor)(scissor[0], scissor[1], scissor[2], scissor[3]);
    GL(ctx, StencilMask)(0xffffffffu);
    GL(ctx, ClearStencil)(0);
    GL(ctx, Clear)(GL_STENCIL_BUFFER_BIT);
    GL_ENABLE(ctx, GL_STENCIL_TEST);
    GL(ctx, StencilFunc)(GL_ALWAYS, 0, 0xffffffffu);
    GL(ctx, ColorMask)(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    GL(ctx, DepthMask)(GL_FALSE);
    GL(ctx, DepthFunc)(GL_LESS);
    GL_DISABLE(ctx, GL_BLEND);
    GL(ctx, FrontFace)(GL_CCW);
    if (ctx->volume_depth_clamp)
        GL_ENABLE(ctx, GL_DEPTH_CLAMP);
    path->volume_begin(ctx);
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        float center[3], radius;
        GLenum back[3], front[3];
        int zfail;
        caster_bounds(ctx, d, center, &radius);
        zfail = (ctx->desc.debug_flags & STIN_DEBUG_VOLUME_ZFAIL)   ? 1
                : (ctx->desc.debug_flags & STIN_DEBUG_VOLUME_ZPASS) ? 0
                                                                    : needs_zfail(ctx, light_world, center, radius);
        if (zfail)
            ctx->stats.zfail_casters++;
        else
            ctx->stats.zpass_casters++;
        ops_for(zfail, 1, incr, decr, back);
        ops_for(zfail, 0, incr, decr, front);
        if (two_sided) {
            GL_DISABLE(ctx, GL_CULL_FACE);
            if (caps & STIN_CAP_BIT(STIN_CAP_SEPARATE_STENCIL)) {
                GL(ctx, StencilOpSeparate)(GL_BACK, back[0], back[1], back[2]);
                GL(ctx, StencilOpSeparate)(GL_FRONT, front[0], front[1], front[2]);
            } else {
                GL_ENABLE(ctx, GL_STENCIL_TEST_TWO_SIDE_EXT);
                GL(ctx, ActiveStencilFaceEXT)(GL_BACK);
                stencil_op(ctx, back[0], back[1], back[2]);
                GL(ctx, StencilFunc)(GL_ALWAYS, 0, 0xffffffffu);
                GL(ctx, ActiveStencilFaceEXT)(GL_FRONT);
                stencil_op(ctx, front[0], front[1], front[2]);
            }
            draw_caster(ctx, path, d, light_world, zfail);
        } else {
            /* Increments first (z-pass: front faces, z-fail: back faces), so a
             * clamped count never has to go below zero. */
            GL_ENABLE(ctx, GL_CULL_FACE);
            GL(ctx, CullFace)(zfail ? GL_FRONT : GL_BACK);
            stencil_op(ctx, zfail ? back[0] : front[0], zfail ? back[1] : front[1],
                       zfail ? back[2] : front[2]);
            draw_caster(ctx, path, d, light_world, zfail);
            GL(ctx, CullFace)(zfail ? GL_BACK : GL_FRONT);
            stencil_op(ctx, zfail ? front[0] : back[0], zfail ? front[1] : back[1],
                       zfail ? front[2] : back[2]);
            draw_caster(ctx, path, d, light_world, zfail);
        }
    }
    path->volume_end(ctx);
    if (two_sided && !(caps & STIN_CAP_BIT(STIN_CAP_SEPARATE_STENCIL))) {
        GL_DISABLE(ctx, GL_STENCIL_TEST_TWO_SIDE_EXT);
        GL(ctx, ActiveStencilFaceEXT)(GL_FRONT);
    }
    GL_DISABLE(ctx, GL_CULL_FACE);
    GL(ctx, CullFace)(GL_BACK);
    if (ctx->volume_depth_clamp)
        GL_DISABLE(ctx, GL_DEPTH_CLAMP);
    GL(ctx, ColorMask)(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    /* Lit where the count is zero; INCR keeps a second fragment at the same
     * depth from being lit twice. */
    GL(ctx, StencilFunc)(GL_EQUAL, 0, 0xffffffffu);
    GL(ctx, StencilOp)(GL_KEEP, GL_KEEP, GL_INCR);
    ctx->stats.passes++;
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
