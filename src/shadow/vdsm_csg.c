/* SPDX-License-Identifier: MIT */
/* vdsm's shadows of CSG products, exact per pixel as vdsm's own. A
 * product's surface is not its primitives' triangles, so their shadow
 * polygons cannot simply write the mask; instead, per light and product,
 * every primitive's shadow polygons list per pixel each crossing of the
 * pixel's segment to the light with that primitive's surface (append pass:
 * vdsm_csg_append.frag, into per-pixel linked lists in shader storage
 * buffers), then one screen pass walks each list in order from the
 * light back to the surface, primitive by primitive in or out, and writes
 * the shadow where the product's normal form holds anywhere on the way
 * (vdsm_csg_walk.frag). Needs GL 4.3's storage buffers and atomics (the
 * "compute shaders" capability); without them, or where a product has more
 * than 128 primitives or 64 terms (logged), the frame's products cast
 * through the casters' depth map instead (shadow/cast_map.c). Whether the light lies inside a primitive
 * (where the walk starts) is a ray's parity on the CPU, from the block's
 * copy of the mesh. The node pool starts at one node a pixel of the
 * viewport and grows when a product's crossings outrun it (that product is
 * listed again). */
#include "shadow/vdsm_private.h"

#define HEAD_BYTES 4u
#define NODE_BYTES 16u
#define POOL_HEADER 16u /* used, unused, capacity, unused */
#define MIN_NODES 4096u

static int built(const stin_context *ctx)
{
    return ctx->vdsm->csg.walk_prog != 0;
}

static const stin__uniform_name append_uniforms[] = {
    STIN__UNIFORM(stin__vdsm_csg, a_model, "u_model"),
    STIN__UNIFORM(stin__vdsm_csg, a_view_proj, "u_view_proj"),
    STIN__UNIFORM(stin__vdsm_csg, a_light, "u_light"),
    STIN__UNIFORM(stin__vdsm_csg, a_camera, "u_camera"),
    STIN__UNIFORM(stin__vdsm_csg, a_viewport, "u_viewport"),
    STIN__UNIFORM(stin__vdsm_csg, a_grow, "u_grow"),
    STIN__UNIFORM(stin__vdsm_csg, a_caps, "u_caps"),
    STIN__UNIFORM(stin__vdsm_csg, a_position, "u_position"),
    STIN__UNIFORM(stin__vdsm_csg, a_normal, "u_normal"),
    STIN__UNIFORM(stin__vdsm_csg, a_primitive, "u_primitive"),
    STIN__UNIFORM(stin__vdsm_csg, a_mirrored, "u_mirrored"),
    STIN__UNIFORM(stin__vdsm_csg, a_frame, "u_frame"),
};

static const stin__uniform_name walk_uniforms[] = {
    STIN__UNIFORM(stin__vdsm_csg, w_terms, "u_terms"),
    STIN__UNIFORM(stin__vdsm_csg, w_light_inside, "u_light_inside"),
    STIN__UNIFORM(stin__vdsm_csg, w_frame, "u_frame"),
    STIN__UNIFORM(stin__vdsm_csg, w_clear, "u_clear"),
};

void stin__vdsm_csg_init(stin_context *ctx)
{
    stin__vdsm_csg *c = &ctx->vdsm->csg;
    stin__program_source src;
    char msg[160];
    stin__memzero(c, sizeof *c);
    if (!(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_COMPUTE)) ||
        ctx->sel.choice[STIN_FEATURE_CSG].technique == STIN_TECH_CSG_OFF)
        return;
    msg[0] = '\0';
    c->append_prog = stin__vdsm_polygon_program(ctx, "gl4/vdsm_csg_append.frag", 0, msg,
                                                sizeof msg);
    if (c->append_prog) {
        stin__memzero(&src, sizeof src);
        src.vert = "gl4/screen.vert";
        src.frag = "gl4/vdsm_csg_walk.frag";
        c->walk_prog = stin__program_build_source(ctx, &src, msg, sizeof msg);
    }
    if (!c->walk_prog) {
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "vdsm: the programs of CSG products' shadows failed to build (%s); products "
                  "cast no shadow", msg);
        stin__vdsm_csg_release(ctx);
        return;
    }
    STIN__LOCATE(ctx, c->append_prog, c, append_uniforms);
    STIN__LOCATE(ctx, c->walk_prog, c, walk_uniforms);
    stin__displace_locate(ctx, c->append_prog, 0, &c->displace);
    GL(ctx, GenBuffers)(3, c->buffers);
}

