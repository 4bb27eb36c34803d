/* SPDX-License-Identifier: MIT */
/* The visibility map for the application's own shaders: after the frame's
 * lights, each light's visibility is drawn into one channel of the screen
 * mask (render/screen_mask.c, its own copy of the opaque draws' depth) by the
 * technique that shades the frame - its mask hook where it has one on GLSL
 * paths, else its light hook with the flat pass written into that channel
 * alone - and every three lights are copied into their tile of the map. The
 * same tests as the lit passes, so the application's pixels agree with
 * stin's. Where the frame's lights have deep or colour maps (transparent
 * casters), each light's map is made again and its transmittance alone
 * (the flat pass with no shadow test, the map's lookup per channel) goes
 * into a tile of its own after the visibility tiles. */
#include "internal.h"

#define TILES_PER_ROW 2
/* R, G and B: a fixed-function pass's alpha is its shadow test's (map-combine) */
#define LIGHTS_PER_TILE 3

typedef struct stin__export_state {
    GLuint texture;
    int width, height;           /* allocated texels (0: not yet) */
    int tile_width, tile_height; /* of the last export */
    uint32_t lights;             /* lights in the map */
    uint32_t transmittance_tile; /* the first light's transmittance tile (0: none) */
    int valid;                   /* the last frame exported */
    int said_size;               /* lights left out for the map's size were logged */
} stin__export_state;

size_t stin__export_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(stin__export_state);
}

/* The map is drawn through the screen mask, so it needs what the mask does. */
int stin__export_supported(const stin_context *ctx)
{
    return stin__mask_drawable(ctx);
}

void stin__export_release(stin_context *ctx)
{
    if (ctx->visibility->texture)
        GL(ctx, DeleteTextures)(1, &ctx->visibility->texture);
    stin__memzero(ctx->visibility, sizeof *ctx->visibility);
}

/* How many of `tiles` fit the context's largest texture, the map grown to
 * hold them; 0 when not even one does. */
static uint32_t ensure_map(stin_context *ctx, int tile_w, int tile_h, uint32_t tiles)
{
    stin__export_state *e = ctx->visibility;
    int max = ctx->caps.max_texture_size > 0 ? ctx->caps.max_texture_size : 1 << 30;
    uint32_t fit = tiles;
    int cols, rows, w, h;
    while (fit > 0) {
        cols = fit < TILES_PER_ROW ? (int)fit : TILES_PER_ROW;
        rows = (int)((fit + TILES_PER_ROW - 1) / TILES_PER_ROW);
        if (tile_w <= max / cols && tile_h <= max / rows)
            break;
        fit--;
    }
    if (fit == 0)
        return 0;
    w = tile_w * cols;
    h = tile_h * rows;
    if (e->texture && w <= e->width && h <= e->height)
        return fit;
    if (w < e->width)
        w = e->width;
    if (h < e->height)
        h = e->height;
    if (!e->texture)
        GL(ctx, GenTextures)(1, &e->texture);
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, e->texture); /* on unit 0, counted as the frame's */
    stin__rt_texture(ctx, e->texture, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, w, h);
    e->width = w;
    e->height = h;
    return fit;
}

/* Light li's transmittance through its deep or colour map, RGB, in the
 * mask (no shadow test: the mask's fresh state has none). */
static void export_transmittance(stin_context *ctx, const stin__path *path, uint32_t li)
{
    static const float white[4] = {1, 1, 1, 1};
    stin__light_maps_make(ctx, li);
    path->flat(ctx, STIN__OPAQUE, white, &ctx->lights[li]);
    stin__light_maps_done(ctx);
}

/* A light's visibility through the flat pass, into the pass's channel. */
static void shade_channel(stin_context *ctx, const stin__path *path, const stin_light_desc *l,
                          float weight)
{
    float c[4];
    c[0] = c[1] = c[2] = c[3] = weight;
    path->flat(ctx, STIN__OPAQUE, c, l);
}

static void export_light(stin_context *ctx, const stin__path *path, uint32_t li, int channel,
                         int shadowed)
{
    const stin__shadow_technique *t = ctx->shadow;
    if (shadowed && t->mask && path->lit_lights && t->mask(ctx, path, li, channel))
        return;
    ctx->pass_channel = (unsigned char)(channel + 1);
    if (shadowed)
        t->light(ctx, path, li, shade_channel);
    else
        shade_channel(ctx, path, &ctx->lights[li], 1.0f);
    ctx->pass_channel = 0;
}

