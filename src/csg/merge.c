/* SPDX-License-Identifier: MIT */
/* Where a CSG resolve keeps its candidates and its result. On the CPU (GL1
 * tiers, light maps' resolves, STIN_DEBUG_CSG_READBACK) the resolve runs in
 * the frame's own buffers, and every candidate layer's depth and each
 * parity count are read back into the staging and merged there. Each
 * read-back drains the GPU's pipeline, which made the resolve many times
 * slower than OpenCSG on a GPU (docs/benchmarks.md). On the GPU (the
 * frame's resolve on GLSL tiers with FBOs and packed depth-stencil
 * textures) nothing is read back:
 *   - the resolve runs in a work FBO (a depth-stencil texture) beside the
 *     frame, whose buffers it leaves alone;
 *   - a candidate's losing pixels (stencil & mask != want) are pushed to
 *     the far plane by a stencil-tested quad;
 *   - the candidate is min-merged into the result (a depth texture of a
 *     second FBO) by a quad writing the work texture's texel as
 *     gl_FragDepth, depth LESS, dropping 0 (scs's term where no plain
 *     primitive drew) and the far plane;
 *   - a stencil's largest value comes from occlusion queries of quads at
 *     thresholds (one wait, not a transfer);
 *   - at the end the products' faces are drawn into the frame, depth LESS,
 *     each fragment kept only within SNAP_BAND of the result: the frame's
 *     depth gets the faces' own rasterised depth, which the faces' depth
 *     EQUAL meets later bit for bit. The result itself can be a step or two
 *     off that: the work texture is rasterised in another buffer, and a
 *     24-bit depth read through a sampler and written back through
 *     gl_FragDepth can move by a step (Mesa's llvmpipe does; measured
 *     +1 and +2 on csg.json).
 * Two frames skip parts of that. In place (one scs term, the frame's only
 * candidate) the resolve runs in the frame's own buffers. Direct (any
 * other frame but interval's) each candidate is taken by snapping its own
 * faces into the frame on the work texture's depth instead of merging it:
 * the frame's depth is the result, with no result clear, merge quads or
 * final snap (on llvmpipe the merge quads and the final snap cost the
 * small products most of their frame; docs/benchmarks.md). Both copy the
 * frame's depth into the result texture only when a pass asks for it.
 * Without depth read-back a light's map resolves its products direct too
 * (csg/cast.c): in the cast's own work framebuffer, each candidate's faces
 * taken into the map with the light's polygon offset, the band widened by
 * it; the frame's work and result textures are left as they were.
 * A multisampled frame takes neither: the result stays one depth a pixel,
 * and the final snap (face_ids, then the snap with SNAP_SLOPE and the
 * neighbours) keeps each face on the samples it covers (stin.h,
 * MULTISAMPLED TARGETS).
 * Packed (no depth textures, no read-back: bare OpenGL ES 2.0, whose FBOs
 * cannot pair depth and stencil renderbuffers on Mesa) the frame's own
 * buffers, just cleared, are the work and its colour is scratch: the kill
 * quads lie on the far plane (csg_far.vert: no gl_FragDepth); a candidate
 * is taken by its faces, depth EQUAL on it, writing pack_depth(z) where
 * nearer than the result texture (RGBA8), and the region's colour is
 * copied into that texture; at the end the frame is cleared again as the
 * target's clear left it and the faces snapped onto the unpacked result. */
#include "csg/csg_private.h"

#define GL_DEPTH32F_STENCIL8 0x8CAD
#define READ_FRAMEBUFFER 0x8CA8
#define GL_FLOAT_32_UNSIGNED_INT_24_8_REV 0x8DAD
/* 8 steps of a 24-bit depth buffer (the vdsm position buffer's tolerance
 * for the same result): far above the result's error, far below what
 * separates two faces that are not one plane. */
#define SNAP_BAND (1.0f / 2097152.0f)
/* Where the near plane cuts a face, the clipper's new vertices carry a
 * rounding of the face's largest clip coordinate (its reach) in every
 * coordinate, and the divide by w magnifies it near the eye: the candidate
 * and the snap then disagree by up to about 2^-25 reach / w (measured on
 * a drill 20 long reaching behind the eye). The band grows by eight
 * times that, through gl_FragCoord.w, for such faces only. */
#define NEAR_CUT_BAND (4.0f / 16777216.0f)
/* Into a multisampled framebuffer the result (single-sampled) holds, at a
 * pixel a triangle edge crosses, the depth of the triangle over the
 * centre; the other triangle's fragment there carries its own plane's
 * depth at the centre, off by the two planes' slopes times the centre's
 * distance from the edge (under half a pixel where that triangle covers a
 * sample). The band grows by this many pixels of the fragment's own depth
 * change (|dz/dx| + |dz/dy|); each kept fragment still writes its own
 * per-sample depth, depth LESS. */
#define SNAP_SLOPE 1.0f

static const unsigned thresholds[STIN__CSG_MERGE_THRESHOLDS] = {
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 32, 64, 128, 255};

