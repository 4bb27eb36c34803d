/* SPDX-License-Identifier: MIT */
/* The window's read-back written as stin-render writes its images: PNG
 * sRGB-encoded, EXR linear (R G B A). */
#ifndef VIEWER_SHOT_H
#define VIEWER_SHOT_H

#include "viewer_window.h"

#include <stddef.h>

/* Reads the back buffer (call before the swap) and writes path; 0 and a
 * message in err on failure. */
int viewer_shot_write(const viewer_window *w, const char *path, char *err, size_t err_size);

#endif
