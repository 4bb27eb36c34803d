/* SPDX-License-Identifier: MIT */
/* Tier selection and per-feature technique chains (stin__select,
 * stin_tier_supported, stin_best_tier) on hand-built capabilities shaped like
 * the emulation profiles. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "internal.h"

#define BIT(c) STIN_CAP_BIT(STIN_CAP_##c)

#define GL11_BITS (BIT(STENCIL) | BIT(FIXED_FUNCTION))
#define GL13_BITS                                                                         \
    (GL11_BITS | BIT(MULTITEXTURE) | BIT(TEXTURE_ENV_COMBINE) | BIT(TEXTURE_ENV_DOT3) |   \
     BIT(TEXTURE_CUBE_MAP) | BIT(SEPARATE_SPECULAR))
#define GL14_BITS                                                                         \
    (GL13_BITS | BIT(DEPTH_TEXTURE) | BIT(SHADOW) | BIT(STENCIL_WRAP) |                   \
     BIT(STENCIL_TWO_SIDE) | BIT(DEPTH_CLAMP))
#define GL21_BITS (GL14_BITS | BIT(VBO) | BIT(GLSL) | BIT(SEPARATE_STENCIL) | BIT(FBO) |  \
                   BIT(OCCLUSION_QUERY) | BIT(ANY_SAMPLES_QUERY) | BIT(VERTEX_TEXTURE_FETCH) | \
                   BIT(FRAG_DEPTH) | BIT(DERIVATIVES))
#define GL33_CORE_BITS                                                                    \
    ((GL21_BITS & ~BIT(FIXED_FUNCTION)) | BIT(FLOAT_TEXTURE) | BIT(VAO) | BIT(GEOMETRY_SHADER) | \
     BIT(GLSL_150) | BIT(PACKED_DEPTH_STENCIL) | BIT(FLOAT_BLEND))
#define GL45_CORE_BITS (GL33_CORE_BITS | BIT(TESSELLATION) | BIT(COMPUTE))

static stin_caps caps_with(int gl, int glsl, int core, uint64_t present)
{
    stin_caps c;
    memset(&c, 0, sizeof c);
    c.gl_major = gl / 10;
    c.gl_minor = gl % 10;
    c.glsl_major = glsl / 10;
    c.glsl_minor = glsl % 10;
    c.profile = core ? STIN_GL_PROFILE_CORE : STIN_GL_PROFILE_COMPATIBILITY;
    c.present = present;
    c.stencil_bits = 8;
    return c;
}

typedef struct expected {
    const char *name;
    stin_caps caps;
    stin_tier tier;
    stin_technique lighting;
} expected;

static void test_auto_selection_per_profile(void **state)
{
    const expected cases[] = {
        {"gl11", caps_with(11, 0, 0, GL11_BITS), STIN_TIER_GL1, STIN_TECH_LIGHTING_FIXED},
        {"gl13", caps_with(13, 0, 0, GL13_BITS), STIN_TIER_GL1, STIN_TECH_LIGHTING_FIXED},
        {"gl14", caps_with(14, 0, 0, GL14_BITS), STIN_TIER_GL1, STIN_TECH_LIGHTING_FIXED},
        {"gl21", caps_with(21, 12, 0, GL21_BITS), STIN_TIER_GL2, STIN_TECH_LIGHTING_GLSL110},
        {"gl33", caps_with(33, 33, 1, GL33_CORE_BITS), STIN_TIER_GL4, STIN_TECH_LIGHTING_GLSL150},
        {"gl45", caps_with(45, 45, 1, GL45_CORE_BITS), STIN_TIER_GL4, STIN_TECH_LIGHTING_GLSL150},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        stin__selection sel;
        char msg[256] = "";
        stin_result r = stin__select(&cases[i].caps, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg);
        if (r != STIN_OK || sel.tier != cases[i].tier)
            print_error("profile %s: %s, tier %d, %s\n", cases[i].name, stin_result_name(r),
                        (int)sel.tier, msg);
        assert_int_equal(r, STIN_OK);
        assert_int_equal(sel.tier, cases[i].tier);
        assert_int_equal(stin_best_tier(&cases[i].caps), cases[i].tier);
        assert_int_equal(sel.choice[STIN_FEATURE_LIGHTING].technique, cases[i].lighting);
        assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique,
                         cases[i].tier == STIN_TIER_GL4          ? STIN_TECH_SHADOWS_VDSM
                         : (cases[i].caps.present & BIT(STENCIL)) ? STIN_TECH_SHADOWS_VOLUME
                                                                  : STIN_TECH_SHADOWS_OFF);
        /* DOT3 where the fixed-function path has combine/dot3/cube maps (gl13, gl14);
         * the GLSL tiers take parallax occlusion mapping (GLSL lighting). */
        assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique,
                         cases[i].lighting != STIN_TECH_LIGHTING_FIXED ? STIN_TECH_SURFACE_POM
                         : (cases[i].caps.present & BIT(TEXTURE_ENV_DOT3))
                             ? STIN_TECH_SURFACE_DOT3
                             : STIN_TECH_SURFACE_PLAIN);
        assert_true(sel.choice[STIN_FEATURE_LIGHTING].reason[0] != '\0');
    }
}

static void test_tier_supported_names_missing_capabilities(void **state)
{
    stin_caps gl11 = caps_with(11, 0, 0, GL11_BITS), gl33 = caps_with(33, 33, 1, GL33_CORE_BITS);
    char missing[256];
    (void)state;
    assert_true(stin_tier_supported(&gl11, STIN_TIER_GL1, missing, sizeof missing));
    assert_string_equal(missing, "");
    assert_false(stin_tier_supported(&gl11, STIN_TIER_GL2, missing, sizeof missing));
    assert_string_equal(missing, "GLSL 1.10 shaders");
    assert_false(stin_tier_supported(&gl11, STIN_TIER_GL4, missing, sizeof missing));
    assert_string_equal(missing, "vertex buffer objects, GLSL 1.10 shaders, framebuffer objects, "
                                 "vertex array objects, GLSL 1.50 shaders (GLSL ES 3.00 on ES)");
    /* Core profiles run neither fixed-function tier. */
    assert_false(stin_tier_supported(&gl33, STIN_TIER_GL1, missing, sizeof missing));
    assert_string_equal(missing, stin_cap_name(STIN_CAP_FIXED_FUNCTION));
    assert_false(stin_tier_supported(&gl33, STIN_TIER_GL2, missing, sizeof missing));
    assert_string_equal(missing, stin_cap_name(STIN_CAP_FIXED_FUNCTION));
    assert_true(stin_tier_supported(&gl33, STIN_TIER_GL4, NULL, 0));
    /* AUTO is not a tier that runs. */
    assert_false(stin_tier_supported(&gl33, STIN_TIER_AUTO, NULL, 0));
}

