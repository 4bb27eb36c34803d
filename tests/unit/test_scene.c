/* SPDX-License-Identifier: MIT */
/* Unit tests for the tools' scene loader, primitives, camera and image I/O.
 * Run from the repository root (scene paths are relative to it). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "image_io.h"
#include "isolate.h"
#include "one_line.h"
#include "scene.h"
#include "scene_csg.h"
#include "scene_internal.h" /* scene_load_text */
#include "scene_primitives.h"

#define BAD_DIR "tests/scenes/bad"

/* ---- helpers ---------------------------------------------------------- */

static int is_zeroed(const void *p, size_t n)
{
    const unsigned char *c = p;
    size_t i;
    for (i = 0; i < n; i++)
        if (c[i])
            return 0;
    return 1;
}

static void sub3(const float *a, const float *b, float *o)
{
    o[0] = a[0] - b[0];
    o[1] = a[1] - b[1];
    o[2] = a[2] - b[2];
}

/* Indices in range, unit normals, finite data, and every triangle's
 * geometric normal agreeing with its vertex normals (CCW = outward). */
static void check_mesh(const scene_mesh *m)
{
    uint32_t i, t;
    assert_true(m->vertex_count > 0 && m->triangle_count > 0);
    for (i = 0; i < m->vertex_count; i++) {
        const float *n = m->normals + 3 * i;
        float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        assert_true(fabsf(len - 1) < 1e-4f);
        assert_true(isfinite(m->positions[3 * i]) && isfinite(m->uvs[2 * i]));
    }
    for (t = 0; t < m->triangle_count; t++) {
        const uint32_t *tri = m->indices + 3 * t;
        float e1[3], e2[3], c[3], n[3] = { 0, 0, 0 };
        int k;
        for (k = 0; k < 3; k++)
            assert_true(tri[k] < m->vertex_count);
        sub3(m->positions + 3 * tri[1], m->positions + 3 * tri[0], e1);
        sub3(m->positions + 3 * tri[2], m->positions + 3 * tri[0], e2);
        c[0] = e1[1] * e2[2] - e1[2] * e2[1];
        c[1] = e1[2] * e2[0] - e1[0] * e2[2];
        c[2] = e1[0] * e2[1] - e1[1] * e2[0];
        for (k = 0; k < 3; k++) {
            n[0] += m->normals[3 * tri[k] + 0];
            n[1] += m->normals[3 * tri[k] + 1];
            n[2] += m->normals[3 * tri[k] + 2];
        }
        assert_true(c[0] * n[0] + c[1] * n[1] + c[2] * n[2] > 0);
    }
}

typedef struct edge {
    uint32_t a, b;
} edge;

static int edge_cmp(const void *x, const void *y)
{
    const edge *e = x, *f = y;
    if (e->a != f->a)
        return e->a < f->a ? -1 : 1;
    return e->b < f->b ? -1 : e->b > f->b;
}

/* Welds vertices with identical positions, then requires every undirected
 * edge to be used exactly twice and every directed edge once (closed and
 * consistently oriented). */
static void check_closed(const scene_mesh *m)
{
    uint32_t *weld = malloc(m->vertex_count * sizeof *weld);
    edge *dir = malloc(3 * (size_t)m->triangle_count * sizeof *dir);
    edge *und = malloc(3 * (size_t)m->triangle_count * sizeof *und);
    size_t n = 3 * (size_t)m->triangle_count, i, run;
    uint32_t v, w, t;
    assert_non_null(weld);
    assert_non_null(dir);
    assert_non_null(und);
    for (v = 0; v < m->vertex_count; v++) {
        weld[v] = v;
        for (w = 0; w < v; w++)
            if (memcmp(m->positions + 3 * v, m->positions + 3 * w, 3 * sizeof(float)) == 0) {
                weld[v] = weld[w];
                break;
            }
    }
    for (t = 0; t < m->triangle_count; t++)
        for (i = 0; i < 3; i++) {
            uint32_t a = weld[m->indices[3 * t + i]], b = weld[m->indices[3 * t + (i + 1) % 3]];
            assert_true(a != b); /* no degenerate triangles after welding */
            dir[3 * t + i].a = a;
            dir[3 * t + i].b = b;
            und[3 * t + i].a = a < b ? a : b;
            und[3 * t + i].b = a < b ? b : a;
        }
    qsort(dir, n, sizeof *dir, edge_cmp);
    qsort(und, n, sizeof *und, edge_cmp);
    for (i = 1; i < n; i++)
        assert_true(edge_cmp(&dir[i - 1], &dir[i]) != 0);
    for (i = 0; i < n; i += run) {
        for (run = 1; i + run < n && edge_cmp(&und[i], &und[i + run]) == 0; run++)
            ;
        assert_int_equal(run, 2);
    }
    free(weld);
    free(dir);
    free(und);
}

/* ---- bad scenes ---------------------------------------------------------- */

/* where == NULL: the file loads and stin rejects it at the GPU stage
 * (stin-render's test wants exit 2 and one line for it). */

