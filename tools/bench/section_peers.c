/* SPDX-License-Identifier: MIT */
/* The peers section (issue 36): stin's shadow techniques (the GL4 default
 * vdsm, volume, map-pcf) against OpenSceneGraph 3.6's osgShadow techniques
 * on the same scenes, meshes, camera, light and size, in the bench's one GL
 * context. Per scene every renderer is created, warmed up and then timed
 * frame by frame in turn (the order rotates each round, so drift falls on
 * all alike); a row is the median frame (glFinish included), its ratio to
 * each stin technique's, and the mismatch of its light-0 visibility against
 * the exact Embree reference (peers_vis.h): stin's read from its
 * visibility output, OSG's classified from its shadowed, unshadowed and
 * full-shadow frames. The classifier is checked on stin's own frames,
 * where the visibility output gives the answer. A renderer that cannot
 * run, or whose frame reports an error, is a row saying why. */
#include "bench_options.h"
#include "bench_report.h"
#include "bench_time.h"
#include "peers_rows.h"
#include "stin_platform.h"
#ifdef STIN_BENCH_OSGSHADOW
#include "osgshadow_shim.h"
#endif

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* stin's rows: each technique forced, then the default (auto: vdsm or
 * volumes by measured cost where the context has timer queries) */
enum { STIN_OFF, STIN_VDSM, STIN_VOLUME, STIN_MAP_PCF, STIN_DEFAULT, STIN_ROWS };
/* Frames the default row runs before its timed ones, past the bench's
 * warm-up: enough for the measured choice to time every candidate three
 * times (one frame in two a trial until then), then for two more trials at
 * its default pace of one in 30 frames (a switch needs two won in a row),
 * so the row shows where an application's frames settle. */
#define DEFAULT_SETTLE 100
#define OSG_ROWS 7
#define OSG_OFF STIN_ROWS /* OSG's row without a technique */
#define MAX_ROWS (STIN_ROWS + OSG_ROWS)

static const stin_technique stin_tech[STIN_ROWS] = {
    STIN_TECH_SHADOWS_OFF, STIN_TECH_SHADOWS_VDSM, STIN_TECH_SHADOWS_VOLUME,
    STIN_TECH_SHADOWS_MAP_PCF, STIN_TECH_NONE};
static const char *const stin_name[STIN_ROWS] = {"stin shadows-off", "stin vdsm", "stin volume",
                                                 "stin map-pcf", "stin default"};

typedef struct peers_run {
    bench_env *env;
    scene *s;
    peer_row rows[MAX_ROWS];
    int n;
    uint8_t *img[5]; /* stin's unshadowed and ambient-only frames, three scratch */
    uint8_t *vis[2];
    peers_ref ref;
} peers_run;

static const char *light_kind(const scene *s)
{
    return s->lights[0].type == SCENE_LIGHT_SPOT          ? "spot light"
           : s->lights[0].type == SCENE_LIGHT_DIRECTIONAL ? "directional light"
                                                            : "point light";
}

static void make_rows(peers_run *p, int map_size)
{
    int i;
    memset(p->rows, 0, sizeof p->rows);
    for (i = 0; i < STIN_ROWS; i++) {
        peer_row *r = &p->rows[p->n++];
        snprintf(r->name, sizeof r->name, "%s", stin_name[i]);
        r->technique = (int)stin_tech[i];
        peer_row_create(r, p->env, p->s, map_size);
    }
    for (i = 0; i < OSG_ROWS; i++) {
        peer_row *r = &p->rows[p->n++];
        int t = i ? i - 1 : OSG_ROWS - 1; /* no shadows (OSGS_NONE) first */
#ifdef STIN_BENCH_OSGSHADOW
        snprintf(r->name, sizeof r->name, "OSG %s", osgs_name(t));
#else
        snprintf(r->name, sizeof r->name, "OSG technique %d", t);
#endif
        r->osg = 1;
        r->technique = t;
        if (peer_osg_absent(p->env)) {
            snprintf(r->why, sizeof r->why, "%s", peer_osg_absent(p->env));
            r->failed = 1;
        } else {
            peer_row_create(r, p->env, p->s, map_size);
        }
    }
}

