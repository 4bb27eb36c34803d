/* SPDX-License-Identifier: MIT */
/*
 * The browser front end (WebAssembly, emscripten): a WebGL 2 context on a
 * canvas, a scene pack (tools/common/scene_pack.h) handed to libstin through
 * the tools' scene_gpu, frames into the canvas or into an offscreen
 * framebuffer of the canvas's size, and its read-backs. The memory block
 * stin works in comes from the wasm heap (malloc here, never inside stin);
 * stin loads every GL entry point through emscripten's WebGL 2 table.
 *
 * The page calls the web_* functions (exported; see examples/web/stin.js).
 */
#include "scene_csg.h"
#include "scene_gpu.h"
#include "scene_pack.h"
#include "stin/stin.h"

#include <GLES3/gl3.h>
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define LOG_BYTES 16384

static struct web {
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE gl;
    int width, height;
    GLuint fbo, color, depth;      /* the offscreen target: RGBA8, DEPTH24_STENCIL8 texture */
    GLuint pack_fbo, pack_color;   /* depth packed into RGBA8 */
    GLuint pack_program, pack_vao;
    unsigned char *pack;           /* the scene pack (the arrays point into it) */
    scene s;
    scene_csg_products products;   /* the scene's csg list as stin products */
    float eye[3];                  /* the file's eye, which web_orbit turns about the target */
    scene_gpu g;
    int have_scene, have_gpu;
    stin_context *ctx;
    void *block;
    float projection[16];
    double frame_ms;
    unsigned log_errors;
    char log[LOG_BYTES];
    char choice[1024];
    char frame_status[128];
    char init_error[256];
    /* web_force and web_option's settings for the next web_create */
    stin_technique forced[STIN_FEATURE_COUNT];
    uint32_t deep_map_size, deep_layers;
    uint64_t debug_flags;
    int csg_only;                  /* 0: every product; k: product k - 1 alone */
} w;

static void *get_proc(void *user, const char *name)
{
    (void)user;
    return emscripten_webgl_get_proc_address(name);
}

static void log_line(void *user, stin_log_level level, stin_log_item item, const char *msg)
{
    size_t used = strlen(w.log);
    static const char *const names[] = {"error", "warning", "info"};
    (void)user;
    (void)item;
    if (level == STIN_LOG_LEVEL_ERROR)
        w.log_errors++;
    snprintf(w.log + used, sizeof w.log - used, "%s: %s\n",
             (unsigned)level < 3u ? names[level] : "log", msg);
}

static GLuint texture(GLenum internal, GLenum format, GLenum type)
{
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internal, w.width, w.height, 0, format, type, NULL);
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
}

/* WebGL reads no depth back: a pass samples the depth texture and writes
 * its 24 bits into R, G, B (most significant first). The clamp: 1.0 (the
 * background) times 2^24 - 1, plus a half, rounds to 2^24 in float. */
static GLuint depth_pack_program(void)
{
    static const char *vs = "#version 300 es\n"
                            "out vec2 uv;\n"
                            "void main() {\n"
                            "  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));\n"
                            "  uv = p;\n"
                            "  gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0);\n"
                            "}\n";
    static const char *fs = "#version 300 es\n"
                            "precision highp float;\n"
                            "uniform highp sampler2D depth;\n"
                            "in vec2 uv;\n"
                            "out vec4 color;\n"
                            "void main() {\n"
                            "  uint d = min(uint(texture(depth, uv).r * 16777215.0 + 0.5), 16777215u);\n"
                            "  color = vec4(float(d >> 16u), float((d >> 8u) & 255u),\n"
                            "               float(d & 255u), 255.0) / 255.0;\n"
                            "}\n";
    GLuint p = glCreateProgram(), s[2];
    const char *src[2] = {vs, fs};
    GLint ok = 0;
    int i;
    for (i = 0; i < 2; i++) {
        s[i] = glCreateShader(i ? GL_FRAGMENT_SHADER : GL_VERTEX_SHADER);
        glShaderSource(s[i], 1, &src[i], NULL);
        glCompileShader(s[i]);
        glAttachShader(p, s[i]);
        glDeleteShader(s[i]);
    }
    glLinkProgram(p);
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    return ok ? p : 0;
}