static const struct {
    const char *file, *where, *problem;
} bad_scenes[] = {
    { "malformed.json", "line 6, column 3", "expected ','" },
    { "unknown-primitive.json", "meshes.ball.primitive", "unknown primitive 'cone'" },
    { "missing-mesh-file.json", "meshes.ball.file", "cannot open 'no-such-model.obj'" },
    { "string-number.json", "meshes.ball.radius", "expected a finite number" },
    { "nan-number.json", "meshes.ball.radius", "expected a finite number" },
    { "huge-number.json", "lights[0].intensity", "magnitude <= 1e+06" },
    { "negative-radius.json", "meshes.ball.radius", "must be > 0" },
    { "zero-slices.json", "meshes.ball.slices", "expected an integer in [3, 1024]" },
    { "unknown-top-key.json", "", "unknown top-level key 'lihgts'" },
    { "unknown-material.json", "objects[0].material", "unknown material 'gold'" },
    { "two-sided-number.json", "materials.grey.two_sided", "expected true or false" },
    { "unknown-mesh.json", "objects[0].mesh", "unknown mesh 'foo'" },
    { "wrong-array-length.json", "lights[0].position", "expected an array of 3 numbers" },
    { "unknown-object-key.json", "objects[0]", "unknown key 'tranlsate'" },
    { "csg-unknown-object.json", "csg[0].b", "unknown object or csg result 'cube'" },
    { "csg-unknown-op.json", "csg[0].op", "unknown operation 'xor'" },
    { "csg-repeated-operand.json", "csg[0].a", "object 'balls' is 4 instances" },
    { "too-many-lights.json", "lights", "at most 32" },
    { "out-of-range-face.json", "meshes.bad.file", "out of range" },
    { "truncated-ply-header.json", "meshes.cut.file", "no end_header line" },
    { "newline-in-name.json", "objects[0].mesh", "unknown mesh 'ball\\nx\xc3\xa9'" },
    { "truncated-texture.json", "textures.cut.file", "cannot read 'truncated.png'" },
    { "degenerate-mesh.json", NULL, "" },
    { "raw-bytes.json", "", "line 2, column 13: unexpected '\\xff\\xfe\\n\\x01" },
    { "truncated-glb.json", "meshes.cut.file", "cannot open 'truncated.glb'" },
    { "camera-near-tiny.json", "camera.near", "must be at least 1e-06 (got 1e-30)" },
    { "surface-not-a-surface.json", "materials.grey.surface", "'vdsm' is not a surface technique" },
    { "surface-csg-off.json", "materials.grey.surface", "'csg-off' is not a surface technique" },
    /* loaded; scene_csg_products_check refuses them (test_csg_checked) */
    { "csg-transparent-operand.json", NULL, "" },
    { "csg-too-deep.json", NULL, "" },
    { "csg-doubled-crossed.json", NULL, "" },
    /* loaded; refused once stin has judged the meshes (tests/cli/test_render.sh) */
    { "csg-open-mesh.json", NULL, "" },
};
#define BAD_COUNT (sizeof bad_scenes / sizeof bad_scenes[0])

static void expect_failure(const char *path, const char *where, const char *problem)
{
    scene s;
    char err[512], prefix[300];
    memset(&s, 0x5a, sizeof s);
    assert_int_equal(scene_load(path, &s, err, sizeof err), 0);
    assert_true(is_zeroed(&s, sizeof s));
    snprintf(prefix, sizeof prefix, "%s: %s%s", path, where, where[0] ? ": " : "");
    if (strncmp(err, prefix, strlen(prefix)) != 0 || !strstr(err, problem))
        fail_msg("%s: got \"%s\", want \"%s...%s\"", path, err, prefix, problem);
}

static void test_bad_scenes(void **state)
{
    DIR *d = opendir(BAD_DIR);
    struct dirent *e;
    int seen[BAD_COUNT] = { 0 };
    size_t i;
    (void)state;
    assert_non_null(d);
    while ((e = readdir(d))) {
        char path[512];
        if (!strstr(e->d_name, ".json"))
            continue;
        for (i = 0; i < BAD_COUNT && strcmp(bad_scenes[i].file, e->d_name) != 0; i++)
            ;
        if (i == BAD_COUNT)
            fail_msg("%s/%s has no expected message in test_scene.c", BAD_DIR, e->d_name);
        snprintf(path, sizeof path, "%s/%s", BAD_DIR, e->d_name);
        if (bad_scenes[i].where) {
            expect_failure(path, bad_scenes[i].where, bad_scenes[i].problem);
        } else {
            scene s;
            char err[512];
            if (!scene_load(path, &s, err, sizeof err))
                fail_msg("%s should load (stin rejects it later): %s", path, err);
            scene_free(&s);
        }
        seen[i] = 1;
    }
    closedir(d);
    for (i = 0; i < BAD_COUNT; i++)
        if (!seen[i])
            fail_msg("%s/%s is missing", BAD_DIR, bad_scenes[i].file);
    expect_failure(BAD_DIR "/does-not-exist.json", "", "cannot open");
}

/* ---- decoders in a child process, one-line messages ------------------- */

static int work_hangs(void *arg, int fd, char *why, size_t why_size)
{
    (void)arg, (void)fd, (void)why, (void)why_size;
    while (pause() != 0 || 1)
        ;
    return 0;
}

static int work_crashes(void *arg, int fd, char *why, size_t why_size)
{
    (void)arg, (void)fd, (void)why, (void)why_size;
    raise(SIGSEGV);
    return 1;
}

static int work_says(void *arg, int fd, char *why, size_t why_size)
{
    if (arg)
        return isolate_write(fd, arg, strlen(arg));
    snprintf(why, why_size, "no such thing");
    return 0;
}

