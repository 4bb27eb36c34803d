/* SPDX-License-Identifier: MIT */
/* VDSM's position buffer: a frame stage that draws the visible surface once
 * into two float textures - world position (RGBA32F, w 1 where something was
 * drawn), the facet normal turned to the eye and the shading normal turned
 * with it (RGBA16F each; the terminator rule, vdsm_position.frag) - the size of the
 * viewport's far corner, so gl_FragCoord addresses it directly. Exact
 * positions, not depth reconstruction: a 24-bit depth buffer holds the eye
 * distance to about 1e-7 of the far/near ratio, too coarse for contact
 * shadows, while the float buffer holds the interpolated position itself. */
#include "shadow/vdsm_private.h"

void stin__vdsm_buffer_release(stin_context *ctx)
{
    struct stin__vdsm_state *v = ctx->vdsm;
    GLuint tex[4];
    int i, n = 0;
    if (v->fbo)
        GL(ctx, DeleteFramebuffers)(1, &v->fbo);
    tex[0] = v->position;
    tex[1] = v->normal;
    tex[2] = v->shading;
    tex[3] = v->depth;
    for (i = 0; i < 4; i++)
        if (tex[i])
            tex[n++] = tex[i];
    if (n)
        GL(ctx, DeleteTextures)(n, tex);
    v->fbo = v->position = v->normal = v->shading = v->depth = 0;
    v->width = v->height = 0;
}

/* Grows the buffer to the viewport's far corner; 0 if the framebuffer is
 * incomplete (logged once; the buffer is released). */
static int ensure_size(stin_context *ctx)
{
    static const GLenum all[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1,
                                  GL_COLOR_ATTACHMENT2};
    struct stin__vdsm_state *v = ctx->vdsm;
    const int *vp = ctx->frame.viewport;
    int w = vp[0] + vp[2], h = vp[1] + vp[3];
    GLenum status;
    if (v->fbo && w <= v->width && h <= v->height)
        return 1;
    if (!v->fbo) {
        GL(ctx, GenFramebuffers)(1, &v->fbo);
        GL(ctx, GenTextures)(1, &v->position);
        GL(ctx, GenTextures)(1, &v->normal);
        GL(ctx, GenTextures)(1, &v->shading);
        GL(ctx, GenTextures)(1, &v->depth);
    }
    w = w > v->width ? w : v->width;
    h = h > v->height ? h : v->height;
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    stin__rt_texture(ctx, v->position, GL_RGBA32F, GL_RGBA, GL_FLOAT, w, h);
    stin__rt_texture(ctx, v->normal, GL_RGBA16F, GL_RGBA, GL_FLOAT, w, h);
    stin__rt_texture(ctx, v->shading, GL_RGBA16F, GL_RGBA, GL_FLOAT, w, h);
    stin__rt_texture(ctx, v->depth, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, w, h);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, v->fbo);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                  v->position, 0);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D,
                                  v->normal, 0);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D,
                                  v->shading, 0);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, v->depth,
                                  0);
    GL(ctx, DrawBuffers)(3, all); /* framebuffer state: set once */
    status = GL(ctx, CheckFramebufferStatus)(GL_FRAMEBUFFER);
    v->width = w;
    v->height = h;
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        if (!v->said_failed)
            stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FALLBACK,
                      "vdsm: position buffer framebuffer incomplete (0x%x): lights are drawn "
                      "without shadows", (unsigned)status);
        v->said_failed = 1;
        stin__vdsm_buffer_release(ctx);
        return 0;
    }
    return 1;
}

/* The centre of projection of the frame's camera in world space: the null
 * vector of the projection's x, y and w rows, taken back through the view.
 * A perspective eye is a point (w 1); an orthographic one the direction
 * toward it (w 0, eye-space +z). */
static void camera_point(stin_context *ctx, float out[4])
{
    const float *p = ctx->frame.projection;
    float r[3][4], e[4], inv[16], len;
    int i, k;
    for (k = 0; k < 4; k++) {
        r[0][k] = p[4 * k];
        r[1][k] = p[4 * k + 1];
        r[2][k] = p[4 * k + 3];
    }
    for (i = 0; i < 4; i++) { /* e_i = (-1)^i det(the rows without column i) */
        int c[3], n = 0;
        for (k = 0; k < 4; k++)
            if (k != i)
                c[n++] = k;
        e[i] = r[0][c[0]] * (r[1][c[1]] * r[2][c[2]] - r[1][c[2]] * r[2][c[1]]) -
               r[0][c[1]] * (r[1][c[0]] * r[2][c[2]] - r[1][c[2]] * r[2][c[0]]) +
               r[0][c[2]] * (r[1][c[0]] * r[2][c[1]] - r[1][c[1]] * r[2][c[0]]);
        if (i & 1)
            e[i] = -e[i];
    }
    len = stin__sqrtf(e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[3] * e[3]);
    if (!(len > 0.0f))
        len = 1.0f;
    if ((e[3] < 0.0f ? -e[3] : e[3]) > 1e-6f * len) {
        len = e[3];
    } else if (e[2] < 0.0f) {
        len = -len;
        e[3] = 0.0f;
    } else {
        e[3] = 0.0f;
    }
    for (k = 0; k < 4; k++)
        e[k] /= len;
    stin__mat4_invert(inv, ctx->frame.view);
    for (k = 0; k < 4; k++)
        out[k] = inv[k] * e[0] + inv[4 + k] * e[1] + inv[8 + k] * e[2] + inv[12 + k] * e[3];
}