static int framebuffer(GLuint *fbo, GLuint color, GLuint depth)
{
    glGenFramebuffers(1, fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, *fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    if (depth)
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

/* A WebGL 2 context on the canvas (CSS selector, e.g. "#view") with depth
 * and stencil, and the offscreen target of width x height. 1 on success. */
EMSCRIPTEN_KEEPALIVE int web_init(const char *canvas, int width, int height)
{
    EmscriptenWebGLContextAttributes a;
    int ok;
    emscripten_webgl_init_context_attributes(&a);
    a.majorVersion = 2;
    a.minorVersion = 0;
    a.depth = 1;
    a.stencil = 1;
    a.antialias = 0;
    a.alpha = 0;
    a.preserveDrawingBuffer = 1;
    w.gl = emscripten_webgl_create_context(canvas, &a);
    if (w.gl <= 0 || emscripten_webgl_make_context_current(w.gl) != EMSCRIPTEN_RESULT_SUCCESS) {
        /* WebGL 1 is not taken instead: stin's GL2 tier on ES needs ES 3.0
         * here (no client-side arrays, the front end's own GLSL ES 3.00) */
        snprintf(w.init_error, sizeof w.init_error,
                 "no WebGL 2 context with depth and stencil on %s: stin's browser front end "
                 "needs WebGL 2 (OpenGL ES 3.0)", canvas);
        return 0;
    }
    emscripten_set_canvas_element_size(canvas, width, height);
    w.width = width;
    w.height = height;
    w.color = texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE);
    w.depth = texture(GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8);
    w.pack_color = texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE);
    ok = framebuffer(&w.fbo, w.color, w.depth) && framebuffer(&w.pack_fbo, w.pack_color, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    w.pack_program = depth_pack_program();
    glGenVertexArrays(1, &w.pack_vao);
    if (!ok || !w.pack_program)
        snprintf(w.init_error, sizeof w.init_error, "%s",
                 ok ? "the depth read-back program failed to build"
                    : "the offscreen target (RGBA8, DEPTH24_STENCIL8) is incomplete");
    return ok && w.pack_program;
}

/* Why web_init returned 0. */
EMSCRIPTEN_KEEPALIVE const char *web_init_error(void) { return w.init_error; }

static void release_context(void)
{
    if (w.have_gpu)
        scene_gpu_destroy(&w.g, w.ctx);
    if (w.ctx)
        stin_destroy(w.ctx);
    free(w.block);
    w.have_gpu = 0;
    w.ctx = NULL;
    w.block = NULL;
}

/* Takes the scene pack (size bytes from malloc; freed here later). */
EMSCRIPTEN_KEEPALIVE int web_scene(unsigned char *pack, int size)
{
    char err[256];
    release_context();
    if (w.have_scene)
        scene_pack_release(&w.s);
    scene_csg_products_free(&w.products);
    free(w.pack);
    w.pack = pack;
    w.have_scene = scene_pack_read(pack, (size_t)size, &w.s, err, sizeof err);
    if (w.have_scene && !scene_csg_products_build(&w.s, &w.products)) {
        snprintf(err, sizeof err, "%s: out of memory for its csg list", w.s.path);
        scene_pack_release(&w.s);
        w.have_scene = 0;
    }
    if (!w.have_scene) {
        snprintf(w.log, sizeof w.log, "error: %s\n", err);
        return 0;
    }
    memcpy(w.eye, w.s.camera.eye, sizeof w.eye);
    return 1;
}

static void describe_choice(void)
{
    size_t used;
    int f;
    snprintf(w.choice, sizeof w.choice, "tier %s\n", stin_tier_name(stin_query_tier(w.ctx)));
    for (f = 0; f < STIN_FEATURE_COUNT; f++) {
        stin_choice c = stin_query_choice(w.ctx, (stin_feature)f);
        used = strlen(w.choice);
        snprintf(w.choice + used, sizeof w.choice - used, "%s %s%s\n",
                 stin_feature_name((stin_feature)f), stin_technique_name(c.technique),
                 c.fell_back ? " (fell back)" : "");
    }
}

/* A stin context for the scene: tier ("auto", "gl2", "gl4"), the shadow
 * technique by name ("" = stin's choice), the shadow map size (0 = stin's
 * default) and PCF taps a side for every light (0 leaves the lights' own:
 * the pack's, or an earlier call's). The log starts over. 1 on success; else web_log says why. */
EMSCRIPTEN_KEEPALIVE int web_create(const char *tier, const char *shadows, int map_size,
                                    int pcf_kernel)
{
    stin_desc d;
    size_t size;
    char err[256];
    int i;
    release_context();
    w.log[0] = '\0';
    w.choice[0] = '\0';
    w.log_errors = 0;
    if (!w.have_scene)
        return 0;
    memset(&d, 0, sizeof d);
    d.get_proc_address = get_proc;
    d.log = log_line;
    d.tier = !strcmp(tier, "gl2") ? STIN_TIER_GL2 : !strcmp(tier, "gl4") ? STIN_TIER_GL4
                                                                           : STIN_TIER_AUTO;
    if (shadows[0])
        d.techniques[STIN_FEATURE_SHADOWS] = stin_technique_from_name(shadows);
    for (i = 0; i < STIN_FEATURE_COUNT; i++)
        if (w.forced[i] != STIN_TECH_NONE)
            d.techniques[i] = w.forced[i];
    d.translucent.deep_map_size = w.deep_map_size;
    d.translucent.deep_layers = w.deep_layers;
    d.debug_flags = w.debug_flags;
    d.shadows.map_size = (uint32_t)map_size;
    for (i = 0; pcf_kernel && i < w.s.light_count; i++)
        w.s.lights[i].pcf_kernel = pcf_kernel;
    if (!scene_gpu_size_desc_checked(&w.s, &d, err, sizeof err) ||
        scene_csg_products_check(&w.s, &w.products, &d, err, sizeof err) <= 0) {
        log_line(NULL, STIN_LOG_LEVEL_ERROR, STIN_LOG_FALLBACK, err);
        return 0;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, w.fbo); /* stencil bits are probed here */
    size = stin_memory_size(&d);
    w.block = malloc(size);
    if (!w.block || stin_create(&d, w.block, size, &w.ctx) != STIN_OK) {
        release_context();
        return 0;
    }
    describe_choice();
    if (!scene_gpu_create(&w.g, &w.s, w.ctx, err, sizeof err)) {
        log_line(NULL, STIN_LOG_LEVEL_ERROR, STIN_LOG_FALLBACK, err);
        release_context();
        return 0;
    }
    w.have_gpu = 1;
    /* the csg list's products drawn as products (their objects not alone) */
    if (w.csg_only > 0 && w.csg_only <= w.products.count) {
        w.g.csg = &w.products.products[w.csg_only - 1];
        w.g.csg_count = 1;
    } else {
        w.g.csg = w.products.products;
        w.g.csg_count = w.products.count;
    }
    return 1;
}

/* Forces a technique by name (its feature's) in the next web_create's
 * contexts; "" forgets every forced one and the options below. 1 when the
 * name is a technique. */
EMSCRIPTEN_KEEPALIVE int web_force(const char *technique)
{
    stin_technique t = stin_technique_from_name(technique);
    int f;
    if (!technique[0]) {
        for (f = 0; f < STIN_FEATURE_COUNT; f++)
            w.forced[f] = STIN_TECH_NONE;
        w.deep_map_size = w.deep_layers = 0;
        w.debug_flags = 0;
        w.csg_only = 0;
        return 1;
    }
    if (t == STIN_TECH_NONE)
        return 0;
    w.forced[stin_technique_feature(t)] = t;
    return 1;
}

/* A setting for the next web_create: "deep_map_size"
 * (translucent.deep_map_size), "deep_layers" (translucent.deep_layers),
 * "debug" (debug_flags: STIN_DEBUG_* below
 * 2^53, which a JavaScript number holds exactly) or "csg_product" (k >= 0:
 * the csg list's product k drawn alone, the others' objects not drawn;
 * -1: every product). 1 when the name is known. */
EMSCRIPTEN_KEEPALIVE int web_option(const char *name, double value)
{
    if (!strcmp(name, "csg_product"))
        w.csg_only = value < 0 ? 0 : (int)value + 1;
    else if (!strcmp(name, "deep_map_size"))
        w.deep_map_size = (uint32_t)value;
    else if (!strcmp(name, "deep_layers"))
        w.deep_layers = (uint32_t)value;
    else if (!strcmp(name, "debug"))
        w.debug_flags = (uint64_t)value;
    else
        return 0;
    return 1;
}

/* Turns the file's eye about the target: yaw and pitch in degrees, the
 * distance scaled. */
EMSCRIPTEN_KEEPALIVE void web_orbit(float yaw_deg, float pitch_deg, float distance_scale)
{
    scene_camera *c = &w.s.camera;
    double d[3], r, yaw, pitch;
    int k;
    for (k = 0; k < 3; k++)
        d[k] = w.eye[k] - c->target[k];
    r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) * distance_scale;
    yaw = atan2(d[0], d[2]) + yaw_deg * 0.017453292519943295;
    pitch = asin(r > 0 ? d[1] / (r / distance_scale) : 0) + pitch_deg * 0.017453292519943295;
    if (pitch > 1.5)
        pitch = 1.5;
    if (pitch < -1.5)
        pitch = -1.5;
    c->eye[0] = c->target[0] + (float)(r * cos(pitch) * sin(yaw));
    c->eye[1] = c->target[1] + (float)(r * sin(pitch));
    c->eye[2] = c->target[2] + (float)(r * cos(pitch) * cos(yaw));
}

