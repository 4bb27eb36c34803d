/* stin-bench: median frame time of libstin's unshadowed path per tier on the
 * spheres scenes, next to a minimal raw-GL loop drawing the same geometry in
 * the same process, printed as markdown tables (docs/benchmarks.md). */
#include "bench_machine.h"
#include "bench_run.h"
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

typedef struct options {
    const char *platform, *shader_dir;
    char scene_list[2048];
    const char *scenes[MAX_SCENES];
    int scene_count;
    int width, height, frames, warmup, setups, quick, verbose;
    stin_tier tier; /* AUTO: every tier */
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
            "exit codes: 0 ok, 1 failure, 2 bad input, 3 the --tier is unsupported here\n");
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

static int parse_args(int argc, char **argv, options *o)
{
    const char *scenes = NULL;
    int i, frames = 0;
    memset(o, 0, sizeof *o);
    o->platform = "egl";
    o->shader_dir = "shaders";
    o->width = 1280;
    o->height = 720;
    o->warmup = 3;
    o->setups = 5;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            exit(0);
        } else if (!strcmp(a, "--quick")) {
            o->quick = 1;
        } else if (!strcmp(a, "--verbose")) {
            o->verbose = 1;
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
    scene scenes[MAX_SCENES];
    stin_platform_desc pd;
    stin_platform *plat = NULL;
    raw_gl gl;
    bench_settings b;
    stin_caps caps;
    char err[1024];
    worst_ratio worst;
    int loaded = 0, rc = EXIT_FAILED, i, ran = 0;

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

    printf("## stin-bench: %dx%d, %s; per side the lowest of %d set-ups' median of %d frames "
           "(ABBA-interleaved, glFinish per frame, %d warm-up)\n", b.width, b.height,
           stin_platform_kind_name(pd.kind), b.setups, b.frames, b.warmup);
    rc = 0;
    for (i = 0; i < 3 && rc == 0; i++) {
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
        printf("goal stin / raw <= %.2f on every row: %s (worst %.3f, %s)\n", GOAL_RATIO,
               worst.ratio <= GOAL_RATIO ? "met" : "NOT met", worst.ratio, worst.at);
    }
done:
    if (plat)
        stin_platform_destroy(plat);
    for (i = 0; i < loaded; i++)
        scene_free(&scenes[i]);
    return rc;
}
