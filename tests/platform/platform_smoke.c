/* SPDX-License-Identifier: MIT */
/*
 * platform_smoke KIND PROFILE [--size WxH] [--extensions]
 *
 * Creates a context through libstin_platform for one profile, prints what the
 * driver reports, clears colour/depth/stencil to known values and checks the
 * readback of every pixel. Prints "ok" and exits 0 when all match.
 * PROFILE is a name from the profile table, or "none" for no profile.
 */
#include "stin_platform.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GL_DEPTH_BUFFER_BIT 0x00000100
#define GL_STENCIL_BUFFER_BIT 0x00000400
#define GL_COLOR_BUFFER_BIT 0x00004000
#define GL_STENCIL_BITS 0x0D57
#define GL_VENDOR 0x1F00
#define GL_RENDERER 0x1F01
#define GL_VERSION 0x1F02
#define GL_EXTENSIONS 0x1F03
#define GL_SHADING_LANGUAGE_VERSION 0x8B8C
#define GL_NUM_EXTENSIONS 0x821D
#define GL_CONTEXT_PROFILE_MASK 0x9126
#define GL_CONTEXT_CORE_PROFILE_BIT 0x1
#define GL_FRAMEBUFFER 0x8D40
#define GL_STENCIL 0x1802
#define GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE 0x8217

typedef const unsigned char *(*get_string_fn)(unsigned);
typedef const unsigned char *(*get_stringi_fn)(unsigned, unsigned);
typedef void (*get_integerv_fn)(unsigned, int *);
typedef void (*clear_color_fn)(float, float, float, float);
typedef void (*clear_depth_fn)(double);
typedef void (*clear_depthf_fn)(float);
typedef void (*clear_stencil_fn)(int);
typedef void (*clear_fn)(unsigned);
typedef unsigned (*get_error_fn)(void);
typedef void (*get_fb_attachment_fn)(unsigned, unsigned, unsigned, int *);

typedef struct gl {
    get_string_fn get_string;
    get_stringi_fn get_stringi;
    get_integerv_fn get_integerv;
    clear_color_fn clear_color;
    clear_depth_fn clear_depth;   /* desktop GL */
    clear_depthf_fn clear_depthf; /* OpenGL ES */
    int es;
    clear_stencil_fn clear_stencil;
    clear_fn clear;
    get_error_fn get_error;
    get_fb_attachment_fn get_fb_attachment;
} gl;

/* void * -> function pointer without the ISO C object/function cast. */
#define LOAD(p, dst, name)                                              \
    do {                                                                \
        void *ptr_ = stin_platform_get_proc_address((p), (name));       \
        memcpy(&(dst), &ptr_, sizeof ptr_);                             \
    } while (0)

static int load_gl(stin_platform *p, gl *g)
{
    memset(g, 0, sizeof *g);
    LOAD(p, g->get_string, "glGetString");
    LOAD(p, g->get_stringi, "glGetStringi");
    LOAD(p, g->get_integerv, "glGetIntegerv");
    LOAD(p, g->clear_color, "glClearColor");
    LOAD(p, g->get_string, "glGetString");
    g->es = g->get_string && !strncmp((const char *)g->get_string(GL_VERSION), "OpenGL ES ", 10);
    if (g->es) /* Mesa resolves desktop-only names on ES too: never call them there */
        LOAD(p, g->clear_depthf, "glClearDepthf");
    else
        LOAD(p, g->clear_depth, "glClearDepth");
    LOAD(p, g->clear_stencil, "glClearStencil");
    LOAD(p, g->clear, "glClear");
    LOAD(p, g->get_error, "glGetError");
    LOAD(p, g->get_fb_attachment, "glGetFramebufferAttachmentParameteriv");
    return g->get_string && g->get_integerv && g->clear_color &&
           (g->clear_depth || g->clear_depthf) &&
           g->clear_stencil && g->clear && g->get_error;
}

static const char *str(const gl *g, unsigned name)
{
    const unsigned char *s = g->get_string(name);
    g->get_error(); /* GLSL version is INVALID_ENUM on GL 1.x */
    return s ? (const char *)s : "(none)";
}

