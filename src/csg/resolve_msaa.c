/* SPDX-License-Identifier: MIT */
/* The read-back resolve (GL1 tiers) into a multisampled framebuffer object.
 * glReadPixels cannot read a multisampled depth or stencil, so the frame's
 * depth and stencil are resolved by one blit into the GPU resolve's work
 * framebuffer (single-sampled, csg/merge.c), where the resolve runs and
 * reads back as into a single-sampled frame. Its result is one depth a
 * pixel, at the pixel centre; written so into the frame, the samples of a
 * face that does not cover the centre would miss it (lines along the faces'
 * edges: what STIN_DEBUG_CSG_SNAP_AT_CENTRE does). Instead each sample takes
 * its own face's depth, the products' faces drawn into the frame and kept
 * within a band about the result: [lo, hi] a pixel, the result with 8 steps
 * of a 24-bit depth and twice the result's depth change to the next pixel
 * (where the surface runs on: a face covering a sample is at most a pixel
 * from the centre's), and beside the product's outline the band of its
 * neighbouring pixels (antialiased silhouettes). In fixed function, with
 * the bounds in the depth buffer by a quad a pixel at its depth (stencil bit 0: the band's
 * pixels, set where lo went in):
 *   1. depth = lo; the faces, depth GEQUAL with writes: the farthest face
 *      at or behind lo (a nearer face the resolve took away, such as the
 *      box's front over a hole, stays out);
 *   2. where that lies behind hi (bit 1): depth = hi, the faces depth
 *      LEQUAL: the nearest at or before hi (a farther face of the product,
 *      such as a hole's wall behind the box's front, stays out);
 *   3. where no face lies within the band (bit 2: depth still at or beyond
 *      a bound), the depth the frame held, and the stencil cleared.
 * Needs framebuffer objects, packed depth-stencil and depth textures (the
 * work framebuffer), a blit (GL 3.0, ARB_framebuffer_object or
 * EXT_framebuffer_blit) and glDrawPixels (a compatibility context), and
 * 13 bytes of staging a pixel (the CPU resolve's 9 and the frame's depth). */
#include "csg/csg_private.h"

#define READ_FRAMEBUFFER 0x8CA8
#define DRAW_FRAMEBUFFER 0x8CA9
#define GL_QUADS 0x0007
/* 8 steps of a 24-bit depth buffer (as the GPU resolve's snap band). */
#define BAND (1.0f / 2097152.0f)
/* Pixels of the result's depth change a face's sample may lie from it. */
#define SLOPE 2.0f

typedef stin__csg_pixels resolve;

int stin__csg_msaa_readback_ready(const stin_context *ctx)
{
    const uint64_t need = STIN_CAP_BIT(STIN_CAP_FBO) | STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE) |
                          STIN_CAP_BIT(STIN_CAP_PACKED_DEPTH_STENCIL) |
                          STIN_CAP_BIT(STIN_CAP_FIXED_FUNCTION);
    return (ctx->caps.present & need) == need && ctx->target.separate_read &&
           ctx->gl.BlitFramebuffer && !ctx->caps.es;
}

/* Whether pixel i holds a product's surface (nearer than the frame held). */
static int has(const resolve *r, const float *held, size_t i)
{
    return r->result[i] < held[i];
}

/* The result's depth change a pixel along one axis at i (the smaller of
 * its two sides where both hold a product: a step at an edge is not the
 * surface's slope). */
static float slope_along(const resolve *r, const float *held, size_t i, int at, int size,
                         size_t step)
{
    float d = r->result[i], a = -1.0f, b = -1.0f;
    if (at > 0 && has(r, held, i - step))
        a = d > r->result[i - step] ? d - r->result[i - step] : r->result[i - step] - d;
    if (at + 1 < size && has(r, held, i + step))
        b = d > r->result[i + step] ? d - r->result[i + step] : r->result[i + step] - d;
    if (a < 0.0f)
        return b < 0.0f ? 0.0f : b;
    return b < 0.0f || a < b ? a : b;
}

