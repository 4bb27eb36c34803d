/* SPDX-License-Identifier: MIT */
/* VDSM step DC's receivers by storage-buffer atomics (GL 4.3). The pyramid
 * (shadow/vdsm_pyramid.c) needs per light texel the deepest receiver: the
 * deepest light depth of the position buffer's points that fall in it. On
 * GL 3.2 it draws one point per pixel, MAX-blended into its accumulation.
 * llvmpipe runs those points' vertex stage and set-up on one thread, and it
 * took about half of the pyramid's time (docs/benchmarks.md). Here one
 * full-viewport quad does the same work in the fragment stage
 * (shaders/gl4/vdsm_receiver_atomic.frag): each pixel's point goes to the
 * texel its point would cover, its depth kept by an atomic maximum of bits
 * ordered as the floats are, in a buffer of one word a texel (0: none).
 * Level 0 of the pyramid then reads them (vdsm_reduce_first.frag) and sets
 * each word back to 0, so the next light starts from none without a clear.
 * The quad reads the position buffer where the light's facing pass would:
 * it writes that pass's mask channel too, and vdsm draws no facing pass. */
#include "shadow/vdsm_private.h"

void stin__vdsm_receivers_release(stin_context *ctx)
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    GLuint none = 0;
    stin__vdsm_delete_programs(ctx, &p->atomic_prog, &p->first_prog, &none);
    if (p->deepest)
        GL(ctx, DeleteBuffers)(1, &p->deepest);
    p->deepest = 0;
}

static const stin__uniform_name atomic_uniforms[] = {
    STIN__UNIFORM(stin__vdsm_pyramid, a_position, "u_position"),
    STIN__UNIFORM(stin__vdsm_pyramid, a_normal, "u_normal"),
    STIN__UNIFORM(stin__vdsm_pyramid, a_shading, "u_shading"),
    STIN__UNIFORM(stin__vdsm_pyramid, a_light, "u_light"),
    STIN__UNIFORM(stin__vdsm_pyramid, a_vp, "u_light_vp"),
    STIN__UNIFORM(stin__vdsm_pyramid, a_depth, "u_depth_row"),
    STIN__UNIFORM(stin__vdsm_pyramid, a_size, "u_size"),
};

static const stin__uniform_name first_uniforms[] = {
    STIN__UNIFORM(stin__vdsm_pyramid, f_source, "u_source"),
    STIN__UNIFORM(stin__vdsm_pyramid, f_size, "u_size"),
};

static void locate(stin_context *ctx)
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    STIN__LOCATE(ctx, p->atomic_prog, p, atomic_uniforms);
    STIN__LOCATE(ctx, p->first_prog, p, first_uniforms);
}

int stin__vdsm_receivers_init(stin_context *ctx)
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    char msg[160];
    if (!(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_COMPUTE)) || !p->usable)
        return 0;
    msg[0] = '\0';
    p->atomic_prog = stin__vdsm_program(ctx, "gl4/screen.vert", NULL,
                                        "gl4/vdsm_receiver_atomic.frag", NULL, 0, msg, sizeof msg);
    if (p->atomic_prog)
        p->first_prog = stin__vdsm_program(ctx, "gl4/screen.vert", NULL,
                                           "gl4/vdsm_reduce_first.frag", NULL, 0, msg, sizeof msg);
    if (!p->first_prog) {
        stin__vdsm_receivers_release(ctx);
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "vdsm: the receivers' atomic pass failed to build (%s): they are drawn as "
                  "points", msg);
        return 0;
    }
    locate(ctx);
    return 1;
}

/* The words, all 0, at the first pass: made inside a frame, whose contract
 * lets storage bindings end at 0 (stin_create leaves the caller's). */
static void make_words(stin_context *ctx)
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    static const GLuint none = 0;
    GL(ctx, GenBuffers)(1, &p->deepest);
    GL(ctx, BindBuffer)(GL_SHADER_STORAGE_BUFFER, p->deepest);
    GL(ctx, BufferData)(GL_SHADER_STORAGE_BUFFER,
                        (GLsizeiptr)((size_t)p->size * (size_t)p->size * 4u), NULL,
                        GL_DYNAMIC_COPY);
    GL(ctx, ClearBufferData)(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT,
                             &none);
    GL(ctx, BindBuffer)(GL_SHADER_STORAGE_BUFFER, 0);
}

/* With the pyramid's framebuffer bound and its blending off: the pass
 * over the frame's viewport in the screen mask's framebuffer, which is
 * also the light's facing pass into mask channel `channel`, then the
 * pyramid's framebuffer and viewport again. */
void stin__vdsm_receivers_draw(stin_context *ctx, const float light[4], int channel)
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    const int *vp = ctx->frame.viewport;
    stin__pass_state before = *stin__pass_current(ctx), ps = before;
    if (!p->deepest)
        make_words(ctx);
    ps.color_write = 1;
    ps.color_only = (unsigned char)(channel + 1);
    ps.scissor = 0; /* the pyramid's scissor box is not the frame's viewport */
    stin__pass_apply(ctx, &ps);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, stin__mask_target_of(ctx).fbo);
    GL(ctx, Viewport)(vp[0], vp[1], vp[2], vp[3]);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, ctx->vdsm->position);
    stin__bind_unit(ctx, 1, GL_TEXTURE_2D, ctx->vdsm->normal);
    stin__bind_unit(ctx, 2, GL_TEXTURE_2D, ctx->vdsm->shading);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, UseProgram)(p->atomic_prog);
    GL(ctx, Uniform1i)(p->a_position, 0);
    GL(ctx, Uniform1i)(p->a_normal, 1);
    GL(ctx, Uniform1i)(p->a_shading, 2);
    GL(ctx, Uniform4fv)(p->a_light, 1, light);
    GL(ctx, UniformMatrix4fv)(p->a_vp, 1, GL_FALSE, p->view_proj);
    GL(ctx, Uniform4fv)(p->a_depth, 1, p->depth_row);
    GL(ctx, Uniform1i)(p->a_size, p->size);
    GL(ctx, BindBufferBase)(GL_SHADER_STORAGE_BUFFER, 0, p->deepest);
    /* the last level 0's resets land before this pass's maxima */
    GL(ctx, MemoryBarrier)(GL_SHADER_STORAGE_BARRIER_BIT);
    stin__screen_quad(ctx);
    GL(ctx, MemoryBarrier)(GL_SHADER_STORAGE_BARRIER_BIT);
    GL(ctx, BindBufferBase)(GL_SHADER_STORAGE_BUFFER, 0, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, p->fbo);
    GL(ctx, Viewport)(0, 0, p->size, p->size);
    stin__pass_apply(ctx, &before);
    ctx->stats.shadows.vdsm_atomic_receivers++;
}

/* Level 0 (attached, its viewport set) from the accumulation and the
 * receivers' words (once made: the first pass makes them); the program is
 * the caller's to set again. */
void stin__vdsm_receivers_first_level(stin_context *ctx)
{
    stin__vdsm_pyramid *p = &ctx->vdsm->pyramid;
    GL(ctx, UseProgram)(p->first_prog);
    GL(ctx, Uniform1i)(p->f_source, 0);
    GL(ctx, Uniform1i)(p->f_size, p->size);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, p->accum);
    GL(ctx, BindBufferBase)(GL_SHADER_STORAGE_BUFFER, 0, p->deepest);
    stin__screen_quad(ctx);
    GL(ctx, BindBufferBase)(GL_SHADER_STORAGE_BUFFER, 0, 0);
}
