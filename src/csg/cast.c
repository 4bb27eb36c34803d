/* SPDX-License-Identifier: MIT */
/* CSG products casting shadows into the map techniques' maps. A product's
 * surface seen from a light is what the camera's resolve finds, with the
 * light's camera: the same scs, interval or goldfeather passes
 * (csg/goldfeather.c), run over the rectangle of the map the products'
 * bounding boxes cover (the projection cropped to it, so the CPU copies
 * are as small as the products' shadow and not the whole map), in bands of
 * rows where the staging holds less. It runs where the map is drawn when
 * that framebuffer has a stencil buffer (the GL1 maps drawn in the frame's
 * own), else in a depth-stencil framebuffer of its own (packed
 * depth-stencil), and goes into the map's depth with depth LESS before the
 * ordinary casters, so the nearest of both stays. The light's slope-scaled
 * offset, which the ordinary casters get from glPolygonOffset, is added on
 * the CPU: per axis the flatter of the two one-sided depth differences (so
 * a product's silhouette does not count as slope), the steeper axis,
 * times factor, plus units times the map's depth step (glPolygonOffset's r:
 * stin__rt_depth_unit). The CPU copies follow the camera's
 * in the staging, so a point light's faces, drawn mid-frame, leave the
 * camera's resolve intact. Without depth read-back (OpenGL ES without
 * GL_NV_read_depth_stencil: WebGL 2, es20-ext) the rectangle is resolved
 * on the GPU alone instead, in one go: csg/merge.c's direct resolve in the
 * cast's own depth-stencil framebuffer, each candidate's faces drawn into
 * the map on its depth, depth LESS, with the light's glPolygonOffset as
 * the ordinary casters get it (the snap's band widened by that offset,
 * which gl_FragCoord.z carries: on llvmpipe without the widening the
 * sloped faces fell outside the band and cast nothing). Nothing is kept
 * for cast_again (the GL1 maps', which never run there), interval's walk
 * is no one face set to snap (it casts nothing there, logged), and the
 * packed resolve (bare ES 2.0) has no depth texture to resolve in. The
 * camera's resolve is left alone: its result texture and work buffer are
 * not touched. */
#include "csg/csg_private.h"

/* A light's map resolve, kept for the passes that draw the products'
 * surface into the same map again (map-combine's ramp, map-depth's side
 * test): its pixels (result unbiased, candidate biased) and camera. */
typedef struct stin__csg_cast_state {
    GLuint fbo, depth_stencil; /* where a map without stencil resolves (0: none yet) */
    int size;                 /* the renderbuffer's side */
    int valid;                /* the last map's cast drew products */
    int kept;                 /* in one band: pixels below hold its whole resolve */
    int rect[4];              /* the map's rectangle under the products */
    stin__csg_pixels pixels;
    float view[16], projection[16]; /* the light's, the projection cropped to the pixels */
    float light_projection[16];       /* the light's, uncropped */
    int said_room, said_no_target, said_technique;
} stin__csg_cast_state;

size_t stin__csg_cast_state_bytes(void) { return sizeof(stin__csg_cast_state); }


typedef struct camera_saved {
    float view[16], projection[16], view_proj[16], cap_transform[16];
    int viewport[4], cap_usable;
} camera_saved;

static void camera_save(const stin_context *ctx, camera_saved *s)
{
    stin__memcopy(s->view, ctx->frame.view, sizeof s->view);
    stin__memcopy(s->projection, ctx->projection, sizeof s->projection);
    stin__memcopy(s->view_proj, ctx->view_proj, sizeof s->view_proj);
    stin__memcopy(s->cap_transform, ctx->csg->cap_transform, sizeof s->cap_transform);
    stin__memcopy(s->viewport, ctx->frame.viewport, sizeof s->viewport);
    s->cap_usable = ctx->csg->cap_usable;
}

