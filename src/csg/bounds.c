/* SPDX-License-Identifier: MIT */
/* The window rectangle a CSG primitive can cover: its mesh's bounding box
 * through its transform and the frame's view and projection. Where two
 * primitives' rectangles do not meet, neither covers a pixel of the other,
 * so goldfeather skips the parity pass of the one for the other (outside:
 * what a complemented primitive asks; a plain one rules the candidate out)
 * and its passes follow the primitives that overlap, not all of them. The
 * same holds where their world boxes do not meet: no point of the one lies
 * inside the other. */
#include "csg/csg_private.h"

#define NEAR_W 1e-6f /* clip w below which a point counts as at or behind the eye */

static void rect_add(float rect[4], const float clip[4])
{
    int k;
    for (k = 0; k < 2; k++) {
        float v = clip[k] / clip[3];
        rect[k] = v < rect[k] ? v : rect[k];
        rect[2 + k] = v > rect[2 + k] ? v : rect[2 + k];
    }
}

/* The box's part in front of the eye (w > NEAR_W): its corners there and
 * the points where its edges cross w = NEAR_W, projected. Empty (min > max)
 * where the whole box lies at or behind the eye. */
void stin__csg_screen_rect(const stin_context *ctx, const stin__draw *d, float rect[4])
{
    const stin_mesh_info *info = &ctx->meshes[d->mesh_slot].info;
    float m[16], clip[8][4];
    int i, k;
    stin__mat4_mul(m, ctx->view_proj, d->transform);
    rect[0] = rect[1] = 1e30f;
    rect[2] = rect[3] = -1e30f;
    for (i = 0; i < 8; i++) {
        const float c[3] = {(i & 1) ? info->bounds_max[0] : info->bounds_min[0],
                            (i & 2) ? info->bounds_max[1] : info->bounds_min[1],
                            (i & 4) ? info->bounds_max[2] : info->bounds_min[2]};
        for (k = 0; k < 4; k++)
            clip[i][k] = m[k] * c[0] + m[4 + k] * c[1] + m[8 + k] * c[2] + m[12 + k];
        if (clip[i][3] > NEAR_W)
            rect_add(rect, clip[i]);
    }
    for (i = 0; i < 8; i++) /* the 12 edges: corners one bit apart */
        for (k = 0; k < 3; k++) {
            int j = i | (1 << k), c;
            float t, x[4];
            if (j == i || (clip[i][3] > NEAR_W) == (clip[j][3] > NEAR_W))
                continue;
            t = (NEAR_W - clip[i][3]) / (clip[j][3] - clip[i][3]);
            for (c = 0; c < 4; c++)
                x[c] = clip[i][c] + t * (clip[j][c] - clip[i][c]);
            x[3] = NEAR_W;
            rect_add(rect, x);
        }
}

/* Whether two rectangles (normalised device x, y: min then max) meet, with
 * a pixel's margin for rasterisation at their edges. */
int stin__csg_rects_meet(const stin_context *ctx, const float a[4], const float b[4])
{
    const int *vp = ctx->frame.viewport;
    float mx = 2.0f / (float)(vp[2] > 0 ? vp[2] : 1), my = 2.0f / (float)(vp[3] > 0 ? vp[3] : 1);
    return a[0] <= b[2] + mx && b[0] <= a[2] + mx && a[1] <= b[3] + my && b[1] <= a[3] + my;
}

void stin__csg_world_box(const stin_context *ctx, const stin__draw *d, float box[6])
{
    const stin_mesh_info *info = &ctx->meshes[d->mesh_slot].info;
    const float *m = d->transform;
    int i, k;
    for (k = 0; k < 3; k++) {
        box[k] = 1e30f;
        box[3 + k] = -1e30f;
    }
    for (i = 0; i < 8; i++) {
        const float c[3] = {(i & 1) ? info->bounds_max[0] : info->bounds_min[0],
                            (i & 2) ? info->bounds_max[1] : info->bounds_min[1],
                            (i & 4) ? info->bounds_max[2] : info->bounds_min[2]};
        for (k = 0; k < 3; k++) {
            float v = m[k] * c[0] + m[4 + k] * c[1] + m[8 + k] * c[2] + m[12 + k];
            box[k] = v < box[k] ? v : box[k];
            box[3 + k] = v > box[3 + k] ? v : box[3 + k];
        }
    }
}

