/* SPDX-License-Identifier: MIT */
/* Point samples of an area light for soft shadows: a Fibonacci spiral over
 * the sphere of the light's radius, the same for every frame (no shimmer)
 * and public so that a reference can use the very same points. */
#include "internal.h"

void stin_light_sample(const stin_light_desc *light, uint32_t i, uint32_t n, float out[3])
{
    double y, r, phi;
    if (!light || !out)
        return;
    out[0] = light->position[0];
    out[1] = light->position[1];
    out[2] = light->position[2];
    if (n <= 1 || !(light->radius > 0.0f) || light->type == STIN_LIGHT_DIRECTIONAL)
        return;
    i %= n;
    y = 1.0 - 2.0 * ((double)i + 0.5) / (double)n;
    r = (double)stin__sqrtf((float)(1.0 - y * y));
    phi = (double)i * 137.50776405003785; /* the golden angle, degrees */
    phi -= 360.0 * (double)(uint32_t)(phi / 360.0);
    out[0] += light->radius * (float)(r * (double)stin__cos_deg((float)phi));
    out[1] += light->radius * (float)y;
    out[2] += light->radius * (float)(r * (double)stin__cos_deg((float)(phi - 90.0)));
}
