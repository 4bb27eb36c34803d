/* SPDX-License-Identifier: MIT */
/* The visibility map for the application's own shaders (issue 8 item 2),
 * on four-lights with two more lights (six: two tiles) and on shadow-soft
 * (area lights: fractional visibility), for every shadow technique the tier
 * runs:
 *   - each light's channel of the map equals, on every pixel, the
 *     visibility output (STIN_OUTPUT_VISIBILITY) of a frame with that light
 *     first - the same test as the lit passes, exactly;
 *   - the application's own program with stin_visibility_glsl() and
 *     stin_bind_visibility() reads the same values (GLSL contexts);
 *   - a frame with STIN_EXPORT_VISIBILITY draws the same beauty as one
 *     without and the same map as STIN_EXPORT_VISIBILITY_ONLY;
 *   - against the Embree reference, a light's map differs on at most 3% of
 *     the covered pixels (a loose bound: the exact agreement is the first
 *     check; this one catches a map that is right about nothing, e.g. all
 *     lit), and "off" exports 1 everywhere;
 * and without framebuffer objects or packed depth-stencil (bare OpenGL ES
 * 2.0) the export is refused as documented. On ES the application's
 * program is GLSL ES 1.00 or 3.00 with its own default precision.
 * On glass-panes (coloured transparent panes over a floor; the tier's
 * translucent-shadows technique: deep on GL4, coloured on GL2), per light:
 *   - the map has transmittance tiles (stin_visibility_map.transmittance_tile)
 *     and on at least 500 covered pixels a light's transmittance is coloured
 *     (its channels differ by more than 8/255);
 *   - visibility times transmittance equals, per channel, the visibility
 *     output of a frame with that light first (which multiplies the two in
 *     one pass) within 2/255 - two 8-bit values multiplied - on all but
 *     0.05% of the pixels where an opaque draw is the first hit (the
 *     output draws the panes over them; the map does not);
 *   - the application's stin_shadow_transmittance reads that product
 *     (within 1/255). */
#include "caller_gl.h"
#include "image_test.h"
#include "reference.h"
#include "scene.h"
#include "test_context.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EXTRA_LIGHTS 2
#define REFERENCE_BUDGET 0.03
/* Pixels of a light that may differ from its visibility output, of the
 * covered ones: drawn in another framebuffer (the screen mask), a few edge
 * pixels of the stencil count or of a filtered map lookup (map-pcf,
 * map-depth) round the other way (measured on four-lights: at most 4 for
 * volumes, 27 for map-depth, of 31,641). */
#define EXACT_BUDGET 0.0005
#define FILTERED_BUDGET 0.002

typedef struct vis_run {
    run *r;
    scene *s;
    const caller_gl *gl;
    test_context t;
    const ref_hit *hits;
    const reference *ref;
    GLuint program, vbo, vao;
    uint8_t *map, *map_only, *color, *beauty;
    stin_visibility_map info;
    char failures[512];
    int failed;
} vis_run;

static void note(vis_run *v, const char *fmt, ...)
{
    size_t n = strlen(v->failures);
    va_list ap;
    v->failed = 1;
    if (n + 1 >= sizeof v->failures)
        return;
    va_start(ap, fmt);
    vsnprintf(v->failures + n, sizeof v->failures - n, fmt, ap);
    va_end(ap);
}

/* Lights 0 and 1 again, mirrored in x and moved toward +z: six lights, two tiles. */
static int add_lights(scene *s)
{
    scene_light *l = realloc(s->lights, sizeof *l * (size_t)(s->light_count + EXTRA_LIGHTS));
    int i;
    if (!l)
        return 0;
    s->lights = l;
    for (i = 0; i < EXTRA_LIGHTS; i++) {
        scene_light *n = &l[s->light_count + i];
        *n = l[i];
        n->position[0] = -n->position[0];
        n->position[2] += 1.0f;
        n->direction[0] = -n->direction[0];
    }
    s->light_count += EXTRA_LIGHTS;
    return 1;
}