/* With a margin of 1e-3 of the larger extent: boxes that near may hold
 * faces the coplanar rule counts as one plane. */
int stin__csg_world_boxes_meet(const float a[6], const float b[6])
{
    float extent = 0.0f, margin;
    int k;
    for (k = 0; k < 3; k++) {
        float ea = a[3 + k] - a[k], eb = b[3 + k] - b[k];
        extent = ea > extent ? ea : extent;
        extent = eb > extent ? eb : extent;
    }
    margin = 1e-3f * extent;
    for (k = 0; k < 3; k++)
        if (a[k] > b[3 + k] + margin || b[k] > a[3 + k] + margin)
            return 0;
    return 1;
}

static float absf(float x) { return x < 0.0f ? -x : x; }

/* The window depth per unit of eye distance at clip w = z (perspective) or
 * anywhere (orthographic), and the least cosine between a viewport ray and
 * the view axis; 0 for a projection of neither plain form (oblique). */
static float depth_slope(const float *p, float z, float *cos_min)
{
    float tx, ty;
    if (p[3] != 0.0f || p[7] != 0.0f)
        return 0.0f;
    if (p[11] == 0.0f) { /* orthographic: rays along the axis */
        *cos_min = 1.0f;
        return p[15] != 0.0f ? 0.5f * absf(p[10] / p[15]) : 0.0f;
    }
    if (p[12] != 0.0f || p[13] != 0.0f || p[15] != 0.0f || !(z > 0.0f))
        return 0.0f;
    /* x_e / z_e = (x_ndc p11 - p8) / p0, at most this over the viewport */
    tx = (absf(p[11]) + absf(p[8])) / absf(p[0]);
    ty = (absf(p[11]) + absf(p[9])) / absf(p[5]);
    *cos_min = 1.0f / stin__sqrtf(1.0f + tx * tx + ty * ty);
    /* ndc z = p10 / p11 + p14 / w with w = p11 z_e */
    return 0.5f * absf(p[14] * p[11]) / (z * z);
}

/* The boxes' farthest eye distance (clip w), 0 where a corner is at or
 * behind the eye. */
static float farthest_w(const stin_context *ctx, const float a[6], const float b[6])
{
    const float *m = ctx->view_proj;
    float far = 0.0f;
    int i, j;
    for (j = 0; j < 2; j++) {
        const float *box = j ? b : a;
        for (i = 0; i < 8; i++) {
            float w = m[3] * box[(i & 1) ? 3 : 0] + m[7] * box[(i & 2) ? 4 : 1] +
                      m[11] * box[(i & 4) ? 5 : 2] + m[15];
            if (!(w > NEAR_W))
                return 0.0f;
            far = w > far ? w : far;
        }
    }
    return far;
}

int stin__csg_world_boxes_apart(const stin_context *ctx, const float a[6], const float b[6],
                                float units)
{
    const float *p = ctx->projection;
    float gap = 0.0f, step, slope, cos_min = 0.0f, z = 1.0f;
    int k;
    if (stin__csg_world_boxes_meet(a, b))
        return 0;
    for (k = 0; k < 3; k++) { /* the widest slab between them */
        float g = a[k] > b[3 + k] ? a[k] - b[3 + k] : b[k] - a[3 + k];
        gap = g > gap ? g : gap;
    }
    if (p[11] != 0.0f && !((z = farthest_w(ctx, a, b)) > 0.0f))
        return 0;
    slope = depth_slope(p, z, &cos_min);
    step = ctx->target.depth_bits > 16 ? 1.0f / 16777216.0f : 1.0f / 65536.0f;
    /* two points of one ray on either side of the slab lie at least gap
     * apart along it, gap * cos_min in eye distance */
    return slope > 0.0f && gap * cos_min * slope > units * step;
}

void stin__csg_rect_cut(float a[4], const float b[4])
{
    int k;
    for (k = 0; k < 2; k++) {
        a[k] = b[k] > a[k] ? b[k] : a[k];
        a[2 + k] = b[2 + k] < a[2 + k] ? b[2 + k] : a[2 + k];
    }
}

