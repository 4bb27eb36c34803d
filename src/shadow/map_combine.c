/* SPDX-License-Identifier: MIT */
/* map-combine's encoding of depth without depth textures, shared by its
 * maps (shadow/map_fixed.c) and volumes' products map on GL1
 * (shadow/cast_map_fixed.c): texture_env_combine stages, the 1D ramp a
 * map's depths are drawn in, and the ramp coordinate of a fragment's own
 * depth, biased nearer so that a surface does not shadow itself. */
#include "internal.h"

#define RAMP_SIZE 256
#define RAMP_BIAS_STEPS 1.5f /* the stored depth's rounding, with margin */
#define SLOPE_BIAS 2.0f      /* steepest receiver slope (depth per texel) */

void stin__combine_set(stin_context *ctx, const stin__combine_stage *c)
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

GLuint stin__map_ramp_create(stin_context *ctx)
{
    unsigned char ramp[RAMP_SIZE];
    GLuint t;
    int i;
    for (i = 0; i < RAMP_SIZE; i++)
        ramp[i] = (unsigned char)i;
    GL(ctx, GenTextures)(1, &t);
    GL(ctx, BindTexture)(GL_TEXTURE_1D, t);
    GL(ctx, TexParameteri)(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    GL(ctx, TexParameteri)(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    GL(ctx, TexParameteri)(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    stin__upload_bytes(ctx, GL_TEXTURE_1D, GL_INTENSITY8, RAMP_SIZE, 1, GL_LUMINANCE, ramp);
    GL(ctx, BindTexture)(GL_TEXTURE_1D, 0);
    return t;
}

/* Eye-linear plane of the light-eye depth mapped to [0, 1] over [n, f],
 * specified while the modelview is the identity (light-eye coordinates). */
void stin__map_ramp_texgen(stin_context *ctx, float n, float f)
{
    float plane[4] = {0, 0, -1.0f / (f - n), -n / (f - n)};
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)((const float[16]){1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
    GL(ctx, TexGeni)(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    GL(ctx, TexGenfv)(GL_S, GL_EYE_PLANE, plane);
    GL_ENABLE(ctx, GL_TEXTURE_GEN_S);
}

/* Ramp coordinate of the fragment's own light-eye depth d, nearer than
 * the stored one so that a surface does not shadow itself: a constant
 * for the 8-bit steps, plus what a slope up to SLOPE_BIAS changes the
 * depth over one texel - d times the texel's angular size for a
 * perspective map (still a plane in d), the texel's width for an
 * orthographic one. */
void stin__map_ramp_plane(const stin_light_desc *l, const float view[16], const float proj[16],
                          float n, float f, uint32_t texels, float plane[4])
{
    /* the light asks for no offset (stin__map_offset's 0) */
    int off = l->shadow_offset_exact && l->shadow_offset[0] == 0.0f &&
              l->shadow_offset[1] == 0.0f,
        c;
    float texel = 2.0f / (proj[0] * (float)texels);
    int ortho = proj[15] != 0.0f;
    float slope = off ? 0.0f : SLOPE_BIAS * texel;
    float k = -(1.0f - (ortho ? 0.0f : slope)) / (f - n);
    float o = -n / (f - n) - (off ? 0.0f : RAMP_BIAS_STEPS / (float)(RAMP_SIZE - 1)) -
              (ortho ? slope / (f - n) : 0.0f);
    for (c = 0; c < 4; c++)
        plane[c] = k * view[4 * c + 2] + (c == 3 ? o : 0.0f);
}