void stin__export_stage(stin_context *ctx, const stin__path *path, int shadowed)
{
    stin__export_state *e = ctx->visibility;
    const int *vp = ctx->frame.viewport;
    int tile_w = vp[0] + vp[2], tile_h = vp[1] + vp[3];
    uint32_t groups = (ctx->light_count + LIGHTS_PER_TILE - 1) / LIGHTS_PER_TILE, fit, g, want;
    int coloured = stin__light_maps_active(ctx) && ctx->light_count > 0;
    e->valid = 0;
    e->lights = 0;
    e->transmittance_tile = 0;
    if (!ctx->frame.export_visibility)
        return;
    /* a frame without lights still hands out a map (of no lights); with
     * transmittance, a tile a light more, all or nothing */
    want = (groups > 0 ? groups : 1) + (coloured ? ctx->light_count : 0u);
    fit = ensure_map(ctx, tile_w, tile_h, want);
    if (fit < want && !e->said_size) {
        if (coloured && fit >= groups)
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                      "visibility map: the lights' transmittance tiles do not fit "
                      "GL_MAX_TEXTURE_SIZE %d at %dx%d a tile; the map holds visibility only",
                      ctx->caps.max_texture_size, tile_w, tile_h);
        else
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                      "visibility map: %u of %u lights fit GL_MAX_TEXTURE_SIZE %d at %dx%d a "
                      "tile%s",
                      (unsigned)(LIGHTS_PER_TILE * fit < ctx->light_count ? LIGHTS_PER_TILE * fit
                                                                          : ctx->light_count),
                      (unsigned)ctx->light_count, ctx->caps.max_texture_size, tile_w, tile_h,
                      coloured ? ", and no transmittance" : "");
        e->said_size = 1;
    }
    if (coloured && fit < want)
        coloured = 0;
    else if (coloured)
        fit = groups; /* the visibility tiles; the transmittance ones follow */
    stin__mask_frame_end(ctx); /* the mask's depth again: opaque draws only */
    e->valid = fit > 0;
    for (g = 0; g < fit && LIGHTS_PER_TILE * g < ctx->light_count; g++) {
        uint32_t li;
        if (!stin__mask_begin(ctx, path, STIN__OPAQUE, 1)) {
            e->valid = 0; /* logged by the mask */
            break;
        }
        ctx->draw_fbo = stin__mask_target_of(ctx).fbo;
        for (li = LIGHTS_PER_TILE * g; li < ctx->light_count && li < LIGHTS_PER_TILE * (g + 1);
             li++)
            export_light(ctx, path, li, (int)(li - LIGHTS_PER_TILE * g), shadowed);
        stin__bind_unit(ctx, 0, GL_TEXTURE_2D, e->texture);
        GL(ctx, CopyTexSubImage2D)(GL_TEXTURE_2D, 0, (GLint)(g % TILES_PER_ROW) * tile_w,
                                   (GLint)(g / TILES_PER_ROW) * tile_h, 0, 0, tile_w, tile_h);
        e->lights = LIGHTS_PER_TILE * (g + 1) < ctx->light_count ? LIGHTS_PER_TILE * (g + 1)
                                                                 : ctx->light_count;
    }
    for (g = 0; coloured && e->valid && g < ctx->light_count; g++) {
        uint32_t tile = groups + g;
        if (!stin__mask_begin(ctx, path, STIN__OPAQUE, 1)) {
            e->valid = 0;
            break;
        }
        ctx->draw_fbo = stin__mask_target_of(ctx).fbo;
        export_transmittance(ctx, path, g);
        stin__bind_unit(ctx, 0, GL_TEXTURE_2D, e->texture);
        GL(ctx, CopyTexSubImage2D)(GL_TEXTURE_2D, 0, (GLint)(tile % TILES_PER_ROW) * tile_w,
                                   (GLint)(tile / TILES_PER_ROW) * tile_h, 0, 0, tile_w, tile_h);
        e->transmittance_tile = groups;
    }
    stin__mask_frame_end(ctx);
    ctx->draw_fbo = ctx->frame.framebuffer;
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->frame.framebuffer);
    GL(ctx, Viewport)(vp[0], vp[1], vp[2], vp[3]);
    e->tile_width = tile_w;
    e->tile_height = tile_h;
}

/* ---- public ----------------------------------------------------------------- */

stin_result stin_query_visibility_map(const stin_context *ctx, stin_visibility_map *out)
{
    const stin__export_state *e;
    if (!ctx || !out)
        return STIN_ERROR_INVALID_ARGUMENT;
    e = ctx->visibility;
    if (ctx->state != STIN__IDLE || !e->valid)
        return STIN_ERROR_INVALID_STATE;
    out->texture = e->texture;
    out->width = (uint32_t)e->width;
    out->height = (uint32_t)e->height;
    out->tile_width = (uint32_t)e->tile_width;
    out->tile_height = (uint32_t)e->tile_height;
    out->lights = e->lights;
    out->transmittance_tile = (uint32_t)e->transmittance_tile;
    return STIN_OK;
}

const char *stin_visibility_glsl(void)
{
    return stin__shader_source("gl2/app_visibility.glsl");
}

/* The chunk's uniforms (shaders/gl2/app_visibility.glsl) and their types. */
#define CHUNK_UNIFORMS 4
static const struct {
    const char *name;
    GLenum type;
    const char *glsl;
} chunk_uniforms[CHUNK_UNIFORMS] = {
    {"stin_visibility_map", GL_SAMPLER_2D, "sampler2D"},
    {"stin_visibility_layout", GL_FLOAT_VEC4, "vec4"},
    {"stin_visibility_lights", GL_FLOAT, "float"},
    {"stin_visibility_transmittance", GL_FLOAT, "float"},
};