static uint8_t map_value(const vis_run *v, const uint8_t *map, int light, int x, int y)
{
    int tile = light / 3;
    size_t tx = (size_t)(tile % 2) * v->info.tile_width + (size_t)x;
    size_t ty = (size_t)(tile / 2) * v->info.tile_height + (size_t)y;
    return map[4 * (ty * v->info.width + tx) + (size_t)(light % 3)];
}

/* A frame with the export, the map read back into `into`. */
static int export_frame(vis_run *v, stin_export ex, uint8_t *into)
{
    stin_frame_desc fd;
    size_t bytes;
    test_frame_desc(v->r, v->s, &fd);
    fd.export_visibility = ex;
    if (test_context_frame(&v->t, v->s, &fd, -1) != STIN_OK)
        return 0;
    if (stin_query_visibility_map(v->t.ctx, &v->info) != STIN_OK)
        return 0;
    bytes = (size_t)v->info.width * v->info.height * 4;
    if (v->info.lights != (uint32_t)v->s->light_count ||
        v->info.tile_width != (uint32_t)v->r->width || bytes > (size_t)v->r->width * v->r->height * 16)
        return 0;
    return caller_gl_read_texture(v->gl, caller_gl_dialect(v->r->profile), v->info.texture,
                                  (int)v->info.width, (int)v->info.height, into);
}

static int read_frame(vis_run *v, stin_output out, stin_export ex, int first, uint8_t *into)
{
    stin_frame_desc fd;
    test_frame_desc(v->r, v->s, &fd);
    fd.output = out;
    fd.export_visibility = ex;
    return test_context_frame(&v->t, v->s, &fd, first) == STIN_OK &&
           stin_platform_read_color(v->r->plat, into);
}

/* The application's pass: a full-viewport quad through its own program
 * reading light `light` with the chunk, the map bound on unit 5 while unit
 * 2 is active (which must stay active). */
static int app_pass(vis_run *v, int light)
{
    const caller_gl *gl = v->gl;
    static const float quad[6][4] = {{-1, -1, 0, 1}, {1, -1, 0, 1}, {1, 1, 0, 1},
                                     {-1, -1, 0, 1}, {1, 1, 0, 1},  {-1, 1, 0, 1}};
    GLint after = 0;
    int ok;
    gl->BindFramebuffer(GL_FRAMEBUFFER, stin_platform_framebuffer(v->r->plat));
    gl->Viewport(0, 0, v->r->width, v->r->height);
    gl->UseProgram(v->program);
    gl->Uniform1i(gl->GetUniformLocation(v->program, "light"), light);
    gl->ActiveTexture(GL_TEXTURE0 + 2);
    ok = stin_bind_visibility(v->t.ctx, 5) == STIN_OK;
    gl->GetIntegerv(GL_ACTIVE_TEXTURE, &after);
    if (after != GL_TEXTURE0 + 2)
        note(v, "stin_bind_visibility left unit 0x%x active; ", (unsigned)after);
    gl->ActiveTexture(GL_TEXTURE0);
    if (v->vao)
        gl->BindVertexArray(v->vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, v->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
    gl->VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, NULL);
    gl->EnableVertexAttribArray(0);
    gl->DrawArrays(GL_TRIANGLES, 0, 6);
    gl->DisableVertexAttribArray(0);
    gl->BindBuffer(GL_ARRAY_BUFFER, 0);
    if (v->vao)
        gl->BindVertexArray(0);
    gl->UseProgram(0);
    gl->ActiveTexture(GL_TEXTURE0 + 5);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    gl->ActiveTexture(GL_TEXTURE0);
    return ok && stin_platform_read_color(v->r->plat, v->color);
}

/* Pixels where channel `light` of map differs from image (R). */
static long differing(const vis_run *v, const uint8_t *map, int light, const uint8_t *image)
{
    int x, y;
    long n = 0;
    for (y = 0; y < v->r->height; y++)
        for (x = 0; x < v->r->width; x++)
            n += map_value(v, map, light, x, y) != image[4 * ((size_t)y * v->r->width + x)];
    return n;
}

/* Covered pixels whose map value disagrees with the reference (lit above
 * one half), and the covered count; "off" must be 1 wherever covered. */
