/* SPDX-License-Identifier: MIT */
/* The option table: every option of stin-bench with its default and --quick
 * value (both go through the option's own setter, so a default is checked
 * like a typed value), its help line and the section it belongs to. --help
 * is printed from it; --NAME and --no-NAME come from the section table. */
#include "bench_options.h"
#include "bench_maps.h"
#include "bench_shadow.h"
#include "stin_platform.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#define GENERAL (-1)
#define F(member) offsetof(options, member)
#define FRAMES_MAX 100000
#define SETUPS_MAX 1000
#define SIZE_MAX_PX 16384
#define QUICK_SCENE "tests/scenes/spheres-18k.json"
#define SPOT_SCENE "tests/scenes/spheres-18k-spot.json"
/* per light type the spheres and open models (point: open casters and a
 * character, spot: a spider, directional: a 121k-triangle engine; the
 * models from assimp-testmodels), and 174k triangles (point) */
#define PEERS_SCENES                                                                   \
    "tests/scenes/spheres-18k.json,tests/scenes/shadow-open.json,"                       \
    "tools/bench/scenes/peers-wuson.json," SPOT_SCENE ",tools/bench/scenes/peers-spider.json," \
    "tests/scenes/spheres-18k-sun.json,tools/bench/scenes/peers-engine.json,"            \
    "tests/scenes/spheres-174k.json"
#define USAGE_WIDTH 100
#define PCF_MAX_SIZES 4
#define PCF_MAX_KERNELS 3

typedef struct bench_option bench_option;
typedef int (*option_setter)(options *o, const bench_option *opt, const char *arg);

struct bench_option {
    int section;            /* GENERAL, or the section it is listed under */
    const char *name, *arg; /* arg NULL: a flag */
    const char *def, *quick; /* its value before argv, and under --quick (NULL: def) */
    option_setter set;
    size_t field;           /* the member of options it sets */
    int lo, hi, most;       /* numbers lo..hi; a list has at most `most` */
    const char *help;
};

static void *member(options *o, const bench_option *opt)
{
    return (char *)o + opt->field;
}

static int bad(const bench_option *opt, const char *arg, const char *want)
{
    fprintf(stderr, "stin-bench: %s wants %s, got '%s'\n", opt->name, want, arg);
    return 0;
}

static int to_int(const char *s, int lo, int hi, int *out)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (end == s || *end || v < lo || v > hi)
        return 0;
    *out = (int)v;
    return 1;
}

static int set_flag(options *o, const bench_option *opt, const char *arg)
{
    (void)arg;
    *(int *)member(o, opt) = 1;
    return 1;
}

static int set_text(options *o, const bench_option *opt, const char *arg)
{
    *(const char **)member(o, opt) = arg;
    return 1;
}

static int set_int(options *o, const bench_option *opt, const char *arg)
{
    char want[48];
    snprintf(want, sizeof want, "%d..%d", opt->lo, opt->hi);
    return to_int(arg, opt->lo, opt->hi, (int *)member(o, opt)) || bad(opt, arg, want);
}

/* A comma list of lo..hi; `kind` 'p' wants powers of two, 'o' odd values. */
static int set_list_of(options *o, const bench_option *opt, const char *arg, char kind)
{
    int_list *l = member(o, opt);
    char buf[128], want[96], *tok;
    snprintf(buf, sizeof buf, "%s", arg);
    snprintf(want, sizeof want, "up to %d of %d..%d%s", opt->most, opt->lo, opt->hi,
             kind == 'p' ? ", powers of two" : kind == 'o' ? ", odd" : "");
    l->n = 0;
    for (tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
        int *v = &l->v[l->n];
        if (l->n == opt->most || !to_int(tok, opt->lo, opt->hi, v) ||
            (kind == 'p' && (*v & (*v - 1))) || (kind == 'o' && !(*v & 1)))
            return bad(opt, arg, want);
        l->n++;
    }
    return l->n > 0 || bad(opt, arg, want);
}

static int set_list(options *o, const bench_option *opt, const char *arg)
{
    return set_list_of(o, opt, arg, 0);
}

