/* SPDX-License-Identifier: MIT */
/* Point samples of an area light for soft shadows. The light is a ball of
 * uniform radiance; seen from any receiver it is a disc, and n points cast
 * a penumbra of n + 1 steps whose accuracy is how evenly the points'
 * projection covers that disc. Points on the sphere project rim-heavy
 * (density 1 / sqrt(r^2 - rho^2) on the disc: a shadow-soft penumbra stays
 * 0.04 off the truth however many). Inside the ball with radial density
 * 1 / sqrt(r^2 - s^2) they project to a uniform disc in every direction
 * (Abel transform), so no direction is favoured: the radii stratified
 * (the van der Corput sequence of i, so every prefix is spread too), the
 * directions a Fibonacci spiral. The same for every frame (no shimmer). */
#include "internal.h"

/* The radius (of 1) below which a fraction u of the points lie: the inverse
 * of F(s) = (asin s - s sqrt(1 - s^2)) / (pi / 2). With s = sin(x / 2),
 * F = (x - sin x) / pi, increasing on [0, pi]: bisected in degrees. */
static double ball_radius(double u)
{
    double lo = 0.0, hi = 180.0, target = u * 180.0;
    int k;
    for (k = 0; k < 40; k++) {
        double x = 0.5 * (lo + hi);
        double f = x - 57.29577951308232 * (double)stin__cos_deg((float)(x - 90.0)); /* x - sin x */
        if (f < target)
            lo = x;
        else
            hi = x;
    }
    return (double)stin__cos_deg((float)(90.0 - 0.25 * (lo + hi)));
}

/* Base-2 radical inverse of i, offset by half a stratum of n. */
static double stratum(uint32_t i, uint32_t n)
{
    double u = 0.0, f = 0.5;
    for (; i; i >>= 1, f *= 0.5)
        if (i & 1u)
            u += f;
    u += 0.5 / (double)n;
    return u >= 1.0 ? u - 1.0 : u;
}

void stin_light_sample(const stin_light_desc *light, uint32_t i, uint32_t n, float out[3])
{
    double y, r, phi, s;
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
    s = light->radius * ball_radius(stratum(i, n));
    out[0] += (float)(s * r * (double)stin__cos_deg((float)phi));
    out[1] += (float)(s * y);
    out[2] += (float)(s * r * (double)stin__cos_deg((float)(phi - 90.0)));
}

float stin__light_sample_weight(uint32_t i, uint32_t n)
{
    if (n <= 1)
        return 1.0f;
    i %= n;
    return (float)((255u * (i + 1u)) / n - (255u * i) / n) / 255.0f;
}
