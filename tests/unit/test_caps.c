/* SPDX-License-Identifier: MIT */
/* Capability parsing from recorded driver strings (stin__caps_parse), exact
 * extension tokens, version clamping, the caps mask, missing entry points,
 * and detection through the fake GL (stin_detect_caps). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "fake_gl.h"
#include "internal.h"

#define BIT(c) STIN_CAP_BIT(STIN_CAP_##c)
#define HAS(caps, c) (((caps).present & BIT(c)) != 0)

/* Parses version, GLSL and extensions as a compatibility context would report them. */
static stin_caps parse(const char *version, const char *glsl, const char *extensions)
{
    stin__caps_input in;
    stin_caps caps;
    memset(&in, 0, sizeof in);
    memset(&caps, 0, sizeof caps);
    in.version = version;
    in.glsl_version = glsl;
    in.extensions = extensions;
    assert_int_equal(stin__caps_parse(&in, &caps), 1);
    return caps;
}

/* ---- versions ------------------------------------------------------------ */
static void test_gl_version_strings_parse_to_digits(void **state)
{
    static const struct {
        const char *s;
        int major, minor;
    } cases[] = {
        {"1.1 Mesa 22.3.6", 1, 1},
        {"2.1 Mesa 22.3.6", 2, 1},
        {"4.5 (Core Profile) Mesa 22.3.6", 4, 5},
        {"3.3.0 NVIDIA 535.54", 3, 3},
        {"4.6.0 NVIDIA", 4, 6},
        {"OpenGL ES 3.2 Mesa 22.3.6", 3, 2},
        {"1.4 (2.1 Mesa 7.0.4)", 1, 4},
        {"10.2", 10, 2},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        stin_caps c = parse(cases[i].s, NULL, NULL);
        assert_int_equal(c.gl_major, cases[i].major);
        assert_int_equal(c.gl_minor, cases[i].minor);
    }
}

static void test_unparseable_gl_version_is_rejected(void **state)
{
    static const char *const bad[] = {"", "Mesa", "4", "4.", "version 3.x"};
    stin__caps_input in;
    stin_caps caps;
    size_t i;
    (void)state;
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        memset(&in, 0, sizeof in);
        in.version = bad[i];
        assert_int_equal(stin__caps_parse(&in, &caps), 0);
    }
    memset(&in, 0, sizeof in); /* NULL: no context current */
    assert_int_equal(stin__caps_parse(&in, &caps), 0);
}

static void test_glsl_version_strings(void **state)
{
    stin_caps c;
    (void)state;
    c = parse("2.1 Mesa 22.3.6", "1.20", NULL);
    assert_int_equal(c.glsl_major, 1);
    assert_int_equal(c.glsl_minor, 2);
    assert_true(HAS(c, GLSL));
    assert_false(HAS(c, GEOMETRY_SHADER));

    c = parse("4.5 (Compatibility Profile) Mesa 22.3.6", "4.50", NULL);
    assert_int_equal(c.glsl_major, 4);
    assert_int_equal(c.glsl_minor, 5);
    assert_true(HAS(c, GLSL));
    assert_true(HAS(c, GEOMETRY_SHADER));

    c = parse("2.1 Mesa 22.3.6", NULL, NULL);
    assert_int_equal(c.glsl_major, 0);
    assert_false(HAS(c, GLSL));
}

/* Mesa reports its best GLSL even on a context created as GL 1.1. */
static void test_glsl_string_on_gl11_context_means_no_glsl(void **state)
{
    stin_caps c;
    (void)state;
    c = parse("1.1 Mesa 22.3.6", "4.50", NULL);
    assert_int_equal(c.gl_major, 1);
    assert_int_equal(c.glsl_major, 0);
    assert_int_equal(c.glsl_minor, 0);
    assert_false(HAS(c, GLSL));
    assert_false(HAS(c, GEOMETRY_SHADER));
}

/* GLSL never exceeds the version that ships with the GL version. */
static void test_glsl_is_clamped_to_the_gl_version(void **state)
{
    stin_caps c;
    (void)state;
    c = parse("2.0 Mesa 22.3.6", "4.50", NULL);
    assert_int_equal(c.glsl_major * 10 + c.glsl_minor, 11);
    c = parse("2.1 Mesa 22.3.6", "4.50", NULL);
    assert_int_equal(c.glsl_major * 10 + c.glsl_minor, 12);
    c = parse("3.2 Mesa 22.3.6", "4.50", NULL);
    assert_int_equal(c.glsl_major * 10 + c.glsl_minor, 15);
    assert_true(HAS(c, GEOMETRY_SHADER));
    c = parse("3.3 Mesa 22.3.6", "4.50", NULL);
    assert_int_equal(c.glsl_major * 10 + c.glsl_minor, 33);
}

