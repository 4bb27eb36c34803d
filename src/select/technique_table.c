/* SPDX-License-Identifier: MIT */
/* The internal technique table: per technique its capabilities, the lighting
 * it runs on, its conflicts, its texture units and its rank in its chain.
 * The feature and tier come from the public X-macro list. */
#include "internal.h"

#define BIT(c) STIN_CAP_BIT(STIN_CAP_##c)
#define GLSL_ANY STIN_TECH_LIGHTING_GLSL110 /* "any GLSL lighting" */
#define TIER1 (BIT(FIXED_FUNCTION))
/* GLSL 1.10 shaders need a compatibility context next to GL 2.0 (a core
 * context refuses #version 110/120). On OpenGL ES the same sources run as
 * GLSL ES 1.00, which every ES 2.0+ context takes: stin__needs_here drops
 * FIXED_FUNCTION from a need that has GLSL beside it there. */
#define TIER2 (BIT(GLSL) | BIT(FIXED_FUNCTION))
/* The GL4 tier's sources are GLSL 1.50 (GLSL ES 3.00 and later on ES);
 * what needs a geometry stage (vdsm) says so in its own row. */
#define TIER4 (BIT(GLSL) | BIT(GLSL_150) | BIT(VBO) | BIT(VAO) | BIT(FBO))
/* What volumes' own depth map needs (shadow/cast_map.c, on GLSL lighting:
 * without shadow compare its test compares in the shader). */
#define CAST_MAP (BIT(FBO) | BIT(DEPTH_TEXTURE))

/* Techniques that only run on top of one lighting technique: DOT3 and the
 * fixed maps are texture-environment set-ups of the fixed-function passes;
 * the GLSL surface chunks and map-pcf are chunks of the GLSL lit programs. */
