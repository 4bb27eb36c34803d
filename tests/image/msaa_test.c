/* SPDX-License-Identifier: MIT */
/*
 * Multisampled targets (issue 39): msaa/halo.json (a lit ball over its own
 * shadow) drawn into the platform's 4x framebuffer object by every shadow
 * technique of the tier, against the exact reference shaded at the
 * target's own sample positions (glGetMultisamplefv) and box-filtered, as
 * the resolve averages the samples. The check is at silhouettes: a sample
 * that took the other surface's visibility (a screen mask read at the
 * pixel, single-sampled) shows as a lit rim on the shadowed floor or a dark
 * one on the ball there, a one-pixel halo. The same check into 2 and 8
 * samples where the context has them (one technique a tier), with the
 * count the driver allocated.
 */
#include "image_test.h"
#include "reference.h"
#include "scene.h"
#include "test_context.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MSAA_SAMPLES 4
#define MSAA_MAX_SAMPLES 16
#define GL_SAMPLE_POSITION_ 0x8E50
/* A sample of the floor's light (0.34 here) in four: 0.085; the reference
 * shades where multisampling does (each surface at the pixel centre), so
 * what is left is 8-bit rounding and float interpolation. */
#define MSAA_TOLERANCE 0.03
/* Of the silhouette band's pixels (within one pixel of a change of object
 * among the samples): measured 0 with per-sample visibility; a halo along
 * the ball's outline over its shadow is 40 or more. */
#define MSAA_MAX_BAND_OVER 3

typedef void (*get_multisamplefv_fn)(unsigned pname, unsigned index, float *val);

typedef struct msaa_case {
    stin_tier tier;
    stin_technique shadows;
} msaa_case;

/* 2x and 8x: one technique a tier (vdsm, GL2's map-pcf, GL1's volumes),
 * which keeps make check's time; the 4x rows run every one. */
static const msaa_case other_counts[] = {
    {STIN_TIER_GL4, STIN_TECH_SHADOWS_VDSM},
    {STIN_TIER_GL2, STIN_TECH_SHADOWS_MAP_PCF},
    {STIN_TIER_GL1, STIN_TECH_SHADOWS_VOLUME},
};

/* The target's sample positions in the pixel (0..1); 0 where the context
 * cannot say (GL 3.2 / ARB_texture_multisample). */
static int sample_positions(run *r, float pos[][2])
{
    get_multisamplefv_fn get = (get_multisamplefv_fn)stin_platform_get_proc_address(
        r->plat, "glGetMultisamplefv");
    int i, n = stin_platform_samples(r->plat);
    if (!get || n < 2 || n > MSAA_MAX_SAMPLES)
        return 0;
    for (i = 0; i < n; i++)
        get(GL_SAMPLE_POSITION_, (unsigned)i, pos[i]);
    return n;
}

/* The visibility rule of each technique's reference (shadow_test.c's). */
static int facets_of(stin_tier tier, stin_technique t)
{
    if (tier == STIN_TIER_GL1)
        return REFERENCE_FACETS_ALL;
    return t == STIN_TECH_SHADOWS_VOLUME ? REFERENCE_FACETS_OPEN : REFERENCE_FACETS_NONE;
}

typedef struct msaa_ref {
    int w, h, n;
    ref_hit *hits;   /* n images of w x h, bottom row first */
    float *colour;   /* w x h x 3: the samples' mean */
    float *vis;      /* n x w x h: every light's visibility at each sample */
    unsigned char *centre_differs; /* w x h: a sample's surface, taken on to the pixel
                                    * centre, has another visibility there */
} msaa_ref;

/* The lights' visibilities at a hit as one number: sum of v_i 2^i. */
static float visibility_code(const scene *s, const reference *ref, const ref_hit *h)
{
    float code = 0.0f;
    int l;
    for (l = 0; h->hit && l < s->light_count && l < 8; l++)
        code += reference_light_visibility(ref, h, l) * (float)(1 << l);
    return code;
}

