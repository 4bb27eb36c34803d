/* SPDX-License-Identifier: MIT */
/* The terminator rule under stencil volumes (stin.h, Volumes): after a
 * light sample's volumes are counted, each smooth opaque caster's
 * terminator band (facet turned away from the light, shading normal toward
 * it; the path's terminator_band keeps only those fragments) takes back
 * the count its own mesh's volume gives it for the facets' steps.
 *
 * Closed meshes: the ray from a band pixel P runs into the mesh and leaves
 * it once more than it enters, so the classic volume counts it exactly
 * once: one decrement.
 *
 * Open meshes (every triangle its own volume, volume_geometry.c): P's own
 * averted facet counts once (P lies on its light cap), and each triangle of
 * the mesh the segment from P to the light crosses once more. The curved
 * surface the rule starts from lies above the facets, so its ray misses
 * the light-facing neighbours through which P's ray leaves the mesh; but
 * near the mesh's open edge P's ray may leave through the hole and cross
 * none, and taking a second count back there would light a pixel another
 * caster shadows. So the band takes back its own facet's count, and one
 * more only where P lies inside the volume of one of the light-facing
 * triangles around the band (the ring: those sharing a corner with a band
 * triangle or with one of its edge neighbours): that parity is counted
 * per pixel into one stencil bit by the ring's own volumes (z-fail,
 * GL_INVERT, no order to keep), the band decrements where it is set, and
 * the ring's volumes drawn again clear it. The ring's triangles lie side by
 * side seen from the light, so an odd parity means P's ray crosses one of
 * them: a count the band holds. A ray that leaves beyond the ring keeps
 * that count (the facet's step, never a wrongly lit pixel). */
#include "shadow/volume_private.h"
#include "render/draw_bounds.h"

#define NO_TRI 0xffffffffu
#define PARITY_BIT 0x40u /* the ring's parity; counts stay below it */
#define COUNT_BITS 0x3fu
#define RING_CHUNK 128u /* ring triangles a volume build takes at once */

/* Whether triangle tri may hold band fragments for the object-space light
 * l: some corner's normal turned otherwise than the facet, seen from a
 * corner (the interpolated normal's dot with the way to the light is
 * linear across the triangle, so its extremes lie at the corners). */
static int in_band(const stin__vertex *v, const uint32_t *tri, const float l[4])
{
    const float *a = v[tri[0]].position, *b = v[tri[1]].position, *c = v[tri[2]].position;
    float e1[3], e2[3], f[3], d[3][3], facet = 0.0f;
    int j, k, i;
    for (k = 0; k < 3; k++) {
        e1[k] = b[k] - a[k];
        e2[k] = c[k] - a[k];
        for (j = 0; j < 3; j++)
            d[j][k] = l[k] - l[3] * v[tri[j]].position[k];
    }
    f[0] = e1[1] * e2[2] - e1[2] * e2[1];
    f[1] = e1[2] * e2[0] - e1[0] * e2[2];
    f[2] = e1[0] * e2[1] - e1[1] * e2[0];
    for (k = 0; k < 3; k++)
        facet += f[k] * d[0][k];
    for (j = 0; j < 3; j++)
        for (i = 0; i < 3; i++) {
            const float *n = v[tri[i]].normal;
            float s = n[0] * d[j][0] + n[1] * d[j][1] + n[2] * d[j][2];
            if ((facet > 0.0f) != (s > 0.0f))
                return 1;
        }
    return 0;
}

/* One draw's band for one light: its mesh, the light in object space, and
 * the frame scratch carved for the open rule. */
typedef struct band {
    const stin__mesh_slot *m;
    const stin__vertex *v;
    const uint32_t *tris, *adjacency;
    float l[4];
    unsigned char *corner;  /* a bit per vertex: the ring's corners */
    uint32_t *list;         /* the band's triangles (3 indices each) */
    uint32_t count, room;   /* listed, and room for */
} band;

static int band_open(band *b, stin_context *ctx, const stin__draw *d, const float light_world[4])
{
    float inv[16];
    int k;
    b->m = &ctx->meshes[d->mesh_slot];
    b->v = ctx->vertices + b->m->first_vertex;
    b->tris = ctx->indices + 3u * b->m->first_triangle;
    b->adjacency = ctx->adjacency + 3u * b->m->first_triangle;
    if (!stin__mat4_invert(inv, d->transform))
        return 0;
    for (k = 0; k < 4; k++)
        b->l[k] = inv[k] * light_world[0] + inv[4 + k] * light_world[1] +
                  inv[8 + k] * light_world[2] + inv[12 + k] * light_world[3];
    return 1;
}

/* d's triangles that may hold band fragments, in chunks of frame scratch
 * (the closed rule: one decrement, nothing kept). */