/* WebGL's error flags, cleared: the first one raised (0: none). */
static GLenum gl_error(void)
{
    GLenum first = glGetError(), e = first;
    while (e != GL_NO_ERROR)
        e = glGetError();
    return first;
}

/* One frame: output 0 beauty, 1 normal, 2 visibility of light 0; into the
 * offscreen target (offscreen = 1) or the canvas. 1 on success (STIN_OK,
 * no GL error raised during the frame); web_frame_status says which. */
EMSCRIPTEN_KEEPALIVE int web_frame(int output, int offscreen)
{
    stin_result r;
    GLenum before, during;
    double t0;
    if (!w.have_gpu)
        return 0;
    before = gl_error();
    t0 = emscripten_get_now();
    r = scene_gpu_frame(&w.g, w.ctx, w.width, w.height, (stin_output)output,
                        offscreen ? w.fbo : 0);
    glFinish();
    w.frame_ms = emscripten_get_now() - t0;
    during = gl_error();
    stin_query_frame_projection(w.ctx, w.projection);
    snprintf(w.frame_status, sizeof w.frame_status, "%s, GL error 0x%04x (0x%04x before)",
             stin_result_name(r), during, before);
    return r == STIN_OK && during == GL_NO_ERROR;
}

EMSCRIPTEN_KEEPALIVE const char *web_frame_status(void) { return w.frame_status; }