/* A decoder that loops or crashes costs an error, never the caller. */
static void test_isolate(void **state)
{
    unsigned char *out;
    size_t size;
    char why[256];
    (void)state;
    assert_int_equal(isolate_run(work_hangs, NULL, 1, 1024, &out, &size, why, sizeof why), 0);
    assert_non_null(strstr(why, "took longer than 1 s"));
    assert_int_equal(isolate_run(work_crashes, NULL, 10, 1024, &out, &size, why, sizeof why), 0);
    assert_non_null(strstr(why, "crashed"));
    assert_int_equal(isolate_run(work_says, NULL, 10, 1024, &out, &size, why, sizeof why), 0);
    assert_string_equal(why, "no such thing");
    assert_int_equal(isolate_run(work_says, "hello", 10, 1024, &out, &size, why, sizeof why), 1);
    assert_int_equal(size, 5);
    assert_memory_equal(out, "hello", 5);
    free(out);
    assert_int_equal(isolate_run(work_says, "hello", 10, 4, &out, &size, why, sizeof why), 0);
    assert_non_null(strstr(why, "larger than 4 bytes"));
}

static void test_one_line(void **state)
{
    char out[32];
    (void)state;
    one_line_copy(out, sizeof out, "a\nb\t\x01\xff\xc3\xa9\xed\xa0\x80");
    assert_string_equal(out, "a\\nb\\t\\x01\\xff\xc3\xa9\\xed\\xa0\\x80");
    one_line_copy(out, 5, "abc\ndef");
    assert_string_equal(out, "abc"); /* an escape that does not fit is left out */
}

/* ---- example scenes ----------------------------------------------------- */

static const char *const examples[] = {
    "tests/scenes/spheres-18k.json", "tests/scenes/spheres-76k.json",
    "tests/scenes/spheres-174k.json", "tests/scenes/glass-panes.json",
    "tests/scenes/stone-wall.json",   "tests/scenes/csg.json",
    "tests/scenes/torus.json",        "tests/scenes/four-lights.json",
};

static void test_examples_load(void **state)
{
    size_t i;
    int k;
    (void)state;
    for (i = 0; i < sizeof examples / sizeof examples[0]; i++) {
        scene s;
        char err[512] = "";
        if (!scene_load(examples[i], &s, err, sizeof err))
            fail_msg("%s", err);
        assert_string_equal(s.path, examples[i]);
        assert_true(s.object_count > 0 && s.light_count > 0);
        for (k = 0; k < s.mesh_count; k++)
            check_mesh(&s.meshes[k]);
        for (k = 0; k < s.object_count; k++) {
            assert_true(s.objects[k].mesh >= 0 && s.objects[k].mesh < s.mesh_count);
            assert_true(s.objects[k].material >= 0 && s.objects[k].material < s.material_count);
        }
        for (k = 0; k < s.light_count; k++) {
            const float *d = s.lights[k].direction;
            assert_true(fabsf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - 1) < 1e-5f);
        }
        scene_free(&s);
        assert_true(is_zeroed(&s, sizeof s));
    }
}

static void test_sphere_scenes(void **state)
{
    static const struct {
        const char *path;
        uint32_t per_sphere;
        uint64_t spheres;
    } v[] = {
        { "tests/scenes/spheres-18k.json", 180, 18000 },
        { "tests/scenes/spheres-76k.json", 760, 76000 },
        { "tests/scenes/spheres-174k.json", 1740, 174000 },
    };
    size_t i;
    (void)state;
    for (i = 0; i < 3; i++) {
        scene s;
        char err[512];
        int k, balls = 0;
        uint64_t others = 0;
        if (!scene_load(v[i].path, &s, err, sizeof err))
            fail_msg("%s", err);
        assert_int_equal(s.object_count, 102);
        for (k = 0; k < s.object_count; k++) {
            const scene_mesh *m = &s.meshes[s.objects[k].mesh];
            if (strcmp(m->name, "ball") == 0) {
                assert_int_equal(m->triangle_count, v[i].per_sphere);
                balls++;
            } else {
                others += m->triangle_count;
            }
        }
        assert_int_equal(balls, 100);
        assert_int_equal(others, 2 + 12); /* floor plane + rectangle box */
        assert_int_equal(scene_triangle_count(&s) - others, v[i].spheres);
        /* "repeat" expands x fastest: the second instance is one step along x. */
        assert_float_equal(s.objects[2].transform[12], -5.4f, 1e-5f);
        assert_float_equal(s.objects[3].transform[12], -4.2f, 1e-5f);
        assert_float_equal(s.objects[3].transform[13], 0.4f, 1e-5f);
        scene_free(&s);
    }
}

/* A glTF model (tools/make-model-assets.py): one object per node with the
 * node's transform times the object's, each with its own material; the
 * .glb's embedded texture equals the .gltf's external one. */
static void test_model_nodes(void **state)
{
    static const char *const paths[] = { "tests/scenes/meshes/quads-gltf.json",
                                          "tests/scenes/meshes/quads-glb.json" };
    const uint8_t yellow[4] = { 255, 255, 0, 255 }, magenta[4] = { 255, 0, 255, 255 };
    size_t i;
    (void)state;
    for (i = 0; i < 2; i++) {
        scene s;
        char err[512];
        const scene_object *o;
        const scene_material *m;
        const scene_texture *t;
        if (!scene_load(paths[i], &s, err, sizeof err))
            fail_msg("%s", err);
        assert_int_equal(s.object_count, 3);
        assert_int_equal(s.mesh_count, 3);
        assert_true(s.warnings == NULL);
        /* nodes in file order: red, group/cells (child of group), veil */
        o = &s.objects[0];
        m = &s.materials[o->material];
        assert_string_equal(s.meshes[o->mesh].name, "quads/red");
        assert_string_equal(m->name, "quads/red");
        assert_float_equal(o->transform[12], -1.0f, 1e-6f);
        assert_float_equal(o->transform[13], -0.25f, 1e-6f); /* the object's translate */
        assert_true(m->color[0] == 1 && m->color[1] == 0 && m->color[2] == 0 && m->color[3] == 1);
        assert_int_equal(m->albedo, -1);
        o = &s.objects[1];
        m = &s.materials[o->material];
        assert_float_equal(o->transform[0], 0.5f, 1e-6f);
        assert_float_equal(o->transform[12], 1.0f, 1e-6f);
        assert_float_equal(o->transform[13], 0.25f, 1e-6f);
        assert_true(m->albedo >= 0 && m->albedo < s.texture_count);
        t = &s.textures[m->albedo];
        assert_int_equal(t->width, 16);
        assert_int_equal(t->kind, SCENE_TEXTURE_ALBEDO);
        /* rows bottom first: the PNG's top-left cell is the last row's start */
        assert_memory_equal(t->rgba + 4 * 15 * 16, yellow, 4);
        assert_memory_equal(t->rgba + 4 * 15, magenta, 4);
        o = &s.objects[2];
        m = &s.materials[o->material];
        assert_float_equal(o->transform[0], 0.5f, 1e-6f);
        assert_float_equal(o->transform[14], 0.25f, 1e-6f);
        assert_float_equal(m->color[3], 0.5f, 1e-6f); /* BLEND keeps its alpha */
        assert_int_equal(s.has_camera, 1);
        scene_free(&s);
    }
}