static void camera_restore(stin_context *ctx, const camera_saved *s)
{
    stin__memcopy(ctx->frame.view, s->view, sizeof s->view);
    stin__memcopy(ctx->projection, s->projection, sizeof s->projection);
    stin__memcopy(ctx->view_proj, s->view_proj, sizeof s->view_proj);
    stin__memcopy(ctx->csg->cap_transform, s->cap_transform, sizeof s->cap_transform);
    stin__memcopy(ctx->frame.viewport, s->viewport, sizeof s->viewport);
    ctx->csg->cap_usable = s->cap_usable;
}

/* The frame's camera becomes the light's, its projection cropped so that
 * the rectangle (x, y, w, h) of the map's viewport map_vp fills the
 * viewport: every vertex lands on the pixel it has in the whole map. */
static void camera_light(stin_context *ctx, const float view[16], const float proj[16],
                         const int map_vp[4], const int rect[4])
{
    float crop[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    float sx = (float)map_vp[2] / (float)rect[2], sy = (float)map_vp[3] / (float)rect[3];
    float ax = -1.0f + 2.0f * (float)(rect[0] - map_vp[0]) / (float)map_vp[2];
    float ay = -1.0f + 2.0f * (float)(rect[1] - map_vp[1]) / (float)map_vp[3];
    crop[0] = sx;
    crop[5] = sy;
    crop[12] = -sx * ax - 1.0f;
    crop[13] = -sy * ay - 1.0f;
    stin__memcopy(ctx->frame.view, view, sizeof ctx->frame.view);
    stin__mat4_mul(ctx->projection, crop, proj);
    stin__mat4_mul(ctx->view_proj, ctx->projection, ctx->frame.view);
    stin__memcopy(ctx->frame.viewport, rect, sizeof ctx->frame.viewport);
    GL(ctx, Viewport)(rect[0], rect[1], rect[2], rect[3]);
}

/* The map's pixels the products' primitives can cover (under the light's
 * camera already in ctx, over the whole map_vp), a pixel's margin around;
 * 0 when none. */
static int cover(stin_context *ctx, const int map_vp[4], int rect[4])
{
    float all[4] = {1.0f, 1.0f, -1.0f, -1.0f}, one[4];
    int x0, y0, x1, y1;
    uint32_t i;
    for (i = 0; i < ctx->csg->primitive_count; i++) {
        stin__csg_screen_rect(ctx, &ctx->csg->primitives[i], one);
        all[0] = one[0] < all[0] ? one[0] : all[0];
        all[1] = one[1] < all[1] ? one[1] : all[1];
        all[2] = one[2] > all[2] ? one[2] : all[2];
        all[3] = one[3] > all[3] ? one[3] : all[3];
    }
    for (i = 0; i < 4; i++)
        all[i] = all[i] < -1.0f ? -1.0f : all[i] > 1.0f ? 1.0f : all[i];
    x0 = map_vp[0] + (int)((all[0] + 1.0f) * 0.5f * (float)map_vp[2]) - 1;
    y0 = map_vp[1] + (int)((all[1] + 1.0f) * 0.5f * (float)map_vp[3]) - 1;
    x1 = map_vp[0] + (int)((all[2] + 1.0f) * 0.5f * (float)map_vp[2]) + 2;
    y1 = map_vp[1] + (int)((all[3] + 1.0f) * 0.5f * (float)map_vp[3]) + 2;
    x0 = x0 < map_vp[0] ? map_vp[0] : x0;
    y0 = y0 < map_vp[1] ? map_vp[1] : y0;
    x1 = x1 > map_vp[0] + map_vp[2] ? map_vp[0] + map_vp[2] : x1;
    y1 = y1 > map_vp[1] + map_vp[3] ? map_vp[1] + map_vp[3] : y1;
    rect[0] = x0;
    rect[1] = y0;
    rect[2] = x1 - x0;
    rect[3] = y1 - y0;
    return rect[2] > 0 && rect[3] > 0;
}

/* A depth-stencil framebuffer at least size x size (packed depth-stencil
 * texture; made at the first cast that needs it, grown, never shrunk). */
static int own_target(stin_context *ctx, int size)
{
    stin__csg_cast_state *c = ctx->csg->cast;
    uint64_t need = STIN_CAP_BIT(STIN_CAP_FBO) | STIN_CAP_BIT(STIN_CAP_PACKED_DEPTH_STENCIL);
    if ((ctx->caps.present & need) != need)
        return 0;
    if (!c->fbo) {
        GL(ctx, GenFramebuffers)(1, &c->fbo);
        GL(ctx, GenTextures)(1, &c->depth_stencil);
    }
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, c->fbo);
    if (size > c->size) {
        stin__bind_unit(ctx, 0, GL_TEXTURE_2D, c->depth_stencil);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        GLenum f = stin__texture_format(ctx, GL_DEPTH24_STENCIL8);
        GL_ENUM(ctx, TexImage2D, f)(GL_TEXTURE_2D, 0, (GLint)f, size, size, 0, GL_DEPTH_STENCIL,
                                    GL_UNSIGNED_INT_24_8, NULL);
        GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
        GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D,
                                      c->depth_stencil, 0);
        GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                                      c->depth_stencil, 0);
        stin__no_colour_buffers(ctx);
        c->size = size;
    }
    return 1;
}

