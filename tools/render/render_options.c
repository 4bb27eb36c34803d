/* SPDX-License-Identifier: MIT */
/* stin-render's options: parsing and the usage text. */
#include "render_options.h"
#include "render_debug.h"
#include "stin_platform.h"
#include "technique_option.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void render_usage(FILE *f)
{
    fprintf(f,
            "usage: stin-render SCENE.json -o OUT.png|OUT.exr [options]\n"
            "       stin-render SCENE.json --no-output [options]   render, print statistics only\n"
            "       stin-render SCENE.json... --no-output [options]  several scenes in one process,\n"
            "                            each in its own context, a line \"scene FILE: exit N\" after\n"
            "                            each; exits with the highest code\n"
            "  --tier auto|gl1|gl2|gl4   force a tier (error if the context cannot run it)\n"
            "  --profile NAME            capability profile (see docs/profiles.md):");
    {
        size_t i;
        for (i = 0; i < stin_profile_count(); i++)
            fprintf(f, " %s", stin_profile_at(i)->name);
    }
    fprintf(f, "\n"
               "  --platform egl|osmesa     context backend (default egl)\n"
               "  --size WxH                image size (default: the scene's, else 512x512)\n"
               "  --samples N               render into a multisampled target of N samples (1, 2,\n"
               "                            4, 8, 16; default 1: single-sampled); exit 3 where the\n"
               "                            context has no such target\n"
               "  --srgb                    render into an sRGB colour target (GL encodes, stin\n"
               "                            lights in linear): the PNG gets its bytes as stored,\n"
               "                            the EXR their decoded linear values; exit 3 where\n"
               "                            the context has no such target\n"
               "  --shadows NAME            shadow technique: vdsm (GL4), volume, map-pcf (GLSL tiers), map (map-depth where the\n"
               "                            context has ARB_shadow, else map-combine), map-depth,\n"
               "                            map-combine, shadows-off or off (default auto)\n"
               "  --surface NAME            surface technique, or displace: materials with a\n"
               "                            height map displaced by it (default auto)\n"
               "  --csg NAME                CSG technique for the scene's csg list: scs, goldfeather,\n"
               "                            interval (GL4), csg-off or off (default auto)\n"
               "  --shadow-map-size N       texels a side of each shadow map: a power of two, 16..8192\n"
               "                            (default: the scene's shadow_map_size, else 1024)\n"
               "  --max-triangles N         work limit: triangles one frame may draw, instances x\n"
               "                            triangles (default %u; 0 = no limit)\n"
               "  --volume-mode auto|zpass|zfail|facets  shadow-volume counting, or facets\n"
               "                            at the terminator (diagnostics)\n"
               "  --debug shadow-map|volumes|masks  (repeatable) pictures of the shadows' parts:\n"
               "                            OUT-shadow-map-I.png per spot/directional light's map,\n"
               "                            the volumes added over the beauty in orange,\n"
               "                            OUT-masks.png with every light's visibility\n"
               "  --frame                   fit the camera to the scene's bounds (its direction kept;\n"
               "                            automatic when the scene has no camera)\n"
               "  --outline N               a black outline (GLSL tiers): silhouettes, creases and\n"
               "                            depth steps, the filter's taps N pixels apart (0..64)\n"
               "  --stage-times             print the frame's GPU time per stage (timer queries;\n"
               "                            the frame waits for the GPU at its end)\n"
               "  --caps                    print capabilities and choices, render nothing\n"
               "  --verbose                 print stin's info log lines\n"
               "  --version                 print the versions of stin-render and libstin\n"
               "  --progress                progress lines on stderr (default: when it is a terminal)\n"
               "exit codes: 0 ok, 1 failure, 2 bad input, 3 tier/technique unsupported here\n",
            RENDER_MAX_TRIANGLES_DEFAULT);
}

static int parse_tier(const char *s, stin_tier *t)
{
    if (!strcmp(s, "auto")) *t = STIN_TIER_AUTO;
    else if (!strcmp(s, "gl1")) *t = STIN_TIER_GL1;
    else if (!strcmp(s, "gl2")) *t = STIN_TIER_GL2;
    else if (!strcmp(s, "gl4")) *t = STIN_TIER_GL4;
    else return 0;
    return 1;
}