static long against_reference(const vis_run *v, int light, int off, long *covered)
{
    int x, y;
    long wrong = 0;
    *covered = 0;
    for (y = 0; y < v->r->height; y++)
        for (x = 0; x < v->r->width; x++) {
            const ref_hit *h = &v->hits[(size_t)y * v->r->width + x];
            uint8_t m = map_value(v, v->map, light, x, y);
            if (!h->hit)
                continue;
            (*covered)++;
            if (off)
                wrong += m != 255;
            else
                wrong += (m > 127) != (reference_visibility(v->ref, h, light) > 0.5f);
        }
    return wrong;
}

/* Pixels where two maps differ, over every light's channel. */
static long maps_differ(const vis_run *v, const uint8_t *a, const uint8_t *b)
{
    int li, x, y;
    long n = 0;
    for (li = 0; li < v->s->light_count; li++)
        for (y = 0; y < v->r->height; y++)
            for (x = 0; x < v->r->width; x++)
                n += map_value(v, a, li, x, y) != map_value(v, b, li, x, y);
    return n;
}

/* Each light's channel against the visibility output of a frame with that
 * light first; returns the most differing pixels of a light. */
static long against_visibility_output(vis_run *v, const uint8_t *map)
{
    int li;
    long most = 0, diff;
    for (li = 0; li < v->s->light_count; li++) {
        if (!read_frame(v, STIN_OUTPUT_VISIBILITY, STIN_EXPORT_NONE, li, v->color)) {
            note(v, "light %d's visibility frame failed; ", li);
            continue;
        }
        diff = differing(v, map, li, v->color);
        if (diff > most)
            most = diff;
    }
    return most;
}

/* filtered: the technique's visibility is a filtered lookup (map-pcf,
 * map-depth), which may round a few pixels differently in another pass. */
static void check_technique(vis_run *v, const char *name, int off, int filtered)
{
    size_t pixels = (size_t)v->r->width * v->r->height;
    int li;
    long covered = 0, worst = 0, diff, most, allowed;
    if (!export_frame(v, STIN_EXPORT_VISIBILITY_ONLY, v->map_only)) {
        report(v->r, "FAIL", name, "the exporting frame failed");
        return;
    }
    most = against_visibility_output(v, v->map_only);
    if (!read_frame(v, STIN_OUTPUT_BEAUTY, STIN_EXPORT_NONE, -1, v->color) ||
        !export_frame(v, STIN_EXPORT_VISIBILITY, v->map) ||
        !stin_platform_read_color(v->r->plat, v->beauty))
        note(v, "the beauty frames failed; ");
    else if (memcmp(v->color, v->beauty, pixels * 4) != 0)
        note(v, "the beauty differs with the export; ");
    if ((diff = maps_differ(v, v->map, v->map_only)) != 0)
        note(v, "%ld texels differ between the two export modes; ", diff);
    for (li = 0; li < v->s->light_count; li++) {
        long wrong = against_reference(v, li, off, &covered);
        if (wrong > worst)
            worst = wrong;
        if (!v->program)
            continue;
        if (!app_pass(v, li))
            note(v, "light %d: the application's pass failed; ", li);
        else if ((diff = differing(v, v->map, li, v->color)) != 0)
            note(v, "light %d: the application's shader reads %ld pixels otherwise; ", li, diff);
    }
    allowed = (long)((filtered ? FILTERED_BUDGET : EXACT_BUDGET) * (double)covered);
    if (most > allowed)
        note(v, "up to %ld pixels differ from a light's visibility output (%ld allowed); ", most,
             allowed);
    if (worst > REFERENCE_BUDGET * (double)covered || covered == 0)
        note(v, "up to %ld of %ld covered pixels disagree with the reference; ", worst, covered);
    report(v->r, v->failed ? "FAIL" : "PASS", name,
           "%s%d lights in a %ux%u map; at most %ld pixels of a light differ from its visibility "
           "output (%ld allowed)%s; at most %ld of %ld covered pixels off the reference (budget "
           "%.0f%%)",
           v->failures, v->s->light_count, v->info.width, v->info.height, most, allowed,
           v->program ? ", the application's shader reads the map exactly" : "", worst, covered,
           100.0 * REFERENCE_BUDGET);
}