static void test_missing_list_truncates_safely(void **state)
{
    stin_caps none = caps_with(11, 0, 0, 0);
    char missing[12];
    (void)state;
    memset(missing, 'X', sizeof missing);
    assert_false(stin_tier_supported(&none, STIN_TIER_GL4, missing, 8));
    assert_int_equal(missing[7], '\0');
    assert_memory_equal(missing, "vertex ", 7);
    assert_int_equal(missing[8], 'X');
}

static void test_forcing_a_tier_above_the_caps_fails(void **state)
{
    stin_caps gl11 = caps_with(11, 0, 0, GL11_BITS), gl21 = caps_with(21, 12, 0, GL21_BITS);
    stin__selection sel;
    char msg[256];
    (void)state;
    assert_int_equal(stin__select(&gl11, STIN_TIER_GL2, NULL, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, "gl2"));
    assert_non_null(strstr(msg, "GLSL 1.10 shaders"));

    assert_int_equal(stin__select(&gl21, STIN_TIER_GL4, NULL, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, stin_cap_name(STIN_CAP_GLSL_150)));
    assert_non_null(strstr(msg, "vertex array objects"));
    assert_null(strstr(msg, "GLSL 1.10 shaders")); /* it has those */
}

static void test_forcing_a_lower_tier_walks_down(void **state)
{
    stin_caps gl21 = caps_with(21, 12, 0, GL21_BITS);
    stin_caps gl45compat = caps_with(45, 45, 0, GL45_CORE_BITS | BIT(FIXED_FUNCTION));
    stin__selection sel;
    char msg[256];
    const char *reason;
    (void)state;
    assert_int_equal(stin__select(&gl21, STIN_TIER_GL1, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.tier, STIN_TIER_GL1);
    assert_int_equal(sel.choice[STIN_FEATURE_LIGHTING].technique, STIN_TECH_LIGHTING_FIXED);
    /* A tier ceiling the caller chose is not a fallback: the reason names the tier. */
    reason = sel.choice[STIN_FEATURE_LIGHTING].reason;
    assert_null(strstr(reason, "fallback"));
    assert_non_null(strstr(reason, "tier gl1"));

    assert_int_equal(stin__select(&gl45compat, STIN_TIER_GL2, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.tier, STIN_TIER_GL2);
    assert_int_equal(sel.choice[STIN_FEATURE_LIGHTING].technique, STIN_TECH_LIGHTING_GLSL110);
    assert_non_null(strstr(sel.choice[STIN_FEATURE_LIGHTING].reason, "tier gl2"));

    assert_int_equal(stin__select(&gl45compat, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.tier, STIN_TIER_GL4);
    assert_null(strstr(sel.choice[STIN_FEATURE_LIGHTING].reason, "fallback"));
}

static void test_hiding_a_capability_lowers_the_tier(void **state)
{
    stin_caps c = caps_with(45, 45, 0, (GL45_CORE_BITS | BIT(FIXED_FUNCTION)) & ~BIT(GEOMETRY_SHADER));
    (void)state;
    assert_int_equal(stin_best_tier(&c), STIN_TIER_GL4); /* only vdsm needs the geometry stage */
    c.present &= ~BIT(GLSL_150);
    assert_int_equal(stin_best_tier(&c), STIN_TIER_GL2);
    c.present &= ~BIT(GLSL);
    assert_int_equal(stin_best_tier(&c), STIN_TIER_GL1);
    c.present &= ~BIT(FIXED_FUNCTION);
    assert_int_equal(stin_best_tier(&c), STIN_TIER_AUTO);
}

static void test_no_tier_runs(void **state)
{
    stin_caps c = caps_with(45, 45, 1, BIT(STENCIL) | BIT(GLSL));
    stin__selection sel;
    char msg[256];
    (void)state;
    assert_int_equal(stin__select(&c, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, stin_cap_name(STIN_CAP_FIXED_FUNCTION)));
}

static void test_unknown_tier_is_an_invalid_argument(void **state)
{
    stin_caps c = caps_with(45, 45, 1, GL45_CORE_BITS);
    stin__selection sel;
    char msg[256];
    (void)state;
    assert_int_equal(stin__select(&c, (stin_tier)3, NULL, &sel, msg, sizeof msg),
                     STIN_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(msg, "3"));
}

static void test_forced_technique_of_the_wrong_feature(void **state)
{
    stin_caps c = caps_with(21, 12, 0, GL21_BITS);
    stin_technique forced[STIN_FEATURE_COUNT] = {STIN_TECH_NONE, STIN_TECH_NONE, STIN_TECH_NONE};
    stin__selection sel;
    char msg[256];
    (void)state;
    forced[STIN_FEATURE_LIGHTING] = STIN_TECH_SHADOWS_OFF;
    assert_int_equal(stin__select(&c, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(msg, "off"));
    assert_non_null(strstr(msg, "lighting"));

    forced[STIN_FEATURE_LIGHTING] = STIN_TECH_NONE;
    forced[STIN_FEATURE_SURFACE] = STIN_TECH_LIGHTING_FIXED;
    assert_int_equal(stin__select(&c, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_INVALID_ARGUMENT);

    forced[STIN_FEATURE_SURFACE] = (stin_technique)99;
    assert_int_equal(stin__select(&c, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_INVALID_ARGUMENT);
}

static void test_forced_technique_that_runs_is_taken(void **state)
{
    stin_caps c = caps_with(45, 45, 0, GL45_CORE_BITS | BIT(FIXED_FUNCTION));
    stin_technique forced[STIN_FEATURE_COUNT] = {STIN_TECH_LIGHTING_FIXED, STIN_TECH_NONE,
                                                 STIN_TECH_NONE};
    stin__selection sel;
    char msg[256];
    (void)state;
    assert_int_equal(stin__select(&c, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.tier, STIN_TIER_GL4);
    assert_int_equal(sel.choice[STIN_FEATURE_LIGHTING].technique, STIN_TECH_LIGHTING_FIXED);
    assert_non_null(strstr(sel.choice[STIN_FEATURE_LIGHTING].reason, "forced"));
}

static void test_forced_technique_the_caps_cannot_run(void **state)
{
    stin_caps core = caps_with(33, 33, 1, GL33_CORE_BITS);
    stin_technique forced[STIN_FEATURE_COUNT] = {STIN_TECH_LIGHTING_FIXED, STIN_TECH_NONE,
                                                 STIN_TECH_NONE};
    stin__selection sel;
    char msg[256];
    (void)state;
    assert_int_equal(stin__select(&core, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, "fixed-function")); /* the technique */
    assert_non_null(strstr(msg, stin_cap_name(STIN_CAP_FIXED_FUNCTION)));
}

/* vdsm heads the GL4 shadow chain (no stencil needed); on GL2 forcing it is
 * an error that names the geometry shaders it needs, and without float
 * textures the chain goes on to volumes. */
static void test_vdsm_on_gl4_only(void **state)
{
    stin_caps core = caps_with(33, 33, 1, GL33_CORE_BITS);
    stin_caps gl21 = caps_with(21, 12, 0, GL21_BITS);
    stin_technique forced[STIN_FEATURE_COUNT] = {STIN_TECH_NONE, STIN_TECH_SHADOWS_VDSM,
                                                 STIN_TECH_NONE};
    stin__selection sel;
    char msg[256];
    (void)state;
    assert_int_equal(stin__select(&core, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique, STIN_TECH_SHADOWS_VDSM);
    core.present &= ~STIN_CAP_BIT(STIN_CAP_FLOAT_TEXTURE);
    assert_int_equal(stin__select(&core, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique, STIN_TECH_SHADOWS_VOLUME);
    assert_true(sel.choice[STIN_FEATURE_SHADOWS].fell_back);
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, "vdsm"));
    assert_non_null(strstr(msg, stin_cap_name(STIN_CAP_GEOMETRY_SHADER)));
}

/* deep heads the GL4 translucent-shadows chain, with its two units after the
 * shadows'; without float textures it falls back to coloured, GL2's choice
 * (two units), and without FBOs to opaque; forcing deep on GL2 names the
 * tier and what is missing. */
static void test_deep_on_gl4_only(void **state)
{
    stin_caps core = caps_with(33, 33, 1, GL33_CORE_BITS);
    stin_caps gl21 = caps_with(21, 12, 0, GL21_BITS);
    stin_technique forced[STIN_FEATURE_COUNT] = {STIN_TECH_NONE};
    stin__selection sel;
    char msg[256];
    (void)state;
    core.max_texture_image_units = 16;
    assert_int_equal(stin__select(&core, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].technique,
                     STIN_TECH_TRANSLUCENT_DEEP);
    assert_int_equal(sel.translucent_unit, sel.shadow_unit + 1); /* after vdsm's mask */
    /* dual-peel's two units follow, then the vertex stage's height map */
    assert_int_equal(sel.choice[STIN_FEATURE_TRANSPARENCY].technique,
                     STIN_TECH_TRANSPARENCY_DUAL_PEEL);
    assert_int_equal(sel.transparency_unit, sel.translucent_unit + 2);
    assert_int_equal(sel.displace_unit, sel.transparency_unit + 2);
    core.present &= ~STIN_CAP_BIT(STIN_CAP_FLOAT_TEXTURE);
    assert_int_equal(stin__select(&core, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].technique,
                     STIN_TECH_TRANSLUCENT_COLOURED);
    assert_true(sel.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].fell_back);
    assert_non_null(strstr(sel.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].reason, "float textures"));
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].technique,
                     STIN_TECH_TRANSLUCENT_COLOURED);
    assert_int_equal(sel.translucent_unit + 2, sel.units_used); /* its two units */
    /* without FBOs: the opacity threshold, naming what coloured lacks */
    gl21.present &= ~STIN_CAP_BIT(STIN_CAP_FBO);
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].technique,
                     STIN_TECH_TRANSLUCENT_OPAQUE);
    assert_true(sel.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].fell_back);
    assert_non_null(strstr(sel.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].reason,
                           stin_cap_name(STIN_CAP_FBO)));
    gl21.present |= STIN_CAP_BIT(STIN_CAP_FBO);
    forced[STIN_FEATURE_TRANSLUCENT_SHADOWS] = STIN_TECH_TRANSLUCENT_DEEP;
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, "deep needs tier gl4"));
    assert_non_null(strstr(msg, stin_cap_name(STIN_CAP_FLOAT_TEXTURE)));
}

