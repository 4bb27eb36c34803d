/* stin-bench: median frame time of libstin's unshadowed path per tier on the
 * spheres scenes, next to a minimal raw-GL loop drawing the same geometry in
 * the same process, then what stencil shadow volumes cost on top of stin's
 * unshadowed frame, then what the GL1 shadow maps cost at each map size, then
 * what the GLSL tiers' PCF shadow maps cost per map size and kernel, then
 * what each GLSL surface technique costs against plain; printed as markdown
 * tables (docs/benchmarks.md). */
#include "bench_machine.h"
#include "bench_maps.h"
#include "bench_run.h"
#include "bench_shadow.h"
#include "bench_tech.h"
#include "raw_gl.h"
#include "scene.h"
#include "stin/stin.h"
#include "stin_platform.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_FAILED = 1, EXIT_BAD_INPUT = 2, EXIT_UNSUPPORTED = 3 };

#define MAX_SCENES 16
#define GOAL_RATIO 1.15
#define DEFAULT_SCENES                                                                   \
    "tests/scenes/spheres-18k.json,tests/scenes/spheres-76k.json,"                       \
    "tests/scenes/spheres-174k.json"
#define DEFAULT_MAPS_SCENE "tests/scenes/spheres-18k-spot.json"
#define DEFAULT_PCF_SCENE "tests/scenes/spheres-18k-spot.json"
#define DEFAULT_SURFACE_SCENE "tests/scenes/stone-wall.json"
#define PCF_MAX_SIZES 4
#define PCF_MAX_KERNELS 3

/* The sections; --shadows / --maps / --pcf / --surface pick only those named,
 * --no-* drop one. */
enum {
    SECTION_RAW = 1,
    SECTION_SHADOWS = 2,
    SECTION_MAPS = 4,
    SECTION_PCF = 8,
    SECTION_SURFACE = 16
};

typedef struct options {
    const char *platform, *shader_dir;
    char scene_list[2048];
    const char *scenes[MAX_SCENES];
    int scene_count;
    int width, height, frames, warmup, setups, quick, verbose;
    stin_tier tier; /* AUTO: every tier */
    int raw_section, shadow_section, maps_section, pcf_section, surface_section; /* which run */
    int shadow_frames, shadow_setups, small_frames;
    int light_counts[SHADOW_MAX_COUNTS], count_n;
    const char *maps_scene;
    int maps_frames, maps_setups, maps_no_fbo;
    int map_sizes[MAPS_MAX_SIZES], map_size_n;
    const char *pcf_scene, *surface_scene;
    int pcf_frames, pcf_setups, surface_frames, surface_setups;
    int pcf_sizes[PCF_MAX_SIZES], pcf_size_n;
    int pcf_kernels[PCF_MAX_KERNELS], pcf_kernel_n;
} options;

static void usage(FILE *f)
{
    fprintf(f,
            "usage: stin-bench [options]   (run from the repository root)\n"
            "  --tier gl1|gl2|gl4        run one tier (default: every tier the context runs)\n"
            "  --scenes a.json,b.json    scene files (default: the three spheres variants)\n"
            "  --size WxH                framebuffer size (default 1280x720)\n"
            "  --frames N                timed frames per side and set-up (default 30)\n"
            "  --warmup N                untimed frames per side first, per set-up (default 3)\n"
            "  --setups N                fresh stin context + raw loop per scene, each timed;\n"
            "                            the lowest set-up median per side is reported (default 5)\n"
            "  --quick                   smoke run: 5 frames, spheres-18k only\n"
            "  --platform egl|osmesa     context backend (default egl)\n"
            "  --shaders DIR             where gl2/ and gl4/ lie for the raw loop (default shaders)\n"
            "  --verbose                 per-run details and stin's info lines on stderr\n"
            "shadow-volume section (runs after the tables above by default):\n"
            "  --shadows                 run only the shadow-volume section\n"
            "  --no-shadows              skip it (the stin vs raw tables only)\n"
            "  --shadow-lights 1,4,8     point-light counts (1..%d each, at most %d counts)\n"
            "  --shadow-frames N         timed frames per side, set-up and light count (default 7)\n"
            "  --shadow-setups N         fresh context pairs per scene (default 2)\n"
            "  --shadow-small-frames N   timed frames per side at 64x36 (default 7)\n"
            "shadow-map section (gl1; runs after the shadow-volume section by default):\n"
            "  --maps                    run only the shadow-map section (with --shadows: both)\n"
            "  --no-maps                 skip it\n"
            "  --maps-scene FILE         scene with a spot or directional light\n"
            "                            (default " DEFAULT_MAPS_SCENE ")\n"
            "  --maps-sizes 512,1024     map sizes, powers of two 16..8192, at most %d\n"
            "                            (default 512,1024,2048,4096)\n"
            "  --maps-frames N           timed frames per side, set-up and row (default 15)\n"
            "  --maps-setups N           fresh shadows-off context per set-up (default 3)\n"
            "  --maps-no-fbo             hide the FBO capability from stin (maps drawn in the\n"
            "                            frame's framebuffer, at most the viewport's size)\n"
            "PCF shadow-map section (gl2, gl4; runs after the shadow-map section by default):\n"
            "  --pcf                     run only the PCF section (with --shadows, --maps or\n"
            "                            --surface: those too)\n"
            "  --no-pcf                  skip it\n"
            "  --pcf-scene FILE          scene (default " DEFAULT_PCF_SCENE ")\n"
            "  --pcf-sizes 1024,2048     map sizes, powers of two 16..8192, at most %d\n"
            "                            (default 1024,2048,4096)\n"
            "  --pcf-kernels 1,3,5       PCF kernels (1, 3 or 5), at most %d (default 1,3,5)\n"
            "  --pcf-frames N            timed frames per side, set-up and row (default 5)\n"
            "  --pcf-setups N            fresh shadows-off context per set-up (default 2)\n"
            "surface section (gl2, gl4; runs last by default):\n"
            "  --surface                 run only the surface section (with --shadows, --maps or\n"
            "                            --pcf: those too)\n"
            "  --no-surface              skip it\n"
            "  --surface-scene FILE      scene (default " DEFAULT_SURFACE_SCENE ")\n"
            "  --surface-frames N        timed frames per side, set-up and row (default 7)\n"
            "  --surface-setups N        fresh plain context per set-up (default 3)\n"
            "exit codes: 0 ok, 1 failure, 2 bad input, 3 the --tier is unsupported here\n",
            SHADOW_MAX_LIGHTS, SHADOW_MAX_COUNTS, MAPS_MAX_SIZES, PCF_MAX_SIZES,
            PCF_MAX_KERNELS);
}

