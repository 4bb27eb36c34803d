/* Wall-clock timing and the median stin-bench reports. */
#ifndef STIN_BENCH_TIME_H
#define STIN_BENCH_TIME_H

#include <stddef.h>

/* CLOCK_MONOTONIC in milliseconds. */
double bench_now_ms(void);
/* Median of n values (mean of the middle two when n is even); sorts v. */
double bench_median(double *v, size_t n);

#endif
