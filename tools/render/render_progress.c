/* SPDX-License-Identifier: MIT */
#include "render_progress.h"

#include <stdarg.h>
#include <stdio.h>
#include <time.h>
#include <unistd.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

void progress_init(progress *p, int forced)
{
    p->on = forced || isatty(2);
    p->started = now();
}

static void line(const char *fmt, va_list ap, const char *tail, double seconds)
{
    fputs("stin-render: ", stderr);
    vfprintf(stderr, fmt, ap);
    if (seconds >= 0)
        fprintf(stderr, " in %.1f s", seconds);
    fputs(tail, stderr);
    fflush(stderr);
}

void progress_start(progress *p, const char *fmt, ...)
{
    va_list ap;
    p->started = now();
    if (!p->on)
        return;
    va_start(ap, fmt);
    line(fmt, ap, " ...\n", -1.0);
    va_end(ap);
}

void progress_done(progress *p, const char *fmt, ...)
{
    va_list ap;
    if (!p->on)
        return;
    va_start(ap, fmt);
    line(fmt, ap, "\n", now() - p->started);
    va_end(ap);
}