void stin__vdsm_csg_release(stin_context *ctx)
{
    stin__vdsm_csg *c = &ctx->vdsm->csg;
    GLuint none = 0;
    stin__vdsm_delete_programs(ctx, &c->append_prog, &c->walk_prog, &none);
    if (c->buffers[0])
        GL(ctx, DeleteBuffers)(3, c->buffers);
    c->buffers[0] = c->buffers[1] = c->buffers[2] = 0;
    c->pixels = c->capacity = 0;
    c->bytes = 0;
}

int stin__vdsm_csg_ready(const stin_context *ctx)
{
    return built(ctx);
}

/* A product this module can walk: at most 128 primitives (the walk's
 * 4 x 32 bits) and 64 terms (its term buffer). */
static int fits(const stin__caster_product *p)
{
    return p->primitive_count <= STIN__VDSM_CSG_MAX_PRIMITIVES &&
           p->term_count <= STIN__VDSM_CSG_MAX_TERMS;
}

int stin__vdsm_csg_walks_all(const stin_context *ctx)
{
    stin__caster_product p;
    uint32_t i;
    if (!built(ctx))
        return 0;
    for (i = 0; stin__casters_product(ctx, i, &p); i++)
        if (!fits(&p))
            return 0;
    return 1;
}

/* ---- the light's place: a ray's parity on the CPU ------------------------- */

/* The ray from o along dir against triangle (a, b, c): 1 hit at t > 0, 0
 * none, -1 too near an edge or a vertex to tell (another ray decides). */
static int ray_hits(const double o[3], const double dir[3], const double a[3], const double b[3],
                    const double c[3])
{
    const double edge = 1e-9;
    double e1[3], e2[3], pv[3], tv[3], qv[3], det, inv, u, v, t;
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = b[k] - a[k];
        e2[k] = c[k] - a[k];
        tv[k] = o[k] - a[k];
    }
    pv[0] = dir[1] * e2[2] - dir[2] * e2[1];
    pv[1] = dir[2] * e2[0] - dir[0] * e2[2];
    pv[2] = dir[0] * e2[1] - dir[1] * e2[0];
    det = e1[0] * pv[0] + e1[1] * pv[1] + e1[2] * pv[2];
    if (det == 0.0)
        return 0; /* parallel: a ray in the triangle's plane crosses its neighbours */
    inv = 1.0 / det;
    u = (tv[0] * pv[0] + tv[1] * pv[1] + tv[2] * pv[2]) * inv;
    qv[0] = tv[1] * e1[2] - tv[2] * e1[1];
    qv[1] = tv[2] * e1[0] - tv[0] * e1[2];
    qv[2] = tv[0] * e1[1] - tv[1] * e1[0];
    v = (dir[0] * qv[0] + dir[1] * qv[1] + dir[2] * qv[2]) * inv;
    t = (e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2]) * inv;
    if (u < -edge || v < -edge || u + v > 1.0 + edge || t <= 0.0)
        return 0;
    if (u < edge || v < edge || u + v > 1.0 - edge || t < 1e-12)
        return -1;
    return 1;
}

static void world_point(const float m[16], const float p[3], double out[3])
{
    int r;
    for (r = 0; r < 3; r++)
        out[r] = (double)m[r] * p[0] + (double)m[4 + r] * p[1] + (double)m[8 + r] * p[2] +
                 (double)m[12 + r];
}

/* Whether the point light at `light` lies inside closed primitive d: the
 * parity of a ray's crossings, a ray through an edge tried again along
 * another direction. */
