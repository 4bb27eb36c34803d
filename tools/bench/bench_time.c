/* SPDX-License-Identifier: MIT */
#include "bench_time.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

double bench_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y ? 1 : 0;
}

double bench_median(double *v, size_t n)
{
    if (n == 0)
        return 0.0;
    qsort(v, n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int bench_abba(int frames, bench_frame_fn frame, void *user, const char *label, int verbose,
               double *side0_ms, double *side1_ms, char *err, size_t err_size)
{
    double *t[2];
    int k, j, ok = 0;
    t[0] = calloc((size_t)frames, sizeof(double));
    t[1] = calloc((size_t)frames, sizeof(double));
    if (!t[0] || !t[1]) {
        snprintf(err, err_size, "out of memory");
        goto done;
    }
    for (k = 0; k < frames; k++)
        for (j = 0; j < 2; j++) {
            int side = (k % 2 == 0) == (j == 0) ? 0 : 1;
            double ms = frame(user, side);
            if (ms < 0.0) {
                snprintf(err, err_size, "stin frame failed");
                goto done;
            }
            t[side][k] = ms;
        }
    if (verbose) {
        fprintf(stderr, "stin-bench: %s:", label);
        for (k = 0; k < frames; k++)
            fprintf(stderr, " %.2f/%.2f", t[0][k], t[1][k]);
        fprintf(stderr, "\n");
    }
    *side0_ms = bench_median(t[0], (size_t)frames);
    *side1_ms = bench_median(t[1], (size_t)frames);
    ok = 1;
done:
    free(t[0]);
    free(t[1]);
    return ok;
}

void bench_keep_min(double *best, double v, int first)
{
    if (first || v < *best)
        *best = v;
}