/* Channel `channel` of light `light`'s transmittance tile. */
static uint8_t transmittance_value(const vis_run *v, const uint8_t *map, int light, int channel,
                                   int x, int y)
{
    uint32_t tile = v->info.transmittance_tile + (uint32_t)light;
    size_t tx = (size_t)(tile % 2) * v->info.tile_width + (size_t)x;
    size_t ty = (size_t)(tile / 2) * v->info.tile_height + (size_t)y;
    return map[4 * (ty * v->info.width + tx) + (size_t)channel];
}

#define TRANSMITTANCE_ROUNDING 2
#define MIN_COLOURED 500

/* Visibility times transmittance of light li at (x, y), channel c (8-bit). */
static int exported_product(const vis_run *v, int li, int c, int x, int y)
{
    return (map_value(v, v->map_only, li, x, y) *
                transmittance_value(v, v->map_only, li, c, x, y) +
            127) /
           255;
}

static void check_transmittance(vis_run *v, stin_tier tier, const char *scene_name)
{
    int w = v->r->width, h = v->r->height, li, x, y, c;
    long covered = 0, coloured = 0, most = 0, app_off = 0;
    stin_technique t;
    char name[160];
    if (!test_context_create(&v->t, v->r, v->s, tier, STIN_TECH_NONE, 0))
        return;
    t = stin_query_choice(v->t.ctx, STIN_FEATURE_TRANSLUCENT_SHADOWS).technique;
    snprintf(name, sizeof name, "%s/%s/visibility-map-transmittance-%s", stin_tier_name(tier),
             scene_name, stin_technique_name(t));
    v->failures[0] = '\0';
    v->failed = 0;
    if (t != STIN_TECH_TRANSLUCENT_DEEP && t != STIN_TECH_TRANSLUCENT_COLOURED) {
        report(v->r, "SKIP", name, "no deep or colour maps here (translucent shadows: %s)",
               stin_technique_name(t));
        test_context_destroy(&v->t);
        return;
    }
    if (!export_frame(v, STIN_EXPORT_VISIBILITY_ONLY, v->map_only) ||
        v->info.transmittance_tile == 0) {
        report(v->r, "FAIL", name, "the export failed or holds no transmittance tile (%u)",
               v->info.transmittance_tile);
        test_context_destroy(&v->t);
        return;
    }
    for (li = 0; li < v->s->light_count; li++) {
        long differ = 0;
        if (!read_frame(v, STIN_OUTPUT_VISIBILITY, STIN_EXPORT_NONE, li, v->color)) {
            note(v, "light %d's visibility frame failed; ", li);
            continue;
        }
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++) {
                const uint8_t *px = v->color + 4 * ((size_t)y * w + x);
                const ref_hit *hit = &v->hits[(size_t)y * w + x];
                int off = 0, tint;
                /* the map is the opaque draws' (the visibility output
                 * draws the panes over them) */
                if (!hit->hit ||
                    v->s->materials[v->s->objects[hit->object].material].color[3] < 1.0f)
                    continue;
                covered += li == 0;
                for (c = 0; c < 3; c++)
                    off |= abs(exported_product(v, li, c, x, y) - px[c]) > TRANSMITTANCE_ROUNDING;
                differ += off;
                tint = abs(transmittance_value(v, v->map_only, li, 0, x, y) -
                           transmittance_value(v, v->map_only, li, 2, x, y));
                coloured += tint > 8;
            }
        most = differ > most ? differ : most;
        if (!v->program)
            continue;
        if (!export_frame(v, STIN_EXPORT_VISIBILITY, v->map_only) || !app_pass(v, li)) {
            note(v, "light %d: the application's pass failed; ", li);
            continue;
        }
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++)
                for (c = 0; c < 3; c++)
                    app_off += abs(exported_product(v, li, c, x, y) -
                                   v->color[4 * ((size_t)y * w + x) + (size_t)c]) > 1;
    }
    if (most > (long)(EXACT_BUDGET * (double)covered))
        note(v, "up to %ld covered pixels of a light differ from its visibility output; ", most);
    if (coloured < MIN_COLOURED)
        note(v, "only %ld pixels have a coloured transmittance; ", coloured);
    if (app_off)
        note(v, "the application's shader reads %ld channels otherwise; ", app_off);
    report(v->r, v->failed ? "FAIL" : "PASS", name,
           "%stransmittance tiles from tile %u; visibility x transmittance differs from the "
           "visibility output (within %d/255) on at most %ld of %ld covered pixels of a light; "
           "%ld coloured pixels (need %d)%s",
           v->failures, v->info.transmittance_tile, TRANSMITTANCE_ROUNDING, most, covered,
           coloured, MIN_COLOURED,
           v->program ? "; the application's shader reads the same product" : "");
    test_context_destroy(&v->t);
}

