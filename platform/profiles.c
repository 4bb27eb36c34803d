/* SPDX-License-Identifier: MIT */
/*
 * The named capability profiles (docs/profiles.md is the documented copy).
 *
 * Two lines of defence per profile: Mesa's environment overrides make the
 * driver report (and mostly enforce) the weaker GL, and caps_mask hides in
 * process whatever Mesa keeps exposing. The extension overrides list only
 * extensions Mesa 22.3 lets us disable: naming an always-on one (e.g.
 * GL_ARB_depth_texture) prints "cannot be disabled" on stdout and leaves the
 * functionality in place, so those are left to the mask.
 */
#include "stin_platform.h"
#include "stin/stin.h"

#include <string.h>

#define BIT(cap) STIN_CAP_BIT(STIN_CAP_##cap)

/* Every capability bit stin knows. */
#define OR_BIT_(id, name, ver, exts) | BIT(id)
#define ALL_CAPS ((uint64_t)0 STIN_CAP_LIST(OR_BIT_))

/* What each profile keeps; its mask is the complement. */
/* every desktop GL has 32-bit element indices */
#define GL11_KEEP (BIT(STENCIL) | BIT(FIXED_FUNCTION) | BIT(ELEMENT_INDEX_UINT))
#define GL13_KEEP                                                                   \
    (GL11_KEEP | BIT(MULTITEXTURE) | BIT(TEXTURE_ENV_COMBINE) | BIT(TEXTURE_ENV_DOT3) | \
     BIT(TEXTURE_CUBE_MAP) | BIT(SEPARATE_SPECULAR))
#define GL14_KEEP                                                                 \
    (GL13_KEEP | BIT(DEPTH_TEXTURE) | BIT(SHADOW) | BIT(STENCIL_WRAP) |           \
     BIT(STENCIL_TWO_SIDE) | BIT(DEPTH_CLAMP) | BIT(VBO))
/* GL 2.1 class: no VAO or float textures (GL 3.0), nothing of GL 3.2+. */
#define GL21_HIDE                                                                 \
    (BIT(FLOAT_TEXTURE) | BIT(VAO) | BIT(GEOMETRY_SHADER) | BIT(GLSL_150) |       \
     BIT(TESSELLATION) | BIT(COMPUTE) | BIT(TIMER_QUERY) | BIT(TRANSFORM_FEEDBACK))
/* GL 3.3 class: the 4.x features Mesa still lists as extensions. */
#define GL33_HIDE (BIT(TESSELLATION) | BIT(COMPUTE) | BIT(TRANSFORM_FEEDBACK))

/* OpenGL ES 2.0 core: GLSL ES 1.00, FBOs, buffers, separate stencil with
 * wrap, multitexture and cube maps; no depth textures, float textures,
 * VAOs, vertex texture units or occlusion queries. */
#define ES20_KEEP                                                                 \
    (BIT(STENCIL) | BIT(MULTITEXTURE) | BIT(TEXTURE_CUBE_MAP) | BIT(STENCIL_WRAP) | \
     BIT(SEPARATE_STENCIL) | BIT(VBO) | BIT(GLSL) | BIT(FBO))
/* The usual ES 2.0 extensions, and EXT_frag_depth, which ES 2.0 parts with
 * depth textures commonly have and Mesa offers (depth peeling's composite
 * writes depth); vertex texture units are a limit of ES 2.0 (0 allowed),
 * and llvmpipe has 32. */
#define ES20_EXT_KEEP                                                             \
    (ES20_KEEP | BIT(DEPTH_TEXTURE) | BIT(PACKED_DEPTH_STENCIL) | BIT(ELEMENT_INDEX_UINT) | \
     BIT(DERIVATIVES) | BIT(FRAG_DEPTH) | BIT(VERTEX_TEXTURE_FETCH))
/* ES 3.0 has no geometry, tessellation or compute stages (3.1, 3.2). */
#define ES30_HIDE (BIT(GEOMETRY_SHADER) | BIT(TESSELLATION) | BIT(COMPUTE))
/* The ES extensions Mesa 22.3 lets a profile disable; OES_depth_texture,
 * OES_packed_depth_stencil, OES_element_index_uint, OES_vertex_array_object,
 * EXT_color_buffer_float, EXT_draw_buffers and OES_mapbuffer "cannot be
 * disabled" and are left to the mask. */
#define ES20_EXT_OFF                                                          \
    "-GL_OES_texture_float -GL_OES_texture_half_float -GL_OES_texture_float_linear " \
    "-GL_OES_texture_half_float_linear -GL_EXT_occlusion_query_boolean -GL_OES_texture_3D"

/* Disable-able extensions shared by every GL 1.x profile: shaders of any
 * kind, FBO, float textures, PBOs, NPOT textures (GL1 hardware had none; stin
 * resamples to powers of two), occlusion queries, separate stencil. */
