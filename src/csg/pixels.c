/* SPDX-License-Identifier: MIT */
/* The resolve's pixels on the CPU (csg/resolve.c, csg/cast.c): arrays in
 * the block's texture staging (the larger of it and the mesh scratch, both
 * idle during a frame), 9 bytes a pixel of the viewport (the GPU resolve:
 * 1, for interval's walk and a stencil read where there are no queries);
 * the bound framebuffer's depth and stencil read back within the resolve's
 * region; and a result written into the bound depth buffer by glDrawPixels
 * or, on core profiles, an R32F texture and a quad writing gl_FragDepth. */
#include "csg/csg_private.h"

#define GL_STENCIL_INDEX 0x1901
#define GL_PACK_ROW_LENGTH 0x0D02
#define GL_PACK_SKIP_ROWS 0x0D03
#define GL_PACK_SKIP_PIXELS 0x0D04

typedef stin__csg_pixels resolve; /* csg.h: shared with the resolves */

static unsigned char *staging_of(stin_context *ctx, size_t *bytes)
{
    int staging = ctx->staging_bytes >= ctx->scratch_bytes;
    *bytes = staging ? ctx->staging_bytes : ctx->scratch_bytes;
    return staging ? ctx->staging : ctx->scratch;
}

size_t stin__csg_pixels_bytes(int w, int h) { return (size_t)w * (size_t)h * 9u; }

/* The resolve's pixels for the viewport at `offset` bytes into the
 * staging; 0 when it has not the room. */
int stin__csg_pixels_at(stin_context *ctx, size_t offset, resolve *r)
{
    const int *vp = ctx->frame.viewport;
    size_t bytes, need = stin__csg_pixels_bytes(vp[2], vp[3]);
    unsigned char *base = staging_of(ctx, &bytes);
    if (offset > bytes || need > bytes - offset)
        return 0;
    base += offset;
    r->x = vp[0];
    r->y = vp[1];
    r->w = vp[2];
    r->h = vp[3];
    r->pixels = (size_t)vp[2] * (size_t)vp[3];
    r->result = (float *)(void *)base;
    r->candidate = r->result + r->pixels;
    r->stencil = (unsigned char *)(r->candidate + r->pixels);
    r->bits = ctx->target.stencil_bits < 8 ? ctx->target.stencil_bits : 8;
    r->gpu = 0;
    return 1;
}

/* The frame's depth before a multisampled read-back resolve: a float a
 * pixel behind r's arrays (16-byte aligned); NULL without the room. */
float *stin__csg_pixels_held(stin_context *ctx, const resolve *r)
{
    size_t bytes, at = (stin__csg_pixels_bytes(r->w, r->h) + 15u) & ~(size_t)15u;
    unsigned char *base = staging_of(ctx, &bytes);
    if (at > bytes || r->pixels * sizeof(float) > bytes - at)
        return NULL;
    return (float *)(void *)(base + at);
}

/* The GPU resolve's pixels: the stencil read alone (1 byte a pixel). */
int stin__csg_pixels_gpu(stin_context *ctx, resolve *r)
{
    const int *vp = ctx->frame.viewport;
    size_t bytes;
    unsigned char *base = staging_of(ctx, &bytes);
    if ((size_t)vp[2] * (size_t)vp[3] > bytes)
        return 0;
    r->x = vp[0];
    r->y = vp[1];
    r->w = vp[2];
    r->h = vp[3];
    r->pixels = (size_t)r->w * (size_t)r->h;
    r->result = r->candidate = NULL;
    r->stencil = base;
    r->bits = ctx->target.stencil_bits < 8 ? ctx->target.stencil_bits : 8;
    r->gpu = 1;
    return 1;
}

/* ---- pixel transfer ------------------------------------------------------- */
/* The resolve's region of the bound framebuffer into its place in the
 * viewport-sized array out (rows r->w long); the rest of out is left as it
 * was (the loops over it keep to the region too). */
