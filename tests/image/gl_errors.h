/* SPDX-License-Identifier: MIT */
/* The GL-error property of every image test: stin raises no GL error and no
 * driver error message. A synchronous KHR_debug callback sees each one as
 * the driver raises it (nothing is read with glGetError, so nothing of the
 * caller's is cleared); every public stin function that takes a context is
 * linked through a wrapper (gl_errors.c, STIN_CALL_WRAP in the Makefile)
 * that says whether stin or the test's own code made the call. */
#ifndef STIN_TESTS_GL_ERRORS_H
#define STIN_TESTS_GL_ERRORS_H

#include "image_test.h"

/* Installs the callback on the run's context and proves it fires (a
 * deliberate error outside stin): one PASS line "gl-errors", or SKIP with
 * the reason where the context cannot report errors this way. */
void gl_errors_arm(run *r);
/* Before each result line (report() calls it): the messages stin's calls
 * raised since the last line, as one FAIL line under `next`/gl-errors
 * naming them and the stin call. */
void gl_errors_flush(run *r, const char *next);
/* At the end: the last messages, and how many the tests' own code raised
 * outside stin calls (on purpose: the hostile tests), on stderr. */
void gl_errors_finish(run *r);

#endif
