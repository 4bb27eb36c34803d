/* SPDX-License-Identifier: MIT */
/* The checked build's OpenGL ES audit (src/gl/gl_audit.c) on the fake GL:
 * on an ES 2.0 context a desktop-only enum (GL_DEPTH_CLAMP), an ES 3.0 one
 * (shadow compare, without EXT_shadow_samplers) and an ES 3.2 one are each
 * a GL-audit violation naming the call site; ES 2.0 enums are not, and ES
 * 3.2 takes what ES 3.0 lacked (ES 3.1's image calls too). Linked against libstin_checked.a and
 * compiled with STIN_GL_CHECK, so that GL() here is the library's. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "fake_gl.h"
#include "internal.h"

#if !defined(STIN_GL_CHECK) || !STIN_GL_CHECK
#error "build this test with -DSTIN_GL_CHECK=1 against libstin_checked.a"
#endif

static fake_log log_;
static void *block;

/* A stin context on a fake OpenGL ES context of `version`. */
static stin_context *es_context(const char *version, const char *glsl, const char *extensions)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    stin_desc d;
    stin_context *ctx = NULL;
    size_t bytes;
    cfg.version = version;
    cfg.glsl_version = glsl;
    cfg.extensions = extensions;
    cfg.extension_list = NULL;
    cfg.extension_count = 0;
    fake_gl_reset(&cfg);
    d = fake_gl_desc(&log_);
    d.max_meshes = 2;
    d.max_vertices = 64;
    d.max_triangles = 64;
    d.techniques[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_OFF;
    bytes = stin_memory_size(&d);
    block = malloc(bytes);
    assert_non_null(block);
    assert_int_equal(stin_create(&d, block, bytes, &ctx), STIN_OK);
    assert_int_equal(stin_query_caps(ctx)->es, 1);
    return ctx;
}

static void done(stin_context *ctx)
{
    stin_destroy(ctx);
    free(block);
    block = NULL;
}

static void test_es20_desktop_enum_fails(void **state)
{
    stin_context *ctx = es_context("OpenGL ES 2.0 Mesa 22.3.6", "OpenGL ES GLSL ES 1.0.16",
                                   "GL_OES_standard_derivatives GL_OES_depth_texture");
    uint32_t before = ctx->gl_violations;
    (void)state;
    assert_int_equal(before, 0); /* stin's own set-up passes no ES 3.x enum */
    GL(ctx, Enable)(GL_BLEND);   /* ES 2.0 core */
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, 0);
    assert_int_equal(ctx->gl_violations, 0);
    GL(ctx, Enable)(GL_DEPTH_CLAMP); /* desktop GL only */
    assert_int_equal(ctx->gl_violations, 1);
    assert_true(fake_log_has(&log_, STIN_LOG_GL_ERROR, "glEnable(GL_DEPTH_CLAMP 0x864f)"));
    assert_true(fake_log_has(&log_, STIN_LOG_GL_ERROR, "test_gl_audit.c:"));
    assert_true(fake_log_has(&log_, STIN_LOG_GL_ERROR, "desktop GL only"));
    /* ES 3.0's shadow compare, without EXT_shadow_samplers */
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    assert_int_equal(ctx->gl_violations, 3); /* the parameter and its value */
    /* ES 3.0's read framebuffer and 2D arrays */
    GL(ctx, BindTexture)(GL_TEXTURE_2D_ARRAY, 0);
    assert_int_equal(ctx->gl_violations, 4);
    /* OES_depth_texture brings GL_DEPTH_COMPONENT to ES 2.0 */
    GL(ctx, TexImage2D)(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 1, 1, 0, GL_DEPTH_COMPONENT,
                        GL_UNSIGNED_INT, NULL);
    assert_int_equal(ctx->gl_violations, 4);
    done(ctx);
}

static void test_es32_takes_es3_enums(void **state)
{
    stin_context *ctx = es_context("OpenGL ES 3.2 Mesa 22.3.6", "OpenGL ES GLSL ES 3.20", "");
    (void)state;
    GL(ctx, BindTexture)(GL_TEXTURE_2D_ARRAY, 0);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    GL(ctx, TexParameteri)(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    assert_int_equal(ctx->gl_violations, 0);
    GL(ctx, Enable)(GL_COLOR_LOGIC_OP); /* desktop GL only, on every ES */
    assert_int_equal(ctx->gl_violations, 1);
    assert_true(fake_log_has(&log_, STIN_LOG_GL_ERROR, "OpenGL ES 3.2 lacks it"));
    done(ctx);
}

/* vdsm's area lights on ES 3.2 OR their bits by image atomics: the image
 * calls and their enums are ES 3.1, glMemoryBarrier there without COMPUTE. */
static void test_es_image_atomics(void **state)
{
    stin_context *ctx = es_context("OpenGL ES 3.2 Mesa 22.3.6", "OpenGL ES GLSL ES 3.20", "");
    (void)state;
    GL(ctx, TexStorage2D)(GL_TEXTURE_2D, 1, GL_R32UI, 2, 1);
    GL(ctx, BindImageTexture)(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    GL(ctx, MemoryBarrier)(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    assert_int_equal(ctx->gl_violations, 0);
    done(ctx);
    ctx = es_context("OpenGL ES 3.0 Mesa 22.3.6", "OpenGL ES GLSL ES 3.00", "");
    GL(ctx, BindImageTexture)(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    assert_int_equal(ctx->gl_violations, 2); /* the call and GL_READ_WRITE */
    GL(ctx, MemoryBarrier)(GL_TEXTURE_FETCH_BARRIER_BIT);
    assert_int_equal(ctx->gl_violations, 3);
    done(ctx);
}

static void test_es_enum_table(void **state)
{
    int cap;
    (void)state;
    assert_int_equal(stin__es_enum_version(GL_BLEND, &cap), 20);
    assert_int_equal(stin__es_enum_version(GL_TEXTURE_2D_ARRAY, &cap), 30);
    assert_int_equal(stin__es_enum_version(GL_SHADER_STORAGE_BUFFER, &cap), 31);
    assert_int_equal(stin__es_enum_version(GL_TRIANGLES_ADJACENCY, &cap), 32);
    assert_int_equal(cap, STIN_CAP_GEOMETRY_SHADER);
    assert_int_equal(stin__es_enum_version(GL_DEPTH_COMPONENT, &cap), 30);
    assert_int_equal(cap, STIN_CAP_DEPTH_TEXTURE);
    assert_int_equal(stin__es_enum_version(GL_TEXTURE_1D, &cap), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_es20_desktop_enum_fails),
        cmocka_unit_test(test_es32_takes_es3_enums),
        cmocka_unit_test(test_es_image_atomics),
        cmocka_unit_test(test_es_enum_table),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
