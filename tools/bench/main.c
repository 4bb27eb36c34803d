/* SPDX-License-Identifier: MIT */
/* stin-bench: what libstin costs per frame, printed as markdown tables
 * (docs/benchmarks.md): the sections of bench_sections.c in turn, on one GL
 * context. Options: bench_options.c. */
#include "bench_options.h"
#include "bench_report.h"
#include "raw_gl.h"
#include "scene.h"
#include "stin/stin.h"
#include "stin_platform.h"

#include <stdio.h>
#include <string.h>

/* Every scene the chosen sections read, before any GL work: bad input ends
 * the run before a minute of measuring. */
typedef struct scenes {
    scene list[MAX_SCENES], own[SECTION_COUNT];
    int list_n, own_loaded[SECTION_COUNT];
} scenes;

static int load_scenes(const options *o, scenes *sc)
{
    char err[1024];
    int i;
    for (; sc->list_n < o->scene_count; sc->list_n++)
        if (!scene_load(o->scenes[sc->list_n], &sc->list[sc->list_n], err, sizeof err))
            goto bad;
    for (i = 0; i < SECTION_COUNT; i++) {
        if (!o->sec[i].on || !o->sec[i].scene)
            continue;
        if (!scene_load(o->sec[i].scene, &sc->own[i], err, sizeof err))
            goto bad;
        sc->own_loaded[i] = 1;
    }
    return 1;
bad:
    fprintf(stderr, "stin-bench: %s\n", err);
    return 0;
}

static void free_scenes(scenes *sc)
{
    int i;
    for (i = 0; i < sc->list_n; i++)
        scene_free(&sc->list[i]);
    for (i = 0; i < SECTION_COUNT; i++)
        if (sc->own_loaded[i])
            scene_free(&sc->own[i]);
}

/* The default (NULL profile) compatibility context runs all three tiers; a
 * profile's mask and version cap go into every stin_desc (bench_desc_init). */
static stin_platform *open_context(const options *o, raw_gl *gl, stin_caps *caps)
{
    stin_platform_desc pd;
    stin_platform *plat;
    char err[1024];
    memset(&pd, 0, sizeof pd);
    stin_platform_kind_from_name(o->platform, &pd.kind);
    pd.profile = o->profile ? stin_profile_find(o->profile) : NULL;
    pd.width = o->width;
    pd.height = o->height;
    if (!(plat = stin_platform_create(&pd, err, sizeof err))) {
        fprintf(stderr, "stin-bench: no GL context: %s\n", err);
        return NULL;
    }
    raw_gl_load(gl, stin_platform_get_proc_address, plat);
    if (raw_gl_missing(gl, RAW_NEED_CORE)) {
        fprintf(stderr, "stin-bench: %s did not load\n", raw_gl_missing(gl, RAW_NEED_CORE));
    } else if (stin_detect_caps(stin_platform_get_proc_address, plat,
                                pd.profile ? pd.profile->caps_mask : 0,
                                pd.profile ? pd.profile->max_gl_version : 0, caps) != STIN_OK) {
        fprintf(stderr, "stin-bench: cannot read GL capabilities\n");
    } else {
        return plat;
    }
    stin_platform_destroy(plat);
    return NULL;
}

static int run_sections(bench_env *env, scenes *sc)
{
    int i, rc = 0;
    for (i = 0; i < SECTION_COUNT && rc == 0; i++) {
        int ran = 0;
        if (!env->o->sec[i].on)
            continue;
        rc = bench_sections[i].run(env, env->o->sec[i].scene ? &sc->own[i] : NULL, &ran);
        if (rc == 0 && ran)
            bench_machine_once(env);
    }
    return rc;
}

int main(int argc, char **argv)
{
    static options o;
    static scenes sc; /* large: off the stack */
    stin_platform_kind kind;
    const stin_profile *prof;
    stin_platform *plat;
    raw_gl gl;
    stin_caps caps;
    bench_env env;
    int rc = EXIT_BAD_INPUT;
    if (!options_parse(argc, argv, &o)) {
        options_usage(stderr);
        return EXIT_BAD_INPUT;
    }
    if (!stin_platform_kind_from_name(o.platform, &kind)) {
        fprintf(stderr, "stin-bench: unknown platform '%s' (egl, osmesa)\n", o.platform);
        return EXIT_BAD_INPUT;
    }
    if (!load_scenes(&o, &sc))
        goto done;
    rc = EXIT_FAILED;
    if (!(plat = open_context(&o, &gl, &caps)))
        goto done;
    memset(&env, 0, sizeof env);
    env.b.plat = plat;
    env.b.gl = &gl;
    env.b.width = stin_platform_width(plat);
    env.b.height = stin_platform_height(plat);
    env.b.frames = o.sec[SEC_RAW].frames;
    env.b.warmup = o.warmup;
    env.b.setups = o.sec[SEC_RAW].setups;
    env.b.verbose = o.verbose;
    env.b.shader_dir = o.shader_dir;
    if ((prof = o.profile ? stin_profile_find(o.profile) : NULL)) {
        env.b.caps_mask = prof->caps_mask;
        env.b.max_gl_version = prof->max_gl_version;
    }
    env.caps = &caps;
    env.o = &o;
    env.scenes = sc.list;
    rc = run_sections(&env, &sc);
    stin_platform_destroy(plat);
done:
    free_scenes(&sc);
    return rc;
}
