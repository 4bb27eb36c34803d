/* SPDX-License-Identifier: MIT */
/* The update section: what a mesh that changes every frame costs, per
 * tier the context runs. On a UV sphere of about 18k and 76k vertices
 * (192 x 94 and 384 x 196 quads; --quick: the 18k one), each timed call is
 * followed by glFinish so that the upload counts:
 *   update   stin_update_mesh with positions and normals (alternating two
 *            poses the caller skinned beforehand: stin's cost alone);
 *   create   stin_destroy_mesh and stin_create_mesh of the same data (what
 *            an application had to do before stin_update_mesh).
 * Per row: the median ms of --update-frames calls each, ns per vertex, and
 * create / update. */
#include "bench_options.h"
#include "bench_report.h"
#include "bench_time.h"
#include "scene_gpu.h"
#include "scene_primitives.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WHAT "mesh updates"

typedef struct update_case {
    const char *name;
    int slices, stacks;
} update_case;

static const update_case cases[] = {{"sphere 18k", 192, 94}, {"sphere 76k", 384, 196}};
enum { CASES = sizeof cases / sizeof cases[0] };

typedef struct update_bench {
    stin_context *ctx;
    void *block;
    const raw_gl *gl;
    scene_mesh pose[2];   /* the same sphere at radius 1 and 1.1 */
    stin_mesh mesh;
} update_bench;

/* One timed call of the row (0 update, 1 destroy and create) in ms;
 * negative on failure. */
static double timed(update_bench *u, int row, int i)
{
    const scene_mesh *m = &u->pose[i & 1];
    double t0 = bench_now_ms();
    stin_result r;
    if (row == 0) {
        stin_mesh_update_desc ud = scene_gpu_mesh_update_desc(m);
        r = stin_update_mesh(u->ctx, u->mesh, &ud);
    } else {
        stin_mesh_desc md = scene_gpu_mesh_desc(m);
        stin_destroy_mesh(u->ctx, u->mesh);
        r = stin_create_mesh(u->ctx, &md, &u->mesh);
    }
    u->gl->Finish();
    return r == STIN_OK ? bench_now_ms() - t0 : -1.0;
}

static int open_case(update_bench *u, const bench_env *env, stin_tier tier, const update_case *c,
                     char *err, size_t err_size)
{
    stin_desc d;
    stin_mesh_desc md;
    size_t bytes;
    int k;
    memset(u, 0, sizeof *u);
    u->gl = env->b.gl;
    if (!scene_prim_sphere(&u->pose[0], 1.0f, c->slices, c->stacks) ||
        !scene_prim_sphere(&u->pose[1], 1.0f, c->slices, c->stacks)) {
        snprintf(err, err_size, "out of memory for the sphere");
        return 0;
    }
    for (k = 0; k < 3 * (int)u->pose[1].vertex_count; k++)
        u->pose[1].positions[k] *= 1.1f;
    bench_desc_init(&env->b, &d);
    d.tier = tier;
    d.max_meshes = 4;
    d.max_vertices = u->pose[0].vertex_count;
    d.max_triangles = d.max_mesh_triangles = u->pose[0].triangle_count;
    bytes = stin_memory_size(&d);
    u->block = malloc(bytes);
    md = scene_gpu_mesh_desc(&u->pose[0]);
    if (!u->block || stin_create(&d, u->block, bytes, &u->ctx) != STIN_OK ||
        stin_create_mesh(u->ctx, &md, &u->mesh) != STIN_OK) {
        snprintf(err, err_size, "stin_create or stin_create_mesh failed (tier %s, %u vertices)",
                 stin_tier_name(tier), u->pose[0].vertex_count);
        return 0;
    }
    return 1;
}

static void close_case(update_bench *u)
{
    if (u->ctx)
        stin_destroy(u->ctx);
    free(u->block);
    scene_mesh_release(&u->pose[0]);
    scene_mesh_release(&u->pose[1]);
}

/* The median of each row over `frames` calls, the rows interleaved. */
static int measure(update_bench *u, int frames, int warmup, double ms[2], char *err,
                   size_t err_size)
{
    double *v = malloc(sizeof(double) * 2u * (size_t)frames);
    int i, row, ok = v != NULL;
    for (i = 0; ok && i < warmup; i++)
        for (row = 0; row < 2; row++)
            ok = timed(u, row, i) >= 0.0;
    for (i = 0; ok && i < frames; i++)
        for (row = 0; row < 2; row++) {
            v[row * frames + i] = timed(u, row, i);
            ok = v[row * frames + i] >= 0.0;
        }
    if (ok) {
        ms[0] = bench_median(v, (size_t)frames);
        ms[1] = bench_median(v + frames, (size_t)frames);
    } else {
        snprintf(err, err_size, "an update or a re-creation failed");
    }
    free(v);
    return ok;
}

int section_update(bench_env *env, const scene *s, int *ran)
{
    stin_tier tiers[3];
    int frames = env->o->sec[SEC_UPDATE].frames, tier_n, t, c, rc = 0;
    int cases_run = env->o->quick ? 1 : CASES, warmup = env->b.warmup > 0 ? env->b.warmup : 1;
    (void)s;
    printf("\n## Mesh updates: stin_update_mesh against destroy and create, each call with "
           "glFinish; median of %d calls (%d warm-up)\n", frames, warmup);
    tier_n = bench_tiers(env, ALL_TIERS, WHAT, "", tiers);
    for (t = 0; t < tier_n && !rc; t++) {
        if (!bench_tier_ok(env, tiers[t], WHAT, &rc))
            continue;
        printf("\n### %s (%s)\n\n| mesh | vertices | update ms | update ns / vertex "
               "| create ms | create ns / vertex | create / update |\n"
               "|---|---:|---:|---:|---:|---:|---:|\n",
               stin_tier_name(tiers[t]), tier_label(tiers[t]));
        for (c = 0; c < cases_run; c++) {
            update_bench u;
            char err[256];
            double ms[2] = {0, 0};
            uint32_t n;
            if (!open_case(&u, env, tiers[t], &cases[c], err, sizeof err) ||
                !measure(&u, frames, warmup, ms, err, sizeof err)) {
                fprintf(stderr, "stin-bench: %s\n", err);
                close_case(&u);
                rc = EXIT_FAILED;
                break;
            }
            n = u.pose[0].vertex_count;
            printf("| %s | %u | %.3f | %.1f | %.3f | %.1f | %.2f |\n", cases[c].name, n, ms[0],
                   1e6 * ms[0] / n, ms[1], 1e6 * ms[1] / n, ms[0] > 0 ? ms[1] / ms[0] : 0.0);
            fflush(stdout);
            close_case(&u);
            *ran = 1;
        }
    }
    bench_machine_once(env);
    return rc;
}
