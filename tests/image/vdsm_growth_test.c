/* SPDX-License-Identifier: MIT */
/*
 * VDSM's conservative growth, measured on its own (once per run, GL4): the
 * shadow polygons' face builder (face_polygon in shaders/gl4/vdsm_volume.glsl,
 * read from the source tree and driven by a small geometry shader) draws
 * random convex faces - triangles, quads, slivers, faces smaller than a
 * thousandth of a pixel, repeated corners, homogeneous corners with w far
 * from 1, faces crossing the viewport's edge - one in each 16-pixel cell of
 * the framebuffer, and the coverage is read back:
 *   margin   every pixel whose square the face reaches (the square shrunk by
 *            1/64 pixel still meets it: the rasteriser snaps vertices to
 *            1/256) is covered, so the exact per-pixel test runs wherever
 *            the face touches the pixel; and no covered pixel's centre lies
 *            farther than 1 + 1/64 pixel from the face (the mitred corners'
 *            bound: a growth reaching twice as far fails). The same faces at
 *            a quarter-pixel growth and at none must leave pixels uncovered,
 *            or the check could not see a short growth.
 * The full scenes' tests (vdsm_test.c) cannot see the margin: there a face
 * needs to reach a pixel's centre only by the rasteriser's snap.
 */
#include "caller_gl.h"
#include "image_test.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CELL 16          /* pixels a side of each face's cell */
#define REACH_SLACK (1.0 / 64.0)
#define FAR_BOUND 1.0    /* a mitred corner's farthest reach from the face */

typedef struct face {
    double x[4], y[4]; /* pixels */
    int n;             /* 3 or 4 */
    float w;           /* homogeneous scale of every corner */
} face;

typedef struct growth_gl {
    caller_gl gl;
    GLuint program, vbo, vao;
} growth_gl;

/* Each stage's first lines: GLSL 1.50, or GLSL ES 3.20 (geometry shaders
 * are core there) with the precision ES asks for. */
static const char *const version_desktop = "#version 150\n";
static const char *const version_es =
    "#version 320 es\n#define STIN_ES 1\nprecision highp float;\nprecision highp int;\n";

static const char *const vert_src =
    "in vec4 a_c01; in vec4 a_c23; in vec2 a_nw;\n"
    "out vec4 g_c01; out vec4 g_c23; out vec2 g_nw;\n"
    "void main() { g_c01 = a_c01; g_c23 = a_c23; g_nw = a_nw; gl_Position = vec4(0.0); }\n";

static const char *const geom_head =
    "layout(points) in;\n"
    "layout(triangle_strip, max_vertices = 12) out;\n"
    "in vec4 g_c01[]; in vec4 g_c23[]; in vec2 g_nw[];\n";

static const char *const geom_main =
    "void main()\n"
    "{\n"
    "    float s = g_nw[0].y;\n"
    "    vec4 w[4] = vec4[4](vec4(g_c01[0].xy * s, 0.0, s), vec4(g_c01[0].zw * s, 0.0, s),\n"
    "                        vec4(g_c23[0].xy * s, 0.0, s), vec4(g_c23[0].zw * s, 0.0, s));\n"
    "    vec2 r[GROWN_MAX];\n"
    "    vec3 depth;\n"
    "    tri = vec3[3](vec3(0.0), vec3(0.0), vec3(0.0));\n"
    "    put_polygon(r, face_polygon(w, int(g_nw[0].x), false, r, depth), depth);\n"
    "}\n";

static const char *const frag_src =
    "out vec4 c;\nvoid main() { c = vec4(1.0); }\n";

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *s = NULL;
    long n;
    if (!f)
        return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0 &&
        (s = malloc((size_t)n + 1)) != NULL) {
        if (fread(s, 1, (size_t)n, f) != (size_t)n) {
            free(s);
            s = NULL;
        } else {
            s[n] = '\0';
        }
    }
    fclose(f);
    return s;
}

static GLuint shader(const caller_gl *gl, GLenum type, const char *const *src, int n, char *log,
                     size_t size)
{
    GLuint s = gl->CreateShader(type);
    GLint ok = 0;
    gl->ShaderSource(s, n, src, NULL);
    gl->CompileShader(s);
    gl->GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        gl->GetShaderInfoLog(s, (GLsizei)size, NULL, log);
        gl->DeleteShader(s);
        return 0;
    }
    return s;
}