static void read_region(stin_context *ctx, const resolve *r, GLenum format, GLenum type,
                        void *out)
{
    const int *g = ctx->csg->region;
    int whole = g[0] == r->x && g[1] == r->y && g[2] == r->w && g[3] == r->h;
    if (!whole) {
        GL(ctx, PixelStorei)(GL_PACK_ROW_LENGTH, r->w);
        GL(ctx, PixelStorei)(GL_PACK_SKIP_PIXELS, g[0] - r->x);
        GL(ctx, PixelStorei)(GL_PACK_SKIP_ROWS, g[1] - r->y);
    }
    GL(ctx, ReadPixels)(g[0], g[1], g[2], g[3], format, type, out);
    if (!whole) { /* tightly packed again, as stin__pack_begin left it */
        GL(ctx, PixelStorei)(GL_PACK_ROW_LENGTH, 0);
        GL(ctx, PixelStorei)(GL_PACK_SKIP_PIXELS, 0);
        GL(ctx, PixelStorei)(GL_PACK_SKIP_ROWS, 0);
    }
}

/* OpenGL ES reads no GL_DEPTH_COMPONENT as floats: a 24-bit depth comes
 * back with its stencil as one GL_UNSIGNED_INT_24_8 word
 * (NV_read_depth_stencil, which stin__csg_init asks for on ES), each
 * turned into the float desktop GL would have read, in place. */
static void read_depth_es(stin_context *ctx, const resolve *r, float *out)
{
    const int *g = ctx->csg->region;
    int x, y;
    read_region(ctx, r, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out);
    for (y = 0; y < g[3]; y++) {
        float *row = out + (size_t)(g[1] - r->y + y) * (size_t)r->w + (size_t)(g[0] - r->x);
        for (x = 0; x < g[2]; x++) {
            uint32_t word;
            stin__memcopy(&word, &row[x], sizeof word); /* the bytes GL wrote */
            row[x] = (float)((double)(word >> 8) / 16777215.0);
        }
    }
}

void stin__csg_read_depth(stin_context *ctx, const resolve *r, float *out)
{
    if (ctx->caps.es && ctx->target.depth_bits <= 24)
        read_depth_es(ctx, r, out);
    else
        read_region(ctx, r, GL_DEPTH_COMPONENT, GL_FLOAT, out);
}

/* On ES a row piece at a time through a word buffer: the stencil array
 * has a byte a pixel only. */
#define ES_STENCIL_RUN 256

void stin__csg_read_stencil(stin_context *ctx, const resolve *r)
{
    const int *g = ctx->csg->region;
    uint32_t words[ES_STENCIL_RUN];
    int x, y, i, n;
    if (!ctx->caps.es) {
        read_region(ctx, r, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, r->stencil);
        return;
    }
    for (y = g[1]; y < g[1] + g[3]; y++)
        for (x = g[0]; x < g[0] + g[2]; x += n) {
            unsigned char *row = r->stencil + (size_t)(y - r->y) * (size_t)r->w + (size_t)(x - r->x);
            n = g[0] + g[2] - x < ES_STENCIL_RUN ? g[0] + g[2] - x : ES_STENCIL_RUN;
            GL(ctx, ReadPixels)(x, y, n, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, words);
            for (i = 0; i < n; i++)
                row[i] = (unsigned char)(words[i] & 0xffu);
        }
}

#define GL_R32F 0x822E

/* The result into the R32F texture (grown to the viewport), left bound on unit 0. */
void stin__csg_upload_result(stin_context *ctx, const resolve *r)
{
    stin__csg_state *c = ctx->csg;
    stin__unpack_saved saved;
    stin__bind_unit(ctx, 0, GL_TEXTURE_2D, c->depth_tex);
    stin__unpack_begin(ctx, &saved);
    if (r->w > c->tex_width || r->h > c->tex_height) {
        c->tex_width = r->w > c->tex_width ? r->w : c->tex_width;
        c->tex_height = r->h > c->tex_height ? r->h : c->tex_height;
        stin__rt_texture(ctx, c->depth_tex, GL_R32F, GL_RED, GL_FLOAT, c->tex_width,
                         c->tex_height);
    }
    GL(ctx, TexSubImage2D)(GL_TEXTURE_2D, 0, 0, 0, r->w, r->h, GL_RED, GL_FLOAT, r->result);
    stin__unpack_end(ctx, &saved);
}