static int light_inside(const stin_context *ctx, const stin__draw *d, const float light[4])
{
    static const double dirs[3][3] = {{0.5773, 0.5774, 0.5775},
                                      {-0.3141, 0.8660, 0.3891},
                                      {0.7071, -0.1234, -0.6963}};
    const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
    const stin__vertex *v = ctx->vertices + m->first_vertex;
    const uint32_t *tri = ctx->indices + 3u * m->first_triangle;
    double o[3] = {light[0], light[1], light[2]};
    int attempt;
    for (attempt = 0; attempt < 3; attempt++) {
        uint32_t i, crossings = 0;
        int sure = 1;
        for (i = 0; i < m->triangle_count && sure; i++) {
            double a[3], b[3], c[3];
            int hit;
            world_point(d->transform, v[tri[3 * i]].position, a);
            world_point(d->transform, v[tri[3 * i + 1]].position, b);
            world_point(d->transform, v[tri[3 * i + 2]].position, c);
            hit = ray_hits(o, dirs[attempt], a, b, c);
            sure = hit >= 0;
            crossings += hit > 0;
        }
        if (sure)
            return (int)(crossings & 1u);
    }
    return 0; /* three rays through edges: taken as outside */
}

/* ---- buffers ---------------------------------------------------------------- */

static void pool_data(stin_context *ctx, uint32_t capacity)
{
    stin__vdsm_csg *c = &ctx->vdsm->csg;
    GLuint header[4] = {0, 0, 0, 0};
    header[2] = capacity;
    GL(ctx, BindBuffer)(GL_SHADER_STORAGE_BUFFER, c->buffers[1]);
    GL(ctx, BufferData)(GL_SHADER_STORAGE_BUFFER,
                        (GLsizeiptr)(POOL_HEADER + (size_t)capacity * NODE_BYTES), NULL,
                        GL_DYNAMIC_COPY);
    GL(ctx, BufferSubData)(GL_SHADER_STORAGE_BUFFER, 0, (GLsizeiptr)sizeof header, header);
    c->capacity = capacity;
}

static void count_bytes(stin_context *ctx)
{
    stin__vdsm_csg *c = &ctx->vdsm->csg;
    c->bytes = (uint64_t)c->pixels * HEAD_BYTES + POOL_HEADER + (uint64_t)c->capacity * NODE_BYTES +
               2u * STIN__VDSM_CSG_MAX_TERMS * 16u;
}

/* The mask pass's state with colour writes off (channel < 0) or into one
 * channel of the mask. */
static void colour(stin_context *ctx, int channel)
{
    stin__pass_state ps = *stin__pass_current(ctx);
    ps.color_write = channel >= 0;
    ps.color_only = (unsigned char)(channel >= 0 ? channel + 1 : 0);
    stin__pass_apply(ctx, &ps);
}

/* The walk's empty lists everywhere in the viewport (after the heads were
 * made or a listing was abandoned). */
static void clear_lists(stin_context *ctx)
{
    stin__vdsm_csg *c = &ctx->vdsm->csg;
    colour(ctx, -1);
    GL(ctx, UseProgram)(c->walk_prog);
    GL(ctx, Uniform4iv)(c->w_frame, 1, ctx->frame.viewport);
    GL(ctx, Uniform1i)(c->w_clear, 1);
    stin__screen_quad(ctx);
    GL(ctx, MemoryBarrier)(GL_SHADER_STORAGE_BARRIER_BIT);
    ctx->stats.passes++;
}

/* Heads for the viewport's pixels and a pool of at least one node each;
 * 0 where the heads' bytes would overflow GL's sizes. */