/* A whole decimal number, nothing after it. */
static int parse_count(const char *s, uint64_t *out)
{
    char *end;
    unsigned long long v;
    if (!s[0] || s[0] == '-' || s[0] == '+')
        return 0;
    errno = 0;
    v = strtoull(s, &end, 10);
    if (errno || *end)
        return 0;
    *out = v;
    return 1;
}

/* stin_desc.shadows.map_size: a power of two, at most 8192 (and at least 16
 * here: smaller maps only show blocks). */
static int parse_map_size(const char *s, uint32_t *out)
{
    uint64_t v;
    if (!parse_count(s, &v) || v < 16 || v > 8192 || (v & (v - 1)))
        return 0;
    *out = (uint32_t)v;
    return 1;
}

/* --shadow-map-size and --max-triangles; prints the problem. */
static int parse_number_option(const char *name, const char *value, options *o)
{
    int map = !strcmp(name, "--shadow-map-size");
    if (map ? parse_map_size(value, &o->shadow_map_size) : parse_count(value, &o->max_triangles))
        return 1;
    fprintf(stderr, "stin-render: %s wants %s, got '%s'\n", name,
            map ? "a power of two in [16, 8192]" : "a whole number", value);
    return 0;
}

static int takes_value(const char *a)
{
    static const char *const names[] = {"-o", "--tier", "--profile", "--platform", "--shadows",
                                        "--volume-mode", "--shadow-map-size", "--max-triangles",
                                        "--surface", "--csg", "--size", "--debug", "--outline",
                                        "--samples"};
    size_t i;
    for (i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(a, names[i]))
            return 1;
    return 0;
}

/* The output's directory must exist and be writable before anything renders. */
static int output_writable(const char *path)
{
    char dir[4096];
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) : 0;
    if (n >= sizeof dir)
        return 0;
    memcpy(dir, slash ? path : ".", slash ? n : 1);
    dir[slash ? n : 1] = '\0';
    if (slash && n == 0)
        dir[0] = '/', dir[1] = '\0';
    return access(dir, W_OK | X_OK) == 0;
}