static void test_versions_enable_core_capabilities(void **state)
{
    stin_caps c;
    (void)state;
    c = parse("1.1 Mesa 22.3.6", NULL, "");
    assert_int_equal(c.present, BIT(STENCIL) | BIT(FIXED_FUNCTION) | BIT(ELEMENT_INDEX_UINT));

    c = parse("1.3 Mesa 22.3.6", NULL, "");
    assert_true(HAS(c, MULTITEXTURE) && HAS(c, TEXTURE_ENV_COMBINE) && HAS(c, TEXTURE_ENV_DOT3));
    assert_true(HAS(c, TEXTURE_CUBE_MAP) && HAS(c, SEPARATE_SPECULAR));
    assert_false(HAS(c, DEPTH_TEXTURE) || HAS(c, SHADOW) || HAS(c, STENCIL_WRAP));

    c = parse("1.4 Mesa 22.3.6", NULL, "");
    assert_true(HAS(c, DEPTH_TEXTURE) && HAS(c, SHADOW) && HAS(c, STENCIL_WRAP));
    assert_false(HAS(c, VBO) || HAS(c, STENCIL_TWO_SIDE));

    c = parse("3.0 Mesa 22.3.6", "1.30", "");
    assert_true(HAS(c, FBO) && HAS(c, VAO) && HAS(c, FLOAT_TEXTURE) && HAS(c, VBO));
    assert_false(HAS(c, DEPTH_CLAMP) || HAS(c, GEOMETRY_SHADER) || HAS(c, TESSELLATION));
    /* desktop: blending float targets comes with them, "any passed" with counts */
    assert_true(HAS(c, FLOAT_BLEND) && HAS(c, ANY_SAMPLES_QUERY) && HAS(c, OCCLUSION_QUERY));
}

/* A mask that hides sample counts (or float targets) on desktop hides the
 * any-samples queries (or float blending) stin would take from them. */
static void test_desktop_any_samples_and_float_blend_follow(void **state)
{
    stin__caps_input in;
    stin_caps c;
    (void)state;
    memset(&in, 0, sizeof in);
    in.version = "3.3 Mesa 22.3.6";
    in.glsl_version = "3.30";
    in.extensions = "";
    in.caps_mask = BIT(OCCLUSION_QUERY) | BIT(FLOAT_TEXTURE);
    assert_int_equal(stin__caps_parse(&in, &c), 1);
    assert_false(HAS(c, ANY_SAMPLES_QUERY) || HAS(c, FLOAT_BLEND));
    assert_true(HAS(c, GEOMETRY_SHADER));
}

/* ---- extensions ---------------------------------------------------------- */
static void test_extension_prefix_does_not_match(void **state)
{
    stin_caps c;
    (void)state;
    c = parse("1.1 Mesa 22.3.6", NULL, "GL_ARB_shadow_ambient GL_ARB_depth_texture_extra");
    assert_false(HAS(c, SHADOW));
    assert_false(HAS(c, DEPTH_TEXTURE));
    c = parse("1.1 Mesa 22.3.6", NULL, "GL_ARB_shadow_ambient GL_ARB_shadow");
    assert_true(HAS(c, SHADOW));
    /* A token that is a prefix of a listed name does not match either. */
    c = parse("1.1 Mesa 22.3.6", NULL, "GL_ARB_sha GL_EXT_stencil");
    assert_false(HAS(c, SHADOW));
    assert_false(HAS(c, STENCIL_WRAP) || HAS(c, STENCIL_TWO_SIDE));
}

static void test_ext_texture_env_combine_alone(void **state)
{
    stin_caps c;
    (void)state;
    c = parse("1.1 Mesa 22.3.6", NULL, "GL_EXT_texture_env_combine");
    assert_int_equal(c.present, BIT(STENCIL) | BIT(FIXED_FUNCTION) | BIT(TEXTURE_ENV_COMBINE) |
                                    BIT(ELEMENT_INDEX_UINT));
}

static void test_extension_string_spacing(void **state)
{
    stin_caps c;
    (void)state;
    c = parse("1.1 Mesa 22.3.6", NULL,
              "  GL_EXT_stencil_wrap   GL_ARB_multitexture  GL_EXT_stencil_two_side ");
    assert_true(HAS(c, STENCIL_WRAP));
    assert_true(HAS(c, MULTITEXTURE));
    assert_true(HAS(c, STENCIL_TWO_SIDE));
    assert_false(HAS(c, SHADOW));
}

static const char *list_at(void *user, int i) { return ((const char *const *)user)[i]; }

