/* stin-render: renders a scene file through libstin on an offscreen context
 * and writes PNG or OpenEXR (the image contract of DESIGN.md). */
#include "aov.h"
#include "cli_log.h"
#include "scene.h"
#include "scene_gpu.h"
#include "stin/stin.h"
#include "stin_platform.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_FAILED = 1, EXIT_BAD_INPUT = 2, EXIT_UNSUPPORTED = 3 };

typedef struct options {
    const char *scene_path, *output, *profile, *platform, *shadows, *surface;
    uint32_t debug_flags;
    stin_tier tier;
    int width, height, caps, verbose;
} options;

static void usage(FILE *f)
{
    fprintf(f,
            "usage: stin-render SCENE.json [-o OUT.png|OUT.exr] [options]\n"
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
               "  --shadows NAME            shadow technique: volume, map-pcf (GLSL tiers), map (map-depth where the\n"
               "                            context has ARB_shadow, else map-combine), map-depth,\n"
               "                            map-combine, off (default auto)\n"
               "  --surface NAME            surface technique (default auto)\n"
               "  --volume-mode auto|zpass|zfail  shadow-volume counting (diagnostics)\n"
               "  --caps                    print capabilities and choices, render nothing\n"
               "  --verbose                 print stin's info log lines\n"
               "exit codes: 0 ok, 1 failure, 2 bad input, 3 tier/technique unsupported here\n");
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

static int parse_args(int argc, char **argv, options *o)
{
    int i;
    memset(o, 0, sizeof *o);
    o->platform = "egl";
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            exit(0);
        } else if (!strcmp(a, "--caps")) {
            o->caps = 1;
        } else if (!strcmp(a, "--verbose")) {
            o->verbose = 1;
        } else if (a[0] == '-' && !v) {
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
            else if (strcmp(v, "auto")) {
                fprintf(stderr, "stin-render: --volume-mode wants auto, zpass or zfail\n");
                return 0;
            }
        } else if (!strcmp(a, "--surface")) {
            o->surface = argv[++i];
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
        } else if (!o->scene_path) {
            o->scene_path = a;
        } else {
            fprintf(stderr, "stin-render: more than one scene given ('%s')\n", a);
            return 0;
        }
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
    }
    return 1;
}

/* --shadows/--surface: a technique name of that feature, or "auto". */
static int parse_technique(const char *name, stin_feature f, stin_technique *out)
{
    int t;
    *out = STIN_TECH_NONE;
    if (!name || !strcmp(name, "auto"))
        return 1;
    if (f == STIN_FEATURE_SHADOWS && !strcmp(name, "map")) {
        *out = STIN_TECH_SHADOWS_MAP_DEPTH; /* narrowed to what the context has, see main */
        return 1;
    }
    for (t = 1; t < STIN_TECH_COUNT; t++) {
        stin_technique tech = (stin_technique)t;
        if (!strcmp(stin_technique_name(tech), name) && stin_technique_feature(tech) == f) {
            *out = tech;
            return 1;
        }
    }
    fprintf(stderr, "stin-render: unknown %s technique '%s'; this build knows: auto%s",
            stin_feature_name(f), name, f == STIN_FEATURE_SHADOWS ? ", map" : "");
    for (t = 1; t < STIN_TECH_COUNT; t++)
        if (stin_technique_feature((stin_technique)t) == f)
            fprintf(stderr, ", %s", stin_technique_name((stin_technique)t));
    fprintf(stderr, "\n");
    return 0;
}

static void print_caps(const stin_caps *c)
{
    int i;
    char missing[512];
    printf("GL %d.%d, GLSL %d.%d, %s profile, renderer %s\n", c->gl_major, c->gl_minor,
           c->glsl_major, c->glsl_minor,
           c->profile == STIN_GL_PROFILE_CORE ? "core" : "compatibility", c->renderer);
    printf("limits: texture %d, units %d/%d (fixed/fragment), vertex textures %d, lights %d, "
           "stencil %d bits, depth %d bits, draw buffers %d, GS output %d\n",
           c->max_texture_size, c->max_texture_units, c->max_texture_image_units,
           c->max_vertex_texture_units, c->max_lights, c->stencil_bits, c->depth_bits,
           c->max_draw_buffers, c->max_geometry_output_vertices);
    for (i = 0; i < STIN_CAP_COUNT; i++) {
        uint64_t b = STIN_CAP_BIT(i);
        printf("  %-34s %s\n", stin_cap_name((stin_cap)i),
               (c->present & b) ? "yes" : (c->hidden & b) ? "hidden by profile mask" : "no");
    }
    for (i = 1; i <= 4; i *= 2) {
        stin_tier t = (stin_tier)(i == 1 ? 1 : i == 2 ? 2 : 4);
        if (stin_tier_supported(c, t, missing, sizeof missing))
            printf("tier %s: runs\n", stin_tier_name(t));
        else
            printf("tier %s: needs %s\n", stin_tier_name(t), missing);
    }
}

static void print_choices(const stin_context *ctx)
{
    int f;
    printf("tier: %s\n", stin_tier_name(stin_query_tier(ctx)));
    for (f = 0; f < STIN_FEATURE_COUNT; f++) {
        stin_choice c = stin_query_choice(ctx, (stin_feature)f);
        printf("%s: %s (%s)\n", stin_feature_name((stin_feature)f),
               stin_technique_name(c.technique), c.reason);
    }
}

