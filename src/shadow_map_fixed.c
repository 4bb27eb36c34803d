/* Shadow maps without shaders (the GL1 tier's two map techniques).
 *
 * map-depth: ARB_depth_texture + ARB_shadow. The light's depth (with polygon
 * offset) goes into a depth texture — rendered into an FBO where there is one,
 * else into the frame's own framebuffer before its clear and copied out. The
 * lit pass generates (s, t, r, q) in light clip space by eye-linear texgen and
 * the texture unit compares r/q with the stored depth (LEQUAL), LINEAR filtering
 * giving the hardware's 2x2 PCF, and modulates the light's colour.
 *
 * map-combine: for TNT-class hardware without depth textures. The light's
 * depth is drawn as colour (a 1D ramp indexed by texgen of the light-eye
 * depth, near/far fitted to the scene so 8 bits cover it) and copied into an
 * INTENSITY8 texture. In the lit pass one unit projects the map (stored depth
 * in alpha), the next looks the fragment's own light depth up in the same
 * ramp, and texture_env_combine forms map - own + 0.5 (ADD_SIGNED with
 * ONE_MINUS_SRC_ALPHA); the alpha test GEQUAL 0.5 keeps the lit fragments.
 *
 * Spot lights get a perspective map over their cone, directional lights an
 * orthographic one fitted to the draws. Point lights have no single map: they
 * fall back to stencil volumes (or none) and the log says so once. */
#include "internal.h"

#define RAMP_SIZE 256
/* The face mask's border texel lies just outside the 90-degree square: the
 * face frustum is widened so that the square's edge falls exactly between
 * the border texel and the first inner one (NEAREST sampling). */
#define FACE_MASK 256u

int stin__maps_active(const stin_context *ctx)
{
    stin_technique t = ctx->sel.choice[STIN_FEATURE_SHADOWS].technique;
    return t == STIN_TECH_SHADOWS_MAP_DEPTH || t == STIN_TECH_SHADOWS_MAP_COMBINE;
}

static int combine(const stin_context *ctx)
{
    return ctx->sel.choice[STIN_FEATURE_SHADOWS].technique == STIN_TECH_SHADOWS_MAP_COMBINE;
}

/* map-combine renders into its texture where FBOs and depth textures exist. */
static int combine_fbo(const stin_context *ctx)
{
    uint64_t need = STIN_CAP_BIT(STIN_CAP_FBO) | STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE);
    return combine(ctx) && (ctx->caps.present & need) == need;
}

static uint32_t pow2_at_most(uint32_t n)
{
    uint32_t p = 1;
    while (p * 2u <= n)
        p *= 2u;
    return p;
}

