/* SPDX-License-Identifier: MIT */
/* The CSG resolve: the frame's products into its depth buffer (after the
 * target's clear, before the ambient pass), each by the first method of
 * the chain that takes it: interval (csg/interval.c) where the technique is
 * interval and the product fits its limits, scs (csg/scs.c) where the
 * technique is scs or interval and its primitives are convex, else
 * goldfeather (csg/goldfeather.c). The candidates and the result are kept
 * on the GPU (csg/merge.c: on GLSL tiers with FBOs and depth textures) or
 * on the CPU (csg/pixels.c). The result goes into the frame's depth buffer
 * (depth ALWAYS over what the buffer held before, itself copied first and
 * kept in the minimum, so earlier products and a caller's keep_contents depth
 * stay): from the GPU by the faces snapped onto it (onto the result, or in
 * a direct resolve each candidate's onto its own depth, or resolved in the
 * frame's own buffers in place), from the CPU as csg/pixels.c writes it.
 * The primitives' faces on the resolved depth are then drawn like any
 * draw, depth EQUAL (csg/csg.c's face draws). */
#include "csg/csg_private.h"

typedef stin__csg_pixels resolve; /* csg.h */

/* Whether this frame can resolve its products (on the GPU where gpu asks);
 * logs once per reason. */
static int usable(stin_context *ctx, resolve *r, int gpu)
{
    const char *why = NULL;
    if (ctx->sel.choice[STIN_FEATURE_CSG].technique == STIN_TECH_CSG_OFF)
        why = "the CSG technique is csg-off";
    else if (ctx->target.stencil_bits < 1 || !stin__target_has_stencil(ctx))
        why = "the frame's framebuffer has no stencil buffer";
    else if (!gpu && ctx->csg->no_readback)
        why = "the read-back resolve reads depth and stencil, which OpenGL ES does only "
              "with GL_NV_read_depth_stencil";
    else if (gpu ? !stin__csg_pixels_gpu(ctx, r) : !stin__csg_pixels_at(ctx, 0, r))
        why = gpu ? "the viewport needs more than the texture staging (1 byte a pixel; raise "
                    "desc.max_texture_bytes)"
                  : "the viewport needs more than the texture staging (9 bytes a pixel; raise "
                    "desc.max_texture_bytes)";
    if (why) {
        if (!ctx->csg->said_unusable) {
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                      "CSG products are not drawn: %s", why);
            ctx->csg->said_unusable = 1;
        }
        return 0;
    }
    return 1;
}

void stin__csg_resolve_pixels(stin_context *ctx, const stin__path *path, resolve *r)
{
    stin__unpack_saved saved; /* the caller's pack state */
    uint32_t pi;
    stin__pack_begin(ctx, &saved);
    stin__csg_region_reset(ctx); /* this resolve's viewport (a light's band, csg/cast.c) */
    if (!r->gpu) /* what the buffer holds stays where nearer (the GPU's: merge_begin) */
        stin__csg_read_depth(ctx, r, r->result);
    ctx->csg->cap_usable = ctx->csg->cap_slot != STIN__NO_SLOT &&
                           stin__csg_cap_transform(ctx, ctx->csg->cap_transform);
    path->geometry_begin(ctx);
    for (pi = 0; pi < ctx->csg->product_count; pi++) {
        stin__csg_product *p = &ctx->csg->products[pi];
        p->capped = 0;
        stin__csg_region_reset(ctx); /* scs and goldfeather narrow it on the GPU */
        if (!stin__csg_interval_product(ctx, path, r, p) &&
            !stin__csg_scs_product(ctx, path, r, p))
            stin__csg_goldfeather_product(ctx, path, r, p);
    }
    stin__csg_region_reset(ctx);
    path->geometry_end(ctx);
    stin__pack_end(ctx, &saved);
}

