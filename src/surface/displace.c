/* SPDX-License-Identifier: MIT */
/* Displacement "displace" (GL2/GL4): vertex texture fetch of the material's
 * height map in every vertex stage that draws meshes (shaders/gl2/
 * displace.glsl, spliced in by gl/shader.c), so the lit, ambient, flat and
 * normal passes, shadow-map depth and vdsm's buffers all see one displaced
 * surface; "displace-tess" (GL4 with tessellation) runs the same vertex
 * shaders as evaluation stages behind gl4/tess.tesc's screen-space edge
 * levels. Here: the per-frame tessellation scale, the tessellated programs
 * swapped in for frames with displaced draws, and the step down beside a
 * technique it conflicts with (stencil volumes); the chunk every program
 * carries is render/displace_chunk.c's. */
#include "internal.h"

struct stin__displace_state {
    GLint caller_patch_vertices;
    int tessellating;     /* this frame draws with the tessellated programs */
};

size_t stin__displace_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(struct stin__displace_state);
}

/* 1 when a draw of the frame is displaced. */
static int frame_displaces(const stin_context *ctx)
{
    uint32_t i;
    for (i = 0; i < ctx->draw_count; i++)
        if (stin__displace_active(ctx, &ctx->draws[i].material))
            return 1;
    return 0;
}

void stin__displace_frame_begin(stin_context *ctx)
{
    const float *view = ctx->frame.view, *proj = ctx->frame.projection;
    float inv[16], tess[4], eye[3];
    GLint levels = ctx->caps.max_tess_gen_level > 0 ? ctx->caps.max_tess_gen_level : 64;
    GLint cap = (GLint)ctx->desc.displacement.tess_max;
    int k;
    if (!stin__displace_built(ctx))
        return;
    /* pixels a unit spans at eye distance 1 (perspective) or anywhere
     * (orthographic): the projection's y scale over half the viewport */
    tess[0] = proj[5] * 0.5f * (float)ctx->frame.viewport[3];
    tess[1] = ctx->desc.displacement.tess_pixels;
    tess[2] = (float)(cap < levels ? cap : levels);
    tess[3] = proj[11] != 0.0f ? 1.0f : 0.0f;
    if (!stin__mat4_invert(inv, view))
        stin__mat4_identity(inv); /* begin checked the view: not reached */
    for (k = 0; k < 3; k++)
        eye[k] = inv[12 + k];
    stin__displace_frame_scale(ctx, tess, eye);
    if (!stin__displace_tessellated(ctx) || !frame_displaces(ctx))
        return;
    /* only frames with displaced draws pay for tessellation stages */
    stin__glsl_tessellate(ctx, 1);
    if (ctx->shadow->tessellate)
        ctx->shadow->tessellate(ctx, 1);
    ctx->displace->tessellating = 1;
    GL(ctx, GetIntegerv)(GL_PATCH_VERTICES, &ctx->displace->caller_patch_vertices);
    GL(ctx, PatchParameteri)(GL_PATCH_VERTICES, 3);
}

void stin__displace_frame_end(stin_context *ctx)
{
    if (!ctx->displace->tessellating)
        return;
    stin__glsl_tessellate(ctx, 0);
    if (ctx->shadow->tessellate)
        ctx->shadow->tessellate(ctx, 0);
    ctx->displace->tessellating = 0;
    if (ctx->displace->caller_patch_vertices > 0)
        GL(ctx, PatchParameteri)(GL_PATCH_VERTICES, ctx->displace->caller_patch_vertices);
}

/* Selection kept displacement from what it conflicts with (the technique
 * table: volume, whose silhouettes are the undisplaced mesh's, where it has
 * no depth map to cast them through), but another
 * feature's set-up may have fallen back onto such a technique since. */
void stin__displace_init(stin_context *ctx)
{
    stin_technique clash = stin__choice_conflict(&ctx->caps, &ctx->sel,
                                                 STIN_FEATURE_DISPLACEMENT);
    char why[200];
    if (!stin__displace_built(ctx) || clash == STIN_TECH_NONE)
        return;
    stin__formatf(why, sizeof why,
                  "%s fell back to %s, which cannot run beside it: displaced draws would "
                  "be shadowed as the flat mesh",
                  stin_feature_name(stin__technique_feature(clash)), stin_technique_name(clash));
    stin__demote(ctx, STIN_FEATURE_DISPLACEMENT, STIN_TECH_DISPLACEMENT_OFF, why);
}

