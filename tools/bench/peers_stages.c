/* SPDX-License-Identifier: MIT */
/* stin's GPU time per frame stage for a peers row: a second context of the
 * row's technique with STIN_DEBUG_STAGE_TIMES (timer queries, kept out of
 * the timed frames), one warm-up frame, then the frames, the median per
 * stage. */
#include "peers_rows.h"
#include "bench_time.h"

#include <string.h>

#define MOST_FRAMES 64

void peer_row_stages(peer_row *r, const bench_env *env, scene *s, int map_size, int frames)
{
    static double ms[STIN_STAGE_COUNT][MOST_FRAMES];
    peer_row t;
    int k, i, n = frames < MOST_FRAMES ? frames : MOST_FRAMES;
    if (r->osg || r->failed)
        return;
    memset(&t, 0, sizeof t);
    t.technique = r->technique;
    t.debug_flags = STIN_DEBUG_STAGE_TIMES;
    peer_row_create(&t, env, s, map_size);
    for (k = -1; k < n && !t.failed; k++) {
        stin_frame_stats fs;
        if (peer_row_frame(&t, env, PEER_SHADOWED) < 0)
            break;
        fs = stin_query_frame_stats(t.ctx);
        if (!fs.stage_times)
            break; /* no timer queries: no stages */
        for (i = 0; k >= 0 && i < STIN_STAGE_COUNT; i++)
            ms[i][k] = (double)fs.stage_ns[i] / 1e6;
    }
    if (k == n) {
        for (i = 0; i < STIN_STAGE_COUNT; i++)
            r->stage_ms[i] = bench_median(ms[i], (size_t)n);
        r->staged = 1;
    }
    peer_row_destroy(&t);
}