static void create_map_texture(stin_context *ctx, GLuint *t, uint32_t size)
{
    GL(ctx, GenTextures)(1, t);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, *t);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    if (combine(ctx)) {
        /* stored depths must not be averaged: nearest. Rendered into (FBO:
         * RGBA8, colour-renderable, the ramp in every channel) or copied
         * into (INTENSITY8). */
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        GL(ctx, TexImage2D)(GL_TEXTURE_2D, 0, combine_fbo(ctx) ? GL_RGBA8 : GL_INTENSITY8,
                            (GLsizei)size, (GLsizei)size, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE,
                            NULL);
    } else {
        /* compare, then filter: LINEAR is the hardware's 2x2 PCF */
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        GL_ENUM(ctx, TexParameteri, GL_TEXTURE_COMPARE_MODE)(
            GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
        GL_ENUM(ctx, TexParameteri, GL_TEXTURE_COMPARE_FUNC)(GL_TEXTURE_2D,
                                                             GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        GL_ENUM(ctx, TexParameteri, GL_DEPTH_TEXTURE_MODE)(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE,
                                                           GL_INTENSITY);
        GL_ENUM(ctx, TexImage2D, GL_DEPTH_COMPONENT24)(
            GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, (GLsizei)size, (GLsizei)size, 0,
            GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
    }
}

stin_result stin__maps_init(stin_context *ctx)
{
    uint32_t i, size = ctx->desc.shadow_map_size;
    int units = combine(ctx) ? 2 : 1;
    if (!stin__maps_active(ctx))
        return STIN_OK;
    /* after the surface technique's units (DOT3 uses four), else after albedo */
    ctx->maps.unit = ctx->sel.choice[STIN_FEATURE_SURFACE].technique == STIN_TECH_SURFACE_DOT3 ? 4 : 1;
    if (ctx->maps.unit == 4 && 4 + units > ctx->caps.max_texture_units &&
        ctx->desc.techniques[STIN_FEATURE_SURFACE] != STIN_TECH_SURFACE_DOT3) {
        /* shadows outrank bump: DOT3 gives its units up unless it was forced */
        stin_choice *c = &ctx->sel.choice[STIN_FEATURE_SURFACE];
        stin__dot3_release(ctx);
        c->technique = STIN_TECH_SURFACE_PLAIN;
        stin__formatf(c->reason, sizeof c->reason,
                      "fallback: dot3 needs texture units 0..3 and the shadow maps %d more",
                      units);
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK, "surface: %s", c->reason);
        ctx->maps.unit = 1;
    }
    if (ctx->maps.unit + units > ctx->caps.max_texture_units) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_TECHNIQUE_UNSUPPORTED,
                  "shadows: %s needs texture units %d..%d, the context has %d",
                  stin_technique_name(ctx->sel.choice[STIN_FEATURE_SHADOWS].technique),
                  ctx->maps.unit, ctx->maps.unit + units - 1, ctx->caps.max_texture_units);
        return STIN_ERROR_UNSUPPORTED;
    }
    if (ctx->caps.max_texture_size > 0 && size > (uint32_t)ctx->caps.max_texture_size)
        size = pow2_at_most((uint32_t)ctx->caps.max_texture_size);
    ctx->maps.size = size;
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    for (i = 0; i < ctx->desc.max_lights; i++)
        create_map_texture(ctx, &ctx->maps.textures[i], size);
    if (combine(ctx)) {
        unsigned char ramp[RAMP_SIZE];
        for (i = 0; i < RAMP_SIZE; i++)
            ramp[i] = (unsigned char)i;
        GL(ctx, GenTextures)(1, &ctx->maps.ramp);
        GL(ctx, BindTexture)(GL_TEXTURE_1D, ctx->maps.ramp);
        GL(ctx, TexParameteri)(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        GL(ctx, TexParameteri)(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        GL(ctx, TexParameteri)(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        GL(ctx, PixelStorei)(GL_UNPACK_ALIGNMENT, 1);
        GL(ctx, TexImage1D)(GL_TEXTURE_1D, 0, GL_INTENSITY8, RAMP_SIZE, 0, GL_LUMINANCE,
                            GL_UNSIGNED_BYTE, ramp);
        GL(ctx, BindTexture)(GL_TEXTURE_1D, 0);
    }
    if (combine_fbo(ctx)) {
        GL(ctx, GenTextures)(1, &ctx->maps.depth_scratch);
        GL(ctx, BindTexture)(GL_TEXTURE_2D, ctx->maps.depth_scratch);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        GL_ENUM(ctx, TexImage2D, GL_DEPTH_COMPONENT24)(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24,
                                                       (GLsizei)size, (GLsizei)size, 0,
                                                       GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
        GL(ctx, GenFramebuffers)(1, &ctx->maps.fbo);
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->maps.fbo);
        GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D,
                                      ctx->maps.depth_scratch, 0);
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, 0);
    } else if (!combine(ctx) && (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FBO))) {
        /* depth only: no colour buffer to draw or read */
        GL(ctx, GenFramebuffers)(1, &ctx->maps.fbo);
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->maps.fbo);
        GL(ctx, DrawBuffer)(GL_NONE);
        GL(ctx, ReadBuffer)(GL_NONE);
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, 0);
    }
    /* point lights: six maps drawn mid-frame (FBOs), shared by all of them,
     * and a mask unit that keeps each face to its own 90-degree square */
    if (ctx->maps.fbo && !combine(ctx) && ctx->maps.unit + units + 1 <= ctx->caps.max_texture_units &&
        (FACE_MASK * FACE_MASK) <= ctx->staging_bytes + ctx->scratch_bytes) {
        unsigned char *m = ctx->staging_bytes >= FACE_MASK * FACE_MASK ? ctx->staging : ctx->scratch;
        uint32_t x, y;
        for (i = 0; i < 6; i++)
            create_map_texture(ctx, &ctx->maps.textures[32 + i], size);
        for (y = 0; y < FACE_MASK; y++)
            for (x = 0; x < FACE_MASK; x++)
                m[y * FACE_MASK + x] =
                    (x == 0 || y == 0 || x == FACE_MASK - 1 || y == FACE_MASK - 1) ? 0 : 255;
        GL(ctx, GenTextures)(1, &ctx->maps.face_mask);
        GL(ctx, BindTexture)(GL_TEXTURE_2D, ctx->maps.face_mask);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        GL(ctx, PixelStorei)(GL_UNPACK_ALIGNMENT, 1);
        GL(ctx, TexImage2D)(GL_TEXTURE_2D, 0, GL_LUMINANCE, FACE_MASK, FACE_MASK, 0, GL_LUMINANCE,
                            GL_UNSIGNED_BYTE, m);
        ctx->maps.faces = 1;
    }
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    stin__gl_check_errors(ctx, "shadow-map set-up");
    return STIN_OK;
}