/* ---- set-up ------------------------------------------------------------- */
static int glsl_tier(const stin_context *ctx, int *gl4)
{
    stin_technique t = ctx->sel.choice[STIN_FEATURE_LIGHTING].technique;
    *gl4 = t == STIN_TECH_LIGHTING_GLSL150;
    return t == STIN_TECH_LIGHTING_GLSL150 || t == STIN_TECH_LIGHTING_GLSL110;
}

static GLuint build(stin_context *ctx, int gl4, const char *vert, const char *frag, char *msg,
                    size_t size)
{
    char v[40], f[40];
    stin__formatf(v, sizeof v, "%s/%s", gl4 ? "gl4" : "gl2", vert);
    stin__formatf(f, sizeof f, "%s/%s", gl4 ? "gl4" : "gl2", frag);
    return stin__program_build(ctx, v, f, NULL, 0, msg, size);
}

static const stin__uniform_name merge_uniforms[] = {
    STIN__UNIFORM(stin__csg_merge_state, u_depth, "u_depth"),
    STIN__UNIFORM(stin__csg_merge_state, u_select, "u_select"),
    STIN__UNIFORM(stin__csg_merge_state, u_params, "u_params"),
};

static const stin__uniform_name snap_uniforms[] = {
    STIN__UNIFORM(stin__csg_merge_state, snap_model, "u_model"),
    STIN__UNIFORM(stin__csg_merge_state, snap_view_proj, "u_view_proj"),
    STIN__UNIFORM(stin__csg_merge_state, snap_result, "u_result"),
    STIN__UNIFORM(stin__csg_merge_state, snap_params, "u_params"),
    STIN__UNIFORM(stin__csg_merge_state, snap_samples, "u_samples"),
    STIN__UNIFORM(stin__csg_merge_state, snap_ids, "u_ids"),
};

void stin__csg_merge_init(stin_context *ctx)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    const uint64_t need = STIN_CAP_BIT(STIN_CAP_FBO) | STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE) |
                          STIN_CAP_BIT(STIN_CAP_PACKED_DEPTH_STENCIL) |
                          STIN_CAP_BIT(STIN_CAP_FRAG_DEPTH);
    char msg[160];
    int gl4;
    stin__memzero(m, sizeof *m);
    if (ctx->sel.choice[STIN_FEATURE_CSG].technique == STIN_TECH_CSG_OFF ||
        !glsl_tier(ctx, &gl4))
        return; /* the CPU resolve */
    /* no read-back and no depth texture (bare OpenGL ES 2.0): packed */
    m->packed = ctx->csg->no_readback && !gl4 &&
                !(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE));
    if (!m->packed && (ctx->caps.present & need) != need)
        return;
    if (m->packed) {
        static const char *const chunks[] = {"gl2/pack_depth.glsl", NULL};
        m->kill_prog = build(ctx, 0, "csg_far.vert", "csg_kill.frag", msg, sizeof msg);
        if (m->kill_prog)
            m->snap_prog = stin__program_build(ctx, "gl2/volume.vert", "gl2/csg_snap.frag",
                                               chunks, 0, msg, sizeof msg);
    } else {
        m->merge_prog = build(ctx, gl4, "screen.vert", "csg_merge.frag", msg, sizeof msg);
        if (m->merge_prog)
            m->kill_prog = build(ctx, gl4, "screen.vert", "csg_kill.frag", msg, sizeof msg);
        if (m->kill_prog) /* the volume program's vertices: the lit passes' depth */
            m->snap_prog = build(ctx, gl4, "volume.vert", "csg_snap.frag", msg, sizeof msg);
    }
    if (!m->snap_prog) {
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "CSG: the GPU resolve's programs failed to build (%s); products resolve "
                  "with read-backs", msg);
        stin__csg_merge_release(ctx);
        return;
    }
    if (m->merge_prog)
        STIN__LOCATE(ctx, m->merge_prog, m, merge_uniforms);
    STIN__LOCATE(ctx, m->snap_prog, m, snap_uniforms);
    stin__displace_locate(ctx, m->snap_prog, 0, &m->snap_displace);
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_ANY_SAMPLES_QUERY))
        GL(ctx, GenQueries)(STIN__CSG_MERGE_THRESHOLDS + 1, m->queries);
}

void stin__csg_merge_release(stin_context *ctx)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    GLuint programs[3];
    int i;
    programs[0] = m->merge_prog;
    programs[1] = m->kill_prog;
    programs[2] = m->snap_prog;
    for (i = 0; i < 3; i++)
        if (programs[i])
            GL(ctx, DeleteProgram)(programs[i]);
    if (m->fbo[0])
        GL(ctx, DeleteFramebuffers)(2, m->fbo);
    if (m->texture[0])
        GL(ctx, DeleteTextures)(2, m->texture);
    if (m->queries[0])
        GL(ctx, DeleteQueries)(STIN__CSG_MERGE_THRESHOLDS + 1, m->queries);
    if (m->id_fbo) {
        GL(ctx, DeleteFramebuffers)(1, &m->id_fbo);
        GL(ctx, DeleteTextures)(1, &m->id_texture);
    }
    stin__memzero(m, sizeof *m);
}

int stin__csg_merge_ready(const stin_context *ctx)
{
    return ctx->csg->merge.snap_prog && !(ctx->desc.debug_flags & STIN_DEBUG_CSG_READBACK);
}