static int ref_build(const scene *s, stin_tier tier, stin_technique t, int per_vertex,
                     const float pos[][2], int n, msaa_ref *m, char *err, size_t err_size)
{
    reference *ref = reference_create(s, err, err_size);
    size_t px = (size_t)m->w * m->h, i;
    int k, ok = ref != NULL;
    m->n = n;
    m->hits = malloc(sizeof *m->hits * px * (size_t)n);
    m->colour = calloc(px * 3, sizeof(float));
    m->vis = malloc(sizeof(float) * px * (size_t)n);
    m->centre_differs = calloc(px, 1);
    ok = ok && m->hits && m->colour && m->vis && m->centre_differs;
    if (ok)
        reference_facet_terminator(ref, facets_of(tier, t));
    for (k = 0; ok && k < n; k++) {
        ref_hit *hk = m->hits + px * (size_t)k;
        ok = reference_primary_at(ref, m->w, m->h, pos[k][0], pos[k][1], hk);
        for (i = 0; ok && i < px; i++) {
            /* shaded where multisampling shades: the sample's surface taken
             * on to the pixel centre (one fragment a surface a pixel) */
            int x = (int)(i % (size_t)m->w), y = (int)(i / (size_t)m->w);
            ref_hit c = hk[i];
            float rgba[4], *v = &m->vis[px * (size_t)k + i];
            *v = visibility_code(s, ref, &hk[i]);
            if (hk[i].hit && reference_hit_on_plane(ref, m->w, m->h, &hk[i], x + 0.5, y + 0.5, &c) &&
                visibility_code(s, ref, &c) != *v)
                m->centre_differs[i] = 1;
            reference_shade_passes(s, ref, &c, per_vertex, rgba);
            m->colour[3 * i] += rgba[0] / (float)n;
            m->colour[3 * i + 1] += rgba[1] / (float)n;
            m->colour[3 * i + 2] += rgba[2] / (float)n;
        }
    }
    if (ref)
        reference_destroy(ref);
    if (!ok && err[0] == '\0')
        snprintf(err, err_size, "reference failed");
    return ok;
}

static void ref_free(msaa_ref *m)
{
    free(m->hits);
    free(m->colour);
    free(m->vis);
    free(m->centre_differs);
}

static int object_at(const msaa_ref *m, int k, int x, int y)
{
    const ref_hit *h = &m->hits[(size_t)k * m->w * m->h + (size_t)y * m->w + x];
    return h->hit ? h->object : -1;
}

/* Pixel (x, y) has samples of more than one object (or background). */
static int mixed(const msaa_ref *m, int x, int y)
{
    int k, o = object_at(m, 0, x, y);
    for (k = 1; k < m->n; k++)
        if (object_at(m, k, x, y) != o)
            return 1;
    return 0;
}

/* A shadow edge of one object inside the pixel or its 8 neighbours, or
 * between a sample and its surface's point at the pixel centre: the
 * technique decides visibility once a pixel per surface (multisampling
 * shades at the centre), which the box filter of per-sample visibility
 * does not; those pixels are the shadow tests' business, not the halo's. */
static int shadow_edge(const msaa_ref *m, int x, int y)
{
    size_t px = (size_t)m->w * m->h;
    int dx, dy, k, j;
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++) {
            int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= m->w || yy >= m->h)
                continue;
            if (m->centre_differs[(size_t)yy * m->w + xx])
                return 1;
            for (k = 0; k < m->n; k++)
                for (j = 0; j < m->n; j++) {
                    size_t a = px * (size_t)k + (size_t)y * m->w + x;
                    size_t b = px * (size_t)j + (size_t)yy * m->w + xx;
                    if (object_at(m, k, x, y) == object_at(m, j, xx, yy) &&
                        m->vis[a] != m->vis[b])
                        return 1;
                }
        }
    return 0;
}

typedef struct band_result {
    long band, over, compared, compared_over;
    double band_max;
} band_result;

