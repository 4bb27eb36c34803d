/* SPDX-License-Identifier: MIT */
#include "light_reach.h"

#include <math.h>

int light_reaches(const scene *s, const ref_hit *h)
{
    const scene_light *l = &s->lights[0];
    const float *eye = s->camera.eye;
    double to_eye = 0, to_light = 0, len = 0, along = 0;
    int k;
    for (k = 0; k < 3; k++) {
        double L = l->type == SCENE_LIGHT_DIRECTIONAL ? -l->direction[k] : l->position[k] - h->P[k];
        to_eye += h->Ng[k] * (eye[k] - h->P[k]);
        to_light += h->Ng[k] * L;
        len += L * L;
        along += -L * l->direction[k];
    }
    if ((to_eye >= 0) != (to_light > 0))
        return 0;
    if (l->type == SCENE_LIGHT_SPOT &&
        along / sqrt(len) < cos(l->spot_cutoff_deg * 3.14159265358979323846 / 180.0))
        return 0;
    return 1;
}

int near_shadow_edge(const ref_hit *hits, const float *ref, int w, int h, int x, int y, int band)
{
    float v = ref[((size_t)y * w + x) * REFERENCE_CHANNELS + REFERENCE_CH_VIS_R];
    int dx, dy;
    for (dy = -band; dy <= band; dy++)
        for (dx = -band; dx <= band; dx++) {
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h)
                continue;
            if (hits[(size_t)ny * w + nx].object != hits[(size_t)y * w + x].object ||
                fabsf(ref[((size_t)ny * w + nx) * REFERENCE_CHANNELS + REFERENCE_CH_VIS_R] - v) > 0.5f)
                return 1;
        }
    return 0;
}