/* GL 3.0+: one token per glGetStringi; a NULL entry is skipped. */
static void test_extensions_from_indexed_list(void **state)
{
    static const char *const exts[] = {"GL_EXT_stencil_two_side_x", NULL, "GL_ARB_tessellation_shader",
                                       "GL_EXT_stencil_two_side"};
    stin__caps_input in;
    stin_caps c;
    (void)state;
    memset(&in, 0, sizeof in);
    in.version = "3.3 (Core Profile) Mesa 22.3.6";
    in.glsl_version = "3.30";
    in.core_profile = 1;
    in.extension_at = list_at;
    in.extension_user = (void *)exts;
    in.extension_count = 3; /* the last entry is outside the count */
    in.extensions = "GL_EXT_stencil_two_side"; /* ignored when the indexed list is used */
    assert_int_equal(stin__caps_parse(&in, &c), 1);
    assert_true(HAS(c, TESSELLATION));
    assert_false(HAS(c, STENCIL_TWO_SIDE));
    in.extension_count = 4;
    assert_int_equal(stin__caps_parse(&in, &c), 1);
    assert_true(HAS(c, STENCIL_TWO_SIDE));
}

static void test_token_in_list_edge_cases(void **state)
{
    (void)state;
    assert_false(stin__token_in_list(NULL, "GL_A", 4));
    assert_false(stin__token_in_list("", "GL_A", 4));
    assert_false(stin__token_in_list("    ", "GL_A", 4));
    assert_false(stin__token_in_list("GL_A", "GL_A", 0));
    assert_true(stin__token_in_list("GL_A", "GL_A", 4));
    assert_true(stin__token_in_list("  GL_A", "GL_A", 4));
    assert_true(stin__token_in_list("GL_A  ", "GL_A", 4));
    assert_true(stin__token_in_list("GL_B  GL_A", "GL_A", 4));
    assert_true(stin__token_in_list("GL_B GL_C GL_A", "GL_A", 4));
    assert_false(stin__token_in_list("GL_AB", "GL_A", 4));  /* list token longer */
    assert_false(stin__token_in_list("GL_A", "GL_AB", 5));  /* list token shorter */
    assert_false(stin__token_in_list("XGL_A", "GL_A", 4));  /* suffix */
    assert_false(stin__token_in_list("GL_AB GL_B", "GL_A", 4));
    /* Only token_len characters of the token count. */
    assert_true(stin__token_in_list("GL_B GL_A", "GL_A GL_C", 4));
}

/* ---- clamping, masking, entry points, profile ---------------------------- */
static void test_max_gl_version_clamps(void **state)
{
    stin__caps_input in;
    stin_caps c;
    (void)state;
    memset(&in, 0, sizeof in);
    in.version = "4.6.0 NVIDIA 535.54.03";
    in.glsl_version = "4.60 NVIDIA";
    in.extensions = "";
    in.max_gl_version = 14;
    assert_int_equal(stin__caps_parse(&in, &c), 1);
    assert_int_equal(c.gl_major, 1);
    assert_int_equal(c.gl_minor, 4);
    assert_int_equal(c.glsl_major, 0);
    assert_true(HAS(c, SHADOW));
    assert_false(HAS(c, VBO) || HAS(c, GLSL) || HAS(c, FBO));

    in.max_gl_version = 21;
    assert_int_equal(stin__caps_parse(&in, &c), 1);
    assert_int_equal(c.gl_major * 10 + c.gl_minor, 21);
    assert_int_equal(c.glsl_major * 10 + c.glsl_minor, 12);
    assert_true(HAS(c, GLSL) && HAS(c, VBO));
    assert_false(HAS(c, GEOMETRY_SHADER) || HAS(c, FBO));

    in.max_gl_version = 50; /* above the context: as reported */
    assert_int_equal(stin__caps_parse(&in, &c), 1);
    assert_int_equal(c.gl_major * 10 + c.gl_minor, 46);
    assert_true(HAS(c, COMPUTE));
}

static void test_caps_mask_hides_present_bits(void **state)
{
    stin__caps_input in;
    stin_caps open, masked;
    (void)state;
    memset(&in, 0, sizeof in);
    in.version = "2.1 Mesa 22.3.6";
    in.glsl_version = "1.20";
    in.extensions = "";
    assert_int_equal(stin__caps_parse(&in, &open), 1);
    assert_int_equal(open.hidden, 0);
    in.caps_mask = BIT(SHADOW) | BIT(GLSL) | BIT(TESSELLATION); /* 2.1 lacks tessellation */
    assert_int_equal(stin__caps_parse(&in, &masked), 1);
    assert_int_equal(masked.hidden, BIT(SHADOW) | BIT(GLSL));
    assert_int_equal(masked.present, open.present & ~(BIT(SHADOW) | BIT(GLSL)));
    assert_int_equal(masked.present & masked.hidden, 0);
}