static void test_textures_and_files(void **state)
{
    scene s;
    char err[512];
    int k;
    (void)state;
    if (!scene_load("tests/scenes/stone-wall.json", &s, err, sizeof err))
        fail_msg("%s", err);
    assert_int_equal(s.texture_count, 3);
    assert_int_equal(s.textures[0].kind, SCENE_TEXTURE_ALBEDO);
    assert_int_equal(s.textures[1].kind, SCENE_TEXTURE_HEIGHT);
    assert_int_equal(s.textures[2].kind, SCENE_TEXTURE_NORMAL);
    assert_int_equal(s.materials[0].albedo, 0);
    assert_int_equal(s.materials[0].height, 1);
    assert_int_equal(s.materials[0].normal, 2);
    {
        const scene_texture *h = &s.textures[1], *n = &s.textures[2];
        int x, y, mortar = 0, top = 0;
        for (k = 0; k < h->width * h->height; k++) {
            mortar += h->rgba[4 * k] == 0;
            top += h->rgba[4 * k] == 255;
            /* Normal maps point out of the surface: z >= 0 stored >= 127. */
            assert_true(n->rgba[4 * k + 2] >= 127);
        }
        assert_true(mortar > 0 && top > 0);
        /* Where the height is flat the normal is (0, 0, 1). */
        for (y = 1; y < h->height - 1; y++)
            for (x = 1; x < h->width - 1; x++) {
                const uint8_t *c = h->rgba + 4 * (y * h->width + x);
                if (c[0] == 255 && c[4] == 255 && c[-4] == 255 && c[4 * h->width] == 255 &&
                    c[-4 * h->width] == 255) {
                    const uint8_t *nn = n->rgba + 4 * (y * n->width + x);
                    assert_int_equal(nn[0], 128);
                    assert_int_equal(nn[1], 128);
                    assert_int_equal(nn[2], 255);
                }
            }
    }
    scene_free(&s);

    if (!scene_load("tests/scenes/four-lights.json", &s, err, sizeof err))
        fail_msg("%s", err);
    for (k = 0; k < s.mesh_count && strcmp(s.meshes[k].name, "gem") != 0; k++)
        ;
    assert_true(k < s.mesh_count);
    assert_int_equal(s.meshes[k].triangle_count, 8);
    assert_int_equal(s.meshes[k].vertex_count, 6);
    check_closed(&s.meshes[k]);
    /* The object without a material gets the implicit default one. */
    assert_string_equal(s.materials[s.material_count - 1].name, "default");
    assert_float_equal(s.materials[s.material_count - 1].color[0], 0.8f, 1e-6f);
    scene_free(&s);
}

/* ---- primitives ----------------------------------------------------------- */

static void test_primitive_sphere(void **state)
{
    static const int p[] = { 3, 10, 20, 30 };
    static const uint32_t tris[] = { 12, 180, 760, 1740 };
    size_t i;
    (void)state;
    for (i = 0; i < 4; i++) {
        scene_mesh m;
        memset(&m, 0, sizeof m);
        assert_true(scene_prim_sphere(&m, 0.4f, p[i], p[i]));
        assert_int_equal(m.triangle_count, tris[i]);
        check_mesh(&m);
        check_closed(&m);
        scene_mesh_release(&m);
    }
}

static void test_primitive_others(void **state)
{
    scene_mesh m;
    uint32_t v;
    (void)state;
    memset(&m, 0, sizeof m);
    assert_true(scene_prim_box(&m, 4, 0.05f, 4));
    assert_int_equal(m.vertex_count, 24);
    assert_int_equal(m.triangle_count, 12);
    check_mesh(&m);
    check_closed(&m);
    scene_mesh_release(&m);

    assert_true(scene_prim_torus(&m, 1, 0.3f, 24, 12));
    assert_int_equal(m.triangle_count, 2 * 24 * 12);
    check_mesh(&m);
    check_closed(&m);
    scene_mesh_release(&m);

    assert_true(scene_prim_cylinder(&m, 0.5f, 2, 16, 1));
    assert_int_equal(m.triangle_count, 4 * 16);
    check_mesh(&m);
    check_closed(&m);
    scene_mesh_release(&m);

    assert_true(scene_prim_cylinder(&m, 0.5f, 2, 16, 0));
    assert_int_equal(m.triangle_count, 2 * 16);
    check_mesh(&m);
    scene_mesh_release(&m);

    assert_true(scene_prim_plane(&m, 16, 8, 4, 2));
    assert_int_equal(m.vertex_count, 15);
    assert_int_equal(m.triangle_count, 16);
    check_mesh(&m);
    for (v = 0; v < m.vertex_count; v++) {
        assert_float_equal(m.normals[3 * v + 1], 1, 0);
        assert_true(fabsf(m.positions[3 * v]) <= 8 && fabsf(m.positions[3 * v + 2]) <= 4);
    }
    scene_mesh_release(&m);
}