/* The frame's depth precision with a stencil beside it. */
static GLenum depth_format(const stin_context *ctx, GLenum *type)
{
    int wide = ctx->target.depth_bits > 24;
    *type = wide ? GL_FLOAT_32_UNSIGNED_INT_24_8_REV : GL_UNSIGNED_INT_24_8;
    return wide ? GL_DEPTH32F_STENCIL8 : GL_DEPTH24_STENCIL8;
}

/* 1 where status says complete; else 0, and `what` logged once (said). */
static int complete(stin_context *ctx, GLenum status, int *said, const char *what)
{
    if (status == GL_FRAMEBUFFER_COMPLETE)
        return 1;
    if (!*said)
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK, "CSG: %s (0x%x)", what,
                  (unsigned)status);
    *said = 1;
    return 0;
}

/* Work and result at the viewport's window size (x + w by y + h: texel =
 * window pixel), grown, never shrunk; 0 when a framebuffer is incomplete
 * (logged once). */
int stin__csg_merge_targets(stin_context *ctx)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    const int *vp = ctx->frame.viewport;
    int w = vp[0] + vp[2], h = vp[1] + vp[3], i;
    GLenum type, format = depth_format(ctx, &type), status = GL_FRAMEBUFFER_COMPLETE;
    if (m->packed) /* RGBA8, no framebuffer: the colour is copied in */
        format = GL_RGBA8;
    if (w <= m->width && h <= m->height && format == m->format)
        return 1;
    if (m->packed) {
        if (!m->texture[0])
            GL(ctx, GenTextures)(2, m->texture);
        m->width = w > m->width ? w : m->width;
        m->height = h > m->height ? h : m->height;
        m->format = format;
        m->bytes = (size_t)m->width * (size_t)m->height * 4u;
        stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
        stin__rt_texture(ctx, m->texture[STIN__CSG_MERGE_RESULT], GL_RGBA8, GL_RGBA,
                         GL_UNSIGNED_BYTE, m->width, m->height);
        stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
        return 1;
    }
    if (!m->fbo[0]) {
        GL(ctx, GenFramebuffers)(2, m->fbo);
        GL(ctx, GenTextures)(2, m->texture);
    }
    w = w > m->width ? w : m->width;
    h = h > m->height ? h : m->height;
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0); /* unit 0 active for the textures */
    for (i = 0; i < 2; i++) {
        GLenum made;
        stin__rt_texture(ctx, m->texture[i], format, GL_DEPTH_STENCIL, type, w, h);
        /* work: its stencil counts too (GL 2.x names both halves) */
        made = stin__rt_attach_depth_only(ctx, m->fbo[i], m->texture[i],
                                          i == STIN__CSG_MERGE_WORK ? m->texture[i] : 0);
        if (status == GL_FRAMEBUFFER_COMPLETE)
            status = made;
    }
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    m->width = w;
    m->height = h;
    m->format = format;
    m->bytes = (size_t)w * (size_t)h * (format == GL_DEPTH24_STENCIL8 ? 4u : 8u) * 2u;
    if (complete(ctx, status, &m->said_failed,
                 "the GPU resolve's framebuffers are incomplete; products resolve with "
                 "read-backs"))
        return 1;
    m->width = m->height = 0; /* tried again next frame */
    return 0;
}

/* ---- quads -------------------------------------------------------------- */
/* The work texture's depth into the bound (result) framebuffer, depth
 * LESS, through the merge program; select: interval's layer. */
static void merge_quad(stin_context *ctx, const stin__csg_select *select)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    stin__pass_state ps = stin__pass_defaults;
    float params[4];
    ps.depth_test = 1;
    ps.depth_func = GL_LESS;
    ps.color_write = 0;
    stin__csg_region_keep_to(ctx, &ps);
    stin__pass_apply(ctx, &ps);
    GL(ctx, UseProgram)(m->merge_prog);
    stin__lit_program_forget(ctx);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, m->texture[STIN__CSG_MERGE_WORK]);
    GL(ctx, Uniform1i)(m->u_depth, 0);
    params[0] = select ? (float)select->id : -1.0f;
    params[1] = 0.0f;
    params[2] = 1.0f / (float)m->width;
    params[3] = 1.0f / (float)m->height;
    GL(ctx, Uniform4fv)(m->u_params, 1, params);
    if (select) {
        stin__bind_unit(ctx, 1, GL_TEXTURE_2D, select->texture);
        GL(ctx, Uniform1i)(m->u_select, 1);
    }
    stin__screen_quad(ctx);
    if (select)
        stin__bind_unit(ctx, 1, GL_TEXTURE_2D, 0);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    ctx->stats.passes++;
}

/* A quad through the kill program with pass state ps, within the
 * resolve's region. */
static void kill_quad(stin_context *ctx, stin__pass_state *ps)
{
    stin__csg_region_keep_to(ctx, ps);
    stin__pass_apply(ctx, ps);
    GL(ctx, UseProgram)(ctx->csg->merge.kill_prog);
    stin__lit_program_forget(ctx);
    stin__screen_quad(ctx);
}

static void resume(stin_context *ctx, const stin__path *path)
{
    if (path)
        path->geometry_begin(ctx);
}

