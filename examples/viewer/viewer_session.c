/* SPDX-License-Identifier: MIT */
#include "viewer_session.h"
#include "one_line.h"
#include "technique_option.h"

#include <stdio.h>
#include <string.h>

enum { EXIT_FAILED = 1, EXIT_BAD_INPUT = 2, EXIT_UNSUPPORTED = 3 };

int viewer_session_open(viewer_session *v, const viewer_settings *settings, int *exit_code)
{
    stin_desc desc;
    scene_context sc;
    stin_result r;
    char err[512], line[1400];
    scene_context_step step;
    memset(&desc, 0, sizeof desc);
    desc.get_proc_address = viewer_window_get_proc;
    desc.log = cli_log_fn;
    desc.log_user = &v->log;
    desc.tier = settings->tier;
    desc.techniques[STIN_FEATURE_SHADOWS] = settings->shadows;
    desc.techniques[STIN_FEATURE_SURFACE] = settings->surface;
    desc.techniques[STIN_FEATURE_TRANSPARENCY] = settings->transparency;
    desc.debug_flags = STIN_DEBUG_STAGE_TIMES; /* the title's stage times */
    desc.shadows.map_size = (uint32_t)v->scene->shadow_map_size;
    memset(&v->log, 0, sizeof v->log);
    v->log.program = "viewer";
    v->log.verbose = v->verbose;
    v->log.collect = 1;
    step = scene_context_open(&sc, v->scene, v->products, &desc, &r, err, sizeof err);
    if (step != SCENE_CONTEXT_OK) {
        int bare = step == SCENE_CONTEXT_MEMORY || step == SCENE_CONTEXT_CREATE;
        /* the file, then with stin's own words: what it lacks */
        snprintf(line, sizeof line, "%s%s%s%s%s", bare ? v->scene->path : "", bare ? ": " : "",
                 err, v->log.first_error[0] ? ": " : "", v->log.first_error);
        one_line_copy(v->refused, sizeof v->refused, line);
        *exit_code = step == SCENE_CONTEXT_CREATE && r == STIN_ERROR_UNSUPPORTED ? EXIT_UNSUPPORTED
                   : step == SCENE_CONTEXT_CREATE || step == SCENE_CONTEXT_MEMORY ? EXIT_FAILED
                                                                                  : EXIT_BAD_INPUT;
        return 0;
    }
    viewer_session_close(v);
    v->sc = sc;
    v->running = *settings;
    v->refused[0] = '\0';
    v->log.note_count = 0; /* from here on: what frames fell back to */
    *exit_code = 0;
    return 1;
}

void viewer_session_close(viewer_session *v)
{
    if (v->sc.ctx)
        scene_context_close(&v->sc);
}

stin_result viewer_session_frame(viewer_session *v, const viewer_window *w)
{
    int width, height;
    viewer_window_size(w, &width, &height);
    viewer_window_begin_frame(w);
    return scene_gpu_frame(&v->sc.gpu, v->sc.ctx, width, height, STIN_OUTPUT_BEAUTY, 0);
}
