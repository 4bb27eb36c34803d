/* SPDX-License-Identifier: MIT */
/* Progress lines on stderr for long loads and renders: what starts, and how
 * long it took, flushed at once. On when stderr is a terminal or with
 * --progress; otherwise stderr carries only the one line of a failure. */
#ifndef STIN_RENDER_PROGRESS_H
#define STIN_RENDER_PROGRESS_H

typedef struct progress {
    int on;
    double started; /* seconds, monotonic */
} progress;

void progress_init(progress *p, int forced);
/* "stin-render: WHAT ..." */
void progress_start(progress *p, const char *fmt, ...);
/* "stin-render: WHAT in S s" */
void progress_done(progress *p, const char *fmt, ...);

#endif
