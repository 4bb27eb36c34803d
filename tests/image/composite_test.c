/* SPDX-License-Identifier: MIT */
/* The application's own geometry in stin's depth buffer (issue 8 item 2):
 * on four-lights, the application draws a magenta quad on the plane z = 0
 * (x in [-6, 6], y in [-1, 3], through the objects and the floor) with the
 * projection stin_query_frame_projection gives after stin_begin_frame,
 * once before stin's draws (stin with keep_contents) and once after stin's frame.
 * Exact answer: a pixel shows the quad iff the quad is nearer along the
 * pixel's ray than the Embree first hit. Pixels where the two distances are
 * within 0.1% are left out; at most 0.05% of the rest may differ (pixel
 * centres exactly on the quad's outline). Stencil volumes move the far
 * plane to infinity, so the caller's own projection would get this wrong. */
#include "aov.h"
#include "caller_gl.h"
#include "image_test.h"
#include "reference.h"
#include "scene.h"
#include "scene_gpu.h"
#include "test_context.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define QUAD_X 6.0f
#define QUAD_Y0 (-1.0f)
#define QUAD_Y1 3.0f
#define TIE 1e-3
#define BUDGET 0.0005

typedef struct composite {
    run *r;
    const scene *s;
    const caller_gl *gl;
    test_context t;
    GLuint program, vbo, vao;
    const ref_hit *hits;
    uint8_t *rgba;
} composite;

/* The quad's clip-space corners under projection * view, two triangles. */
static void upload_quad(composite *c, const float view[16], const float proj[16])
{
    static const float corners[6][2] = {{-QUAD_X, QUAD_Y0}, {QUAD_X, QUAD_Y0}, {QUAD_X, QUAD_Y1},
                                        {-QUAD_X, QUAD_Y0}, {QUAD_X, QUAD_Y1}, {-QUAD_X, QUAD_Y1}};
    float clip[6][4], eye[4];
    int v, i, k;
    for (v = 0; v < 6; v++) {
        const float w[4] = {corners[v][0], corners[v][1], 0.0f, 1.0f};
        for (i = 0; i < 4; i++)
            for (eye[i] = 0, k = 0; k < 4; k++)
                eye[i] += view[4 * k + i] * w[k];
        for (i = 0; i < 4; i++)
            for (clip[v][i] = 0, k = 0; k < 4; k++)
                clip[v][i] += proj[4 * k + i] * eye[k];
    }
    c->gl->BindBuffer(GL_ARRAY_BUFFER, c->vbo);
    c->gl->BufferData(GL_ARRAY_BUFFER, sizeof clip, clip, GL_STATIC_DRAW);
}

/* The application's draw: its program, its buffer, depth LESS with writes. */
static void draw_quad(composite *c)
{
    const caller_gl *gl = c->gl;
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LESS);
    gl->DepthMask(GL_TRUE);
    gl->UseProgram(c->program);
    if (c->vao)
        gl->BindVertexArray(c->vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, c->vbo);
    gl->VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, NULL);
    gl->EnableVertexAttribArray(0);
    gl->DrawArrays(GL_TRIANGLES, 0, 6);
    gl->DisableVertexAttribArray(0);
    gl->BindBuffer(GL_ARRAY_BUFFER, 0);
    if (c->vao)
        gl->BindVertexArray(0);
    gl->UseProgram(0);
    gl->Disable(GL_DEPTH_TEST);
}

/* One frame: the quad before stin's draws (keep_contents) or after its frame. */
static int frame(composite *c, int before)
{
    const scene *s = c->s;
    int w = c->r->width, h = c->r->height, i;
    stin_frame_desc fd;
    float proj[16];
    test_frame_desc(c->r, s, &fd);
    fd.keep_contents = before;
    if (before) { /* the application clears, draws, then stin draws with it */
        c->gl->BindFramebuffer(GL_FRAMEBUFFER, fd.framebuffer);
        c->gl->Viewport(0, 0, w, h);
        c->gl->ClearColor(0, 0, 0, 0);
        c->gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    }
    if (stin_begin_frame(c->t.ctx, &fd) != STIN_OK)
        return 0;
    stin_query_frame_projection(c->t.ctx, proj);
    upload_quad(c, fd.view, proj);
    if (before)
        draw_quad(c);
    for (i = 0; i < s->light_count; i++) {
        stin_light_desc l;
        scene_gpu_light(&s->lights[i], &l);
        stin_add_light(c->t.ctx, &l);
    }
    for (i = 0; i < s->object_count; i++)
        stin_draw(c->t.ctx, c->t.g.meshes[s->objects[i].mesh], s->objects[i].transform,
                  &c->t.g.materials[s->objects[i].material]);
    if (stin_end_frame(c->t.ctx) != STIN_OK)
        return 0;
    if (!before)
        draw_quad(c);
    return stin_platform_read_color(c->r->plat, c->rgba);
}