int stin__csg_merge_begin(stin_context *ctx)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    if (!stin__csg_merge_ready(ctx) || !stin__csg_merge_targets(ctx))
        return 0;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, m->fbo[STIN__CSG_MERGE_RESULT]);
    stin__clear_depth(ctx, 1.0);
    stin__csg_clear(ctx, GL_DEPTH_BUFFER_BIT);
    ctx->csg->resolve_fbo = m->fbo[STIN__CSG_MERGE_WORK];
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->csg->resolve_fbo);
    ctx->stats.csg.gpu_resolves = 1;
    ctx->stats.csg.gpu_bytes = m->bytes;
    m->ids_done = 0;
    return 1;
}

int stin__csg_in_place_fits(const stin_context *ctx)
{
    const stin__csg_state *c = ctx->csg;
    /* the copy into the result texture cannot read a multisampled framebuffer */
    return !(ctx->desc.debug_flags & STIN_DEBUG_CSG_NO_IN_PLACE) && !ctx->frame.keep_contents &&
           !ctx->target.multisampled && c->product_count == 1 &&
           c->products[0].term_count == 1 && stin__csg_scs_takes(ctx, &c->products[0]);
}

int stin__csg_in_place_begin(stin_context *ctx)
{
    if (!stin__csg_merge_ready(ctx) || !stin__csg_merge_targets(ctx))
        return 0;
    ctx->csg->resolve_fbo = ctx->draw_fbo; /* stin__csg_merge_targets left it bound */
    ctx->csg->in_place = 1;
    ctx->stats.csg.gpu_resolves = 1;
    ctx->stats.csg.gpu_bytes = ctx->csg->merge.bytes;
    ctx->stats.csg.in_place = 1;
    return 1;
}

void stin__csg_in_place_end(stin_context *ctx)
{
    stin__csg_clear(ctx, GL_STENCIL_BUFFER_BIT);
    ctx->csg->in_place = 0;
    ctx->csg->pending_fbo = ctx->draw_fbo;
    ctx->csg->result_pending = 1;
    if (!ctx->target.separate_read) /* the copy could not leave a pass's binding alone */
        stin__csg_merge_result_ready(ctx);
}

void stin__csg_merge_result_ready(stin_context *ctx)
{
    const int *vp = ctx->frame.viewport;
    GLint bound = 0;
    if (!ctx->csg->result_pending)
        return;
    /* within the GL (no read-back); only where asked: llvmpipe's copy cost
     * a fifth of the bench's n = 2 frame */
    if (ctx->target.separate_read) {
        GL(ctx, GetIntegerv)(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
        GL(ctx, BindFramebuffer)(READ_FRAMEBUFFER, ctx->csg->pending_fbo);
    }
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, ctx->csg->merge.texture[STIN__CSG_MERGE_RESULT]);
    GL(ctx, CopyTexSubImage2D)(GL_TEXTURE_2D, 0, vp[0], vp[1], vp[0], vp[1], vp[2], vp[3]);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    if (ctx->target.separate_read) /* stin binds both as one */
        GL(ctx, BindFramebuffer)(READ_FRAMEBUFFER, (GLuint)bound);
    ctx->csg->result_pending = 0;
}

GLuint stin__csg_merge_result(stin_context *ctx)
{
    return ctx->csg->merge.texture[STIN__CSG_MERGE_RESULT];
}

/* The unit of the id pass's texture: not the height map's (a sampler of
 * another type on one unit is an error at the draw). */
static int ids_unit(const stin_context *ctx) { return ctx->sel.displace_unit == 1 ? 2 : 1; }

/* The snap program bound, reading depth texture `against` on unit 0 and
 * the id pass's texture `ids` (0: none) on ids_unit. */
static void snap_begin(stin_context *ctx, GLuint against, GLuint ids)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    GL(ctx, UseProgram)(m->snap_prog);
    stin__lit_program_forget(ctx);
    GL(ctx, UniformMatrix4fv)(m->snap_view_proj, 1, GL_FALSE, ctx->view_proj);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, against);
    GL(ctx, Uniform1i)(m->snap_result, 0);
    if (ids) {
        stin__bind_unit(ctx, ids_unit(ctx), GL_TEXTURE_2D, ids);
        GL(ctx, Uniform1i)(m->snap_ids, ids_unit(ctx));
    }
    ctx->bound_mesh = 0xffffffffu;
}

static void snap_end(stin_context *ctx, GLuint ids)
{
    ctx->bound_mesh = 0xffffffffu;
    if (ids)
        stin__bind_unit(ctx, ids_unit(ctx), GL_TEXTURE_2D, 0);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
}

/* u_samples for the next face set: the slope band and the neighbours (a
 * multisampled target), its id (1-based; the id pass writes it), and
 * whether the id pass's texture is read. */
static void snap_samples(stin_context *ctx, float slope, float neighbours, uint32_t id,
                         float with_ids)
{
    float v[4];
    v[0] = slope;
    v[1] = neighbours;
    v[2] = (float)id;
    v[3] = with_ids;
    GL(ctx, Uniform4fv)(ctx->csg->merge.snap_samples, 1, v);
}

