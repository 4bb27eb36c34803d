/* SPDX-License-Identifier: MIT */
/* stin-render --debug: the lights' visibility map of one more frame that
 * exports it, and the shadow maps of the last frame, read back with the
 * application's GL and written as PNG beside the output. */
#include "render_debug.h"

#include "image_io.h"
#include "stin/stin_debug.h"

#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef void (*bind_texture_fn)(GLenum target, GLuint texture);
typedef void (*get_tex_image_fn)(GLenum target, GLint level, GLenum format, GLenum type,
                                 void *pixels);
typedef void (*active_texture_fn)(GLenum unit);

typedef struct readback {
    bind_texture_fn bind;
    get_tex_image_fn get;
    active_texture_fn active;
} readback;

static void *proc(stin_platform *p, const char *name, void *out, size_t size)
{
    void *fp = stin_platform_get_proc_address(p, name);
    memcpy(out, &fp, size);
    return fp;
}

unsigned render_debug_parse(const char *name)
{
    return !strcmp(name, "shadow-map") ? RENDER_DEBUG_SHADOW_MAP
           : !strcmp(name, "volumes")  ? RENDER_DEBUG_VOLUMES
           : !strcmp(name, "masks")    ? RENDER_DEBUG_MASKS
                                       : 0u;
}

/* <output without its extension>-<what>.png */
static void debug_path(char *out, size_t size, const char *output, const char *what)
{
    const char *slash = strrchr(output, '/'), *dot = strrchr(output, '.');
    int stem = dot && (!slash || dot > slash) ? (int)(dot - output) : (int)strlen(output);
    snprintf(out, size, "%.*s-%s.png", stem, output, what);
}

/* A texture of stin's, level 0, as float (GL_RGBA or GL_DEPTH_COMPONENT). */
static float *read_texture(const readback *rb, uint32_t texture, int w, int h, GLenum format)
{
    float *px = malloc(sizeof *px * (size_t)w * h * (format == GL_RGBA ? 4 : 1));
    if (!px)
        return NULL;
    if (rb->active)
        rb->active(GL_TEXTURE0);
    rb->bind(GL_TEXTURE_2D, texture);
    rb->get(GL_TEXTURE_2D, 0, format, GL_FLOAT, px);
    rb->bind(GL_TEXTURE_2D, 0);
    return px;
}

/* width x height texels of src (channels each, rows bottom first, stride
 * src_w) into an RGB(A) image, rows top first; depth stretched from its
 * nearest texel to 1 so that the casters show. */
static int write_texels(const char *path, const float *src, int src_w, int w, int h,
                        int channels, char *err, size_t err_size)
{
    image img;
    float lo = 1.0f;
    int x, y, c, ok;
    if (!image_alloc(&img, w, h, 4)) {
        snprintf(err, err_size, "out of memory");
        return 0;
    }
    for (c = 0; c < 4; c++)
        snprintf(img.channel_names[c], sizeof img.channel_names[c], "%c", "RGBA"[c]);
    if (channels == 1)
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++)
                if (src[(size_t)y * src_w + x] < lo)
                    lo = src[(size_t)y * src_w + x];
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const float *s = src + ((size_t)y * src_w + x) * channels;
            float *o = img.pixels + ((size_t)(h - 1 - y) * w + x) * 4;
            for (c = 0; c < 3; c++)
                o[c] = channels == 1 ? (lo < 1.0f ? (s[0] - lo) / (1.0f - lo) : 1.0f) : s[c];
            o[3] = 1.0f;
        }
    ok = image_write(path, &img, 0, err, err_size);
    image_free(&img);
    if (ok)
        printf("wrote %s\n", path);
    return ok;
}

static int write_masks(const readback *rb, const char *output, const scene_gpu *g,
                       stin_context *ctx, stin_platform *p, char *err, size_t err_size)
{
    stin_visibility_map m;
    char path[1024];
    float *px;
    int ok;
    stin_result r = scene_gpu_frame_export(g, ctx, stin_platform_width(p), stin_platform_height(p),
                                           STIN_OUTPUT_BEAUTY, STIN_EXPORT_VISIBILITY_ONLY,
                                           stin_platform_framebuffer(p));
    if (r != STIN_OK || stin_query_visibility_map(ctx, &m) != STIN_OK) {
        snprintf(err, err_size, "--debug masks: no visibility map (%s; it needs framebuffer "
                                "objects)", stin_result_name(r));
        return 0;
    }
    if (!(px = read_texture(rb, m.texture, (int)m.width, (int)m.height, GL_RGBA))) {
        snprintf(err, err_size, "out of memory");
        return 0;
    }
    debug_path(path, sizeof path, output, "masks");
    printf("masks: %u lights, three a tile (R, G, B), tiles of %ux%u two to a row\n", m.lights,
           m.tile_width, m.tile_height);
    ok = write_texels(path, px, (int)m.width, (int)m.width, (int)m.height, 4, err, err_size);
    free(px);
    return ok;
}

static int write_shadow_maps(const readback *rb, const char *output, const scene_gpu *g,
                             stin_context *ctx, char *err, size_t err_size)
{
    uint32_t i;
    for (i = 0; i < (uint32_t)g->src->light_count; i++) {
        stin_debug_map m;
        char path[1024], what[32];
        float *px;
        int ok;
        if (stin_debug_query_shadow_map(ctx, i, &m) != STIN_OK) {
            printf("light %u: no shadow map kept (point lights' faces are redrawn per light; "
                   "volume and vdsm have none)\n", (unsigned)i);
            continue;
        }
        px = read_texture(rb, m.texture, (int)m.allocated, (int)m.allocated,
                          m.depth ? GL_DEPTH_COMPONENT : GL_RGBA);
        if (!px) {
            snprintf(err, err_size, "out of memory");
            return 0;
        }
        snprintf(what, sizeof what, "shadow-map-%u", (unsigned)i);
        debug_path(path, sizeof path, output, what);
        ok = write_texels(path, px, (int)m.allocated, (int)m.size, (int)m.size, m.depth ? 1 : 4,
                          err, err_size);
        free(px);
        if (!ok)
            return 0;
    }
    return 1;
}

int render_debug_write(unsigned kinds, const char *output, const scene_gpu *g,
                       stin_context *ctx, stin_platform *p, char *err, size_t err_size)
{
    readback rb;
    if (!proc(p, "glBindTexture", &rb.bind, sizeof rb.bind) ||
        !proc(p, "glGetTexImage", &rb.get, sizeof rb.get)) {
        snprintf(err, err_size, "--debug: the context has no glGetTexImage");
        return 0;
    }
    proc(p, "glActiveTexture", &rb.active, sizeof rb.active);
    /* the shadow maps first: the masks' frame draws them again */
    if ((kinds & RENDER_DEBUG_SHADOW_MAP) && !write_shadow_maps(&rb, output, g, ctx, err, err_size))
        return 0;
    if ((kinds & RENDER_DEBUG_MASKS) && !write_masks(&rb, output, g, ctx, p, err, err_size))
        return 0;
    return 1;
}
