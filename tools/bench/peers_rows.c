/* SPDX-License-Identifier: MIT */
#include "peers_rows.h"
#include "bench_options.h"
#include "bench_time.h"
#include "cli_log.h"
#include "peers_osg.h"
#include "stin_platform.h"
#ifdef STIN_BENCH_OSGSHADOW
#include "osgshadow_shim.h"
#endif

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *peer_osg_absent(const bench_env *env)
{
#ifdef STIN_BENCH_OSGSHADOW
    /* OSG calls libGL, whose dispatch follows the current EGL context; an
     * OSMesa context is not current there */
    if (strcmp(env->o->platform, "egl"))
        return "osgShadow draws through libGL, which does not reach an OSMesa context";
    /* OSG 3.6 is built for desktop GL: its viewer crashes on an ES context */
    if (env->caps->es)
        return "osgShadow needs desktop GL; this context is OpenGL ES";
    return NULL;
#else
    (void)env;
    return "stin-bench was built without osgShadow (libopenscenegraph-dev)";
#endif
}

static void stin_row(peer_row *r, const bench_env *env, scene *s, int map_size)
{
    static cli_log log; /* stin keeps the pointer for the context's life */
    stin_desc d;
    size_t bytes;
    stin_result res;
    memset(&log, 0, sizeof log);
    log.program = "stin-bench: peers";
    log.verbose = env->b.verbose;
    bench_desc_init(&env->b, &d);
    d.log = cli_log_fn;
    d.log_user = &log;
    d.tier = env->o->tier;
    d.techniques[STIN_FEATURE_SHADOWS] = (stin_technique)r->technique;
    d.shadows.map_size = (uint32_t)map_size;
    d.debug_flags = r->debug_flags;
    scene_gpu_size_desc(s, &d);
    bytes = stin_memory_size(&d);
    if (!bytes || !(r->block = malloc(bytes))) {
        snprintf(r->why, sizeof r->why, "stin_memory_size refused the desc");
        r->failed = 1;
        return;
    }
    res = stin_create(&d, r->block, bytes, &r->ctx);
    if (res != STIN_OK) {
        snprintf(r->why, sizeof r->why, "not on this context (stin_create: %s)",
                 stin_result_name(res));
        r->ctx = NULL;
        r->failed = 1;
        return;
    }
    if (!scene_gpu_create(&r->gpu, s, r->ctx, r->why, sizeof r->why))
        r->failed = 1;
}

void peer_row_create(peer_row *r, const bench_env *env, scene *s, int map_size)
{
    if (!r->osg) {
        stin_row(r, env, s, map_size);
        return;
    }
#ifdef STIN_BENCH_OSGSHADOW
    r->peer = peers_osg_peer(env, s, r->technique, map_size, r->why, sizeof r->why);
    r->failed = !r->peer;
#else
    snprintf(r->why, sizeof r->why, "%s", peer_osg_absent(env));
    r->failed = 1;
#endif
}

double peer_row_frame(peer_row *r, const bench_env *env, int mode)
{
    double t0 = bench_now_ms();
    if (r->failed)
        return -1.0;
    if (!r->osg) {
        stin_result res = scene_gpu_frame(&r->gpu, r->ctx, env->b.width, env->b.height,
                                          mode == PEER_VISIBILITY ? STIN_OUTPUT_VISIBILITY
                                                                  : STIN_OUTPUT_BEAUTY,
                                          stin_platform_framebuffer(env->b.plat));
        if (res != STIN_OK) {
            snprintf(r->why, sizeof r->why, "frame failed: %s", stin_result_name(res));
            r->failed = 1;
            return -1.0;
        }
    } else {
#ifdef STIN_BENCH_OSGSHADOW
        static const int osg_mode[] = {OSGS_SHADOWED, OSGS_UNSHADOWED, OSGS_FULL, OSGS_SHADOWED};
        if (!osgs_frame(r->peer, osg_mode[mode], r->why, sizeof r->why)) {
            r->failed = 1;
            return -1.0;
        }
#endif
    }
    env->b.gl->Finish();
    return bench_now_ms() - t0;
}

void peer_row_settled(peer_row *r)
{
    static const char *const names[] = {"no measured choice (vdsm or the selection's)",
                                        "vdsm", "volume, GPU-extruded", "volume, CPU-built"};
    stin_shadows_stats st;
    if (r->failed || !r->ctx)
        return;
    st = stin_query_frame_stats(r->ctx).shadows;
    if (st.choice_current > STIN_SHADOW_CHOICE_VOLUME_CPU)
        st.choice_current = STIN_SHADOW_CHOICE_OFF;
    if (st.choice_current == STIN_SHADOW_CHOICE_OFF) {
        snprintf(r->note, sizeof r->note, "%s", names[0]);
        return;
    }
    snprintf(r->note, sizeof r->note,
             "settled on %s (smoothed GPU ms: vdsm %.2f, GPU volumes %.2f, CPU volumes %.2f)",
             names[st.choice_current], st.choice_ms[0], st.choice_ms[1], st.choice_ms[2]);
}

void peer_row_destroy(peer_row *r)
{
    if (r->ctx) {
        scene_gpu_destroy(&r->gpu, r->ctx);
        stin_destroy(r->ctx);
    }
    free(r->block);
#ifdef STIN_BENCH_OSGSHADOW
    if (r->peer)
        osgs_destroy(r->peer);
#endif
    r->ctx = NULL;
    r->block = NULL;
    r->peer = NULL;
}