void stin__maps_release(stin_context *ctx)
{
    uint32_t i;
    for (i = 0; i < 38; i++)
        if (ctx->maps.textures[i]) {
            GL(ctx, DeleteTextures)(1, &ctx->maps.textures[i]);
            ctx->maps.textures[i] = 0;
        }
    if (ctx->maps.ramp)
        GL(ctx, DeleteTextures)(1, &ctx->maps.ramp);
    if (ctx->maps.fbo)
        GL(ctx, DeleteFramebuffers)(1, &ctx->maps.fbo);
    if (ctx->maps.depth_scratch)
        GL(ctx, DeleteTextures)(1, &ctx->maps.depth_scratch);
    if (ctx->maps.face_mask)
        GL(ctx, DeleteTextures)(1, &ctx->maps.face_mask);
    ctx->maps.face_mask = 0;
    ctx->maps.faces = 0;
    ctx->maps.ramp = ctx->maps.fbo = ctx->maps.depth_scratch = 0;
}

/* ---- rendering the maps -------------------------------------------------- */

static void set_offset(stin_context *ctx, const stin_light_desc *l)
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

/* Eye-linear plane of the light-eye depth mapped to [0, 1] over [n, f],
 * specified while the modelview is the identity (light-eye coordinates). */
static void ramp_texgen_light_eye(stin_context *ctx, float n, float f)
{
    float plane[4] = {0, 0, -1.0f / (f - n), -n / (f - n)};
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)((const float[16]){1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
    GL(ctx, TexGeni)(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    GL(ctx, TexGenfv)(GL_S, GL_EYE_PLANE, plane);
    GL_ENABLE(ctx, GL_TEXTURE_GEN_S);
}

static void render_one(stin_context *ctx, uint32_t slot, uint32_t li, const float view[16],
                       const float proj[16], float n, float f)
{
    const stin_light_desc *l = &ctx->lights[li];
    const int *vp = ctx->frame.viewport;
    uint32_t used = ctx->maps.used;
    float saved_view[16];
    int fbo = ctx->maps.fbo != 0;
    if (fbo) {
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->maps.fbo);
        GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER,
                                      combine(ctx) ? GL_COLOR_ATTACHMENT0 : GL_DEPTH_ATTACHMENT,
                                      GL_TEXTURE_2D, ctx->maps.textures[slot], 0);
        GL(ctx, Viewport)(0, 0, (GLsizei)used, (GLsizei)used);
    } else {
        GL(ctx, Viewport)(vp[0], vp[1], (GLsizei)used, (GLsizei)used);
        GL_ENABLE(ctx, GL_SCISSOR_TEST);
        GL(ctx, Scissor)(vp[0], vp[1], (GLsizei)used, (GLsizei)used);
    }
    GL_DISABLE(ctx, GL_BLEND); /* a lit pass may come before (point-light faces) */
    GL(ctx, DepthMask)(GL_TRUE);
    /* A point-light face's empty texels hold a depth just under 1: a point
     * behind the face has r past 1, clamped to 1, and must fail there. */
    GL(ctx, ClearDepth)(slot >= 32 ? 1.0 - 1.0 / 65536.0 : 1.0);
    GL(ctx, ClearColor)(1.0f, 1.0f, 1.0f, 1.0f); /* map-combine: "nothing" is the far end */
    GL(ctx, Clear)(GL_DEPTH_BUFFER_BIT | (combine(ctx) ? GL_COLOR_BUFFER_BIT : 0u));
    GL_ENABLE(ctx, GL_DEPTH_TEST);
    GL(ctx, DepthFunc)(GL_LESS);
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, LoadMatrixf)(proj);
    if (combine(ctx)) {
        GL(ctx, ColorMask)(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        GL_DISABLE(ctx, GL_POLYGON_OFFSET_FILL);
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
        GL_ENABLE(ctx, GL_TEXTURE_1D);
        GL(ctx, BindTexture)(GL_TEXTURE_1D, ctx->maps.ramp);
        GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
        ramp_texgen_light_eye(ctx, n, f);
    } else {
        GL(ctx, ColorMask)(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        set_offset(ctx, l);
    }
    stin__memcopy(saved_view, ctx->frame.view, sizeof saved_view);
    stin__memcopy(ctx->frame.view, view, sizeof saved_view);
    stin__fixed_draw_geometry(ctx);
    stin__memcopy(ctx->frame.view, saved_view, sizeof saved_view);
    if (combine(ctx)) {
        GL_DISABLE(ctx, GL_TEXTURE_GEN_S);
        GL_DISABLE(ctx, GL_TEXTURE_1D);
        GL(ctx, BindTexture)(GL_TEXTURE_1D, 0);
    }
    GL_DISABLE(ctx, GL_POLYGON_OFFSET_FILL);
    GL(ctx, ColorMask)(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (fbo) {
        GL(ctx, FramebufferTexture2D)(GL_FRAMEBUFFER,
                                      combine(ctx) ? GL_COLOR_ATTACHMENT0 : GL_DEPTH_ATTACHMENT,
                                      GL_TEXTURE_2D, 0, 0);
    } else {
        /* the colour (ramp) or depth of the region into the light's texture */
        GL(ctx, BindTexture)(GL_TEXTURE_2D, ctx->maps.textures[slot]);
        GL(ctx, CopyTexSubImage2D)(GL_TEXTURE_2D, 0, 0, 0, vp[0], vp[1], (GLsizei)used,
                                   (GLsizei)used);
        GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
        GL_DISABLE(ctx, GL_SCISSOR_TEST);
    }
    ctx->stats.passes++;
}

/* World -> texture: bias/scale into the used corner of the texture, then the
 * light's projection and view. Rows are the texgen planes. */
static void store_texgen(stin_context *ctx, uint32_t slot, uint32_t li, const float view[16],
                         const float proj[16], float n, float f)
{
    float vp[16], bias[16], m[16];
    float scale = (float)ctx->maps.used / (float)ctx->maps.size;
    int r, c;
    stin__mat4_mul(vp, proj, view);
    stin__mat4_identity(bias);
    bias[0] = bias[5] = 0.5f * scale;
    bias[12] = bias[13] = 0.5f * scale;
    bias[10] = bias[14] = 0.5f;
    stin__mat4_mul(m, bias, vp);
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++)
            ctx->maps.texgen[slot][4 * r + c] = m[4 * c + r];
    /* ramp coordinate of the fragment's own light-eye depth, a little nearer
     * than the stored one so a surface does not shadow itself (8-bit steps) */
    {
        float bias_steps = ctx->lights[li].shadow_offset_off ? 0.0f : 1.5f;
        float k = -1.0f / (f - n), o = -n / (f - n) - bias_steps / (float)(RAMP_SIZE - 1);
        for (c = 0; c < 4; c++)
            ctx->maps.ramp_plane[slot][c] = k * view[4 * c + 2] + (c == 3 ? o : 0.0f);
    }
}

void stin__maps_render(stin_context *ctx)
{
    uint32_t i;
    const int *vp = ctx->frame.viewport;
    uint32_t limit = ctx->maps.size;
    if (!ctx->maps.fbo) { /* drawn in the frame's own framebuffer */
        uint32_t fit = (uint32_t)(vp[2] < vp[3] ? vp[2] : vp[3]);
        if (fit < limit)
            limit = pow2_at_most(fit);
    }
    ctx->maps.used = limit;
    ctx->stats.shadow_map_size = limit;
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, PushMatrix)();
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, PushMatrix)();
    GL(ctx, EnableClientState)(GL_VERTEX_ARRAY);
    GL_DISABLE(ctx, GL_LIGHTING);
    for (i = 0; i < ctx->light_count && i < 32; i++) {
        const stin_light_desc *l = &ctx->lights[i];
        float view[16], proj[16], n, f;
        ctx->maps.valid[i] = 0;
        if (l->type == STIN_LIGHT_POINT) {
            if (!ctx->maps.said_point && !ctx->maps.faces) {
                stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                          "shadows: point lights need six depth maps drawn mid-frame (map-depth "
                          "with framebuffer objects); here they use %s",
                          (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_STENCIL)) ? "stencil volumes"
                                                                               : "no shadows");
                ctx->maps.said_point = 1;
            }
            continue;
        }
        if (l->radius > 0.0f && !ctx->maps.said_area) {
            stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                      "shadows: shadow maps treat area lights as points (hard shadows)");
            ctx->maps.said_area = 1;
        }
        if (!stin__light_camera(ctx, l, view, proj, &n, &f, ctx->maps.used))
            continue;
        render_one(ctx, i, i, view, proj, n, f);
        store_texgen(ctx, i, i, view, proj, n, f);
        ctx->maps.valid[i] = 1;
    }
    GL(ctx, DisableClientState)(GL_VERTEX_ARRAY);
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, PopMatrix)();
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, PopMatrix)();
    if (ctx->maps.fbo)
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->frame.framebuffer);
    stin__gl_check_errors(ctx, "shadow maps");
}