static int parse_int(const char *s, int lo, int hi, int *out)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (end == s || *end || v < lo || v > hi)
        return 0;
    *out = (int)v;
    return 1;
}

static int split_scenes(options *o, const char *list)
{
    char *tok;
    snprintf(o->scene_list, sizeof o->scene_list, "%s", list);
    o->scene_count = 0;
    for (tok = strtok(o->scene_list, ","); tok; tok = strtok(NULL, ",")) {
        if (o->scene_count == MAX_SCENES) {
            fprintf(stderr, "stin-bench: at most %d scenes\n", MAX_SCENES);
            return 0;
        }
        o->scenes[o->scene_count++] = tok;
    }
    if (!o->scene_count)
        fprintf(stderr, "stin-bench: --scenes names no file\n");
    return o->scene_count > 0;
}

static int parse_light_counts(options *o, const char *v)
{
    char buf[128], *tok;
    snprintf(buf, sizeof buf, "%s", v);
    o->count_n = 0;
    for (tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
        if (o->count_n == SHADOW_MAX_COUNTS ||
            !parse_int(tok, 1, SHADOW_MAX_LIGHTS, &o->light_counts[o->count_n]))
            return 0;
        o->count_n++;
    }
    return o->count_n > 0;
}

static int parse_map_sizes(options *o, const char *v)
{
    char buf[128], *tok;
    snprintf(buf, sizeof buf, "%s", v);
    o->map_size_n = 0;
    for (tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
        int *size = &o->map_sizes[o->map_size_n];
        if (o->map_size_n == MAPS_MAX_SIZES || !parse_int(tok, 16, 8192, size) ||
            (*size & (*size - 1)))
            return 0;
        o->map_size_n++;
    }
    return o->map_size_n > 0;
}

static int parse_pcf_sizes(options *o, const char *v)
{
    char buf[128], *tok;
    snprintf(buf, sizeof buf, "%s", v);
    o->pcf_size_n = 0;
    for (tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
        int *size = &o->pcf_sizes[o->pcf_size_n];
        if (o->pcf_size_n == PCF_MAX_SIZES || !parse_int(tok, 16, 8192, size) ||
            (*size & (*size - 1)))
            return 0;
        o->pcf_size_n++;
    }
    return o->pcf_size_n > 0;
}

static int parse_pcf_kernels(options *o, const char *v)
{
    char buf[128], *tok;
    snprintf(buf, sizeof buf, "%s", v);
    o->pcf_kernel_n = 0;
    for (tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
        int *k = &o->pcf_kernels[o->pcf_kernel_n];
        if (o->pcf_kernel_n == PCF_MAX_KERNELS || !parse_int(tok, 1, 5, k) || !(*k & 1))
            return 0;
        o->pcf_kernel_n++;
    }
    return o->pcf_kernel_n > 0;
}

