/* SPDX-License-Identifier: MIT */
/* Light cameras for shadow maps (both tiers): a spot light's perspective
 * over its cone, a directional light's orthographic square fitted to the
 * receivers in view (snapped to whole texels so it does not swim as the
 * camera moves) with its depth over every caster, and a point light's six
 * 90-degree faces. Depth ranges are fitted to the draws' bounds. */
#include "internal.h"

/* ---- the light's camera ------------------------------------------------- */

static float dot3(const float a[3], const float b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void stin__light_look_along(float m[16], const float eye[3], const float dir[3])
{
    float up[3] = {0, 1, 0}, s[3], u[3], f[3] = {dir[0], dir[1], dir[2]}, l;
    if (f[1] > 0.99f || f[1] < -0.99f) {
        up[1] = 0;
        up[0] = 1;
    }
    s[0] = f[1] * up[2] - f[2] * up[1];
    s[1] = f[2] * up[0] - f[0] * up[2];
    s[2] = f[0] * up[1] - f[1] * up[0];
    l = stin__sqrtf(dot3(s, s));
    s[0] /= l;
    s[1] /= l;
    s[2] /= l;
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    stin__mat4_identity(m);
    m[0] = s[0], m[4] = s[1], m[8] = s[2];
    m[1] = u[0], m[5] = u[1], m[9] = u[2];
    m[2] = -f[0], m[6] = -f[1], m[10] = -f[2];
    m[12] = -dot3(s, eye);
    m[13] = -dot3(u, eye);
    m[14] = dot3(f, eye);
}

/* Bounding spheres of every draw in world space, folded into a depth range
 * along the light's view and, for directional lights, a lateral radius. */
/* A world-space sphere touches the camera's frustum (Gribb-Hartmann planes
 * of projection * view). */
static int in_view(const float vp[16], const float c[3], float r)
{
    int p, k;
    for (p = 0; p < 6; p++) {
        float pl[4], len;
        for (k = 0; k < 4; k++) /* row 3 +/- row p/2 */
            pl[k] = vp[4 * k + 3] + (p % 2 ? -vp[4 * k + p / 2] : vp[4 * k + p / 2]);
        len = stin__sqrtf(pl[0] * pl[0] + pl[1] * pl[1] + pl[2] * pl[2]);
        if (len > 0.0f && (pl[0] * c[0] + pl[1] * c[1] + pl[2] * c[2] + pl[3]) / len < -r)
            return 0;
    }
    return 1;
}

/* receivers_only: the lateral extent (and centre) covers only the draws the
 * camera sees, the depth range still every caster along the light. */
void stin__light_fit(const stin_context *ctx, const float view[16], int receivers_only, float *near_d,
                float *far_d, float *half_width, float center_out[3])
{
    uint32_t i;
    float lo = 1e30f, hi = -1e30f, lat = 0.0f, vp[16];
    float cmin[3] = {1e30f, 1e30f, 1e30f}, cmax[3] = {-1e30f, -1e30f, -1e30f};
    int k, seen = 0;
    stin__mat4_mul(vp, ctx->frame.projection, ctx->frame.view);
    for (i = 0; i < ctx->draw_count && receivers_only; i++) {
        const stin_mesh_info *info = &ctx->meshes[ctx->draws[i].mesh_slot].info;
        float c[3], w[3], half = 0;
        for (k = 0; k < 3; k++) {
            c[k] = 0.5f * (info->bounds_min[k] + info->bounds_max[k]);
            half += (info->bounds_max[k] - c[k]) * (info->bounds_max[k] - c[k]);
        }
        stin__mat4_transform_point(ctx->draws[i].transform, c, w);
        /* a generous radius (scale ignored is fine: only whether it is seen) */
        seen |= in_view(vp, w, 4.0f * stin__sqrtf(half) + 1e-3f);
    }
    if (!seen)
        receivers_only = 0; /* nothing in view: cover everything */
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[i];
        const stin_mesh_info *info = &ctx->meshes[d->mesh_slot].info;
        float c[3], w[3], e[3], r2 = 0, r;
        int corner;
        for (k = 0; k < 3; k++)
            c[k] = 0.5f * (info->bounds_min[k] + info->bounds_max[k]);
        stin__mat4_transform_point(d->transform, c, w);
        for (corner = 0; corner < 8; corner++) {
            float p[3], q[3], dd = 0;
            for (k = 0; k < 3; k++)
                p[k] = (corner >> k) & 1 ? info->bounds_max[k] : info->bounds_min[k];
            stin__mat4_transform_point(d->transform, p, q);
            for (k = 0; k < 3; k++)
                dd += (q[k] - w[k]) * (q[k] - w[k]);
            if (dd > r2)
                r2 = dd;
        }
        r = stin__sqrtf(r2);
        stin__mat4_transform_point(view, w, e);
        if (-e[2] - r < lo) lo = -e[2] - r;
        if (-e[2] + r > hi) hi = -e[2] + r;
        if (receivers_only && !in_view(vp, w, r))
            continue; /* casts into the map's depth range, but needs no texels */
        for (k = 0; k < 2; k++) {
            float a = (e[k] < 0 ? -e[k] : e[k]) + r;
            if (a > lat)
                lat = a;
        }
        for (k = 0; k < 3; k++) {
            if (w[k] - r < cmin[k]) cmin[k] = w[k] - r;
            if (w[k] + r > cmax[k]) cmax[k] = w[k] + r;
        }
    }
    *near_d = lo;
    *far_d = hi;
    *half_width = lat;
    for (k = 0; k < 3; k++)
        center_out[k] = 0.5f * (cmin[k] + cmax[k]);
}