static int buffers_ready(stin_context *ctx)
{
    stin__vdsm_csg *c = &ctx->vdsm->csg;
    const int *vp = ctx->frame.viewport;
    uint64_t pixels = (uint64_t)vp[2] * (uint64_t)vp[3];
    if (pixels == 0 || pixels > 0x3fffffffu / NODE_BYTES)
        return 0;
    if (pixels > c->pixels) {
        GL(ctx, BindBuffer)(GL_SHADER_STORAGE_BUFFER, c->buffers[0]);
        GL(ctx, BufferData)(GL_SHADER_STORAGE_BUFFER, (GLsizeiptr)(pixels * HEAD_BYTES), NULL,
                            GL_DYNAMIC_COPY);
        c->pixels = (uint32_t)pixels;
        c->cleared = 0;
    }
    if (c->capacity < c->pixels || c->capacity < MIN_NODES)
        pool_data(ctx, c->pixels > MIN_NODES ? c->pixels : MIN_NODES);
    if (!c->terms_made) {
        GL(ctx, BindBuffer)(GL_SHADER_STORAGE_BUFFER, c->buffers[2]);
        GL(ctx, BufferData)(GL_SHADER_STORAGE_BUFFER,
                            (GLsizeiptr)(2u * STIN__VDSM_CSG_MAX_TERMS * 16u), NULL,
                            GL_DYNAMIC_COPY);
        c->terms_made = 1;
    }
    GL(ctx, BindBuffer)(GL_SHADER_STORAGE_BUFFER, 0);
    count_bytes(ctx);
    return 1;
}

/* ---- the two passes ---------------------------------------------------------- */