int render_parse_args(int argc, char **argv, options *o)
{
    int i;
    memset(o, 0, sizeof *o);
    o->platform = "egl";
    o->max_triangles = RENDER_MAX_TRIANGLES_DEFAULT;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            render_usage(stdout);
            exit(0);
        } else if (!strcmp(a, "--caps")) {
            o->caps = 1;
        } else if (!strcmp(a, "--verbose")) {
            o->verbose = 1;
        } else if (!strcmp(a, "--stage-times")) {
            o->debug_flags |= STIN_DEBUG_STAGE_TIMES;
        } else if (!strcmp(a, "--version")) {
            printf("stin-render %d.%d.%d (libstin %d)\n", STIN_VERSION_MAJOR, STIN_VERSION_MINOR,
                   STIN_VERSION_PATCH, stin_version());
            exit(0);
        } else if (!strcmp(a, "--no-output")) {
            o->no_output = 1;
        } else if (!strcmp(a, "--progress")) {
            o->progress = 1;
        } else if (!strcmp(a, "--frame")) {
            o->frame = 1;
        } else if (!strcmp(a, "--srgb")) {
            o->srgb = 1;
        } else if (takes_value(a) && !v) {
            fprintf(stderr, "stin-render: %s needs a value\n", a);
            return 0;
        } else if (!strcmp(a, "-o")) {
            o->output = argv[++i];
        } else if (!strcmp(a, "--tier")) {
            if (!parse_tier(argv[++i], &o->tier)) {
                fprintf(stderr, "stin-render: unknown tier '%s' (auto, gl1, gl2, gl4)\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--profile")) {
            o->profile = argv[++i];
        } else if (!strcmp(a, "--platform")) {
            o->platform = argv[++i];
        } else if (!strcmp(a, "--shadows")) {
            o->shadows = argv[++i];
        } else if (!strcmp(a, "--volume-mode")) {
            i++;
            if (!strcmp(v, "zpass")) o->debug_flags |= STIN_DEBUG_VOLUME_ZPASS;
            else if (!strcmp(v, "zfail")) o->debug_flags |= STIN_DEBUG_VOLUME_ZFAIL;
            else if (!strcmp(v, "facets")) o->debug_flags |= STIN_DEBUG_VOLUME_FACETS;
            else if (strcmp(v, "auto")) {
                fprintf(stderr, "stin-render: --volume-mode wants auto, zpass, zfail or facets\n");
                return 0;
            }
        } else if (!strcmp(a, "--debug")) {
            unsigned kind = render_debug_parse(argv[++i]);
            if (!kind) {
                fprintf(stderr, "stin-render: --debug wants shadow-map, volumes or masks, got "
                                "'%s'\n", v);
                return 0;
            }
            o->debug_outputs |= kind;
            if (kind == RENDER_DEBUG_VOLUMES)
                o->debug_flags |= STIN_DEBUG_VOLUME_SHOW;
        } else if (!strcmp(a, "--shadow-map-size") || !strcmp(a, "--max-triangles")) {
            if (!parse_number_option(a, argv[++i], o))
                return 0;
        } else if (!strcmp(a, "--outline")) {
            char extra;
            if (sscanf(argv[++i], "%f%c", &o->outline, &extra) != 1 || !(o->outline >= 0.0f) ||
                o->outline > 64.0f) {
                fprintf(stderr, "stin-render: --outline wants pixels in 0..64, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--surface")) {
            o->surface = argv[++i];
        } else if (!strcmp(a, "--csg")) {
            o->csg = argv[++i];
        } else if (!strcmp(a, "--samples")) {
            char extra;
            if (sscanf(argv[++i], "%d%c", &o->samples, &extra) != 1 || o->samples < 1 ||
                o->samples > 16 || (o->samples & (o->samples - 1))) {
                fprintf(stderr, "stin-render: --samples wants 1, 2, 4, 8 or 16, got '%s'\n", v);
                return 0;
            }
        } else if (!strcmp(a, "--size")) {
            char extra;
            if (sscanf(argv[++i], "%dx%d%c", &o->width, &o->height, &extra) != 2 ||
                o->width < 1 || o->height < 1 || o->width > 16384 || o->height > 16384) {
                fprintf(stderr, "stin-render: --size wants WxH with 1..16384, got '%s'\n", v);
                return 0;
            }
        } else if (a[0] == '-') {
            fprintf(stderr, "stin-render: unknown option %s\n", a);
            return 0;
        } else if (o->scene_count < RENDER_MAX_SCENES) {
            o->scenes[o->scene_count++] = a;
            o->scene_path = o->scenes[0];
        } else {
            fprintf(stderr, "stin-render: more than %d scenes given ('%s')\n", RENDER_MAX_SCENES, a);
            return 0;
        }
    }
    if (o->scene_count > 1 && (!o->no_output || o->caps)) {
        fprintf(stderr, "stin-render: several scenes render with --no-output only\n");
        return 0;
    }
    if (!o->scene_path && !o->caps) {
        fprintf(stderr, "stin-render: no scene file given\n");
        return 0;
    }
    if (o->output) {
        const char *dot = strrchr(o->output, '.');
        if (!dot || (strcmp(dot, ".png") && strcmp(dot, ".exr"))) {
            fprintf(stderr, "stin-render: output must end in .png or .exr: '%s'\n", o->output);
            return 0;
        }
        if (!output_writable(o->output)) {
            fprintf(stderr, "%s: output: its directory does not exist or is not writable\n",
                    o->output);
            return 0;
        }
    } else if (o->debug_outputs & (RENDER_DEBUG_SHADOW_MAP | RENDER_DEBUG_MASKS)) {
        fprintf(stderr, "stin-render: --debug shadow-map and masks write beside -o OUT\n");
        return 0;
    } else if (!o->caps && !o->no_output) {
        fprintf(stderr, "stin-render: no output: give -o OUT.png|OUT.exr, or --no-output to "
                        "render and print statistics only\n");
        return 0;
    }
    return 1;
}

int render_parse_technique(const char *name, stin_feature f, stin_technique *out)
{
    return technique_option_parse("stin-render", name, f, out);
}
