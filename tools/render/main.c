/* SPDX-License-Identifier: MIT */
/* stin-render: renders a scene file through libstin on an offscreen context
 * and writes PNG or OpenEXR (the image contract of DESIGN.md). Every failure
 * is one stderr line, "stin-render: FILE: where: problem". */
#include "aov.h"
#include "cli_log.h"
#include "one_line.h"
#include "render_debug.h"
#include "render_options.h"
#include "render_progress.h"
#include "scene.h"
#include "scene_context.h"
#include "scene_csg.h"
#include "scene_gpu.h"
#include "stin/stin.h"
#include "stin_platform.h"
#include "technique_option.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The tool's one failure line: its own words, then what stin logged (its
 * error lines are held back by the cli_log so that they join this one). */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void fail_line(const cli_log *log, const char *fmt, ...)
{
    char msg[1024], line[1600];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (log && log->first_error[0])
        snprintf(line, sizeof line, "%s: %s", msg, log->first_error);
    else
        snprintf(line, sizeof line, "%s", msg);
    one_line_copy(msg, sizeof msg, line);
    fprintf(stderr, "stin-render: %s\n", msg);
}

static void print_caps(const stin_caps *c)
{
    int i;
    char missing[512];
    printf("%s %d.%d, GLSL %d.%d, %s profile, renderer %s\n", c->es ? "OpenGL ES" : "GL",
           c->gl_major, c->gl_minor, c->glsl_major, c->glsl_minor,
           c->es ? "ES" : c->profile == STIN_GL_PROFILE_CORE ? "core" : "compatibility",
           c->renderer);
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

/* The technique per feature; after a frame, with what the frame fell back
 * to (stin logs that at info level: e.g. point lights that get volumes
 * under a map technique). */
static void print_choices(const stin_context *ctx, const cli_log *log)
{
    int f, n;
    printf("tier: %s\n", stin_tier_name(stin_query_tier(ctx)));
    for (f = 0; f < STIN_FEATURE_COUNT; f++) {
        const char *name = stin_feature_name((stin_feature)f);
        size_t len = strlen(name);
        stin_choice c = stin_query_choice(ctx, (stin_feature)f);
        printf("%s: %s (%s)", name, stin_technique_name(c.technique), c.reason);
        for (n = 0; n < log->note_count; n++)
            if (!strncmp(log->notes[n], name, len) && !strncmp(log->notes[n] + len, ": ", 2))
                printf("; frame: %s", log->notes[n] + len + 2);
        printf("\n");
    }
}

/* The work limit (--max-triangles): instances x triangles over the scene. */
static int within_work_limit(const options *o, const scene *s, const cli_log *log)
{
    uint64_t tris = scene_triangle_count(s);
    if (!o->max_triangles || tris <= o->max_triangles)
        return 1;
    fail_line(log, "%s: objects: %llu triangles a frame (instances x triangles) exceed the work "
                   "limit of %llu; raise it with --max-triangles",
              s->path, (unsigned long long)tris, (unsigned long long)o->max_triangles);
    return 0;
}

/* What a model file lost, one stderr line each ("stin-render: warning: ..."). */
static void print_warnings(const char *lines)
{
    char line[1024];
    while (lines && *lines) {
        const char *nl = strchr(lines, '\n');
        int n = nl ? (int)(nl - lines) : (int)strlen(lines);
        snprintf(line, sizeof line, "%.*s", n, lines);
        fprintf(stderr, "stin-render: warning: %s\n", line);
        lines += n + (nl != NULL);
    }
}

/* --frame, or a scene without a camera: fit it to this image's aspect. */
static void frame_camera(scene *s, int width, int height)
{
    const scene_camera *c = &s->camera;
    scene_camera_frame(s, width, height, &s->camera);
    printf("camera: framed, eye (%g, %g, %g), target (%g, %g, %g), fovy %g, near %g, far %g\n",
           c->eye[0], c->eye[1], c->eye[2], c->target[0], c->target[1], c->target[2], c->fovy_deg,
           c->near_plane, c->far_plane);
}

/* The beauty frame's figures; stage times where timed asks for them. */
/* An sRGB target's stored beauty (R G B) back to linear: IEC 61966-2-1. */
static void decode_beauty(image *img)
{
    size_t i, n = (size_t)img->width * img->height;
    int c;
    for (i = 0; i < n; i++)
        for (c = AOV_R; c <= AOV_B; c++) {
            float *v = &img->pixels[i * AOV_CHANNELS + c];
            *v = *v <= 0.04045f ? *v / 12.92f : powf((*v + 0.055f) / 1.055f, 2.4f);
        }
}

static void print_frame(const stin_frame_stats *stats, const scene *s, double ms, int w, int h,
                        int timed)
{
    stin_frame_stats st = *stats;
    printf("frame: %.2f ms (%dx%d, %llu triangles, %u passes)\n", ms, w, h,
           (unsigned long long)scene_triangle_count(s), st.passes);
    if (st.stage_times) {
        uint64_t total = 0;
        int i;
        printf("stages (GPU ms):");
        for (i = 0; i < STIN_STAGE_COUNT; i++) {
            total += st.stage_ns[i];
            printf(" %s %.3f", stin_stage_name((stin_stage)i), st.stage_ns[i] / 1e6);
        }
        printf("; total %.3f\n", total / 1e6);
    } else if (timed) {
        printf("stages: not timed (the context has no timer queries)\n");
    }
    if (st.shadows.map_size)
        printf("shadow maps: %u texels a side\n", st.shadows.map_size);
    if (st.shadows.map_faces)
        printf("point-light faces: %u drawn, %u casters drawn into them\n",
               st.shadows.map_faces, st.shadows.map_face_casters);
    if (st.shadows.zpass_casters + st.shadows.zfail_casters)
        printf("shadow volumes: %u triangles, %u casters z-pass, %u z-fail, %u extruded by "
               "the GPU (last output)\n",
               st.shadows.volume_triangles, st.shadows.zpass_casters, st.shadows.zfail_casters,
               st.shadows.volume_gpu_casters);
}

/* One scene (o->scene_path), or none with --caps: the whole run of one. */
static int render_scene(const options *opt)
{
    options o = *opt;
    scene s;
    scene_context sc;
    scene_context_step step;
    scene_gpu *g;
    stin_result r;
    scene_csg_products products = {0};
    stin_platform_desc pd;
    stin_platform *plat = NULL;
    stin_desc desc;
    stin_context *ctx = NULL;
    static cli_log log;
    char err[1024];
    const char *file;
    int rc = EXIT_FAILED, have_scene = 0, displace_all, i;
    image img;
    double ms = 0;
    stin_frame_stats stats;
    progress pr;

    memset(&s, 0, sizeof s);
    memset(&sc, 0, sizeof sc);
    memset(&img, 0, sizeof img);
    memset(&log, 0, sizeof log);
    progress_init(&pr, o.progress);
    log.program = "stin-render";
    log.verbose = o.verbose;
    log.collect = 1;
    memset(&desc, 0, sizeof desc);
    /* --surface displace: the displacement feature, every height-mapped material displaced */
    displace_all = o.surface && stin_technique_feature(stin_technique_from_name(o.surface)) ==
                                    STIN_FEATURE_DISPLACEMENT;
    if (displace_all)
        desc.techniques[STIN_FEATURE_DISPLACEMENT] = stin_technique_from_name(o.surface);
    if (!render_parse_technique(o.shadows, STIN_FEATURE_SHADOWS, &desc.techniques[STIN_FEATURE_SHADOWS]) ||
        (!displace_all &&
         !render_parse_technique(o.surface, STIN_FEATURE_SURFACE, &desc.techniques[STIN_FEATURE_SURFACE])) ||
        !render_parse_technique(o.csg, STIN_FEATURE_CSG, &desc.techniques[STIN_FEATURE_CSG]))
        return EXIT_BAD_INPUT;
    if (o.scene_path) {
        progress_start(&pr, "loading %s", o.scene_path);
        if (!scene_load(o.scene_path, &s, err, sizeof err)) {
            fail_line(NULL, "%s", err);
            return EXIT_BAD_INPUT;
        }
        have_scene = 1;
        for (i = 0; displace_all && i < s.material_count; i++)
            s.materials[i].displace |= s.materials[i].height >= 0;
        progress_done(&pr, "loaded %s: %d meshes, %d objects, %d textures", o.scene_path,
                      s.mesh_count, s.object_count, s.texture_count);
        print_warnings(s.warnings);
        if (!within_work_limit(&o, &s, NULL)) {
            rc = EXIT_BAD_INPUT;
            goto done;
        }
        /* the file's csg list: what stin would refuse, refused now; the
         * capacities it needs, given */
        if (!scene_csg_products_build(&s, &products)) {
            fail_line(NULL, "%s: out of memory", s.path);
            goto done;
        }
        i = scene_csg_products_check(&s, &products, &desc, err, sizeof err);
        if (i <= 0) {
            fail_line(NULL, "%s%s", i < 0 ? s.path : err, i < 0 ? ": out of memory" : "");
            rc = i < 0 ? EXIT_FAILED : EXIT_BAD_INPUT;
            goto done;
        }
    }
    file = have_scene ? s.path : "stin-render";
    memset(&pd, 0, sizeof pd);
    if (!stin_platform_kind_from_name(o.platform, &pd.kind)) {
        fail_line(NULL, "unknown platform '%s' (egl, osmesa)", o.platform);
        rc = EXIT_BAD_INPUT;
        goto done;
    }
    if (o.profile && !(pd.profile = stin_profile_find(o.profile))) {
        fail_line(NULL, "unknown profile '%s'", o.profile);
        rc = EXIT_BAD_INPUT;
        goto done;
    }
    pd.width = o.width ? o.width : (have_scene && s.width ? s.width : 512);
    pd.height = o.height ? o.height : (have_scene && s.height ? s.height : 512);
    plat = stin_platform_create(&pd, err, sizeof err);
    if (!plat) {
        fail_line(NULL, "no GL context: %s", err);
        goto done;
    }
    if (o.samples > 1 && !stin_platform_set_samples(plat, o.samples, err, sizeof err)) {
        fail_line(NULL, "--samples %d: %s", o.samples, err);
        rc = EXIT_UNSUPPORTED;
        goto done;
    }
    if (o.srgb && !stin_platform_set_srgb(plat, 1, err, sizeof err)) {
        fail_line(NULL, "--srgb: %s", err);
        rc = EXIT_UNSUPPORTED;
        goto done;
    }
    desc.get_proc_address = stin_platform_get_proc_address;
    desc.get_proc_user = plat;
    desc.log = cli_log_fn;
    desc.log_user = &log;
    desc.tier = o.tier;
    desc.debug_flags = o.debug_flags;
    desc.shadows.map_size = o.shadow_map_size ? o.shadow_map_size
                         : have_scene      ? (uint32_t)s.shadow_map_size : 0u;
    if (pd.profile) {
        desc.caps_mask = pd.profile->caps_mask;
        desc.max_gl_version = pd.profile->max_gl_version;
    }
    if (o.shadows && !strcmp(o.shadows, "map"))
        technique_option_narrow_map(stin_platform_get_proc_address, plat, &desc);
    if (o.caps) {
        stin_caps caps;
        if (stin_detect_caps(stin_platform_get_proc_address, plat, desc.caps_mask,
                             desc.max_gl_version, &caps) != STIN_OK) {
            fail_line(NULL, "cannot read GL capabilities");
            goto done;
        }
        printf("platform: %s, profile: %s\n", stin_platform_kind_name(pd.kind),
               pd.profile ? pd.profile->name : "none");
        print_caps(&caps);
    }
    step = scene_context_create(&sc, have_scene ? &s : NULL, &products, &desc, &r, err,
                                sizeof err);
    if (step != SCENE_CONTEXT_OK) {
        if (step == SCENE_CONTEXT_SCENE)
            fail_line(NULL, "%s", err);
        else
            fail_line(step == SCENE_CONTEXT_CREATE ? &log : NULL, "%s: %s", file, err);
        rc = step == SCENE_CONTEXT_SCENE            ? EXIT_BAD_INPUT
           : r == STIN_ERROR_UNSUPPORTED            ? EXIT_UNSUPPORTED
                                                    : EXIT_FAILED;
        goto done;
    }
    ctx = sc.ctx;
    log.note_count = 0; /* from here on: what frames fell back to */
    if (o.caps || !have_scene) {
        print_choices(ctx, &log);
        rc = 0;
        goto done;
    }
    if (o.frame || !s.has_camera)
        frame_camera(&s, pd.width, pd.height);
    progress_start(&pr, "creating meshes and textures");
    step = scene_context_load(&sc, &s, &products, err, sizeof err);
    if (step != SCENE_CONTEXT_OK) {
        if (step == SCENE_CONTEXT_MESHES)
            print_choices(ctx, &log);
        fail_line(step == SCENE_CONTEXT_MESHES ? &log : NULL, "%s", err);
        rc = EXIT_BAD_INPUT;
        goto done;
    }
    g = &sc.gpu;
    g->outline_step = o.outline; /* black: stin's default colour */
    progress_done(&pr, "created meshes and textures");
    progress_start(&pr, "rendering %dx%d (beauty, normal and visibility frames)", pd.width,
                   pd.height);
    if (!aov_capture(g, ctx, plat, &img, &ms, &stats, err, sizeof err)) {
        print_choices(ctx, &log);
        fail_line(&log, "%s: %s", file, err);
        goto done;
    }
    progress_done(&pr, "rendered");
    print_choices(ctx, &log);
    print_frame(&stats, &s, ms, pd.width, pd.height,
                (o.debug_flags & STIN_DEBUG_STAGE_TIMES) != 0);
    if (o.output) {
        const char *dot = strrchr(o.output, '.');
        int png = strcmp(dot, ".png") == 0;
        if (o.srgb && !png) /* the EXR's beauty is linear */
            decode_beauty(&img);
        if (!image_write(o.output, &img, png && !o.srgb, err, sizeof err)) {
            fail_line(NULL, "%s", err);
            goto done;
        }
        printf("wrote %s\n", o.output);
        if (o.debug_outputs &&
            !render_debug_write(o.debug_outputs, o.output, g, ctx, plat, err, sizeof err)) {
            fail_line(NULL, "%s", err);
            goto done;
        }
    }
    rc = 0;
    if (log.errors) {
        fail_line(&log, "%s: stin logged %u error(s) during the frame", file, log.errors);
        rc = EXIT_FAILED;
    }
done:
    image_free(&img);
    scene_context_close(&sc);
    scene_csg_products_free(&products);
    if (plat)
        stin_platform_destroy(plat);
    if (have_scene)
        scene_free(&s);
    return rc;
}

int main(int argc, char **argv)
{
    static options o;
    int i, rc = 0;
    setvbuf(stdout, NULL, _IOLBF, 0); /* piped output appears as it is printed */
    if (!render_parse_args(argc, argv, &o))
        return EXIT_BAD_INPUT; /* its one line says what is wrong; --help lists the options */
    if (o.scene_count <= 1)
        return render_scene(&o);
    /* Several scenes: one process (its start-up, mostly the dynamic
     * linker's, is most of a tiny render's time), a context each. */
    for (i = 0; i < o.scene_count; i++) {
        int one;
        o.scene_path = o.scenes[i];
        one = render_scene(&o);
        printf("scene %s: exit %d\n", o.scene_path, one);
        if (one > rc)
            rc = one;
    }
    return rc;
}