/* ---- the lit pass's shadow test ----------------------------------------- */

static void texgen_planes(stin_context *ctx, const float *rows, int with_r)
{
    static const GLenum coord[4] = {GL_S, GL_T, GL_R, GL_Q};
    static const GLenum gen[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
                                  GL_TEXTURE_GEN_Q};
    int i;
    for (i = 0; i < 4; i++) {
        if (i == 2 && !with_r) {
            GL_DISABLE(ctx, GL_TEXTURE_GEN_R);
            continue;
        }
        GL(ctx, TexGeni)(coord[i], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        GL(ctx, TexGenfv)(coord[i], GL_EYE_PLANE, rows + 4 * i);
        GL_ENABLE(ctx, gen[i]);
    }
}

/* One texture_env_combine stage: operation, sources and operands for RGB and
 * alpha (a second source of 0 is unused). */
typedef struct combine_stage {
    GLenum rgb, rgb_src[2], rgb_op[2];
    GLenum alpha, alpha_src[2], alpha_op[2];
} combine_stage;

static void set_combine(stin_context *ctx, const combine_stage *c)
{
    int i;
    GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    GL_ENUM(ctx, TexEnvi, c->rgb)(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)c->rgb);
    GL_ENUM(ctx, TexEnvi, c->alpha)(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLint)c->alpha);
    for (i = 0; i < 2; i++) {
        if (c->rgb_src[i]) {
            GL(ctx, TexEnvi)(GL_TEXTURE_ENV, (GLenum)(GL_SOURCE0_RGB + i), (GLint)c->rgb_src[i]);
            GL(ctx, TexEnvi)(GL_TEXTURE_ENV, (GLenum)(GL_OPERAND0_RGB + i), (GLint)c->rgb_op[i]);
        }
        if (c->alpha_src[i]) {
            GL(ctx, TexEnvi)(GL_TEXTURE_ENV, (GLenum)(GL_SOURCE0_ALPHA + i), (GLint)c->alpha_src[i]);
            GL(ctx, TexEnvi)(GL_TEXTURE_ENV, (GLenum)(GL_OPERAND0_ALPHA + i), (GLint)c->alpha_op[i]);
        }
    }
}

