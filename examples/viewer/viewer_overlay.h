/* SPDX-License-Identifier: MIT */
/* The status overlay: lines of text on a dark panel at the window's top
 * left, drawn with GL after stin's frame (the title is cut at the window's
 * width; the overlay wraps instead). */
#ifndef VIEWER_OVERLAY_H
#define VIEWER_OVERLAY_H

/* The panel the last draw covered, in pixels from the top left. */
typedef struct viewer_overlay {
    int panel_w, panel_h;
} viewer_overlay;

/* Draws text ('\n' between lines; each wrapped at the window's width) over
 * the bound framebuffer of width x height pixels, as far down as it fits,
 * by scissored clears: no shader, texture, matrix or blend state of the
 * frame's matters. The scissor box and test, clear colour and colour mask
 * are given back. */
void viewer_overlay_draw(viewer_overlay *o, const char *text, int width, int height);

#endif
