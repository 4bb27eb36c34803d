/* SPDX-License-Identifier: MIT */
/*
 * Runs untrusted-input work (model and image decoders we do not own) in a
 * child process with a time limit, so that a decoder that crashes or never
 * returns costs a one-line error instead of the whole tool.
 */
#ifndef STIN_TOOLS_ISOLATE_H
#define STIN_TOOLS_ISOLATE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Work done in the child: writes its result with isolate_write(fd, ...) and
 * returns 1, or writes a reason (one line) into why and returns 0. */
typedef int (*isolate_work)(void *arg, int fd, char *why, size_t why_size);

/* Runs work in a child and collects every byte it writes. On success returns
 * 1 and a malloc'ed *out of *out_size bytes (the caller frees it). On failure
 * returns 0 and writes why: the child's own reason, "took longer than N s",
 * "crashed (...)", or "more than MAX bytes". */
int isolate_run(isolate_work work, void *arg, unsigned timeout_s, size_t max_bytes,
                unsigned char **out, size_t *out_size, char *why, size_t why_size);

/* For the child: writes all n bytes (retrying short writes). 1 on success. */
int isolate_write(int fd, const void *data, size_t n);

#ifdef __cplusplus
}
#endif
#endif