/* Camera transparency's chain: dual-peel (GL4) -> depth-peel -> sorted,
 * each step naming the capability it lacked; forcing dual-peel on GL2 names
 * the tier. */
static void test_transparency_chain(void **state)
{
    stin_caps core = caps_with(33, 33, 1, GL33_CORE_BITS);
    stin_caps gl21 = caps_with(21, 12, 0, GL21_BITS | BIT(PACKED_DEPTH_STENCIL));
    stin_technique forced[STIN_FEATURE_COUNT] = {STIN_TECH_NONE};
    stin__selection sel;
    const stin_choice *c = &sel.choice[STIN_FEATURE_TRANSPARENCY];
    char msg[256];
    (void)state;
    core.max_texture_image_units = 16;
    assert_int_equal(stin__select(&core, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(c->technique, STIN_TECH_TRANSPARENCY_DUAL_PEEL);
    assert_false(c->fell_back);
    core.present &= ~BIT(ANY_SAMPLES_QUERY); /* its early stop */
    assert_int_equal(stin__select(&core, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(c->technique, STIN_TECH_TRANSPARENCY_DEPTH_PEEL);
    assert_true(c->fell_back);
    assert_non_null(strstr(c->reason, stin_cap_name(STIN_CAP_ANY_SAMPLES_QUERY)));
    core.present |= BIT(ANY_SAMPLES_QUERY);
    core.present &= ~BIT(FLOAT_BLEND); /* its RG32F MIN/MAX blending */
    assert_int_equal(stin__select(&core, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(c->technique, STIN_TECH_TRANSPARENCY_DEPTH_PEEL);
    assert_non_null(strstr(c->reason, stin_cap_name(STIN_CAP_FLOAT_BLEND)));
    core.present |= BIT(FLOAT_BLEND);
    core.present &= ~(BIT(FLOAT_TEXTURE) | BIT(PACKED_DEPTH_STENCIL));
    assert_int_equal(stin__select(&core, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(c->technique, STIN_TECH_TRANSPARENCY_SORTED);
    assert_true(c->fell_back);
    /* the reason names the step just above: what depth-peel lacked */
    assert_non_null(strstr(c->reason, stin_cap_name(STIN_CAP_PACKED_DEPTH_STENCIL)));
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(c->technique, STIN_TECH_TRANSPARENCY_DEPTH_PEEL);
    /* its composite writes depth: GLSL ES 1.00 without GL_EXT_frag_depth */
    gl21.present &= ~BIT(FRAG_DEPTH);
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(c->technique, STIN_TECH_TRANSPARENCY_SORTED);
    assert_non_null(strstr(c->reason, stin_cap_name(STIN_CAP_FRAG_DEPTH)));
    gl21.present |= BIT(FRAG_DEPTH);
    forced[STIN_FEATURE_TRANSPARENCY] = STIN_TECH_TRANSPARENCY_DUAL_PEEL;
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, "dual-peel needs tier gl4"));
}

/* A forced technique above the tier ceiling names the tier and what is missing,
 * as separate items. */
static void test_forced_technique_above_the_tier(void **state)
{
    stin_caps gl21 = caps_with(21, 12, 0, GL21_BITS);
    stin_technique forced[STIN_FEATURE_COUNT] = {STIN_TECH_LIGHTING_GLSL150, STIN_TECH_NONE,
                                                 STIN_TECH_NONE};
    stin__selection sel;
    char msg[256];
    const char *tier;
    (void)state;
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, "glsl150-per-pixel"));
    assert_non_null(strstr(msg, "gl4"));
    assert_non_null(strstr(msg, stin_cap_name(STIN_CAP_GLSL_150)));
    /* The tier name is its own word, not run together with the capability list. */
    tier = strstr(msg, "gl4");
    assert_non_null(tier);
    assert_true(tier[3] == '\0' || tier[3] == ' ' || tier[3] == ',' || tier[3] == ';' ||
                tier[3] == ')' || tier[3] == ':');
}

/* DOT3 is drawn by the fixed-function lighting path only: a feature chosen
 * after lighting skips a technique bound to another lighting technique (not
 * a fallback), and forcing it there is refused. */
static void test_surface_follows_the_lighting_technique(void **state)
{
    stin_caps gl21 = caps_with(21, 12, 0, GL21_BITS), gl13 = caps_with(13, 0, 0, GL13_BITS);
    stin_technique forced[STIN_FEATURE_COUNT] = {STIN_TECH_NONE, STIN_TECH_NONE, STIN_TECH_NONE};
    stin__selection sel;
    char msg[256];
    (void)state;
    assert_int_equal(stin__technique_lighting(STIN_TECH_SURFACE_DOT3), STIN_TECH_LIGHTING_FIXED);
    assert_int_equal(stin__technique_lighting(STIN_TECH_SURFACE_PLAIN), STIN_TECH_NONE);
    /* the GLSL surface techniques run with either GLSL lighting, never fixed */
    assert_true(stin__technique_runs_with(STIN_TECH_SURFACE_POM, STIN_TECH_LIGHTING_GLSL110));
    assert_true(stin__technique_runs_with(STIN_TECH_SURFACE_NORMAL, STIN_TECH_LIGHTING_GLSL150));
    assert_false(stin__technique_runs_with(STIN_TECH_SURFACE_PARALLAX, STIN_TECH_LIGHTING_FIXED));
    assert_false(stin__technique_runs_with(STIN_TECH_SURFACE_DOT3, STIN_TECH_LIGHTING_GLSL150));
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique, STIN_TECH_SURFACE_POM);
    assert_null(strstr(sel.choice[STIN_FEATURE_SURFACE].reason, "fallback"));
    /* fixed-function lighting on the GL2 tier: pom is passed over (not a fallback) */
    forced[STIN_FEATURE_LIGHTING] = STIN_TECH_LIGHTING_FIXED;
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique, STIN_TECH_SURFACE_DOT3);
    assert_non_null(strstr(sel.choice[STIN_FEATURE_SURFACE].reason, "pom runs with GLSL lighting"));
    forced[STIN_FEATURE_SURFACE] = STIN_TECH_SURFACE_NORMAL;
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, "needs GLSL lighting"));
    forced[STIN_FEATURE_LIGHTING] = STIN_TECH_NONE;
    forced[STIN_FEATURE_SURFACE] = STIN_TECH_NONE;
    assert_int_equal(stin__select(&gl21, STIN_TIER_GL1, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique, STIN_TECH_SURFACE_DOT3);
    forced[STIN_FEATURE_SURFACE] = STIN_TECH_SURFACE_DOT3;
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, "dot3"));
    assert_non_null(strstr(msg, "glsl110-per-pixel"));
    assert_int_equal(stin__select(&gl13, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique, STIN_TECH_SURFACE_DOT3);
}