/* The face builder's program: 0 with why in log. */
static GLuint build(const caller_gl *gl, int es, char *log, size_t size)
{
    char *side = read_text("shaders/gl4/vdsm_side.glsl");
    char *volume = read_text("shaders/gl4/vdsm_volume.glsl");
    const char *geom[5], *vert[2], *frag[2];
    GLuint p = 0, s[3] = {0, 0, 0};
    GLint ok = 0;
    int i;
    snprintf(log, size, "cannot read shaders/gl4/vdsm_side.glsl or vdsm_volume.glsl");
    if (side && volume) {
        vert[0] = geom[0] = frag[0] = es ? version_es : version_desktop;
        vert[1] = vert_src;
        frag[1] = frag_src;
        geom[1] = geom_head;
        geom[2] = side;
        geom[3] = volume;
        geom[4] = geom_main;
        s[0] = shader(gl, GL_VERTEX_SHADER, vert, 2, log, size);
        s[1] = s[0] ? shader(gl, GL_GEOMETRY_SHADER, geom, 5, log, size) : 0;
        s[2] = s[1] ? shader(gl, GL_FRAGMENT_SHADER, frag, 2, log, size) : 0;
    }
    if (s[2]) {
        p = gl->CreateProgram();
        for (i = 0; i < 3; i++)
            gl->AttachShader(p, s[i]);
        gl->BindAttribLocation(p, 0, "a_c01");
        gl->BindAttribLocation(p, 1, "a_c23");
        gl->BindAttribLocation(p, 2, "a_nw");
        gl->LinkProgram(p);
        gl->GetProgramiv(p, GL_LINK_STATUS, &ok);
        if (!ok) {
            gl->GetProgramInfoLog(p, (GLsizei)size, NULL, log);
            gl->DeleteProgram(p);
            p = 0;
        }
    }
    for (i = 0; i < 3; i++)
        if (s[i])
            gl->DeleteShader(s[i]);
    free(side);
    free(volume);
    return p;
}

/* A deterministic stream (the faces are the same every run). */
static double next(uint32_t *state)
{
    *state = *state * 1664525u + 1013904223u;
    return (*state >> 8) / 16777216.0;
}

/* Face k of the cell at (cx, cy): a convex polygon on a circle, one of
 * several kinds; cells on the framebuffer's edge push theirs across it. */
static void make_face(uint32_t *st, int k, double cx, double cy, int edge_x, int edge_y, face *f)
{
    const double pi = 3.14159265358979;
    double a[4], radius, squash, turn, ox, oy;
    int i, j, kind = k % 6;
    f->n = kind == 1 ? 3 : kind == 2 ? 4 : 3 + (next(st) < 0.5);
    radius = kind == 3 ? 1e-3 * next(st) : 0.5 + 5.5 * next(st);
    squash = kind == 4 ? 0.01 + 0.05 * next(st) : 1.0; /* slivers */
    turn = 2.0 * pi * next(st);
    for (i = 0; i < f->n; i++)
        a[i] = 2.0 * pi * next(st);
    for (i = 1; i < f->n; i++) /* sorted angles: a convex polygon */
        for (j = i; j > 0 && a[j] < a[j - 1]; j--) {
            double t = a[j];
            a[j] = a[j - 1];
            a[j - 1] = t;
        }
    ox = cx + (next(st) - 0.5) + edge_x * 0.6 * CELL;
    oy = cy + (next(st) - 0.5) + edge_y * 0.6 * CELL;
    for (i = 0; i < f->n; i++) {
        double u = radius * cos(a[i]), v = radius * squash * sin(a[i]);
        f->x[i] = ox + u * cos(turn) - v * sin(turn);
        f->y[i] = oy + u * sin(turn) + v * cos(turn);
    }
    if (kind == 5 && f->n == 4) { /* a repeated corner */
        f->x[3] = f->x[2];
        f->y[3] = f->y[2];
    }
    for (i = f->n; i < 4; i++) {
        f->x[i] = f->x[0];
        f->y[i] = f->y[0];
    }
    f->w = (float)(0.25 * pow(16.0, next(st))); /* 0.25 .. 4 */
}

/* Whether the square [x0, x1] x [y0, y1] meets convex face f (separating
 * axes: the square's two and each edge's normal). */