/* Core profiles: the result into the R32F texture and a screen quad
 * writing it as gl_FragDepth. */
static void write_depth_core(stin_context *ctx, const resolve *r)
{
    stin__csg_state *c = ctx->csg;
    float origin[4];
    stin__csg_upload_result(ctx, r);
    GL(ctx, UseProgram)(c->depth_prog);
    stin__lit_program_forget(ctx);
    GL(ctx, Uniform1i)(c->u_depth, 0);
    origin[0] = (float)r->x;
    origin[1] = (float)r->y;
    origin[2] = origin[3] = 0.0f;
    GL(ctx, Uniform4fv)(c->u_origin, 1, origin);
    stin__screen_quad(ctx);
}

/* Identity matrices and no program (compatibility contexts), for draws
 * given in clip coordinates; end: the caller's or the fixed path's again. */
void stin__csg_identity_begin(stin_context *ctx, const stin__path *path)
{
    static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    int fixed = path == stin__fixed_path();
    if (!fixed) {
        GL(ctx, UseProgram)(0);
        stin__lit_program_forget(ctx);
    }
    GL(ctx, MatrixMode)(GL_PROJECTION);
    if (!fixed)
        GL(ctx, PushMatrix)(); /* the caller's (the fixed path pushed its own level) */
    GL(ctx, LoadMatrixf)(identity);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    if (!fixed)
        GL(ctx, PushMatrix)();
    GL(ctx, LoadMatrixf)(identity);
}

void stin__csg_identity_end(stin_context *ctx, const stin__path *path)
{
    if (path != stin__fixed_path()) {
        GL(ctx, PopMatrix)();
        GL(ctx, MatrixMode)(GL_PROJECTION);
        GL(ctx, PopMatrix)();
    } else {
        GL(ctx, MatrixMode)(GL_PROJECTION);
        GL(ctx, LoadMatrixf)(ctx->projection);
    }
    GL(ctx, MatrixMode)(GL_MODELVIEW);
}

/* values (r's viewport, rows r->w long) into the depth buffer at the
 * viewport's corner under pass state ps by glDrawPixels, with no program
 * (the fragments keep the pixels' depth) and the raster position at clip
 * (-1, -1). Compatibility contexts only. */
void stin__csg_draw_depth_pixels(stin_context *ctx, const stin__path *path, const resolve *r,
                                 const float *values, const stin__pass_state *ps)
{
    stin__unpack_saved saved;
    stin__pass_apply(ctx, ps);
    stin__csg_identity_begin(ctx, path);
    GL(ctx, RasterPos2f)(-1.0f, -1.0f);
    stin__unpack_begin(ctx, &saved);
    GL(ctx, DrawPixels)(r->w, r->h, GL_DEPTH_COMPONENT, GL_FLOAT, values);
    stin__unpack_end(ctx, &saved);
    stin__csg_identity_end(ctx, path);
    ctx->stats.passes++;
}

/* The result into the depth buffer at the viewport's corner (func: the
 * depth test): by glDrawPixels, or on core profiles through
 * write_depth_core. */
void stin__csg_write_depth(stin_context *ctx, const stin__path *path, const resolve *r,
                           GLenum func)
{
    stin__pass_state ps = stin__pass_defaults;
    ps.depth_test = 1;
    ps.depth_func = func;
    ps.color_write = 0;
    if (ctx->csg->depth_prog) {
        stin__pass_apply(ctx, &ps);
        write_depth_core(ctx, r);
        ctx->stats.passes++;
        return;
    }
    stin__csg_draw_depth_pixels(ctx, path, r, r->result, &ps);
}