/* Every primitive of p listed; returns the nodes the listing took. */
static uint32_t list_crossings(stin_context *ctx, const stin__caster_product *p,
                               const float light[4])
{
    stin__vdsm_csg *c = &ctx->vdsm->csg;
    const int *vp = ctx->frame.viewport;
    static const GLuint zero[1] = {0};
    float viewport[4];
    GLuint used = 0;
    uint32_t i;
    viewport[0] = (float)vp[0];
    viewport[1] = (float)vp[1];
    viewport[2] = (float)vp[2];
    viewport[3] = (float)vp[3];
    colour(ctx, -1);
    GL(ctx, BindBuffer)(GL_SHADER_STORAGE_BUFFER, c->buffers[1]);
    GL(ctx, BufferSubData)(GL_SHADER_STORAGE_BUFFER, 0, (GLsizeiptr)sizeof zero, zero);
    GL(ctx, UseProgram)(c->append_prog);
    GL(ctx, UniformMatrix4fv)(c->a_view_proj, 1, GL_FALSE, ctx->view_proj);
    GL(ctx, Uniform4fv)(c->a_light, 1, light);
    GL(ctx, Uniform4fv)(c->a_camera, 1, ctx->vdsm->camera);
    GL(ctx, Uniform4fv)(c->a_viewport, 1, viewport);
    GL(ctx, Uniform4iv)(c->a_frame, 1, vp);
    GL(ctx, Uniform1f)(c->a_grow,
                       ctx->desc.debug_flags & STIN_DEBUG_VDSM_NO_GROW ? 0.0f : 0.5f);
    /* every triangle: the walk needs both crossings of each primitive, and
     * a primitive is not in the depth buffer where the product leaves it out */
    GL(ctx, Uniform1i)(c->a_caps, 1);
    GL(ctx, Uniform1i)(c->a_position, 0);
    GL(ctx, Uniform1i)(c->a_normal, 1);
    for (i = 0; i < p->primitive_count; i++) {
        const stin__draw *d = &p->primitives[i];
        GL(ctx, Uniform1i)(c->a_primitive, (GLint)i);
        GL(ctx, Uniform1i)(c->a_mirrored, stin__mat4_det(d->transform) < 0.0);
        stin__glsl_submit_geometry(ctx, c->a_model, &c->displace, d);
    }
    ctx->stats.passes++;
    GL(ctx, MemoryBarrier)(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    GL(ctx, GetBufferSubData)(GL_SHADER_STORAGE_BUFFER, 0, (GLsizeiptr)sizeof used, &used);
    return used;
}

static void walk(stin_context *ctx, const stin__caster_product *p, const float light[4],
                 int channel)
{
    stin__vdsm_csg *c = &ctx->vdsm->csg;
    GLuint masks[2 * STIN__VDSM_CSG_MAX_TERMS][4], inside[4] = {0, 0, 0, 0};
    uint32_t ti, li, count;
    stin__memzero(masks, sizeof masks);
    for (ti = 0; ti < p->term_count; ti++) {
        const uint32_t *literals = stin__casters_term(ctx, p, ti, &count);
        for (li = 0; li < count; li++) {
            uint32_t lit = literals[li], k = STIN__CSG_PRIMITIVE_OF(lit);
            masks[2 * ti + STIN__CSG_COMPLEMENTED(lit)][k >> 5] |= 1u << (k & 31u);
        }
    }
    if (light[3] != 0.0f)
        for (li = 0; li < p->primitive_count; li++)
            if (light_inside(ctx, &p->primitives[li], light))
                inside[li >> 5] |= 1u << (li & 31u);
    GL(ctx, BindBuffer)(GL_SHADER_STORAGE_BUFFER, c->buffers[2]);
    GL(ctx, BufferSubData)(GL_SHADER_STORAGE_BUFFER, 0,
                           (GLsizeiptr)(2u * p->term_count * sizeof masks[0]), masks);
    GL(ctx, UseProgram)(c->walk_prog);
    GL(ctx, Uniform1i)(c->w_terms, (GLint)p->term_count);
    GL(ctx, Uniform4uiv)(c->w_light_inside, 1, inside);
    GL(ctx, Uniform4iv)(c->w_frame, 1, ctx->frame.viewport);
    GL(ctx, Uniform1i)(c->w_clear, 0);
    colour(ctx, channel);
    stin__screen_quad(ctx);
    GL(ctx, MemoryBarrier)(GL_SHADER_STORAGE_BARRIER_BIT);
    ctx->stats.passes++;
}

static void bind_buffers(stin_context *ctx, int on)
{
    const stin__vdsm_csg *c = &ctx->vdsm->csg;
    GLuint i;
    for (i = 0; i < 3; i++)
        GL(ctx, BindBufferBase)(GL_SHADER_STORAGE_BUFFER, i, on ? c->buffers[i] : 0);
    if (!on)
        GL(ctx, BindBuffer)(GL_SHADER_STORAGE_BUFFER, 0);
}

void stin__vdsm_csg_cast(stin_context *ctx, const float light[4], int channel)
{
    stin__vdsm_csg *c = &ctx->vdsm->csg;
    stin__caster_product product, *p = &product;
    uint32_t pi;
    if (!built(ctx) || !stin__casters_wanted(ctx) || !buffers_ready(ctx))
        return;
    bind_buffers(ctx, 1);
    if (!c->cleared) {
        clear_lists(ctx);
        c->cleared = 1;
    }
    for (pi = 0; stin__casters_product(ctx, pi, p); pi++) {
        uint32_t used;
        if (!fits(p)) {
            if (!c->said_limits)
                stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                          "vdsm: a CSG product of %u primitives and %u terms is past the "
                          "walk's limits (%u and %u): the products cast through a depth map",
                          p->primitive_count, p->term_count,
                          STIN__VDSM_CSG_MAX_PRIMITIVES, STIN__VDSM_CSG_MAX_TERMS);
            c->said_limits = 1;
            continue;
        }
        used = list_crossings(ctx, p, light);
        if (used > c->capacity) { /* the pool ran out: grown, listed again */
            clear_lists(ctx);
            pool_data(ctx, used + used / 4u);
            count_bytes(ctx);
            used = list_crossings(ctx, p, light);
        }
        if (used > c->capacity) { /* still short: a second listing found more */
            if (!c->said_pool)
                stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                          "vdsm: a CSG product's second listing took %u crossings, more than "
                          "the %u its first grew the pool to; it casts no shadow this frame",
                          used, c->capacity);
            c->said_pool = 1;
            clear_lists(ctx);
            continue;
        }
        walk(ctx, p, light, channel);
        ctx->stats.shadows.vdsm_csg_casts++;
    }
    bind_buffers(ctx, 0);
    ctx->stats.shadows.vdsm_csg_bytes = c->bytes;
}
