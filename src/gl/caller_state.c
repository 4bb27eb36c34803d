/* SPDX-License-Identifier: MIT */
/* Caller state that no pass sets but every pass relies on: the blend
 * equation, polygon mode, logic op, depth range, clip planes, primitive
 * restart, rasterizer discard, multisample coverage, sampler objects and,
 * on the fixed-function path, everything the fixed pipeline would mix in
 * (a bound program, texture units stin does not use, texture matrices, fog,
 * texgen, client arrays, pixel transfer). A caller may leave any of it set;
 * the frame establishes GL's defaults first (the header's GL STATE). */
#include "internal.h"

/* Sampler objects override a texture's own parameters on their unit;
 * every unit a technique may bind is below this. */
#define SAMPLER_UNITS 16
/* GL guarantees 6 user clip planes; stin clears up to this many. */
#define CLIP_PLANES 8

static int version(const stin_context *ctx) { return ctx->caps.gl_major * 10 + ctx->caps.gl_minor; }

static int has(const stin_context *ctx, stin_cap cap)
{
    return (ctx->caps.present & STIN_CAP_BIT(cap)) != 0;
}

static void disable_from(stin_context *ctx, int min_version, const GLenum *caps, int n)
{
    int i;
    if (version(ctx) < min_version)
        return;
    for (i = 0; i < n; i++)
        GL_DISABLE(ctx, caps[i]);
}

/* OpenGL ES: the same defaults where ES has the state (no logic op,
 * polygon mode or smoothing, clip planes or non-fixed primitive restart;
 * WebGL 2 restarts at the fixed index always). */
static void es_defaults(stin_context *ctx)
{
    static const GLenum es20[] = {GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_COVERAGE};
    static const GLenum es30[] = {GL_RASTERIZER_DISCARD, GL_PRIMITIVE_RESTART_FIXED_INDEX};
    static const GLenum es32[] = {GL_SAMPLE_MASK}; /* ES 3.1, audited as GL 3.2 */
    disable_from(ctx, 20, es20, 2);
    disable_from(ctx, 30, es30, ctx->caps.webgl ? 1 : 2); /* WebGL: always on */
    disable_from(ctx, 32, es32, 1);
    stin__depth_range(ctx, 0.0, 1.0);
}

static void desktop_defaults(stin_context *ctx)
{
    static const GLenum gl11[] = {GL_COLOR_LOGIC_OP, GL_POLYGON_SMOOTH};
    static const GLenum gl13[] = {GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE,
                                  GL_SAMPLE_COVERAGE};
    static const GLenum gl30[] = {GL_RASTERIZER_DISCARD};
    static const GLenum gl31[] = {GL_PRIMITIVE_RESTART};
    static const GLenum gl32[] = {GL_SAMPLE_MASK};
    static const GLenum gl43[] = {GL_PRIMITIVE_RESTART_FIXED_INDEX};
    int i, planes = ctx->caps.max_clip_planes < CLIP_PLANES ? ctx->caps.max_clip_planes
                                                             : CLIP_PLANES;
    disable_from(ctx, 11, gl11, 2);
    disable_from(ctx, 13, gl13, 3);
    disable_from(ctx, 30, gl30, 1);
    disable_from(ctx, 31, gl31, 1);
    disable_from(ctx, 32, gl32, 1);
    disable_from(ctx, 43, gl43, 1);
    for (i = 0; i < planes; i++)
        GL_DISABLE(ctx, (GLenum)(GL_CLIP_PLANE0 + i));
    if (has(ctx, STIN_CAP_FIXED_FUNCTION)) { /* these apply to shaders' output too */
        GL_DISABLE(ctx, GL_ALPHA_TEST);
        GL_DISABLE(ctx, GL_POLYGON_STIPPLE);
    }
    GL(ctx, PolygonMode)(GL_FRONT_AND_BACK, GL_FILL);
    GL(ctx, DepthRange)(0.0, 1.0);
}

void stin__caller_state_defaults(stin_context *ctx)
{
    int i;
    if (ctx->caps.es)
        es_defaults(ctx);
    else
        desktop_defaults(ctx);
    if (stin__gl_available(ctx, STIN_GLFN_BlendEquation))
        GL(ctx, BlendEquation)(GL_FUNC_ADD);
    if (stin__gl_available(ctx, STIN_GLFN_BindSampler)) {
        int units = ctx->caps.max_texture_image_units < SAMPLER_UNITS
                        ? ctx->caps.max_texture_image_units
                        : SAMPLER_UNITS;
        for (i = 0; i < units; i++)
            GL(ctx, BindSampler)((GLuint)i, 0);
    }
}

