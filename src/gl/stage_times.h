/* SPDX-License-Identifier: MIT */
/* GPU time per frame stage (gl/stage_times.c; stin.h, STIN_DEBUG_STAGE_TIMES):
 * a timestamp query at each change of stage, read at the frame's end. */
#ifndef STIN_STAGE_TIMES_H
#define STIN_STAGE_TIMES_H

#include <stddef.h>

#include "stin/stin.h"
#include "gl/gl_types.h"

/* Timestamps one frame can take: each stage change spends one (per light
 * about four); past the last the frame's remaining changes go uncounted,
 * their time to the stage before (logged once). */
#define STIN__STAGE_MARKS 256u

/* Bytes of the timestamps' private state (gl/stage_times_private.h; a
 * slot of frame/modules.c). */
size_t stin__times_state_bytes(const stin_desc *d);

/* The queries at stin_create where STIN_DEBUG_STAGE_TIMES asks and the
 * context has timer (and occlusion) queries; freed at release. */
void stin__times_init(stin_context *ctx);
void stin__times_release(stin_context *ctx);
/* The frame's first timestamp, opening stage s. */
void stin__times_begin(stin_context *ctx, stin_stage s);
/* A timestamp closing the current stage and opening s; returns the stage
 * it closed, for the caller to enter again when its part is done. */
stin_stage stin__times_enter(stin_context *ctx, stin_stage s);
/* The last timestamp; waits for it and sums the stages into the frame's
 * stats (stage_times 1). */
void stin__times_end(stin_context *ctx);

#endif