static void test_missing_entry_points_turn_caps_off(void **state)
{
    unsigned char loaded[STIN_GLFN_COUNT];
    stin__caps_input in;
    stin_caps all, some;
    (void)state;
    memset(loaded, 1, sizeof loaded);
    memset(&in, 0, sizeof in);
    in.version = "2.1 Mesa 22.3.6";
    in.glsl_version = "1.20";
    in.extensions = "GL_ARB_framebuffer_object";
    in.loaded = loaded;
    assert_int_equal(stin__caps_parse(&in, &all), 1);
    assert_true(HAS(all, GLSL) && HAS(all, VBO) && HAS(all, MULTITEXTURE) && HAS(all, FBO));

    loaded[STIN_GLFN_CompileShader] = 0;
    loaded[STIN_GLFN_BufferData] = 0;
    loaded[STIN_GLFN_ClientActiveTexture] = 0;
    loaded[STIN_GLFN_GenerateMipmap] = 0;
    assert_int_equal(stin__caps_parse(&in, &some), 1);
    assert_int_equal(all.present & ~some.present, /* derivatives, frag depth are GLSL's */
                     BIT(GLSL) | BIT(DERIVATIVES) | BIT(FRAG_DEPTH) | BIT(VBO) |
                         BIT(MULTITEXTURE) | BIT(FBO));
    assert_int_equal(some.hidden, 0); /* not hidden by the mask: absent */
}

static void test_core_profile_has_no_fixed_function(void **state)
{
    stin__caps_input in;
    stin_caps c;
    (void)state;
    memset(&in, 0, sizeof in);
    in.version = "4.5 (Core Profile) Mesa 22.3.6";
    in.glsl_version = "4.50";
    in.core_profile = 1;
    assert_int_equal(stin__caps_parse(&in, &c), 1);
    assert_int_equal(c.profile, STIN_GL_PROFILE_CORE);
    assert_false(HAS(c, FIXED_FUNCTION));
    assert_true(HAS(c, GLSL) && HAS(c, GEOMETRY_SHADER) && HAS(c, TESSELLATION));
    in.core_profile = 0;
    assert_int_equal(stin__caps_parse(&in, &c), 1);
    assert_int_equal(c.profile, STIN_GL_PROFILE_COMPATIBILITY);
    assert_true(HAS(c, FIXED_FUNCTION));
}

/* ---- detection through the fake GL --------------------------------------- */
static void test_detect_gl11_through_fake(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL11);
    stin_caps c;
    (void)state;
    cfg.max_lights = 6;
    cfg.max_texture_size = 1024;
    fake_gl_reset(&cfg);
    assert_int_equal(stin_detect_caps(fake_gl_get_proc, NULL, 0, 0, &c), STIN_OK);
    assert_int_equal(c.gl_major * 10 + c.gl_minor, 11);
    assert_int_equal(c.present, BIT(STENCIL) | BIT(FIXED_FUNCTION) | BIT(ELEMENT_INDEX_UINT));
    assert_int_equal(c.max_lights, 6);
    assert_int_equal(c.max_texture_size, 1024);
    assert_int_equal(c.stencil_bits, 8);
    assert_int_equal(c.max_texture_units, 1);
    assert_string_equal(c.renderer, "stin fake GL");
}

static void test_detect_without_stencil_bits_has_no_stencil(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL11);
    stin_caps c;
    (void)state;
    cfg.stencil_bits = 0;
    fake_gl_reset(&cfg);
    assert_int_equal(stin_detect_caps(fake_gl_get_proc, NULL, 0, 0, &c), STIN_OK);
    assert_false(HAS(c, STENCIL));
    assert_true(HAS(c, FIXED_FUNCTION));
}

static void test_detect_core_uses_indexed_extensions_and_fbo_queries(void **state)
{
    static const char *const exts[] = {"GL_EXT_stencil_two_side", "GL_ARB_shadow_ambient"};
    fake_gl_config cfg = fake_gl_profile(FAKE_GL33_CORE);
    stin_caps c;
    (void)state;
    cfg.extension_list = exts;
    cfg.extension_count = 2;
    cfg.extensions = "GL_ARB_tessellation_shader"; /* a core context does not read this */
    cfg.stencil_bits = 8;
    cfg.max_lights = 8; /* GL_MAX_LIGHTS means nothing on core */
    fake_gl_reset(&cfg);
    assert_int_equal(stin_detect_caps(fake_gl_get_proc, NULL, 0, 0, &c), STIN_OK);
    assert_int_equal(c.profile, STIN_GL_PROFILE_CORE);
    assert_true(HAS(c, STENCIL_TWO_SIDE));
    assert_false(HAS(c, TESSELLATION));
    assert_false(HAS(c, FIXED_FUNCTION));
    assert_true(HAS(c, STENCIL)); /* stencil size from the framebuffer attachment */
    assert_int_equal(c.stencil_bits, 8);
    assert_int_equal(c.max_lights, 0);
    assert_int_equal(c.max_geometry_output_vertices, 256);
    assert_true(HAS(c, VERTEX_TEXTURE_FETCH));
    assert_true(fake_gl.calls[STIN_GLFN_GetStringi] >= 2);
    /* glPatchParameteri resolves, but without GL 4.0 or the extension its
     * limit is not GL's to answer (issue 38: GL_INVALID_ENUM at create) */
    assert_int_equal(fake_gl.gl_errors, 0);
}