int main(int argc, char **argv)
{
    options o;
    scene s;
    scene_gpu g;
    stin_platform_desc pd;
    stin_platform *plat = NULL;
    stin_desc desc;
    stin_context *ctx = NULL;
    cli_log log = {0, "stin-render", 0};
    void *block = NULL;
    char err[1024];
    int rc = EXIT_FAILED, have_scene = 0, have_gpu = 0;
    image img;
    double ms = 0;

    memset(&s, 0, sizeof s);
    memset(&img, 0, sizeof img);
    if (!parse_args(argc, argv, &o)) {
        usage(stderr);
        return EXIT_BAD_INPUT;
    }
    log.verbose = o.verbose;
    memset(&desc, 0, sizeof desc);
    if (!parse_technique(o.shadows, STIN_FEATURE_SHADOWS, &desc.techniques[STIN_FEATURE_SHADOWS]) ||
        !parse_technique(o.surface, STIN_FEATURE_SURFACE, &desc.techniques[STIN_FEATURE_SURFACE]))
        return EXIT_BAD_INPUT;
    if (o.scene_path) {
        if (!scene_load(o.scene_path, &s, err, sizeof err)) {
            fprintf(stderr, "stin-render: %s\n", err);
            return EXIT_BAD_INPUT;
        }
        have_scene = 1;
    }
    memset(&pd, 0, sizeof pd);
    if (!stin_platform_kind_from_name(o.platform, &pd.kind)) {
        fprintf(stderr, "stin-render: unknown platform '%s' (egl, osmesa)\n", o.platform);
        rc = EXIT_BAD_INPUT;
        goto done;
    }
    if (o.profile && !(pd.profile = stin_profile_find(o.profile))) {
        fprintf(stderr, "stin-render: unknown profile '%s'\n", o.profile);
        rc = EXIT_BAD_INPUT;
        goto done;
    }
    pd.width = o.width ? o.width : (have_scene && s.width ? s.width : 512);
    pd.height = o.height ? o.height : (have_scene && s.height ? s.height : 512);
    plat = stin_platform_create(&pd, err, sizeof err);
    if (!plat) {
        fprintf(stderr, "stin-render: no GL context: %s\n", err);
        goto done;
    }
    desc.get_proc_address = stin_platform_get_proc_address;
    desc.get_proc_user = plat;
    desc.log = cli_log_fn;
    desc.log_user = &log;
    desc.tier = o.tier;
    desc.debug_flags = o.debug_flags;
    if (pd.profile) {
        desc.caps_mask = pd.profile->caps_mask;
        desc.max_gl_version = pd.profile->max_gl_version;
    }
    if (o.shadows && !strcmp(o.shadows, "map")) { /* the best map path the context has */
        stin_caps caps;
        uint64_t depth = STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE) | STIN_CAP_BIT(STIN_CAP_SHADOW);
        if (stin_detect_caps(stin_platform_get_proc_address, plat, desc.caps_mask,
                             desc.max_gl_version, &caps) == STIN_OK &&
            (caps.present & depth) != depth)
            desc.techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_MAP_COMBINE;
    }
    if (o.caps) {
        stin_caps caps;
        if (stin_detect_caps(stin_platform_get_proc_address, plat, desc.caps_mask,
                             desc.max_gl_version, &caps) != STIN_OK) {
            fprintf(stderr, "stin-render: cannot read GL capabilities\n");
            goto done;
        }
        printf("platform: %s, profile: %s\n", stin_platform_kind_name(pd.kind),
               pd.profile ? pd.profile->name : "none");
        print_caps(&caps);
    }
    if (have_scene)
        scene_gpu_size_desc(&s, &desc);
    block = malloc(stin_memory_size(&desc));
    if (!block) {
        fprintf(stderr, "stin-render: cannot allocate %zu bytes\n", stin_memory_size(&desc));
        goto done;
    }
    {
        stin_result r = stin_create(&desc, block, stin_memory_size(&desc), &ctx);
        if (r != STIN_OK) {
            fprintf(stderr, "stin-render: cannot create the stin context: %s\n",
                    stin_result_name(r));
            rc = r == STIN_ERROR_UNSUPPORTED ? EXIT_UNSUPPORTED : EXIT_FAILED;
            goto done;
        }
    }
    print_choices(ctx);
    if (o.caps || !have_scene) {
        rc = 0;
        goto done;
    }
    if (!scene_gpu_create(&g, &s, ctx, err, sizeof err)) {
        fprintf(stderr, "stin-render: %s\n", err);
        rc = EXIT_BAD_INPUT;
        goto done;
    }
    have_gpu = 1;
    if (!aov_capture(&g, ctx, plat, &img, &ms, err, sizeof err)) {
        fprintf(stderr, "stin-render: %s\n", err);
        goto done;
    }
    {
        stin_frame_stats st = stin_query_frame_stats(ctx);
        printf("frame: %.2f ms (%dx%d, %llu triangles, %u passes)\n", ms, pd.width, pd.height,
               (unsigned long long)scene_triangle_count(&s), st.passes);
        if (st.zpass_casters + st.zfail_casters)
            printf("shadow volumes: %u triangles, %u casters z-pass, %u z-fail (last output)\n",
                   st.shadow_volume_triangles, st.zpass_casters, st.zfail_casters);
    }
    if (o.output) {
        const char *dot = strrchr(o.output, '.');
        if (!image_write(o.output, &img, strcmp(dot, ".png") == 0, err, sizeof err)) {
            fprintf(stderr, "stin-render: %s\n", err);
            goto done;
        }
        printf("wrote %s\n", o.output);
    }
    rc = log.errors ? EXIT_FAILED : 0;
done:
    image_free(&img);
    if (have_gpu)
        scene_gpu_destroy(&g, ctx);
    if (ctx)
        stin_destroy(ctx);
    free(block);
    if (plat)
        stin_platform_destroy(plat);
    if (have_scene)
        scene_free(&s);
    return rc;
}
