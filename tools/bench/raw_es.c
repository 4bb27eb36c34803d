/* SPDX-License-Identifier: MIT */
/* The raw loop's own GLSL ES 3.x preamble: the lines that stand in for a
 * file's desktop #version line on an OpenGL ES 3.0+ context. Written here
 * rather than taken from libstin, so that the raw side stays independent
 * of the library it measures; what it must match is the precision stin's
 * programs run at (highp everywhere), or the agreement check would see the
 * difference. */
#include "raw.h"

#include <stdio.h>

/* ES 3.x always has highp in fragment stages; samplers used by the lit
 * program's sources get it too (GLSL ES leaves sampler2D at lowp). */
static const char precision[] =
    "#define STIN_ES 1\n"
    "precision highp float;\nprecision highp int;\n"
    "precision highp sampler2D;\nprecision highp samplerCube;\n";
/* shaders/gl2 is written in GLSL 1.10: its storage qualifiers, texture
 * lookups and colour output under their GLSL ES 3.x names. The gl4 files
 * need none of this (they map the chunks they share themselves). */
static const char gl2_vertex[] =
    "#define attribute in\n#define varying out\n#define texture2D texture\n";
static const char gl2_fragment[] =
    "#define varying in\n#define texture2D texture\n"
    "out vec4 raw_frag_color;\n#define gl_FragColor raw_frag_color\n";

int raw_es_preamble(int es_version, int fragment, int gl2_source, char *version_line,
                    size_t line_size, const char **parts)
{
    int n = 0;
    snprintf(version_line, line_size, "#version %d es\n", es_version);
    parts[n++] = version_line;
    parts[n++] = precision;
    if (gl2_source)
        parts[n++] = fragment ? gl2_fragment : gl2_vertex;
    return n;
}