/* rgba: the resolved frame, w x h rows bottom first (the run's width per row). */
static void compare_band(const msaa_ref *m, const uint8_t *rgba, int stride, band_result *b)
{
    int x, y, dx, dy;
    memset(b, 0, sizeof *b);
    for (y = 0; y < m->h; y++)
        for (x = 0; x < m->w; x++) {
            const uint8_t *p = rgba + 4 * ((size_t)y * stride + x);
            const float *c = m->colour + 3 * ((size_t)y * m->w + x);
            double d = 0;
            int c3, near_edge = 0;
            for (c3 = 0; c3 < 3; c3++)
                d = fmax(d, fabs(p[c3] / 255.0 - c[c3]));
            if (shadow_edge(m, x, y))
                continue;
            for (dy = -1; dy <= 1 && !near_edge; dy++)
                for (dx = -1; dx <= 1 && !near_edge; dx++) {
                    int xx = x + dx, yy = y + dy;
                    near_edge = xx >= 0 && yy >= 0 && xx < m->w && yy < m->h && mixed(m, xx, yy);
                }
            if (near_edge) {
                b->band++;
                b->over += d > MSAA_TOLERANCE;
                b->band_max = fmax(b->band_max, d);
            } else {
                b->compared++;
                b->compared_over += d > MSAA_TOLERANCE;
            }
        }
}

/* One frame of the scene at its own size into the platform's target. */
static int render(run *r, const scene *s, stin_tier tier, stin_technique t, uint8_t *rgba,
                  char *why, size_t why_size)
{
    test_context tc;
    stin_frame_desc fd;
    stin_result res;
    if (!test_context_create(&tc, r, s, tier, t, 1)) {
        snprintf(why, why_size, "%s does not run on this tier here", stin_technique_name(t));
        return -1;
    }
    memset(&fd, 0, sizeof fd);
    scene_camera_matrices(&s->camera, s->width, s->height, fd.view, fd.projection);
    fd.viewport[2] = s->width;
    fd.viewport[3] = s->height;
    fd.framebuffer = stin_platform_framebuffer(r->plat);
    memcpy(fd.clear_color, s->background, sizeof fd.clear_color);
    memcpy(fd.ambient, s->ambient, sizeof fd.ambient);
    res = test_context_frame(&tc, s, &fd, -1);
    test_context_destroy(&tc);
    if (res != STIN_OK) {
        snprintf(why, why_size, "frame: %s", stin_result_name(res));
        return 0;
    }
    if (!stin_platform_read_color(r->plat, rgba)) {
        snprintf(why, why_size, "read-back failed");
        return 0;
    }
    return 1;
}

static void save_pair(run *r, const char *name, const uint8_t *rgba, const msaa_ref *m)
{
    image img;
    char path[1024], err[256];
    int x, y, c;
    if (!r->out_dir || !image_alloc(&img, 2 * m->w, m->h, 3))
        return;
    for (y = 0; y < m->h; y++)
        for (x = 0; x < m->w; x++)
            for (c = 0; c < 3; c++) {
                float *row = img.pixels + 3 * (size_t)(m->h - 1 - y) * 2 * m->w;
                row[3 * x + c] = rgba[4 * ((size_t)y * r->width + x) + c] / 255.0f;
                row[3 * (m->w + x) + c] = m->colour[3 * ((size_t)y * m->w + x) + c];
            }
    snprintf(path, sizeof path, "%s/%s-%s-%s.png", r->out_dir, r->platform_name,
             r->profile_name, name);
    for (c = (int)strlen(r->out_dir) + 1; path[c]; c++)
        if (path[c] == '/')
            path[c] = '-';
    if (!image_write(path, &img, 0, err, sizeof err))
        fprintf(stderr, "stin-imagetest: %s\n", err);
    image_free(&img);
}

