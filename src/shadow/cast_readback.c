/* SPDX-License-Identifier: MIT */
/* The CSG products cast under stencil volumes on GL 1.1, where a map's test
 * has no second texture unit beside the geometry pass (and no framebuffer
 * objects or depth textures): the map is made and tested on the CPU.
 *
 * Before a light's count, its products are resolved from the light (the
 * read-back resolve, render/casters.h) into the frame's own depth at the
 * viewport's corner, one image for a spot or directional light's frustum
 * or one per face of a point light's cube, each read back (the frame's
 * depth under them kept first and drawn back after, as floats, which the
 * CPU resolve's glDrawPixels shows to come back exact: the lit passes test
 * it EQUAL; unsigned integers did not, on llvmpipe). The projection is cropped to the
 * rectangle the products' bounds cover, as the GL1 maps are.
 *
 * After the count, band by band of rows, the frame's depth is read back,
 * each pixel unprojected to the world and projected into the image of its
 * face (a point light's by the major axis of its direction from the light),
 * and it is shadowed where it lies farther from the light than the stored
 * depth plus BIAS (the stored depth already carries the light's
 * slope-scaled offset, added by the resolve). The decisions go back as an
 * alpha image by glDrawPixels, alpha test on, stencil REPLACE 0x80 where it
 * passes: the lit pass's "count zero" then leaves those pixels dark, as the
 * marking pass of the other tiers does.
 *
 * Memory: the state's slot (frame/modules.c) holds the six images, the
 * corner's depth and one band of rows (BAND_PIXELS of depth and decisions),
 * sized from the desc by stin__cast_readback_bytes. */
#include "shadow/cast_map_private.h"

#define GL_ALPHA 0x1906

#define MAX_SIZE 128u         /* texels a side at most: 7 images of 64 KiB */
#define BAND_PIXELS 16384u    /* frame pixels a band: its rows' depth and decisions */
/* In the light's window depth, beyond the stored offset: the frame's depth
 * buffer holds its surfaces to 2^-24 of window depth, which unprojected
 * and seen from the light spreads over some 2^-18 (a lit product face must
 * not shadow itself). */
#define BIAS (1.0f / 16384.0f)

/* The images' side for desc d (a power of two). */
static uint32_t cap_of(const stin_desc *d)
{
    return d->shadows.map_size < MAX_SIZE ? d->shadows.map_size : MAX_SIZE;
}

size_t stin__cast_readback_bytes(const stin_desc *d)
{
    size_t texels = (size_t)cap_of(d) * cap_of(d);
    /* a desc that rules the path out takes none: a higher tier forced, or
     * CSG or shadows forced off */
    if ((d->tier != STIN_TIER_AUTO && d->tier != STIN_TIER_GL1) ||
        d->techniques[STIN_FEATURE_CSG] == STIN_TECH_CSG_OFF ||
        d->techniques[STIN_FEATURE_SHADOWS] == STIN_TECH_SHADOWS_OFF)
        return 0;
    return (STIN__CUBE_FACES + 1u) * texels * 4u + (size_t)BAND_PIXELS * 5u;
}

void stin__cast_readback_init(stin_context *ctx)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    unsigned char *base = (unsigned char *)m + stin__align16(sizeof *m);
    size_t texels;
    if (!stin__cast_readback_bytes(&ctx->desc))
        return; /* sized out of the block: the products cast none (logged by draw) */
    m->cpu = 1;
    m->cpu_cap = cap_of(&ctx->desc);
    texels = (size_t)m->cpu_cap * m->cpu_cap;
    m->cpu_images = (float *)(void *)base;
    m->cpu_corner = (float *)(void *)(base + STIN__CUBE_FACES * texels * 4u);
    m->cpu_rows = base + (STIN__CUBE_FACES + 1u) * texels * 4u;
}

/* A rectangle of the bound framebuffer, rows tightly packed. */
static void read_pixels(stin_context *ctx, const int r[4], GLenum format, GLenum type, void *out)
{
    stin__unpack_saved saved;
    stin__pack_begin(ctx, &saved);
    GL(ctx, ReadPixels)(r[0], r[1], r[2], r[3], format, type, out);
    stin__pack_end(ctx, &saved);
}

/* An image of r[2] x r[3] at window (r[0], r[1]), through identity
 * matrices and the raster position at the viewport's corner. */
