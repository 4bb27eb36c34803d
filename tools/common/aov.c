/* SPDX-License-Identifier: MIT */
/* Readback of one frame into the EXR channel set of the image contract. */
#include "aov.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

const char *const aov_channel_names[AOV_CHANNELS] = {
    "R", "G", "B", "A", "P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "Z", "vis.R", "vis.G", "vis.B",
    "T.R", "T.G", "T.B"};

int aov_inverse_view_proj(const float view[16], const float proj[16], double out[16])
{
    double m[16], inv[16], det;
    int c, r, k, i;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) {
            double s = 0;
            for (k = 0; k < 4; k++)
                s += (double)proj[k * 4 + r] * (double)view[c * 4 + k];
            m[c * 4 + r] = s;
        }
    /* Gauss-Jordan with partial pivoting on a row-major copy. */
    {
        double a[4][8];
        for (r = 0; r < 4; r++)
            for (c = 0; c < 4; c++) {
                a[r][c] = m[c * 4 + r];
                a[r][c + 4] = r == c;
            }
        for (c = 0; c < 4; c++) {
            int piv = c;
            for (r = c + 1; r < 4; r++)
                if (fabs(a[r][c]) > fabs(a[piv][c]))
                    piv = r;
            if (fabs(a[piv][c]) < 1e-300)
                return 0;
            for (k = 0; k < 8; k++) {
                double t = a[c][k];
                a[c][k] = a[piv][k];
                a[piv][k] = t;
            }
            det = a[c][c];
            for (k = 0; k < 8; k++)
                a[c][k] /= det;
            for (r = 0; r < 4; r++)
                if (r != c) {
                    double f = a[r][c];
                    for (k = 0; k < 8; k++)
                        a[r][k] -= f * a[c][k];
                }
        }
        for (r = 0; r < 4; r++)
            for (c = 0; c < 4; c++)
                inv[c * 4 + r] = a[r][c + 4];
    }
    for (i = 0; i < 16; i++)
        out[i] = inv[i];
    return 1;
}