/* The steeper of the flatter one-sided differences along x and y at pixel
 * (x, y) of a w x h depth image; sides off the surface (1) are left out. */
static float slope_at(const float *d, int w, int h, int x, int y)
{
    float here = d[(size_t)y * (size_t)w + (size_t)x], m[2];
    int axis;
    for (axis = 0; axis < 2; axis++) {
        float best = -1.0f;
        int s;
        for (s = -1; s <= 1; s += 2) {
            int nx = x + (axis == 0 ? s : 0), ny = y + (axis == 1 ? s : 0);
            float there, diff;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h)
                continue;
            there = d[(size_t)ny * (size_t)w + (size_t)nx];
            if (!(there < 1.0f))
                continue;
            diff = there > here ? there - here : here - there;
            if (best < 0.0f || diff < best)
                best = diff;
        }
        m[axis] = best < 0.0f ? 0.0f : best;
    }
    return m[0] > m[1] ? m[0] : m[1];
}

/* candidate = result pushed back by the offset where the products are;
 * unit: the depth one of the offset's units moves in the map. */
static void bias(stin__csg_pixels *r, float factor, float units, float unit)
{
    int x, y;
    for (y = 0; y < r->h; y++)
        for (x = 0; x < r->w; x++) {
            size_t i = (size_t)y * (size_t)r->w + (size_t)x;
            float d = r->result[i];
            if (d < 1.0f) {
                d += factor * slope_at(r->result, r->w, r->h, x, y) + units * unit;
                d = d < 1.0f ? d : 1.0f;
            }
            r->candidate[i] = d;
        }
}

/* Bytes the camera's resolve keeps at the staging's start this frame. */
static size_t camera_bytes(const stin_context *ctx)
{
    size_t n = stin__csg_pixels_bytes(ctx->frame.viewport[2], ctx->frame.viewport[3]);
    return (n + 15u) & ~(size_t)15u;
}

int stin__csg_cast_wanted(const stin_context *ctx)
{
    return ctx->csg->product_count > 0 &&
           ctx->sel.choice[STIN_FEATURE_CSG].technique != STIN_TECH_CSG_OFF &&
           !(ctx->desc.debug_flags & STIN_DEBUG_CSG_NO_CAST);
}

/* The products drawn over the resolved depth, depth EQUAL, with the fixed
 * path's colour state as it is (map-combine's ramp, the side test's white). */
static void surface_pass(stin_context *ctx, const stin__pass_state *base)
{
    stin__pass_state eq = *base;
    uint32_t i;
    eq.depth_test = 1;
    eq.depth_func = GL_EQUAL;
    eq.depth_write = 0;
    eq.polygon_offset = 0;
    eq.cull = 0;
    eq.scissor = 0;
    stin__pass_apply(ctx, &eq);
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, LoadMatrixf)(ctx->projection);
    ctx->bound_mesh = 0xffffffffu;
    for (i = 0; i < ctx->csg->primitive_count; i++)
        stin__fixed_path()->geometry(ctx, &ctx->csg->primitives[i]);
    ctx->bound_mesh = 0xffffffffu;
}