static int square_meets(const face *f, double x0, double y0, double x1, double y1)
{
    double lo = 1e30, hi = -1e30, ylo = 1e30, yhi = -1e30;
    int i, j;
    for (i = 0; i < f->n; i++) {
        lo = fmin(lo, f->x[i]);
        hi = fmax(hi, f->x[i]);
        ylo = fmin(ylo, f->y[i]);
        yhi = fmax(yhi, f->y[i]);
    }
    if (hi < x0 || lo > x1 || yhi < y0 || ylo > y1)
        return 0;
    for (i = 0; i < f->n; i++) {
        int e = (i + 1) % f->n;
        double nx = f->y[e] - f->y[i], ny = f->x[i] - f->x[e];
        double c[4], fmin_ = 1e30, fmax_ = -1e30, smin = 1e30, smax = -1e30;
        if (nx == 0.0 && ny == 0.0)
            continue;
        for (j = 0; j < f->n; j++) {
            double d = nx * f->x[j] + ny * f->y[j];
            fmin_ = fmin(fmin_, d);
            fmax_ = fmax(fmax_, d);
        }
        c[0] = nx * x0 + ny * y0;
        c[1] = nx * x1 + ny * y0;
        c[2] = nx * x0 + ny * y1;
        c[3] = nx * x1 + ny * y1;
        for (j = 0; j < 4; j++) {
            smin = fmin(smin, c[j]);
            smax = fmax(smax, c[j]);
        }
        if (smax < fmin_ || smin > fmax_)
            return 0;
    }
    return 1;
}

/* Distance from point (px, py) to face f (0 inside). */
static double distance_to(const face *f, double px, double py)
{
    double best = 1e30;
    int i, inside = 1, sign = 0;
    for (i = 0; i < f->n; i++) {
        int e = (i + 1) % f->n;
        double ex = f->x[e] - f->x[i], ey = f->y[e] - f->y[i];
        double qx = px - f->x[i], qy = py - f->y[i], len2 = ex * ex + ey * ey;
        double t = len2 > 0.0 ? fmax(0.0, fmin(1.0, (qx * ex + qy * ey) / len2)) : 0.0;
        double cross = ex * qy - ey * qx;
        int s = cross > 0.0 ? 1 : cross < 0.0 ? -1 : 0;
        best = fmin(best, hypot(qx - t * ex, qy - t * ey));
        if (len2 > 0.0 && s != 0) {
            if (sign == 0)
                sign = s;
            else if (s != sign)
                inside = 0;
        }
    }
    return inside && sign != 0 ? 0.0 : best;
}

typedef struct tally {
    long reached, missed; /* pixels the face reaches; of those uncovered */
    long covered;
    double farthest;      /* the farthest covered centre from its face */
} tally;

/* Draws every face at growth `grow` and counts what the read-back shows. */
static int measure(run *r, growth_gl *g, const face *faces, int count, float grow,
                   uint8_t *rgba, tally *t)
{
    const caller_gl *gl = &g->gl;
    int cols = r->width / CELL, k, x, y;
    float m[16];
    memset(t, 0, sizeof *t);
    memset(m, 0, sizeof m);
    m[0] = 2.0f / (float)r->width;
    m[5] = 2.0f / (float)r->height;
    m[10] = 1.0f;
    m[12] = m[13] = -1.0f;
    m[15] = 1.0f;
    gl->BindFramebuffer(GL_FRAMEBUFFER, stin_platform_framebuffer(r->plat));
    gl->Viewport(0, 0, r->width, r->height);
    gl->ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    gl->Clear(GL_COLOR_BUFFER_BIT);
    gl->UseProgram(g->program);
    gl->UniformMatrix4fv(gl->GetUniformLocation(g->program, "u_view_proj"), 1, GL_FALSE, m);
    gl->Uniform4f(gl->GetUniformLocation(g->program, "u_viewport"), 0.0f, 0.0f, (float)r->width,
                 (float)r->height);
    gl->Uniform1f(gl->GetUniformLocation(g->program, "u_grow"), grow);
    gl->Uniform1i(gl->GetUniformLocation(g->program, "u_depth_test"), 0);
    if (g->vao)
        gl->BindVertexArray(g->vao);
    gl->DrawArrays(GL_POINTS, 0, count);
    if (g->vao)
        gl->BindVertexArray(0);
    gl->UseProgram(0);
    if (!stin_platform_read_color(r->plat, rgba) || gl->GetError() != GL_NO_ERROR)
        return 0;
    for (k = 0; k < count; k++) {
        const face *f = &faces[k];
        int x0 = (k % cols) * CELL, y0 = (k / cols) * CELL;
        for (y = y0; y < y0 + CELL; y++)
            for (x = x0; x < x0 + CELL; x++) {
                int on = rgba[((size_t)y * r->width + x) * 4] > 127;
                if (square_meets(f, x + REACH_SLACK, y + REACH_SLACK, x + 1 - REACH_SLACK,
                                 y + 1 - REACH_SLACK)) {
                    t->reached++;
                    t->missed += !on;
                }
                if (on) {
                    t->covered++;
                    t->farthest = fmax(t->farthest, distance_to(f, x + 0.5, y + 0.5));
                }
            }
    }
    return 1;
}