void aov_unproject(const double m[16], int width, int height, int x, int y, double depth,
                   double out[3])
{
    double ndc[4] = {2.0 * (x + 0.5) / width - 1.0, 2.0 * (y + 0.5) / height - 1.0,
                     2.0 * depth - 1.0, 1.0};
    double w[4];
    int r;
    for (r = 0; r < 4; r++)
        w[r] = m[r] * ndc[0] + m[4 + r] * ndc[1] + m[8 + r] * ndc[2] + m[12 + r] * ndc[3];
    out[0] = w[0] / w[3];
    out[1] = w[1] / w[3];
    out[2] = w[2] / w[3];
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

typedef void (*finish_fn)(void);

static int render_read(const scene_gpu *g, stin_context *ctx, stin_platform *p,
                       stin_output out, uint8_t *rgba, double *ms, char *err, size_t err_size)
{
    int w = stin_platform_width(p), h = stin_platform_height(p);
    finish_fn finish;
    void *fp = stin_platform_get_proc_address(p, "glFinish");
    double t0;
    stin_result r;
    memcpy(&finish, &fp, sizeof finish);
    if (finish)
        finish();
    t0 = now_ms();
    r = scene_gpu_frame(g, ctx, w, h, out, stin_platform_framebuffer(p));
    if (finish)
        finish();
    if (ms)
        *ms = now_ms() - t0;
    if (r != STIN_OK) {
        snprintf(err, err_size, "frame failed: %s", stin_result_name(r));
        return 0;
    }
    if (!(out == STIN_OUTPUT_BEAUTY ? stin_platform_read_color(p, rgba)
                                    : stin_platform_read_data(p, rgba))) {
        snprintf(err, err_size, "colour readback failed");
        return 0;
    }
    return 1;
}

int aov_capture(const scene_gpu *g, stin_context *ctx, stin_platform *p, image *img,
                double *frame_ms, stin_frame_stats *frame_stats, char *err, size_t err_size)
{
    int w = stin_platform_width(p), h = stin_platform_height(p), ok = 0;
    size_t n = (size_t)w * h;
    uint8_t *beauty = malloc(n * 4), *normal = malloc(n * 4), *vis = malloc(n * 4);
    float *depth = malloc(n * sizeof(float));
    float view[16], proj[16];
    const scene_camera *cam = &g->src->camera;
    if (!beauty || !normal || !vis || !depth) {
        snprintf(err, err_size, "out of memory");
        goto done;
    }
    if (!render_read(g, ctx, p, STIN_OUTPUT_BEAUTY, beauty, frame_ms, err, err_size))
        goto done;
    if (frame_stats)
        *frame_stats = stin_query_frame_stats(ctx);
    /* Depth was written with this frame's projection, which shadow volumes
     * may have moved to an infinite far plane; the next frames' may differ
     * (the measured choice of the exact technique runs vdsm or volumes). */
    scene_camera_matrices(cam, w, h, view, proj);
    stin_query_frame_projection(ctx, proj);
    if (!stin_platform_read_depth(p, depth)) {
        snprintf(err, err_size, "depth readback failed");
        goto done;
    }
    if (!render_read(g, ctx, p, STIN_OUTPUT_NORMAL, normal, NULL, err, err_size) ||
        !render_read(g, ctx, p, STIN_OUTPUT_VISIBILITY, vis, NULL, err, err_size))
        goto done;
    ok = aov_assemble(w, h, beauty, normal, vis, depth, view, proj, cam->eye, img, err, err_size);
done:
    free(beauty);
    free(normal);
    free(vis);
    free(depth);
    return ok;
}

int aov_assemble(int w, int h, const uint8_t *beauty, const uint8_t *normal, const uint8_t *vis,
                 const float *depth, const float view[16], const float proj[16],
                 const float eye[3], image *img, char *err, size_t err_size)
{
    int x, y, c;
    double inv[16];
    if (!image_alloc(img, w, h, AOV_CHANNELS)) {
        snprintf(err, err_size, "out of memory");
        return 0;
    }
    for (c = 0; c < AOV_CHANNELS; c++)
        snprintf(img->channel_names[c], sizeof img->channel_names[c], "%s", aov_channel_names[c]);
    if (!aov_inverse_view_proj(view, proj, inv)) {
        snprintf(err, err_size, "camera matrices are singular");
        image_free(img);
        return 0;
    }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t src = (size_t)y * w + x;
            float *o = img->pixels + ((size_t)(h - 1 - y) * w + x) * AOV_CHANNELS;
            int covered = depth[src] < 1.0f;
            for (c = 0; c < 4; c++)
                o[AOV_R + c] = beauty[4 * src + c] / 255.0f;
            if (!covered) {
                /* P, N, Z stay 0 on the background; nothing there is in shadow */
                o[AOV_VIS_R] = o[AOV_VIS_G] = o[AOV_VIS_B] = 1.0f;
                o[AOV_T_R] = o[AOV_T_G] = o[AOV_T_B] = 1.0f;
                continue;
            }
            {
                double P[3], d[3], len = 0, nl = 0;
                aov_unproject(inv, w, h, x, y, depth[src], P);
                for (c = 0; c < 3; c++) {
                    double nv = normal[4 * src + c] / 255.0 * 2.0 - 1.0;
                    o[AOV_PX + c] = (float)P[c];
                    o[AOV_NX + c] = (float)nv;
                    d[c] = P[c] - eye[c];
                    len += d[c] * d[c];
                    nl += nv * nv;
                    o[AOV_VIS_R + c] = vis[4 * src + c] / 255.0f;
                    o[AOV_T_R + c] = o[AOV_VIS_R + c];
                }
                nl = nl > 0 ? sqrt(nl) : 1.0;
                for (c = 0; c < 3; c++)
                    o[AOV_NX + c] = (float)(o[AOV_NX + c] / nl);
                o[AOV_Z] = (float)sqrt(len);
            }
        }
    return 1;
}