static void bind_slot(stin_context *ctx, uint32_t li);

int stin__maps_bind(stin_context *ctx, uint32_t li)
{
    if (li >= 32 || !ctx->maps.valid[li])
        return 0;
    bind_slot(ctx, li);
    return 1;
}

static void bind_slot(stin_context *ctx, uint32_t li)
{
    GLenum u = (GLenum)(GL_TEXTURE0 + (GLenum)ctx->maps.unit);
    /* planes are given in world space: specify them under the camera's view,
     * whose inverse GL applies, so any draw's eye coordinates map back */
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(ctx->frame.view);
    GL(ctx, ActiveTexture)(u);
    GL_ENABLE(ctx, GL_TEXTURE_2D);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, ctx->maps.textures[li]);
    texgen_planes(ctx, ctx->maps.texgen[li], !combine(ctx));
    if (!combine(ctx)) {
        GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    } else {
        /* colour passed on, the stored depth into alpha */
        const combine_stage stored = {GL_REPLACE, {GL_PREVIOUS, 0}, {GL_SRC_COLOR, 0},
                                      GL_REPLACE, {GL_TEXTURE, 0}, {GL_SRC_ALPHA, 0}};
        const combine_stage compare = {GL_REPLACE, {GL_PREVIOUS, 0}, {GL_SRC_COLOR, 0},
                                       GL_ADD_SIGNED, {GL_PREVIOUS, GL_TEXTURE},
                                       {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA}};
        set_combine(ctx, &stored);
        /* next unit: stored - own + 0.5 into alpha, colour passed on */
        GL(ctx, ActiveTexture)(u + 1u);
        GL_ENABLE(ctx, GL_TEXTURE_1D);
        GL(ctx, BindTexture)(GL_TEXTURE_1D, ctx->maps.ramp);
        GL(ctx, TexGeni)(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        GL(ctx, TexGenfv)(GL_S, GL_EYE_PLANE, ctx->maps.ramp_plane[li]);
        GL_ENABLE(ctx, GL_TEXTURE_GEN_S);
        set_combine(ctx, &compare);
        GL_ENABLE(ctx, GL_ALPHA_TEST);
        GL(ctx, AlphaFunc)(GL_GEQUAL, 0.5f);
    }
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    /* the shadow must darken the specular term too: one colour through the units */
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_SEPARATE_SPECULAR))
        GL_ENUM(ctx, LightModeli, GL_LIGHT_MODEL_COLOR_CONTROL)(GL_LIGHT_MODEL_COLOR_CONTROL,
                                                                GL_SINGLE_COLOR);
}

