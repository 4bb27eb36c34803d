/* SPDX-License-Identifier: MIT */
/* The viewer's command line (viewer_options.c). */
#ifndef VIEWER_OPTIONS_H
#define VIEWER_OPTIONS_H

#include "viewer_camera.h"
#include "viewer_settings.h"

typedef struct viewer_options {
    const char *scene_path;
    const char *screenshot;  /* --screenshot OUT.png|OUT.exr after the last scripted frame */
    viewer_settings settings;
    int width, height;       /* 0: the scene's size */
    int frames;              /* --frames N: the scripted run (no input), then exit; 0: interactive */
    viewer_orbit orbit;      /* --orbit YAW,PITCH and --zoom F: the script's camera motion,
                              * spread evenly over its frames as a drag would be */
    const char *keys;        /* --keys: one key a frame from the first (letters as the keys) */
    int hidden, verbose;
} viewer_options;

/* Parses argv into *o; on a bad option prints one line to stderr and
 * returns 0. --help prints the usage and the keys, and exits 0. */
int viewer_parse_args(int argc, char **argv, viewer_options *o);

#endif
