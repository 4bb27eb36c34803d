/* SPDX-License-Identifier: MIT */
/* Textures from caller pixels: resampled to a power of two where the GL
 * version needs it, mipmaps built on the CPU (GL 1.1 has no mipmap
 * generation, and the surface tests reproduce the CPU's box filter and
 * Toksvig lengths), level by level through the arena's staging block. */
#include "internal.h"


stin__texture_slot *stin__texture_lookup(const stin_context *ctx, stin_texture tex)
{
    uint32_t s;
    if (!ctx)
        return NULL;
    s = stin__handle_resolve(&ctx->textures[0].handle, sizeof ctx->textures[0],
                             ctx->desc.max_textures, ctx->handle_tag, tex.id);
    return s == STIN__NO_SLOT ? NULL : &ctx->textures[s];
}

/* n is at most STIN__MAX_TEXELS (checked first): p cannot shift out. */
uint32_t stin__pot_at_least(uint32_t n)
{
    uint32_t p = 1;
    while (p < n && p < 0x80000000u)
        p <<= 1;
    return p;
}

/* Bilinear resample with wrap addressing (the sampler's addressing too). */
static void resample(const uint8_t *src, uint32_t sw, uint32_t sh, uint8_t *dst, uint32_t dw,
                     uint32_t dh)
{
    uint32_t x, y;
    int c;
    for (y = 0; y < dh; y++)
        for (x = 0; x < dw; x++) {
            float fx = ((float)x + 0.5f) * (float)sw / (float)dw - 0.5f;
            float fy = ((float)y + 0.5f) * (float)sh / (float)dh - 0.5f;
            int x0 = fx < 0 ? -1 : (int)fx, y0 = fy < 0 ? -1 : (int)fy;
            float ax = fx - (float)x0, ay = fy - (float)y0;
            uint32_t xa = (uint32_t)(x0 + (int)sw) % sw, xb = (uint32_t)(x0 + 1) % sw;
            uint32_t ya = (uint32_t)(y0 + (int)sh) % sh, yb = (uint32_t)(y0 + 1) % sh;
            for (c = 0; c < 4; c++) {
                float v = (1 - ax) * (1 - ay) * src[4u * (ya * sw + xa) + (uint32_t)c] +
                          ax * (1 - ay) * src[4u * (ya * sw + xb) + (uint32_t)c] +
                          (1 - ax) * ay * src[4u * (yb * sw + xa) + (uint32_t)c] +
                          ax * ay * src[4u * (yb * sw + xb) + (uint32_t)c];
                dst[4u * (y * dw + x) + (uint32_t)c] = (uint8_t)(v + 0.5f);
            }
        }
}

/* 2x2 box filter; a dimension of 1 stays 1. */
static void halve(const uint8_t *src, uint32_t w, uint32_t h, uint8_t *dst)
{
    uint32_t nw = w > 1 ? w / 2 : 1, nh = h > 1 ? h / 2 : 1, x, y;
    int c;
    for (y = 0; y < nh; y++)
        for (x = 0; x < nw; x++) {
            uint32_t x0 = w > 1 ? 2 * x : 0, x1 = w > 1 ? 2 * x + 1 : 0;
            uint32_t y0 = h > 1 ? 2 * y : 0, y1 = h > 1 ? 2 * y + 1 : 0;
            for (c = 0; c < 4; c++) {
                unsigned s = src[4u * (y0 * w + x0) + (uint32_t)c] + src[4u * (y0 * w + x1) + (uint32_t)c] +
                             src[4u * (y1 * w + x0) + (uint32_t)c] + src[4u * (y1 * w + x1) + (uint32_t)c];
                dst[4u * (y * nw + x) + (uint32_t)c] = (uint8_t)((s + 2u) / 4u);
            }
        }
}

/* Normal maps: 128 + 127 n per channel (128 is zero). */
static float decode_n(uint8_t c) { return ((float)c - 128.0f) / 127.0f; }

static uint8_t encode_unit(float x, float scale, float offset)
{
    float v = offset + scale * x + 0.5f;
    return (uint8_t)(v < 0.0f ? 0.0f : v > 255.0f ? 255.0f : v);
}

/* Normal-map mip level: the mean of the four unit normals (each scaled by
 * its own mean length in A); RGB its direction, A its length (Toksvig). */