static void test_detect_missing_entry_points_through_fake(void **state)
{
    static const char *const missing[] = {"glGenBuffers", "glUseProgram", NULL};
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    stin_caps c;
    (void)state;
    cfg.missing = missing;
    fake_gl_reset(&cfg);
    assert_int_equal(stin_detect_caps(fake_gl_get_proc, NULL, 0, 0, &c), STIN_OK);
    assert_false(HAS(c, VBO));
    assert_false(HAS(c, GLSL));
    assert_false(HAS(c, VERTEX_TEXTURE_FETCH));
    assert_true(HAS(c, FBO) && HAS(c, MULTITEXTURE) && HAS(c, FIXED_FUNCTION));
}

static void test_detect_mask_and_max_version_through_fake(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    stin_caps c;
    (void)state;
    fake_gl_reset(&cfg);
    assert_int_equal(stin_detect_caps(fake_gl_get_proc, NULL, BIT(VERTEX_TEXTURE_FETCH), 14, &c),
                     STIN_OK);
    assert_int_equal(c.gl_major * 10 + c.gl_minor, 14);
    assert_false(HAS(c, GLSL));
    assert_false(HAS(c, VERTEX_TEXTURE_FETCH));
    assert_true(HAS(c, FBO)); /* GL_ARB_framebuffer_object is still in the string */
}

/* hidden is "bits the driver has but caps_mask hid": that includes the bits
 * detection adds from limits (vertex texture fetch). */
static void test_detect_masked_vertex_texture_fetch_is_hidden(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    stin_caps open, masked;
    (void)state;
    fake_gl_reset(&cfg);
    assert_int_equal(stin_detect_caps(fake_gl_get_proc, NULL, 0, 0, &open), STIN_OK);
    assert_true(HAS(open, VERTEX_TEXTURE_FETCH));
    assert_int_equal(stin_detect_caps(fake_gl_get_proc, NULL, BIT(VERTEX_TEXTURE_FETCH), 0, &masked),
                     STIN_OK);
    assert_false(HAS(masked, VERTEX_TEXTURE_FETCH));
    assert_int_equal(masked.hidden, BIT(VERTEX_TEXTURE_FETCH));
}

static void test_detect_without_version_fails(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
    stin_caps c;
    (void)state;
    cfg.version = NULL; /* no current context */
    fake_gl_reset(&cfg);
    assert_int_equal(stin_detect_caps(fake_gl_get_proc, NULL, 0, 0, &c), STIN_ERROR_GL);
    assert_int_equal(stin_detect_caps(NULL, NULL, 0, 0, &c), STIN_ERROR_INVALID_ARGUMENT);
}

/* ---- OpenGL ES ------------------------------------------------------------ */
/* ES 2.0 without OES_standard_derivatives: GLSL, no derivatives */
#define ES20_BARE                                                                        \
    (BIT(STENCIL) | BIT(MULTITEXTURE) | BIT(TEXTURE_CUBE_MAP) | BIT(STENCIL_WRAP) |        \
     BIT(SEPARATE_STENCIL) | BIT(VBO) | BIT(FBO) | BIT(GLSL))
#define ES20_CORE (ES20_BARE | BIT(DERIVATIVES))
#define DERIVATIVES_EXT "GL_OES_standard_derivatives"
#define ES30_CORE                                                                        \
    (ES20_CORE | BIT(VAO) | BIT(DEPTH_TEXTURE) | BIT(SHADOW) | BIT(PACKED_DEPTH_STENCIL) | \
     BIT(ELEMENT_INDEX_UINT) | BIT(FRAG_DEPTH) | BIT(ANY_SAMPLES_QUERY) | BIT(GLSL_150))

