/* SPDX-License-Identifier: MIT */
/* An area light's point samples (stin_light_sample) and their shares. Seen
 * from any direction the points must cover the light's disc evenly: a
 * uniform disc holds half its points within r / sqrt(2) of the centre,
 * where points on the sphere put only 1 - cos 45 = 29% (rim-heavy, the
 * penumbra's bias). The shares must be whole 255ths summing to 1, so 8-bit
 * targets add the samples up to full light exactly. No GL. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "internal.h"

static stin_light_desc area_light(void)
{
    stin_light_desc l;
    memset(&l, 0, sizeof l);
    l.type = STIN_LIGHT_POINT;
    l.position[0] = 1.0f;
    l.position[1] = 2.0f;
    l.position[2] = 3.0f;
    l.radius = 0.5f;
    return l;
}

static void test_samples_inside_the_ball(void **state)
{
    stin_light_desc l = area_light();
    uint32_t n, i;
    (void)state;
    for (n = 1; n <= 64; n++)
        for (i = 0; i < n; i++) {
            float p[3];
            double d2 = 0;
            int c;
            stin_light_sample(&l, i, n, p);
            for (c = 0; c < 3; c++)
                d2 += (p[c] - l.position[c]) * (p[c] - l.position[c]);
            assert_true(d2 <= (double)l.radius * l.radius * 1.0002);
        }
}

/* Along each of several directions, the fraction of the n points whose
 * projection lies within r / sqrt(2) of the centre: 0.5 for a uniform disc. */
static void test_projection_is_even(void **state)
{
    static const double dirs[][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.577, 0.577, 0.577},
                                     {0.8, -0.6, 0}, {0, 0.28, -0.96}};
    stin_light_desc l = area_light();
    const uint32_t counts[] = {32, 64};
    size_t k, j;
    (void)state;
    for (j = 0; j < sizeof counts / sizeof counts[0]; j++)
        for (k = 0; k < sizeof dirs / sizeof dirs[0]; k++) {
            uint32_t i, inner = 0, n = counts[j];
            double len2 = dirs[k][0] * dirs[k][0] + dirs[k][1] * dirs[k][1] +
                          dirs[k][2] * dirs[k][2];
            for (i = 0; i < n; i++) {
                float p[3];
                double q[3], along = 0, rho2 = 0;
                int c;
                stin_light_sample(&l, i, n, p);
                for (c = 0; c < 3; c++) {
                    q[c] = (p[c] - l.position[c]) / l.radius;
                    along += q[c] * dirs[k][c];
                }
                for (c = 0; c < 3; c++) {
                    double t = q[c] - along * dirs[k][c] / len2;
                    rho2 += t * t;
                }
                inner += rho2 <= 0.5;
            }
            /* a uniform disc: 0.5; the sphere's surface: 0.29 */
            assert_true((double)inner / n >= 0.4 && (double)inner / n <= 0.6);
        }
}

static void test_shares_sum_to_one(void **state)
{
    uint32_t n, i;
    (void)state;
    assert_true(stin__light_sample_weight(0, 1) == 1.0f);
    for (n = 2; n <= 64; n++) {
        uint32_t sum = 0;
        for (i = 0; i < n; i++) {
            float w = stin__light_sample_weight(i, n) * 255.0f;
            uint32_t whole = (uint32_t)(w + 0.5f);
            assert_true(w - (float)whole < 1e-3f && (float)whole - w < 1e-3f); /* whole 255ths */
            assert_true(whole + 1 >= 255 / n && whole <= 255 / n + 1);
            sum += whole;
        }
        assert_int_equal(sum, 255);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_samples_inside_the_ball),
        cmocka_unit_test(test_projection_is_even),
        cmocka_unit_test(test_shares_sum_to_one),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
