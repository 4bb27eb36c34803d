/* SPDX-License-Identifier: MIT */
/* A mesh that changes every frame: a capped tube over a floor, skinned on
 * the CPU by two bones (the second bending up to 60 degrees over eight
 * frames), handed to stin with stin_update_mesh between frames: no
 * adjacency, welding or index upload again, the same handle. Shadows on
 * (whatever stin chooses). The last frame goes to the PPM named on the
 * command line; tests/cli/example_check.c checks its shadow.
 *   cc skinned.c $(pkg-config --cflags --libs stin) -lEGL -lm */
#include "example_egl.h"

#define TUBE_RINGS 33   /* along the tube */
#define TUBE_SIDES 24   /* around it */
#define TUBE_RADIUS 0.2f
#define TUBE_Y 0.7f
#define BONE 1.2f       /* each bone's length; the joint at x = 0 */
#define FRAMES 8
#define BEND_DEG 60.0f
/* ring vertices, then each cap's centre and its own ring copy (flat normal) */
#define TUBE_VERTICES (TUBE_RINGS * TUBE_SIDES + 2 * (1 + TUBE_SIDES))
#define TUBE_TRIANGLES ((TUBE_RINGS - 1) * TUBE_SIDES * 2 + 2 * TUBE_SIDES)

static float rest_pos[3 * TUBE_VERTICES], rest_nrm[3 * TUBE_VERTICES];
static float weight[TUBE_VERTICES]; /* of bone 1; bone 0 has the rest */
static float pos[3 * TUBE_VERTICES], nrm[3 * TUBE_VERTICES];
static uint32_t idx[3 * TUBE_TRIANGLES];

static void set3(float *v, float x, float y, float z) { v[0] = x, v[1] = y, v[2] = z; }

/* The tube at rest along x from -BONE to BONE; bone 1's weight rises
 * smoothly over 0.5 around the joint. */
static void build_tube(void)
{
    int r, s, c, t = 0;
    for (r = 0; r < TUBE_RINGS; r++)
        for (s = 0; s < TUBE_SIDES; s++) {
            float a = 6.2831853f * (float)s / TUBE_SIDES, x = -BONE + 2.0f * BONE * r / (TUBE_RINGS - 1);
            float u = (x + 0.25f) / 0.5f;
            int v = r * TUBE_SIDES + s;
            u = u < 0.0f ? 0.0f : u > 1.0f ? 1.0f : u;
            set3(rest_nrm + 3 * v, 0.0f, cosf(a), sinf(a));
            set3(rest_pos + 3 * v, x, TUBE_Y + TUBE_RADIUS * cosf(a), TUBE_RADIUS * sinf(a));
            weight[v] = u * u * (3.0f - 2.0f * u);
            if (r + 1 < TUBE_RINGS) {
                uint32_t a0 = (uint32_t)v, a1 = (uint32_t)(r * TUBE_SIDES + (s + 1) % TUBE_SIDES);
                uint32_t q[6] = {a0, a1, a1 + TUBE_SIDES, a0, a1 + TUBE_SIDES, a0 + TUBE_SIDES};
                memcpy(idx + 3 * t, q, sizeof q);
                t += 2;
            }
        }
    for (c = 0; c < 2; c++) { /* caps: r = 0 faces -x, the last ring +x */
        int centre = TUBE_RINGS * TUBE_SIDES + c * (1 + TUBE_SIDES), ring = c ? (TUBE_RINGS - 1) * TUBE_SIDES : 0;
        float side = c ? 1.0f : -1.0f;
        memcpy(rest_pos + 3 * centre, rest_pos + 3 * ring, 3 * sizeof(float));
        rest_pos[3 * centre + 1] = TUBE_Y, rest_pos[3 * centre + 2] = 0.0f;
        weight[centre] = weight[ring];
        for (s = 0; s <= TUBE_SIDES; s++) {
            int v = centre + (s < TUBE_SIDES ? 1 + s : 0);
            set3(rest_nrm + 3 * v, side, 0.0f, 0.0f);
            if (s == TUBE_SIDES)
                break;
            memcpy(rest_pos + 3 * v, rest_pos + 3 * (ring + s), 3 * sizeof(float));
            weight[v] = weight[ring + s];
            idx[3 * t] = (uint32_t)centre;
            idx[3 * t + 1] = (uint32_t)(centre + 1 + (c ? s : (s + 1) % TUBE_SIDES));
            idx[3 * t + 2] = (uint32_t)(centre + 1 + (c ? (s + 1) % TUBE_SIDES : s));
            t++;
        }
    }
}