/* Reads the offscreen target into out (width * height * 4 bytes, rows
 * bottom to top): what 0 the colour, 1 the depth packed into RGB. */
EMSCRIPTEN_KEEPALIVE int web_read(int what, unsigned char *out)
{
    GLint unit = 0;
    if (what == 1) {
        glBindFramebuffer(GL_FRAMEBUFFER, w.pack_fbo);
        glViewport(0, 0, w.width, w.height);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_CULL_FACE);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glUseProgram(w.pack_program);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &unit);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, w.depth);
        glUniform1i(glGetUniformLocation(w.pack_program, "depth"), 0);
        glBindVertexArray(w.pack_vao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glBindTexture(GL_TEXTURE_2D, 0);
        glActiveTexture((GLenum)unit);
        glUseProgram(0);
    } else {
        glBindFramebuffer(GL_FRAMEBUFFER, w.fbo);
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w.width, w.height, GL_RGBA, GL_UNSIGNED_BYTE, out);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return glGetError() == GL_NO_ERROR;
}

EMSCRIPTEN_KEEPALIVE const char *web_log(void) { return w.log; }
EMSCRIPTEN_KEEPALIVE const char *web_choice(void) { return w.choice; }
EMSCRIPTEN_KEEPALIVE unsigned web_log_errors(void) { return w.log_errors; }
EMSCRIPTEN_KEEPALIVE double web_frame_ms(void) { return w.frame_ms; }
/* The last frame's projection (16 floats, column-major): volumes move the
 * far plane to infinity, so depth is unprojected with this one. */
EMSCRIPTEN_KEEPALIVE const float *web_projection(void) { return w.projection; }
EMSCRIPTEN_KEEPALIVE const char *web_scene_path(void) { return w.s.path; }