#define GL1X_OFF                                                                    \
    "-GL_ARB_vertex_shader -GL_ARB_fragment_shader -GL_ARB_vertex_program "         \
    "-GL_ARB_fragment_program -GL_ARB_fragment_program_shadow -GL_EXT_gpu_shader4 " \
    "-GL_ARB_tessellation_shader -GL_ARB_compute_shader -GL_ARB_framebuffer_object " \
    "-GL_ARB_texture_float -GL_ATI_texture_float -GL_ARB_pixel_buffer_object "      \
    "-GL_EXT_pixel_buffer_object -GL_ARB_texture_non_power_of_two "                 \
    "-GL_ARB_occlusion_query -GL_ARB_occlusion_query2"

/* GL 1.1 to 1.3 also lose the GL 1.4 group (shadow, two-sided, depth clamp). */
#define GL14_GROUP_OFF                                                      \
    " -GL_ARB_shadow -GL_EXT_shadow_funcs -GL_EXT_stencil_two_side "        \
    "-GL_ATI_separate_stencil -GL_ARB_depth_clamp -GL_NV_depth_clamp"

static const stin_profile profiles[] = {
    {
        "gl11",
        "GL 1.1 + stencil, fixed function only",
        1, 1, 0,
        "1.1", NULL,
        GL1X_OFF GL14_GROUP_OFF
        " -GL_EXT_texture_env_dot3 -GL_NV_texture_env_combine4 -GL_ATI_texture_env_combine3",
        ALL_CAPS & ~GL11_KEEP,
        11,
        0,
    },
    {
        "gl13-combine",
        "GL 1.3: multitexture, env_combine/dot3, cube maps; no depth textures",
        1, 3, 0,
        "1.3", NULL,
        GL1X_OFF GL14_GROUP_OFF,
        ALL_CAPS & ~GL13_KEEP,
        13,
        0,
    },
    {
        "gl14-shadow",
        "GL 1.4: gl13-combine + ARB_shadow, two-sided stencil, wrap, depth clamp, VBO",
        1, 4, 0,
        "1.4", NULL,
        GL1X_OFF,
        ALL_CAPS & ~GL14_KEEP,
        14,
        0,
    },
    {
        "gl21",
        "GL 2.1 compatibility, GLSL 1.20, FBO by extension; no GL 3 features",
        2, 1, 0,
        "2.1", "120",
        "-GL_ARB_tessellation_shader -GL_ARB_compute_shader -GL_ARB_texture_float "
        "-GL_ATI_texture_float -GL_EXT_gpu_shader4",
        GL21_HIDE,
        21,
        0,
    },
    {
        "gl33-core",
        "GL 3.3 core, GLSL 3.30; no tessellation or compute",
        3, 3, 1,
        "3.3", "330",
        "-GL_ARB_tessellation_shader -GL_ARB_compute_shader",
        GL33_HIDE,
        33,
        0,
    },
    {
        "gl45-core",
        "GL 4.5 core, GLSL 4.50",
        4, 5, 1,
        NULL, NULL, NULL,
        0,
        45,
        0,
    },
    {
        "es20",
        "OpenGL ES 2.0 bare: GLSL ES 1.00; no depth or float textures, 32-bit indices, "
        "vertex textures or derivatives",
        2, 0, 0,
        "2.0", NULL,
        ES20_EXT_OFF " -GL_OES_standard_derivatives",
        ALL_CAPS & ~ES20_KEEP,
        20,
        1,
    },
    {
        "es20-ext",
        "OpenGL ES 2.0 + OES_depth_texture, OES_packed_depth_stencil, "
        "OES_element_index_uint, OES_standard_derivatives",
        2, 0, 0,
        "2.0", NULL,
        /* not -GL_OES_texture_npot: Mesa then refuses every NPOT texture,
         * where ES 2.0 allows clamped ones without mipmaps (screen targets) */
        ES20_EXT_OFF,
        ALL_CAPS & ~ES20_EXT_KEEP,
        20,
        1,
    },
    {
        "es30",
        "OpenGL ES 3.0, GLSL ES 3.00 (WebGL 2 class)",
        3, 0, 0,
        "3.0", NULL, NULL,
        ES30_HIDE,
        30,
        1,
    },
    {
        "es31",
        "OpenGL ES 3.1, GLSL ES 3.10: + compute",
        3, 1, 0,
        "3.1", NULL, NULL,
        BIT(GEOMETRY_SHADER) | BIT(TESSELLATION),
        31,
        1,
    },
    {
        "es32",
        "OpenGL ES 3.2, GLSL ES 3.20: + geometry and tessellation shaders",
        3, 2, 0,
        "3.2", NULL, NULL,
        0,
        32,
        1,
    },
    {
        /* For tools, not tests: whatever the driver offers, no emulation.
         * Clears any MESA_*_OVERRIDE inherited from the environment. */
        "native",
        "the driver's best compatibility context, no overrides, no mask",
        0, 0, 0,
        NULL, NULL, NULL,
        0,
        0,
        0,
    },
};

size_t stin_profile_count(void)
{
    return sizeof profiles / sizeof profiles[0];
}

const stin_profile *stin_profile_at(size_t i)
{
    return i < stin_profile_count() ? &profiles[i] : NULL;
}

const stin_profile *stin_profile_find(const char *name)
{
    size_t i;
    for (i = 0; name && i < stin_profile_count(); i++)
        if (strcmp(profiles[i].name, name) == 0)
            return &profiles[i];
    return NULL;
}