static void test_es_version_strings(void **state)
{
    stin_caps c;
    (void)state;
    c = parse("OpenGL ES 3.2 Mesa 22.3.6", "OpenGL ES GLSL ES 3.20", NULL);
    assert_int_equal(c.es, 1);
    assert_int_equal(c.gl_major * 10 + c.gl_minor, 32);
    assert_int_equal(c.glsl_major * 10 + c.glsl_minor, 32);
    assert_int_equal(c.profile, STIN_GL_PROFILE_CORE);
    c = parse("OpenGL ES 2.0 Mesa 22.3.6", "OpenGL ES GLSL ES 1.0.16", DERIVATIVES_EXT);
    assert_int_equal(c.es, 1);
    assert_int_equal(c.gl_major * 10 + c.gl_minor, 20);
    assert_int_equal(c.glsl_major * 10 + c.glsl_minor, 10); /* GLSL ES 1.00 */
    assert_true(HAS(c, GLSL));
    /* a GLSL ES version above the ES version's is capped, as on desktop */
    c = parse("OpenGL ES 3.0 Mesa 22.3.6", "OpenGL ES GLSL ES 3.20", NULL);
    assert_int_equal(c.glsl_major * 10 + c.glsl_minor, 30);
    c = parse("4.5 (Core Profile) Mesa 22.3.6", "4.50", NULL);
    assert_int_equal(c.es, 0);
    c = parse("OpenGL ES-CM 1.1 Mesa 22.3.6", NULL, NULL); /* ES 1.x: nothing stin runs */
    assert_int_equal(c.es, 1);
    assert_int_equal(c.present, 0);
}

/* What each ES version has in core, and never fixed function. */
static void test_es_core_capabilities_by_version(void **state)
{
    stin_caps c;
    (void)state;
    /* derivatives: an extension on ES 2.0 (its GLSL counts without), core from 3.0 */
    c = parse("OpenGL ES 2.0 Mesa", "OpenGL ES GLSL ES 1.0.16", NULL);
    assert_int_equal(c.present, ES20_BARE);
    c = parse("OpenGL ES 2.0 Mesa", "OpenGL ES GLSL ES 1.0.16", DERIVATIVES_EXT);
    assert_int_equal(c.present, ES20_CORE);
    c = parse("OpenGL ES 3.0 Mesa", "OpenGL ES GLSL ES 3.00", NULL);
    assert_int_equal(c.present, ES30_CORE);
    /* float textures are core, rendering into them needs EXT_color_buffer_float */
    c = parse("OpenGL ES 3.0 Mesa", "OpenGL ES GLSL ES 3.00", "GL_EXT_color_buffer_float");
    assert_int_equal(c.present, ES30_CORE | BIT(FLOAT_TEXTURE));
    c = parse("OpenGL ES 3.1 Mesa", "OpenGL ES GLSL ES 3.10", NULL);
    assert_int_equal(c.present, ES30_CORE | BIT(COMPUTE));
    c = parse("OpenGL ES 3.2 Mesa", "OpenGL ES GLSL ES 3.20", "GL_EXT_color_buffer_float");
    assert_int_equal(c.present, ES30_CORE | BIT(COMPUTE) | BIT(FLOAT_TEXTURE) |
                                    BIT(GEOMETRY_SHADER) | BIT(TESSELLATION));
    assert_false(HAS(c, FIXED_FUNCTION));
    /* blending float targets: EXT_float_blend, and only beside rendering them */
    c = parse("OpenGL ES 3.0 Mesa", "OpenGL ES GLSL ES 3.00",
              "GL_EXT_color_buffer_float GL_EXT_float_blend");
    assert_int_equal(c.present, ES30_CORE | BIT(FLOAT_TEXTURE) | BIT(FLOAT_BLEND));
    c = parse("OpenGL ES 3.2 Mesa", "OpenGL ES GLSL ES 3.20", "GL_EXT_float_blend");
    assert_false(HAS(c, FLOAT_BLEND));
    /* any-samples queries but never sample counts on ES */
    assert_true(HAS(c, ANY_SAMPLES_QUERY));
    assert_false(HAS(c, OCCLUSION_QUERY));
    /* WebGL 2 answers a query only after the frame: no any-samples query,
     * neither present nor hidden (docs/web.md) */
    c = parse("OpenGL ES 3.0 (WebGL 2.0 (OpenGL ES 3.0 Chromium))",
              "OpenGL ES GLSL ES 3.00 (WebGL GLSL ES 3.00 (OpenGL ES GLSL ES 3.0 Chromium))",
              NULL);
    assert_int_equal(c.webgl, 1);
    assert_int_equal(c.present, ES30_CORE & ~BIT(ANY_SAMPLES_QUERY));
    assert_false(c.hidden & BIT(ANY_SAMPLES_QUERY));
}

/* ES 2.0's extensions map to the same bits; desktop names mean nothing on
 * ES and ES names nothing on desktop. */
