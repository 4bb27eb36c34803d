/* SPDX-License-Identifier: MIT */
/* The expected table: detected tier, runnable tiers and the technique per
 * feature for every named profile. */
#include "expected.h"

#include <string.h>

#define LIGHT_FIXED STIN_TECH_LIGHTING_FIXED
#define LIGHT_110 STIN_TECH_LIGHTING_GLSL110
#define LIGHT_150 STIN_TECH_LIGHTING_GLSL150
#define VOLUME STIN_TECH_SHADOWS_VOLUME
#define VDSM STIN_TECH_SHADOWS_VDSM
#define PLAIN STIN_TECH_SURFACE_PLAIN
#define DOT3 STIN_TECH_SURFACE_DOT3
#define POM STIN_TECH_SURFACE_POM
/* translucent shadows, displacement, CSG, transparency: deep shadow maps on
 * GL4, colour maps on GL2, the opacity threshold on GL1, displacement where
 * there are vertex textures (beside volumes too: they cast displaced draws
 * through a depth map of their own), tessellated first where there are
 * tessellation shaders (GL 4.0); scs everywhere (products of non-convex
 * primitives go to goldfeather); dual depth peeling on GL4 (float
 * targets it blends into, any-samples queries), depth peeling on GL2 (FBOs, depth textures,
 * packed depth-stencil), sorted on GL1 */
#define RESERVED STIN_TECH_TRANSLUCENT_OPAQUE, STIN_TECH_DISPLACEMENT_OFF, STIN_TECH_CSG_SCS, \
    STIN_TECH_TRANSPARENCY_SORTED
#define COLOURED STIN_TECH_TRANSLUCENT_COLOURED, STIN_TECH_DISPLACEMENT_VTF, STIN_TECH_CSG_SCS, \
    STIN_TECH_TRANSPARENCY_DEPTH_PEEL
#define DISPLACED STIN_TECH_TRANSLUCENT_DEEP, STIN_TECH_DISPLACEMENT_VTF, \
    STIN_TECH_CSG_SCS, STIN_TECH_TRANSPARENCY_DUAL_PEEL
#define TESSELLATED STIN_TECH_TRANSLUCENT_DEEP, STIN_TECH_DISPLACEMENT_TESS, \
    STIN_TECH_CSG_SCS, STIN_TECH_TRANSPARENCY_DUAL_PEEL

static const expected_profile table[] = {
    {"gl11", STIN_TIER_GL1, {LIGHT_FIXED, VOLUME, PLAIN, RESERVED}, {1, 0, 0}},
    {"gl13-combine", STIN_TIER_GL1, {LIGHT_FIXED, VOLUME, DOT3, RESERVED}, {1, 0, 0}},
    {"gl14-shadow", STIN_TIER_GL1, {LIGHT_FIXED, VOLUME, DOT3, RESERVED}, {1, 0, 0}},
    {"gl21", STIN_TIER_GL2, {LIGHT_110, VOLUME, POM, COLOURED}, {1, 1, 0}},
    {"gl33-core", STIN_TIER_GL4, {LIGHT_150, VDSM, POM, DISPLACED}, {0, 0, 1}},
    {"gl45-core", STIN_TIER_GL4, {LIGHT_150, VDSM, POM, TESSELLATED}, {0, 0, 1}},
    /* OpenGL ES (egl only): no fixed function, so no GL1 tier; GLSL ES 1.00
     * runs the GL2 tier, ES 3.2 the GL4 one. CSG writes depth back with a
     * GLSL ES 3.00 program from ES 3.0 on (glDrawPixels is desktop
     * compatibility); on ES 2.0 its GPU resolve alone runs, in a work
     * buffer where depth textures are (es20-ext), else in the frame's own
     * buffers with the result packed into colour (es20). Volumes' own map
     * for displaced draws compares in the shader on es20-ext (no shadow
     * samplers), so it displaces beside them as gl21 does. */
    {"es20", STIN_TIER_GL2, {LIGHT_110, VOLUME, POM, STIN_TECH_TRANSLUCENT_OPAQUE,
                             STIN_TECH_DISPLACEMENT_OFF, STIN_TECH_CSG_SCS,
                             STIN_TECH_TRANSPARENCY_SORTED}, {0, 1, 0}},
    {"es20-ext", STIN_TIER_GL2, {LIGHT_110, VOLUME, POM, COLOURED}, {0, 1, 0}},
    /* ES 3.0 and 3.1 run the GL4 tier's GLSL ES 3.00 programs without a
     * geometry stage: volumes instead of vdsm, vertex-texture displacement */
    {"es30", STIN_TIER_GL4, {LIGHT_150, VOLUME, POM, DISPLACED}, {0, 1, 1}},
    {"es31", STIN_TIER_GL4, {LIGHT_150, VOLUME, POM, DISPLACED}, {0, 1, 1}},
    /* dual peeling's early stop by an any-samples query, its RG32F MIN/MAX
     * by EXT_float_blend */
    {"es32", STIN_TIER_GL4, {LIGHT_150, VDSM, POM, TESSELLATED}, {0, 1, 1}},
    {"native", STIN_TIER_GL4, {LIGHT_150, VDSM, POM, TESSELLATED}, {1, 1, 1}},
};

const expected_profile *expected_find(const char *profile)
{
    size_t i;
    for (i = 0; i < sizeof table / sizeof table[0]; i++)
        if (!strcmp(table[i].profile, profile))
            return &table[i];
    return NULL;
}
