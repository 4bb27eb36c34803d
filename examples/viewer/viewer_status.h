/* SPDX-License-Identifier: MIT */
/* The window title: the tier and techniques stin chose, samples and sRGB,
 * the last frame's time and its stages, and why (the choice's reason, a
 * fallback stin logged during the frames, or what it refused). */
#ifndef VIEWER_STATUS_H
#define VIEWER_STATUS_H

#include "viewer_session.h"

#include <stddef.h>

/* why_feature: the feature whose reason the title ends with (the one a key
 * last changed; STIN_FEATURE_COUNT: shadows). frame_ms: the last frame,
 * begin to swap. */
void viewer_status_title(const viewer_session *v, const viewer_window *w,
                         stin_feature why_feature, double frame_ms, char *out, size_t size);
/* The title's facts a line each ('\n' between), for the overlay. */
void viewer_status_lines(const viewer_session *v, const viewer_window *w,
                         stin_feature why_feature, double frame_ms, char *out, size_t size);
/* The same facts over several lines, for stdout (H, and each change). */
void viewer_status_print(const viewer_session *v, const viewer_window *w);

#endif