void stin__maps_unbind(stin_context *ctx)
{
    GLenum u = (GLenum)(GL_TEXTURE0 + (GLenum)ctx->maps.unit);
    GL(ctx, ActiveTexture)(u);
    GL_DISABLE(ctx, GL_TEXTURE_GEN_S);
    GL_DISABLE(ctx, GL_TEXTURE_GEN_T);
    GL_DISABLE(ctx, GL_TEXTURE_GEN_R);
    GL_DISABLE(ctx, GL_TEXTURE_GEN_Q);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    if (combine(ctx)) {
        GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        GL(ctx, ActiveTexture)(u + 1u);
        GL_DISABLE(ctx, GL_TEXTURE_GEN_S);
        GL(ctx, BindTexture)(GL_TEXTURE_1D, 0);
        GL_DISABLE(ctx, GL_TEXTURE_1D);
        GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        GL_DISABLE(ctx, GL_ALPHA_TEST);
    }
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_SEPARATE_SPECULAR))
        GL_ENUM(ctx, LightModeli, GL_LIGHT_MODEL_COLOR_CONTROL)(GL_LIGHT_MODEL_COLOR_CONTROL,
                                                                GL_SEPARATE_SPECULAR_COLOR);
}

/* ---- point lights: six 90-degree maps ------------------------------------ */