/* ---- camera --------------------------------------------------------------- */

static void test_camera(void **state)
{
    /* Eye on +x looking at the origin: gluLookAt gives side = (0,0,-1),
     * up = (0,1,0), back = (1,0,0), translation -R*eye = (0,0,-5). */
    static const float want_view[16] = { 0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, -5, 1 };
    /* fovy 90 (cot = 1), aspect 2, near 1, far 3. */
    static const float want_proj[16] = { 0.5f, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -1, 0, 0, -3, 0 };
    scene_camera cam = { { 5, 0, 0 }, { 0, 0, 0 }, { 0, 1, 0 }, 90, 1, 3 };
    float view[16], proj[16];
    int i;
    (void)state;
    scene_camera_matrices(&cam, 200, 100, view, proj);
    for (i = 0; i < 16; i++) {
        assert_float_equal(view[i], want_view[i], 1e-6f);
        assert_float_equal(proj[i], want_proj[i], 1e-6f);
    }
}

/* ---- image I/O ------------------------------------------------------------ */

static char tmp_dir[256];

static int make_tmp_dir(void **state)
{
    const char *base = getenv("TMPDIR");
    (void)state;
    snprintf(tmp_dir, sizeof tmp_dir, "%s/stin-test-scene-XXXXXX", base && base[0] ? base : "/tmp");
    return mkdtemp(tmp_dir) ? 0 : -1;
}

static int remove_tmp_dir(void **state)
{
    DIR *d = opendir(tmp_dir);
    struct dirent *e;
    (void)state;
    while (d && (e = readdir(d))) {
        char p[600];
        if (e->d_name[0] == '.')
            continue;
        snprintf(p, sizeof p, "%s/%s", tmp_dir, e->d_name);
        if (remove(p) != 0)
            rmdir(p);
    }
    if (d)
        closedir(d);
    return rmdir(tmp_dir);
}

static int dir_entries(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    while (d && (e = readdir(d)))
        n += e->d_name[0] != '.';
    if (d)
        closedir(d);
    return n;
}

static void test_exr_round_trip(void **state)
{
    static const char *names[] = { "R", "G", "B", "A", "P.X", "P.Y", "P.Z" };
    image img, back;
    char path[400], err[512];
    int i, c;
    (void)state;
    assert_true(image_alloc(&img, 5, 3, 7));
    for (c = 0; c < 7; c++)
        strcpy(img.channel_names[c], names[c]);
    for (i = 0; i < 15 * 7; i++)
        img.pixels[i] = i % 7 < 4 ? (float)(i % 11) / 10.0f : 1234.5678f + (float)i / 3.0f;
    snprintf(path, sizeof path, "%s/aov.exr", tmp_dir);
    if (!image_write(path, &img, 0, err, sizeof err))
        fail_msg("%s", err);
    if (!image_read(path, &back, err, sizeof err))
        fail_msg("%s", err);
    assert_int_equal(back.width, 5);
    assert_int_equal(back.height, 3);
    assert_int_equal(back.channels, 7);
    for (c = 0; c < 7; c++) {
        int bc = image_channel(&back, names[c]);
        assert_true(bc >= 0);
        for (i = 0; i < 15; i++) {
            float want = img.pixels[i * 7 + c], got = back.pixels[i * back.channels + bc];
            if (c < 4)
                assert_float_equal(got, want, 1e-3f); /* half */
            else
                assert_true(got == want); /* float: exact */
        }
    }
    image_free(&back);
    image_free(&img);
}

static void test_png_round_trip(void **state)
{
    image img, back;
    char path[400], err[512];
    int i;
    (void)state;
    assert_true(image_alloc(&img, 4, 4, 4));
    for (i = 0; i < 64; i++)
        img.pixels[i] = (float)((i * 37) % 256) / 255.0f + 0.001f;
    snprintf(path, sizeof path, "%s/plain.png", tmp_dir);
    if (!image_write(path, &img, 0, err, sizeof err))
        fail_msg("%s", err);
    if (!image_read(path, &back, err, sizeof err))
        fail_msg("%s", err);
    assert_int_equal(back.channels, 4);
    for (i = 0; i < 64; i++)
        assert_float_equal(back.pixels[i], img.pixels[i], 1.0f / 255.0f);
    image_free(&back);

    /* sRGB transfer on colour only: linear 0.5 -> 0.7354, alpha stays. */
    for (i = 0; i < 64; i++)
        img.pixels[i] = 0.5f;
    snprintf(path, sizeof path, "%s/srgb.png", tmp_dir);
    assert_true(image_write(path, &img, 1, err, sizeof err));
    assert_true(image_read(path, &back, err, sizeof err));
    assert_float_equal(back.pixels[0], 0.7354f, 1.0f / 255.0f);
    assert_float_equal(back.pixels[3], 0.5f, 1.0f / 255.0f);
    image_free(&back);
    image_free(&img);
}

