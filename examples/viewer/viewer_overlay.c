/* SPDX-License-Identifier: MIT */
#include "viewer_overlay.h"

#include "viewer_font.h"

#include <GLFW/glfw3.h>
#include <string.h>

typedef void (*gl_scissor_fn)(int x, int y, int w, int h);
typedef void (*gl_clear_color_fn)(float r, float g, float b, float a);
typedef void (*gl_bits_fn)(unsigned mask);
typedef void (*gl_enum_fn)(unsigned cap);
typedef unsigned char (*gl_is_enabled_fn)(unsigned cap);
typedef void (*gl_get_iv_fn)(unsigned pname, int *v);
typedef void (*gl_get_fv_fn)(unsigned pname, float *v);
typedef void (*gl_get_bv_fn)(unsigned pname, unsigned char *v);
typedef void (*gl_mask_fn)(unsigned char r, unsigned char g, unsigned char b, unsigned char a);

typedef struct overlay_gl {
    gl_scissor_fn scissor;
    gl_clear_color_fn clear_color;
    gl_bits_fn clear;
    int height; /* the framebuffer's: rows count from the top here */
} overlay_gl;

#define PADDING 2 /* font pixels around the text */
#define ADVANCE (VIEWER_GLYPH_W + 1)
#define LINE (VIEWER_GLYPH_H + 2)

static void (*proc(const char *name))(void)
{
    return glfwGetProcAddress(name);
}

/* A w x h rectangle at (x, y) from the top left. */
static void fill(const overlay_gl *gl, int x, int y, int w, int h)
{
    gl->scissor(x, gl->height - y - h, w, h);
    gl->clear(GL_COLOR_BUFFER_BIT);
}

/* One character's lit runs, a clear each. */
static void draw_char(const overlay_gl *gl, char c, int x, int y, int scale)
{
    const unsigned char *rows = viewer_font_glyph(c);
    int r, col;
    for (r = 0; r < VIEWER_GLYPH_H; r++)
        for (col = 0; col < VIEWER_GLYPH_W; col++) {
            int run = 0;
            while (col + run < VIEWER_GLYPH_W && (rows[r] >> (VIEWER_GLYPH_W - 1 - col - run) & 1))
                run++;
            if (run)
                fill(gl, x + col * scale, y + r * scale, run * scale, scale);
            col += run;
        }
}

/* The length of the line at text (up to '\n' or the end), cut at most
 * `max` characters, at a space where there is one. *next: the line after. */
static int line_length(const char *text, int max, const char **next)
{
    int n = (int)strcspn(text, "\n"), cut;
    if (n <= max) {
        *next = text[n] ? text + n + 1 : text + n;
        return n;
    }
    for (cut = max; cut > max / 2 && text[cut] != ' '; cut--)
        ;
    if (text[cut] != ' ')
        cut = max;
    *next = text + cut + (text[cut] == ' ');
    return cut;
}

/* Lines and the widest one's characters, for columns characters a line. */
static int measure(const char *text, int columns, int *widest)
{
    int lines = 0;
    *widest = 0;
    while (*text) {
        int n = line_length(text, columns, &text);
        *widest = n > *widest ? n : *widest;
        lines++;
    }
    return lines;
}

void viewer_overlay_draw(viewer_overlay *o, const char *text, int width, int height)
{
    overlay_gl gl;
    int scale = width >= 800 ? 2 : 1, box[4], scissor, lines, widest, columns, i, y;
    float colour[4];
    unsigned char mask[4];
    gl_get_iv_fn get_iv = (gl_get_iv_fn)proc("glGetIntegerv");
    gl_get_fv_fn get_fv = (gl_get_fv_fn)proc("glGetFloatv");
    gl_get_bv_fn get_bv = (gl_get_bv_fn)proc("glGetBooleanv");
    gl_is_enabled_fn is_enabled = (gl_is_enabled_fn)proc("glIsEnabled");
    gl_enum_fn enable = (gl_enum_fn)proc("glEnable"), disable = (gl_enum_fn)proc("glDisable");
    gl_mask_fn colour_mask = (gl_mask_fn)proc("glColorMask");
    gl.scissor = (gl_scissor_fn)proc("glScissor");
    gl.clear_color = (gl_clear_color_fn)proc("glClearColor");
    gl.clear = (gl_bits_fn)proc("glClear");
    gl.height = height;
    o->panel_w = o->panel_h = 0;
    columns = (width - 2 * PADDING * scale) / (ADVANCE * scale);
    if (columns < 1 || !text[0])
        return;
    lines = measure(text, columns, &widest);
    if (lines > (height - 2 * PADDING * scale) / (LINE * scale))
        lines = (height - 2 * PADDING * scale) / (LINE * scale);
    if (lines < 1)
        return;
    get_iv(GL_SCISSOR_BOX, box);
    get_fv(GL_COLOR_CLEAR_VALUE, colour);
    get_bv(GL_COLOR_WRITEMASK, mask);
    scissor = is_enabled(GL_SCISSOR_TEST);
    enable(GL_SCISSOR_TEST);
    colour_mask(1, 1, 1, 1);
    o->panel_w = (widest * ADVANCE + 2 * PADDING) * scale;
    o->panel_h = (lines * LINE + 2 * PADDING) * scale;
    gl.clear_color(0.05f, 0.05f, 0.08f, 1.0f);
    fill(&gl, 0, 0, o->panel_w, o->panel_h);
    gl.clear_color(1.0f, 1.0f, 0.85f, 1.0f);
    for (i = 0, y = PADDING * scale; i < lines; i++, y += LINE * scale) {
        const char *line = text;
        int n = line_length(line, columns, &text), c;
        for (c = 0; c < n; c++)
            if (line[c] != ' ')
                draw_char(&gl, line[c], (PADDING + c * ADVANCE) * scale, y, scale);
    }
    gl.scissor(box[0], box[1], box[2], box[3]);
    gl.clear_color(colour[0], colour[1], colour[2], colour[3]);
    colour_mask(mask[0], mask[1], mask[2], mask[3]);
    if (!scissor)
        disable(GL_SCISSOR_TEST);
}