static float reach(const resolve *r, const float *held, size_t i, int x, int y)
{
    return BAND + SLOPE * (slope_along(r, held, i, x, r->w, 1) +
                           slope_along(r, held, i, y, r->h, (size_t)r->w));
}

/* Bound `far` (0: lo, 1: hi) of every pixel into out: a product's pixel's
 * own band, else its neighbours' (the product's outline), else 1 (depth
 * LESS keeps it out). */
static void bounds(resolve *r, const float *held, int far, float *out)
{
    int x, y, dx, dy;
    for (y = 0; y < r->h; y++)
        for (x = 0; x < r->w; x++) {
            size_t i = (size_t)y * (size_t)r->w + (size_t)x;
            float v = far ? -1.0f : 2.0f;
            for (dy = -1; dy <= 1; dy++)
                for (dx = -1; dx <= 1; dx++) {
                    int nx = x + dx, ny = y + dy;
                    size_t j = (size_t)ny * (size_t)r->w + (size_t)nx;
                    float e;
                    if (nx < 0 || ny < 0 || nx >= r->w || ny >= r->h || !has(r, held, j))
                        continue;
                    if (has(r, held, i) && j != i)
                        continue; /* a product's pixel keeps to its own surface */
                    e = reach(r, held, j, nx, ny);
                    e = far ? r->result[j] + e : r->result[j] - e;
                    v = far ? (e > v ? e : v) : (e < v ? e : v);
                }
            r->stencil[i] = (unsigned char)!(v < -0.5f || v > 1.5f);
            out[i] = !r->stencil[i] ? 1.0f : v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v;
        }
}

/* A pass state: depth func (write: whether it writes), stencil test
 * (value & mask) == want, and where it passes the stencil bits `set`. */
static stin__pass_state step(GLenum func, int write, unsigned want, unsigned mask, unsigned set)
{
    stin__pass_state ps = stin__pass_defaults;
    ps.depth_test = 1;
    ps.depth_func = func;
    ps.depth_write = (unsigned char)write;
    ps.color_write = 0;
    ps.stencil_test = 1;
    ps.front.func = mask ? GL_EQUAL : GL_ALWAYS;
    ps.front.ref = (GLint)(want | set);
    ps.front.mask = mask;
    ps.front.fail = ps.front.zfail = GL_KEEP;
    ps.front.zpass = set ? GL_REPLACE : GL_KEEP;
    ps.stencil_write_mask = set;
    ps.back = ps.front;
    return ps;
}

/* Every face of the frame's products under ps (its cull per face). */
static void faces(stin_context *ctx, const stin__path *path, stin__pass_state ps)
{
    uint32_t i, n;
    const stin__draw *d = stin__csg_face_list(ctx, &n);
    path->geometry_begin(ctx);
    for (i = 0; i < n; i++) {
        ps.cull = 1;
        ps.cull_face = stin__csg_face_hidden(&d[i]);
        stin__pass_apply(ctx, &ps);
        path->geometry(ctx, &d[i]);
    }
    path->geometry_end(ctx);
    ctx->stats.passes++;
}

/* values into every sample of the band's pixels (marked) under ps: a
 * quad a pixel at its depth (glDrawPixels writes one sample a pixel into a
 * multisampled buffer on some drivers: Mesa's llvmpipe). */
static void depth_pixels(stin_context *ctx, const stin__path *path, const resolve *r,
                         const float *values, stin__pass_state ps)
{
    const unsigned char *marked = r->stencil;
    float sx = 2.0f / (float)r->w, sy = 2.0f / (float)r->h, v[3];
    int x, y;
    stin__pass_apply(ctx, &ps);
    stin__csg_identity_begin(ctx, path);
    GL(ctx, Begin)(GL_QUADS);
    for (y = 0; y < r->h; y++)
        for (x = 0; x < r->w; x++) {
            size_t i = (size_t)y * (size_t)r->w + (size_t)x;
            if (!marked[i])
                continue;
            v[2] = 2.0f * values[i] - 1.0f;
            v[0] = (float)x * sx - 1.0f;
            v[1] = (float)y * sy - 1.0f;
            GL(ctx, Vertex3fv)(v);
            v[0] += sx;
            GL(ctx, Vertex3fv)(v);
            v[1] += sy;
            GL(ctx, Vertex3fv)(v);
            v[0] -= sx;
            GL(ctx, Vertex3fv)(v);
        }
    GL(ctx, End)();
    stin__csg_identity_end(ctx, path);
    ctx->stats.passes++;
}