/* The position program with the frame's camera, meshes to be bound again. */
static void use_position_program(stin_context *ctx)
{
    static const float off[4] = {0, 0, 0, 0};
    struct stin__vdsm_state *v = ctx->vdsm;
    GL(ctx, UseProgram)(v->position_prog);
    stin__lit_program_forget(ctx);
    GL(ctx, UniformMatrix4fv)(v->pos_view_proj, 1, GL_FALSE, ctx->view_proj);
    GL(ctx, Uniform4fv)(v->pos_camera, 1, v->camera);
    GL(ctx, Uniform4fv)(v->pos_csg, 1, off);
    ctx->bound_mesh = 0xffffffffu;
}

/* A draw into the position buffer with its normal matrix for the terminator
 * rule (vdsm_position.geom): a zero one keeps the facets where the vertex
 * normals do not describe the drawn surface (displaced, a CSG cap). */
static void submit(stin_context *ctx, const stin__draw *d)
{
    struct stin__vdsm_state *v = ctx->vdsm;
    float nm[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    if (d->csg != STIN__CSG_CAP && !stin__displace_active(ctx, &d->material))
        stin__mat3_normal(nm, d->transform);
    GL(ctx, UniformMatrix3fv)(v->pos_normal_matrix, 1, GL_FALSE, nm);
    stin__glsl_submit_geometry(ctx, v->pos_model, &v->pos_displace, d);
}

/* The stage: the visible surface's positions and normals. For the
 * visibility output blended draws count as surfaces, as in its depth pass. */
void stin__vdsm_buffer_draw(stin_context *ctx)
{
    struct stin__vdsm_state *v = ctx->vdsm;
    const int *vp = ctx->frame.viewport;
    int which = ctx->frame.output == STIN_OUTPUT_VISIBILITY ? STIN__ALL : STIN__OPAQUE;
    stin__pass_state ps = stin__pass_defaults;
    uint32_t i;
    v->ready = 0;
    camera_point(ctx, v->camera);
    if (!ensure_size(ctx))
        return;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, v->fbo);
    GL(ctx, Viewport)(vp[0], vp[1], vp[2], vp[3]);
    stin__pass_apply(ctx, &ps); /* writes on, no scissor: the clear covers the buffer */
    GL(ctx, ClearColor)(0.0f, 0.0f, 0.0f, 0.0f);
    stin__clear_depth(ctx, 1.0);
    GL(ctx, Clear)(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    ps.depth_test = 1;
    ps.depth_func = GL_LESS;
    stin__pass_apply(ctx, &ps);
    use_position_program(ctx);
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        if (which & (d->material.color[3] < 1.0f ? STIN__BLENDED : STIN__OPAQUE))
            submit(ctx, d);
    }
    ctx->stats.passes++;
    v->ready = 1;
}

/* After the CSG resolve (frame/frame.c): the products' surfaces into the position
 * buffer too. The buffer was drawn before the frame's target (a light
 * pre-pass): the products' faces are drawn over it, depth LEQUAL against
 * the draws there, each fragment kept only where it lies on the resolved
 * surface (the shader's test against the resolve's depth texture, within
 * the face's band: render/resolved.h). They write depth as the draws do:
 * into a multisampled target the lit pass finds a fragment's own texel by
 * this depth (render/screen_mask.c), and a product's pixel left at the
 * depth behind it sent its outline to the neighbour below (a halo). */
void stin__vdsm_buffer_csg(stin_context *ctx, const stin__path *path)
{
    struct stin__vdsm_state *v = ctx->vdsm;
    const int *vp = ctx->frame.viewport;
    stin__pass_state ps = stin__pass_defaults, saved;
    GLuint resolved;
    float csg[4] = {0.0f, 0.0f, 1.0f, 0.0f}, band[2];
    int origin[2];
    uint32_t i, count;
    const stin__draw *faces = stin__resolved_faces(ctx, &count);
    (void)path;
    if (!v->ready || !count)
        return;
    resolved = stin__resolved_depth_texture(ctx, origin);
    if (!resolved)
        return;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, v->fbo);
    ps.depth_test = 1;
    ps.depth_func = GL_LEQUAL;
    stin__pass_apply(ctx, &ps);
    use_position_program(ctx);
    GL(ctx, Uniform1i)(v->pos_csg_depth, 0);
    csg[0] = (float)origin[0];
    csg[1] = (float)origin[1];
    for (i = 0; i < count; i++)
        if (stin__resolved_face_begin(ctx, &faces[i], &saved)) {
            stin__resolved_snap_band(ctx, &faces[i], band);
            csg[3] = band[0];
            GL(ctx, Uniform4fv)(v->pos_csg, 1, csg);
            GL(ctx, Uniform1f)(v->pos_csg_grow, band[1]);
            submit(ctx, &faces[i]);
            stin__resolved_face_end(ctx, &saved);
        }
    ctx->bound_mesh = 0xffffffffu;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    GL(ctx, Viewport)(vp[0], vp[1], vp[2], vp[3]);
    ctx->stats.passes++;
}

