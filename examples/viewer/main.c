/* SPDX-License-Identifier: MIT */
/* viewer: a window onto a scene file through libstin. Orbit and zoom with
 * the mouse; keys force the tier and each feature's technique (a new stin
 * context each time, what stin chose and why in the title and the
 * overlay), multisampling and sRGB. --frames N runs a script with no input instead and can write
 * the last frame's read-back (the test compares it with stin-render's). */
#include "cli_log.h"
#include "scene.h"
#include "scene_csg.h"
#include "viewer_camera.h"
#include "viewer_input.h"
#include "viewer_options.h"
#include "viewer_overlay.h"
#include "viewer_session.h"
#include "viewer_shot.h"
#include "viewer_status.h"

#include <GLFW/glfw3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_FAILED = 1, EXIT_BAD_INPUT = 2, EXIT_NO_DISPLAY = 4 };

typedef struct viewer {
    viewer_options opt;
    scene scene;
    scene_camera file_camera; /* the orbit's origin */
    scene_csg_products products;
    viewer_window window;
    viewer_input input;
    viewer_session session;
    viewer_settings asked;    /* where the keys have got to (running, or one stin refused) */
    viewer_orbit orbit;
    stin_feature why;         /* the feature the title explains */
    char title[1024];         /* the last frame's */
    char lines[2048];         /* the overlay's text, the last frame's */
    int overlay_on;           /* O */
    viewer_overlay overlay;
    int width, height;
} viewer;

static int open_window(viewer *v, int samples, char *err, size_t err_size)
{
    /* sRGB-capable always: G turns the encoding on and off without a new window */
    if (!viewer_window_open(&v->window, v->width, v->height, samples, 1, !v->opt.hidden,
                            "stin viewer", err, err_size))
        return 0;
    v->window.srgb_asked = v->asked.srgb; /* kept across new windows */
    viewer_input_attach(&v->input, &v->window);
    return 1;
}

/* settings into effect: a new window for other samples (the old count
 * again where the window system has none such), a new stin context; what
 * stin refuses leaves the running one. 0: nothing runs. */
static int apply(viewer *v, const viewer_settings *want, int new_window, int *exit_code)
{
    char err[512], note[640] = "";
    viewer_settings got = *want;
    if (new_window) {
        viewer_window_size(&v->window, &v->width, &v->height);
        viewer_session_close(&v->session);
        viewer_window_close(&v->window);
        if (!open_window(v, want->samples, err, sizeof err)) {
            snprintf(note, sizeof note, "%d samples: %s", want->samples, err);
            got.samples = v->session.running.samples;
            if (!open_window(v, got.samples, err, sizeof err)) {
                fprintf(stderr, "viewer: %s\n", err);
                *exit_code = EXIT_FAILED;
                return 0;
            }
        }
        if (!viewer_session_open(&v->session, &got, exit_code) &&
            !viewer_session_open(&v->session, &v->session.running, exit_code))
            return 0;
        if (note[0])
            snprintf(v->session.refused, sizeof v->session.refused, "%s", note);
        return 1;
    }
    return viewer_session_open(&v->session, want, exit_code) || v->session.sc.ctx;
}

static double now_ms(void)
{
    return glfwGetTime() * 1e3;
}

/* One frame: camera, stin, title; the caller swaps. */
static void frame(viewer *v, double *ms)
{
    double t0 = now_ms();
    stin_result r;
    viewer_orbit_apply(&v->orbit, &v->file_camera, &v->scene.camera);
    r = viewer_session_frame(&v->session, &v->window);
    if (r != STIN_OK)
        snprintf(v->session.refused, sizeof v->session.refused, "frame failed: %s%s%s",
                 stin_result_name(r), v->session.log.first_error[0] ? ": " : "",
                 v->session.log.first_error);
    *ms = now_ms() - t0;
    viewer_status_title(&v->session, &v->window, v->why, *ms, v->title, sizeof v->title);
    viewer_window_set_title(&v->window, v->title);
    if (v->overlay_on) { /* after stin's frame, over it; the times are the frame's alone */
        int w, h;
        viewer_window_size(&v->window, &w, &h);
        viewer_status_lines(&v->session, &v->window, v->why, *ms, v->lines, sizeof v->lines);
        viewer_overlay_draw(&v->overlay, v->lines, w, h);
    }
}

/* One key, as pressed in the window or given by --keys. 0: go on; else
 * quit, with *exit_code (0 for Q). */
static int handle_key(viewer *v, int key, int *exit_code)
{
    viewer_settings want = v->asked;
    stin_feature f;
    viewer_action a;
    want.srgb = v->window.srgb_asked;
    want.samples = v->session.running.samples;
    a = viewer_settings_key(&want, key, &f);
    v->asked = want; /* a refused setting too: the next press goes on from it */
    if (f != STIN_FEATURE_COUNT)
        v->why = f;
    *exit_code = 0;
    switch (a) {
    case VIEWER_QUIT:
        return 1;
    case VIEWER_NOTHING:
        return 0;
    case VIEWER_HELP:
        printf("%s", viewer_keys_help);
        return 0;
    case VIEWER_RESET_CAMERA:
        viewer_orbit_reset(&v->orbit);
        return 0;
    case VIEWER_SRGB:
        v->window.srgb_asked = want.srgb;
        break;
    case VIEWER_OVERLAY:
        v->overlay_on = !v->overlay_on;
        return 0;
    case VIEWER_RECREATE_CONTEXT:
    case VIEWER_RECREATE_WINDOW:
        if (!apply(v, &want, a == VIEWER_RECREATE_WINDOW, exit_code))
            return 1;
        break;
    }
    viewer_status_print(&v->session, &v->window);
    return 0;
}