int stin__csg_resolve(stin_context *ctx, const stin__path *path)
{
    resolve r;
    int gpu = stin__csg_merge_ready(ctx);
    ctx->csg->resolved = ctx->csg->merged = ctx->csg->result_pending = 0;
    if (!ctx->csg->product_count || !usable(ctx, &r, gpu))
        return 0;
    ctx->csg->resolve_fbo = ctx->draw_fbo;
    stin__csg_region_reset(ctx);
    if (gpu && stin__csg_packed(ctx)) { /* no depth textures: nothing else runs */
        if (!stin__csg_packed_begin(ctx))
            return 0;
        stin__csg_resolve_pixels(ctx, path, &r);
        stin__csg_packed_end(ctx);
        ctx->csg->resolved = ctx->csg->merged = 1;
        stin__csg_faces(ctx);
        stin__csg_merge_snap(ctx);
        return 1;
    }
    if (gpu && stin__csg_in_place_fits(ctx) && stin__csg_in_place_begin(ctx)) {
        stin__csg_resolve_pixels(ctx, path, &r);
        stin__csg_in_place_end(ctx);
        ctx->csg->resolved = ctx->csg->merged = 1;
        return 1;
    }
    if (gpu && stin__csg_direct_fits(ctx) && stin__csg_direct_begin(ctx)) {
        stin__csg_resolve_pixels(ctx, path, &r);
        stin__csg_direct_end(ctx);
        ctx->csg->resolved = ctx->csg->merged = 1;
        return 1;
    }
    if (!gpu && ctx->target.multisampled) /* through a single-sampled copy */
        return stin__csg_msaa_resolve(ctx, path, &r);
    /* its framebuffers failed (logged): the CPU's, if the staging holds it
     * and the frame's buffers can be read back (not multisampled) */
    if (gpu && !stin__csg_merge_begin(ctx) && (ctx->target.multisampled || !usable(ctx, &r, 0)))
        return 0;
    stin__csg_resolve_pixels(ctx, path, &r);
    ctx->csg->resolved = 1;
    ctx->csg->merged = r.gpu;
    if (r.gpu) { /* the frame's buffers untouched so far: the faces on the result */
        ctx->csg->resolve_fbo = ctx->draw_fbo;
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
        stin__csg_faces(ctx);
        stin__csg_merge_snap(ctx);
        return 1;
    }
    stin__csg_write_depth(ctx, path, &r, GL_ALWAYS);
    stin__csg_clear(ctx, GL_STENCIL_BUFFER_BIT);
    return 1;
}

GLuint stin__csg_depth_texture(stin_context *ctx, int origin[2])
{
    resolve r;
    if (!ctx->csg->resolved || ctx->csg->merge.packed) /* packed: no depth to sample */
        return 0;
    origin[0] = origin[1] = 0;
    if (ctx->csg->merged) {
        GLuint result;
        stin__csg_merge_result_ready(ctx);
        result = stin__csg_merge_result(ctx);
        stin__bind_unit(ctx, 0, GL_TEXTURE_2D, result);
        return result;
    }
    if (!ctx->csg->depth_tex || !usable(ctx, &r, 0))
        return 0;
    if (!ctx->csg->depth_prog) /* compatibility profiles wrote it with glDrawPixels */
        stin__csg_upload_result(ctx, &r);
    else
        stin__bind_unit(ctx, 0, GL_TEXTURE_2D, ctx->csg->depth_tex);
    origin[0] = r.x;
    origin[1] = r.y;
    return ctx->csg->depth_tex;
}

/* The resolved depth again into the bound framebuffer, depth LESS against
 * what it holds (the screen mask's copy of the frame's depth). */
void stin__csg_depth_again(stin_context *ctx, const stin__path *path)
{
    resolve r;
    if (!ctx->csg->resolved)
        return;
    if (ctx->csg->merged) {
        stin__csg_merge_result_ready(ctx);
        stin__csg_merge_snap(ctx);
    } else if (usable(ctx, &r, 0)) {
        stin__csg_write_depth(ctx, path, &r, GL_LESS);
    }
}

static const stin__uniform_name depth_uniforms[] = {
    STIN__UNIFORM(stin__csg_state, u_depth, "u_depth"),
    STIN__UNIFORM(stin__csg_state, u_origin, "u_origin"),
};

