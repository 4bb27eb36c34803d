/* SPDX-License-Identifier: MIT */
#include "raw_math.h"

void raw_mat4_mul(float out[16], const float a[16], const float b[16])
{
    int r, c, k;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) {
            float sum = 0.0f;
            for (k = 0; k < 4; k++)
                sum += a[4 * k + r] * b[4 * c + k];
            out[4 * c + r] = sum;
        }
}

void raw_mat3_normal(float out[9], const float m[16])
{
    /* Cofactors of the upper 3x3 over its determinant = inverse transpose. */
    float a = m[0], b = m[4], c = m[8], d = m[1], e = m[5], f = m[9], g = m[2], h = m[6],
          i = m[10];
    float co[9], det, inv;
    int k;
    co[0] = e * i - f * h;
    co[3] = -(d * i - f * g);
    co[6] = d * h - e * g;
    co[1] = -(b * i - c * h);
    co[4] = a * i - c * g;
    co[7] = -(a * h - b * g);
    co[2] = b * f - c * e;
    co[5] = -(a * f - c * d);
    co[8] = a * e - b * d;
    det = a * co[0] + b * co[3] + c * co[6];
    inv = det != 0.0f ? 1.0f / det : 1.0f;
    /* co is column-major (co[row + 3 col]), and C / det is the inverse transpose. */
    for (k = 0; k < 9; k++)
        out[k] = co[k] * inv;
}