static int set_pow2s(options *o, const bench_option *opt, const char *arg)
{
    return set_list_of(o, opt, arg, 'p');
}

/* One power of two in lo..hi. */
static int set_pow2(options *o, const bench_option *opt, const char *arg)
{
    char want[64];
    int *v = (int *)member(o, opt);
    snprintf(want, sizeof want, "a power of two in %d..%d", opt->lo, opt->hi);
    return (to_int(arg, opt->lo, opt->hi, v) && !(*v & (*v - 1))) || bad(opt, arg, want);
}

static int set_odds(options *o, const bench_option *opt, const char *arg)
{
    return set_list_of(o, opt, arg, 'o');
}

static int set_tier(options *o, const bench_option *opt, const char *arg)
{
    static const stin_tier tiers[] = {STIN_TIER_GL1, STIN_TIER_GL2, STIN_TIER_GL4};
    size_t i;
    for (i = 0; i < sizeof tiers / sizeof tiers[0]; i++)
        if (!strcmp(arg, stin_tier_name(tiers[i]))) {
            o->tier = tiers[i];
            return 1;
        }
    return bad(opt, arg, "gl1, gl2 or gl4");
}

static int set_profile(options *o, const bench_option *opt, const char *arg)
{
    if (!stin_profile_find(arg))
        return bad(opt, arg, "a profile of docs/profiles.md (es30, es32, gl21, ...)");
    o->profile = arg;
    return 1;
}

static int set_size(options *o, const bench_option *opt, const char *arg)
{
    char extra, want[32];
    if (sscanf(arg, "%dx%d%c", &o->width, &o->height, &extra) == 2 && o->width >= 1 &&
        o->height >= 1 && o->width <= SIZE_MAX_PX && o->height <= SIZE_MAX_PX)
        return 1;
    snprintf(want, sizeof want, "WxH with 1..%d", SIZE_MAX_PX);
    return bad(opt, arg, want);
}

static int set_scenes(options *o, const bench_option *opt, const char *arg)
{
    char *tok, want[32];
    snprintf(o->scene_list, sizeof o->scene_list, "%s", arg);
    snprintf(want, sizeof want, "1 to %d files", MAX_SCENES);
    o->scene_count = 0;
    for (tok = strtok(o->scene_list, ","); tok; tok = strtok(NULL, ",")) {
        if (o->scene_count == MAX_SCENES)
            return bad(opt, arg, want);
        o->scenes[o->scene_count++] = tok;
    }
    return o->scene_count > 0 || bad(opt, arg, want);
}

static int show_help(options *o, const bench_option *opt, const char *arg)
{
    (void)o, (void)opt, (void)arg;
    options_usage(stdout);
    exit(0);
}

/* Every section's timed frames and set-ups (--quick: 1 unless given). */
#define FRAMES(s, name, def, quick, help) \
    {s, name, "N", def, quick, set_int, F(sec[s].frames), 1, FRAMES_MAX, 0, help}
#define SETUPS(s, name, def, help) \
    {s, name, "N", def, "1", set_int, F(sec[s].setups), 1, SETUPS_MAX, 0, help}
#define PER_ROW "timed frames per side, set-up and row"