/* The bound framebuffer's depth and stencil cleared within rect (far, 0),
 * ps (colour writes off) scissored to it and applied. */
static void clear_rect(stin_context *ctx, stin__pass_state *ps, const int rect[4])
{
    ps->color_write = 0;
    ps->scissor = 1;
    stin__memcopy(ps->scissor_box, rect, sizeof ps->scissor_box);
    stin__pass_apply(ctx, ps);
    stin__clear_depth(ctx, 1.0);
    GL(ctx, ClearStencil)(0);
    GL(ctx, Clear)(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

/* What a run of bands does with each resolved band. */
typedef struct cast_job {
    const stin__path *path;
    const float *view, *proj;
    const int *map_vp;
    GLuint target;            /* the map's framebuffer */
    int in_place;             /* resolve in it (it has a stencil buffer) */
    float factor, units;      /* the offset (0, 0: none) */
    int surface;              /* draw the products depth EQUAL after each band */
    size_t offset;            /* staging bytes the camera's resolve keeps */
} cast_job;

/* The products' rectangle of the map resolved band by band (as many rows
 * as the staging holds beside the camera's resolve), each band written
 * into the map. Returns the bands done (0: none; logged where it could
 * not). The camera is the light's, cropped, until the caller restores it. */
static int run_bands(stin_context *ctx, const cast_job *job, const int rect[4])
{
    stin__csg_cast_state *c = ctx->csg->cast;
    stin__csg_pixels *r = &c->pixels, biased;
    stin__pass_state ps = stin__pass_defaults, base = *stin__pass_current(ctx);
    size_t offset = job->offset, total, row = stin__csg_pixels_bytes(rect[2], 1);
    int rows, y, bands = 0;
    total = ctx->staging_bytes > ctx->scratch_bytes ? ctx->staging_bytes : ctx->scratch_bytes;
    rows = total > offset ? (int)((total - offset) / row) : 0;
    rows = rows < rect[3] ? rows : rect[3];
    if (rows < 1) {
        if (!c->said_room)
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                      "CSG products cast no shadow from a light: a row of its map under them "
                      "needs %lu bytes of staging beside the camera's %lu (raise "
                      "desc.max_texture_bytes)",
                      (unsigned long)row, (unsigned long)offset);
        c->said_room = 1;
        return 0;
    }
    if (!job->in_place &&
        !own_target(ctx, job->map_vp[0] + job->map_vp[2] > job->map_vp[1] + job->map_vp[3]
                             ? job->map_vp[0] + job->map_vp[2]
                             : job->map_vp[1] + job->map_vp[3])) {
        if (!c->said_no_target)
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                      "CSG products cast no shadow: the light's map has no stencil buffer and "
                      "the context no packed depth-stencil framebuffer to resolve them in");
        c->said_no_target = 1;
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, job->target);
        return 0;
    }
    for (y = rect[1]; y < rect[1] + rect[3]; y += rows) {
        const int band[4] = {rect[0], y, rect[2],
                             rect[1] + rect[3] - y < rows ? rect[1] + rect[3] - y : rows};
        camera_light(ctx, job->view, job->proj, job->map_vp, band);
        (void)stin__csg_pixels_at(ctx, offset, r); /* rows were sized to fit */
        ctx->csg->resolve_fbo = job->in_place ? job->target : c->fbo;
        if (!job->in_place) {
            GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, c->fbo);
            r->bits = 8;
        }
        clear_rect(ctx, &ps, band);
        if (job->path == stin__fixed_path()) {
            GL(ctx, MatrixMode)(GL_PROJECTION);
            GL(ctx, LoadMatrixf)(ctx->projection);
        }
        stin__csg_resolve_pixels(ctx, job->path, r);
        if (!job->in_place) {
            GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, job->target);
        } else { /* the resolve's stencil back to the map's clear */
            stin__pass_apply(ctx, &ps);
            GL(ctx, Clear)(GL_STENCIL_BUFFER_BIT);
        }
        bias(r, job->factor, job->units, stin__rt_depth_unit(ctx));
        biased = *r;
        biased.result = r->candidate;
        /* in place, over what the resolve's passes left: the band was
         * cleared to 1 before them, so writing it whole restores it */
        stin__csg_write_depth(ctx, job->path, &biased, job->in_place ? GL_ALWAYS : GL_LESS);
        if (job->surface)
            surface_pass(ctx, &base);
        bands++;
        ctx->stats.csg.cast_bands++;
    }
    stin__pass_apply(ctx, &base);
    return bands;
}