static void test_technique_tables(void **state)
{
    (void)state;
    assert_int_equal(stin__technique_feature(STIN_TECH_LIGHTING_GLSL110), STIN_FEATURE_LIGHTING);
    assert_int_equal(stin__technique_feature(STIN_TECH_SHADOWS_OFF), STIN_FEATURE_SHADOWS);
    assert_int_equal(stin__technique_feature((stin_technique)99), STIN_FEATURE_COUNT);
    assert_int_equal(stin__technique_tier(STIN_TECH_LIGHTING_GLSL150), STIN_TIER_GL4);
    assert_int_equal(stin__technique_tier(STIN_TECH_LIGHTING_FIXED), STIN_TIER_GL1);
    assert_int_equal(stin__technique_needs(STIN_TECH_LIGHTING_GLSL110),
                     BIT(GLSL) | BIT(FIXED_FUNCTION));
    assert_int_equal(stin__technique_needs(STIN_TECH_SHADOWS_OFF), 0);
}

/* Every technique has one row; ranks order each chain without ties; the
 * chains read as the header documents them, whatever the enum values. */
static void test_every_technique_has_a_row_and_a_rank(void **state)
{
    static const stin_technique shadows[] = {STIN_TECH_SHADOWS_VDSM,   STIN_TECH_SHADOWS_VOLUME,
                                             STIN_TECH_SHADOWS_MAP_PCF,
                                             STIN_TECH_SHADOWS_MAP_DEPTH,
                                             STIN_TECH_SHADOWS_MAP_COMBINE, STIN_TECH_SHADOWS_OFF};
    stin_technique chain[STIN_TECH_COUNT];
    int t, f, n, i, total = 0;
    (void)state;
    assert_null(stin__technique_row_of(STIN_TECH_NONE));
    for (t = 1; t < STIN_TECH_COUNT; t++)
        assert_non_null(stin__technique_row_of((stin_technique)t));
    for (f = 0; f < STIN_FEATURE_COUNT; f++) {
        n = stin__feature_chain((stin_feature)f, chain);
        assert_true(n >= 1);
        for (i = 1; i < n; i++)
            assert_true(stin__technique_row_of(chain[i - 1])->rank <
                        stin__technique_row_of(chain[i])->rank);
        total += n;
    }
    assert_int_equal(total, STIN_TECH_COUNT - 1);
    n = stin__feature_chain(STIN_FEATURE_SHADOWS, chain);
    assert_int_equal(n, 6);
    for (i = 0; i < n; i++)
        assert_int_equal(chain[i], shadows[i]);
    /* every shadows technique has its module (frame/modules.c), anything
     * else gets off's */
    for (t = 1; t < STIN_TECH_COUNT; t++)
        assert_int_equal(stin__shadow_technique_of((stin_technique)t) != &stin__shadow_off,
                         stin__technique_feature((stin_technique)t) == STIN_FEATURE_SHADOWS &&
                             t != STIN_TECH_SHADOWS_OFF);
}