static int is_core(const gl *g)
{
    int mask = 0;
    if (g->es)
        return 0;
    g->get_integerv(GL_CONTEXT_PROFILE_MASK, &mask);
    g->get_error(); /* INVALID_ENUM before GL 3.2 */
    return (mask & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
}

/* Core profiles have no GL_STENCIL_BITS: ask the default framebuffer. */
static int stencil_bits(const gl *g, int core)
{
    int bits = -1;
    if (core && g->get_fb_attachment)
        g->get_fb_attachment(GL_FRAMEBUFFER, GL_STENCIL, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE,
                             &bits);
    else
        g->get_integerv(GL_STENCIL_BITS, &bits);
    return bits;
}

static void print_extensions(const gl *g, int core)
{
    int i, n = 0;
    if (!core || g->es) { /* ES 3.x keeps the GL_EXTENSIONS string */
        printf("extensions: %s\n", str(g, GL_EXTENSIONS));
        return;
    }
    g->get_integerv(GL_NUM_EXTENSIONS, &n);
    printf("extensions:");
    for (i = 0; i < n && g->get_stringi; i++)
        printf(" %s", (const char *)g->get_stringi(GL_EXTENSIONS, (unsigned)i));
    printf("\n");
}

static int near_byte(int got, int want)
{
    return abs(got - want) <= 1;
}

/* Clears, reads back, reports the first mismatch of each buffer. */
static int check_clear(stin_platform *p, const gl *g)
{
    int w = stin_platform_width(p), h = stin_platform_height(p), i, bad = 0;
    size_t n = (size_t)w * (size_t)h;
    uint8_t *rgba = malloc(n * 4), *stencil = malloc(n);
    float *depth = malloc(n * sizeof *depth);

    g->clear_color(0.25f, 0.5f, 0.75f, 1.0f);
    if (g->es)
        g->clear_depthf(0.5f);
    else
        g->clear_depth(0.5);
    g->clear_stencil(7);
    g->clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    if (!rgba || !stencil || !depth || !stin_platform_read_color(p, rgba) ||
        !stin_platform_read_depth(p, depth) || !stin_platform_read_stencil(p, stencil)) {
        fprintf(stderr, "readback failed\n");
        bad = 1;
        goto done;
    }
    for (i = 0; i < (int)n; i++) {
        const uint8_t *c = rgba + 4 * i;
        if (!near_byte(c[0], 64) || !near_byte(c[1], 128) || !near_byte(c[2], 191) ||
            c[3] != 255) {
            fprintf(stderr, "colour at %d,%d is %d %d %d %d, want 64 128 191 255\n", i % w,
                    i / w, c[0], c[1], c[2], c[3]);
            bad = 1;
            break;
        }
    }
    for (i = 0; i < (int)n; i++) {
        float d = depth[i] - 0.5f;
        if (d > 1e-5f || d < -1e-5f) {
            fprintf(stderr, "depth at %d,%d is %.8f, want 0.5\n", i % w, i / w, depth[i]);
            bad = 1;
            break;
        }
    }
    for (i = 0; i < (int)n; i++) {
        if (stencil[i] != 7) {
            fprintf(stderr, "stencil at %d,%d is %d, want 7\n", i % w, i / w, stencil[i]);
            bad = 1;
            break;
        }
    }
done:
    free(rgba);
    free(stencil);
    free(depth);
    return !bad;
}

static int usage(void)
{
    size_t i;
    fprintf(stderr, "usage: platform_smoke egl|osmesa PROFILE [--size WxH] [--extensions]\n"
                    "profiles: none");
    for (i = 0; i < stin_profile_count(); i++)
        fprintf(stderr, " %s", stin_profile_at(i)->name);
    fprintf(stderr, "\n");
    return 2;
}

int main(int argc, char **argv)
{
    stin_platform_desc desc;
    stin_platform *p;
    char err[512];
    gl g;
    int i, core, ok, extensions = 0;

    memset(&desc, 0, sizeof desc);
    if (argc < 3 || !stin_platform_kind_from_name(argv[1], &desc.kind))
        return usage();
    if (strcmp(argv[2], "none") != 0 && !(desc.profile = stin_profile_find(argv[2])))
        return usage();
    for (i = 3; i < argc; i++) {
        if (strcmp(argv[i], "--extensions") == 0)
            extensions = 1;
        else if (strcmp(argv[i], "--size") == 0 && i + 1 < argc &&
                 sscanf(argv[i + 1], "%dx%d", &desc.width, &desc.height) == 2)
            i++;
        else
            return usage();
    }
    p = stin_platform_create(&desc, err, sizeof err);
    if (!p) {
        fprintf(stderr, "stin_platform_create: %s\n", err);
        return 1;
    }
    if (!load_gl(p, &g)) {
        fprintf(stderr, "GL 1.1 entry points did not resolve\n");
        stin_platform_destroy(p);
        return 1;
    }
    core = is_core(&g);
    printf("backend: %s  profile: %s  size: %dx%d\n", stin_platform_kind_name(desc.kind),
           desc.profile ? desc.profile->name : "none", stin_platform_width(p),
           stin_platform_height(p));
    printf("GL_RENDERER: %s\n", str(&g, GL_RENDERER));
    printf("GL_VERSION: %s\n", str(&g, GL_VERSION));
    printf("GL_SHADING_LANGUAGE_VERSION: %s\n", str(&g, GL_SHADING_LANGUAGE_VERSION));
    printf("profile: %s\n", g.es ? "es" : core ? "core" : "compatibility");
    printf("stencil bits: %d\n", stencil_bits(&g, core));
    if (extensions)
        print_extensions(&g, core);
    ok = check_clear(p, &g);
    stin_platform_destroy(p);
    printf("%s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