/* A frame of r read back into out; 0 where it failed (r says why). */
static int grab(peers_run *p, peer_row *r, int mode, uint8_t *out)
{
    if (peer_row_frame(r, p->env, mode) < 0)
        return 0;
    if (!stin_platform_read_color(p->env->b.plat, out)) {
        snprintf(r->why, sizeof r->why, "read-back failed");
        r->failed = 1;
        return 0;
    }
    return 1;
}

/* stin's unshadowed and ambient-only frames, then the reference. */
static int reference(peers_run *p, char *err, size_t err_size)
{
    peer_row *off = &p->rows[STIN_OFF];
    float color[3];
    int ok;
    if (off->failed) {
        snprintf(err, err_size, "stin shadows-off: %s", off->why);
        return 0;
    }
    ok = grab(p, off, PEER_SHADOWED, p->img[0]);
    /* the light off (a colour or intensity of 0 is stin's default: white, 1) */
    memcpy(color, p->s->lights[0].color, sizeof color);
    p->s->lights[0].color[0] = p->s->lights[0].color[1] = p->s->lights[0].color[2] = 1e-9f;
    ok = ok && grab(p, off, PEER_SHADOWED, p->img[1]);
    memcpy(p->s->lights[0].color, color, sizeof color);
    if (!ok) {
        snprintf(err, err_size, "stin shadows-off: %s", off->why);
        return 0;
    }
    return peers_ref_create(&p->ref, p->s, p->env->b.width, p->env->b.height, p->img[0],
                            p->img[1], err, err_size);
}

/* The row's visibility against the reference (stin: also the classifier
 * against its visibility output). */
static void judge(peers_run *p, peer_row *r)
{
    int n = p->env->b.width * p->env->b.height;
    if (r->failed || r == &p->rows[STIN_OFF] || r == &p->rows[OSG_OFF])
        return;
    if (!r->osg) {
        if (!grab(p, r, PEER_SHADOWED, p->img[2]) || !grab(p, r, PEER_VISIBILITY, p->img[3]))
            return;
        peers_vis_output(p->img[3], n, p->vis[0]);
        peers_classify(p->img[2], p->img[0], p->img[1], n, p->vis[1]);
        r->disagree = peers_disagree(&p->ref, p->vis[0], p->vis[1]);
        peers_mismatch_of(&p->ref, p->vis[0], &r->mm);
        return;
    }
    if (!grab(p, r, PEER_SHADOWED, p->img[2]) || !grab(p, r, PEER_UNSHADOWED, p->img[3]) ||
        !grab(p, r, PEER_FULL, p->img[4]))
        return;
    peers_classify(p->img[2], p->img[3], p->img[4], n, p->vis[0]);
    peers_mismatch_of(&p->ref, p->vis[0], &r->mm);
}

/* Every live row one frame a round, the order rotated each round. */
static int time_rows(peers_run *p, int frames, char *err, size_t err_size)
{
    double *t = calloc((size_t)(p->n * frames), sizeof *t);
    int k, j, i;
    if (!t) {
        snprintf(err, err_size, "out of memory");
        return 0;
    }
    for (i = 0; i < p->n; i++) /* warm-up: compiled programs, resident buffers */
        for (k = 0; k < (p->env->b.warmup > 0 ? p->env->b.warmup : 1); k++)
            peer_row_frame(&p->rows[i], p->env, PEER_SHADOWED);
    for (k = 0; k < DEFAULT_SETTLE; k++) /* the default's measured choice settles */
        peer_row_frame(&p->rows[STIN_DEFAULT], p->env, PEER_SHADOWED);
    for (k = 0; k < frames; k++)
        for (j = 0; j < p->n; j++) {
            peer_row *r = &p->rows[(j + k) % p->n];
            t[((j + k) % p->n) * frames + k] = peer_row_frame(r, p->env, PEER_SHADOWED);
        }
    for (i = 0; i < p->n; i++)
        if (!p->rows[i].failed)
            p->rows[i].ms = bench_median(t + i * frames, (size_t)frames);
    free(t);
    return 1;
}