/* The depth texture a peeled layer is lit against: the depth attachment of
 * the layer's framebuffer (ctx->draw_fbo, bound during its lights), asked
 * of GL so any layer source (depth-peel, or another peeler behind the same
 * layer interface) serves; 0 when it is no texture. */
static GLuint layer_depth(stin_context *ctx)
{
    GLint type = GL_NONE, name = 0;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    GL(ctx, GetFramebufferAttachmentParameteriv)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                                 GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type == GL_TEXTURE)
        GL(ctx, GetFramebufferAttachmentParameteriv)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                                     GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                                                     &name);
    return type == GL_TEXTURE && name > 0 ? (GLuint)name : 0;
}

/* STIN_DEBUG_PEEL_VDSM_UNSHADOWED: the layers are lit unshadowed (once
 * said), for comparing peeling's cost with and without vdsm per layer. */
int stin__vdsm_buffer_layers_begin(stin_context *ctx)
{
    if (!(ctx->desc.debug_flags & STIN_DEBUG_PEEL_VDSM_UNSHADOWED))
        return 1;
    if (!ctx->vdsm->said_unshadowed_layers)
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                  "peeling: STIN_DEBUG_PEEL_VDSM_UNSHADOWED: peeled layers are lit "
                  "unshadowed under vdsm");
    ctx->vdsm->said_unshadowed_layers = 1;
    return 0;
}

/* A peeled layer's surface as the buffer (frame/frame.c, before the layer's
 * lights): the blended draws kept where their window depth lies within
 * 2^-21 of the layer's own depth texture (the shader's test, as for CSG
 * faces), without a depth test. Not depth EQUAL: the position program's
 * geometry stage (the terminator rule) may round the depth otherwise than
 * the lit programs that drew the layer, by far less than that. Pixels the
 * layer leaves empty hold w 0: vdsm tests nothing there. The light's
 * pyramid follows (its receivers are read from this buffer per light). */
void stin__vdsm_buffer_layer(stin_context *ctx)
{
    static const float on_layer[4] = {0.0f, 0.0f, 1.0f, 1.0f / 2097152.0f};
    struct stin__vdsm_state *v = ctx->vdsm;
    const int *vp = ctx->frame.viewport;
    stin__pass_state ps = stin__pass_defaults;
    GLuint depth;
    uint32_t i;
    if (!v->fbo)
        return;
    v->ready = 0;
    depth = layer_depth(ctx);
    if (!depth) {
        if (!v->said_layer)
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                      "vdsm: a peeled layer's depth is no texture: its lights are drawn "
                      "unshadowed");
        v->said_layer = 1;
        return;
    }
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, v->fbo);
    GL(ctx, Viewport)(vp[0], vp[1], vp[2], vp[3]);
    ps.depth_write = 0;
    stin__pass_apply(ctx, &ps);
    GL(ctx, ClearColor)(0.0f, 0.0f, 0.0f, 0.0f);
    GL(ctx, Clear)(GL_COLOR_BUFFER_BIT);
    use_position_program(ctx);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, depth);
    GL(ctx, Uniform1i)(v->pos_csg_depth, 0);
    GL(ctx, Uniform4fv)(v->pos_csg, 1, on_layer);
    GL(ctx, Uniform1f)(v->pos_csg_grow, 0.0f);
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        if (d->material.color[3] < 1.0f)
            submit(ctx, d);
    }
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, 0);
    ctx->bound_mesh = 0xffffffffu;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    GL(ctx, Viewport)(vp[0], vp[1], vp[2], vp[3]);
    ctx->stats.passes++;
    v->ready = 1;
}

/* After the layers: the opaque surfaces into the buffer again, for the
 * stages that still read it (the visibility export's masks). */
void stin__vdsm_buffer_layers_end(stin_context *ctx, const stin__path *path)
{
    const int *vp = ctx->frame.viewport;
    if (!ctx->frame.export_visibility)
        return;
    stin__vdsm_buffer_draw(ctx);
    stin__vdsm_buffer_csg(ctx, path);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    GL(ctx, Viewport)(vp[0], vp[1], vp[2], vp[3]);
}