/* Without depth read-back (OpenGL ES without GL_NV_read_depth_stencil):
 * the products' rectangle resolved on the GPU alone, in one go, in the
 * cast's own depth-stencil framebuffer, each candidate's faces snapped
 * into the map with the light's offset (csg/merge.c's direct resolve).
 * Returns 1 when it ran (0: logged why not). */
static int run_gpu(stin_context *ctx, const cast_job *job, const int rect[4])
{
    stin__csg_cast_state *c = ctx->csg->cast;
    stin__pass_state ps = stin__pass_defaults, base = *stin__pass_current(ctx);
    stin__csg_pixels r;
    const char *why = NULL;
    int side = job->map_vp[0] + job->map_vp[2] > job->map_vp[1] + job->map_vp[3]
                   ? job->map_vp[0] + job->map_vp[2]
                   : job->map_vp[1] + job->map_vp[3];
    camera_light(ctx, job->view, job->proj, job->map_vp, rect);
    if (job->path != stin__glsl_path() || job->in_place || !stin__csg_direct_cast_fits(ctx))
        why = ctx->sel.choice[STIN_FEATURE_CSG].technique == STIN_TECH_CSG_INTERVAL
                  ? "under interval: a light's resolve on the GPU alone snaps each candidate's "
                    "faces into the map, and interval's layers are no one face set"
                  : "from a light here: OpenGL ES reads depth and stencil back only with "
                    "GL_NV_read_depth_stencil, and the GPU resolve from a light needs depth "
                    "textures";
    else if (!stin__csg_pixels_gpu(ctx, &r))
        why = "from a light: the map's rectangle under them needs more than the texture "
              "staging (1 byte a pixel; raise desc.max_texture_bytes)";
    else if (!own_target(ctx, side))
        why = "from a light: its resolve on the GPU alone needs a packed depth-stencil "
              "framebuffer";
    if (why) {
        if (!c->said_room)
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                      "CSG products cast no shadow %s", why);
        c->said_room = 1;
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, job->target);
        return 0;
    }
    r.bits = 8;
    clear_rect(ctx, &ps, rect);
    stin__csg_direct_cast_begin(ctx, c->fbo, c->depth_stencil, c->size, job->target,
                                job->factor, job->units);
    stin__csg_resolve_pixels(ctx, job->path, &r);
    stin__csg_direct_cast_end(ctx, job->target);
    stin__pass_apply(ctx, &base);
    ctx->stats.csg.cast_bands++;
    return 1;
}

/* The light's camera and the products' rectangle of its map; 0 when the
 * products cover none of it. */
static int light_rect(stin_context *ctx, const float view[16], const float proj[16],
                      const int map_vp[4], int rect[4])
{
    camera_light(ctx, view, proj, map_vp, map_vp);
    return cover(ctx, map_vp, rect);
}

static void finish(stin_context *ctx, const camera_saved *saved, const cast_job *job)
{
    camera_restore(ctx, saved);
    GL(ctx, Viewport)(job->map_vp[0], job->map_vp[1], job->map_vp[2], job->map_vp[3]);
    if (job->path == stin__fixed_path()) {
        GL(ctx, MatrixMode)(GL_PROJECTION);
        GL(ctx, LoadMatrixf)(job->proj);
        GL(ctx, MatrixMode)(GL_MODELVIEW);
    }
}