static void print_ratio(const peer_row *stin, const peer_row *r)
{
    if (stin->failed || r->failed || r->ms <= 0.0)
        printf(" - |");
    else
        printf(" %.2f |", stin->ms / r->ms);
}

/* The faster of vdsm and volume forced (the default's goal: at most 1.1x
 * it); a huge value where neither ran. */
static double faster_exact(const peers_run *p)
{
    const peer_row *v = &p->rows[STIN_VDSM], *w = &p->rows[STIN_VOLUME];
    double best = 1e30;
    if (!v->failed && v->ms > 0.0)
        best = v->ms;
    if (!w->failed && w->ms > 0.0 && w->ms < best)
        best = w->ms;
    return best;
}

static void print_table(const peers_run *p, const char *label)
{
    int i, k;
    printf("\n### %s: %llu triangles, %s\n\n", label,
           (unsigned long long)scene_triangle_count(p->s), light_kind(p->s));
    printf("| renderer | frame ms | vdsm / it | volume / it | map-pcf / it | wrong %% | "
           "far wrong %% | note |\n|---|---:|---:|---:|---:|---:|---:|---|\n");
    for (i = 0; i < p->n; i++) {
        const peer_row *r = &p->rows[i];
        if (r->failed) {
            printf("| %s | - | - | - | - | - | - | %s |\n", r->name, r->why);
            continue;
        }
        printf("| %s | %.2f |", r->name, r->ms);
        for (k = STIN_VDSM; k <= STIN_MAP_PCF; k++)
            print_ratio(&p->rows[k], r);
        if (i == STIN_OFF || i == OSG_OFF)
            printf(" - | - | unshadowed |\n");
        else if (i == STIN_DEFAULT)
            printf(" %.3f | %.3f | visibility output; %.2fx the faster exact technique "
                   "forced; %s |\n", r->mm.wrong_pct, r->mm.far_pct,
                   r->ms / faster_exact(p), r->note);
        else
            printf(" %.3f | %.3f | %s |\n", r->mm.wrong_pct, r->mm.far_pct,
                   r->osg ? "classified" : "visibility output");
    }
    printf("\nclassifier on stin's frames (pixels where it disagrees with the visibility "
           "output, of %ld judged):", p->ref.judged_n);
    for (i = STIN_VDSM; i < STIN_ROWS; i++)
        if (!p->rows[i].failed)
            printf(" %s %ld;", stin_name[i] + 5, p->rows[i].disagree);
    printf("\n");
    fflush(stdout);
}

/* Where the time goes: each row's frame as its library's unshadowed frame
 * plus the shadows' cost, and stin's GPU time per stage. */
static void print_cost(const peers_run *p)
{
    static const int shown[] = {STIN_STAGE_PREPASS, STIN_STAGE_BASE, STIN_STAGE_SHADOW,
                                STIN_STAGE_LIGHTING};
    int i, k;
    printf("\nwhere the time goes: the frame as its library's unshadowed frame plus the "
           "shadows' cost; stin's GPU time per stage from a second context with timer "
           "queries (median of the same frame count)\n");
    printf("\n| renderer | frame ms | unshadowed ms | shadow cost ms | GPU ms: maps, base, "
           "shadow, lighting |\n|---|---:|---:|---:|---|\n");
    for (i = 0; i < p->n; i++) {
        const peer_row *r = &p->rows[i], *base = &p->rows[r->osg ? OSG_OFF : STIN_OFF];
        if (r->failed || r == base)
            continue;
        printf("| %s | %.2f |", r->name, r->ms);
        if (base->failed)
            printf(" - | - |");
        else
            printf(" %.2f | %.2f |", base->ms, r->ms - base->ms);
        if (!r->staged) {
            printf(" %s |\n", r->osg                ? "-"
                              : i == STIN_DEFAULT ? "(not staged: its frames vary)"
                                                  : "(no timer queries)");
            continue;
        }
        for (k = 0; k < (int)(sizeof shown / sizeof shown[0]); k++)
            printf("%s%.2f", k ? ", " : " ", r->stage_ms[shown[k]]);
        printf(" |\n");
    }
    fflush(stdout);
}

