/* SPDX-License-Identifier: MIT */
/* How far a caster's shadow volume must reach, and whether it reaches the
 * view at all (clamped and culled volumes, after Lloyd et al.'s CC shadow
 * volumes). A light sample's volumes only count where they cover a visible
 * receiver; the part beyond every visible receiver, and beyond the eye, is
 * never crossed by a view ray between the eye and a surface it sees, so each
 * volume is cut by a plane across its light's rays past all of them and
 * closed there (the far cap of z-fail moves onto the plane). That keeps the
 * count of every visible pixel and shrinks the fill from the horizon to the
 * receivers. A volume whose cut hull misses the view frustum is skipped. */
#include "shadow/volume_reach.h"
#include "render/draw_bounds.h"

static float dot3(const float a[3], const float b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void grow(float lo[3], float hi[3], const float p[3])
{
    int k;
    for (k = 0; k < 3; k++) {
        if (p[k] < lo[k]) lo[k] = p[k];
        if (p[k] > hi[k]) hi[k] = p[k];
    }
}

/* The eye: the view's inverse translation. */
static void eye_position(const float view[16], float eye[3])
{
    int k;
    for (k = 0; k < 3; k++)
        eye[k] = -(view[4 * k] * view[12] + view[4 * k + 1] * view[13] + view[4 * k + 2] * view[14]);
}

void stin__volume_reach_begin(const stin_context *ctx, const float light_world[4],
                              stin__volume_reach *r)
{
    uint32_t i;
    int k;
    float eye[3];
    /* a keep_contents frame's depth may hold the caller's own surfaces,
     * which the visibility export and mask count for: not ours to bound */
    r->bounded = !(ctx->desc.debug_flags & STIN_DEBUG_VOLUME_UNBOUNDED) && !ctx->frame.keep_contents;
    for (k = 0; k < 4; k++)
        r->light[k] = light_world[k];
    stin__frustum_planes(ctx->view_proj, r->camera);
    eye_position(ctx->frame.view, eye);
    for (k = 0; k < 3; k++)
        r->box_min[k] = r->box_max[k] = eye[k];
    for (i = 0; i < ctx->draw_count && r->bounded; i++) {
        float corners[24];
        int c;
        if (!stin__draw_world_corners(ctx, &ctx->draws[i], corners)) {
            r->bounded = 0; /* a receiver whose bounds tell nothing */
            break;
        }
        if (!stin__points_meet(corners, 8, r->camera[0], 6))
            continue; /* not visible: it receives nothing anyone sees */
        for (c = 0; c < 8; c++)
            grow(r->box_min, r->box_max, corners + 3 * c);
    }
}

/* The largest d . (q - origin) over the 8 corners of the box lo..hi. */
static float box_reach(const float lo[3], const float hi[3], const float d[3],
                       const float origin[3])
{
    float best = -1e30f;
    int c, k;
    for (c = 0; c < 8; c++) {
        float q[3], t;
        for (k = 0; k < 3; k++)
            q[k] = ((c >> k) & 1 ? hi[k] : lo[k]) - origin[k];
        t = dot3(q, d);
        if (t > best)
            best = t;
    }
    return best;
}

static const float unbounded[4] = {0.0f, 0.0f, 0.0f, -1.0f};

int stin__volume_reach_caster(const stin__volume_reach *r, const float corners[24],
                              float far_plane[4])
{
    float axis[3], origin[3] = {0, 0, 0}, t = -1e30f, diag2 = 0.0f, pts[48];
    int c, k;
    for (k = 0; k < 4; k++)
        far_plane[k] = unbounded[k];
    if (!r->bounded)
        return 1;
    if (r->light[3] == 0.0f) { /* directional: the rays run away from the light */
        float len = stin__sqrtf(dot3(r->light, r->light));
        if (!(len > 0.0f))
            return 1;
        for (k = 0; k < 3; k++)
            axis[k] = -r->light[k] / len;
    } else { /* a point: the axis from it through the caster's centre */
        float center[3] = {0, 0, 0}, radius2 = 0.0f, dist;
        for (c = 0; c < 8; c++)
            for (k = 0; k < 3; k++)
                center[k] += 0.125f * corners[3 * c + k];
        for (c = 0; c < 8; c++) {
            float d2 = 0.0f;
            for (k = 0; k < 3; k++)
                d2 += (corners[3 * c + k] - center[k]) * (corners[3 * c + k] - center[k]);
            if (d2 > radius2)
                radius2 = d2;
        }
        for (k = 0; k < 3; k++) {
            origin[k] = r->light[k] / r->light[3];
            axis[k] = center[k] - origin[k];
        }
        dist = stin__sqrtf(dot3(axis, axis));
        /* every ray through the caster must lean less than 90 degrees from
         * the axis, or no plane across the axis cuts them all */
        if (!(dist * dist > 1.0001f * radius2 * 1.0001f))
            return 1;
        for (k = 0; k < 3; k++)
            axis[k] /= dist;
    }
    for (c = 0; c < 8; c++) { /* past the caster itself too: every vertex before the cut */
        float q[3], d;
        for (k = 0; k < 3; k++)
            q[k] = corners[3 * c + k] - origin[k];
        d = dot3(q, axis);
        if (d > t)
            t = d;
    }
    {
        float rec = box_reach(r->box_min, r->box_max, axis, origin);
        if (rec > t)
            t = rec;
    }
    for (k = 0; k < 3; k++)
        diag2 += (r->box_max[k] - r->box_min[k]) * (r->box_max[k] - r->box_min[k]);
    /* a margin, so no receiver point ties with the far cap */
    t += 1e-3f * stin__sqrtf(diag2) + 1e-3f * (t < 0.0f ? -t : t) + 1e-6f;
    for (k = 0; k < 3; k++)
        far_plane[k] = axis[k];
    far_plane[3] = -(t + dot3(axis, origin));
    /* the cut volume lies in the hull of the caster's box and the box's
     * shadow on the plane: cull it against the view */
    for (c = 0; c < 8; c++) {
        const float *q = corners + 3 * c;
        float dir[3], s, along;
        for (k = 0; k < 3; k++)
            dir[k] = r->light[3] == 0.0f ? axis[k] : q[k] - origin[k];
        along = dot3(far_plane, dir);
        if (!(along > 0.0f)) { /* the plane misses a ray (rounding): no cut */
            for (k = 0; k < 4; k++)
                far_plane[k] = unbounded[k];
            return 1;
        }
        s = -(dot3(far_plane, q) + far_plane[3]) / along;
        for (k = 0; k < 3; k++) {
            pts[3 * c + k] = q[k];
            pts[24 + 3 * c + k] = q[k] + s * dir[k];
        }
    }
    return stin__points_meet(pts, 16, r->camera[0], 6);
}

void stin__volume_plane_to_object(const float plane[4], const float model[16], float out[4])
{
    int j;
    for (j = 0; j < 4; j++) /* a plane is a row vector: plane . (M p) = (plane M) . p */
        out[j] = plane[0] * model[4 * j] + plane[1] * model[4 * j + 1] +
                 plane[2] * model[4 * j + 2] + plane[3] * model[4 * j + 3];
}