static const stin__technique_row rows[] = {
    /* technique                      rank needs  lighting conflicts frag vert spare lifted */
    {STIN_TECH_LIGHTING_GLSL150,       0, TIER4, STIN_TECH_NONE, 0, 1, 0, 0, 0},
    {STIN_TECH_LIGHTING_GLSL110,       1, TIER2, STIN_TECH_NONE, 0, 1, 0, 0, 0},
    {STIN_TECH_LIGHTING_FIXED,         2, TIER1, STIN_TECH_NONE, 0, 1, 0, 0, 0},
    /* exact shadows from a position buffer and per-triangle shadow polygons
     * drawn by a geometry shader into the screen mask (its unit); the
     * position buffer's facet normals are screen derivatives (no vertex
     * normal can stand in for the exact facet) */
    {STIN_TECH_SHADOWS_VDSM,           0,
     TIER4 | BIT(GEOMETRY_SHADER) | BIT(FLOAT_TEXTURE) | BIT(PACKED_DEPTH_STENCIL) |
         BIT(DERIVATIVES), STIN_TECH_LIGHTING_GLSL150, 0, 1, 0, 0, 0},
    /* a spare unit holds the screen mask (several lights per lit pass) */
    {STIN_TECH_SHADOWS_VOLUME,         1, BIT(STENCIL), STIN_TECH_NONE, 0, 0, 0, 1, 0},
    /* without shadow compare the lit programs compare, without depth
     * textures the maps hold depth packed into RGBA8 (shadow/map_pcf.c) */
    {STIN_TECH_SHADOWS_MAP_PCF,        2,
     BIT(GLSL) | BIT(FBO) | BIT(MULTITEXTURE), GLSL_ANY, 0, 1, 0, 0, 0},
    {STIN_TECH_SHADOWS_MAP_DEPTH,      3, BIT(DEPTH_TEXTURE) | BIT(SHADOW) | BIT(MULTITEXTURE),
     STIN_TECH_LIGHTING_FIXED, 0, 1, 0, 0, 0},
    {STIN_TECH_SHADOWS_MAP_COMBINE,    4, BIT(TEXTURE_ENV_COMBINE) | BIT(MULTITEXTURE),
     STIN_TECH_LIGHTING_FIXED, 0, 2, 0, 0, 0},
    {STIN_TECH_SHADOWS_OFF,            5, 0, STIN_TECH_NONE, 0, 0, 0, 0, 0},
    /* three samplers: albedo, normal map, height map */
    {STIN_TECH_SURFACE_POM,            0, BIT(GLSL) | BIT(MULTITEXTURE), GLSL_ANY, 0, 2, 0, 0, 0},
    {STIN_TECH_SURFACE_PARALLAX,       1, BIT(GLSL) | BIT(MULTITEXTURE), GLSL_ANY, 0, 2, 0, 0, 0},
    {STIN_TECH_SURFACE_NORMAL,         2, BIT(GLSL) | BIT(MULTITEXTURE), GLSL_ANY, 0, 2, 0, 0, 0},
    {STIN_TECH_SURFACE_DOT3,           3,
     BIT(MULTITEXTURE) | BIT(TEXTURE_ENV_COMBINE) | BIT(TEXTURE_ENV_DOT3) | BIT(TEXTURE_CUBE_MAP) |
         BIT(FIXED_FUNCTION), STIN_TECH_LIGHTING_FIXED, 0, 2, 0, 0, 0}, /* a 4th for albedo if spare */
    {STIN_TECH_SURFACE_PLAIN,          4, 0, STIN_TECH_NONE, 0, 0, 0, 0, 0},
    /* deep shadow maps: two array textures of RGBA32F layers (even, odd);
     * its gl4 sources take the facet from derivatives */
    {STIN_TECH_TRANSLUCENT_DEEP,       0, TIER4 | BIT(FLOAT_TEXTURE) | BIT(DERIVATIVES),
     STIN_TECH_LIGHTING_GLSL150, 0, 2, 0, 0, 0},
    /* one colour map and the nearest transparent depth per light (atlases) */
    {STIN_TECH_TRANSLUCENT_COLOURED,   1,
     BIT(GLSL) | BIT(FBO) | BIT(DEPTH_TEXTURE) | BIT(MULTITEXTURE), GLSL_ANY, 0, 2, 0, 0, 0},
    /* casters at or above desc.translucent.opaque_threshold cast, the rest not */
    {STIN_TECH_TRANSLUCENT_OPAQUE,     2, 0, STIN_TECH_NONE, 0, 0, 0, 0, 0},
    /* every caster casts fully: chosen only when forced (opaque needs no more) */
    {STIN_TECH_TRANSLUCENT_SOLID,      3, 0, STIN_TECH_NONE, 0, 0, 0, 0, 0},
    /* vertex texture fetch of the height map in every mesh-drawing vertex
     * stage (after tessellation where there is one); volumes' silhouettes
     * would be the undisplaced mesh's, so beside volumes the displaced draws
     * cast through volumes' depth map (shadow/cast_map.c), which needs
     * depth textures in a framebuffer object */
    {STIN_TECH_DISPLACEMENT_TESS,      0, TIER4 | BIT(VERTEX_TEXTURE_FETCH) | BIT(TESSELLATION),
     STIN_TECH_LIGHTING_GLSL150, STIN__TECH_BIT(STIN_TECH_SHADOWS_VOLUME), 0, 1, 0, CAST_MAP},
    {STIN_TECH_DISPLACEMENT_VTF,       1, BIT(GLSL) | BIT(VERTEX_TEXTURE_FETCH), GLSL_ANY,
     STIN__TECH_BIT(STIN_TECH_SHADOWS_VOLUME), 0, 1, 0, CAST_MAP},
    {STIN_TECH_DISPLACEMENT_OFF,       2, 0, STIN_TECH_NONE, 0, 0, 0, 0, 0},
    /* stencil parity; depth written back by glDrawPixels (compatibility) or
     * a GLSL 1.50 program (core: csg/goldfeather.c demotes without it) */
    {STIN_TECH_CSG_GOLDFEATHER,        2, BIT(STENCIL), STIN_TECH_NONE, 0, 0, 0, 0, 0},
    {STIN_TECH_CSG_OFF,                3, 0, STIN_TECH_NONE, 0, 0, 0, 0, 0},
    /* sequenced convex subtraction (csg/scs.c) for products of convex
     * primitives, goldfeather's depth write-back; other products go to
     * goldfeather (logged) */
    {STIN_TECH_CSG_SCS,                0, BIT(STENCIL), STIN_TECH_NONE, 0, 0, 0, 0, 0},
    /* depth peeling of the camera's layers: two samplers in the lit programs
     * (the previous layer's depth, the opaque depth); packed depth-stencil
     * textures hold a layer's depth and the stencil volumes count in; the
     * composite writes the first layer's depth (gl_FragDepth) */
    {STIN_TECH_TRANSPARENCY_DEPTH_PEEL,      1,
     BIT(GLSL) | BIT(FBO) | BIT(DEPTH_TEXTURE) | BIT(PACKED_DEPTH_STENCIL) | BIT(MULTITEXTURE) |
         BIT(VBO) | BIT(FRAG_DEPTH), GLSL_ANY, 0, 2, 0, 0, 0},
    {STIN_TECH_TRANSPARENCY_SORTED,    2, 0, STIN_TECH_NONE, 0, 0, 0, 0, 0},
    /* dual depth peeling: depth-peel's needs on GLSL 1.50 (3.2+: the MAX
     * blend equation) with float colour targets it blends into (RG32F
     * min-max, RGBA16F composites) and an any-samples query (its early
     * stop); the same two samplers (this pass's min-max, the opaque depth) */
    {STIN_TECH_TRANSPARENCY_DUAL_PEEL, 0,
     TIER4 | BIT(FLOAT_TEXTURE) | BIT(FLOAT_BLEND) | BIT(DEPTH_TEXTURE) |
         BIT(PACKED_DEPTH_STENCIL) | BIT(MULTITEXTURE) | BIT(ANY_SAMPLES_QUERY),
     STIN_TECH_LIGHTING_GLSL150, 0, 2, 0, 0, 0},
    /* the ray-interval walk over peeled layers (csg/interval.c): GLSL 1.50,
     * FBOs, texture arrays (GL 3.0: DEPTH_COMPONENT32F and R8 layers) and a
     * float colour target (R32F) the walk writes and the CPU reads back, an
     * any-samples query for the overflow;
     * goldfeather's depth write-back (its GLSL 1.50 program) and stencil
     * for the products it hands on; products past its limits go to
     * scs/goldfeather (logged) */
    {STIN_TECH_CSG_INTERVAL,           1, TIER4 | BIT(FLOAT_TEXTURE) | BIT(STENCIL) |
         BIT(ANY_SAMPLES_QUERY),
     STIN_TECH_LIGHTING_GLSL150, 0, 0, 0, 0, 0},
};