static void halve_normals(const uint8_t *src, uint32_t w, uint32_t h, uint8_t *dst)
{
    uint32_t nw = w > 1 ? w / 2 : 1, nh = h > 1 ? h / 2 : 1, x, y;
    for (y = 0; y < nh; y++)
        for (x = 0; x < nw; x++) {
            uint32_t xs[2], ys[2];
            float sum[3] = {0, 0, 0}, len;
            int i, j, c;
            uint8_t *o = dst + 4u * (y * nw + x);
            xs[0] = w > 1 ? 2 * x : 0;
            xs[1] = w > 1 ? 2 * x + 1 : 0;
            ys[0] = h > 1 ? 2 * y : 0;
            ys[1] = h > 1 ? 2 * y + 1 : 0;
            for (j = 0; j < 2; j++)
                for (i = 0; i < 2; i++) {
                    const uint8_t *p = src + 4u * (ys[j] * w + xs[i]);
                    float d[3], l;
                    for (c = 0; c < 3; c++)
                        d[c] = decode_n(p[c]);
                    l = stin__sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                    if (l > 0.0f)
                        for (c = 0; c < 3; c++)
                            sum[c] += 0.25f * d[c] / l * ((float)p[3] / 255.0f);
                }
            len = stin__sqrtf(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
            if (!(len > 1e-6f)) {
                sum[0] = sum[1] = 0.0f;
                sum[2] = len = 1e-6f;
            }
            for (c = 0; c < 3; c++)
                o[c] = encode_unit(sum[c] / len, 127.0f, 128.0f);
            o[3] = encode_unit(len > 1.0f ? 1.0f : len, 255.0f, 0.0f);
        }
}

/* A normal map from the R channel of a height field: central differences
 * with wrap-around, n = normalize(-s dh/dx, -s dh/dy, 1), h in [0,1]. */
static void normals_from_height(const uint8_t *src, uint32_t w, uint32_t h, float strength,
                                uint8_t *dst)
{
    uint32_t x, y;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            float hl = src[4u * (y * w + (x + w - 1) % w)] / 255.0f;
            float hr = src[4u * (y * w + (x + 1) % w)] / 255.0f;
            float hd = src[4u * (((y + h - 1) % h) * w + x)] / 255.0f;
            float hu = src[4u * (((y + 1) % h) * w + x)] / 255.0f;
            float n[3], l;
            uint8_t *o = dst + 4u * (y * w + x);
            n[0] = -strength * 0.5f * (hr - hl);
            n[1] = -strength * 0.5f * (hu - hd);
            n[2] = 1.0f;
            l = stin__sqrtf(n[0] * n[0] + n[1] * n[1] + 1.0f);
            o[0] = encode_unit(n[0] / l, 127.0f, 128.0f);
            o[1] = encode_unit(n[1] / l, 127.0f, 128.0f);
            o[2] = encode_unit(n[2] / l, 127.0f, 128.0f);
            o[3] = 255;
        }
}

static uint64_t level_bytes(uint32_t w, uint32_t h, int level)
{
    uint64_t lw = w >> level, lh = h >> level;
    return 4ull * (lw ? lw : 1) * (lh ? lh : 1);
}

/* Staging for a texture built level by level. Level 0 is staged when it
 * must be made (resampled, derived from a height map, or a normal map's
 * alpha set to 1); otherwise the caller's pixels are uploaded as they are.
 * Mip levels alternate between two regions, each made from the one before:
 * level 0's region and one of level 1's size, or regions of levels 1 and 2
 * (5/16 of level 0) when level 0 is the caller's. */
stin__staging_plan stin__plan_staging(uint32_t w, uint32_t h, int mips, int staged0,
                                      uint64_t derived_bytes)
{
    stin__staging_plan p;
    p.region_a = staged0 ? level_bytes(w, h, 0) : mips ? level_bytes(w, h, 1) : 0;
    p.region_b = !mips ? 0 : staged0 ? level_bytes(w, h, 1) : level_bytes(w, h, 2);
    p.derived = derived_bytes;
    p.total = p.region_a + p.region_b + p.derived;
    return p;
}

/* Uploads src (w x h) as level 0 of the bound 2D texture and, with mips,
 * each next level, halved into the staging region (buf or region_b) that
 * the level before it is not in. Returns the highest level uploaded. */