static void one_case(run *r, const scene *s, const msaa_case *mc, int asked, int per_vertex,
                     const float pos[][2], int n)
{
    char name[128], why[512] = "";
    uint8_t *rgba = malloc((size_t)r->width * r->height * 4);
    msaa_ref m;
    band_result b;
    int got;
    memset(&m, 0, sizeof m);
    m.w = s->width;
    m.h = s->height;
    if (asked == MSAA_SAMPLES)
        snprintf(name, sizeof name, "%s/msaa-%s", stin_tier_name(mc->tier),
                 stin_technique_name(mc->shadows));
    else
        snprintf(name, sizeof name, "%s/msaa-%dx-%s", stin_tier_name(mc->tier), asked,
                 stin_technique_name(mc->shadows));
    got = rgba ? render(r, s, mc->tier, mc->shadows, rgba, why, sizeof why) : 0;
    if (got < 0) {
        report(r, "SKIP", name, "%s", why);
    } else if (!got) {
        report(r, "FAIL", name, "%s", why);
    } else if (!ref_build(s, mc->tier, mc->shadows, per_vertex, pos, n, &m, why, sizeof why)) {
        report(r, "FAIL", name, "reference: %s", why);
    } else {
        compare_band(&m, rgba, r->width, &b);
        report(r, b.over <= MSAA_MAX_BAND_OVER && b.band > 100 ? "PASS" : "FAIL", name,
               "%d samples (%d asked): %ld of %ld silhouette-band pixels beyond %.2f of the "
               "reference at the samples (max %.3f; at most %d); elsewhere %ld of %ld",
               n, asked, b.over, b.band, MSAA_TOLERANCE, b.band_max, MSAA_MAX_BAND_OVER,
               b.compared_over, b.compared);
        if (b.over > MSAA_MAX_BAND_OVER)
            save_pair(r, name, rgba, &m);
    }
    ref_free(&m);
    free(rgba);
}

/* A CSG product into the multisampled target must be refused, not drawn
 * with lines along its faces' edges (stin.h, MULTISAMPLED TARGETS). */
static void csg_refused(run *r, const scene *s, stin_tier tier)
{
    test_context tc;
    stin_frame_desc fd;
    stin_csg_primitive prim;
    stin_csg_node node;
    stin_csg_desc cd;
    stin_result res = STIN_OK;
    char name[64];
    snprintf(name, sizeof name, "%s/msaa-csg-refused", stin_tier_name(tier));
    if (!test_context_create(&tc, r, s, tier, STIN_TECH_NONE, 0)) {
        report(r, "FAIL", name, "no context");
        return;
    }
    memset(&fd, 0, sizeof fd);
    scene_camera_matrices(&s->camera, s->width, s->height, fd.view, fd.projection);
    fd.viewport[2] = s->width;
    fd.viewport[3] = s->height;
    fd.framebuffer = stin_platform_framebuffer(r->plat);
    memset(&prim, 0, sizeof prim);
    prim.mesh = tc.g.meshes[s->objects[0].mesh]; /* the ball: closed */
    prim.material = tc.g.materials[s->objects[0].material];
    memset(&node, 0, sizeof node);
    memset(&cd, 0, sizeof cd);
    cd.primitives = &prim;
    cd.primitive_count = 1;
    cd.nodes = &node;
    cd.node_count = 1;
    if (stin_begin_frame(tc.ctx, &fd) == STIN_OK) {
        res = stin_draw_csg(tc.ctx, &cd);
        stin_end_frame(tc.ctx);
    }
    report(r, res == STIN_ERROR_UNSUPPORTED && stin_query_frame_stats(tc.ctx).csg.dropped == 1
                  ? "PASS" : "FAIL",
           name, "stin_draw_csg into a %d-sample target: %s, %u dropped (want "
           "STIN_ERROR_UNSUPPORTED, 1)", stin_platform_samples(r->plat), stin_result_name(res),
           (unsigned)stin_query_frame_stats(tc.ctx).csg.dropped);
    test_context_destroy(&tc);
}

/* One run a tier: GL4 on the two core profiles, GL2 and the GL1 path on
 * gl21 (the GL 1.x profiles hide framebuffer objects from stin). */
static int runs_here(const run *r, stin_tier tier)
{
    if (tier == STIN_TIER_GL4)
        return !strcmp(r->profile_name, "gl45-core") || !strcmp(r->profile_name, "gl33-core");
    return !strcmp(r->profile_name, "gl21");
}