static void test_es_extension_names(void **state)
{
    stin_caps c;
    (void)state;
    c = parse("OpenGL ES 2.0 Mesa", "OpenGL ES GLSL ES 1.0.16",
              "GL_OES_depth_texture GL_OES_packed_depth_stencil GL_OES_vertex_array_object "
              "GL_EXT_occlusion_query_boolean GL_EXT_shadow_samplers GL_OES_texture_float "
              "GL_EXT_color_buffer_float GL_OES_element_index_uint GL_EXT_frag_depth "
              DERIVATIVES_EXT);
    /* any-samples queries are not the sample counts OCCLUSION_QUERY means,
     * and ES 2.0's EXT entry points are not loaded: neither bit */
    assert_int_equal(c.present, ES20_CORE | BIT(DEPTH_TEXTURE) | BIT(PACKED_DEPTH_STENCIL) |
                                    BIT(VAO) | BIT(SHADOW) | BIT(ELEMENT_INDEX_UINT) |
                                    BIT(FRAG_DEPTH));
    /* gl_FragDepth: GLSL ES 1.00 has it only by GL_EXT_frag_depth; every
     * desktop GLSL has it */
    c = parse("OpenGL ES 2.0 Mesa", "OpenGL ES GLSL ES 1.0.16", "GL_OES_depth_texture " DERIVATIVES_EXT);
    assert_false(HAS(c, FRAG_DEPTH));
    c = parse("2.1 Mesa", "1.20", "");
    assert_true(HAS(c, FRAG_DEPTH));
    c = parse("OpenGL ES 2.0 Mesa", "OpenGL ES GLSL ES 1.0.16",
              "GL_ARB_depth_texture GL_ARB_shadow GL_EXT_stencil_two_side GL_ARB_depth_clamp "
              "GL_ARB_texture_env_combine GL_EXT_depth_clamp GL_ARB_shader_objects");
    assert_int_equal(c.present, ES20_BARE);
    c = parse("1.3 Mesa", NULL, "GL_OES_depth_texture GL_OES_packed_depth_stencil");
    assert_false(HAS(c, DEPTH_TEXTURE));
    assert_false(HAS(c, PACKED_DEPTH_STENCIL));
}

/* Fragment derivatives are a capability of their own: core on desktop GLSL
 * and from ES 3.0, OES_standard_derivatives on ES 2.0, never without GLSL;
 * GLSL on ES 2.0 no longer waits for them, and the mask hides them. */
static void test_derivatives_capability(void **state)
{
    stin__caps_input in;
    stin_caps c;
    (void)state;
    c = parse("2.1 Mesa 22.3.6", "1.20", "");
    assert_true(HAS(c, GLSL) && HAS(c, DERIVATIVES));
    c = parse("1.4 Mesa 22.3.6", "4.50", "");
    assert_false(HAS(c, GLSL) || HAS(c, DERIVATIVES));
    c = parse("OpenGL ES 2.0 Mesa 22.3.6", "OpenGL ES GLSL ES 1.0.16", NULL);
    assert_true(HAS(c, GLSL));
    assert_false(HAS(c, DERIVATIVES));
    c = parse("OpenGL ES 2.0 Mesa 22.3.6", "OpenGL ES GLSL ES 1.0.16", DERIVATIVES_EXT);
    assert_true(HAS(c, GLSL) && HAS(c, DERIVATIVES));
    c = parse("OpenGL ES 3.0 Mesa 22.3.6", "OpenGL ES GLSL ES 3.00", NULL);
    assert_true(HAS(c, DERIVATIVES));
    memset(&in, 0, sizeof in);
    in.version = "3.3 Mesa 22.3.6";
    in.glsl_version = "3.30";
    in.caps_mask = BIT(DERIVATIVES);
    assert_int_equal(stin__caps_parse(&in, &c), 1);
    assert_false(HAS(c, DERIVATIVES));
    assert_true(HAS(c, GLSL));
    assert_int_equal(c.hidden, BIT(DERIVATIVES));
}

static void test_es_max_gl_version_clamps(void **state)
{
    stin__caps_input in;
    stin_caps c;
    (void)state;
    memset(&in, 0, sizeof in);
    in.version = "OpenGL ES 3.2 Mesa 22.3.6";
    in.glsl_version = "OpenGL ES GLSL ES 3.20";
    in.max_gl_version = 30;
    assert_int_equal(stin__caps_parse(&in, &c), 1);
    assert_int_equal(c.gl_major * 10 + c.gl_minor, 30);
    assert_int_equal(c.glsl_major * 10 + c.glsl_minor, 30);
    assert_int_equal(c.present, ES30_CORE);
}

/* Drivers resolve desktop-only names on ES too: the loader marks them not
 * loaded there, and capabilities that desktop ties to them stay. */
