/* SPDX-License-Identifier: MIT */
/* Wall-clock timing and the median stin-bench reports. */
#ifndef STIN_BENCH_TIME_H
#define STIN_BENCH_TIME_H

#include <stddef.h>

/* CLOCK_MONOTONIC in milliseconds. */
double bench_now_ms(void);
/* Median of n values (mean of the middle two when n is even); sorts v. */
double bench_median(double *v, size_t n);

/* One timed frame of side 0 or 1 in ms; negative on failure. */
typedef double (*bench_frame_fn)(void *user, int side);
/* ABBA over `frames` pairs (0, 1 | 1, 0 | 0, 1 ...) so drift and noise fall
 * on both sides alike; the median of each side. verbose prints every frame
 * under `label`. 0 on failure, with err set. */
int bench_abba(int frames, bench_frame_fn frame, void *user, const char *label, int verbose,
               double *side0_ms, double *side1_ms, char *err, size_t err_size);
/* best = v on the first set-up, else the smaller: the lowest set-up median. */
void bench_keep_min(double *best, double v, int first);

#endif