void stin__light_perspective(float m[16], float fovy_deg, float n, float f)
{
    float half = 0.5f * fovy_deg, c = stin__cos_deg(half), s = stin__cos_deg(90.0f - half);
    float cot = c / s;
    stin__memzero(m, 16 * sizeof(float));
    m[0] = cot;
    m[5] = cot;
    m[10] = -(f + n) / (f - n);
    m[11] = -1.0f;
    m[14] = -2.0f * f * n / (f - n);
}

static void ortho(float m[16], float half_width, float n, float f)
{
    stin__mat4_identity(m);
    m[0] = 1.0f / half_width;
    m[5] = 1.0f / half_width;
    m[10] = -2.0f / (f - n);
    m[14] = -(f + n) / (f - n);
}

/* The light's view and projection, and the [near, far] its depth spans. */
/* Snaps the centre (in the light's frame) to whole texels and the square to
 * a power of two, so a moving camera moves the map by whole texels only. */
static float snap_directional(const float probe[16], float center[3], float half, uint32_t size)
{
    float e[3], texel, side = 1.0f;
    int k;
    while (side < half)
        side *= 2.0f;
    while (side * 0.5f >= half && side > 1e-6f)
        side *= 0.5f;
    if (!size)
        return half;
    texel = 2.0f * side / (float)size;
    stin__mat4_transform_point(probe, center, e);
    for (k = 0; k < 2; k++) { /* floor to a texel */
        float q = e[k] / texel;
        long qi = (long)q;
        if ((float)qi > q)
            qi--;
        e[k] = (float)qi * texel;
    }
    /* probe is a rotation: its inverse is its transpose */
    for (k = 0; k < 3; k++)
        center[k] = probe[k * 4 + 0] * e[0] + probe[k * 4 + 1] * e[1] + probe[k * 4 + 2] * e[2];
    return side;
}

int stin__light_camera(const stin_context *ctx, const stin_light_desc *l, float view[16],
                       float proj[16], float *n_out, float *f_out, uint32_t map_size)
{
    float n, f, half, center[3], eye[3];
    int k;
    if (l->type == STIN_LIGHT_SPOT) {
        stin__light_look_along(view, l->position, l->direction);
        stin__light_fit(ctx, view, 0, &n, &f, &half, center);
        if (f <= 0.0f)
            return 0; /* everything is behind the spot */
        if (n < f * 1e-3f)
            n = f * 1e-3f; /* 24 bits can span a 1:1000 range */
        {
            float fov = 2.0f * l->spot_cutoff_deg + 2.0f;
            stin__light_perspective(proj, fov > 170.0f ? 170.0f : fov, n, f);
        }
    } else if (l->type == STIN_LIGHT_DIRECTIONAL) {
        float probe[16];
        stin__mat4_identity(probe);
        stin__light_look_along(probe, (const float[3]){0, 0, 0}, l->direction);
        stin__light_fit(ctx, probe, 1, &n, &f, &half, center);
        half = snap_directional(probe, center, half, map_size);
        for (k = 0; k < 3; k++) /* back off along the light so every draw is in front */
            eye[k] = center[k] - l->direction[k] * (f - n + 1.0f);
        stin__light_look_along(view, eye, l->direction);
        {
            float unused_half, unused_center[3];
            stin__light_fit(ctx, view, 1, &n, &f, &unused_half, unused_center);
        }
        if (n < 1e-3f)
            n = 1e-3f;
        ortho(proj, half > 0 ? half : 1.0f, n, f);
    } else {
        return 0;
    }
    *n_out = n;
    *f_out = f;
    return 1;
}


static const float cube_axis[STIN__CUBE_FACES][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                                     {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

void stin__light_cube_face(const stin_context *ctx, const float position[3], int face,
                           float view[16], float proj[16])
{
    float n, f, half, center[3];
    stin__light_look_along(view, position, cube_axis[face]);
    stin__light_fit(ctx, view, 0, &n, &f, &half, center);
    if (f <= 0.0f) { /* nothing in front: an empty face */
        f = 1.0f;
        n = 1e-3f;
    }
    if (n < f * 1e-3f)
        n = f * 1e-3f;
    /* the lookups pick the face by the major axis, so 90 degrees exactly */
    stin__light_perspective(proj, 90.0f, n, f);
}

void stin__light_window_matrix(float out[16], const float view[16], const float proj[16])
{
    float vp[16], bias[16];
    stin__mat4_mul(vp, proj, view);
    stin__mat4_identity(bias);
    bias[0] = bias[5] = bias[10] = 0.5f;
    bias[12] = bias[13] = bias[14] = 0.5f;
    stin__mat4_mul(out, bias, vp);
}

void stin__light_into_cell(float m[16], int cell)
{
    float sx = 1.0f / (float)STIN__ATLAS_COLUMNS, sy = 1.0f / (float)STIN__ATLAS_ROWS;
    float ox = (float)((unsigned)cell % STIN__ATLAS_COLUMNS) * sx;
    float oy = (float)((unsigned)cell / STIN__ATLAS_COLUMNS) * sy;
    int c;
    for (c = 0; c < 4; c++) {
        m[4 * c + 0] = sx * m[4 * c + 0] + ox * m[4 * c + 3];
        m[4 * c + 1] = sy * m[4 * c + 1] + oy * m[4 * c + 3];
    }
}