static void draw_pixels(stin_context *ctx, const int r[4], GLenum format, GLenum type,
                        const void *pixels)
{
    static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    stin__unpack_saved saved;
    GL(ctx, Viewport)(r[0], r[1], r[2], r[3]);
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, LoadMatrixf)(identity);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(identity);
    GL(ctx, RasterPos2f)(-1.0f, -1.0f);
    stin__unpack_begin(ctx, &saved);
    GL(ctx, DrawPixels)(r[2], r[3], format, type, pixels);
    stin__unpack_end(ctx, &saved);
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, LoadMatrixf)(ctx->projection);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, Viewport)(ctx->frame.viewport[0], ctx->frame.viewport[1], ctx->frame.viewport[2],
                      ctx->frame.viewport[3]);
}

/* Face `face` of light l (its frustum for a spot or directional light)
 * resolved at the corner and read back; 1 if products drew there. */
static int one_face(stin_context *ctx, const stin_light_desc *l, int face, const int corner[4])
{
    struct stin__cast_map_state *m = ctx->cast_map;
    float view[16], proj[16], n, f;
    if (l->type == STIN_LIGHT_POINT) {
        stin__light_cube_face(ctx, l->position, face, view, proj);
        n = proj[14] / (proj[10] - 1.0f);
        f = proj[14] / (proj[10] + 1.0f);
    } else if (!stin__light_camera(ctx, l, view, proj, &n, &f, m->cpu_size)) {
        return 0;
    }
    stin__cast_fixed_focus(ctx, m->cpu_size, view, proj, &n, &f);
    if (!stin__cast_fixed_products(ctx, l, corner, view, proj))
        return 0;
    stin__light_window_matrix(m->cpu_matrix[face], view, proj);
    read_pixels(ctx, corner, GL_DEPTH_COMPONENT, GL_FLOAT,
                m->cpu_images + (size_t)face * m->cpu_size * m->cpu_size);
    ctx->stats.passes++;
    return 1;
}

int stin__cast_readback_draw(stin_context *ctx, uint32_t li)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    const stin_light_desc *l = &ctx->lights[li];
    const int *vp = ctx->frame.viewport;
    stin__pass_state saved = *stin__pass_current(ctx), ps = stin__pass_defaults;
    uint32_t fit = (uint32_t)(vp[2] < vp[3] ? vp[2] : vp[3]);
    int corner[4], face;
    m->cpu_drawn = 0;
    if (!m->cpu || fit < 1u || !stin__target_has_stencil(ctx))
        return 0; /* the resolve needs the frame's stencil */
    if (vp[2] > (int)BAND_PIXELS) {
        if (!m->said_cpu_wide)
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                      "volume: CSG products cast no shadow: a viewport %d pixels wide passes "
                      "the read-backs' band of %u pixels",
                      vp[2], BAND_PIXELS);
        m->said_cpu_wide = 1;
        return 0;
    }
    m->cpu_size = fit < m->cpu_cap ? stin__pow2_at_most(fit) : m->cpu_cap;
    m->cpu_faces = l->type == STIN_LIGHT_POINT ? STIN__CUBE_FACES : 1;
    corner[0] = vp[0];
    corner[1] = vp[1];
    corner[2] = corner[3] = (int)m->cpu_size;
    /* the frame's depth where the images are drawn, kept */
    read_pixels(ctx, corner, GL_DEPTH_COMPONENT, GL_FLOAT, m->cpu_corner);
    GL_DISABLE(ctx, GL_LIGHTING);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    for (face = 0; face < m->cpu_faces; face++)
        if (one_face(ctx, l, face, corner))
            m->cpu_drawn |= 1u << face;
    /* the frame's depth back (its stencil is the count's, cleared by it) */
    ps.depth_test = 1; /* GL writes depth only with the test on */
    ps.depth_func = GL_ALWAYS;
    ps.color_write = 0;
    ps.scissor = 1;
    stin__memcopy(ps.scissor_box, corner, sizeof ps.scissor_box);
    stin__pass_apply(ctx, &ps);
    draw_pixels(ctx, corner, GL_DEPTH_COMPONENT, GL_FLOAT, m->cpu_corner);
    stin__pass_apply(ctx, &saved);
    return m->cpu_drawn != 0;
}

/* The face of a point light's cube that direction d lies in (its major
 * axis: +x -x +y -y +z -z, as stin__light_cube_face). */