/* The products' faces into the frame on the result (see the top). */
static void faces_on_result(stin_context *ctx, const stin__path *path, resolve *r,
                            const float *held)
{
    float *band = r->candidate; /* free once the resolve is done */
    bounds(r, held, 0, band);
    depth_pixels(ctx, path, r, band, step(GL_LESS, 1, 0, 0, 1));
    faces(ctx, path, step(GL_GEQUAL, 1, 1, 1, 0));
    bounds(r, held, 1, band);
    depth_pixels(ctx, path, r, band, step(GL_LESS, 0, 1, 1, 2));
    depth_pixels(ctx, path, r, band, step(GL_ALWAYS, 1, 3, 3, 0));
    faces(ctx, path, step(GL_LEQUAL, 1, 3, 3, 0));
    depth_pixels(ctx, path, r, band, step(GL_LEQUAL, 0, 1, 1, 4));
    bounds(r, held, 0, band);
    depth_pixels(ctx, path, r, band, step(GL_GEQUAL, 0, 1, 1, 4));
    depth_pixels(ctx, path, r, held, step(GL_ALWAYS, 1, 5, 5, 0));
}

/* STIN_DEBUG_CSG_SNAP_AT_CENTRE: the result written one depth a pixel
 * (the single-sampled resolve's write): its faces' samples off the centre
 * miss it. */
static void at_centre(stin_context *ctx, const stin__path *path, resolve *r, const float *held)
{
    size_t i;
    for (i = 0; i < r->pixels; i++)
        r->stencil[i] = (unsigned char)has(r, held, i);
    depth_pixels(ctx, path, r, r->result, step(GL_ALWAYS, 1, 0, 0, 0));
}

int stin__csg_msaa_resolve(stin_context *ctx, const stin__path *path, resolve *r)
{
    stin__csg_state *c = ctx->csg;
    stin__unpack_saved saved;
    GLuint work;
    float *held = stin__csg_pixels_held(ctx, r);
    const int *vp = ctx->frame.viewport;
    if (!stin__csg_msaa_readback_ready(ctx) || !held || !stin__csg_merge_targets(ctx)) {
        if (!c->said_unusable)
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                      "CSG products are not drawn: the multisampled read-back resolve needs "
                      "13 bytes of texture staging a pixel and its work framebuffer");
        c->said_unusable = 1;
        return 0;
    }
    work = c->merge.fbo[STIN__CSG_MERGE_WORK];
    /* the frame's depth and stencil, one sample a pixel, into the work buffers */
    stin__pass_apply(ctx, &stin__pass_defaults); /* a blit keeps to the scissor */
    GL(ctx, BindFramebuffer)(READ_FRAMEBUFFER, ctx->draw_fbo);
    GL(ctx, BindFramebuffer)(DRAW_FRAMEBUFFER, work);
    GL(ctx, BlitFramebuffer)(vp[0], vp[1], vp[0] + vp[2], vp[1] + vp[3], vp[0], vp[1],
                             vp[0] + vp[2], vp[1] + vp[3],
                             GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, work);
    c->resolve_fbo = work;
    stin__pack_begin(ctx, &saved);
    stin__csg_region_reset(ctx);
    stin__csg_read_depth(ctx, r, held);
    stin__pack_end(ctx, &saved);
    stin__csg_resolve_pixels(ctx, path, r);
    c->resolve_fbo = ctx->draw_fbo;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    stin__csg_region_reset(ctx);
    c->resolved = 1;
    stin__csg_faces(ctx);
    if (ctx->desc.debug_flags & STIN_DEBUG_CSG_SNAP_AT_CENTRE)
        at_centre(ctx, path, r, held); /* one depth a pixel: must fail */
    else
        faces_on_result(ctx, path, r, held);
    stin__csg_clear(ctx, GL_STENCIL_BUFFER_BIT);
    return 1;
}