static uint32_t upload_levels(stin_context *ctx, const uint8_t *src, uint32_t w, uint32_t h,
                              int mips, int normal, uint8_t *buf, uint8_t *region_b)
{
    uint32_t level = 0;
    for (;;) {
        stin__upload_level(ctx, GL_TEXTURE_2D, (GLint)level, GL_RGBA8, w, h, GL_RGBA, src);
        if (!mips || (w == 1 && h == 1))
            return level;
        {
            uint8_t *next = src == buf ? region_b : buf;
            if (normal)
                halve_normals(src, w, h, next);
            else
                halve(src, w, h, next);
            src = next;
        }
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
        level++;
    }
}

/* Displacement's copy of a height map with its mip chain (the draw's
 * level from its distance, surface/displace.c): the sampling parameters of
 * the two levels it blends. */
static void create_lods(stin_context *ctx, stin__texture_slot *t, const uint8_t *level0,
                        uint32_t w, uint32_t h, uint8_t *buf, uint8_t *region_b)
{
    GL(ctx, GenTextures)(1, &t->lod_name);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, t->lod_name);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    t->lod_top = upload_levels(ctx, level0, w, h, 1, 0, buf, region_b);
}

stin_result stin_create_texture(stin_context *ctx, const stin_texture_desc *desc,
                                stin_texture *out)
{
    uint32_t w, h, slot, max = 0;
    const uint8_t *src;
    uint8_t *buf;
    stin__texture_slot *t = NULL;
    int mips, resized, normal, derive, lods;
    GLint caller_binding = 0;
    stin__staging_plan plan;
    uint8_t *region_b;
    if (out)
        out->id = 0;
    if (!ctx || !desc || !out || !desc->pixels || !desc->width || !desc->height ||
        (uint64_t)desc->width * desc->height > STIN__MAX_TEXELS ||
        (unsigned)desc->kind > STIN_TEXTURE_HEIGHT || !stin__isfinite(desc->normal_from_height) ||
        desc->normal_from_height < 0.0f ||
        (desc->normal_from_height > 0.0f && desc->kind != STIN_TEXTURE_NORMAL)) {
        if (ctx)
            stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_ARGUMENT,
                      "stin_create_texture: need pixels, width and height (width * height "
                      "at most 2^30) and a valid kind (normal_from_height: finite, >= 0, "
                      "normal maps only)");
        return STIN_ERROR_INVALID_ARGUMENT;
    }
    max = ctx->caps.max_texture_size > 0 ? (uint32_t)ctx->caps.max_texture_size : 64u;
    w = desc->width;
    h = desc->height;
    if (!stin__npot_textures(ctx)) { /* mipmapped, repeated: GL 2.0, ES 3.0 */
        w = stin__pot_at_least(w);
        h = stin__pot_at_least(h);
    }
    while (w > max)
        w /= 2;
    while (h > max)
        h /= 2;
    resized = w != desc->width || h != desc->height;
    /* height maps: level 0 only (the parallax march reads the true field) */
    mips = !desc->base_level_only && desc->kind != STIN_TEXTURE_HEIGHT;
    /* and displacement's copy of a height map with its mip chain */
    lods = desc->kind == STIN_TEXTURE_HEIGHT && !desc->base_level_only && ctx->vertex_chunk.displace;
    normal = desc->kind == STIN_TEXTURE_NORMAL;
    derive = desc->normal_from_height > 0.0f;
    plan = stin__plan_staging(w, h, mips || lods, resized || normal || derive,
                        derive && resized ? 4ull * desc->width * desc->height : 0);
    if (plan.total > ctx->staging_bytes) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_POOL_FULL,
                  "stin_create_texture: %ux%u%s%s needs %lu staging bytes, "
                  "desc.max_texture_bytes is %zu", w, h, mips || lods ? " with mipmaps" : "",
                  derive ? " derived from a height map" : "", (unsigned long)plan.total,
                  ctx->staging_bytes);
        return STIN_ERROR_CAPACITY;
    }
    slot = stin__handle_free_slot(&ctx->textures[0].handle, sizeof ctx->textures[0],
                                  ctx->desc.max_textures);
    if (slot != STIN__NO_SLOT)
        t = &ctx->textures[slot];
    if (!t) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_POOL_FULL,
                  "stin_create_texture: all %u texture slots in use (desc.max_textures)",
                  ctx->desc.max_textures);
        return STIN_ERROR_CAPACITY;
    }
    buf = ctx->staging;
    region_b = buf + plan.region_a;
    src = desc->pixels;
    if (derive) { /* level 0 (before any resample) computed into staging */
        uint8_t *at = resized ? region_b + plan.region_b : buf;
        normals_from_height(desc->pixels, desc->width, desc->height, desc->normal_from_height, at);
        src = at;
    }
    if (resized) {
        resample(src, desc->width, desc->height, buf, w, h);
        src = buf;
    }
    if (normal && src == desc->pixels) { /* A = 1 at level 0: a copy to own */
        stin__memcopy(buf, src, 4u * w * h);
        src = buf;
    }
    if (normal) {
        uint32_t i;
        for (i = 0; i < w * h; i++)
            buf[4u * i + 3u] = 255;
    }
    GL(ctx, GetIntegerv)(GL_TEXTURE_BINDING_2D, &caller_binding); /* the active unit's */
    GL(ctx, GenTextures)(1, &t->name);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, t->name);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                           mips ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    (void)upload_levels(ctx, src, w, h, mips, normal, buf, region_b);
    t->lod_name = 0;
    t->lod_top = 0;
    if (lods) /* level 0 is still src: upload_levels halved into other regions only */
        create_lods(ctx, t, src, w, h, buf, region_b);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, (GLuint)caller_binding);
    t->kind = desc->kind;
    t->width = desc->width;
    t->height = desc->height;
    out->id = stin__handle_issue(&t->handle, slot, ctx->desc.max_textures, ctx->handle_tag);
    return STIN_OK;
}

