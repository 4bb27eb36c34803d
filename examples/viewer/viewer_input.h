/* SPDX-License-Identifier: MIT */
/* The window's input between two frames: keys pressed, the drag and the
 * wheel (GLFW callbacks into this struct). */
#ifndef VIEWER_INPUT_H
#define VIEWER_INPUT_H

#include "viewer_window.h"

#define VIEWER_INPUT_KEYS 16

typedef struct viewer_input {
    int keys[VIEWER_INPUT_KEYS]; /* GLFW key codes, in order; more are dropped */
    int key_count;
    double drag_x, drag_y;       /* pixels moved with the left button held */
    double wheel;                /* notches, away from the user positive */
    int dragging;
    double last_x, last_y;
} viewer_input;

/* Points w's callbacks at in (again after a window is re-created). */
void viewer_input_attach(viewer_input *in, viewer_window *w);
/* Waits for nothing: takes what happened since the last call into in,
 * which the caller then consumes and clears with viewer_input_clear. */
void viewer_input_poll(void);
void viewer_input_clear(viewer_input *in);

#endif