static void test_write_failures(void **state)
{
    image img;
    char path[400], err[512] = "";
    int before;
    (void)state;
    assert_true(image_alloc(&img, 2, 2, 3));
    snprintf(path, sizeof path, "%s/no-such-dir/x.png", tmp_dir);
    assert_int_equal(image_write(path, &img, 1, err, sizeof err), 0);
    assert_true(strstr(err, path) != NULL);
    assert_int_equal(access(path, F_OK), -1);

    /* The rename fails onto a directory: the temporary must be removed. */
    snprintf(path, sizeof path, "%s/dir.exr", tmp_dir);
    assert_int_equal(mkdir(path, 0700), 0);
    before = dir_entries(tmp_dir);
    assert_int_equal(image_write(path, &img, 0, err, sizeof err), 0);
    assert_int_equal(dir_entries(tmp_dir), before);
    rmdir(path);

    snprintf(path, sizeof path, "%s/x.bmpx", tmp_dir);
    assert_int_equal(image_write(path, &img, 0, err, sizeof err), 0);
    assert_int_equal(access(path, F_OK), -1);
    image_free(&img);
}

/* A scene file at path: a quad whose albedo is the picture file pic (a
 * name beside it). */
static void write_texture_scene(const char *path, const char *pic)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f,
            "{\"camera\": {\"eye\": [0, 0, 3], \"target\": [0, 0, 0]},\n"
            " \"meshes\": {\"quad\": {\"primitive\": \"plane\"}},\n"
            " \"textures\": {\"pic\": {\"file\": \"%s\"}},\n"
            " \"materials\": {\"m\": {\"albedo\": \"pic\"}},\n"
            " \"objects\": [{\"mesh\": \"quad\", \"material\": \"m\"}]}\n",
            pic);
    fclose(f);
}

/* A file texture next to a scene file: relative path, rows flipped to
 * bottom-to-top, grey PNG expanded to RGBA. */
static void test_file_texture(void **state)
{
    image img;
    scene s;
    char path[400], err[512];
    (void)state;
    assert_true(image_alloc(&img, 1, 2, 1));
    strcpy(img.channel_names[0], "Y");
    img.pixels[0] = 1.0f; /* top row in the file */
    snprintf(path, sizeof path, "%s/pic.png", tmp_dir);
    assert_true(image_write(path, &img, 0, err, sizeof err));
    image_free(&img);
    snprintf(path, sizeof path, "%s/tex.json", tmp_dir);
    write_texture_scene(path, "pic.png");
    if (!scene_load(path, &s, err, sizeof err))
        fail_msg("%s", err);
    assert_int_equal(s.texture_count, 1);
    assert_int_equal(s.textures[0].width, 1);
    assert_int_equal(s.textures[0].height, 2);
    assert_memory_equal(s.textures[0].rgba, "\0\0\0\377\377\377\377\377", 8);
    assert_int_equal(s.lights == NULL && s.light_count == 0, 1);
    scene_free(&s);
}

/* A 1 x 2 grey picture: top, and 1 - top below it. */
static void write_pic(const char *path, float top)
{
    image img;
    char err[512];
    assert_true(image_alloc(&img, 1, 2, 1));
    strcpy(img.channel_names[0], "Y");
    img.pixels[0] = top; /* top row in the file */
    img.pixels[1] = 1.0f - top;
    assert_true(image_write(path, &img, 0, err, sizeof err));
    image_free(&img);
}

static void load_top(const char *json_path, unsigned char expect)
{
    scene s;
    char err[512];
    if (!scene_load(json_path, &s, err, sizeof err))
        fail_msg("%s", err);
    assert_int_equal(s.texture_count, 1);
    assert_int_equal(s.textures[0].rgba[4], expect); /* the file's top row, last in rgba */
    scene_free(&s);
}

/* scene_import_memo: an unchanged file's bytes come from the memo (a file
 * rewritten with its size and time kept still reads as before, proving no
 * decoder ran), a changed time decodes it again. */
static void test_import_memo(void **state)
{
    char pic[400], other[400], path[400], bytes[4096];
    struct stat first, again;
    struct timespec times[2];
    size_t n;
    FILE *f;
    (void)state;
    snprintf(pic, sizeof pic, "%s/memo.png", tmp_dir);
    snprintf(other, sizeof other, "%s/memo-swapped.png", tmp_dir);
    snprintf(path, sizeof path, "%s/memo.json", tmp_dir);
    write_texture_scene(path, "memo.png");
    write_pic(pic, 1.0f);
    write_pic(other, 0.0f); /* the rows swapped: the same size */
    assert_int_equal(stat(pic, &first), 0);
    scene_import_memo = 1;
    load_top(path, 255);
    /* the swapped picture's bytes written over the file in place (the same
     * inode and size), its times put back */
    f = fopen(other, "rb");
    assert_non_null(f);
    n = fread(bytes, 1, sizeof bytes, f);
    fclose(f);
    assert_int_equal(n, (size_t)first.st_size);
    f = fopen(pic, "r+b");
    assert_non_null(f);
    assert_int_equal(fwrite(bytes, 1, n, f), n);
    fclose(f);
    times[0] = first.st_atim;
    times[1] = first.st_mtim;
    assert_int_equal(utimensat(AT_FDCWD, pic, times, 0), 0);
    assert_int_equal(stat(pic, &again), 0);
    assert_true(again.st_ino == first.st_ino && again.st_size == first.st_size);
    load_top(path, 255); /* the memo's bytes: no decoder read the new file */
    times[1].tv_sec += 10;
    assert_int_equal(utimensat(AT_FDCWD, pic, times, 0), 0);
    load_top(path, 0); /* changed: decoded again */
    scene_import_memo = 0;
    load_top(path, 0);
}