/* The faces' vertex buffer: per point two corners a vec4, then (n, w). */
static int upload(growth_gl *g, int core, const face *faces, int count)
{
    const caller_gl *gl = &g->gl;
    float *v = malloc(sizeof *v * 10 * (size_t)count);
    int k, i;
    if (!v)
        return 0;
    for (k = 0; k < count; k++) {
        for (i = 0; i < 4; i++) {
            v[k * 10 + 2 * i] = (float)faces[k].x[i];
            v[k * 10 + 2 * i + 1] = (float)faces[k].y[i];
        }
        v[k * 10 + 8] = (float)faces[k].n;
        v[k * 10 + 9] = faces[k].w;
    }
    caller_gl_buffers(gl, core, &g->vbo, &g->vao);
    if (g->vao)
        gl->BindVertexArray(g->vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, g->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof *v * 10 * (size_t)count), v,
                   GL_STATIC_DRAW);
    for (i = 0; i < 3; i++) {
        gl->EnableVertexAttribArray((GLuint)i);
        gl->VertexAttribPointer((GLuint)i, i < 2 ? 4 : 2, GL_FLOAT, GL_FALSE, 10 * sizeof(float),
                                (const void *)(sizeof(float) * 4 * (size_t)i));
    }
    gl->BindBuffer(GL_ARRAY_BUFFER, 0);
    if (g->vao)
        gl->BindVertexArray(0);
    free(v);
    return 1;
}

void vdsm_growth_tests(run *r)
{
    const char *name = "gl4/vdsm-growth/margin";
    int cols = r->width / CELL, rows = r->height / CELL, count = cols * rows, k, ok;
    growth_gl g;
    face *faces = malloc(sizeof *faces * (size_t)(count > 0 ? count : 1));
    uint8_t *rgba = malloc((size_t)r->width * r->height * 4);
    tally full, quarter, none;
    uint32_t st = 2026u;
    char log[512];
    memset(&g, 0, sizeof g);
    caller_gl_load(&g.gl, r->plat);
    for (k = 0; k < 16 && g.gl.GetError() != GL_NO_ERROR; k++)
        ; /* an error an earlier test left must not count as this one's */
    if (!faces || !rgba || count < 16) {
        report(r, "FAIL", name, "out of memory, or a framebuffer under 16 cells");
        goto done;
    }
    for (k = 0; k < count; k++) {
        int cx = k % cols, cy = k / cols;
        make_face(&st, k, cx * CELL + CELL / 2.0, cy * CELL + CELL / 2.0,
                  cx == 0 ? -1 : cx == cols - 1 ? 1 : 0, cy == 0 ? -1 : cy == rows - 1 ? 1 : 0,
                  &faces[k]);
    }
    g.program = g.gl.Uniform1f && g.gl.UniformMatrix4fv && g.gl.GetShaderiv
                    ? build(&g.gl, r->profile->es, log, sizeof log) : 0;
    if (!g.program) {
        report(r, "FAIL", name, "the face builder does not build: %s", log);
        goto done;
    }
    ok = upload(&g, r->profile->core, faces, count) &&
         measure(r, &g, faces, count, 0.5f, rgba, &full) &&
         measure(r, &g, faces, count, 0.25f, rgba, &quarter) &&
         measure(r, &g, faces, count, 0.0f, rgba, &none);
    if (!ok) {
        report(r, "FAIL", name, "out of memory, a GL error or no read-back");
        goto done;
    }
    report(r,
           full.reached > 0 && full.missed == 0 && full.farthest <= FAR_BOUND + REACH_SLACK &&
                   quarter.missed > 0 && none.missed > 0
               ? "PASS" : "FAIL",
           name,
           "%d random faces at growth 0.5: %ld of %ld pixels they reach left uncovered (need 0); "
           "the farthest covered centre %.3f px from its face (need <= %.3f); at growth 0.25 "
           "%ld uncovered, at 0 %ld (need > 0 each: the check sees a short growth)",
           count, full.missed, full.reached, full.farthest, FAR_BOUND + REACH_SLACK,
           quarter.missed, none.missed);
done:
    caller_gl_delete(&g.gl, &g.program, &g.vbo, &g.vao);
    free(faces);
    free(rgba);
}
