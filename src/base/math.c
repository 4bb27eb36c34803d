/* SPDX-License-Identifier: MIT */
/* Column-major 4x4 helpers (GL conventions) and float checks without libm. */
#include "internal.h"

void stin__mat4_identity(float m[16])
{
    int i;
    for (i = 0; i < 16; i++)
        m[i] = (i % 5 == 0) ? 1.0f : 0.0f;
}

void stin__mat4_mul(float out[16], const float a[16], const float b[16])
{
    float r[16];
    int c, row, k;
    for (c = 0; c < 4; c++)
        for (row = 0; row < 4; row++) {
            float s = 0.0f;
            for (k = 0; k < 4; k++)
                s += a[k * 4 + row] * b[c * 4 + k];
            r[c * 4 + row] = s;
        }
    stin__memcopy(out, r, sizeof r);
}

/* Cofactor expansion; returns 0 for a singular matrix. */
int stin__mat4_invert(float out[16], const float m[16])
{
    float inv[16], det;
    int i;
    inv[0] = m[5] * m[10] * m[15] - m[5] * m[11] * m[14] - m[9] * m[6] * m[15] +
             m[9] * m[7] * m[14] + m[13] * m[6] * m[11] - m[13] * m[7] * m[10];
    inv[4] = -m[4] * m[10] * m[15] + m[4] * m[11] * m[14] + m[8] * m[6] * m[15] -
             m[8] * m[7] * m[14] - m[12] * m[6] * m[11] + m[12] * m[7] * m[10];
    inv[8] = m[4] * m[9] * m[15] - m[4] * m[11] * m[13] - m[8] * m[5] * m[15] +
             m[8] * m[7] * m[13] + m[12] * m[5] * m[11] - m[12] * m[7] * m[9];
    inv[12] = -m[4] * m[9] * m[14] + m[4] * m[10] * m[13] + m[8] * m[5] * m[14] -
              m[8] * m[6] * m[13] - m[12] * m[5] * m[10] + m[12] * m[6] * m[9];
    inv[1] = -m[1] * m[10] * m[15] + m[1] * m[11] * m[14] + m[9] * m[2] * m[15] -
             m[9] * m[3] * m[14] - m[13] * m[2] * m[11] + m[13] * m[3] * m[10];
    inv[5] = m[0] * m[10] * m[15] - m[0] * m[11] * m[14] - m[8] * m[2] * m[15] +
             m[8] * m[3] * m[14] + m[12] * m[2] * m[11] - m[12] * m[3] * m[10];
    inv[9] = -m[0] * m[9] * m[15] + m[0] * m[11] * m[13] + m[8] * m[1] * m[15] -
             m[8] * m[3] * m[13] - m[12] * m[1] * m[11] + m[12] * m[3] * m[9];
    inv[13] = m[0] * m[9] * m[14] - m[0] * m[10] * m[13] - m[8] * m[1] * m[14] +
              m[8] * m[2] * m[13] + m[12] * m[1] * m[10] - m[12] * m[2] * m[9];
    inv[2] = m[1] * m[6] * m[15] - m[1] * m[7] * m[14] - m[5] * m[2] * m[15] +
             m[5] * m[3] * m[14] + m[13] * m[2] * m[7] - m[13] * m[3] * m[6];
    inv[6] = -m[0] * m[6] * m[15] + m[0] * m[7] * m[14] + m[4] * m[2] * m[15] -
             m[4] * m[3] * m[14] - m[12] * m[2] * m[7] + m[12] * m[3] * m[6];
    inv[10] = m[0] * m[5] * m[15] - m[0] * m[7] * m[13] - m[4] * m[1] * m[15] +
              m[4] * m[3] * m[13] + m[12] * m[1] * m[7] - m[12] * m[3] * m[5];
    inv[14] = -m[0] * m[5] * m[14] + m[0] * m[6] * m[13] + m[4] * m[1] * m[14] -
              m[4] * m[2] * m[13] - m[12] * m[1] * m[6] + m[12] * m[2] * m[5];
    inv[3] = -m[1] * m[6] * m[11] + m[1] * m[7] * m[10] + m[5] * m[2] * m[11] -
             m[5] * m[3] * m[10] - m[9] * m[2] * m[7] + m[9] * m[3] * m[6];
    inv[7] = m[0] * m[6] * m[11] - m[0] * m[7] * m[10] - m[4] * m[2] * m[11] +
             m[4] * m[3] * m[10] + m[8] * m[2] * m[7] - m[8] * m[3] * m[6];
    inv[11] = -m[0] * m[5] * m[11] + m[0] * m[7] * m[9] + m[4] * m[1] * m[11] -
              m[4] * m[3] * m[9] - m[8] * m[1] * m[7] + m[8] * m[3] * m[5];
    inv[15] = m[0] * m[5] * m[10] - m[0] * m[6] * m[9] - m[4] * m[1] * m[10] +
              m[4] * m[2] * m[9] + m[8] * m[1] * m[6] - m[8] * m[2] * m[5];
    det = m[0] * inv[0] + m[1] * inv[4] + m[2] * inv[8] + m[3] * inv[12];
    if (det == 0.0f || !stin__isfinite(det))
        return 0;
    det = 1.0f / det;
    for (i = 0; i < 16; i++)
        out[i] = inv[i] * det;
    return 1;
}

