/* SPDX-License-Identifier: MIT */
/* The scene in a stin context made for the viewer's settings, in the
 * window's GL context. A new setting makes a new stin context (stin fixes
 * its tier and techniques at stin_create); one stin refuses leaves the
 * running one as it was, with stin's reason kept. */
#ifndef VIEWER_SESSION_H
#define VIEWER_SESSION_H

#include "cli_log.h"
#include "scene_context.h"
#include "viewer_settings.h"
#include "viewer_window.h"

typedef struct viewer_session {
    scene *scene;                       /* the loaded file; its camera is the frame's */
    const scene_csg_products *products; /* built once from the file */
    scene_context sc;                   /* sc.ctx NULL: none running */
    cli_log log;                        /* stin's log: errors and fallbacks kept */
    int verbose;
    viewer_settings running;            /* what sc.ctx was made with */
    char refused[512];                  /* why the last setting could not run ("" none) */
} viewer_session;

/* A stin context for settings in the current GL context; 1 on success.
 * On failure the session is as it was, refused says why (stin's log
 * line), and *exit_code is what a command line should exit with (1, 2, 3
 * as stin-render's). */
int viewer_session_open(viewer_session *v, const viewer_settings *settings, int *exit_code);
void viewer_session_close(viewer_session *v);
/* One frame of the scene, its camera as it stands, into the window's
 * framebuffer; stage times in stin_query_frame_stats afterwards. */
stin_result viewer_session_frame(viewer_session *v, const viewer_window *w);

#endif