/* The interactive loop until the window closes or Q. */
static int run_interactive(viewer *v)
{
    double ms = 0;
    int i, code = 0;
    printf("keys (H again for them):\n%s", viewer_keys_help);
    while (!glfwWindowShouldClose(v->window.glfw)) {
        viewer_input in;
        viewer_input_poll();
        in = v->input;
        viewer_input_clear(&v->input);
        viewer_orbit_drag(&v->orbit, in.drag_x, in.drag_y);
        viewer_orbit_wheel(&v->orbit, in.wheel);
        for (i = 0; i < in.key_count; i++)
            if (handle_key(v, in.keys[i], &code))
                return code;
        frame(v, &ms);
        glfwSwapBuffers(v->window.glfw);
    }
    return 0;
}

/* The script: frames with the orbit spread over them, then the read-back. */
static int run_script(viewer *v)
{
    viewer_orbit step = v->opt.orbit;
    double ms = 0;
    int i;
    char err[512];
    const char *keys = v->opt.keys;
    for (i = 1; i <= v->opt.frames; i++) {
        int code;
        if (keys && *keys && handle_key(v, (unsigned char)*keys++, &code))
            return code;
        v->orbit.yaw_deg = step.yaw_deg * i / v->opt.frames;
        v->orbit.pitch_deg = step.pitch_deg * i / v->opt.frames;
        v->orbit.zoom = 1.0 + (step.zoom - 1.0) * i / v->opt.frames;
        frame(v, &ms);
        if (i == v->opt.frames && v->opt.screenshot) {
            if (!viewer_shot_write(&v->window, v->opt.screenshot, err, sizeof err)) {
                fprintf(stderr, "viewer: %s\n", err);
                return EXIT_FAILED;
            }
            printf("wrote %s\n", v->opt.screenshot);
        }
        glfwSwapBuffers(v->window.glfw);
        viewer_input_poll();
    }
    viewer_status_print(&v->session, &v->window);
    printf("title: %s\n", v->title);
    if (v->overlay_on) /* the test compares what lies below the panel */
        printf("overlay: %dx%d at the top left\n", v->overlay.panel_w, v->overlay.panel_h);
    return v->session.refused[0] || v->session.log.errors ? EXIT_FAILED : 0;
}

int main(int argc, char **argv)
{
    static viewer v;
    char err[1024], note[1024];
    int code = EXIT_FAILED;
    setvbuf(stdout, NULL, _IOLBF, 0);
    if (!viewer_parse_args(argc, argv, &v.opt))
        return EXIT_BAD_INPUT;
    if (!scene_load(v.opt.scene_path, &v.scene, err, sizeof err)) {
        fprintf(stderr, "viewer: %s\n", err);
        return EXIT_BAD_INPUT;
    }
    if (v.scene.warnings)
        fprintf(stderr, "viewer: warning: %s", v.scene.warnings);
    if (!scene_csg_products_build(&v.scene, &v.products)) {
        fprintf(stderr, "viewer: %s: out of memory\n", v.scene.path);
        goto done;
    }
    v.width = v.opt.width ? v.opt.width : v.scene.width ? v.scene.width : 512;
    v.height = v.opt.height ? v.opt.height : v.scene.height ? v.scene.height : 512;
    if (!v.scene.has_camera)
        scene_camera_frame(&v.scene, v.width, v.height, &v.scene.camera);
    v.file_camera = v.scene.camera;
    viewer_orbit_reset(&v.orbit);
    v.why = STIN_FEATURE_COUNT;
    v.session.scene = &v.scene;
    v.session.products = &v.products;
    v.session.verbose = v.opt.verbose;
    v.asked = v.opt.settings;
    if (!open_window(&v, v.opt.settings.samples, err, sizeof err)) {
        /* a display without multisampled windows: say so, go on without */
        if (!v.opt.settings.samples || !open_window(&v, 0, note, sizeof note)) {
            fprintf(stderr, "viewer: %s\n", err);
            code = EXIT_NO_DISPLAY;
            goto done;
        }
        fprintf(stderr, "viewer: %d samples: %s; running without\n", v.opt.settings.samples, err);
        v.opt.settings.samples = 0;
    }
    if (!viewer_session_open(&v.session, &v.opt.settings, &code)) {
        fprintf(stderr, "viewer: %s\n", v.session.refused);
        goto done;
    }
    v.asked.samples = v.opt.settings.samples;
    v.overlay_on = !v.opt.frames; /* a script's read-back is stin's frame alone unless O */
    viewer_status_print(&v.session, &v.window);
    code = v.opt.frames ? run_script(&v) : run_interactive(&v);
done:
    viewer_session_close(&v.session);
    viewer_window_close(&v.window);
    viewer_window_shutdown();
    scene_csg_products_free(&v.products);
    scene_free(&v.scene);
    return code;
}