void stin__csg_init(stin_context *ctx)
{
    stin__csg_state *c = ctx->csg;
    char msg[160], why[200];
    const char *gpu_alone = "OpenGL ES reads depth and stencil back only with "
                            "GL_NV_read_depth_stencil";
    /* GLSL ES 3.00 has gl_FragDepth and texelFetch: the depth program
     * builds on every ES 3.x context, whichever lighting it chose */
    int gl4 = ctx->sel.choice[STIN_FEATURE_LIGHTING].technique == STIN_TECH_LIGHTING_GLSL150 ||
              (ctx->caps.es && ctx->caps.glsl_major >= 3);
    c->cap_slot = STIN__NO_SLOT;
    if (ctx->sel.choice[STIN_FEATURE_CSG].technique == STIN_TECH_CSG_OFF)
        return;
    if (!(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FIXED_FUNCTION)) && !gl4 && !ctx->caps.es) {
        stin__demote(ctx, STIN_FEATURE_CSG, STIN_TECH_CSG_OFF,
                     "goldfeather and scs write depth with glDrawPixels (compatibility "
                     "profile) or a GLSL 1.50 / GLSL ES 3.00 program (GL4 lighting, "
                     "OpenGL ES 3.0+)");
        return;
    }
    if (!(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FIXED_FUNCTION)) && !gl4) {
        /* OpenGL ES 2.0: no program writes read-back depth again (GLSL ES
         * 1.00 has no texelFetch, ES 2.0 no float textures): as without
         * the read-back, the camera's products take the GPU resolve alone */
        c->no_readback = 1;
        gpu_alone = "OpenGL ES 2.0 writes no read-back depth again";
    } else if (!(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FIXED_FUNCTION))) {
        /* the read-back resolves (light maps', STIN_DEBUG_CSG_READBACK,
         * no GPU resolve) read depth and stencil, which core ES cannot: there
         * the camera's products take the GPU resolve alone (checked below,
         * once it is built), and so do the lights' maps (csg/cast.c) */
        c->no_readback = ctx->caps.es && !stin_query_extension(ctx, "GL_NV_read_depth_stencil");
        c->depth_prog = stin__program_build(ctx, "gl4/screen.vert", "gl4/csg_depth.frag",
                                            NULL, 0, msg, sizeof msg);
        if (!c->depth_prog) {
            stin__formatf(why, sizeof why, "its depth program failed to build (%s)", msg);
            stin__demote(ctx, STIN_FEATURE_CSG, STIN_TECH_CSG_OFF, why);
            return;
        }
        STIN__LOCATE(ctx, c->depth_prog, c, depth_uniforms);
    }
    /* the R32F texture of the resolved depth (core profiles write the depth
     * through it; vdsm's position buffer reads it), made at its first upload */
    if (gl4)
        GL(ctx, GenTextures)(1, &c->depth_tex);
    stin__csg_cap_init(ctx);
    stin__csg_merge_init(ctx);
    if (c->no_readback && !stin__csg_merge_ready(ctx)) {
        stin__csg_release(ctx);
        stin__formatf(why, sizeof why, "%s, and %s",
                      ctx->desc.debug_flags & STIN_DEBUG_CSG_READBACK
                          ? "STIN_DEBUG_CSG_READBACK resolves by read-back"
                          : "its GPU resolve did not build",
                      gpu_alone);
        stin__demote(ctx, STIN_FEATURE_CSG, STIN_TECH_CSG_OFF, why);
        return;
    }
    if (c->no_readback)
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                  "CSG: %s: products resolve on the GPU alone (from the lights too, where "
                  "depth textures are), and scs and goldfeather count no layers (they run "
                  "to their limits)",
                  gpu_alone);
}

void stin__csg_release(stin_context *ctx)
{
    stin__csg_state *c = ctx->csg;
    stin__csg_cast_release(ctx);
    stin__csg_merge_release(ctx);
    if (c->depth_prog)
        GL(ctx, DeleteProgram)(c->depth_prog);
    if (c->depth_tex)
        GL(ctx, DeleteTextures)(1, &c->depth_tex);
    c->depth_prog = c->depth_tex = 0;
}