/* GL1's lighting: Gouraud, with or without a separate specular colour. */
static int gl1_per_vertex(run *r, const scene *s)
{
    test_context tc;
    int per_vertex = 0;
    if (test_context_create(&tc, r, s, STIN_TIER_GL1, STIN_TECH_NONE, 0)) {
        per_vertex = stin_query_caps(tc.ctx)->present & STIN_CAP_BIT(STIN_CAP_SEPARATE_SPECULAR)
                         ? 1
                         : REFERENCE_GOURAUD_SINGLE_COLOR;
        test_context_destroy(&tc);
    }
    return per_vertex;
}

/* The tier's cases of `list` into a target of `asked` samples: SKIP with
 * the platform's reason where the context has no such target (llvmpipe's
 * GL_MAX_SAMPLES is 4). */
static void at_count(run *r, const scene *s, stin_tier tier, int asked, const msaa_case *list,
                     size_t count)
{
    char err[512], name[64];
    float pos[MSAA_MAX_SAMPLES][2];
    int n, per_vertex = tier == STIN_TIER_GL1 ? gl1_per_vertex(r, s) : 0;
    size_t i;
    if (asked == MSAA_SAMPLES)
        snprintf(name, sizeof name, "%s/msaa", stin_tier_name(tier));
    else
        snprintf(name, sizeof name, "%s/msaa-%dx", stin_tier_name(tier), asked);
    if (!stin_platform_set_samples(r->plat, asked, err, sizeof err)) {
        report(r, "SKIP", name, "%s", err);
        return;
    }
    n = sample_positions(r, pos);
    if (!n) {
        report(r, "SKIP", name, "the context cannot say where its samples lie "
                                "(glGetMultisamplefv: GL 3.2 or ARB_texture_multisample)");
    } else {
        for (i = 0; i < count; i++)
            if (list[i].tier == tier)
                one_case(r, s, &list[i], asked, per_vertex, (const float(*)[2])pos, n);
        if (asked == MSAA_SAMPLES && tier != STIN_TIER_GL1)
            csg_refused(r, s, tier);
    }
    if (!stin_platform_set_samples(r->plat, 0, err, sizeof err))
        report(r, "FAIL", name, "back to the default framebuffer: %s", err);
}

void msaa_tests(run *r, stin_tier tier, const char *path)
{
    static const msaa_case cases[] = {
        {STIN_TIER_GL4, STIN_TECH_SHADOWS_VDSM},    {STIN_TIER_GL4, STIN_TECH_SHADOWS_VOLUME},
        {STIN_TIER_GL4, STIN_TECH_SHADOWS_MAP_PCF}, {STIN_TIER_GL2, STIN_TECH_SHADOWS_VOLUME},
        {STIN_TIER_GL2, STIN_TECH_SHADOWS_MAP_PCF}, {STIN_TIER_GL1, STIN_TECH_SHADOWS_VOLUME},
    };
    char file[1024], err[512], name[64];
    const char *slash = strrchr(path, '/');
    scene s;
    if (strcmp(scene_base_name(path), "shadow-overlap"))
        return;
    snprintf(name, sizeof name, "%s/msaa", stin_tier_name(tier));
    if (!runs_here(r, tier))
        return;
    snprintf(file, sizeof file, "%.*smsaa/halo.json", slash ? (int)(slash - path + 1) : 0, path);
    if (!scene_load(file, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    if (s.width > r->width || s.height > r->height) {
        report(r, "SKIP", name, "the run's %dx%d is smaller than the scene's %dx%d", r->width,
               r->height, s.width, s.height);
        scene_free(&s);
        return;
    }
    at_count(r, &s, tier, MSAA_SAMPLES, cases, sizeof cases / sizeof cases[0]);
    at_count(r, &s, tier, 2, other_counts, sizeof other_counts / sizeof other_counts[0]);
    at_count(r, &s, tier, 8, other_counts, sizeof other_counts / sizeof other_counts[0]);
    scene_free(&s);
}