void stin__csg_region_reset(stin_context *ctx)
{
    stin__memcopy(ctx->csg->region, ctx->frame.viewport, sizeof ctx->csg->region);
}

/* A normalised device coordinate to a window one along axis k, within the
 * viewport's span [lo, hi]: far-off values (a box reaching behind the eye)
 * clamp before the conversion to int. */
static int window_of(const int *vp, int k, float v, int round_up)
{
    float w = (float)vp[k] + (v + 1.0f) * 0.5f * (float)vp[2 + k];
    float lo = (float)vp[k], hi = (float)(vp[k] + vp[2 + k]);
    w = w < lo ? lo : (w > hi ? hi : w);
    return round_up ? (int)w + ((float)(int)w < w) : (int)w;
}

int stin__csg_window_box(const stin_context *ctx, const float ndc[4], int box[4])
{
    const int *vp = ctx->frame.viewport;
    int lo[2], hi[2], k;
    for (k = 0; k < 2; k++) {
        if (!(ndc[k] <= ndc[2 + k]))
            return 0; /* empty, or behind the eye */
        lo[k] = window_of(vp, k, ndc[k], 0) - 1; /* a pixel's margin: rasterisation */
        hi[k] = window_of(vp, k, ndc[2 + k], 1) + 1;
        lo[k] = lo[k] < vp[k] ? vp[k] : lo[k];
        hi[k] = hi[k] > vp[k] + vp[2 + k] ? vp[k] + vp[2 + k] : hi[k];
        if (hi[k] <= lo[k])
            return 0;
    }
    box[0] = lo[0];
    box[1] = lo[1];
    box[2] = hi[0] - lo[0];
    box[3] = hi[1] - lo[1];
    return 1;
}

int stin__csg_region_narrow(stin_context *ctx, const float ndc[4])
{
    return stin__csg_window_box(ctx, ndc, ctx->csg->region);
}

void stin__csg_region_keep_to(const stin_context *ctx, stin__pass_state *ps)
{
    ps->scissor = 1;
    stin__memcopy(ps->scissor_box, ctx->csg->region, sizeof ps->scissor_box);
}

float stin__csg_nearest_w(const stin_context *ctx, const stin__draw *d)
{
    const stin_mesh_info *info = &ctx->meshes[d->mesh_slot].info;
    float m[16], nearest = 1e30f;
    int i;
    stin__mat4_mul(m, ctx->view_proj, d->transform);
    for (i = 0; i < 8; i++) {
        float w = m[3] * ((i & 1) ? info->bounds_max[0] : info->bounds_min[0]) +
                  m[7] * ((i & 2) ? info->bounds_max[1] : info->bounds_min[1]) +
                  m[11] * ((i & 4) ? info->bounds_max[2] : info->bounds_min[2]) + m[15];
        nearest = w < nearest ? w : nearest;
    }
    return nearest;
}

int stin__csg_eye(const stin_context *ctx, float eye[3])
{
    float inv[16];
    int k;
    /* the eye is the point the projection sends to w = 0 with x = y = 0:
     * the inverse's image of the clip direction (0, 0, 1, 0) */
    if (!stin__mat4_invert(inv, ctx->view_proj))
        return 0;
    if (!(inv[11] > 1e-20f || inv[11] < -1e-20f))
        return 0; /* orthographic: the eye lies at infinity */
    for (k = 0; k < 3; k++)
        eye[k] = inv[8 + k] / inv[11];
    return stin__finite_n(eye, 3);
}

float stin__csg_power(const stin_context *ctx, const stin__draw *d, const float eye[3])
{
    float box[6], centre, half, distance2 = 0.0f, radius2 = 0.0f;
    int k;
    stin__csg_world_box(ctx, d, box);
    for (k = 0; k < 3; k++) {
        centre = 0.5f * (box[k] + box[3 + k]);
        half = 0.5f * (box[3 + k] - box[k]);
        distance2 += (centre - eye[k]) * (centre - eye[k]);
        radius2 += half * half / 3.0f; /* a sphere's box is a cube: the sphere's own */
    }
    return distance2 - radius2;
}