/* section, name, argument, default, --quick, setter, member, lo, hi, most, help */
static const bench_option table[] = {
    {GENERAL, "--help", NULL, NULL, NULL, show_help, 0, 0, 0, 0, "this text"},
    {GENERAL, "--tier", "gl1|gl2|gl4", NULL, NULL, set_tier, F(tier), 0, 0, 0,
     "run one tier (default: every tier; exit 3 if the context cannot)"},
    {GENERAL, "--size", "WxH", "1280x720", "64x36", set_size, 0, 0, 0, 0, "framebuffer size"},
    {GENERAL, "--warmup", "N", "3", "0", set_int, F(warmup), 0, FRAMES_MAX, 0,
     "untimed frames per side first, per set-up (a row: at least 1)"},
    {GENERAL, "--quick", NULL, NULL, NULL, set_flag, F(quick), 0, 0, 0,
     "smoke run: every section, tiny size, few frames; given options win"},
    {GENERAL, "--platform", "egl|osmesa", "egl", NULL, set_text, F(platform), 0, 0, 0,
     "context backend"},
    {GENERAL, "--profile", "NAME", NULL, NULL, set_profile, F(profile), 0, 0, 0,
     "capability profile (docs/profiles.md; es30, es32: OpenGL ES on egl)"},
    {GENERAL, "--shaders", "DIR", "shaders", NULL, set_text, F(shader_dir), 0, 0, 0,
     "where gl2/ and gl4/ lie for the raw loop"},
    {GENERAL, "--verbose", NULL, NULL, NULL, set_flag, F(verbose), 0, 0, 0,
     "per-run details and stin's info lines on stderr"},

    {SEC_RAW, "--scenes", "a.json,b.json",
     "tests/scenes/spheres-18k.json,tests/scenes/spheres-76k.json,tests/scenes/spheres-174k.json",
     QUICK_SCENE, set_scenes, 0, 0, 0, 0, "scene files (the shadow-volume section's too)"},
    FRAMES(SEC_RAW, "--frames", "30", "3", "timed frames per side and set-up"),
    SETUPS(SEC_RAW, "--setups", "5", "fresh stin context + raw loop per scene, each timed"),

    {SEC_SHADOWS, "--shadow-lights", "1,4,8", "1,4,8", "1,8", set_list, F(light_counts), 1,
     SHADOW_MAX_LIGHTS, SHADOW_MAX_COUNTS, "point-light counts"},
    FRAMES(SEC_SHADOWS, "--shadow-frames", "7", "1", "timed frames per side, set-up and count"),
    SETUPS(SEC_SHADOWS, "--shadow-setups", "2", "fresh context pairs per scene"),
    {SEC_SHADOWS, "--shadow-small-frames", "N", "7", "1", set_int, F(small_frames), 1,
     FRAMES_MAX, 0, "timed stin_end_frame calls per side at 64x36"},
    {SEC_SHADOWS, "--shadow-cpu-volumes", NULL, NULL, NULL, set_flag, F(cpu_volumes), 0, 0, 0,
     "build gl4's volumes on the CPU, as gl1/gl2 do, not in a geometry shader"},

    {SEC_MAPS, "--maps-scene", "FILE", SPOT_SCENE, NULL, set_text, F(sec[SEC_MAPS].scene), 0, 0,
     0, "scene with a spot or directional light"},
    {SEC_MAPS, "--maps-sizes", "512,1024", "512,1024,2048,4096", "256", set_pow2s, F(map_sizes),
     16, 8192, MAPS_MAX_SIZES, "map sizes, powers of two"},
    FRAMES(SEC_MAPS, "--maps-frames", "15", "1", PER_ROW),
    SETUPS(SEC_MAPS, "--maps-setups", "3", "fresh shadows-off context per set-up"),
    {SEC_MAPS, "--maps-no-fbo", NULL, NULL, NULL, set_flag, F(maps_no_fbo), 0, 0, 0,
     "hide the FBO from stin: maps drawn in the frame's framebuffer"},

    {SEC_PCF, "--pcf-scene", "FILE", SPOT_SCENE, NULL, set_text, F(sec[SEC_PCF].scene), 0, 0, 0,
     "scene"},
    {SEC_PCF, "--pcf-sizes", "1024,2048", "1024,2048,4096", "256", set_pow2s, F(pcf_sizes), 16,
     8192, PCF_MAX_SIZES, "map sizes, powers of two"},
    {SEC_PCF, "--pcf-kernels", "1,3,5", "1,3,5", NULL, set_odds, F(pcf_kernels), 1, 5,
     PCF_MAX_KERNELS, "PCF kernels, odd"},
    FRAMES(SEC_PCF, "--pcf-frames", "5", "1", PER_ROW),
    SETUPS(SEC_PCF, "--pcf-setups", "2", "fresh shadows-off context per set-up"),

    {SEC_SURFACE, "--surface-scene", "FILE", "tests/scenes/stone-wall.json", NULL, set_text,
     F(sec[SEC_SURFACE].scene), 0, 0, 0, "scene"},
    FRAMES(SEC_SURFACE, "--surface-frames", "7", "1", PER_ROW),
    SETUPS(SEC_SURFACE, "--surface-setups", "3", "fresh plain context per set-up"),

    FRAMES(SEC_VDSM, "--vdsm-frames", "3", "1", PER_ROW),
    SETUPS(SEC_VDSM, "--vdsm-setups", "1", "fresh shadows-off context per set-up"),
    {SEC_VDSM, "--vdsm-goal", NULL, NULL, NULL, set_flag, F(vdsm_goal), 0, 0, 0,
     "only the rows the 1.5x goal compares: the full chain and stencil volumes"},

    {SEC_DISPLACE, "--displace-scene", "FILE", "tools/bench/scenes/displace-grid.json", NULL,
     set_text, F(sec[SEC_DISPLACE].scene), 0, 0, 0, "the dense grid (height-mapped materials "
     "displaced; the camera moved in and out for the speed-ups)"},
    {SEC_DISPLACE, "--displace-wall", "FILE", "tests/scenes/stone-wall.json", NULL, set_text,
     F(displace_wall), 0, 0, 0, "the coarse scene"},
    {SEC_DISPLACE, "--displace-levels", "1,4", "1,4,16,64", "1,4", set_list, F(displace_levels), 1,
     64, 4, "fixed tessellation levels on the coarse scene (gl4)"},
    FRAMES(SEC_DISPLACE, "--displace-frames", "5", "1", PER_ROW),
    SETUPS(SEC_DISPLACE, "--displace-setups", "2", "fresh plain context per set-up"),

    {SEC_DEEP, "--deep-scene", "FILE", "tests/scenes/deep-stack.json", NULL, set_text,
     F(sec[SEC_DEEP].scene), 0, 0, 0, "the layers table's scene (a spot light)"},
    {SEC_DEEP, "--deep-one", "FILE", "tools/bench/scenes/deep-point-one.json", NULL, set_text,
     F(deep_one), 0, 0, 0, "a point light with transparency in one cube face"},
    {SEC_DEEP, "--deep-all", "FILE", "tools/bench/scenes/deep-point-all.json", NULL, set_text,
     F(deep_all), 0, 0, 0, "a point light with transparency in all six faces"},
    {SEC_DEEP, "--deep-size", "N", "1024", "64", set_pow2, F(deep_size), 16, 4096, 0,
     "texels a side of the map-pcf map and of each deep or coloured face"},
    FRAMES(SEC_DEEP, "--deep-frames", "5", "1", PER_ROW),
    SETUPS(SEC_DEEP, "--deep-setups", "2", "fresh shadows-off context per set-up"),

    FRAMES(SEC_CSG, "--csg-frames", "10", "2", "timed frames per side and row"),
    {SEC_CSG, "--csg-readback", NULL, NULL, NULL, set_flag, F(csg_readback), 0, 0, 0,
     "stin resolves with read-backs (STIN_DEBUG_CSG_READBACK), as before the GPU resolve"},
    {SEC_PEEL, "--peel-scene", "FILE", "tests/scenes/peel/panes.json", NULL, set_text,
     F(sec[SEC_PEEL].scene), 0, 0, 0, "the panes (0, 2 and 4 of them over the floor)"},
    FRAMES(SEC_PEEL, "--peel-frames", "7", "1", PER_ROW),
    SETUPS(SEC_PEEL, "--peel-setups", "2", "fresh sorted context per set-up"),

    FRAMES(SEC_UPDATE, "--update-frames", "20", "1", "timed calls per row, mesh and tier"),

    {SEC_PEERS, "--peers-scenes", "a.json,b.json", PEERS_SCENES, QUICK_SCENE, set_text,
     F(peers_scenes), 0, 0, 0, "scenes (light 0 of each)"},
    {SEC_PEERS, "--peers-map-size", "N", "2048", "256", set_pow2, F(peers_map_size), 16, 8192, 0,
     "texels a side of every shadow map, stin's and osgShadow's"},
    FRAMES(SEC_PEERS, "--peers-frames", "15", "1", "timed frames per renderer and scene"),
};
enum { OPTION_COUNT = sizeof table / sizeof table[0] };