/* Singular or nearly so, whatever the scale: |det| within 1e-12 of the
 * smaller of its Hadamard bounds (the product of the row lengths, or of the
 * column lengths; the columns' keeps a far translation from looking
 * singular). */
int stin__mat4_singular(const float m[16])
{
    double det = stin__mat4_det(m), rows = 1.0, cols = 1.0;
    int r, c;
    for (r = 0; r < 4; r++) {
        double rl = 0.0, cl = 0.0;
        for (c = 0; c < 4; c++) {
            rl += (double)m[4 * c + r] * m[4 * c + r];
            cl += (double)m[4 * r + c] * m[4 * r + c];
        }
        rows *= rl;
        cols *= cl;
    }
    /* squared bounds: compare det^2 with (1e-12)^2 times them (an overflowing
     * bound, entries near float's largest, cannot judge: exact zero only) */
    rows = rows < cols ? rows : cols;
    return rows > 1e300 ? det == 0.0 : det * det <= 1e-24 * rows;
}

void stin__mat3_normal(float out[9], const float m[16])
{
    /* inverse transpose of the upper 3x3 = cofactor matrix / det */
    float a = m[0], b = m[4], c = m[8], d = m[1], e = m[5], f = m[9], g = m[2], h = m[6],
          k = m[10];
    float co[9], det;
    int i;
    co[0] = e * k - f * h;  co[3] = -(d * k - f * g); co[6] = d * h - e * g;
    co[1] = -(b * k - c * h); co[4] = a * k - c * g; co[7] = -(a * h - b * g);
    co[2] = b * f - c * e;  co[5] = -(a * f - c * d); co[8] = a * e - b * d;
    det = a * co[0] + b * co[3] + c * co[6];
    if (det == 0.0f)
        det = 1.0f;
    /* out is column-major: column j row i = cofactor(row i, col j) / det */
    for (i = 0; i < 3; i++) {
        out[i * 3 + 0] = co[i * 3 + 0] / det;
        out[i * 3 + 1] = co[i * 3 + 1] / det;
        out[i * 3 + 2] = co[i * 3 + 2] / det;
    }
}

void stin__mat4_transform_point(const float m[16], const float p[3], float out[3])
{
    float r[3];
    int i;
    for (i = 0; i < 3; i++)
        r[i] = m[i] * p[0] + m[4 + i] * p[1] + m[8 + i] * p[2] + m[12 + i];
    out[0] = r[0];
    out[1] = r[1];
    out[2] = r[2];
}

/* By the 2x2 minors of the top two rows (GL's column-major m[4 * col + row])
 * and those of the bottom two. */
double stin__mat4_det(const float m[16])
{
    static const int pair[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    static const double sign[6] = {1, -1, 1, 1, -1, 1};
    double det = 0.0;
    int k;
    for (k = 0; k < 6; k++) {
        int a = pair[k][0], b = pair[k][1], c = pair[5 - k][0], d = pair[5 - k][1];
        double top = (double)m[4 * a] * m[4 * b + 1] - (double)m[4 * b] * m[4 * a + 1];
        double bottom = (double)m[4 * c + 2] * m[4 * d + 3] - (double)m[4 * d + 2] * m[4 * c + 3];
        det += sign[k] * top * bottom;
    }
    return det;
}

/* Newton iterations from a bit-level guess: libm is not a dependency. */
float stin__sqrtf(float x)
{
    union { float f; uint32_t u; } v;
    float y;
    int i;
    if (!(x > 0.0f))
        return 0.0f;
    v.f = x;
    v.u = (v.u >> 1) + 0x1fc00000u;
    y = v.f;
    for (i = 0; i < 4; i++)
        y = 0.5f * (y + x / y);
    return y;
}

/* Divides by the largest component first, so the squares can neither
 * overflow (1e20) nor underflow (1e-30) whatever the vector's scale. */
int stin__normalize3(float v[3])
{
    float m = 0.0f, l;
    int k;
    for (k = 0; k < 3; k++) {
        float a = v[k] < 0.0f ? -v[k] : v[k];
        if (!stin__isfinite(v[k]))
            return 0;
        if (a > m)
            m = a;
    }
    if (!(m > 0.0f))
        return 0;
    for (k = 0; k < 3; k++)
        v[k] /= m;
    l = stin__sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (k = 0; k < 3; k++)
        v[k] /= l;
    return 1;
}

int stin__isfinite(float x)
{
    union { float f; uint32_t u; } v;
    v.f = x;
    return (v.u & 0x7f800000u) != 0x7f800000u;
}

/* Cosine of an angle in degrees by range reduction and a Taylor series
 * (accurate to float precision on [0, 180]); spot cones need nothing more. */
float stin__cos_deg(float degrees)
{
    double x = (double)degrees * 3.14159265358979323846 / 180.0, term = 1.0, sum = 1.0;
    int n;
    while (x > 3.14159265358979323846)
        x -= 2.0 * 3.14159265358979323846;
    while (x < -3.14159265358979323846)
        x += 2.0 * 3.14159265358979323846;
    for (n = 1; n < 20; n++) {
        term *= -x * x / ((2.0 * n - 1.0) * (2.0 * n));
        sum += term;
    }
    return (float)sum;
}

int stin__finite_n(const float *v, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!stin__isfinite(v[i]))
            return 0;
    return 1;
}

uint32_t stin__pow2_at_most(uint32_t n)
{
    uint32_t p = 1;
    while (p <= n / 2u)
        p *= 2u;
    return p;
}
