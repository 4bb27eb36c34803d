/* SPDX-License-Identifier: MIT */
/*
 * The render tool's image contract (DESIGN.md): one frame of a scene read
 * back into the fixed EXR channels
 *   R G B A, P.X P.Y P.Z, N.X N.Y N.Z, Z, vis.R vis.G vis.B, T.R T.G T.B
 * Beauty comes from the lit frame, N from STIN_OUTPUT_NORMAL, vis from
 * STIN_OUTPUT_VISIBILITY, T the same values (the technique's visibility is
 * its transmittance: coloured where a translucent-shadows technique lets
 * light through transparent casters; the reference tells the two apart), P by unprojecting the depth buffer through the
 * camera (exact for every tier, no float targets needed), Z = |P - eye|.
 */
#ifndef STIN_TOOLS_AOV_H
#define STIN_TOOLS_AOV_H

#include "image_io.h"
#include "scene_gpu.h"
#include "stin_platform.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    AOV_R = 0, AOV_G, AOV_B, AOV_A, AOV_PX, AOV_PY, AOV_PZ, AOV_NX, AOV_NY, AOV_NZ, AOV_Z,
    AOV_VIS_R, AOV_VIS_G, AOV_VIS_B, AOV_T_R, AOV_T_G, AOV_T_B, AOV_CHANNELS
};
extern const char *const aov_channel_names[AOV_CHANNELS];

/* Renders the three outputs and fills img (allocated here, rows top to
 * bottom as in files). frame_ms gets the beauty frame's time (begin to
 * glFinish), frame_stats its statistics (either may be NULL; the
 * context's own are the last frame's, the visibility output's). 1 on
 * success; err says what failed. */
int aov_capture(const scene_gpu *g, stin_context *ctx, stin_platform *p, image *img,
                double *frame_ms, stin_frame_stats *frame_stats, char *err, size_t err_size);

/* The AOV image (allocated here) from one frame's read-backs, rows bottom to
 * top as GL reads them: RGBA8 beauty, normal (STIN_OUTPUT_NORMAL) and
 * visibility, depth in [0, 1], the frame's view and projection
 * (stin_query_frame_projection) and the camera's eye. aov_capture's
 * assembly, also used for frames read back elsewhere (a browser's). 1 on
 * success; err says what failed. */
int aov_assemble(int width, int height, const uint8_t *beauty, const uint8_t *normal,
                 const uint8_t *vis, const float *depth, const float view[16],
                 const float proj[16], const float eye[3], image *img, char *err,
                 size_t err_size);
/* Depth-buffer unprojection for one pixel centre (x, y from the bottom). */
void aov_unproject(const double inv_view_proj[16], int width, int height, int x, int y,
                   double depth, double out[3]);
/* Double-precision inverse of proj * view; 0 if singular. */
int aov_inverse_view_proj(const float view[16], const float proj[16], double out[16]);

#ifdef __cplusplus
}
#endif
#endif