static void usage_row(FILE *f, const bench_option *opt)
{
    char head[64], range[48] = "", tail[256] = "";
    int n;
    snprintf(head, sizeof head, "%s%s%s", opt->name, opt->arg ? " " : "",
             opt->arg ? opt->arg : "");
    if (opt->most)
        snprintf(range, sizeof range, "%d..%d, at most %d%s", opt->lo, opt->hi, opt->most,
                 opt->def ? "; " : "");
    if (opt->most || opt->def)
        snprintf(tail, sizeof tail, " (%s%s%s%s%s)", range, opt->def ? "default " : "",
                 opt->def ? opt->def : "", opt->quick ? "; --quick " : "",
                 opt->quick ? opt->quick : "");
    n = fprintf(f, "  %-25s %s", head, opt->help);
    if (tail[0] && n + (int)strlen(tail) > USAGE_WIDTH)
        fprintf(f, "\n%27s", ""); /* a long default on a line of its own */
    fprintf(f, "%s\n", tail);
}

void options_usage(FILE *f)
{
    int i, s;
    fprintf(f, "usage: stin-bench [options]   (run from the repository root)\n");
    for (i = 0; i < OPTION_COUNT; i++)
        if (table[i].section == GENERAL)
            usage_row(f, &table[i]);
    fprintf(f, "sections, in the order they run (--NAME runs only the sections named, --no-NAME "
            "skips one):\n");
    for (s = 0; s < SECTION_COUNT; s++) {
        fprintf(f, "--%s: %s\n", bench_sections[s].name, bench_sections[s].about);
        for (i = 0; i < OPTION_COUNT; i++)
            if (table[i].section == s)
                usage_row(f, &table[i]);
    }
    fprintf(f, "exit codes: 0 ok, 1 failure, 2 bad input, 3 the --tier is unsupported here\n");
}