static const stin_feature tech_feature[] = {
#define STIN_X_(id, name, feature, tier) feature,
    STIN_TECHNIQUE_LIST(STIN_X_)
#undef STIN_X_
};

static const stin_tier tech_tier[] = {
#define STIN_X_(id, name, feature, tier) tier,
    STIN_TECHNIQUE_LIST(STIN_X_)
#undef STIN_X_
};

const stin__technique_row *stin__technique_row_of(stin_technique t)
{
    size_t i;
    for (i = 0; i < sizeof rows / sizeof rows[0]; i++)
        if (rows[i].technique == t)
            return &rows[i];
    return NULL;
}

int stin__feature_chain(stin_feature f, stin_technique out[STIN_TECH_COUNT])
{
    int n = 0, rank;
    size_t i;
    for (rank = 0; rank < 256 && n < STIN_TECH_COUNT; rank++)
        for (i = 0; i < sizeof rows / sizeof rows[0]; i++)
            if (rows[i].rank == rank && tech_feature[rows[i].technique] == f)
                out[n++] = rows[i].technique;
    return n;
}

uint64_t stin__tier_needs(stin_tier t)
{
    switch (t) {
    case STIN_TIER_GL1: return TIER1;
    case STIN_TIER_GL2: return TIER2;
    case STIN_TIER_GL4: return TIER4;
    case STIN_TIER_AUTO: break;
    }
    return 0;
}

uint64_t stin__needs_here(const stin_caps *caps, uint64_t needs)
{
    if (caps && caps->es && (needs & BIT(GLSL)))
        needs &= ~BIT(FIXED_FUNCTION);
    return needs;
}

uint64_t stin__technique_needs(stin_technique t)
{
    const stin__technique_row *r = stin__technique_row_of(t);
    return r ? r->needs : 0;
}

stin_technique stin__technique_lighting(stin_technique t)
{
    const stin__technique_row *r = stin__technique_row_of(t);
    return r ? r->lighting : STIN_TECH_NONE;
}

int stin__technique_runs_with(stin_technique t, stin_technique lighting)
{
    stin_technique need = stin__technique_lighting(t);
    if (need == STIN_TECH_NONE || need == lighting)
        return 1;
    /* GLSL 1.10 lighting stands for the GLSL class: 1.50 runs those too */
    return need == STIN_TECH_LIGHTING_GLSL110 && lighting == STIN_TECH_LIGHTING_GLSL150;
}

stin_feature stin__technique_feature(stin_technique t)
{
    return (unsigned)t < STIN_TECH_COUNT ? tech_feature[t] : STIN_FEATURE_COUNT;
}

stin_feature stin_technique_feature(stin_technique t) { return stin__technique_feature(t); }

stin_tier stin__technique_tier(stin_technique t)
{
    return (unsigned)t < STIN_TECH_COUNT ? tech_tier[t] : STIN_TIER_AUTO;
}