void stin__csg_snap_band(const stin_context *ctx, const stin__draw *d, float band[2])
{
    float reach;
    int near_cut, far_cut;
    stin__csg_clip_extent(ctx, d, &near_cut, &far_cut, &reach);
    band[0] = SNAP_BAND;
    band[1] = near_cut ? NEAR_CUT_BAND * reach : 0.0f;
}

/* take: a direct resolve's take, whose texture is the direct work's and
 * whose band grows by the offset's units (u_samples.x: its factor). */
static void snap_band_for(stin_context *ctx, const stin__draw *d, int take)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    float params[4];
    stin__csg_snap_band(ctx, d, params);
    /* the offset's units in the map's own depth step (glPolygonOffset's r) */
    params[0] += take ? m->direct_offset[1] * stin__rt_depth_unit(ctx) : 0.0f;
    params[2] = 1.0f / (float)(take ? m->direct_width : m->width);
    params[3] = 1.0f / (float)(take ? m->direct_height : m->height);
    GL(ctx, Uniform4fv)(m->snap_params, 1, params);
}

/* How snap_faces draws: the snap, the id pass (colour written, no depth
 * test), the packed resolve's take (colour written where the faces lie on
 * the candidate's depth, depth EQUAL, none written). */
enum { SNAP_FACES, SNAP_IDS, SNAP_TAKE };

/* d's faces but `culled` into the bound framebuffer, depth LESS, where
 * they lie on the bound texture's depth; within the resolve's region where
 * `region` asks (the work texture outside it holds older candidates); how:
 * SNAP_*. */
static void snap_faces(stin_context *ctx, const stin__draw *d, GLenum culled, int region,
                       int how)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    stin__pass_state ps = stin__pass_defaults;
    int take;
    ps.depth_test = (unsigned char)(how != SNAP_IDS);
    ps.depth_func = how == SNAP_TAKE ? GL_EQUAL : GL_LESS; /* under what the buffer holds nearer */
    ps.depth_write = (unsigned char)(how != SNAP_TAKE);
    ps.color_write = (unsigned char)(how != SNAP_FACES);
    ps.cull = 1;
    ps.cull_face = culled;
    if (region)
        stin__csg_region_keep_to(ctx, &ps);
    take = how == SNAP_FACES && region; /* a direct resolve's take */
    if (take && (m->direct_offset[0] != 0.0f || m->direct_offset[1] != 0.0f)) {
        ps.polygon_offset = 1;
        ps.offset_factor = m->direct_offset[0];
        ps.offset_units = m->direct_offset[1];
    }
    stin__pass_apply(ctx, &ps);
    snap_band_for(ctx, d, take);
    stin__glsl_submit_geometry(ctx, m->snap_model, &m->snap_displace, d);
    ctx->stats.passes++;
}

/* The id texture at the targets' size, its framebuffer bound; 0 when the
 * framebuffer is incomplete (logged once). */
static int ensure_ids(stin_context *ctx)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    GLenum status;
    if (m->id_fbo && m->id_width == m->width && m->id_height == m->height) {
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, m->id_fbo);
        return 1;
    }
    if (!m->id_fbo) {
        GL(ctx, GenFramebuffers)(1, &m->id_fbo);
        GL(ctx, GenTextures)(1, &m->id_texture);
    }
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    stin__rt_texture(ctx, m->id_texture, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, m->width,
                     m->height);
    status = stin__rt_attach(ctx, m->id_fbo, m->id_texture, 0, 0);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    m->id_width = m->width;
    m->id_height = m->height;
    if (complete(ctx, status, &m->said_ids_failed,
                 "the multisampled snap's id framebuffer is incomplete; products are snapped "
                 "at the pixel centres (lines along their edges)"))
        return 1;
    m->id_width = m->id_height = 0;
    return 0;
}

/* The id pass (once a resolve): each face set's faces, single-sampled,
 * where they lie on the result at the pixel centre (the snap's band),
 * write their id, so that the multisampled snap keeps a face only where
 * the centre's surface (or at a silhouette a neighbour's) is its own face
 * set's: a face whose plane passes near another primitive's surface (a
 * rim where two meet at a shallow angle) stays out. 0 when it cannot
 * (more than 65535 face sets, or no framebuffer). */
static GLuint face_ids(stin_context *ctx)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    GLint bound = 0;
    uint32_t i;
    if (m->ids_done)
        return m->id_texture;
    if (ctx->csg->face_count > 65535u)
        return 0;
    GL(ctx, GetIntegerv)(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    if (ensure_ids(ctx)) {
        stin__pass_apply(ctx, &stin__pass_defaults); /* colour writes on, no scissor */
        GL(ctx, ClearColor)(0.0f, 0.0f, 0.0f, 0.0f);
        GL(ctx, Clear)(GL_COLOR_BUFFER_BIT);
        snap_begin(ctx, m->texture[STIN__CSG_MERGE_RESULT], 0);
        for (i = 0; i < ctx->csg->face_count; i++) {
            snap_samples(ctx, 0.0f, 0.0f, i + 1u, 0.0f);
            snap_faces(ctx, &ctx->csg->faces[i], stin__csg_face_hidden(&ctx->csg->faces[i]), 0,
                       SNAP_IDS);
        }
        snap_end(ctx, 0);
        m->ids_done = 1;
        ctx->stats.csg.gpu_bytes = m->bytes + (size_t)m->id_width * (size_t)m->id_height * 4u;
    }
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, (GLuint)bound);
    return m->ids_done ? m->id_texture : 0;
}