/* Without framebuffer objects or packed depth-stencil: refused, and nothing
 * to query. */
static void check_refusal(vis_run *v, const char *name)
{
    stin_frame_desc fd;
    stin_visibility_map m;
    stin_result res;
    test_frame_desc(v->r, v->s, &fd);
    fd.export_visibility = STIN_EXPORT_VISIBILITY;
    res = test_context_frame(&v->t, v->s, &fd, -1);
    report(v->r,
           res == STIN_ERROR_UNSUPPORTED &&
                   stin_query_visibility_map(v->t.ctx, &m) == STIN_ERROR_INVALID_STATE
               ? "PASS"
               : "FAIL",
           name, "without framebuffer objects or packed depth-stencil the export is refused "
                 "(result %d)", (int)res);
}

static const char app_shader[] =
    "uniform int light;\n"
    "void main() { c = vec4(stin_shadow_transmittance(light), 1.0); }\n";

/* A program that declares the chunk's names with other types: refused, and
 * nothing bound or set (on main stin set them: STIN_OK, GL_INVALID_OPERATION;
 * a GL error fails the gl-errors line before this one, gl_errors.c). */
static const char mistyped_shader[] =
    "uniform int stin_visibility_lights;\n"
    "uniform vec3 stin_visibility_layout;\n"
    "void main() { c = vec4(stin_visibility_layout, float(stin_visibility_lights)); }\n";

static void check_mistyped(vis_run *v, const char *name)
{
    const caller_gl *gl = v->gl;
    GLuint program = caller_gl_program(gl, caller_gl_dialect(v->r->profile), mistyped_shader);
    GLint bound = -1;
    stin_result res;
    if (!program || !export_frame(v, STIN_EXPORT_VISIBILITY, v->map)) {
        report(v->r, "FAIL", name, "%s", program ? "the exporting frame failed"
                                                 : "the mistyped program did not link");
        if (program)
            gl->DeleteProgram(program);
        return;
    }
    gl->UseProgram(program);
    gl->ActiveTexture(GL_TEXTURE0 + 5);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    res = stin_bind_visibility(v->t.ctx, 5);
    gl->GetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    gl->ActiveTexture(GL_TEXTURE0);
    gl->UseProgram(0);
    gl->DeleteProgram(program);
    report(v->r, res == STIN_ERROR_INVALID_STATE && bound == 0 ? "PASS" : "FAIL", name,
           "a program with an int stin_visibility_lights and a vec3 stin_visibility_layout: %s "
           "(need STIN_ERROR_INVALID_STATE), unit 5's texture %d (need 0: nothing bound)",
           stin_result_name(res), (int)bound);
}