/* A GL2 part with 3 fragment samplers: map-pcf (one sampler: a light's map
 * or a point light's atlas) and albedo leave one unit, so pom, parallax and
 * normal (2 more each) are passed over for plain, naming the limit;
 * with 1 unit map-pcf itself cannot be forced. Units are placed after
 * the albedo (unit 0) in feature order. */
/* displace conflicts with volume (CPU silhouettes of the undisplaced mesh)
 * where volumes have no depth map to cast displaced draws through (FBOs and
 * depth textures: the conflict's lifting capabilities; without shadow
 * compare the map's test compares in the shader): with them both run by
 * default and may be forced together; without depth textures, beside auto
 * volumes it steps down (logged reason),
 * forcing it moves the shadow chain past volume, forcing both is refused;
 * hidden vertex textures step it down with the capability named. */
static void test_displacement_beside_volumes(void **state)
{
    stin_caps gl21 = caps_with(21, 12, 0, GL21_BITS), gl45 = caps_with(45, 45, 1, GL45_CORE_BITS);
    /* no depth textures (lifts nothing; map-pcf packs its depth into colour) */
    stin_caps no_map = caps_with(21, 12, 0, GL21_BITS & ~(BIT(SHADOW) | BIT(DEPTH_TEXTURE)));
    stin_technique forced[STIN_FEATURE_COUNT];
    stin__selection sel;
    char msg[256];
    (void)state;
    memset(forced, 0, sizeof forced);
    gl21.max_texture_image_units = gl45.max_texture_image_units = 16;
    no_map.max_texture_image_units = 16;
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique, STIN_TECH_SHADOWS_VOLUME);
    assert_int_equal(sel.choice[STIN_FEATURE_DISPLACEMENT].technique, STIN_TECH_DISPLACEMENT_VTF);
    assert_false(sel.choice[STIN_FEATURE_DISPLACEMENT].fell_back);
    forced[STIN_FEATURE_DISPLACEMENT] = STIN_TECH_DISPLACEMENT_VTF;
    forced[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_VOLUME;
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg), STIN_OK);
    memset(forced, 0, sizeof forced);
    assert_int_equal(stin__select(&no_map, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique, STIN_TECH_SHADOWS_VOLUME);
    assert_int_equal(sel.choice[STIN_FEATURE_DISPLACEMENT].technique, STIN_TECH_DISPLACEMENT_OFF);
    assert_true(sel.choice[STIN_FEATURE_DISPLACEMENT].fell_back);
    assert_non_null(strstr(sel.choice[STIN_FEATURE_DISPLACEMENT].reason, "displace cannot run beside"));
    forced[STIN_FEATURE_DISPLACEMENT] = STIN_TECH_DISPLACEMENT_VTF;
    assert_int_equal(stin__select(&no_map, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique, STIN_TECH_SHADOWS_MAP_PCF);
    assert_int_equal(sel.choice[STIN_FEATURE_DISPLACEMENT].technique, STIN_TECH_DISPLACEMENT_VTF);
    assert_int_equal(sel.displace_unit, sel.units_used);
    forced[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_VOLUME;
    assert_int_equal(stin__select(&no_map, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, "displace cannot run beside"));
    /* GL4: vdsm shadows displaced geometry, so displace is the default,
     * tessellated where the context has tessellation shaders */
    assert_int_equal(stin__select(&gl45, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_DISPLACEMENT].technique, STIN_TECH_DISPLACEMENT_TESS);
    assert_false(sel.choice[STIN_FEATURE_DISPLACEMENT].fell_back);
    gl45.present &= ~BIT(TESSELLATION);
    assert_int_equal(stin__select(&gl45, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_DISPLACEMENT].technique, STIN_TECH_DISPLACEMENT_VTF);
    /* tessellation is GL4 only: forcing it on GL2 is an error naming what is missing */
    forced[STIN_FEATURE_SHADOWS] = STIN_TECH_NONE;
    forced[STIN_FEATURE_DISPLACEMENT] = STIN_TECH_DISPLACEMENT_TESS;
    assert_int_equal(stin__select(&gl21, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, "displace-tess"));
    gl45.present &= ~BIT(VERTEX_TEXTURE_FETCH);
    assert_int_equal(stin__select(&gl45, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_DISPLACEMENT].technique, STIN_TECH_DISPLACEMENT_OFF);
    assert_non_null(strstr(sel.choice[STIN_FEATURE_DISPLACEMENT].reason, "vertex texture fetch"));
    /* never on the fixed-function tier */
    assert_int_equal(stin__select(&gl21, STIN_TIER_GL1, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_DISPLACEMENT].technique, STIN_TECH_DISPLACEMENT_OFF);
}

/* A shadows set-up failure under vdsm walks the table's chain down: to
 * volume beside displacement where volumes cast it through their map (with
 * or without shadow compare), past it (a conflict) where depth textures are
 * missing, past map-pcf where it
 * lacks a capability or its sampler does not fit after the surface's
 * units, past the fixed-function maps always (GLSL lighting), to off at
 * the end. */
static void test_fallback_walks_the_chain(void **state)
{
    stin_caps gl45 = caps_with(45, 45, 1, GL45_CORE_BITS);
    stin__selection sel;
    char msg[256];
    (void)state;
    gl45.max_texture_image_units = 16;
    assert_int_equal(stin__select(&gl45, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique, STIN_TECH_SHADOWS_VDSM);
    assert_int_equal(sel.choice[STIN_FEATURE_DISPLACEMENT].technique, STIN_TECH_DISPLACEMENT_TESS);
    assert_int_equal(stin__fallback(&gl45, &sel, STIN_FEATURE_SHADOWS), STIN_TECH_SHADOWS_VOLUME);
    gl45.present &= ~BIT(SHADOW); /* volumes' map compares in its shader (ES 2.0) */
    assert_int_equal(stin__fallback(&gl45, &sel, STIN_FEATURE_SHADOWS), STIN_TECH_SHADOWS_VOLUME);
    gl45.present &= ~BIT(DEPTH_TEXTURE); /* map-pcf's packed into colour (bare ES 2.0) */
    assert_int_equal(stin__fallback(&gl45, &sel, STIN_FEATURE_SHADOWS), STIN_TECH_SHADOWS_MAP_PCF);
    gl45.present &= ~BIT(FBO);
    assert_int_equal(stin__fallback(&gl45, &sel, STIN_FEATURE_SHADOWS), STIN_TECH_SHADOWS_OFF);
    gl45.present |= BIT(SHADOW) | BIT(DEPTH_TEXTURE) | BIT(FBO);
    sel.choice[STIN_FEATURE_DISPLACEMENT].technique = STIN_TECH_DISPLACEMENT_OFF;
    assert_int_equal(stin__fallback(&gl45, &sel, STIN_FEATURE_SHADOWS), STIN_TECH_SHADOWS_VOLUME);
    gl45.present &= ~BIT(STENCIL);
    assert_int_equal(stin__fallback(&gl45, &sel, STIN_FEATURE_SHADOWS), STIN_TECH_SHADOWS_MAP_PCF);
    sel.unit_limit = sel.shadow_unit; /* no unit left for its sampler */
    assert_int_equal(stin__fallback(&gl45, &sel, STIN_FEATURE_SHADOWS), STIN_TECH_SHADOWS_OFF);
    sel.choice[STIN_FEATURE_SHADOWS].technique = STIN_TECH_SHADOWS_OFF; /* nothing below */
    assert_int_equal(stin__fallback(&gl45, &sel, STIN_FEATURE_SHADOWS), STIN_TECH_SHADOWS_OFF);
}

/* Which other choice displacement conflicts with, from either row, on a
 * context without what lifts the conflict (depth textures); none with it. */
static void test_choice_conflict(void **state)
{
    stin_caps gl45 = caps_with(45, 45, 1, GL45_CORE_BITS);
    stin_caps no_map = caps_with(45, 45, 1, GL45_CORE_BITS & ~BIT(DEPTH_TEXTURE));
    stin__selection sel;
    char msg[256];
    (void)state;
    assert_int_equal(stin__select(&gl45, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(stin__choice_conflict(&gl45, &sel, STIN_FEATURE_DISPLACEMENT), STIN_TECH_NONE);
    sel.choice[STIN_FEATURE_SHADOWS].technique = STIN_TECH_SHADOWS_VOLUME;
    assert_int_equal(stin__choice_conflict(&gl45, &sel, STIN_FEATURE_DISPLACEMENT), STIN_TECH_NONE);
    assert_int_equal(stin__choice_conflict(&no_map, &sel, STIN_FEATURE_DISPLACEMENT),
                     STIN_TECH_SHADOWS_VOLUME);
    assert_int_equal(stin__choice_conflict(&no_map, &sel, STIN_FEATURE_SHADOWS),
                     STIN_TECH_DISPLACEMENT_TESS);
    sel.choice[STIN_FEATURE_DISPLACEMENT].technique = STIN_TECH_DISPLACEMENT_OFF;
    assert_int_equal(stin__choice_conflict(&no_map, &sel, STIN_FEATURE_DISPLACEMENT), STIN_TECH_NONE);
}

static void test_texture_unit_budget(void **state)
{
    stin_caps c = caps_with(21, 12, 0, GL21_BITS);
    stin_technique forced[STIN_FEATURE_COUNT];
    stin__selection sel;
    char msg[256];
    (void)state;
    memset(forced, 0, sizeof forced);
    c.max_texture_image_units = 8;
    assert_int_equal(stin__select(&c, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique, STIN_TECH_SURFACE_POM);
    assert_int_equal(sel.surface_unit, 1);
    assert_int_equal(sel.shadow_unit, 3); /* volumes need none ... */
    assert_int_equal(sel.shadow_spare_units, 1); /* ... and take a spare one for the mask */
    assert_int_equal(sel.translucent_unit, 4);   /* coloured's two after them */
    assert_int_equal(sel.units_used, 6);
    /* with the surface's units the last, no unit is spare: volumes run without */
    c.max_texture_image_units = 3;
    assert_int_equal(stin__select(&c, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique, STIN_TECH_SHADOWS_VOLUME);
    assert_int_equal(sel.shadow_spare_units, 0);
    assert_int_equal(sel.units_used, 3);
    /* map-pcf forced beside pom on 8 units: one sampler leaves room for both */
    c.max_texture_image_units = 8;
    forced[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_MAP_PCF;
    assert_int_equal(stin__select(&c, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique, STIN_TECH_SURFACE_POM);
    assert_int_equal(sel.shadow_unit, 3);
    assert_int_equal(sel.translucent_unit, 4); /* coloured's two right after the one */
    c.max_texture_image_units = 3;
    assert_int_equal(stin__select(&c, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique, STIN_TECH_SHADOWS_MAP_PCF);
    assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique, STIN_TECH_SURFACE_PLAIN);
    assert_true(sel.choice[STIN_FEATURE_SURFACE].fell_back);
    assert_non_null(strstr(sel.choice[STIN_FEATURE_SURFACE].reason, "needs 4 texture units"));
    assert_non_null(strstr(sel.choice[STIN_FEATURE_SURFACE].reason, "the context has 3"));
    assert_int_equal(sel.shadow_unit, 1);
    assert_true(sel.units_used <= 3);
    /* a forced surface keeps its units: the automatic shadows walk past map-pcf */
    c.present &= ~BIT(STENCIL);
    forced[STIN_FEATURE_SHADOWS] = STIN_TECH_NONE;
    forced[STIN_FEATURE_SURFACE] = STIN_TECH_SURFACE_NORMAL;
    assert_int_equal(stin__select(&c, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique, STIN_TECH_SHADOWS_OFF);
    assert_non_null(strstr(sel.choice[STIN_FEATURE_SHADOWS].reason, "map-pcf needs 4"));
    /* too few units for the forced technique itself: an error naming the limit */
    c.max_texture_image_units = 1;
    forced[STIN_FEATURE_SURFACE] = STIN_TECH_NONE;
    forced[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_MAP_PCF;
    assert_int_equal(stin__select(&c, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, "map-pcf needs 2 texture units"));
}

/* ---- OpenGL ES ------------------------------------------------------------ */
#define ES20_BITS                                                                         \
    (BIT(STENCIL) | BIT(MULTITEXTURE) | BIT(TEXTURE_CUBE_MAP) | BIT(STENCIL_WRAP) |         \
     BIT(SEPARATE_STENCIL) | BIT(VBO) | BIT(GLSL) | BIT(FBO))
#define ES30_BITS                                                                         \
    (ES20_BITS | BIT(VAO) | BIT(DEPTH_TEXTURE) | BIT(SHADOW) | BIT(PACKED_DEPTH_STENCIL) |  \
     BIT(VERTEX_TEXTURE_FETCH) | BIT(DERIVATIVES) | BIT(GLSL_150))
#define ES32_BITS                                                                         \
    (ES30_BITS | BIT(COMPUTE) | BIT(GEOMETRY_SHADER) | BIT(TESSELLATION) | BIT(FLOAT_TEXTURE))

static stin_caps es_caps(int version, uint64_t present)
{
    stin_caps c = caps_with(version, version >= 30 ? version : 10, 1, present);
    c.es = 1;
    return c;
}

/* GLSL ES 1.00 runs the GLSL 1.10 sources: ES 2.0 takes the GL2 tier
 * without fixed function; ES 3.0 on the GL4 tier (GLSL ES 3.00), whose
 * vdsm needs ES 3.2's geometry shaders. */
static void test_es_tiers(void **state)
{
    stin_caps es20 = es_caps(20, ES20_BITS), es30 = es_caps(30, ES30_BITS);
    stin_caps es32 = es_caps(32, ES32_BITS);
    stin_caps desktop = caps_with(33, 33, 1, ES32_BITS); /* the same bits on core: no GL2 */
    char missing[256];
    (void)state;
    assert_int_equal(stin_best_tier(&es20), STIN_TIER_GL2);
    assert_int_equal(stin_best_tier(&es30), STIN_TIER_GL4);
    assert_int_equal(stin_best_tier(&es32), STIN_TIER_GL4);
    assert_true(stin_tier_supported(&es32, STIN_TIER_GL2, NULL, 0));
    assert_false(stin_tier_supported(&desktop, STIN_TIER_GL2, missing, sizeof missing));
    assert_string_equal(missing, stin_cap_name(STIN_CAP_FIXED_FUNCTION));
    /* no fixed function on ES: the GL1 tier is refused, naming it */
    assert_false(stin_tier_supported(&es32, STIN_TIER_GL1, missing, sizeof missing));
    assert_string_equal(missing, stin_cap_name(STIN_CAP_FIXED_FUNCTION));
    assert_true(stin_tier_supported(&es30, STIN_TIER_GL2, NULL, 0));
    assert_false(stin_tier_supported(&es20, STIN_TIER_GL4, missing, sizeof missing));
    assert_string_equal(missing, "vertex array objects, " /* ES 2.0 has no GLSL ES 3.00 */
                                 "GLSL 1.50 shaders (GLSL ES 3.00 on ES)");
}

static void test_es_auto_selection(void **state)
{
    stin_caps es20 = es_caps(20, ES20_BITS), es30 = es_caps(30, ES30_BITS);
    stin_caps es32 = es_caps(32, ES32_BITS);
    stin__selection sel;
    char msg[256];
    int f;
    (void)state;
    assert_int_equal(stin__select(&es20, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_LIGHTING].technique, STIN_TECH_LIGHTING_GLSL110);
    assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique, STIN_TECH_SHADOWS_VOLUME);
    assert_int_equal(sel.choice[STIN_FEATURE_SURFACE].technique, STIN_TECH_SURFACE_POM);
    assert_int_equal(sel.choice[STIN_FEATURE_DISPLACEMENT].technique, STIN_TECH_DISPLACEMENT_OFF);
    assert_int_equal(stin__select(&es30, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.tier, STIN_TIER_GL4);
    assert_int_equal(sel.choice[STIN_FEATURE_LIGHTING].technique, STIN_TECH_LIGHTING_GLSL150);
    /* no geometry stage: volumes (extruded on the CPU) instead of vdsm */
    assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique, STIN_TECH_SHADOWS_VOLUME);
    assert_non_null(strstr(sel.choice[STIN_FEATURE_SHADOWS].reason,
                           stin_cap_name(STIN_CAP_GEOMETRY_SHADER)));
    assert_int_equal(sel.choice[STIN_FEATURE_DISPLACEMENT].technique,
                     STIN_TECH_DISPLACEMENT_VTF);
    assert_int_equal(stin__select(&es32, STIN_TIER_AUTO, NULL, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.tier, STIN_TIER_GL4);
    assert_int_equal(sel.choice[STIN_FEATURE_LIGHTING].technique, STIN_TECH_LIGHTING_GLSL150);
    assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique, STIN_TECH_SHADOWS_VDSM);
    for (f = 0; f < STIN_FEATURE_COUNT; f++) /* nothing of the fixed pipeline */
        assert_false(stin__technique_needs(sel.choice[f].technique) & BIT(FIXED_FUNCTION));
}

/* Forcing what the ES context lacks is the same error as on desktop,
 * naming what is missing; the GL1 techniques are never offered. */
static void test_es_forced_above_the_context(void **state)
{
    static const stin_technique fixed[] = {STIN_TECH_LIGHTING_FIXED, STIN_TECH_SHADOWS_MAP_DEPTH,
                                           STIN_TECH_SHADOWS_MAP_COMBINE, STIN_TECH_SURFACE_DOT3};
    stin_caps es20 = es_caps(20, ES20_BITS), es32 = es_caps(32, ES32_BITS);
    stin_technique forced[STIN_FEATURE_COUNT];
    stin__selection sel;
    char msg[256];
    size_t i;
    int f;
    (void)state;
    assert_int_equal(stin__select(&es32, STIN_TIER_GL1, NULL, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, stin_cap_name(STIN_CAP_FIXED_FUNCTION)));
    assert_int_equal(stin__select(&es20, STIN_TIER_GL4, NULL, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, stin_cap_name(STIN_CAP_GLSL_150)));
    for (i = 0; i < sizeof fixed / sizeof fixed[0]; i++) {
        for (f = 0; f < STIN_FEATURE_COUNT; f++)
            forced[f] = STIN_TECH_NONE;
        forced[stin__technique_feature(fixed[i])] = fixed[i];
        assert_int_equal(stin__select(&es32, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                         STIN_ERROR_UNSUPPORTED);
    }
    for (f = 0; f < STIN_FEATURE_COUNT; f++)
        forced[f] = STIN_TECH_NONE;
    /* bare ES 2.0 runs map-pcf (its depth packed into colour) */
    forced[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_MAP_PCF;
    assert_int_equal(stin__select(&es20, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg), STIN_OK);
    assert_int_equal(sel.choice[STIN_FEATURE_SHADOWS].technique, STIN_TECH_SHADOWS_MAP_PCF);
    /* vdsm's facets come from derivatives: refused without them, named */
    es32.present &= ~BIT(DERIVATIVES);
    forced[STIN_FEATURE_SHADOWS] = STIN_TECH_SHADOWS_VDSM;
    assert_int_equal(stin__select(&es32, STIN_TIER_AUTO, forced, &sel, msg, sizeof msg),
                     STIN_ERROR_UNSUPPORTED);
    assert_non_null(strstr(msg, stin_cap_name(STIN_CAP_DERIVATIVES)));
    assert_null(strstr(msg, stin_cap_name(STIN_CAP_FIXED_FUNCTION)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_auto_selection_per_profile),
        cmocka_unit_test(test_tier_supported_names_missing_capabilities),
        cmocka_unit_test(test_missing_list_truncates_safely),
        cmocka_unit_test(test_forcing_a_tier_above_the_caps_fails),
        cmocka_unit_test(test_forcing_a_lower_tier_walks_down),
        cmocka_unit_test(test_hiding_a_capability_lowers_the_tier),
        cmocka_unit_test(test_no_tier_runs),
        cmocka_unit_test(test_unknown_tier_is_an_invalid_argument),
        cmocka_unit_test(test_forced_technique_of_the_wrong_feature),
        cmocka_unit_test(test_forced_technique_that_runs_is_taken),
        cmocka_unit_test(test_forced_technique_the_caps_cannot_run),
        cmocka_unit_test(test_forced_technique_above_the_tier),
        cmocka_unit_test(test_vdsm_on_gl4_only),
        cmocka_unit_test(test_deep_on_gl4_only),
        cmocka_unit_test(test_transparency_chain),
        cmocka_unit_test(test_surface_follows_the_lighting_technique),
        cmocka_unit_test(test_technique_tables),
        cmocka_unit_test(test_every_technique_has_a_row_and_a_rank),
        cmocka_unit_test(test_texture_unit_budget),
        cmocka_unit_test(test_displacement_beside_volumes),
        cmocka_unit_test(test_fallback_walks_the_chain),
        cmocka_unit_test(test_choice_conflict),
        cmocka_unit_test(test_es_tiers),
        cmocka_unit_test(test_es_auto_selection),
        cmocka_unit_test(test_es_forced_above_the_context),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
