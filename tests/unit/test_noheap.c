/* SPDX-License-Identifier: MIT */
/* No heap, anywhere: (1) the allocator functions are interposed in this
 * executable and count calls while `counting` is set around every public
 * stin call; (2) `nm -u` on the release archive names none of them.
 *
 * Build WITHOUT AddressSanitizer (it owns malloc): UBSan only. glibc only
 * (forwards through __libc_malloc and friends).
 * Usage: test_noheap [path/to/libstin.a]   (else $STIN_LIB, else build/libstin.a) */
#define _POSIX_C_SOURCE 200809L

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fake_gl.h"
#include "internal.h"

/* ---- the interposed allocator -------------------------------------------- */
extern void *__libc_malloc(size_t size);
extern void *__libc_calloc(size_t n, size_t size);
extern void *__libc_realloc(void *p, size_t size);
extern void *__libc_memalign(size_t alignment, size_t size);
extern void __libc_free(void *p);

static volatile int counting;
static volatile unsigned allocations;

static void note(void)
{
    if (counting)
        allocations++;
}

void *malloc(size_t size)
{
    note();
    return __libc_malloc(size);
}

void *calloc(size_t n, size_t size)
{
    note();
    return __libc_calloc(n, size);
}

void *realloc(void *p, size_t size)
{
    note();
    return __libc_realloc(p, size);
}

void free(void *p)
{
    note();
    __libc_free(p);
}

void *memalign(size_t alignment, size_t size);
void *memalign(size_t alignment, size_t size)
{
    note();
    return __libc_memalign(alignment, size);
}

void *aligned_alloc(size_t alignment, size_t size);
void *aligned_alloc(size_t alignment, size_t size)
{
    note();
    return __libc_memalign(alignment, size);
}

int posix_memalign(void **out, size_t alignment, size_t size)
{
    void *p;
    note();
    if (alignment < sizeof(void *) || (alignment & (alignment - 1)))
        return EINVAL;
    p = __libc_memalign(alignment, size);
    if (!p)
        return ENOMEM;
    *out = p;
    return 0;
}

char *strndup(const char *s, size_t n)
{
    size_t len = 0;
    char *d;
    note();
    while (len < n && s[len])
        len++;
    d = __libc_malloc(len + 1);
    if (d) {
        memcpy(d, s, len);
        d[len] = '\0';
    }
    return d;
}

char *strdup(const char *s)
{
    size_t len = strlen(s);
    char *d;
    note();
    d = __libc_malloc(len + 1);
    if (d)
        memcpy(d, s, len + 1);
    return d;
}

#define COUNT_ALLOCATIONS(code)                                                          \
    do {                                                                                 \
        allocations = 0;                                                                 \
        counting = 1;                                                                    \
        code;                                                                            \
        counting = 0;                                                                    \
    } while (0)

/* ---- the library under count --------------------------------------------- */
static unsigned char arena[4u << 20];
static fake_log log_;

static const float cube_pos[] = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                 -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
static const float cube_uv[] = {0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1};
static const uint32_t cube_idx[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                    2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};

static stin_desc small_desc(void)
{
    stin_desc d;
    memset(&d, 0, sizeof d);
    d.get_proc_address = fake_gl_get_proc;
    d.log = fake_log_fn; /* logging on: the formatter runs too */
    d.log_user = &log_;
    d.max_vertices = 1024;
    d.max_triangles = 1024;
    d.max_texture_bytes = 16 * 1024;
    d.max_lights = 16;
    return d;
}