/* Linear blend skinning: bone 0 stays, bone 1 turns by `deg` about z at
 * the joint (0, TUBE_Y, 0); normals blended the same way, renormalised. */
static void skin(float deg)
{
    float a = deg * 3.14159265f / 180.0f, co = cosf(a), si = sinf(a);
    int v;
    for (v = 0; v < TUBE_VERTICES; v++) {
        const float *p = rest_pos + 3 * v, *n = rest_nrm + 3 * v;
        float w = weight[v], dy = p[1] - TUBE_Y, l;
        float *o = pos + 3 * v, *m = nrm + 3 * v;
        o[0] = (1.0f - w) * p[0] + w * (co * p[0] - si * dy);
        o[1] = (1.0f - w) * p[1] + w * (TUBE_Y + si * p[0] + co * dy);
        o[2] = p[2];
        m[0] = (1.0f - w) * n[0] + w * (co * n[0] - si * n[1]);
        m[1] = (1.0f - w) * n[1] + w * (si * n[0] + co * n[1]);
        m[2] = n[2];
        l = sqrtf(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        m[0] /= l, m[1] /= l, m[2] /= l;
    }
}

static int run_frames(uint32_t framebuffer)
{
    static const float eye[3] = {0, 3, 6}, at[3] = {0, 0.4f, 0};
    stin_desc desc = {0};
    stin_frame_desc fd = {0};
    stin_light_desc light = {0};
    stin_material tube_mat = {0}, ground = {0};
    stin_mesh_desc md = {0};
    stin_mesh_update_desc ud = {0};
    stin_context *ctx = NULL;
    stin_mesh tube, floor_mesh;
    void *block;
    size_t bytes;
    int ok, f;
    desc.get_proc_address = get_proc;
    desc.log = example_log;
    bytes = stin_memory_size(&desc);
    block = malloc(bytes);
    if (!block || stin_create(&desc, block, bytes, &ctx) != STIN_OK) {
        free(block);
        return 1;
    }
    printf("tier %s, shadows %s\n", stin_tier_name(stin_query_tier(ctx)),
           stin_technique_name(stin_query_choice(ctx, STIN_FEATURE_SHADOWS).technique));
    build_tube();
    skin(0.0f);
    md.positions = pos;
    md.normals = nrm;
    md.vertex_count = TUBE_VERTICES;
    md.indices = idx;
    md.index_count = 3 * TUBE_TRIANGLES;
    ok = stin_create_mesh(ctx, &md, &tube) == STIN_OK && make_floor(ctx, &floor_mesh) == STIN_OK;
    ud.positions = pos; /* the same arrays, skinned again each frame */
    ud.normals = nrm;
    ud.vertex_count = TUBE_VERTICES;
    look_at(fd.view, eye, at);
    perspective(fd.projection, 45.0f, (float)EXAMPLE_W / EXAMPLE_H, 0.1f, 50.0f);
    fd.viewport[2] = EXAMPLE_W;
    fd.viewport[3] = EXAMPLE_H;
    fd.framebuffer = framebuffer;
    fd.ambient[0] = fd.ambient[1] = fd.ambient[2] = 0.15f;
    light.type = STIN_LIGHT_POINT;
    light.position[0] = 1.5f, light.position[1] = 4.0f, light.position[2] = 1.0f;
    tube_mat.color[0] = 0.2f, tube_mat.color[1] = 0.5f, tube_mat.color[2] = 0.9f, tube_mat.color[3] = 1.0f;
    ground.color[0] = ground.color[1] = ground.color[2] = 0.8f, ground.color[3] = 1.0f;
    for (f = 0; ok && f < FRAMES; f++) {
        if (f > 0) { /* between frames: never between begin and end */
            skin(BEND_DEG * (float)f / (FRAMES - 1));
            ok = stin_update_mesh(ctx, tube, &ud) == STIN_OK;
        }
        ok = ok && stin_begin_frame(ctx, &fd) == STIN_OK && stin_add_light(ctx, &light) == STIN_OK &&
             stin_draw(ctx, tube, NULL, &tube_mat) == STIN_OK &&
             stin_draw(ctx, floor_mesh, NULL, &ground) == STIN_OK && stin_end_frame(ctx) == STIN_OK;
    }
    stin_destroy(ctx);
    free(block);
    return !ok;
}

int main(int argc, char **argv)
{
    example_egl e;
    const char *out = NULL;
    int failed;
    (void)example_render; /* example_scene.h's one-frame scene: not this one */
    if (example_egl_args(&e, argc, argv, &out))
        return 2;
    if (example_egl_open(&e, "skinned"))
        return 2;
    failed = run_frames(e.fbo);
    return example_egl_close(&e, out) || failed;
}