static int face_of(const double d[3])
{
    double ax = d[0] < 0 ? -d[0] : d[0], ay = d[1] < 0 ? -d[1] : d[1],
           az = d[2] < 0 ? -d[2] : d[2];
    if (ax >= ay && ax >= az)
        return d[0] >= 0 ? 0 : 1;
    if (ay >= az)
        return d[1] >= 0 ? 2 : 3;
    return d[2] >= 0 ? 4 : 5;
}

/* Whether world point p lies behind the products of the light's images. */
static int shadowed(const struct stin__cast_map_state *m, const stin_light_desc *l,
                    const double p[3])
{
    const float *w;
    double c[4], d[3];
    int face = 0, k, x, y;
    float stored;
    if (m->cpu_faces > 1) {
        for (k = 0; k < 3; k++)
            d[k] = p[k] - (double)l->position[k];
        face = face_of(d);
    }
    if (!(m->cpu_drawn & (1u << face)))
        return 0;
    w = m->cpu_matrix[face];
    for (k = 0; k < 4; k++)
        c[k] = w[k] * p[0] + w[4 + k] * p[1] + w[8 + k] * p[2] + w[12 + k];
    if (!(c[3] > 0.0))
        return 0; /* behind the light's plane */
    c[0] /= c[3];
    c[1] /= c[3];
    c[2] /= c[3];
    if (!(c[0] >= 0.0 && c[0] < 1.0 && c[1] >= 0.0 && c[1] < 1.0))
        return 0; /* outside the products' rectangle */
    x = (int)(c[0] * (double)m->cpu_size);
    y = (int)(c[1] * (double)m->cpu_size);
    stored = m->cpu_images[(size_t)face * m->cpu_size * m->cpu_size + (size_t)y * m->cpu_size +
                           (size_t)x];
    return stored < 1.0f && c[2] > (double)stored + (double)BIAS;
}

void stin__cast_readback_mark(stin_context *ctx)
{
    struct stin__cast_map_state *m = ctx->cast_map;
    const stin_light_desc *l = &ctx->lights[m->current];
    const int *vp = ctx->frame.viewport;
    float *depth = (float *)(void *)m->cpu_rows;
    unsigned char *decide = m->cpu_rows + (size_t)BAND_PIXELS * 4u;
    float inverse[16], vp_matrix[16];
    int rows = (int)(BAND_PIXELS / (uint32_t)vp[2]), y0, x, y, k;
    if (!m->cpu_drawn)
        return;
    stin__mat4_mul(vp_matrix, ctx->projection, ctx->frame.view);
    if (!stin__mat4_invert(inverse, vp_matrix))
        return;
    GL_DISABLE(ctx, GL_TEXTURE_2D); /* the fragments' alpha is the image's */
    GL_ENABLE(ctx, GL_ALPHA_TEST);
    GL(ctx, AlphaFunc)(GL_GREATER, 0.5f);
    for (y0 = 0; y0 < vp[3]; y0 += rows) {
        const int band[4] = {vp[0], vp[1] + y0, vp[2], vp[3] - y0 < rows ? vp[3] - y0 : rows};
        read_pixels(ctx, band, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
        for (y = 0; y < band[3]; y++)
            for (x = 0; x < band[2]; x++) {
                size_t i = (size_t)y * (size_t)band[2] + (size_t)x;
                double ndc[4], p[4];
                ndc[0] = 2.0 * ((double)x + 0.5) / (double)vp[2] - 1.0;
                ndc[1] = 2.0 * ((double)(y0 + y) + 0.5) / (double)vp[3] - 1.0;
                ndc[2] = 2.0 * (double)depth[i] - 1.0;
                ndc[3] = 1.0;
                decide[i] = 0;
                if (!(depth[i] < 1.0f))
                    continue; /* nothing drawn there */
                for (k = 0; k < 4; k++)
                    p[k] = inverse[k] * ndc[0] + inverse[4 + k] * ndc[1] +
                           inverse[8 + k] * ndc[2] + inverse[12 + k] * ndc[3];
                if (p[3] == 0.0)
                    continue;
                p[0] /= p[3];
                p[1] /= p[3];
                p[2] /= p[3];
                decide[i] = shadowed(m, l, p) ? 255u : 0u;
            }
        draw_pixels(ctx, band, GL_ALPHA, GL_UNSIGNED_BYTE, decide);
    }
    GL_DISABLE(ctx, GL_ALPHA_TEST);
    GL(ctx, AlphaFunc)(GL_ALWAYS, 0.0f);
}
