/* SPDX-License-Identifier: MIT */
/* The scene both examples draw with stin: a UV sphere over a floor, one
 * point light, an ambient term, written as a binary PPM. The GL context is
 * the example's (EGL or OSMesa); everything here is plain stin API.
 * tests/cli/example_check.c knows these numbers and checks the shadow. */
#ifndef EXAMPLE_SCENE_H
#define EXAMPLE_SCENE_H

#include <stin/stin.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EXAMPLE_W 320
#define EXAMPLE_H 240
#define SLICES 48
#define STACKS 24

/* stin_desc.log: print warnings and errors (the default prints nothing). */
static void example_log(void *user, stin_log_level level, stin_log_item item, const char *msg)
{
    (void)user;
    (void)item;
    if (level <= STIN_LOG_LEVEL_WARNING)
        fprintf(stderr, "stin: %s\n", msg);
}

static void look_at(float m[16], const float eye[3], const float at[3])
{
    float f[3] = {at[0] - eye[0], at[1] - eye[1], at[2] - eye[2]}, s[3], u[3], l;
    l = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    f[0] /= l, f[1] /= l, f[2] /= l;
    s[0] = -f[2], s[1] = 0.0f, s[2] = f[0]; /* f x (0,1,0) */
    l = sqrtf(s[0] * s[0] + s[2] * s[2]);
    s[0] /= l, s[2] /= l;
    u[0] = s[1] * f[2] - s[2] * f[1], u[1] = s[2] * f[0] - s[0] * f[2], u[2] = s[0] * f[1] - s[1] * f[0];
    memset(m, 0, 16 * sizeof *m);
    m[0] = s[0], m[4] = s[1], m[8] = s[2];
    m[1] = u[0], m[5] = u[1], m[9] = u[2];
    m[2] = -f[0], m[6] = -f[1], m[10] = -f[2];
    m[12] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
    m[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
    m[14] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
    m[15] = 1.0f;
}

static void perspective(float m[16], float fovy_deg, float aspect, float n, float f)
{
    float t = 1.0f / tanf(fovy_deg * 3.14159265f / 360.0f);
    memset(m, 0, 16 * sizeof *m);
    m[0] = t / aspect;
    m[5] = t;
    m[10] = (f + n) / (n - f);
    m[11] = -1.0f;
    m[14] = 2.0f * f * n / (n - f);
}

/* A UV sphere of radius 0.5 at (0, 0.6, 0): the seam column is a second
 * copy of the first (uv runs 0..1), which stin welds back into one. */
#define SPHERE_VERTICES ((SLICES + 1) * (STACKS + 1))
static float sphere_pos[SPHERE_VERTICES * 3], sphere_nrm[SPHERE_VERTICES * 3];
static uint32_t sphere_idx[SLICES * STACKS * 6];
static const float floor_pos[] = {-4, 0, 4, 4, 0, 4, 4, 0, -4, -4, 0, -4};
static const uint32_t floor_idx[] = {0, 1, 2, 0, 2, 3};

/* Fills the sphere's arrays; returns its index count. */
static uint32_t build_sphere(void)
{
    float *pos = sphere_pos, *nrm = sphere_nrm;
    uint32_t *idx = sphere_idx;
    int i, j, k = 0;
    for (j = 0; j <= STACKS; j++)
        for (i = 0; i <= SLICES; i++) {
            float th = 3.14159265f * (float)j / STACKS, ph = 6.2831853f * (float)i / SLICES;
            float *n = nrm + 3 * (j * (SLICES + 1) + i), *p = pos + 3 * (j * (SLICES + 1) + i);
            n[0] = sinf(th) * cosf(ph), n[1] = cosf(th), n[2] = -sinf(th) * sinf(ph);
            p[0] = 0.5f * n[0], p[1] = 0.6f + 0.5f * n[1], p[2] = 0.5f * n[2];
        }
    for (j = 0; j < STACKS; j++)
        for (i = 0; i < SLICES; i++) {
            uint32_t a = (uint32_t)(j * (SLICES + 1) + i), b = a + SLICES + 1;
            uint32_t q[6] = {a, b, a + 1, a + 1, b, b + 1};
            /* the poles' rows are one point: one triangle per quad there */
            if (j > 0) {
                memcpy(idx + k, q, 3 * sizeof *q);
                k += 3;
            }
            if (j < STACKS - 1) {
                memcpy(idx + k, q + 3, 3 * sizeof *q);
                k += 3;
            }
        }
    return (uint32_t)k;
}

static stin_result make_sphere(stin_context *ctx, stin_mesh *out)
{
    stin_mesh_desc md = {0};
    md.index_count = build_sphere();
    md.positions = sphere_pos;
    md.normals = sphere_nrm;
    md.vertex_count = SPHERE_VERTICES;
    md.indices = sphere_idx;
    return stin_create_mesh(ctx, &md, out);
}

static stin_result make_floor(stin_context *ctx, stin_mesh *out)
{
    stin_mesh_desc md = {0};
    md.positions = floor_pos;
    md.vertex_count = 4;
    md.indices = floor_idx;
    md.index_count = 6;
    return stin_create_mesh(ctx, &md, out);
}

/* The application's own drawing after a frame that exported the lights'
 * visibility (egl_app_shader.c): 0 on success. */
typedef int (*example_app_pass)(stin_context *ctx, const stin_frame_desc *fd,
                                const stin_light_desc *light);

/* Creates stin on the current context, draws one frame into `framebuffer`
 * (0: the default one; it needs a stencil buffer for stencil volumes) and
 * tears stin down. With app_pass, stin only computes the light's visibility
 * (and depth) and the application shades the scene itself. 0 on success. */
static int example_render(stin_get_proc_fn get_proc, void *user, uint32_t framebuffer,
                          example_app_pass app_pass)
{
    static const float eye[3] = {0, 3, 6}, at[3] = {0, 0.4f, 0};
    stin_desc desc = {0}; /* zero means default everywhere */
    stin_frame_desc fd = {0};
    stin_light_desc light = {0};
    stin_material ball = {0}, ground = {0};
    stin_context *ctx = NULL;
    stin_mesh sphere, floor_mesh;
    void *block;
    size_t bytes;
    int ok;
    desc.get_proc_address = get_proc;
    desc.get_proc_user = user;
    desc.log = example_log;
    bytes = stin_memory_size(&desc);
    block = malloc(bytes); /* the caller's memory: stin never allocates */
    if (!block || stin_create(&desc, block, bytes, &ctx) != STIN_OK) {
        free(block);
        return 1;
    }
    printf("tier %s, shadows %s\n", stin_tier_name(stin_query_tier(ctx)),
           stin_technique_name(stin_query_choice(ctx, STIN_FEATURE_SHADOWS).technique));
    ok = make_sphere(ctx, &sphere) == STIN_OK && make_floor(ctx, &floor_mesh) == STIN_OK;
    look_at(fd.view, eye, at);
    perspective(fd.projection, 45.0f, (float)EXAMPLE_W / EXAMPLE_H, 0.1f, 50.0f);
    fd.viewport[2] = EXAMPLE_W;
    fd.viewport[3] = EXAMPLE_H;
    fd.framebuffer = framebuffer;
    fd.ambient[0] = fd.ambient[1] = fd.ambient[2] = 0.15f; /* default 0: black shadows */
    fd.export_visibility = app_pass ? STIN_EXPORT_VISIBILITY_ONLY : STIN_EXPORT_NONE;
    light.type = STIN_LIGHT_POINT;
    light.position[0] = 1.5f, light.position[1] = 4.0f, light.position[2] = 1.0f;
    ball.color[0] = 0.9f, ball.color[1] = 0.3f, ball.color[2] = 0.2f, ball.color[3] = 1.0f;
    ground.color[0] = ground.color[1] = ground.color[2] = 0.8f, ground.color[3] = 1.0f;
    ok = ok && stin_begin_frame(ctx, &fd) == STIN_OK && stin_add_light(ctx, &light) == STIN_OK &&
         stin_draw(ctx, sphere, NULL, &ball) == STIN_OK &&
         stin_draw(ctx, floor_mesh, NULL, &ground) == STIN_OK && stin_end_frame(ctx) == STIN_OK;
    ok = ok && (!app_pass || app_pass(ctx, &fd, &light) == 0);
    stin_destroy(ctx);
    free(block);
    return !ok;
}

/* rgba: EXAMPLE_W x EXAMPLE_H, rows bottom to top (GL's order). */
static int write_ppm(const char *path, const unsigned char *rgba)
{
    FILE *f = fopen(path, "wb");
    int x, y, ok;
    if (!f)
        return 1;
    fprintf(f, "P6\n%d %d\n255\n", EXAMPLE_W, EXAMPLE_H);
    for (y = EXAMPLE_H - 1; y >= 0; y--)
        for (x = 0; x < EXAMPLE_W; x++)
            fwrite(rgba + 4 * (y * EXAMPLE_W + x), 1, 3, f);
    ok = !ferror(f);
    return fclose(f) != 0 || !ok;
}

#endif
