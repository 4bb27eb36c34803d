/* SPDX-License-Identifier: MIT */
#include "viewer_camera.h"

#include <math.h>

#define PI 3.14159265358979323846
/* Tilting past the pole would flip the image over the up vector. */
#define PITCH_LIMIT_DEG 89.0

void viewer_orbit_reset(viewer_orbit *o)
{
    o->yaw_deg = o->pitch_deg = 0.0;
    o->zoom = 1.0;
}

void viewer_orbit_drag(viewer_orbit *o, double dx, double dy)
{
    o->yaw_deg = fmod(o->yaw_deg - 0.25 * dx, 360.0);
    o->pitch_deg += 0.25 * dy;
}

void viewer_orbit_wheel(viewer_orbit *o, double steps)
{
    o->zoom *= pow(0.9, steps);
    if (o->zoom < 0.01)
        o->zoom = 0.01;
    if (o->zoom > 100.0)
        o->zoom = 100.0;
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void normalise(double v[3])
{
    double n = sqrt(dot3(v, v));
    if (n > 0)
        v[0] /= n, v[1] /= n, v[2] /= n;
}

void viewer_orbit_apply(const viewer_orbit *o, const scene_camera *base, scene_camera *out)
{
    double off[3], up[3], h[3], side[3], r, along, hl, elev, az, el;
    int i;
    *out = *base;
    for (i = 0; i < 3; i++) {
        off[i] = (double)base->eye[i] - base->target[i];
        up[i] = base->up[i];
    }
    normalise(up);
    r = sqrt(dot3(off, off));
    if (!(r > 0))
        return;
    /* off in the frame (h, side, up): h its part across up, side = up x h */
    along = dot3(off, up);
    for (i = 0; i < 3; i++)
        h[i] = off[i] - along * up[i];
    hl = sqrt(dot3(h, h));
    if (hl < 1e-9 * r) { /* looking along up: any axis across it will do */
        double a[3] = {fabs(up[0]) < 0.9 ? 1.0 : 0.0, fabs(up[0]) < 0.9 ? 0.0 : 1.0, 0.0};
        double d = dot3(a, up);
        for (i = 0; i < 3; i++)
            h[i] = a[i] - d * up[i];
    }
    normalise(h);
    side[0] = up[1] * h[2] - up[2] * h[1];
    side[1] = up[2] * h[0] - up[0] * h[2];
    side[2] = up[0] * h[1] - up[1] * h[0];
    elev = atan2(along, hl) * 180.0 / PI;
    el = elev + o->pitch_deg; /* a file's camera beyond the limit stays where it is */
    if (el > PITCH_LIMIT_DEG && o->pitch_deg > 0)
        el = elev > PITCH_LIMIT_DEG ? elev : PITCH_LIMIT_DEG;
    if (el < -PITCH_LIMIT_DEG && o->pitch_deg < 0)
        el = elev < -PITCH_LIMIT_DEG ? elev : -PITCH_LIMIT_DEG;
    el *= PI / 180.0;
    az = o->yaw_deg * PI / 180.0;
    r *= o->zoom;
    for (i = 0; i < 3; i++)
        out->eye[i] = (float)(base->target[i] +
                              r * (cos(el) * (cos(az) * h[i] + sin(az) * side[i]) +
                                   sin(el) * up[i]));
    out->near_plane = (float)(base->near_plane * o->zoom);
    out->far_plane = (float)(base->far_plane * o->zoom);
}
