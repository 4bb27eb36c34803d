/* SPDX-License-Identifier: MIT */
/* The raw loop's GLSL program, built from the same files stin embeds: the
 * tier's lit.vert and lit.frag, with the chunks of stin's unshadowed plain
 * program spliced in at lit.frag's "// @chunks" line (src/gl/shader.c,
 * src/render/path_glsl.c, src/surface/glsl.c). Read from disk, not from stin's
 * embedded copy, so the raw side shares no code path with the library. */
#include "raw.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CHUNK_MARKER "// @chunks"
#define MAX_CHUNKS 4
#define PATH_SIZE 1024

/* stin's unshadowed plain-surface program: these chunks, in this order. */
static const char *const plain_chunks[] = {"surface_plain.glsl", "shadow_none.glsl", NULL};
/* and its vertex stage's: no displacement (gl4's vertex shaders take their
 * attributes from a chunk too) */
static const char *const vertex_chunks_gl2[] = {"displace_none.glsl", NULL};
static const char *const vertex_chunks_gl4[] = {"vertex_attributes.glsl", "displace_none.glsl",
                                                NULL};

/* The whole file as a string, or NULL with err set. */
static char *read_file(FILE *f, const char *path, char *err, size_t err_size)
{
    char *text = NULL;
    long n;
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0 &&
        (text = malloc((size_t)n + 1)) && fread(text, 1, (size_t)n, f) == (size_t)n) {
        text[n] = '\0';
    } else {
        snprintf(err, err_size, "cannot read shader %s", path);
        free(text);
        text = NULL;
    }
    fclose(f);
    return text;
}

/* root/dir/name; a chunk falls back to root/gl2/name as stin's lookup does
 * (gl4 shares the GLSL 1.10 chunks, mapped by #define in its main files).
 * Trying both, rather than naming each file's owner, keeps the raw loop on
 * stin's files wherever a chunk moves between the two folders. */
static char *read_shader(const char *root, const char *dir, const char *name, int chunk,
                         char *err, size_t err_size)
{
    char path[PATH_SIZE], first[PATH_SIZE];
    FILE *f;
    snprintf(first, sizeof first, "%s/%s/%s", root, dir, name);
    snprintf(path, sizeof path, "%s", first);
    if (!(f = fopen(path, "rb")) && chunk && strcmp(dir, "gl2") != 0) {
        snprintf(path, sizeof path, "%s/gl2/%s", root, name);
        f = fopen(path, "rb");
    }
    if (!f) {
        snprintf(err, err_size, "cannot open shader %s%s (run from the repository root or "
                 "pass --shaders DIR)", first, strcmp(path, first) ? " or its gl2 copy" : "");
        return NULL;
    }
    return read_file(f, path, err, err_size);
}

/* 1 if the shader compiled (program: linked); else err gets `what` and the
 * driver's log, and the object is deleted. */
static int built(const raw_gl *gl, GLuint obj, int program, const char *what, char *err,
                 size_t err_size)
{
    char log[1024] = "";
    GLint ok = 0;
    if (program)
        gl->GetProgramiv(obj, GL_LINK_STATUS, &ok);
    else
        gl->GetShaderiv(obj, GL_COMPILE_STATUS, &ok);
    if (ok)
        return 1;
    if (program) {
        gl->GetProgramInfoLog(obj, (GLsizei)sizeof log, NULL, log);
        gl->DeleteProgram(obj);
    } else {
        gl->GetShaderInfoLog(obj, (GLsizei)sizeof log, NULL, log);
        gl->DeleteShader(obj);
    }
    snprintf(err, err_size, "%s: %s", what, log);
    return 0;
}

/* The file up to its marker, each chunk, the rest: as stin composes its lit
 * shaders. chunks is NULL-terminated, or NULL for a plain file; defines (or
 * NULL) go in after the file's #version line, which on ES gives way to the
 * GLSL ES preamble. */