int stin__csg_cast(stin_context *ctx, const stin__path *path, const float view[16],
                   const float proj[16], const int map_vp[4], GLuint map_fbo, int in_place,
                   float factor, float units)
{
    stin__csg_cast_state *c = ctx->csg->cast;
    cast_job job;
    camera_saved saved;
    int rect[4], bands = 0;
    c->valid = 0;
    if (!stin__csg_cast_wanted(ctx))
        return 0;
    job.path = path;
    job.view = view;
    job.proj = proj;
    job.map_vp = map_vp;
    job.target = map_fbo;
    job.in_place = in_place;
    job.factor = factor;
    job.units = units;
    job.surface = 0;
    job.offset = camera_bytes(ctx); /* before the camera is the light's */
    camera_save(ctx, &saved);
    if (light_rect(ctx, view, proj, map_vp, rect)) /* on the GPU alone: nothing kept */
        bands = ctx->csg->no_readback ? run_gpu(ctx, &job, rect) : run_bands(ctx, &job, rect);
    if (bands && ctx->csg->no_readback) {
        ctx->stats.csg.cast_maps++;
    } else if (bands) {
        stin__memcopy(c->view, view, sizeof c->view);
        stin__memcopy(c->light_projection, proj, sizeof c->light_projection);
        stin__memcopy(c->rect, rect, sizeof c->rect);
        c->valid = 1;
        c->kept = bands == 1; /* its pixels cover the rectangle */
        stin__memcopy(c->projection, ctx->projection, sizeof c->projection);
        ctx->stats.csg.cast_maps++;
    }
    finish(ctx, &saved, &job);
    return bands > 0;
}

void stin__csg_cast_again(stin_context *ctx, const int map_vp[4], GLuint target, int in_place)
{
    stin__csg_cast_state *c = ctx->csg->cast;
    stin__pass_state base = *stin__pass_current(ctx);
    cast_job job;
    camera_saved saved;
    if (!c->valid)
        return;
    job.path = stin__fixed_path();
    job.view = c->view;
    job.proj = c->light_projection;
    job.map_vp = map_vp;
    job.target = target;
    job.in_place = in_place;
    job.factor = job.units = 0.0f;
    job.surface = 1;
    job.offset = camera_bytes(ctx);
    camera_save(ctx, &saved);
    if (!c->kept) { /* resolved in bands: again, band by band */
        camera_light(ctx, c->view, c->light_projection, map_vp, map_vp);
        (void)run_bands(ctx, &job, c->rect);
    } else {
        stin__memcopy(ctx->frame.view, c->view, sizeof c->view);
        stin__memcopy(ctx->projection, c->projection, sizeof c->projection);
        stin__mat4_mul(ctx->view_proj, ctx->projection, ctx->frame.view);
        ctx->frame.viewport[0] = c->pixels.x;
        ctx->frame.viewport[1] = c->pixels.y;
        ctx->frame.viewport[2] = c->pixels.w;
        ctx->frame.viewport[3] = c->pixels.h;
        GL(ctx, Viewport)(c->pixels.x, c->pixels.y, c->pixels.w, c->pixels.h);
        stin__csg_write_depth(ctx, job.path, &c->pixels, GL_LESS);
        surface_pass(ctx, &base);
        stin__pass_apply(ctx, &base);
    }
    finish(ctx, &saved, &job);
}

void stin__csg_cast_none(stin_context *ctx, const char *why)
{
    if (!stin__csg_cast_wanted(ctx) || !ctx->light_count || ctx->csg->cast->said_technique)
        return;
    stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK, "CSG products cast no shadow %s",
              why);
    ctx->csg->cast->said_technique = 1;
}

void stin__csg_cast_release(stin_context *ctx)
{
    stin__csg_cast_state *c = ctx->csg->cast;
    if (c->fbo)
        GL(ctx, DeleteFramebuffers)(1, &c->fbo);
    if (c->depth_stencil)
        GL(ctx, DeleteTextures)(1, &c->depth_stencil);
    c->fbo = c->depth_stencil = 0;
    c->size = 0;
}