/* Pixel transfer applies to the copies of the GL1 maps without FBOs. */
static void pixel_transfer_defaults(stin_context *ctx)
{
    static const GLenum scales[] = {GL_RED_SCALE, GL_GREEN_SCALE, GL_BLUE_SCALE, GL_ALPHA_SCALE,
                                    GL_DEPTH_SCALE};
    static const GLenum offsets[] = {GL_RED_BIAS,  GL_GREEN_BIAS, GL_BLUE_BIAS,   GL_ALPHA_BIAS,
                                     GL_DEPTH_BIAS, GL_MAP_COLOR, GL_MAP_STENCIL, GL_INDEX_SHIFT,
                                     GL_INDEX_OFFSET};
    size_t i;
    for (i = 0; i < sizeof scales / sizeof scales[0]; i++)
        GL(ctx, PixelTransferf)(scales[i], 1.0f);
    for (i = 0; i < sizeof offsets / sizeof offsets[0]; i++)
        GL(ctx, PixelTransferf)(offsets[i], 0.0f);
}

static int fixed_units(const stin_context *ctx)
{
    return has(ctx, STIN_CAP_MULTITEXTURE) ? ctx->caps.max_texture_units : 1;
}

static void unit_defaults(stin_context *ctx, int unit)
{
    static const GLenum gen[] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
                                 GL_TEXTURE_GEN_Q};
    static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    int i;
    if (has(ctx, STIN_CAP_MULTITEXTURE)) {
        GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + unit));
        GL(ctx, ClientActiveTexture)((GLenum)(GL_TEXTURE0 + unit));
    }
    GL_DISABLE(ctx, GL_TEXTURE_1D);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    if (version(ctx) >= 12)
        GL_DISABLE(ctx, GL_TEXTURE_3D);
    if (has(ctx, STIN_CAP_TEXTURE_CUBE_MAP))
        GL_DISABLE(ctx, GL_TEXTURE_CUBE_MAP);
    for (i = 0; i < 4; i++)
        GL_DISABLE(ctx, gen[i]);
    GL(ctx, DisableClientState)(GL_TEXTURE_COORD_ARRAY);
    /* texture matrices are in no attribute group: one level of each stack */
    GL(ctx, MatrixMode)(GL_TEXTURE);
    GL(ctx, PushMatrix)();
    GL(ctx, LoadMatrixf)(identity);
}

void stin__caller_state_fixed_begin(stin_context *ctx)
{
    static const GLenum arrays[] = {GL_COLOR_ARRAY, GL_INDEX_ARRAY, GL_EDGE_FLAG_ARRAY};
    static const GLenum arrays14[] = {GL_FOG_COORD_ARRAY, GL_SECONDARY_COLOR_ARRAY};
    int u;
    size_t i;
    if (has(ctx, STIN_CAP_GLSL))
        GL(ctx, UseProgram)(0); /* the fixed pipeline would draw through it */
    for (u = fixed_units(ctx) - 1; u >= 0; u--) /* ends on unit 0 */
        unit_defaults(ctx, u);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL_DISABLE(ctx, GL_FOG);
    GL_DISABLE(ctx, GL_COLOR_MATERIAL);
    for (i = 0; i < sizeof arrays / sizeof arrays[0]; i++)
        GL_ENUM(ctx, DisableClientState, arrays[i])(arrays[i]);
    if (version(ctx) >= 14) {
        GL_DISABLE(ctx, GL_COLOR_SUM);
        for (i = 0; i < sizeof arrays14 / sizeof arrays14[0]; i++)
            GL_ENUM(ctx, DisableClientState, arrays14[i])(arrays14[i]);
    }
    pixel_transfer_defaults(ctx);
}

void stin__caller_state_fixed_end(stin_context *ctx)
{
    int u;
    for (u = fixed_units(ctx) - 1; u >= 0; u--) {
        if (has(ctx, STIN_CAP_MULTITEXTURE))
            GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + u));
        GL(ctx, MatrixMode)(GL_TEXTURE);
        GL(ctx, PopMatrix)();
    }
}
