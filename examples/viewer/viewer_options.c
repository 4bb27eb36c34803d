/* SPDX-License-Identifier: MIT */
#include "viewer_options.h"
#include "technique_option.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(void)
{
    printf("usage: viewer SCENE.json [options]   an interactive window onto a scene file\n"
           "  --size WxH             window size (default: the scene's, else 512x512)\n"
           "  --tier auto|gl1|gl2|gl4  force a tier\n"
           "  --shadows NAME         shadows technique (as stin-render's; default auto)\n"
           "  --surface NAME         surface technique\n"
           "  --transparency NAME    transparency technique: dual-peel, depth-peel, sorted\n"
           "  --samples 0|2|4|8      a multisampled window\n"
           "  --srgb                 an sRGB framebuffer (GL_FRAMEBUFFER_SRGB)\n"
           "  --frames N             scripted: N frames with no input, then exit\n"
           "  --orbit YAW,PITCH      scripted: turn the camera this many degrees over the frames\n"
           "  --zoom F               scripted: the camera's distance times F over the frames\n"
           "  --keys KEYS            scripted: one key a frame from the first, e.g. TSS (as pressed)\n"
           "  --screenshot OUT.png|OUT.exr  scripted: the window's read-back after the last frame\n"
           "                         (PNG sRGB-encoded and EXR linear, as stin-render writes them)\n"
           "  --hidden               no window on screen (the same framebuffer)\n"
           "  --verbose              stin's info log lines on stderr\n"
           "keys:\n%s"
           "exit codes: 0 ok, 1 failure, 2 bad input, 3 tier/technique unsupported here,\n"
           "            4 no display\n",
           viewer_keys_help);
}

static int parse_tier(const char *s, stin_tier *t)
{
    static const struct { const char *name; stin_tier tier; } tiers[] = {
        {"auto", STIN_TIER_AUTO}, {"gl1", STIN_TIER_GL1}, {"gl2", STIN_TIER_GL2},
        {"gl4", STIN_TIER_GL4}};
    size_t i;
    for (i = 0; i < sizeof tiers / sizeof tiers[0]; i++)
        if (!strcmp(s, tiers[i].name)) {
            *t = tiers[i].tier;
            return 1;
        }
    return 0;
}

/* One option's value; 0 and a message when it is bad. */
static int parse_value(viewer_options *o, const char *a, const char *v)
{
    char extra;
    viewer_settings *s = &o->settings;
    if (!strcmp(a, "--size"))
        return sscanf(v, "%dx%d%c", &o->width, &o->height, &extra) == 2 && o->width > 0 &&
               o->height > 0 && o->width <= 16384 && o->height <= 16384;
    if (!strcmp(a, "--tier"))
        return parse_tier(v, &s->tier);
    if (!strcmp(a, "--shadows"))
        return technique_option_parse("viewer", v, STIN_FEATURE_SHADOWS, &s->shadows);
    if (!strcmp(a, "--surface"))
        return technique_option_parse("viewer", v, STIN_FEATURE_SURFACE, &s->surface);
    if (!strcmp(a, "--transparency"))
        return technique_option_parse("viewer", v, STIN_FEATURE_TRANSPARENCY, &s->transparency);
    if (!strcmp(a, "--samples"))
        return sscanf(v, "%d%c", &s->samples, &extra) == 1 &&
               (s->samples == 0 || s->samples == 2 || s->samples == 4 || s->samples == 8);
    if (!strcmp(a, "--frames"))
        return sscanf(v, "%d%c", &o->frames, &extra) == 1 && o->frames > 0;
    if (!strcmp(a, "--orbit"))
        return sscanf(v, "%lf,%lf%c", &o->orbit.yaw_deg, &o->orbit.pitch_deg, &extra) == 2;
    if (!strcmp(a, "--zoom"))
        return sscanf(v, "%lf%c", &o->orbit.zoom, &extra) == 1 && o->orbit.zoom > 0;
    if (!strcmp(a, "--keys")) {
        size_t k;
        o->keys = v;
        for (k = 0; v[k]; k++)
            if (!(v[k] >= 'A' && v[k] <= 'Z'))
                return 0;
        return 1;
    }
    if (!strcmp(a, "--screenshot")) {
        const char *dot = strrchr(v, '.');
        o->screenshot = v;
        return dot && (!strcmp(dot, ".png") || !strcmp(dot, ".exr"));
    }
    return -1; /* not an option with a value */
}

int viewer_parse_args(int argc, char **argv, viewer_options *o)
{
    int i;
    memset(o, 0, sizeof *o);
    viewer_orbit_reset(&o->orbit);
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        int ok;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage();
            exit(0);
        } else if (!strcmp(a, "--srgb")) {
            o->settings.srgb = 1;
        } else if (!strcmp(a, "--hidden")) {
            o->hidden = 1;
        } else if (!strcmp(a, "--verbose")) {
            o->verbose = 1;
        } else if (a[0] != '-') {
            if (o->scene_path) {
                fprintf(stderr, "viewer: more than one scene given ('%s')\n", a);
                return 0;
            }
            o->scene_path = a;
        } else if (i + 1 >= argc) {
            fprintf(stderr, "viewer: %s: unknown option, or its value is missing\n", a);
            return 0;
        } else if ((ok = parse_value(o, a, argv[i + 1])) <= 0) {
            if (ok < 0)
                fprintf(stderr, "viewer: unknown option %s\n", a);
            else if (strcmp(a, "--shadows") && strcmp(a, "--surface") && strcmp(a, "--transparency"))
                fprintf(stderr, "viewer: bad value for %s: '%s' (see --help)\n", a, argv[i + 1]);
            return 0;
        } else {
            i++;
        }
    }
    if (!o->scene_path) {
        fprintf(stderr, "viewer: no scene file given (see --help)\n");
        return 0;
    }
    if ((o->screenshot || o->keys) && !o->frames) {
        fprintf(stderr, "viewer: --screenshot and --keys need --frames N\n");
        return 0;
    }
    return 1;
}