static void draw_band_chunks(stin_context *ctx, const stin__path *path, const stin__draw *d,
                             const float light_world[4])
{
    band b;
    uint32_t *out = (uint32_t *)(void *)ctx->frame_scratch, t, n = 0;
    uint32_t room = (uint32_t)(ctx->frame_scratch_bytes / (3u * sizeof *out));
    int k;
    if (!band_open(&b, ctx, d, light_world) || room == 0)
        return;
    for (t = 0; t < b.m->triangle_count; t++) {
        if (!in_band(b.v, b.tris + 3u * t, b.l))
            continue;
        for (k = 0; k < 3; k++)
            out[3u * n + (uint32_t)k] = b.tris[3u * t + (uint32_t)k];
        if (++n == room) {
            path->terminator_band(ctx, d, light_world, out, n);
            n = 0;
        }
    }
    if (n)
        path->terminator_band(ctx, d, light_world, out, n);
}

static void mark(unsigned char *bits, uint32_t vertex) { bits[vertex >> 3] |= (unsigned char)(1u << (vertex & 7u)); }
static int marked(const unsigned char *bits, uint32_t vertex) { return bits[vertex >> 3] >> (vertex & 7u) & 1; }

/* The open rule's list of band triangles and the ring's corners: the band
 * triangles' and their edge neighbours' (a seam's split vertices share no
 * index, its edges do), in frame scratch. 0 where the scratch cannot hold
 * them (the caller keeps the facet's step past the own count). */
static int band_list(band *b, stin_context *ctx)
{
    uint32_t vertices = b->m->vertex_count, bits = stin__align16((vertices + 7u) / 8u), t, i;
    size_t left;
    int k;
    if (bits > ctx->frame_scratch_bytes)
        return 0;
    b->corner = ctx->frame_scratch;
    stin__memzero(b->corner, bits);
    b->list = (uint32_t *)(void *)(ctx->frame_scratch + bits);
    left = ctx->frame_scratch_bytes - bits;
    b->room = (uint32_t)(left / (3u * sizeof(uint32_t)));
    b->count = 0;
    for (t = 0; t < b->m->triangle_count; t++) {
        const uint32_t *tri = b->tris + 3u * t;
        if (!in_band(b->v, tri, b->l))
            continue;
        if (b->count == b->room)
            return 0;
        for (k = 0; k < 3; k++) {
            uint32_t n = b->adjacency[3u * t + (uint32_t)k];
            b->list[3u * b->count + (uint32_t)k] = tri[k];
            mark(b->corner, tri[k]);
            if (n != NO_TRI)
                for (i = 0; i < 3; i++)
                    mark(b->corner, b->tris[3u * n + i]);
        }
        b->count++;
    }
    return 1;
}

/* The ring's volumes (z-fail, caps, every side: a side two ring triangles
 * share is drawn twice and cancels in the parity), cut where d's volume is.
 * 0 where the scratch past the band's list cannot hold a chunk. */
static int draw_ring(stin_context *ctx, const stin__path *path, const stin__draw *d,
                     const band *b, const float far_object[4])
{
    unsigned char *free_at = (unsigned char *)(b->list + 3u * b->count);
    size_t used = (size_t)(free_at - ctx->frame_scratch), need;
    uint32_t *chunk, *no_neighbours, t, n = 0, i;
    stin__volume_request r;
    stin__volume_sink_state st;
    used = stin__align16(used);
    need = used + 2u * 12u * RING_CHUNK + RING_CHUNK + 16u * 24u;
    if (need > ctx->frame_scratch_bytes)
        return 0;
    chunk = (uint32_t *)(void *)(ctx->frame_scratch + used);
    no_neighbours = chunk + 3u * RING_CHUNK;
    for (i = 0; i < 3u * RING_CHUNK; i++)
        no_neighbours[i] = NO_TRI;
    stin__memzero(&r, sizeof r);
    r.verts = b->v;
    r.tris = chunk;
    r.adjacency = no_neighbours;
    r.closed = 0;
    r.caps = 1;
    for (i = 0; i < 4; i++) {
        r.light[i] = b->l[i];
        r.far_plane[i] = far_object[i];
    }
    r.facing = (unsigned char *)(no_neighbours + 3u * RING_CHUNK);
    r.buffer = (float *)(void *)(ctx->frame_scratch + stin__align16(used + 2u * 12u * RING_CHUNK +
                                                                     RING_CHUNK));
    r.buffer_vertices = (uint32_t)((ctx->frame_scratch_bytes - (size_t)((unsigned char *)r.buffer -
                                                                      ctx->frame_scratch)) /
                                   16u);
    r.buffer_vertices -= r.buffer_vertices % 3u;
    st.ctx = ctx;
    st.path = path;
    st.model = d->transform;
    r.sink = stin__volume_sink_draw;
    r.user = &st;
    path->volume_begin(ctx);
    for (t = 0; t <= b->m->triangle_count; t++) {
        const uint32_t *tri = b->tris + 3u * t;
        if (t < b->m->triangle_count) {
            if (!(marked(b->corner, tri[0]) || marked(b->corner, tri[1]) ||
                  marked(b->corner, tri[2])) ||
                !stin__triangle_faces_light(b->v[tri[0]].position, b->v[tri[1]].position,
                                            b->v[tri[2]].position, b->l))
                continue;
            for (i = 0; i < 3; i++)
                chunk[3u * n + i] = tri[i];
            n++;
        }
        if (n && (n == RING_CHUNK || t == b->m->triangle_count)) {
            r.tri_count = n;
            ctx->stats.shadows.volume_triangles += stin__volume_build(&r);
            n = 0;
        }
    }
    path->volume_end(ctx);
    return 1;
}