/* Distance along pixel (x, y)'s ray to the quad, or -1. */
static double quad_distance(const double inv[16], const scene_camera *cam, int w, int h, int x,
                            int y)
{
    double far_point[3], d[3], t;
    int k;
    aov_unproject(inv, w, h, x, y, 1.0, far_point);
    for (k = 0; k < 3; k++)
        d[k] = far_point[k] - cam->eye[k];
    if (fabs(d[2]) < 1e-12)
        return -1.0;
    t = -cam->eye[2] / d[2];
    if (t <= 0 || fabs(cam->eye[0] + t * d[0]) > QUAD_X || cam->eye[1] + t * d[1] < QUAD_Y0 ||
        cam->eye[1] + t * d[1] > QUAD_Y1)
        return -1.0;
    return t * sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

static void check(composite *c, const char *name)
{
    int w = c->r->width, h = c->r->height, x, y;
    float view[16], proj[16];
    double inv[16];
    long compared = 0, wrong = 0, quad = 0;
    scene_camera_matrices(&c->s->camera, w, h, view, proj);
    aov_inverse_view_proj(view, proj, inv);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const ref_hit *hit = &c->hits[(size_t)y * w + x];
            const uint8_t *px = c->rgba + 4 * ((size_t)y * w + x);
            double tq = quad_distance(inv, &c->s->camera, w, h, x, y);
            int shows = px[0] == 255 && px[1] == 0 && px[2] == 255, expect;
            if (tq > 0 && hit->hit && fabs(tq - hit->t) <= TIE * hit->t)
                continue;
            expect = tq > 0 && (!hit->hit || tq < hit->t);
            quad += expect;
            compared++;
            wrong += shows != expect;
        }
    report(c->r, compared > 0 && quad > 100 && wrong <= BUDGET * compared ? "PASS" : "FAIL", name,
           "the application's quad shows on %ld pixels where the exact answer differs, of %ld "
           "(%ld should show it; at most %.2f%%)", wrong, compared, quad, 100.0 * BUDGET);
}

void composite_tests(run *r, stin_tier tier, const char *path)
{
    static const stin_technique techniques[2] = {STIN_TECH_NONE, STIN_TECH_SHADOWS_VOLUME};
    composite c;
    scene s;
    caller_gl gl;
    reference *ref = NULL;
    ref_hit *hits = NULL;
    char err[256], name[160];
    int t, before;
    stin_technique first = STIN_TECH_NONE;
    if (strcmp(scene_base_name(path), "four-lights"))
        return;
    memset(&c, 0, sizeof c);
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", "composite", "%s", err);
        return;
    }
    caller_gl_load(&gl, r->plat);
    c.r = r;
    c.s = &s;
    c.gl = &gl;
    c.rgba = malloc((size_t)r->width * r->height * 4);
    hits = malloc(sizeof *hits * (size_t)r->width * r->height);
    ref = reference_create(&s, err, sizeof err);
    c.hits = hits;
    c.program = caller_gl_flat_program(&gl, caller_gl_dialect(r->profile), 1.0f, 0.0f, 1.0f);
    snprintf(name, sizeof name, "%s/four-lights/composite", stin_tier_name(tier));
    if ((r->profile->max_gl_version > 0 && r->profile->max_gl_version < 20) || !c.program ||
        !gl.GenBuffers) {
        report(r, "SKIP", name, "the test draws the application's quad with GLSL and a buffer");
    } else if (!c.rgba || !hits || !ref || !reference_primary(ref, r->width, r->height, hits)) {
        report(r, "FAIL", name, "reference: %s", ref ? "primary rays failed" : err);
    } else {
        caller_gl_buffers(&gl, caller_gl_dialect(r->profile), &c.vbo, &c.vao);
        for (t = 0; t < 2; t++) {
            stin_technique chosen;
            if (!test_context_create(&c.t, r, &s, tier, techniques[t], 0))
                continue;
            chosen = stin_query_choice(c.t.ctx, STIN_FEATURE_SHADOWS).technique;
            if (t == 0)
                first = chosen;
            if (t == 0 || chosen != first) { /* volumes, where they are not the default */
                for (before = 0; before < 2; before++) {
                    snprintf(name, sizeof name, "%s/four-lights/composite-%s-%s",
                             stin_tier_name(tier), stin_technique_name(chosen),
                             before ? "before" : "after");
                    if (frame(&c, before))
                        check(&c, name);
                    else
                        report(r, "FAIL", name, "the frame failed");
                }
            }
            test_context_destroy(&c.t);
        }
    }
    caller_gl_delete(&gl, &c.program, &c.vbo, &c.vao);
    if (ref)
        reference_destroy(ref);
    free(hits);
    free(c.rgba);
    scene_free(&s);
}
