/* SPDX-License-Identifier: MIT */
/* A one-line description of the machine for the bench's closing line. */
#ifndef STIN_BENCH_MACHINE_H
#define STIN_BENCH_MACHINE_H

#include <stddef.h>

/* CPU model name from /proc/cpuinfo ("unknown CPU" if unreadable) and the
 * number of logical processors listed there (0 if unreadable). */
void bench_cpu_model(char *out, size_t size);
int bench_cpu_count(void);

#endif