static int parse_args(int argc, char **argv, options *o)
{
    const char *scenes = NULL;
    int i, frames = 0, shadow_frames = 0, small_frames = 0, shadow_setups = 0;
    int maps_frames = 0, maps_setups = 0, only = 0, skip = 0;
    int pcf_frames = 0, pcf_setups = 0, surface_frames = 0, surface_setups = 0;
    memset(o, 0, sizeof *o);
    o->platform = "egl";
    o->shader_dir = "shaders";
    o->width = 1280;
    o->height = 720;
    o->warmup = 3;
    o->setups = 5;
    o->maps_scene = DEFAULT_MAPS_SCENE;
    o->map_sizes[0] = 512;
    o->map_sizes[1] = 1024;
    o->map_sizes[2] = 2048;
    o->map_sizes[3] = 4096;
    o->map_size_n = 4;
    o->pcf_scene = DEFAULT_PCF_SCENE;
    o->surface_scene = DEFAULT_SURFACE_SCENE;
    o->pcf_sizes[0] = 1024;
    o->pcf_sizes[1] = 2048;
    o->pcf_sizes[2] = 4096;
    o->pcf_size_n = 3;
    o->pcf_kernels[0] = 1;
    o->pcf_kernels[1] = 3;
    o->pcf_kernels[2] = 5;
    o->pcf_kernel_n = 3;
    o->light_counts[0] = 1;
    o->light_counts[1] = 4;
    o->light_counts[2] = 8;
    o->count_n = 3;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            exit(0);
        } else if (!strcmp(a, "--quick")) {
            o->quick = 1;
        } else if (!strcmp(a, "--verbose")) {
            o->verbose = 1;
        } else if (!strcmp(a, "--shadows")) {
            only |= SECTION_SHADOWS;
        } else if (!strcmp(a, "--no-shadows")) {
            skip |= SECTION_SHADOWS;
        } else if (!strcmp(a, "--maps")) {
            only |= SECTION_MAPS;
        } else if (!strcmp(a, "--no-maps")) {
            skip |= SECTION_MAPS;
        } else if (!strcmp(a, "--pcf")) {
            only |= SECTION_PCF;
        } else if (!strcmp(a, "--no-pcf")) {
            skip |= SECTION_PCF;
        } else if (!strcmp(a, "--surface")) {
            only |= SECTION_SURFACE;
        } else if (!strcmp(a, "--no-surface")) {
            skip |= SECTION_SURFACE;
        } else if (!strcmp(a, "--maps-no-fbo")) {
            o->maps_no_fbo = 1;
        } else if (a[0] != '-') {
            fprintf(stderr, "stin-bench: unexpected argument '%s'\n", a);
            return 0;
        } else if (!v) {
            fprintf(stderr, "stin-bench: unknown option %s, or it needs a value\n", a);
            return 0;
        } else if (i++, !strcmp(a, "--tier")) {
            if (!strcmp(v, "gl1")) o->tier = STIN_TIER_GL1;
            else if (!strcmp(v, "gl2")) o->tier = STIN_TIER_GL2;
            else if (!strcmp(v, "gl4")) o->tier = STIN_TIER_GL4;
            else {
                fprintf(stderr, "stin-bench: unknown tier '%s' (gl1, gl2, gl4)\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--scenes")) {
            scenes = v;
        } else if (!strcmp(a, "--size")) {
            char extra;
            if (sscanf(v, "%dx%d%c", &o->width, &o->height, &extra) != 2 || o->width < 1 ||
                o->height < 1 || o->width > 16384 || o->height > 16384) {
                fprintf(stderr, "stin-bench: --size wants WxH with 1..16384, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--frames")) {
            if (!parse_int(v, 1, 100000, &frames)) {
                fprintf(stderr, "stin-bench: --frames wants 1..100000, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--warmup")) {
            if (!parse_int(v, 0, 100000, &o->warmup)) {
                fprintf(stderr, "stin-bench: --warmup wants 0..100000, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--setups")) {
            if (!parse_int(v, 1, 1000, &o->setups)) {
                fprintf(stderr, "stin-bench: --setups wants 1..1000, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--shadow-lights")) {
            if (!parse_light_counts(o, v)) {
                fprintf(stderr, "stin-bench: --shadow-lights wants up to %d counts of 1..%d, "
                        "got '%s'\n", SHADOW_MAX_COUNTS, SHADOW_MAX_LIGHTS, v);
                return 0;
            }
        } else if (!strcmp(a, "--shadow-frames")) {
            if (!parse_int(v, 1, 100000, &shadow_frames)) {
                fprintf(stderr, "stin-bench: --shadow-frames wants 1..100000, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--shadow-small-frames")) {
            if (!parse_int(v, 1, 100000, &small_frames)) {
                fprintf(stderr, "stin-bench: --shadow-small-frames wants 1..100000, got '%s'\n",
                        v);
                return 0;
            }
        } else if (!strcmp(a, "--shadow-setups")) {
            if (!parse_int(v, 1, 1000, &shadow_setups)) {
                fprintf(stderr, "stin-bench: --shadow-setups wants 1..1000, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--maps-scene")) {
            o->maps_scene = v;
        } else if (!strcmp(a, "--maps-sizes")) {
            if (!parse_map_sizes(o, v)) {
                fprintf(stderr, "stin-bench: --maps-sizes wants up to %d powers of two "
                        "16..8192, got '%s'\n", MAPS_MAX_SIZES, v);
                return 0;
            }
        } else if (!strcmp(a, "--maps-frames")) {
            if (!parse_int(v, 1, 100000, &maps_frames)) {
                fprintf(stderr, "stin-bench: --maps-frames wants 1..100000, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--maps-setups")) {
            if (!parse_int(v, 1, 1000, &maps_setups)) {
                fprintf(stderr, "stin-bench: --maps-setups wants 1..1000, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--pcf-scene")) {
            o->pcf_scene = v;
        } else if (!strcmp(a, "--pcf-sizes")) {
            if (!parse_pcf_sizes(o, v)) {
                fprintf(stderr, "stin-bench: --pcf-sizes wants up to %d powers of two "
                        "16..8192, got '%s'\n", PCF_MAX_SIZES, v);
                return 0;
            }
        } else if (!strcmp(a, "--pcf-kernels")) {
            if (!parse_pcf_kernels(o, v)) {
                fprintf(stderr, "stin-bench: --pcf-kernels wants up to %d of 1, 3, 5, got "
                        "'%s'\n", PCF_MAX_KERNELS, v);
                return 0;
            }
        } else if (!strcmp(a, "--pcf-frames")) {
            if (!parse_int(v, 1, 100000, &pcf_frames)) {
                fprintf(stderr, "stin-bench: --pcf-frames wants 1..100000, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--pcf-setups")) {
            if (!parse_int(v, 1, 1000, &pcf_setups)) {
                fprintf(stderr, "stin-bench: --pcf-setups wants 1..1000, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--surface-scene")) {
            o->surface_scene = v;
        } else if (!strcmp(a, "--surface-frames")) {
            if (!parse_int(v, 1, 100000, &surface_frames)) {
                fprintf(stderr, "stin-bench: --surface-frames wants 1..100000, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--surface-setups")) {
            if (!parse_int(v, 1, 1000, &surface_setups)) {
                fprintf(stderr, "stin-bench: --surface-setups wants 1..1000, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--platform")) {
            o->platform = v;
        } else if (!strcmp(a, "--shaders")) {
            o->shader_dir = v;
        } else {
            fprintf(stderr, "stin-bench: unknown option %s\n", a);
            return 0;
        }
    }
    /* --quick sets defaults; explicit --frames/--scenes still win. */
    o->frames = frames ? frames : o->quick ? 5 : 30;
    o->shadow_frames = shadow_frames ? shadow_frames : o->quick ? 3 : 7;
    o->small_frames = small_frames ? small_frames : o->quick ? 3 : 7;
    o->shadow_setups = shadow_setups ? shadow_setups : o->quick ? 1 : 2;
    o->maps_frames = maps_frames ? maps_frames : o->quick ? 3 : 15;
    o->maps_setups = maps_setups ? maps_setups : o->quick ? 1 : 3;
    o->pcf_frames = pcf_frames ? pcf_frames : o->quick ? 3 : 5;
    o->pcf_setups = pcf_setups ? pcf_setups : o->quick ? 1 : 2;
    o->surface_frames = surface_frames ? surface_frames : o->quick ? 3 : 7;
    o->surface_setups = surface_setups ? surface_setups : o->quick ? 1 : 3;
    only = only ? only
                : SECTION_RAW | SECTION_SHADOWS | SECTION_MAPS | SECTION_PCF | SECTION_SURFACE;
    o->raw_section = !!(only & ~skip & SECTION_RAW);
    o->shadow_section = !!(only & ~skip & SECTION_SHADOWS);
    o->maps_section = !!(only & ~skip & SECTION_MAPS);
    o->pcf_section = !!(only & ~skip & SECTION_PCF);
    o->surface_section = !!(only & ~skip & SECTION_SURFACE);
    if (!scenes)
        scenes = o->quick ? "tests/scenes/spheres-18k.json" : DEFAULT_SCENES;
    return split_scenes(o, scenes);
}

/* "tests/scenes/spheres-18k.json" -> "spheres-18k" */
static void scene_label(const char *path, char *out, size_t size)
{
    const char *base = strrchr(path, '/');
    size_t n;
    base = base ? base + 1 : path;
    n = strcspn(base, ".");
    snprintf(out, size, "%.*s", (int)n, base);
}

static const char *tier_label(stin_tier t)
{
    return t == STIN_TIER_GL1 ? "fixed-function, per-vertex lighting"
         : t == STIN_TIER_GL2 ? "GLSL 1.10, per-pixel lighting"
                              : "GLSL 1.50 + VAOs, per-pixel lighting";
}

/* The largest ratio over every row, for the closing goal line. */
typedef struct worst_ratio {
    double ratio;
    char at[160];
} worst_ratio;

/* Runs one tier over every scene and prints its table. Returns 0 on failure. */
static int bench_tier(const bench_settings *b, stin_tier tier, scene *scenes, int n,
                      const options *o, worst_ratio *w)
{
    int i;
    printf("\n### %s (%s)\n\n", stin_tier_name(tier), tier_label(tier));
    printf("| scene | triangles | stin median ms | raw median ms | stin / raw |\n");
    printf("|---|---:|---:|---:|---:|\n");
    fflush(stdout);
    for (i = 0; i < n; i++) {
        bench_result r;
        char err[1024], label[128];
        double ratio;
        scene_label(o->scenes[i], label, sizeof label);
        fprintf(stderr, "stin-bench: %s %s ...\n", stin_tier_name(tier), label);
        if (!bench_run(b, tier, &scenes[i], &r, err, sizeof err)) {
            fprintf(stderr, "stin-bench: %s, %s: %s\n", stin_tier_name(tier), label, err);
            return 0;
        }
        ratio = r.raw_ms > 0 ? r.stin_ms / r.raw_ms : 0.0;
        if (ratio > w->ratio) {
            w->ratio = ratio;
            snprintf(w->at, sizeof w->at, "%s %s", stin_tier_name(tier), label);
        }
        printf("| %s | %llu | %.2f | %.2f | %.3f |\n", label, (unsigned long long)r.triangles,
               r.stin_ms, r.raw_ms, ratio);
        fflush(stdout);
    }
    return 1;
}

/* ---- shadow volumes ----------------------------------------------------- */

typedef struct shadow_table {
    shadow_row rows[3][MAX_SCENES][SHADOW_MAX_COUNTS]; /* tier index, scene, count */
    uint64_t triangles[MAX_SCENES];
    int ran[3];
    double worst, best;
    char worst_at[160], best_at[160];
} shadow_table;

static int shadow_tier(const shadow_settings *st, int ti, stin_tier tier, scene *scenes, int n,
                       const options *o, shadow_table *t)
{
    int i, c;
    printf("\n### shadows, %s (%s)\n\n", stin_tier_name(tier), tier_label(tier));
    printf("| scene | lights | volume triangles / frame | z-pass / z-fail casters | "
           "off median ms | volume median ms | volume / off |\n");
    printf("|---|---:|---:|---:|---:|---:|---:|\n");
    fflush(stdout);
    for (i = 0; i < n; i++) {
        char err[1024], label[128];
        shadow_row *rows = t->rows[ti][i];
        scene_label(o->scenes[i], label, sizeof label);
        fprintf(stderr, "stin-bench: shadows %s %s ...\n", stin_tier_name(tier), label);
        if (!bench_shadow_run(st, tier, &scenes[i], rows, err, sizeof err)) {
            fprintf(stderr, "stin-bench: shadows, %s, %s: %s\n", stin_tier_name(tier), label,
                    err);
            return 0;
        }
        t->triangles[i] = scene_triangle_count(&scenes[i]);
        for (c = 0; c < st->count_n; c++) {
            const shadow_row *r = &rows[c];
            double ratio = r->off_ms > 0 ? r->vol_ms / r->off_ms : 0.0;
            if (ratio > t->worst || !t->worst_at[0]) {
                t->worst = ratio;
                snprintf(t->worst_at, sizeof t->worst_at, "%s %s, %d light(s)",
                         stin_tier_name(tier), label, r->lights);
            }
            if (ratio < t->best || !t->best_at[0]) {
                t->best = ratio;
                snprintf(t->best_at, sizeof t->best_at, "%s %s, %d light(s)",
                         stin_tier_name(tier), label, r->lights);
            }
            printf("| %s | %d | %u | %u / %u | %.2f | %.2f | %.2f |\n", label, r->lights,
                   r->volume_triangles, r->zpass_casters, r->zfail_casters, r->off_ms, r->vol_ms,
                   ratio);
        }
        fflush(stdout);
    }
    t->ran[ti] = 1;
    return 1;
}

/* The CPU estimate of volume building, one row per tier, scene and count. */
static void shadow_cpu_table(const shadow_settings *st, const shadow_table *t, const options *o)
{
    static const stin_tier all[] = {STIN_TIER_GL1, STIN_TIER_GL2, STIN_TIER_GL4};
    int ti, i, c;
    printf("\n### shadows: stin_end_frame at %dx%d (volume building on the CPU)\n\n", st->small_w,
           st->small_h);
    printf("| tier | scene | lights | volume triangles / frame | end_frame off / volume ms | "
           "difference ms | outside GL draws off / volume ms | difference ms | "
           "ns per scene triangle and light | ns per volume triangle |\n");
    printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (ti = 0; ti < 3; ti++) {
        if (!t->ran[ti])
            continue;
        for (i = 0; i < o->scene_count; i++) {
            char label[128];
            scene_label(o->scenes[i], label, sizeof label);
            for (c = 0; c < st->count_n; c++) {
                const shadow_row *r = &t->rows[ti][i][c];
                double cpu = r->vol_cpu_ms - r->off_cpu_ms;
                double per_tri = t->triangles[i] ? 1e6 * cpu / ((double)t->triangles[i] *
                                                                (double)r->lights) : 0.0;
                double per_vol = r->volume_triangles ? 1e6 * cpu / (double)r->volume_triangles
                                                     : 0.0;
                printf("| %s | %s | %d | %u | %.3f / %.3f | %.3f | %.3f / %.3f | %.3f | %.2f | "
                       "%.1f |\n", stin_tier_name(all[ti]), label, r->lights,
                       r->volume_triangles, r->off_end_ms, r->vol_end_ms,
                       r->vol_end_ms - r->off_end_ms, r->off_cpu_ms, r->vol_cpu_ms, cpu, per_tri,
                       per_vol);
            }
        }
    }
    fflush(stdout);
}

static int run_shadows(const bench_settings *b, const stin_caps *caps, scene *scenes,
                       const options *o, int *ran)
{
    static const stin_tier all[] = {STIN_TIER_GL1, STIN_TIER_GL2, STIN_TIER_GL4};
    shadow_settings st;
    shadow_table *t = calloc(1, sizeof *t);
    int i, rc = 0, any = 0;
    char counts[64] = "";
    if (!t) {
        fprintf(stderr, "stin-bench: out of memory\n");
        return EXIT_FAILED;
    }
    memset(&st, 0, sizeof st);
    st.b = b;
    st.frames = o->shadow_frames;
    st.setups = o->shadow_setups;
    st.small_w = 64;
    st.small_h = 36;
    st.small_frames = o->small_frames;
    st.count_n = o->count_n;
    for (i = 0; i < o->count_n; i++) {
        size_t len = strlen(counts);
        st.light_counts[i] = o->light_counts[i];
        snprintf(counts + len, sizeof counts - len, "%s%d", i ? ", " : "", o->light_counts[i]);
    }
    printf("\n## Shadow volumes: %dx%d, %s point light(s); per side the lowest of %d set-ups' "
           "median of %d frames (ABBA-interleaved, glFinish per frame, %d warm-up, 1 per later "
           "light count); stin_end_frame alone at %dx%d: %d frames\n",
           b->width, b->height, counts, st.setups, st.frames, b->warmup > 1 ? b->warmup : 1,
           st.small_w, st.small_h, st.small_frames);
    for (i = 0; i < 3 && rc == 0; i++) {
        char missing[512];
        if (o->tier != STIN_TIER_AUTO && o->tier != all[i])
            continue;
        if (!stin_tier_supported(caps, all[i], missing, sizeof missing)) {
            printf("\n### shadows, %s: SKIP (the context lacks %s)\n", stin_tier_name(all[i]),
                   missing);
            if (o->tier != STIN_TIER_AUTO)
                rc = EXIT_UNSUPPORTED;
            continue;
        }
        if (!(caps->present & STIN_CAP_BIT(STIN_CAP_STENCIL))) {
            printf("\n### shadows, %s: SKIP (no stencil buffer)\n", stin_tier_name(all[i]));
            continue;
        }
        if (!shadow_tier(&st, i, all[i], scenes, o->scene_count, o, t))
            rc = EXIT_FAILED;
        else
            any = 1;
    }
    if (rc == 0 && any) {
        shadow_cpu_table(&st, t, o);
        printf("\nshadow volumes / shadows off: from %.2f (%s) to %.2f (%s)\n", t->best,
               t->best_at, t->worst, t->worst_at);
        ++*ran;
    }
    free(t);
    return rc;
}

/* ---- shadow maps --------------------------------------------------------- */

static int run_maps(const bench_settings *b, const stin_caps *caps, const scene *s,
                    const options *o, int *ran)
{
    maps_settings st;
    maps_row rows[MAPS_MAX_ROWS];
    char err[1024], label[128], missing[512];
    const maps_row *best = NULL, *worst = NULL, *vol = NULL;
    int i, row_n = 0;
    memset(&st, 0, sizeof st);
    st.b = b;
    st.frames = o->maps_frames;
    st.setups = o->maps_setups;
    st.size_n = o->map_size_n;
    for (i = 0; i < o->map_size_n; i++)
        st.sizes[i] = o->map_sizes[i];
    st.caps_mask = o->maps_no_fbo ? STIN_CAP_BIT(STIN_CAP_FBO) : 0;
    scene_label(o->maps_scene, label, sizeof label);
    printf("\n## Shadow maps (gl1, %s): %s, %dx%d, the scene's %d light(s)%s; per side the "
           "lowest of %d set-ups' median of %d frames (ABBA-interleaved, glFinish per frame, "
           "%d warm-up per row)\n", tier_label(STIN_TIER_GL1), label, b->width, b->height,
           s->light_count, o->maps_no_fbo ? ", FBO hidden from stin" : "", st.setups, st.frames,
           b->warmup > 1 ? b->warmup : 1);
    if (o->tier != STIN_TIER_AUTO && o->tier != STIN_TIER_GL1) {
        printf("\n### shadow maps: SKIP (the map techniques are gl1 only; --tier %s)\n",
               stin_tier_name(o->tier));
        return 0;
    }
    if (!stin_tier_supported(caps, STIN_TIER_GL1, missing, sizeof missing)) {
        printf("\n### shadow maps: SKIP (the context lacks %s)\n", missing);
        return o->tier != STIN_TIER_AUTO ? EXIT_UNSUPPORTED : 0;
    }
    fprintf(stderr, "stin-bench: shadow maps gl1 %s ...\n", label);
    fflush(stdout);
    if (!bench_maps_run(&st, s, rows, &row_n, err, sizeof err)) {
        fprintf(stderr, "stin-bench: shadow maps, gl1, %s: %s\n", label, err);
        return EXIT_FAILED;
    }
    printf("\n| shadows | map size asked | map size rendered | passes | off median ms | "
           "shadowed median ms | shadowed / off |\n");
    printf("|---|---:|---:|---:|---:|---:|---:|\n");
    for (i = 0; i < row_n; i++) {
        const maps_row *r = &rows[i];
        int is_vol = r->technique == STIN_TECH_SHADOWS_VOLUME;
        char asked[32], rendered[48];
        if (is_vol) {
            snprintf(asked, sizeof asked, "-");
            snprintf(rendered, sizeof rendered, "- (%u volume triangles)", r->volume_triangles);
        } else {
            snprintf(asked, sizeof asked, "%u", r->requested);
            snprintf(rendered, sizeof rendered, "%u", r->rendered);
        }
        if (r->skipped) {
            printf("| %s | %s | SKIP: %s | | | | |\n", stin_technique_name(r->technique), asked,
                   r->why);
            continue;
        }
        printf("| %s | %s | %s | %u | %.2f | %.2f | %.2f |\n", stin_technique_name(r->technique),
               asked, rendered, r->passes, r->off_ms, r->on_ms,
               r->off_ms > 0 ? r->on_ms / r->off_ms : 0.0);
        if (is_vol) {
            vol = r;
        } else {
            if (!best || r->on_ms / r->off_ms < best->on_ms / best->off_ms)
                best = r;
            if (!worst || r->on_ms / r->off_ms > worst->on_ms / worst->off_ms)
                worst = r;
        }
    }
    if (best && worst)
        printf("\nshadow maps / shadows off: from %.2f (%s %u) to %.2f (%s %u)",
               best->on_ms / best->off_ms, stin_technique_name(best->technique), best->rendered,
               worst->on_ms / worst->off_ms, stin_technique_name(worst->technique),
               worst->rendered);
    if (vol)
        printf("%sshadow volumes / shadows off: %.2f", best && worst ? "; " : "\n",
               vol->on_ms / vol->off_ms);
    printf("\n");
    fflush(stdout);
    ++*ran;
    return 0;
}

/* ---- PCF shadow maps and surface techniques (gl2, gl4) ------------------ */

/* The GLSL tiers a technique section runs: gl2 and gl4, or the --tier one.
 * 0 and a SKIP line when --tier names gl1. */
static int glsl_tiers(const options *o, const char *what, stin_tier *out)
{
    if (o->tier == STIN_TIER_GL1) {
        printf("\n### %s: SKIP (gl2 and gl4 only; --tier gl1)\n", what);
        return 0;
    }
    if (o->tier != STIN_TIER_AUTO) {
        out[0] = o->tier;
        return 1;
    }
    out[0] = STIN_TIER_GL2;
    out[1] = STIN_TIER_GL4;
    return 2;
}

/* Runs st over rows on one tier; prints a SKIP line and returns 0 or
 * EXIT_UNSUPPORTED where the context lacks the tier, EXIT_FAILED on failure,
 * -1 when it ran. */
static int tech_tier(tech_settings *st, stin_tier tier, const stin_caps *caps, const options *o,
                     const char *what, const scene *s, tech_row *rows, int row_n)
{
    char missing[512], err[1024], label[128];
    if (!stin_tier_supported(caps, tier, missing, sizeof missing)) {
        printf("\n### %s, %s: SKIP (the context lacks %s)\n", what, stin_tier_name(tier),
               missing);
        return o->tier != STIN_TIER_AUTO ? EXIT_UNSUPPORTED : 0;
    }
    scene_label(s->path, label, sizeof label);
    st->tier = tier;
    fprintf(stderr, "stin-bench: %s %s %s ...\n", what, stin_tier_name(tier), label);
    fflush(stdout);
    if (!bench_tech_run(st, s, rows, row_n, err, sizeof err)) {
        fprintf(stderr, "stin-bench: %s, %s, %s: %s\n", what, stin_tier_name(tier), label, err);
        return EXIT_FAILED;
    }
    return -1;
}

static double row_ratio(const tech_row *r)
{
    return r->base_ms > 0 ? r->on_ms / r->base_ms : 0.0;
}

static int run_pcf(const bench_settings *b, const stin_caps *caps, const scene *s,
                   const options *o, int *ran)
{
    static tech_row rows[2][TECH_MAX_ROWS];
    stin_tier tiers[2];
    tech_settings st;
    char label[128];
    const tech_row *best = NULL, *worst = NULL;
    stin_tier best_tier = STIN_TIER_AUTO, worst_tier = STIN_TIER_AUTO;
    int tier_n, t, i, k, row_n = 0, rc, done[2] = {0, 0}, any = 0;
    memset(&st, 0, sizeof st);
    st.b = b;
    st.frames = o->pcf_frames;
    st.setups = o->pcf_setups;
    st.base.shadows = STIN_TECH_SHADOWS_OFF;
    st.base.surface = STIN_TECH_NONE;
    scene_label(o->pcf_scene, label, sizeof label);
    printf("\n## PCF shadow maps (map-pcf, gl2/gl4): %s, %dx%d, the scene's %d light(s); per "
           "side the lowest of %d set-ups' median of %d frames (ABBA-interleaved, glFinish per "
           "frame, %d warm-up per row)\n", label, b->width, b->height, s->light_count,
           st.setups, st.frames, b->warmup > 1 ? b->warmup : 1);
    if (!(tier_n = glsl_tiers(o, "PCF shadow maps", tiers)))
        return 0;
    for (t = 0; t < tier_n; t++) {
        for (row_n = 0, i = 0; i < o->pcf_size_n; i++)
            for (k = 0; k < o->pcf_kernel_n; k++, row_n++) {
                tech_config *c = &rows[t][row_n].cfg;
                c->shadows = STIN_TECH_SHADOWS_MAP_PCF;
                c->surface = STIN_TECH_NONE;
                c->map_size = (uint32_t)o->pcf_sizes[i];
                c->pcf_kernel = o->pcf_kernels[k];
            }
        rc = tech_tier(&st, tiers[t], caps, o, "PCF shadow maps", s, rows[t], row_n);
        if (rc >= 0) {
            if (rc)
                return rc;
            continue;
        }
        done[t] = 1;
        any = 1;
        printf("\n### PCF shadow maps, %s (%s)\n\n", stin_tier_name(tiers[t]),
               tier_label(tiers[t]));
        printf("| map size asked | map size rendered | kernel | passes | off median ms | "
               "map-pcf median ms | map-pcf / off |\n");
        printf("|---:|---:|---:|---:|---:|---:|---:|\n");
        for (i = 0; i < row_n; i++) {
            const tech_row *r = &rows[t][i];
            if (r->skipped) {
                printf("| %u | SKIP: %s | %d | | | | |\n", r->cfg.map_size, r->why,
                       r->cfg.pcf_kernel);
                continue;
            }
            printf("| %u | %u | %d | %u | %.2f | %.2f | %.2f |\n", r->cfg.map_size, r->rendered,
                   r->cfg.pcf_kernel, r->passes, r->base_ms, r->on_ms, row_ratio(r));
            if (!best || row_ratio(r) < row_ratio(best))
                best = r, best_tier = tiers[t];
            if (!worst || row_ratio(r) > row_ratio(worst))
                worst = r, worst_tier = tiers[t];
        }
        fflush(stdout);
    }
    if (!any)
        return 0;
    /* the ratios again as one grid: a line per tier and map size, a column per kernel */
    printf("\n### PCF shadow maps: map-pcf / off\n\n| tier | map size |");
    for (k = 0; k < o->pcf_kernel_n; k++)
        printf(" kernel %d |", o->pcf_kernels[k]);
    printf("\n|---|---:|");
    for (k = 0; k < o->pcf_kernel_n; k++)
        printf("---:|");
    printf("\n");
    for (t = 0; t < tier_n; t++) {
        if (!done[t])
            continue;
        for (i = 0; i < o->pcf_size_n; i++) {
            printf("| %s | %d |", stin_tier_name(tiers[t]), o->pcf_sizes[i]);
            for (k = 0; k < o->pcf_kernel_n; k++) {
                const tech_row *r = &rows[t][i * o->pcf_kernel_n + k];
                if (r->skipped)
                    printf(" SKIP |");
                else
                    printf(" %.2f |", row_ratio(r));
            }
            printf("\n");
        }
    }
    if (best && worst)
        printf("\nmap-pcf / shadows off: from %.2f (%s %u, kernel %d) to %.2f (%s %u, kernel "
               "%d)\n", row_ratio(best), stin_tier_name(best_tier), best->rendered,
               best->cfg.pcf_kernel, row_ratio(worst), stin_tier_name(worst_tier),
               worst->rendered, worst->cfg.pcf_kernel);
    fflush(stdout);
    ++*ran;
    return 0;
}

static int run_surface(const bench_settings *b, const stin_caps *caps, const scene *s,
                       const options *o, int *ran)
{
    static const stin_technique surfaces[] = {STIN_TECH_SURFACE_PLAIN, STIN_TECH_SURFACE_NORMAL,
                                              STIN_TECH_SURFACE_PARALLAX,
                                              STIN_TECH_SURFACE_POM};
    enum { N = sizeof surfaces / sizeof surfaces[0] };
    tech_row rows[2][N];
    stin_tier tiers[2];
    tech_settings st;
    char label[128];
    int tier_n, t, i, rc, any = 0;
    memset(&st, 0, sizeof st);
    memset(rows, 0, sizeof rows);
    st.b = b;
    st.frames = o->surface_frames;
    st.setups = o->surface_setups;
    st.base.shadows = STIN_TECH_SHADOWS_OFF;
    st.base.surface = STIN_TECH_SURFACE_PLAIN;
    scene_label(o->surface_scene, label, sizeof label);
    printf("\n## Surface techniques (gl2/gl4, shadows off): %s, %dx%d; per side the lowest of "
           "%d set-ups' median of %d frames (ABBA-interleaved, glFinish per frame, %d warm-up "
           "per row); the plain row is a second plain context against the first\n", label,
           b->width, b->height, st.setups, st.frames, b->warmup > 1 ? b->warmup : 1);
    if (!(tier_n = glsl_tiers(o, "surface techniques", tiers)))
        return 0;
    for (t = 0; t < tier_n; t++) {
        const tech_row *worst = NULL;
        for (i = 0; i < N; i++) {
            rows[t][i].cfg.shadows = STIN_TECH_SHADOWS_OFF;
            rows[t][i].cfg.surface = surfaces[i];
        }
        rc = tech_tier(&st, tiers[t], caps, o, "surface techniques", s, rows[t], N);
        if (rc >= 0) {
            if (rc)
                return rc;
            continue;
        }
        any = 1;
        printf("\n### surface techniques, %s (%s)\n\n", stin_tier_name(tiers[t]),
               tier_label(tiers[t]));
        printf("| surface | passes | plain median ms | surface median ms | surface / plain |\n");
        printf("|---|---:|---:|---:|---:|\n");
        for (i = 0; i < N; i++) {
            const tech_row *r = &rows[t][i];
            if (r->skipped) {
                printf("| %s | SKIP: %s | | | |\n", stin_technique_name(r->cfg.surface), r->why);
                continue;
            }
            printf("| %s | %u | %.2f | %.2f | %.2f |\n", stin_technique_name(r->cfg.surface),
                   r->passes, r->base_ms, r->on_ms, row_ratio(r));
            if (!worst || row_ratio(r) > row_ratio(worst))
                worst = r;
        }
        if (worst)
            printf("\n%s: surface / plain at most %.2f (%s)\n", stin_tier_name(tiers[t]),
                   row_ratio(worst), stin_technique_name(worst->cfg.surface));
        fflush(stdout);
    }
    if (any)
        ++*ran;
    return 0;
}

static void print_machine(const raw_gl *gl)
{
    char cpu[256];
    const GLubyte *renderer = gl->GetString(GL_RENDERER), *version = gl->GetString(GL_VERSION);
    bench_cpu_model(cpu, sizeof cpu);
    printf("\nmachine: %s; GL %s; CPU %s, %d logical cores\n",
           renderer ? (const char *)renderer : "unknown renderer",
           version ? (const char *)version : "unknown", cpu, bench_cpu_count());
}

int main(int argc, char **argv)
{
    static const stin_tier all[] = {STIN_TIER_GL1, STIN_TIER_GL2, STIN_TIER_GL4};
    options o;
    scene scenes[MAX_SCENES], maps_scene, pcf_scene, surface_scene;
    stin_platform_desc pd;
    stin_platform *plat = NULL;
    raw_gl gl;
    bench_settings b;
    stin_caps caps;
    char err[1024];
    worst_ratio worst;
    int loaded = 0, rc = EXIT_FAILED, i, ran = 0, maps_loaded = 0, machine_printed = 0;
    int pcf_loaded = 0, surface_loaded = 0;

    if (!parse_args(argc, argv, &o)) {
        usage(stderr);
        return EXIT_BAD_INPUT;
    }
    memset(&pd, 0, sizeof pd);
    if (!stin_platform_kind_from_name(o.platform, &pd.kind)) {
        fprintf(stderr, "stin-bench: unknown platform '%s' (egl, osmesa)\n", o.platform);
        return EXIT_BAD_INPUT;
    }
    for (loaded = 0; loaded < o.scene_count; loaded++)
        if (!scene_load(o.scenes[loaded], &scenes[loaded], err, sizeof err)) {
            fprintf(stderr, "stin-bench: %s\n", err);
            rc = EXIT_BAD_INPUT;
            goto done;
        }
    if (o.maps_section) {
        if (!scene_load(o.maps_scene, &maps_scene, err, sizeof err)) {
            fprintf(stderr, "stin-bench: %s\n", err);
            rc = EXIT_BAD_INPUT;
            goto done;
        }
        maps_loaded = 1;
    }
    if (o.pcf_section) {
        if (!scene_load(o.pcf_scene, &pcf_scene, err, sizeof err)) {
            fprintf(stderr, "stin-bench: %s\n", err);
            rc = EXIT_BAD_INPUT;
            goto done;
        }
        pcf_loaded = 1;
    }
    if (o.surface_section) {
        if (!scene_load(o.surface_scene, &surface_scene, err, sizeof err)) {
            fprintf(stderr, "stin-bench: %s\n", err);
            rc = EXIT_BAD_INPUT;
            goto done;
        }
        surface_loaded = 1;
    }
    /* The default (NULL profile) compatibility context runs all three tiers. */
    pd.width = o.width;
    pd.height = o.height;
    if (!(plat = stin_platform_create(&pd, err, sizeof err))) {
        fprintf(stderr, "stin-bench: no GL context: %s\n", err);
        goto done;
    }
    raw_gl_load(&gl, stin_platform_get_proc_address, plat);
    if (raw_gl_missing(&gl, RAW_NEED_CORE)) {
        fprintf(stderr, "stin-bench: %s did not load\n", raw_gl_missing(&gl, RAW_NEED_CORE));
        goto done;
    }
    if (stin_detect_caps(stin_platform_get_proc_address, plat, 0, 0, &caps) != STIN_OK) {
        fprintf(stderr, "stin-bench: cannot read GL capabilities\n");
        goto done;
    }
    memset(&b, 0, sizeof b);
    memset(&worst, 0, sizeof worst);
    b.plat = plat;
    b.gl = &gl;
    b.width = stin_platform_width(plat);
    b.height = stin_platform_height(plat);
    b.frames = o.frames;
    b.warmup = o.warmup;
    b.setups = o.setups;
    b.verbose = o.verbose;
    b.shader_dir = o.shader_dir;

    rc = 0;
    if (o.raw_section)
        printf("## stin-bench: %dx%d, %s; per side the lowest of %d set-ups' median of %d frames "
               "(ABBA-interleaved, glFinish per frame, %d warm-up)\n", b.width, b.height,
               stin_platform_kind_name(pd.kind), b.setups, b.frames, b.warmup);
    for (i = 0; i < 3 && rc == 0 && o.raw_section; i++) {
        char missing[512];
        if (o.tier != STIN_TIER_AUTO && o.tier != all[i])
            continue;
        if (!stin_tier_supported(&caps, all[i], missing, sizeof missing)) {
            printf("\n### %s: SKIP (the context lacks %s)\n", stin_tier_name(all[i]), missing);
            if (o.tier != STIN_TIER_AUTO)
                rc = EXIT_UNSUPPORTED;
            continue;
        }
        if (!bench_tier(&b, all[i], scenes, o.scene_count, &o, &worst))
            rc = EXIT_FAILED;
        else
            ran++;
    }
    if (rc == 0 && ran) {
        print_machine(&gl);
        machine_printed = 1;
        printf("goal stin / raw <= %.2f on every row: %s (worst %.3f, %s)\n", GOAL_RATIO,
               worst.ratio <= GOAL_RATIO ? "met" : "NOT met", worst.ratio, worst.at);
    }
    if (rc == 0 && o.shadow_section) {
        int shadow_ran = 0;
        rc = run_shadows(&b, &caps, scenes, &o, &shadow_ran);
        if (rc == 0 && shadow_ran && !machine_printed) {
            print_machine(&gl);
            machine_printed = 1;
        }
    }
    if (rc == 0 && o.maps_section) {
        int maps_ran = 0;
        rc = run_maps(&b, &caps, &maps_scene, &o, &maps_ran);
        if (rc == 0 && maps_ran && !machine_printed) {
            print_machine(&gl);
            machine_printed = 1;
        }
    }
    if (rc == 0 && o.pcf_section) {
        int pcf_ran = 0;
        rc = run_pcf(&b, &caps, &pcf_scene, &o, &pcf_ran);
        if (rc == 0 && pcf_ran && !machine_printed) {
            print_machine(&gl);
            machine_printed = 1;
        }
    }
    if (rc == 0 && o.surface_section) {
        int surface_ran = 0;
        rc = run_surface(&b, &caps, &surface_scene, &o, &surface_ran);
        if (rc == 0 && surface_ran && !machine_printed)
            print_machine(&gl);
    }
done:
    if (plat)
        stin_platform_destroy(plat);
    for (i = 0; i < loaded; i++)
        scene_free(&scenes[i]);
    if (maps_loaded)
        scene_free(&maps_scene);
    if (pcf_loaded)
        scene_free(&pcf_scene);
    if (surface_loaded)
        scene_free(&surface_scene);
    return rc;
}