static const float face_axis[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                      {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

static float face_fov_deg(void)
{
    /* atan(x) for x = 128 / 127 near 1: 45 degrees + (x - 1) / 2 radians to
     * first order, plenty for one texel */
    double x = (double)(FACE_MASK / 2u) / (double)(FACE_MASK / 2u - 1u);
    double half = 45.0 + ((x - 1.0) / (1.0 + x * 1.0) ) * 57.29577951308232;
    return (float)(2.0 * half);
}

int stin__maps_face(stin_context *ctx, uint32_t li, int face)
{
    const stin_light_desc *l = &ctx->lights[li];
    const float *ax = face_axis[face];
    float view[16], proj[16], n, f, half, center[3];
    uint32_t slot = 32u + (uint32_t)face;
    if (!ctx->maps.faces || l->type != STIN_LIGHT_POINT)
        return 0;
    stin__light_look_along(view, l->position, ax);
    stin__light_fit(ctx, view, 0, &n, &f, &half, center);
    if (f <= 0.0f)
        return 0; /* nothing in front of this face */
    if (n < f * 1e-3f)
        n = f * 1e-3f;
    /* tan(fov/2) = (N/2) / (N/2 - 1): the 90-degree square ends on a texel edge */
    stin__light_perspective(proj, face_fov_deg(), n, f);
    ctx->maps.used = ctx->maps.size;
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    GL_DISABLE(ctx, GL_LIGHTING);
    render_one(ctx, slot, li, view, proj, n, f);
    store_texgen(ctx, slot, li, view, proj, n, f);
    /* back to the frame */
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->frame.framebuffer);
    GL(ctx, Viewport)(ctx->frame.viewport[0], ctx->frame.viewport[1], ctx->frame.viewport[2],
                      ctx->frame.viewport[3]);
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, LoadMatrixf)(ctx->projection);
    /* No clip planes: they would change the passes' vertex processing and
     * break the depth EQUAL test. The mask keeps the face to its square;
     * behind the face the depth is past 1 and fails the comparison. */
    bind_slot(ctx, slot);
    {
        GLenum mu = (GLenum)(GL_TEXTURE0 + (GLenum)(ctx->maps.unit + (combine(ctx) ? 2 : 1)));
        GL(ctx, ActiveTexture)(mu);
        GL_ENABLE(ctx, GL_TEXTURE_2D);
        GL(ctx, BindTexture)(GL_TEXTURE_2D, ctx->maps.face_mask);
        texgen_planes(ctx, ctx->maps.texgen[slot], 0);
        const combine_stage mask = {GL_MODULATE, {GL_PREVIOUS, GL_TEXTURE},
                                    {GL_SRC_COLOR, GL_SRC_COLOR}, GL_REPLACE, {GL_PREVIOUS, 0},
                                    {GL_SRC_ALPHA, 0}};
        set_combine(ctx, &mask);
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    }
    return 1;
}

void stin__maps_face_end(stin_context *ctx)
{
    GLenum mu = (GLenum)(GL_TEXTURE0 + (GLenum)(ctx->maps.unit + (combine(ctx) ? 2 : 1)));
    stin__maps_unbind(ctx);
    GL(ctx, ActiveTexture)(mu);
    GL_DISABLE(ctx, GL_TEXTURE_GEN_S);
    GL_DISABLE(ctx, GL_TEXTURE_GEN_T);
    GL_DISABLE(ctx, GL_TEXTURE_GEN_Q);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
}