static GLuint compile(const raw_gl *gl, GLenum type, const raw_config *cfg, const char *dir,
                      const char *name, const char *const *chunks, const char *defines,
                      char *err, size_t err_size)
{
    const char *root = cfg->shader_dir;
    char *src = read_shader(root, dir, name, 0, err, err_size), *texts[MAX_CHUNKS] = {NULL};
    char what[PATH_SIZE], version[32];
    const GLchar *parts[MAX_CHUNKS + RAW_ES_PARTS + 4];
    GLint lengths[MAX_CHUNKS + RAW_ES_PARTS + 4];
    const char *marker = NULL, *rest;
    GLsizei count = 0;
    GLuint sh = 0;
    int n = 0, i;
    if (!src)
        return 0;
    if (chunks && !(marker = strstr(src, CHUNK_MARKER))) {
        snprintf(err, err_size, "%s/%s has no '%s' line for its chunks", dir, name, CHUNK_MARKER);
        goto done;
    }
    rest = src;
    if (defines || cfg->es_glsl) {
        const char *eol = strchr(src, '\n');
        rest = eol ? eol + 1 : src + strlen(src);
        if (cfg->es_glsl) { /* the ES preamble stands in for the #version line */
            count = raw_es_preamble(cfg->es_glsl, type == GL_FRAGMENT_SHADER,
                                    !strcmp(dir, "gl2"), version, sizeof version, parts);
            for (i = 0; i < count; i++)
                lengths[i] = -1;
        } else {
            parts[count] = src;
            lengths[count++] = (GLint)(rest - src);
        }
    }
    if (defines) {
        parts[count] = defines;
        lengths[count++] = -1;
    }
    parts[count] = rest;
    lengths[count++] = marker ? (GLint)(marker - rest) : -1;
    for (; marker && chunks[n]; n++) {
        if (n == MAX_CHUNKS || !(texts[n] = read_shader(root, dir, chunks[n], 1, err, err_size)))
            goto done;
        parts[count] = texts[n];
        lengths[count++] = -1;
    }
    if (marker) {
        parts[count] = marker;
        lengths[count++] = -1;
    }
    sh = gl->CreateShader(type);
    gl->ShaderSource(sh, count, parts, lengths);
    gl->CompileShader(sh);
    snprintf(what, sizeof what, "%s/%s did not compile", dir, name);
    if (!built(gl, sh, 0, what, err, err_size))
        sh = 0;
done:
    for (i = 0; i < MAX_CHUNKS; i++)
        free(texts[i]);
    free(src);
    return sh;
}

GLuint raw_program_link(const raw_gl *gl, const raw_config *cfg, const char *frag_defines,
                        char *err, size_t err_size)
{
    const char *dir = cfg->tier == STIN_TIER_GL4 ? "gl4" : "gl2";
    char what[64];
    GLuint vs, fs, p;
    if (!(vs = compile(gl, GL_VERTEX_SHADER, cfg, dir, "lit.vert",
                       cfg->tier == STIN_TIER_GL4 ? vertex_chunks_gl4 : vertex_chunks_gl2, NULL,
                       err, err_size)))
        return 0;
    if (!(fs = compile(gl, GL_FRAGMENT_SHADER, cfg, dir, "lit.frag", plain_chunks, frag_defines,
                       err, err_size))) {
        gl->DeleteShader(vs);
        return 0;
    }
    p = gl->CreateProgram();
    gl->AttachShader(p, vs);
    gl->AttachShader(p, fs);
    /* stin's fixed attribute locations, so the same layout feeds both */
    gl->BindAttribLocation(p, 0, "a_position");
    gl->BindAttribLocation(p, 1, "a_normal");
    gl->BindAttribLocation(p, 2, "a_uv");
    gl->BindAttribLocation(p, 3, "a_tangent"); /* no array: lit.vert's tangent is unused */
    gl->LinkProgram(p);
    gl->DeleteShader(vs);
    gl->DeleteShader(fs);
    snprintf(what, sizeof what, "%s/lit.vert + %s/lit.frag did not link", dir, dir);
    return built(gl, p, 1, what, err, err_size) ? p : 0;
}