static void test_compare(void **state)
{
    image a, b;
    image_diff d;
    float mask[4] = { 1, 1, 1, 0 };
    int i;
    (void)state;
    assert_true(image_alloc(&a, 2, 2, 2));
    assert_true(image_alloc(&b, 2, 2, 2));
    strcpy(a.channel_names[0], "R");
    strcpy(a.channel_names[1], "vis.R");
    strcpy(b.channel_names[0], "vis.R"); /* matched by name, not position */
    strcpy(b.channel_names[1], "R");
    for (i = 0; i < 4; i++) {
        a.pixels[2 * i] = 0.5f;
        b.pixels[2 * i + 1] = 0.5f;
    }
    b.pixels[2 * 1 + 1] = 0.75f; /* pixel 1: R differs by 0.25 */
    b.pixels[2 * 3 + 1] = 5.0f;  /* pixel 3: masked out */
    assert_true(image_compare(&a, &b, "R", mask, 0.1, &d));
    assert_int_equal(d.compared, 3);
    assert_int_equal(d.over_threshold, 1);
    assert_float_equal(d.max_abs, 0.25, 1e-6);
    assert_float_equal(d.mean_abs, 0.25 / 3, 1e-6);
    assert_true(image_compare(&a, &b, "R,vis.R", NULL, 0.1, &d));
    assert_int_equal(d.compared, 4);
    assert_float_equal(d.max_abs, 4.5, 1e-6);
    assert_int_equal(image_compare(&a, &b, "R,Z", NULL, 0.1, &d), 0);
    image_free(&a);
    image_free(&b);
}

/* No camera: one is made that frames every object. */
static void test_framing(void **state)
{
    char path[300], err[512];
    FILE *f;
    scene s;
    float d;
    (void)state;
    snprintf(path, sizeof path, "%s/no-camera.json", tmp_dir);
    f = fopen(path, "w");
    assert_non_null(f);
    fputs("{\"meshes\": {\"b\": {\"primitive\": \"box\", \"size\": [2, 2, 2]}},\n"
          " \"objects\": [{\"mesh\": \"b\", \"translate\": [10, 0, 0]}]}\n", f);
    fclose(f);
    if (!scene_load(path, &s, err, sizeof err))
        fail_msg("%s", err);
    remove(path);
    assert_int_equal(s.has_camera, 0);
    assert_float_equal(s.camera.target[0], 10.0f, 1e-5f);
    assert_float_equal(s.camera.target[1], 0.0f, 1e-5f);
    /* the box's sphere (radius sqrt 3) fills fovy 45 with a 5% margin */
    d = sqrtf(powf(s.camera.eye[0] - 10, 2) + powf(s.camera.eye[1], 2) + powf(s.camera.eye[2], 2));
    assert_float_equal(d, 1.05f * sqrtf(3.0f) / sinf(22.5f * 3.14159265f / 180), 1e-4f);
    assert_float_equal(s.camera.eye[1] * 2, s.camera.eye[2], 1e-4f); /* from (0, 1, 2) */
    assert_true(s.camera.near_plane > 0 && s.camera.near_plane < d - sqrtf(3.0f));
    assert_true(s.camera.far_plane > d + sqrtf(3.0f));
    scene_free(&s);
}

/* The csg list is kept (operands as objects or earlier results) and turned
 * into products: one per entry no later entry uses, operands first. */
static void test_csg_list(void **state)
{
    scene s;
    scene_csg_products p;
    char err[512];
    (void)state;
    assert_int_equal(scene_load("tests/scenes/csg.json", &s, err, sizeof err), 1);
    assert_int_equal(s.csg_count, 3);
    assert_int_equal(s.csg[0].op, SCENE_CSG_SUBTRACT);
    assert_int_equal(s.csg[1].op, SCENE_CSG_UNION);
    assert_int_equal(s.csg[2].op, SCENE_CSG_INTERSECT);
    assert_int_equal(s.csg[0].a, 0); /* cube */
    assert_int_equal(s.csg[0].b, 1); /* ball */
    assert_int_equal(scene_csg_products_build(&s, &p), 1);
    assert_int_equal(p.count, 3);
    assert_int_equal(p.products[2].primitive_count, 2);
    assert_int_equal(p.products[2].nodes[2].op, STIN_CSG_INTERSECTION);
    scene_csg_products_free(&p);
    scene_free(&s);

    assert_int_equal(scene_load("tests/scenes/csg/nested.json", &s, err, sizeof err), 1);
    assert_int_equal(s.csg_count, 2);
    assert_int_equal(s.csg[0].used, 1);
    assert_int_equal(s.csg[1].a, -1); /* the result of entry 0 */
    assert_int_equal(s.csg[1].b, 3);  /* post */
    assert_int_equal(scene_csg_products_build(&s, &p), 1);
    assert_int_equal(p.count, 1);
    assert_int_equal(p.products[0].primitive_count, 3);
    assert_int_equal(p.products[0].objects[0], 1);
    assert_int_equal(p.products[0].objects[1], 2);
    assert_int_equal(p.products[0].objects[2], 3);
    assert_int_equal(p.products[0].node_count, 5);
    {
        const stin_csg_node *n = p.products[0].nodes;
        assert_int_equal(n[2].op, STIN_CSG_SUBTRACTION);
        assert_int_equal(n[2].a, 0);
        assert_int_equal(n[2].b, 1);
        assert_int_equal(n[3].primitive, 2);
        assert_int_equal(n[4].op, STIN_CSG_UNION);
        assert_int_equal(n[4].a, 2);
        assert_int_equal(n[4].b, 3);
    }
    scene_csg_products_free(&p);
    scene_free(&s);
}

/* What stin_draw_csg would refuse, refused before any GL with the key that
 * names it; what its capacities can hold, given room. */
