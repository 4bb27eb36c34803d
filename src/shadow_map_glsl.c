/* Shadow maps with percentage-closer filtering on the GLSL tiers ("map-pcf").
 *
 * Every spot and directional light gets a depth map (an FBO with a depth
 * texture, compare mode LEQUAL, LINEAR: each tap is the hardware's 2x2 PCF)
 * drawn before the camera's passes; a point light gets six 90-degree maps,
 * drawn just before its lit pass into six shared textures, and the shader
 * picks the face by the major axis of the light-to-point direction. The lit
 * pass's shadow_pcf.glsl chunk pushes the point along its geometric normal
 * (normal-offset bias, about 1.5 texels), projects it, and averages a
 * (2r+1)^2 kernel (r = the light's pcf_radius). Maps are drawn with polygon
 * offset (the light's shadow_offset: slope-scaled bias). */
#include "internal.h"

#define FACE_SLOT 32u

int stin__pcf_active(const stin_context *ctx)
{
    return ctx->sel.choice[STIN_FEATURE_SHADOWS].technique == STIN_TECH_SHADOWS_MAP_PCF;
}

static void create_depth_texture(stin_context *ctx, GLuint *t, uint32_t size)
{
    GL(ctx, GenTextures)(1, t);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, *t);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    GL_ENUM(ctx, TexParameteri, GL_TEXTURE_COMPARE_MODE)(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE,
                                                         GL_COMPARE_R_TO_TEXTURE);
    GL_ENUM(ctx, TexParameteri, GL_TEXTURE_COMPARE_FUNC)(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC,
                                                         GL_LEQUAL);
    GL_ENUM(ctx, TexImage2D, GL_DEPTH_COMPONENT24)(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24,
                                                   (GLsizei)size, (GLsizei)size, 0,
                                                   GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
}

stin_result stin__pcf_init(stin_context *ctx)
{
    uint32_t i, size = ctx->desc.shadow_map_size;
    if (!stin__pcf_active(ctx))
        return STIN_OK;
    if (ctx->caps.max_texture_size > 0 && size > (uint32_t)ctx->caps.max_texture_size)
        size = (uint32_t)ctx->caps.max_texture_size;
    ctx->maps.size = ctx->maps.used = size;
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    for (i = 0; i < ctx->desc.max_lights; i++)
        create_depth_texture(ctx, &ctx->maps.textures[i], size);
    for (i = 0; i < 6; i++)
        create_depth_texture(ctx, &ctx->maps.textures[FACE_SLOT + i], size);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL(ctx, GenFramebuffers)(1, &ctx->maps.fbo);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->maps.fbo);
    GL(ctx, DrawBuffer)(GL_NONE); /* depth only */
    GL(ctx, ReadBuffer)(GL_NONE);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, 0);
    ctx->maps.faces = 1;
    stin__gl_check_errors(ctx, "pcf set-up");
    return STIN_OK;
}

/* world -> [0,1] texture space: bias * projection * view */
static void store_matrix(stin_context *ctx, uint32_t slot, const float view[16],
                         const float proj[16])
{
    float vp[16], bias[16];
    stin__mat4_mul(vp, proj, view);
    stin__mat4_identity(bias);
    bias[0] = bias[5] = bias[10] = 0.5f;
    bias[12] = bias[13] = bias[14] = 0.5f;
    stin__mat4_mul(ctx->maps.texgen[slot], bias, vp);
}

static void offsets(stin_context *ctx, const stin_light_desc *l)
{
    float factor = l->shadow_offset[0], units = l->shadow_offset[1];
    if (l->shadow_offset_off) {
        GL_DISABLE(ctx, GL_POLYGON_OFFSET_FILL);
        return;
    }
    if (factor == 0.0f && units == 0.0f) {
        factor = 1.1f;
        units = 4.0f;
    }
    GL_ENABLE(ctx, GL_POLYGON_OFFSET_FILL);
    GL(ctx, PolygonOffset)(factor, units);
}

static void draw_map(stin_context *ctx, uint32_t slot, const stin_light_desc *l,
                     const float view[16], const float proj[16])
{
    float vp[16];
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->maps.fbo);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D,
                                  ctx->maps.textures[slot], 0);
    GL(ctx, Viewport)(0, 0, (GLsizei)ctx->maps.size, (GLsizei)ctx->maps.size);
    GL_DISABLE(ctx, GL_SCISSOR_TEST);
    GL_DISABLE(ctx, GL_BLEND);
    GL_DISABLE(ctx, GL_STENCIL_TEST);
    GL(ctx, DepthMask)(GL_TRUE);
    GL(ctx, ClearDepth)(1.0);
    GL(ctx, Clear)(GL_DEPTH_BUFFER_BIT);
    GL_ENABLE(ctx, GL_DEPTH_TEST);
    GL(ctx, DepthFunc)(GL_LESS);
    GL(ctx, ColorMask)(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    offsets(ctx, l);
    stin__mat4_mul(vp, proj, view);
    stin__glsl_draw_depth(ctx, vp);
    GL_DISABLE(ctx, GL_POLYGON_OFFSET_FILL);
    GL(ctx, ColorMask)(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->frame.framebuffer);
    GL(ctx, Viewport)(ctx->frame.viewport[0], ctx->frame.viewport[1], ctx->frame.viewport[2],
                      ctx->frame.viewport[3]);
    store_matrix(ctx, slot, view, proj);
    ctx->stats.passes++;
}

