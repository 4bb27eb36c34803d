/* SPDX-License-Identifier: MIT */
/* A 5 x 7 bitmap font for the overlay: printable ASCII, lower case drawn
 * as upper case, anything else as '?'. */
#ifndef VIEWER_FONT_H
#define VIEWER_FONT_H

#define VIEWER_GLYPH_W 5
#define VIEWER_GLYPH_H 7

/* Character c's 7 rows, top first; bit 4 is the leftmost column. */
const unsigned char *viewer_font_glyph(char c);

#endif
