/* SPDX-License-Identifier: MIT */
/* Lit programs specialised to a light batch and a material. The general
 * lit.frag loops over up to 8 lights bounded by a uniform and takes every
 * part of the equation (light kind, attenuation, spot cone, albedo map)
 * behind a uniform branch; a driver that runs branches on masked lanes
 * (llvmpipe) pays for all of it on every pixel. A specialised program has
 * the batch's count as a constant bound and only the parts it uses: the
 * same equation, so the same picture within rounding. Outside a peeled
 * layer it also leaves out the transparency's peel chunk: its fetch ran on
 * masked lanes too, and its discard kept the driver from testing depth
 * before shading (the lit passes test depth EQUAL, so every hidden
 * fragment was shaded). */
#include "render/glsl_private.h"

/* key bits: 0-3 light count, then the parts the batch uses, the albedo
 * map, the surface variant and the tessellated twin */
#define KEY_DIRECTIONAL 0x10u
#define KEY_POSITIONAL 0x20u
#define KEY_SPOT 0x40u
#define KEY_ATTENUATION 0x80u
#define KEY_ALBEDO 0x100u
#define KEY_VARIANT_SHIFT 9
#define KEY_TESS 0x10000u
#define KEY_PEEL 0x20000u

uint32_t stin__lit_lights_key(const stin_light_desc *lights, int n)
{
    uint32_t key = (uint32_t)n;
    int i;
    for (i = 0; i < n; i++) {
        const stin_light_desc *l = &lights[i];
        if (l->type == STIN_LIGHT_DIRECTIONAL) {
            key |= KEY_DIRECTIONAL;
            continue;
        }
        key |= KEY_POSITIONAL;
        if (l->type == STIN_LIGHT_SPOT)
            key |= KEY_SPOT;
        /* stin_add_light stored "none" as (1, 0, 0): k is exactly 1 then */
        if (l->attenuation[0] != 1.0f || l->attenuation[1] != 0.0f || l->attenuation[2] != 0.0f)
            key |= KEY_ATTENUATION;
    }
    return key;
}

static void write_defines(char *out, size_t size, uint32_t key)
{
    stin__formatf(out, size,
                  "#define STIN_SPECIALISED 1\n#define STIN_LIGHT_COUNT %u\n"
                  "#define STIN_DIRECTIONAL %d\n#define STIN_POSITIONAL %d\n"
                  "#define STIN_SPOT %d\n#define STIN_ATTENUATION %d\n"
                  "#define STIN_ALBEDO_TEX %d\n",
                  (unsigned)(key & 0xfu), (key & KEY_DIRECTIONAL) != 0,
                  (key & KEY_POSITIONAL) != 0, (key & KEY_SPOT) != 0,
                  (key & KEY_ATTENUATION) != 0, (key & KEY_ALBEDO) != 0);
}

/* A slot for a new program: a free one, else the one that served the
 * oldest frame (not this one: a pass may still use it); -1 if none. */
static int free_slot(stin_context *ctx)
{
    stin__lit_cache *c = &ctx->glsl->lit_cache;
    uint32_t i;
    int oldest = -1;
    if (c->count < STIN__LIT_CACHE)
        return (int)c->count++;
    for (i = 0; i < STIN__LIT_CACHE; i++)
        if (c->used[i] != c->frame && (oldest < 0 || c->used[i] < c->used[oldest]))
            oldest = (int)i;
    if (oldest >= 0 && c->programs[oldest].name) {
        if (ctx->glsl->current == &c->programs[oldest])
            ctx->glsl->current = NULL;
        GL(ctx, DeleteProgram)(c->programs[oldest].name);
    }
    return oldest;
}

const stin__program *stin__lit_specialised(stin_context *ctx, const stin__program *general,
                                           int variant, uint32_t lights_key, int albedo_tex)
{
    stin__lit_cache *c = &ctx->glsl->lit_cache;
    uint32_t key = lights_key | (albedo_tex ? KEY_ALBEDO : 0u) |
                   ((uint32_t)variant << KEY_VARIANT_SHIFT) |
                   (ctx->glsl->tess.active ? KEY_TESS : 0u) |
                   (stin__in_peeled_layer(ctx) ? KEY_PEEL : 0u);
    char defines[256], msg[160];
    uint32_t i;
    int slot;
    if (ctx->desc.debug_flags & STIN_DEBUG_LIGHTING_GENERAL)
        return general;
    for (i = 0; i < c->count; i++)
        if (c->keys[i] == key) {
            c->used[i] = c->frame;
            if (!c->programs[i].name)
                return general;
            ctx->stats.lighting.specialised++;
            return &c->programs[i];
        }
    slot = free_slot(ctx);
    if (slot < 0) {
        if (!c->said_full) {
            stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                      "a frame needs more than %d specialised lit programs; the general ones "
                      "draw the rest",
                      STIN__LIT_CACHE);
            c->said_full = 1;
        }
        return general;
    }
    write_defines(defines, sizeof defines, key);
    c->keys[slot] = key;
    c->used[slot] = c->frame;
    if (!stin__glsl_build_lit(ctx, variant, ctx->glsl->tess.active, (key & KEY_PEEL) != 0,
                              defines, &c->programs[slot], msg, sizeof msg)) {
        /* kept as a failed slot: the general program serves, without a retry per draw */
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_SHADER_COMPILE,
                  "a specialised lit program did not build (%s); the general one serves", msg);
        c->programs[slot].name = 0;
        return general;
    }
    ctx->stats.lighting.programs_built++;
    ctx->stats.lighting.specialised++;
    return &c->programs[slot];
}

void stin__lit_cache_frame(stin_context *ctx) { ctx->glsl->lit_cache.frame++; }

void stin__lit_cache_release(stin_context *ctx)
{
    stin__lit_cache *c = &ctx->glsl->lit_cache;
    uint32_t i;
    for (i = 0; i < c->count; i++)
        if (c->programs[i].name)
            GL(ctx, DeleteProgram)(c->programs[i].name);
    stin__memzero(c, sizeof *c);
}