/* About 1.5 texels in world units where the receivers are. */
static float texel_offset(const stin_light_desc *l, float n, float f, const float proj[16],
                          uint32_t size)
{
    float across = l->type == STIN_LIGHT_DIRECTIONAL ? 2.0f / proj[0]
                                                      : (n + f) / proj[0];
    return 1.5f * across / (float)size;
}

void stin__pcf_render(stin_context *ctx)
{
    uint32_t i;
    ctx->stats.shadow_map_size = ctx->maps.size;
    for (i = 0; i < ctx->light_count && i < 32; i++) {
        const stin_light_desc *l = &ctx->lights[i];
        float view[16], proj[16], n, f;
        ctx->maps.valid[i] = 0;
        if (l->type == STIN_LIGHT_POINT)
            continue; /* its faces are drawn before its own pass */
        if (!stin__light_camera(ctx, l, view, proj, &n, &f, ctx->maps.size))
            continue;
        draw_map(ctx, i, l, view, proj);
        ctx->maps.ramp_plane[i][0] = texel_offset(l, n, f, proj, ctx->maps.size);
        ctx->maps.valid[i] = 1;
    }
    stin__gl_check_errors(ctx, "pcf maps");
}

static const float face_axis[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                      {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

int stin__pcf_point(stin_context *ctx, uint32_t li)
{
    const stin_light_desc *l = &ctx->lights[li];
    int face, any = 0;
    float worst = 0.0f;
    for (face = 0; face < 6; face++) {
        float view[16], proj[16], n, f, half, center[3];
        uint32_t slot = FACE_SLOT + (uint32_t)face;
        stin__light_look_along(view, l->position, face_axis[face]);
        stin__light_fit(ctx, view, 0, &n, &f, &half, center);
        if (f <= 0.0f) { /* nothing in front: an empty face */
            f = 1.0f;
            n = 1e-3f;
        }
        if (n < f * 1e-3f)
            n = f * 1e-3f;
        /* the shader picks the face by the major axis, so 90 degrees exactly */
        stin__light_perspective(proj, 90.0f, n, f);
        draw_map(ctx, slot, l, view, proj);
        if (texel_offset(l, n, f, proj, ctx->maps.size) > worst)
            worst = texel_offset(l, n, f, proj, ctx->maps.size);
        any = 1;
    }
    ctx->maps.ramp_plane[FACE_SLOT][0] = worst;
    return any;
}

/* Uniforms and textures of the lit pass's shadow test: kind 0 (none),
 * 1 (the light's map) or 2 (a point light's faces). */
void stin__pcf_apply(stin_context *ctx, const stin__program *p, int kind, uint32_t li)
{
    const int unit_base = 3; /* albedo 0, normal map 1, height map 2 */
    float params[4] = {0, 0, 0, 0}, mats[6 * 16];
    int i, count = kind == 2 ? 6 : 1;
    if (p->u_shadow_kind < 0)
        return;
    GL(ctx, Uniform1i)(p->u_shadow_kind, kind);
    /* every shadow sampler on a unit of its own, used or not: two samplers
     * of different types on one unit are an error at draw time */
    for (i = 0; i < 6; i++)
        GL(ctx, Uniform1i)(p->u_shadow_maps[i], unit_base + i);
    if (kind == 0)
        return;
    for (i = 0; i < count; i++) {
        uint32_t slot = kind == 2 ? FACE_SLOT + (uint32_t)i : li;
        stin__memcopy(mats + 16 * i, ctx->maps.texgen[slot], 16 * sizeof(float));
        GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + unit_base + i));
        GL(ctx, BindTexture)(GL_TEXTURE_2D, ctx->maps.textures[slot]);
    }
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, UniformMatrix4fv)(p->u_shadow_matrix, count, GL_FALSE, mats);
    params[0] = 1.0f / (float)ctx->maps.size;
    params[1] = (float)(ctx->lights[li].pcf_kernel / 2u);
    params[2] = ctx->maps.ramp_plane[kind == 2 ? FACE_SLOT : li][0];
    GL(ctx, Uniform4fv)(p->u_shadow_params, 1, params);
}