static void run_techniques(vis_run *v, stin_tier tier, const char *scene_name)
{
    static const stin_technique shadows[] = {
        STIN_TECH_SHADOWS_VDSM,      STIN_TECH_SHADOWS_VOLUME,      STIN_TECH_SHADOWS_MAP_PCF,
        STIN_TECH_SHADOWS_MAP_DEPTH, STIN_TECH_SHADOWS_MAP_COMBINE, STIN_TECH_SHADOWS_OFF};
    /* the screen mask the tiles are drawn in (bare OpenGL ES 2.0 lacks the second) */
    const uint64_t export_needs =
        STIN_CAP_BIT(STIN_CAP_FBO) | STIN_CAP_BIT(STIN_CAP_PACKED_DEPTH_STENCIL);
    size_t i;
    int mistyped = 0;
    char name[160];
    for (i = 0; i < sizeof shadows / sizeof shadows[0]; i++) {
        if (!test_context_create(&v->t, v->r, v->s, tier, shadows[i], 1))
            continue; /* not a technique of this tier and profile */
        snprintf(name, sizeof name, "%s/%s/visibility-map-%s", stin_tier_name(tier), scene_name,
                 stin_technique_name(shadows[i]));
        v->failures[0] = '\0';
        v->failed = 0;
        if ((stin_query_caps(v->t.ctx)->present & export_needs) != export_needs) {
            check_refusal(v, name);
        } else {
            check_technique(v, name, shadows[i] == STIN_TECH_SHADOWS_OFF,
                            shadows[i] == STIN_TECH_SHADOWS_MAP_PCF ||
                                shadows[i] == STIN_TECH_SHADOWS_MAP_DEPTH);
            if (v->program && !mistyped++) { /* once a scene: stin_bind_visibility's check */
                snprintf(name, sizeof name, "%s/%s/visibility-map-mistyped",
                         stin_tier_name(tier), scene_name);
                check_mistyped(v, name);
            }
        }
        test_context_destroy(&v->t);
    }
}

void visibility_tests(run *r, stin_tier tier, const char *path)
{
    const char *base = scene_base_name(path);
    vis_run v;
    scene s;
    caller_gl gl;
    reference *ref = NULL;
    ref_hit *hits = NULL;
    char err[256], name[160];
    size_t pixels = (size_t)r->width * r->height;
    const char *chunk = stin_visibility_glsl();
    if (strcmp(base, "four-lights") && strcmp(base, "shadow-soft") && strcmp(base, "glass-panes"))
        return;
    memset(&v, 0, sizeof v);
    snprintf(name, sizeof name, "%s/%s/visibility-map", stin_tier_name(tier), base);
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    caller_gl_load(&gl, r->plat);
    v.r = r;
    v.s = &s;
    v.gl = &gl;
    hits = malloc(sizeof *hits * pixels);
    v.map = malloc(pixels * 16);
    v.map_only = malloc(pixels * 16);
    v.color = malloc(pixels * 4);
    v.beauty = malloc(pixels * 4);
    if (!strcmp(base, "four-lights") && !add_lights(&s))
        report(r, "FAIL", name, "out of memory");
    else if (!hits || !v.map || !v.map_only || !v.color || !v.beauty ||
             !(ref = reference_create(&s, err, sizeof err)) ||
             !reference_primary(ref, r->width, r->height, hits))
        report(r, "FAIL", name, "reference: %s", ref ? "primary rays failed" : err);
    else if (!gl.GetTexImage && !gl.GenFramebuffers)
        report(r, "SKIP", name, "the test reads the map back with glGetTexImage or a "
                                "framebuffer object");
    else {
        char *frag = malloc(strlen(chunk) + sizeof app_shader);
        v.hits = hits;
        v.ref = ref;
        if (frag && !(r->profile->max_gl_version > 0 && r->profile->max_gl_version < 20) &&
            gl.CreateProgram && gl.GenBuffers) {
            strcpy(frag, chunk);
            strcat(frag, app_shader);
            v.program = caller_gl_program(&gl, caller_gl_dialect(r->profile), frag);
            if (!v.program)
                report(r, "FAIL", name, "the application's program with the chunk did not link");
            caller_gl_buffers(&gl, caller_gl_dialect(r->profile), &v.vbo, &v.vao);
        }
        free(frag);
        if (!strcmp(base, "glass-panes"))
            check_transmittance(&v, tier, base);
        else
            run_techniques(&v, tier, base);
        caller_gl_delete(&gl, &v.program, &v.vbo, &v.vao);
    }
    if (ref)
        reference_destroy(ref);
    free(hits);
    free(v.map);
    free(v.map_only);
    free(v.color);
    free(v.beauty);
    scene_free(&s);
}
