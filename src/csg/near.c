/* SPDX-License-Identifier: MIT */
/* CSG and the camera's near and far planes. A primitive the near plane
 * cuts has lost the faces between the eye and the plane, so counting the
 * faces in front of a point no longer says whether the point is inside it;
 * counting the faces behind the point still does, as long as the far plane
 * cuts nothing (or depth clamping keeps what it would cut). Where the near
 * plane itself lies inside a product, the product is cut open there: the
 * cut is drawn as a cap, a quad at window depth STIN__CSG_CAP_DEPTH facing
 * the eye, which the resolve treats as one more candidate surface. */
#include "csg/csg_private.h"

/* Clip-space position of world point p. */
static void to_clip(const float m[16], const float p[3], float out[4])
{
    int i;
    for (i = 0; i < 4; i++)
        out[i] = m[i] * p[0] + m[4 + i] * p[1] + m[8 + i] * p[2] + m[12 + i];
}

void stin__csg_planes_cut(const stin_context *ctx, const stin__draw *d, int *near_cut,
                          int *far_cut)
{
    float reach;
    stin__csg_clip_extent(ctx, d, near_cut, far_cut, &reach);
}

void stin__csg_clip_extent(const stin_context *ctx, const stin__draw *d, int *near_cut,
                           int *far_cut, float *reach)
{
    const stin_mesh_info *info = &ctx->meshes[d->mesh_slot].info;
    float vp[16];
    int corner, k;
    *near_cut = *far_cut = 0;
    *reach = 0.0f;
    stin__mat4_mul(vp, ctx->projection, ctx->frame.view);
    for (corner = 0; corner < 8; corner++) {
        float p[3], w[3], c[4];
        for (k = 0; k < 3; k++)
            p[k] = (corner >> k) & 1 ? info->bounds_max[k] : info->bounds_min[k];
        stin__mat4_transform_point(d->transform, p, w);
        to_clip(vp, w, c);
        if (c[2] < -c[3] || c[3] <= 0.0f)
            *near_cut = 1;
        if (c[2] > c[3])
            *far_cut = 1;
        for (k = 0; k < 4; k++) {
            float a = c[k] < 0.0f ? -c[k] : c[k];
            if (a > *reach)
                *reach = a;
        }
    }
}

/* The world point at window (ndc) x, y and the cap's depth. */
static int cap_point(const float inverse_vp[16], float x, float y, float out[3])
{
    float c[4];
    int i;
    for (i = 0; i < 4; i++)
        c[i] = inverse_vp[i] * x + inverse_vp[4 + i] * y +
               inverse_vp[8 + i] * (2.0f * STIN__CSG_CAP_DEPTH - 1.0f) + inverse_vp[12 + i];
    if (!(c[3] != 0.0f))
        return 0;
    for (i = 0; i < 3; i++)
        out[i] = c[i] / c[3];
    return stin__finite_n(out, 3);
}

/* The cap quad (object space [-1, 1]^2 at z = 0, facing +z) onto the
 * frame's plane at the cap's depth: x and y to the window's, z toward the
 * eye, so its normal faces the eye whatever the camera mirrors. */
int stin__csg_cap_transform(const stin_context *ctx, float out[16])
{
    float vp[16], inv[16], inv_view[16], a[3], b[3], c[3], toward[3];
    float len = 0.0f;
    int k;
    stin__mat4_mul(vp, ctx->projection, ctx->frame.view);
    if (!stin__mat4_invert(inv, vp) || !stin__mat4_invert(inv_view, ctx->frame.view) ||
        !cap_point(inv, 0.0f, 0.0f, a) || !cap_point(inv, 1.0f, 0.0f, b) ||
        !cap_point(inv, 0.0f, 1.0f, c))
        return 0;
    for (k = 0; k < 3; k++) {
        toward[k] = inv_view[8 + k]; /* the eye's +z in the world */
        out[k] = b[k] - a[k];
        out[4 + k] = c[k] - a[k];
        out[12 + k] = a[k];
        len += out[k] * out[k];
    }
    if (!stin__normalize3(toward))
        return 0;
    len = stin__sqrtf(len);
    for (k = 0; k < 3; k++)
        out[8 + k] = toward[k] * len;
    out[3] = out[7] = out[11] = 0.0f;
    out[15] = 1.0f;
    return !stin__mat4_singular(out);
}

void stin__csg_cap_init(stin_context *ctx)
{
    static const uint32_t tris[6] = {0, 1, 2, 0, 2, 3};
    static const float corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    stin__vertex v[4];
    int i;
    stin__memzero(v, sizeof v);
    for (i = 0; i < 4; i++) {
        v[i].position[0] = corner[i][0];
        v[i].position[1] = corner[i][1];
        v[i].normal[2] = 1.0f;
        v[i].uv[0] = 0.5f * (corner[i][0] + 1.0f);
        v[i].uv[1] = 0.5f * (corner[i][1] + 1.0f);
        v[i].tangent[0] = v[i].tangent[3] = 1.0f;
    }
    ctx->csg->cap_slot = stin__mesh_builtin(ctx, v, 4, tris, 2);
}