/* Where d's volume is cut (volume.c's caster_reach, without its stats), in
 * object space: the ring's volumes must reach as far behind P. */
static void far_plane_of(const stin_context *ctx, const stin__draw *d,
                         const stin__volume_reach *reach, float out[4])
{
    static const float infinity[4] = {0.0f, 0.0f, 0.0f, -1.0f};
    float corners[24], world[4];
    int k;
    for (k = 0; k < 4; k++)
        world[k] = infinity[k];
    if (stin__draw_world_corners(ctx, d, corners) &&
        !stin__volume_reach_caster(reach, corners, world))
        for (k = 0; k < 4; k++)
            world[k] = infinity[k];
    stin__volume_plane_to_object(world, d->transform, out);
}

/* The band's decrement where the stencil passes func (ref, mask), writing
 * write_mask's bits. */
static void band_pass(stin_context *ctx, stin__pass_state *ps, GLenum func, GLuint ref,
                      GLuint mask, GLuint write_mask)
{
    ps->depth_func = GL_EQUAL;
    ps->depth_clamp = 0;
    ps->front.func = func;
    ps->front.ref = (GLint)ref;
    ps->front.mask = mask;
    ps->front.fail = ps->front.zfail = GL_KEEP;
    ps->front.zpass = GL_DECR;
    ps->stencil_write_mask = write_mask;
    stin__pass_apply(ctx, ps);
}

static void parity_pass(stin_context *ctx, stin__pass_state *ps)
{
    ps->depth_func = GL_LESS;
    ps->depth_clamp = (unsigned char)ctx->volume->depth_clamp;
    ps->front.func = GL_ALWAYS;
    ps->front.ref = 0;
    ps->front.mask = 0xffffffffu;
    ps->front.fail = ps->front.zpass = GL_KEEP;
    ps->front.zfail = GL_INVERT;
    ps->stencil_write_mask = PARITY_BIT;
    stin__pass_apply(ctx, ps);
}

/* The open rule for one draw (the header's comment); 0 where the scratch
 * could not hold it: the caller takes back the own facet's count alone. */
static int open_band(stin_context *ctx, const stin__path *path, const stin__draw *d,
                     const float light_world[4], const stin__volume_reach *reach,
                     stin__pass_state *ps)
{
    band b;
    float far_object[4];
    if (!band_open(&b, ctx, d, light_world) || !band_list(&b, ctx))
        return 0;
    if (!b.count)
        return 1;
    band_pass(ctx, ps, GL_ALWAYS, 0, 0xffffffffu, 0xffffffffu); /* the own facet's count */
    path->terminator_band(ctx, d, light_world, b.list, b.count);
    if (ctx->caps.stencil_bits < 8)
        return 1; /* no bit to spare: the facet's step past the own count */
    far_plane_of(ctx, d, reach, far_object);
    parity_pass(ctx, ps);
    if (!draw_ring(ctx, path, d, &b, far_object))
        return 1;
    /* the ray's way out: where the parity is odd and a count is left (a
     * pixel the ring's volume rounds otherwise than the count's is kept) */
    band_pass(ctx, ps, GL_LESS, PARITY_BIT, PARITY_BIT | COUNT_BITS, COUNT_BITS);
    path->terminator_band(ctx, d, light_world, b.list, b.count);
    parity_pass(ctx, ps);
    (void)draw_ring(ctx, path, d, &b, far_object);
    return 1;
}

void stin__volume_take_back_band(stin_context *ctx, const stin__path *path,
                                 const float light_world[4], const stin__volume_reach *reach)
{
    stin__pass_state ps = *stin__pass_current(ctx);
    GLuint write_mask = ps.stencil_write_mask;
    uint32_t i;
    if (ctx->desc.debug_flags & STIN_DEBUG_VOLUME_FACETS)
        return;
    ps.two_sided = 0;
    ps.cull = 0;
    ps.front_face = GL_CCW;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
        if (!d->shadow_caster || d->csg || d->material.color[3] < 1.0f ||
            stin__cast_map_casts(ctx, d) || !m->smooth)
            continue;
        if (m->info.closed_manifold || !open_band(ctx, path, d, light_world, reach, &ps)) {
            band_pass(ctx, &ps, GL_ALWAYS, 0, 0xffffffffu, 0xffffffffu);
            draw_band_chunks(ctx, path, d, light_world);
        }
    }
    ps.depth_func = GL_LESS;
    ps.stencil_write_mask = write_mask;
    stin__pass_apply(ctx, &ps);
}
