/* SPDX-License-Identifier: MIT */
/* Orbit and zoom about the scene camera's target: the file's camera turned
 * about its up vector (yaw) and tilted towards it (pitch, short of the
 * poles), its distance scaled (zoom). Computed from the file's camera each
 * time, so that any path to the same angles gives the same camera. */
#ifndef VIEWER_CAMERA_H
#define VIEWER_CAMERA_H

#include "scene.h"

typedef struct viewer_orbit {
    double yaw_deg, pitch_deg; /* 0, 0: the file's camera */
    double zoom;               /* distance factor, 1: the file's; < 1 nearer */
} viewer_orbit;

void viewer_orbit_reset(viewer_orbit *o);
/* A drag of dx, dy pixels (0.25 degrees a pixel); a wheel of steps notches
 * (each 10% nearer); both kept within reach. */
void viewer_orbit_drag(viewer_orbit *o, double dx, double dy);
void viewer_orbit_wheel(viewer_orbit *o, double steps);
/* base moved by o into out (near and far scaled with the distance). */
void viewer_orbit_apply(const viewer_orbit *o, const scene_camera *base, scene_camera *out);

#endif