static void expect_csg_refused(const char *file, const char *key, const char *problem)
{
    scene s;
    scene_csg_products p;
    stin_desc desc;
    char err[512], path[256];
    snprintf(path, sizeof path, BAD_DIR "/%s", file);
    memset(&desc, 0, sizeof desc);
    assert_int_equal(scene_load(path, &s, err, sizeof err), 1);
    assert_int_equal(scene_csg_products_build(&s, &p), 1);
    assert_int_equal(scene_csg_products_check(&s, &p, &desc, err, sizeof err), 0);
    if (!strstr(err, key) || !strstr(err, problem) || strncmp(err, path, strlen(path)) != 0)
        fail_msg("%s: got \"%s\", want %s ... %s", path, err, key, problem);
    scene_csg_products_free(&p);
    scene_free(&s);
}

static void test_csg_checked(void **state)
{
    static const char doubled[] =
        "{\"meshes\": {\"ball\": {\"primitive\": \"sphere\"}},\n"
        " \"objects\": [{\"mesh\": \"ball\", \"name\": \"a\"}, {\"mesh\": \"ball\", \"name\": \"b\"}],\n"
        " \"csg\": [{\"op\": \"subtract\", \"a\": \"a\", \"b\": \"b\", \"name\": \"x0\"}";
    char text[32768], err[512];
    size_t n = 0;
    int i;
    scene s;
    scene_csg_products p;
    stin_desc desc;
    (void)state;
    expect_csg_refused("csg-transparent-operand.json", "csg[0].b", "opacity 0.5");
    expect_csg_refused("csg-too-deep.json", "csg[1024]", "nests deeper than 1024");
    expect_csg_refused("csg-doubled-crossed.json", "csg[59]", "2^24 steps");
    /* an entry unioned with itself 28 times: 31 nodes, one term */
    n += (size_t)snprintf(text + n, sizeof text - n, "%s", doubled);
    for (i = 1; i <= 28; i++)
        n += (size_t)snprintf(text + n, sizeof text - n,
                              ",\n{\"op\": \"union\", \"a\": \"x%d\", \"b\": \"x%d\", \"name\": \"x%d\"}",
                              i - 1, i - 1, i);
    n += (size_t)snprintf(text + n, sizeof text - n, "]}\n");
    assert_true(n < sizeof text);
    assert_int_equal(scene_load_text("doubled.json", text, n, &s, err, sizeof err), 1);
    assert_int_equal(scene_csg_products_build(&s, &p), 1);
    assert_int_equal(p.count, 1);
    assert_int_equal(p.products[0].node_count, 31);
    assert_int_equal(p.products[0].primitive_count, 2);
    memset(&desc, 0, sizeof desc);
    assert_int_equal(scene_csg_products_check(&s, &p, &desc, err, sizeof err), 1);
    assert_int_equal(desc.csg.max_terms, 0); /* stin's defaults hold it */
    scene_csg_products_free(&p);
    scene_free(&s);
    /* a union of 257 objects: stin's 256 primitives and terms raised to 257 */
    n = (size_t)snprintf(text, sizeof text, "{\"meshes\": {\"cube\": {\"primitive\": \"box\"}},\n"
                         "\"objects\": [{\"mesh\": \"cube\", \"name\": \"o0\"}");
    for (i = 1; i < 257; i++)
        n += (size_t)snprintf(text + n, sizeof text - n, ", {\"mesh\": \"cube\", \"name\": \"o%d\"}", i);
    n += (size_t)snprintf(text + n, sizeof text - n,
                          "],\n\"csg\": [{\"op\": \"union\", \"a\": \"o0\", \"b\": \"o1\", \"name\": \"u1\"}");
    for (i = 2; i < 257; i++)
        n += (size_t)snprintf(text + n, sizeof text - n,
                              ", {\"op\": \"union\", \"a\": \"u%d\", \"b\": \"o%d\", \"name\": \"u%d\"}",
                              i - 1, i, i);
    n += (size_t)snprintf(text + n, sizeof text - n, "]}\n");
    assert_true(n < sizeof text);
    assert_int_equal(scene_load_text("union.json", text, n, &s, err, sizeof err), 1);
    assert_int_equal(scene_csg_products_build(&s, &p), 1);
    memset(&desc, 0, sizeof desc);
    assert_int_equal(scene_csg_products_check(&s, &p, &desc, err, sizeof err), 1);
    assert_int_equal(desc.csg.max_primitives, 257);
    assert_int_equal(desc.csg.max_terms, 257);
    assert_int_equal(desc.csg.max_literals, 0); /* 257 of stin's default 4096 */
    scene_csg_products_free(&p);
    scene_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bad_scenes),
        cmocka_unit_test(test_isolate),
        cmocka_unit_test(test_one_line),
        cmocka_unit_test(test_examples_load),
        cmocka_unit_test(test_sphere_scenes),
        cmocka_unit_test(test_textures_and_files),
        cmocka_unit_test(test_model_nodes),
        cmocka_unit_test(test_framing),
        cmocka_unit_test(test_primitive_sphere),
        cmocka_unit_test(test_primitive_others),
        cmocka_unit_test(test_camera),
        cmocka_unit_test(test_exr_round_trip),
        cmocka_unit_test(test_png_round_trip),
        cmocka_unit_test(test_write_failures),
        cmocka_unit_test(test_file_texture),
        cmocka_unit_test(test_import_memo),
        cmocka_unit_test(test_compare),
        cmocka_unit_test(test_csg_list),
        cmocka_unit_test(test_csg_checked),
    };
    return cmocka_run_group_tests(tests, make_tmp_dir, remove_tmp_dir);
}