static int one_scene(peers_run *p, const char *path, int frames, int map_size)
{
    char err[512], label[128];
    size_t bytes = (size_t)p->env->b.width * (size_t)p->env->b.height * 4;
    int i, ok = 1;
    p->n = 0;
    for (i = 0; i < 5; i++)
        p->img[i] = malloc(bytes);
    p->vis[0] = malloc(bytes / 4);
    p->vis[1] = malloc(bytes / 4);
    scene_label(path, label, sizeof label);
    make_rows(p, map_size);
    if (!p->img[0] || !p->img[1] || !p->img[2] || !p->img[3] || !p->img[4] || !p->vis[0] ||
        !p->vis[1]) {
        snprintf(err, sizeof err, "out of memory");
        ok = 0;
    } else if ((ok = reference(p, err, sizeof err))) {
        for (i = 1; i < p->n; i++)
            judge(p, &p->rows[i]);
        ok = time_rows(p, frames, err, sizeof err);
        if (ok)
            peer_row_settled(&p->rows[STIN_DEFAULT]);
        for (i = STIN_VDSM; ok && i < STIN_DEFAULT; i++) /* the default's frames vary */
            peer_row_stages(&p->rows[i], p->env, p->s, map_size, frames);
    }
    if (ok) {
        print_table(p, label);
        print_cost(p);
    }
    else
        fprintf(stderr, "stin-bench: peers: %s: %s\n", label, err);
    for (i = 0; i < p->n; i++)
        peer_row_destroy(&p->rows[i]);
    peers_ref_release(&p->ref);
    for (i = 0; i < 5; i++)
        free(p->img[i]);
    free(p->vis[0]);
    free(p->vis[1]);
    return ok;
}

int section_peers(bench_env *env, const scene *own, int *ran)
{
    static peers_run p;
    const options *o = env->o;
    const bench_settings *b = &env->b;
    char list[2048], *tok, *save = NULL;
    const char *absent = peer_osg_absent(env);
    int frames = o->sec[SEC_PEERS].frames;
    (void)own;
    memset(&p, 0, sizeof p);
    p.env = env;
    printf("\n## Peers (issue 36): stin against osgShadow (OpenSceneGraph 3.6), %dx%d, %s, "
           "%s %d.%d %s profile, every map %d texels a side; per renderer the median of %d "
           "frames taken in turn (glFinish per frame, order rotated each round); wrong: "
           "pixels whose light-0 visibility differs from the Embree reference, far: more "
           "than a pixel from a reference shadow edge, both in %% of the image\n",
           b->width, b->height, o->platform, env->caps->renderer, env->caps->gl_major,
           env->caps->gl_minor,
           env->caps->profile == STIN_GL_PROFILE_CORE ? "core" : "compatibility",
           o->peers_map_size, frames);
    if (absent)
        printf("\nosgShadow does not run here: %s; stin's rows alone\n", absent);
    snprintf(list, sizeof list, "%s", o->peers_scenes);
    for (tok = strtok_r(list, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        char err[1024], label[128];
        scene s;
        int ok;
        /* a model missing here (assimp-testmodels not installed) skips its scene */
        scene_label(tok, label, sizeof label);
        if (!scene_load(tok, &s, err, sizeof err)) {
            printf("\n### %s: SKIP (%s)\n", label, err);
            continue;
        }
        if (s.light_count < 1) {
            printf("\n### %s: SKIP (no light)\n", label);
            scene_free(&s);
            continue;
        }
        if (!s.has_camera)
            scene_camera_frame(&s, b->width, b->height, &s.camera);
        p.s = &s;
        ok = one_scene(&p, tok, frames, o->peers_map_size);
        scene_free(&s);
        if (!ok)
            return EXIT_FAILED;
        *ran = 1;
    }
    return 0;
}