void stin__csg_merge_snap(stin_context *ctx)
{
    GLint sample_buffers = 0;
    GLuint ids = 0;
    uint32_t i;
    /* the frame's target, or a pass's own buffer (screen mask, outline, peel) */
    GL(ctx, GetIntegerv)(GL_SAMPLE_BUFFERS, &sample_buffers);
    if (sample_buffers > 0 && !(ctx->desc.debug_flags & STIN_DEBUG_CSG_SNAP_AT_CENTRE))
        ids = face_ids(ctx);
    snap_begin(ctx, ctx->csg->merge.texture[STIN__CSG_MERGE_RESULT], ids);
    for (i = 0; i < ctx->csg->face_count; i++) {
        if (ids)
            snap_samples(ctx, SNAP_SLOPE, 1.0f, i + 1u, 1.0f);
        else
            snap_samples(ctx, 0.0f, 0.0f, 0u, 0.0f);
        snap_faces(ctx, &ctx->csg->faces[i], stin__csg_face_hidden(&ctx->csg->faces[i]), 0,
                   SNAP_FACES);
    }
    snap_end(ctx, ids);
}

/* The direct resolve's take: the surface's faces on the work texture's
 * depth (what keep_where left of the candidate) into the frame; the packed
 * resolve's: on the frame's depth (the work), nearer than the result,
 * packed into the frame's colour, then copied into the result. */
static void snap_surface(stin_context *ctx, const stin__csg_surface *s)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    int how = m->packed ? SNAP_TAKE : SNAP_FACES;
    uint32_t i;
    /* never multisampled; a map's offset widens the band by its slope part */
    snap_begin(ctx, m->packed ? m->texture[STIN__CSG_MERGE_RESULT] : m->direct_work, 0);
    snap_samples(ctx, m->packed ? 0.0f : m->direct_offset[0], m->packed ? -1.0f : 0.0f, 0u,
                 0.0f);
    if (s->cap)
        snap_faces(ctx, s->cap, s->cap_culled, 1, how);
    for (i = 0; !s->cap && i < s->count; i++) {
        uint32_t lit = ctx->csg->literals[s->t->first + (s->list ? s->list[i] : s->first + i)];
        const stin__draw *d =
            &ctx->csg->primitives[s->p->first_primitive + STIN__CSG_PRIMITIVE_OF(lit)];
        snap_faces(ctx, d, stin__csg_culled_face(d, (int)STIN__CSG_COMPLEMENTED(lit)), 1, how);
    }
    snap_end(ctx, 0);
    if (m->packed) { /* the region's colour: the result there (unit 0 active) */
        const int *g = ctx->csg->region;
        stin__bind_unit(ctx, 0, GL_TEXTURE_2D, m->texture[STIN__CSG_MERGE_RESULT]);
        GL(ctx, CopyTexSubImage2D)(GL_TEXTURE_2D, 0, g[0], g[1], g[0], g[1], g[2], g[3]);
        stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    }
}

int stin__csg_direct_fits(const stin_context *ctx)
{
    return !(ctx->desc.debug_flags & STIN_DEBUG_CSG_NO_IN_PLACE) && !ctx->target.multisampled &&
           ctx->sel.choice[STIN_FEATURE_CSG].technique != STIN_TECH_CSG_INTERVAL;
}

int stin__csg_direct_begin(stin_context *ctx)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    if (!stin__csg_merge_ready(ctx) || !stin__csg_merge_targets(ctx))
        return 0;
    ctx->csg->resolve_fbo = m->fbo[STIN__CSG_MERGE_WORK];
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->csg->resolve_fbo);
    ctx->csg->direct = 1;
    m->direct_target = ctx->draw_fbo;
    m->direct_work = m->texture[STIN__CSG_MERGE_WORK];
    m->direct_width = m->width;
    m->direct_height = m->height;
    m->direct_offset[0] = m->direct_offset[1] = 0.0f;
    ctx->stats.csg.gpu_resolves = 1;
    ctx->stats.csg.gpu_bytes = m->bytes;
    ctx->stats.csg.direct = 1;
    return 1;
}

int stin__csg_direct_cast_fits(const stin_context *ctx)
{
    return stin__csg_merge_ready(ctx) && !ctx->csg->merge.packed &&
           ctx->sel.choice[STIN_FEATURE_CSG].technique != STIN_TECH_CSG_INTERVAL;
}

void stin__csg_direct_cast_begin(stin_context *ctx, GLuint work, GLuint texture, int size,
                                 GLuint target, float factor, float units)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    ctx->csg->resolve_fbo = work;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, work);
    ctx->csg->direct = 1;
    m->direct_target = target;
    m->direct_work = texture;
    m->direct_width = m->direct_height = size;
    m->direct_offset[0] = factor;
    m->direct_offset[1] = units;
}

void stin__csg_direct_cast_end(stin_context *ctx, GLuint target)
{
    ctx->csg->direct = 0;
    ctx->csg->resolve_fbo = ctx->draw_fbo;
    ctx->csg->merge.direct_offset[0] = ctx->csg->merge.direct_offset[1] = 0.0f;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, target);
}