/* --NAME (only) or --no-NAME (skip) of a section: its bit in *only / *skip. */
static int section_flag(const char *a, unsigned *only, unsigned *skip)
{
    int s, no = !strncmp(a, "--no-", 5);
    for (s = 0; s < SECTION_COUNT && !strncmp(a, "--", 2); s++)
        if (!strcmp(a + (no ? 5 : 2), bench_sections[s].name)) {
            *(no ? skip : only) |= 1u << s;
            return 1;
        }
    return 0;
}

static const bench_option *find(const char *name)
{
    int i;
    if (!strcmp(name, "-h"))
        name = "--help";
    for (i = 0; i < OPTION_COUNT; i++)
        if (!strcmp(name, table[i].name))
            return &table[i];
    return NULL;
}

int options_parse(int argc, char **argv, options *o)
{
    unsigned only = 0, skip = 0;
    int i;
    memset(o, 0, sizeof *o);
    /* --quick picks the defaults, so it is read first; what argv sets wins */
    for (i = 1; i < argc; i++)
        o->quick |= !strcmp(argv[i], "--quick");
    for (i = 0; i < OPTION_COUNT; i++) {
        const char *v = o->quick && table[i].quick ? table[i].quick : table[i].def;
        if (v && table[i].arg && !table[i].set(o, &table[i], v))
            return 0;
    }
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const bench_option *opt = find(a);
        if (!opt && section_flag(a, &only, &skip))
            continue;
        if (!opt) {
            fprintf(stderr, "stin-bench: %s '%s'\n", a[0] == '-' ? "unknown option"
                                                                 : "unexpected argument", a);
            return 0;
        }
        if (opt->arg && i + 1 == argc) {
            fprintf(stderr, "stin-bench: %s needs a value (%s)\n", a, opt->arg);
            return 0;
        }
        if (!opt->set(o, opt, opt->arg ? argv[++i] : NULL))
            return 0;
    }
    for (i = 0; i < SECTION_COUNT; i++)
        o->sec[i].on = (!only || (only >> i & 1u)) && !(skip >> i & 1u);
    return 1;
}