/* Everything a frame's life does, plus the error paths that log. */
static void exercise(fake_gl_profile_id profile)
{
    fake_gl_config cfg = fake_gl_profile(profile);
    stin_desc d = small_desc(), defaults;
    stin_context *ctx = NULL;
    stin_mesh_desc md;
    stin_mesh_update_desc ud;
    stin_mesh mesh = {0}, bad = {0};
    stin_texture_desc td;
    stin_texture tex = {0};
    stin_frame_desc fd;
    stin_light_desc light;
    stin_material mat;
    stin_mesh_info info;
    stin_caps caps;
    uint32_t nb[3];
    float tangent[4];
    static uint8_t pixels[3 * 5 * 4];
    size_t bytes = 0, default_bytes = 0;
    int i;
    stin_result r_small = STIN_OK, r_create = STIN_OK, r_mesh = STIN_OK, r_bad = STIN_OK,
                r_tex = STIN_OK, r_end = STIN_OK, r_detect = STIN_OK, r_update = STIN_OK;

    fake_gl_reset(&cfg);
    memset(&log_, 0, sizeof log_);
    memset(&defaults, 0, sizeof defaults);
    memset(&md, 0, sizeof md);
    memset(&ud, 0, sizeof ud);
    md.positions = cube_pos;
    md.uvs = cube_uv;
    md.vertex_count = 8;
    md.indices = cube_idx;
    md.index_count = 36;
    memset(&td, 0, sizeof td);
    td.width = 3;
    td.height = 5;
    td.pixels = pixels;
    memset(&fd, 0, sizeof fd);
    stin__mat4_identity(fd.view);
    stin__mat4_identity(fd.projection);
    fd.viewport[2] = fd.viewport[3] = 32;
    memset(&light, 0, sizeof light);
    light.position[2] = 4.0f;
    memset(&mat, 0, sizeof mat);

    COUNT_ALLOCATIONS({
        default_bytes = stin_memory_size(&defaults);
        bytes = stin_memory_size(&d);
        r_detect = stin_detect_caps(fake_gl_get_proc, NULL, 0, 0, &caps);
        r_small = stin_create(&d, arena, bytes - 1, &ctx);
        r_create = stin_create(&d, arena + 3, bytes, &ctx); /* unaligned, too */
        if (r_create == STIN_OK) {
            r_mesh = stin_create_mesh(ctx, &md, &mesh);
            md.index_count = 35;
            r_bad = stin_create_mesh(ctx, &md, &bad);
            stin_query_mesh_info(ctx, mesh, &info);
            stin_query_mesh_adjacency(ctx, mesh, 0, nb);
            stin_query_mesh_tangent(ctx, mesh, 0, tangent);
            ud.positions = cube_pos;
            ud.vertex_count = 8;
            r_update = stin_update_mesh(ctx, mesh, &ud);
            r_tex = stin_create_texture(ctx, &td, &tex);
            mat.albedo = tex;
            stin_draw(ctx, mesh, NULL, NULL); /* out of order: logs */
            stin_begin_frame(ctx, &fd);
            for (i = 0; i < 17; i++) /* one more than max_lights: logs */
                stin_add_light(ctx, &light);
            stin_draw(ctx, mesh, NULL, &mat);
            stin_draw(ctx, mesh, NULL, NULL);
            stin_draw(ctx, bad, NULL, NULL);
            stin_update_mesh(ctx, mesh, &ud); /* in a frame: logs */
            r_end = stin_end_frame(ctx);
            stin_query_frame_stats(ctx);
            stin_query_choice(ctx, STIN_FEATURE_LIGHTING);
            stin_query_extension(ctx, "GL_ARB_shadow");
            stin_destroy_texture(ctx, tex);
            stin_destroy_mesh(ctx, mesh);
            stin_destroy_mesh(ctx, mesh); /* stale: logs */
            stin_destroy(ctx);
        }
    });

    assert_int_equal(allocations, 0);
    assert_true(default_bytes > sizeof arena); /* sized, not created */
    assert_true(bytes > 0 && bytes + 3 <= sizeof arena);
    assert_int_equal(r_detect, STIN_OK);
    assert_int_equal(r_small, STIN_ERROR_OUT_OF_MEMORY);
    assert_int_equal(r_create, STIN_OK);
    assert_int_equal(r_mesh, STIN_OK);
    assert_int_equal(r_update, STIN_OK);
    assert_int_equal(r_bad, STIN_ERROR_INVALID_ARGUMENT);
    assert_int_equal(r_tex, STIN_OK);
    assert_int_equal(r_end, STIN_OK);
    assert_true(fake_gl.draw_calls >= 2);
    assert_true(log_.errors >= 4);
}

/* The counter works: otherwise the tests below could pass by not counting. */
static void test_interposer_counts(void **state)
{
    void *(*volatile alloc)(size_t) = malloc;
    void (*volatile release)(void *) = free;
    char *(*volatile dup)(const char *) = strdup;
    (void)state;
    COUNT_ALLOCATIONS({
        void *p = alloc(16);
        char *s = dup("stin");
        release(s);
        release(p);
    });
    assert_int_equal(allocations, 4);
}

static void test_gl11_no_heap(void **state)
{
    (void)state;
    exercise(FAKE_GL11);
}

static void test_gl21_no_heap(void **state)
{
    (void)state;
    exercise(FAKE_GL21);
}

static void test_gl45_no_heap(void **state)
{
    (void)state;
    exercise(FAKE_GL45_CORE);
}

/* ---- the archive's undefined symbols -------------------------------------- */
static const char *library_path = "build/libstin.a";

static void test_archive_names_no_allocator(void **state)
{
    static const char *const forbidden[] = {"malloc", "calloc", "realloc", "free", "strdup",
                                            "strndup", "aligned_alloc", "posix_memalign",
                                            "memalign"};
    char command[1024], line[512];
    FILE *nm, *archive;
    unsigned members = 0;
    size_t i;
    (void)state;
    archive = fopen(library_path, "rb");
    if (!archive)
        fail_msg("cannot open %s (build it with `make build/libstin.a`)", library_path);
    fclose(archive);
    snprintf(command, sizeof command, "nm -u '%s' 2>&1", library_path);
    nm = popen(command, "r");
    assert_non_null(nm);
    while (fgets(line, sizeof line, nm)) {
        char *end = line + strlen(line), *sym;
        while (end > line && (end[-1] == '\n' || end[-1] == ' '))
            *--end = '\0';
        if (end - line > 2 && end[-1] == ':' && end[-2] == 'o') {
            members++; /* "context.o:" */
            continue;
        }
        sym = strrchr(line, ' ');
        sym = sym ? sym + 1 : line;
        for (i = 0; i < sizeof forbidden / sizeof forbidden[0]; i++)
            if (strcmp(sym, forbidden[i]) == 0)
                fail_msg("%s needs %s", library_path, sym);
    }
    assert_int_equal(pclose(nm), 0);
    assert_true(members >= 10); /* nm did read the archive */
}

int main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_interposer_counts),
        cmocka_unit_test(test_gl11_no_heap),
        cmocka_unit_test(test_gl21_no_heap),
        cmocka_unit_test(test_gl45_no_heap),
        cmocka_unit_test(test_archive_names_no_allocator),
    };
    if (argc > 1)
        library_path = argv[1];
    else if (getenv("STIN_LIB"))
        library_path = getenv("STIN_LIB");
    return cmocka_run_group_tests(tests, NULL, NULL);
}