void stin__csg_direct_end(stin_context *ctx)
{
    ctx->csg->direct = 0;
    ctx->csg->resolve_fbo = ctx->draw_fbo;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    stin__pass_apply(ctx, &stin__pass_defaults); /* the last candidate's scissor off */
    ctx->csg->pending_fbo = ctx->draw_fbo;
    ctx->csg->result_pending = 1;
    if (!ctx->target.separate_read) /* as in place */
        stin__csg_merge_result_ready(ctx);
}

int stin__csg_packed(const stin_context *ctx)
{
    return ctx->csg->merge.packed && stin__csg_merge_ready(ctx);
}

/* The whole framebuffer as the target's clear left it (frame/frame.c's
 * stage_target): colour `rgba`, depth far, stencil 0. */
static void clear_frame(stin_context *ctx, const float rgba[4])
{
    stin__pass_apply(ctx, &stin__pass_defaults); /* writes on, no scissor */
    GL(ctx, ClearColor)(rgba[0], rgba[1], rgba[2], rgba[3]);
    stin__clear_depth(ctx, 1.0);
    GL(ctx, ClearStencil)(0);
    GL(ctx, Clear)(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

int stin__csg_packed_begin(stin_context *ctx)
{
    static const float far[4] = {1.0f, 1.0f, 1.0f, 1.0f}; /* pack_depth(1) */
    stin__csg_merge_state *m = &ctx->csg->merge;
    const int *vp = ctx->frame.viewport;
    GLint bits[3] = {0, 0, 0};
    const char *why = ctx->frame.keep_contents ? "the frame keeps its contents"
                      : ctx->target.multisampled ? "the framebuffer is multisampled"
                                                 : NULL;
    GL(ctx, GetIntegerv)(GL_RED_BITS, &bits[0]); /* ES 2.0 asks the bound framebuffer */
    GL(ctx, GetIntegerv)(GL_GREEN_BITS, &bits[1]);
    GL(ctx, GetIntegerv)(GL_BLUE_BITS, &bits[2]);
    if (!why && (bits[0] < 8 || bits[1] < 8 || bits[2] < 8))
        why = "the frame's colour has under 8 bits a channel (the result's 24 bits go there)";
    if (why) {
        if (!m->said_packed)
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                      "CSG products are not drawn: %s, and without depth textures the "
                      "resolve works in the frame's own buffers, just cleared",
                      why);
        m->said_packed = 1;
        return 0;
    }
    if (!stin__csg_merge_targets(ctx))
        return 0;
    clear_frame(ctx, far);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, m->texture[STIN__CSG_MERGE_RESULT]);
    GL(ctx, CopyTexSubImage2D)(GL_TEXTURE_2D, 0, vp[0], vp[1], vp[0], vp[1], vp[2], vp[3]);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    ctx->csg->resolve_fbo = ctx->draw_fbo;
    ctx->stats.csg.gpu_resolves = 1;
    ctx->stats.csg.gpu_bytes = m->bytes;
    ctx->stats.csg.packed = 1;
    return 1;
}

void stin__csg_packed_end(stin_context *ctx)
{
    clear_frame(ctx, ctx->frame.clear_color);
    ctx->csg->result_pending = 0; /* the result is the packed texture */
}

/* ---- the steps ---------------------------------------------------------- */
/* The CPU resolve's region (the term's or candidate's rectangle, where its
 * reads keep to) in r's viewport-sized arrays: rows of `width` pixels from
 * `first`, `stride` apart. Pixels outside it hold what an earlier read left
 * and are never looked at. */
typedef struct region_rows {
    size_t first, width, rows, stride;
} region_rows;

static region_rows rows_of(const stin_context *ctx, const stin__csg_pixels *r)
{
    const int *g = ctx->csg->region;
    region_rows o;
    o.stride = (size_t)r->w;
    o.first = (size_t)(g[1] - r->y) * o.stride + (size_t)(g[0] - r->x);
    o.width = (size_t)g[2];
    o.rows = (size_t)g[3];
    return o;
}

int stin__csg_candidate_open(stin_context *ctx, stin__csg_pixels *r)
{
    region_rows g = rows_of(ctx, r);
    size_t x, y;
    int any = 0;
    if (r->gpu)
        return 1;
    stin__csg_read_depth(ctx, r, r->candidate);
    for (y = 0; y < g.rows; y++)
        for (x = 0; x < g.width; x++) {
            size_t i = g.first + y * g.stride + x;
            if (r->candidate[i] <= 0.0f || r->candidate[i] >= r->result[i])
                r->candidate[i] = 2.0f; /* none here (scs's 0), or not nearer */
            else
                any = 1;
        }
    return any;
}