/* An active uniform's name is `want`, or `want` "[0]" for an array. */
static int uniform_named(const char *active, const char *want)
{
    size_t i = 0;
    while (want[i] && active[i] == want[i])
        i++;
    if (want[i])
        return 0;
    return active[i] == '\0' ||
           (active[i] == '[' && active[i + 1] == '0' && active[i + 2] == ']' && !active[i + 3]);
}

/* The chunk's uniform locations in `program` (-1: not declared), or 0, logged,
 * when the program declares one of them with another type: setting it would
 * be GL_INVALID_OPERATION, so nothing is set. */
static int chunk_locations(stin_context *ctx, GLuint program, GLint loc[CHUNK_UNIFORMS])
{
    GLint active = 0, i;
    int u, declared = 0;
    for (u = 0; u < CHUNK_UNIFORMS; u++)
        declared += (loc[u] = GL(ctx, GetUniformLocation)(program, chunk_uniforms[u].name)) >= 0;
    if (declared)
        GL(ctx, GetProgramiv)(program, GL_ACTIVE_UNIFORMS, &active);
    for (i = 0; i < active; i++) {
        GLchar name[64];
        GLsizei length = 0;
        GLint count = 0;
        GLenum type = GL_NONE;
        GL(ctx, GetActiveUniform)(program, (GLuint)i, (GLsizei)sizeof name, &length, &count, &type,
                                  name);
        for (u = 0; u < CHUNK_UNIFORMS; u++)
            if (loc[u] >= 0 && uniform_named(name, chunk_uniforms[u].name) &&
                type != chunk_uniforms[u].type) {
                stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FRAME_STATE,
                          "stin_bind_visibility: the current program declares %s with GL type "
                          "0x%x, not the chunk's %s; nothing was set",
                          chunk_uniforms[u].name, (unsigned)type, chunk_uniforms[u].glsl);
                return 0;
            }
    }
    return 1;
}

stin_result stin_bind_visibility(stin_context *ctx, int unit)
{
    const stin__export_state *e;
    GLint program = 0, active = GL_TEXTURE0, linked = GL_FALSE, loc[CHUNK_UNIFORMS];
    int units, glsl;
    if (!ctx)
        return STIN_ERROR_INVALID_ARGUMENT;
    e = ctx->visibility;
    units = ctx->caps.max_texture_image_units > ctx->caps.max_texture_units
                ? ctx->caps.max_texture_image_units
                : ctx->caps.max_texture_units;
    if (unit < 0 || unit >= units) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_ARGUMENT,
                  "stin_bind_visibility: unit %d is not one of the context's %d", unit, units);
        return STIN_ERROR_INVALID_ARGUMENT;
    }
    glsl = (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_GLSL)) != 0;
    if (ctx->state != STIN__IDLE || !e->valid || !glsl) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FRAME_STATE, "stin_bind_visibility: %s",
                  !glsl                      ? "the context has no GLSL"
                  : ctx->state != STIN__IDLE ? "a frame is open"
                                             : "the last frame exported no visibility map");
        return STIN_ERROR_INVALID_STATE;
    }
    GL(ctx, GetIntegerv)(GL_CURRENT_PROGRAM, &program);
    if (program == 0) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FRAME_STATE,
                  "stin_bind_visibility: no program is current");
        return STIN_ERROR_INVALID_STATE;
    }
    GL(ctx, GetProgramiv)((GLuint)program, GL_LINK_STATUS, &linked);
    if (!linked) { /* relinked since glUseProgram: it has no uniforms to set */
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FRAME_STATE,
                  "stin_bind_visibility: the current program's last link failed");
        return STIN_ERROR_INVALID_STATE;
    }
    if (!chunk_locations(ctx, (GLuint)program, loc))
        return STIN_ERROR_INVALID_STATE;
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE)) {
        GL(ctx, GetIntegerv)(GL_ACTIVE_TEXTURE, &active);
        GL(ctx, ActiveTexture)(GL_TEXTURE0 + (GLenum)unit);
    }
    GL(ctx, BindTexture)(GL_TEXTURE_2D, e->texture);
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)((GLenum)active);
    if (loc[0] >= 0)
        GL(ctx, Uniform1i)(loc[0], unit);
    if (loc[1] >= 0) {
        float layout[4];
        layout[0] = (float)e->tile_width;
        layout[1] = (float)e->tile_height;
        layout[2] = 1.0f / (float)e->width;
        layout[3] = 1.0f / (float)e->height;
        GL(ctx, Uniform4fv)(loc[1], 1, layout);
    }
    if (loc[2] >= 0)
        GL(ctx, Uniform1f)(loc[2], (float)e->lights);
    if (loc[3] >= 0)
        GL(ctx, Uniform1f)(loc[3], (float)e->transmittance_tile);
    return STIN_OK;
}