void stin_destroy_texture(stin_context *ctx, stin_texture tex)
{
    stin__texture_slot *t = stin__texture_lookup(ctx, tex);
    if (!t) {
        if (ctx && tex.id)
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_BAD_HANDLE,
                      "stin_destroy_texture: stale or unknown handle 0x%x", tex.id);
        return;
    }
    if (ctx->state == STIN__IN_FRAME) { /* queued draws still name it */
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FRAME_STATE,
                  "%s: a frame is open and its draws may use this %s; destroy it after "
                  "stin_end_frame", "stin_destroy_texture", "texture");
        return;
    }
    GL(ctx, DeleteTextures)(1, &t->name);
    if (t->lod_name)
        GL(ctx, DeleteTextures)(1, &t->lod_name);
    stin__handle_release(&t->handle, ctx->desc.max_textures);
    t->name = t->lod_name = 0;
}

void stin__texture_release_all(stin_context *ctx)
{
    uint32_t i;
    for (i = 0; i < ctx->desc.max_textures; i++)
        if (ctx->textures[i].handle.alive) {
            GL(ctx, DeleteTextures)(1, &ctx->textures[i].name);
            if (ctx->textures[i].lod_name)
                GL(ctx, DeleteTextures)(1, &ctx->textures[i].lod_name);
            stin__handle_release(&ctx->textures[i].handle, ctx->desc.max_textures);
        }
}

/* Tightly packed rows from client memory whatever the caller's unpack
 * state (the header promises pixel-store state is left alone). */
void stin__upload_level(stin_context *ctx, GLenum target, GLint level, GLenum internal_format,
                        uint32_t w, uint32_t h, GLenum format, const void *pixels)
{
    stin__unpack_saved saved;
    internal_format = stin__texture_format(ctx, internal_format);
    stin__unpack_begin(ctx, &saved);
    if (target == GL_TEXTURE_1D)
        GL(ctx, TexImage1D)(target, level, (GLint)internal_format, (GLsizei)w, 0, format,
                            GL_UNSIGNED_BYTE, pixels);
    else
        GL_ENUM(ctx, TexImage2D, target)(target, level, (GLint)internal_format, (GLsizei)w,
                                         (GLsizei)h, 0, format, GL_UNSIGNED_BYTE, pixels);
    stin__unpack_end(ctx, &saved);
}

void stin__upload_bytes(stin_context *ctx, GLenum target, GLenum internal_format, uint32_t w,
                        uint32_t h, GLenum format, const void *pixels)
{
    stin__upload_level(ctx, target, 0, internal_format, w, h, format, pixels);
}