static void test_es_loader_marks_desktop_only_entry_points(void **state)
{
    fake_gl_config cfg = fake_gl_profile(FAKE_GL33_CORE);
    unsigned char loaded[STIN_GLFN_COUNT];
    stin__gl gl;
    stin_caps c;
    (void)state;
    fake_gl_reset(&cfg);
    stin__gl_load(&gl, fake_gl_get_proc, NULL, loaded);
    assert_true(loaded[STIN_GLFN_ClearDepth] && loaded[STIN_GLFN_PolygonMode]);
    assert_false(loaded[STIN_GLFN_ClearDepthf]); /* ES only: never called on desktop */
    cfg.version = "OpenGL ES 3.0 Mesa 22.3.6";
    cfg.glsl_version = "OpenGL ES GLSL ES 3.00";
    fake_gl_reset(&cfg);
    stin__gl_load(&gl, fake_gl_get_proc, NULL, loaded);
    assert_false(loaded[STIN_GLFN_ClearDepth]);
    assert_null(gl.ClearDepth);
    assert_false(loaded[STIN_GLFN_DepthRange] || loaded[STIN_GLFN_PolygonMode] ||
                 loaded[STIN_GLFN_DrawBuffer] || loaded[STIN_GLFN_LogicOp] ||
                 loaded[STIN_GLFN_TexImage1D] || loaded[STIN_GLFN_ClientActiveTexture] ||
                 loaded[STIN_GLFN_MatrixMode] || loaded[STIN_GLFN_BindFragDataLocation]);
    assert_true(loaded[STIN_GLFN_ClearDepthf] && loaded[STIN_GLFN_DepthRangef]);
    assert_int_equal(stin_detect_caps(fake_gl_get_proc, NULL, 0, 0, &c), STIN_OK);
    assert_int_equal(c.es, 1);
    assert_true(HAS(c, MULTITEXTURE)); /* without glClientActiveTexture */
    assert_false(HAS(c, FIXED_FUNCTION));
    assert_int_equal(c.max_lights, 0);
    assert_int_equal(c.max_clip_planes, 0);
    assert_int_equal(c.max_fragment_uniform_vectors, 1024);
    /* ES 3.1's compute without glGetBufferSubData/glClearBufferData */
    cfg.version = "OpenGL ES 3.2 Mesa 22.3.6";
    cfg.glsl_version = "OpenGL ES GLSL ES 3.20";
    fake_gl_reset(&cfg);
    assert_int_equal(stin_detect_caps(fake_gl_get_proc, NULL, 0, 0, &c), STIN_OK);
    assert_false(HAS(c, COMPUTE));
    assert_true(HAS(c, GEOMETRY_SHADER));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gl_version_strings_parse_to_digits),
        cmocka_unit_test(test_unparseable_gl_version_is_rejected),
        cmocka_unit_test(test_glsl_version_strings),
        cmocka_unit_test(test_glsl_string_on_gl11_context_means_no_glsl),
        cmocka_unit_test(test_glsl_is_clamped_to_the_gl_version),
        cmocka_unit_test(test_desktop_any_samples_and_float_blend_follow),
        cmocka_unit_test(test_versions_enable_core_capabilities),
        cmocka_unit_test(test_extension_prefix_does_not_match),
        cmocka_unit_test(test_ext_texture_env_combine_alone),
        cmocka_unit_test(test_extension_string_spacing),
        cmocka_unit_test(test_extensions_from_indexed_list),
        cmocka_unit_test(test_token_in_list_edge_cases),
        cmocka_unit_test(test_max_gl_version_clamps),
        cmocka_unit_test(test_caps_mask_hides_present_bits),
        cmocka_unit_test(test_missing_entry_points_turn_caps_off),
        cmocka_unit_test(test_core_profile_has_no_fixed_function),
        cmocka_unit_test(test_detect_gl11_through_fake),
        cmocka_unit_test(test_detect_without_stencil_bits_has_no_stencil),
        cmocka_unit_test(test_detect_core_uses_indexed_extensions_and_fbo_queries),
        cmocka_unit_test(test_detect_missing_entry_points_through_fake),
        cmocka_unit_test(test_detect_mask_and_max_version_through_fake),
        cmocka_unit_test(test_detect_masked_vertex_texture_fetch_is_hidden),
        cmocka_unit_test(test_detect_without_version_fails),
        cmocka_unit_test(test_es_version_strings),
        cmocka_unit_test(test_es_core_capabilities_by_version),
        cmocka_unit_test(test_es_extension_names),
        cmocka_unit_test(test_es_max_gl_version_clamps),
        cmocka_unit_test(test_derivatives_capability),
        cmocka_unit_test(test_es_loader_marks_desktop_only_entry_points),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