void stin__csg_candidate_keep_where(stin_context *ctx, const stin__path *path,
                                    stin__csg_pixels *r, unsigned mask, unsigned want)
{
    region_rows g = rows_of(ctx, r);
    size_t x, y;
    if (r->gpu) {
        stin__pass_state ps = stin__pass_defaults;
        ps.depth_test = 1;
        ps.depth_func = GL_ALWAYS; /* the kill program writes the far plane */
        ps.color_write = 0;
        ps.stencil_test = 1;
        ps.front.func = GL_NOTEQUAL;
        ps.front.ref = (GLint)want;
        ps.front.mask = mask;
        ps.front.fail = ps.front.zfail = ps.front.zpass = GL_KEEP;
        ps.back = ps.front;
        kill_quad(ctx, &ps);
        ctx->stats.passes++;
        resume(ctx, path);
        return;
    }
    stin__csg_read_stencil(ctx, r);
    for (y = 0; y < g.rows; y++)
        for (x = 0; x < g.width; x++) {
            size_t i = g.first + y * g.stride + x;
            if ((r->stencil[i] & mask) != want)
                r->candidate[i] = 2.0f;
        }
}

int stin__csg_candidate_take(stin_context *ctx, const stin__path *path, stin__csg_pixels *r,
                             const stin__csg_select *select, const stin__csg_surface *surface,
                             int want_kept)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    GLuint kept = 1, q = m->queries[STIN__CSG_MERGE_THRESHOLDS];
    int counted = want_kept && m->queries[0] && !(ctx->queries_busy & STIN__QUERY_SAMPLES);
    GLenum target = stin__any_samples_target(ctx);
    region_rows g = rows_of(ctx, r);
    size_t x, y;
    int direct;
    if (!r->gpu) {
        kept = 0;
        for (y = 0; y < g.rows; y++)
            for (x = 0; x < g.width; x++) {
                size_t i = g.first + y * g.stride + x;
                if ((!select || r->stencil[i] == (unsigned char)select->id) &&
                    r->candidate[i] < r->result[i]) {
                    r->result[i] = r->candidate[i];
                    kept = 1;
                }
            }
        return (int)kept;
    }
    if (ctx->csg->in_place) /* the candidate is the result */
        return 1;
    if (m->packed) { /* in the frame's own buffers: no framebuffer to bind */
        if (surface)
            snap_surface(ctx, surface);
        resume(ctx, path);
        return surface != NULL;
    }
    /* a direct resolve has no result: every candidate it takes names its
     * faces (interval's, which do not, never runs direct) */
    direct = ctx->csg->direct && surface;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER,
                             direct ? m->direct_target : m->fbo[STIN__CSG_MERGE_RESULT]);
    if (counted)
        GL_ENUM(ctx, BeginQuery, target)(target, q);
    if (direct)
        snap_surface(ctx, surface);
    else
        merge_quad(ctx, select);
    if (counted) {
        GL_ENUM(ctx, EndQuery, target)(target);
        GL(ctx, GetQueryObjectuiv)(q, GL_QUERY_RESULT, &kept);
    }
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->csg->resolve_fbo);
    resume(ctx, path);
    return kept != 0;
}

/* The bound on a stencil's largest value from which thresholds' quads
 * passed (drawn: how many were). */
static unsigned bound_of(const GLuint *passed, int drawn, unsigned limit)
{
    int i = drawn - 1;
    unsigned most;
    while (i >= 0 && !passed[i])
        i--;
    if (i < 0)
        return 0;
    most = i + 1 < STIN__CSG_MERGE_THRESHOLDS ? thresholds[i + 1] - 1u : 255u;
    return most < limit ? most : limit;
}

unsigned stin__csg_stencil_max(stin_context *ctx, const stin__path *path, stin__csg_pixels *r,
                               unsigned limit)
{
    stin__csg_merge_state *m = &ctx->csg->merge;
    unsigned most = 0;
    region_rows g = rows_of(ctx, r);
    size_t i, x, y;
    if (r->gpu && m->queries[0] && !(ctx->queries_busy & STIN__QUERY_SAMPLES)) {
        GLuint passed[STIN__CSG_MERGE_THRESHOLDS];
        GLenum target = stin__any_samples_target(ctx);
        stin__pass_state ps = stin__pass_defaults;
        int n = 0;
        ps.depth_write = 0;
        ps.color_write = 0;
        ps.stencil_test = 1;
        ps.front.func = GL_LEQUAL; /* passes where the threshold <= the stencil */
        ps.front.mask = 0xffu;
        ps.front.fail = ps.front.zfail = ps.front.zpass = GL_KEEP;
        while (n < STIN__CSG_MERGE_THRESHOLDS && thresholds[n] <= limit) {
            ps.front.ref = (GLint)thresholds[n];
            ps.back = ps.front;
            GL_ENUM(ctx, BeginQuery, target)(target, m->queries[n]);
            kill_quad(ctx, &ps);
            GL_ENUM(ctx, EndQuery, target)(target);
            n++;
        }
        for (i = 0; i < (size_t)n; i++) /* in order: the first read waits, the rest follow */
            GL(ctx, GetQueryObjectuiv)(m->queries[i], GL_QUERY_RESULT, &passed[i]);
        ctx->stats.passes++;
        resume(ctx, path);
        return bound_of(passed, n, limit);
    }
    if (ctx->csg->no_readback) /* nothing to count with: the bound itself */
        return limit;
    stin__csg_read_stencil(ctx, r);
    for (y = 0; y < g.rows; y++)
        for (x = 0; x < g.width; x++) {
            i = g.first + y * g.stride + x;
            most = r->stencil[i] > most ? r->stencil[i] : most;
        }
    return most < limit ? most : limit;
}
