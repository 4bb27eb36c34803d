/* SPDX-License-Identifier: MIT */
/* World bounds of draws and frustum planes: conservative tests, so a skip
 * they allow is exact (what fails them cannot reach a visible pixel). */
#include "render/draw_bounds.h"
#include "internal.h"
#include "render/displace_chunk.h"

int stin__draw_world_corners(const stin_context *ctx, const stin__draw *d, float out[24])
{
    const stin_mesh_info *info = &ctx->meshes[d->mesh_slot].info;
    int c, k;
    if (stin__displace_active(ctx, &d->material))
        return 0;
    for (c = 0; c < 8; c++) {
        float p[3];
        for (k = 0; k < 3; k++)
            p[k] = (c >> k) & 1 ? info->bounds_max[k] : info->bounds_min[k];
        stin__mat4_transform_point(d->transform, p, out + 3 * c);
    }
    return 1;
}

void stin__frustum_planes(const float view_proj[16], float planes[6][4])
{
    int p, k;
    for (p = 0; p < 6; p++)
        for (k = 0; k < 4; k++) /* row 3 +/- row p/2 */
            planes[p][k] = view_proj[4 * k + 3] +
                           (p % 2 ? -view_proj[4 * k + p / 2] : view_proj[4 * k + p / 2]);
}

int stin__points_meet(const float *xyz, int n, const float *planes, int plane_count)
{
    int p, c;
    for (p = 0; p < plane_count; p++) {
        const float *q = planes + 4 * p, *v;
        float scale = stin__sqrtf(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        int outside = 0;
        if (!(scale > 0.0f))
            continue; /* no plane (an infinite far plane) */
        for (c = 0, v = xyz; c < n; c++, v += 3)
            if (q[0] * v[0] + q[1] * v[1] + q[2] * v[2] + q[3] <
                -1e-4f * (scale + (q[3] < 0.0f ? -q[3] : q[3])))
                outside++;
        if (outside == n)
            return 0;
    }
    return 1;
}
