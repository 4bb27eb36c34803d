/* SPDX-License-Identifier: MIT */
/* Printable names of the public enums, generated from the X-macro lists. */
#include "internal.h"

const char *stin_result_name(stin_result r)
{
    switch (r) {
    case STIN_OK: return "ok";
    case STIN_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case STIN_ERROR_OUT_OF_MEMORY: return "memory block too small";
    case STIN_ERROR_CAPACITY: return "capacity exhausted";
    case STIN_ERROR_UNSUPPORTED: return "unsupported by this context";
    case STIN_ERROR_GL: return "GL error";
    case STIN_ERROR_INVALID_HANDLE: return "invalid handle";
    case STIN_ERROR_INVALID_MESH: return "invalid mesh";
    case STIN_ERROR_INVALID_STATE: return "invalid state";
    }
    return "unknown result";
}

const char *stin_log_item_text(stin_log_item item)
{
    static const char *const text[] = {
#define STIN_X_(id, t) t,
        STIN_LOG_ITEMS(STIN_X_)
#undef STIN_X_
    };
    return (unsigned)item < STIN_LOG_ITEM_COUNT ? text[item] : "unknown log item";
}

const char *stin_cap_name(stin_cap cap)
{
    static const char *const names[] = {
#define STIN_X_(id, name, ver, exts) name,
        STIN_CAP_LIST(STIN_X_)
#undef STIN_X_
    };
    return (unsigned)cap < STIN_CAP_COUNT ? names[cap] : "unknown capability";
}

const char *stin_tier_name(stin_tier tier)
{
    switch (tier) {
    case STIN_TIER_AUTO: return "auto";
    case STIN_TIER_GL1: return "gl1";
    case STIN_TIER_GL2: return "gl2";
    case STIN_TIER_GL4: return "gl4";
    }
    return "unknown tier";
}

const char *stin_feature_name(stin_feature f)
{
    switch (f) {
    case STIN_FEATURE_LIGHTING: return "lighting";
    case STIN_FEATURE_SHADOWS: return "shadows";
    case STIN_FEATURE_SURFACE: return "surface";
    case STIN_FEATURE_TRANSLUCENT_SHADOWS: return "translucent-shadows";
    case STIN_FEATURE_DISPLACEMENT: return "displacement";
    case STIN_FEATURE_CSG: return "csg";
    case STIN_FEATURE_TRANSPARENCY: return "transparency";
    case STIN_FEATURE_COUNT: break;
    }
    return "unknown feature";
}

static const char *const technique_names[] = {
#define STIN_X_(id, name, feature, tier) name,
    STIN_TECHNIQUE_LIST(STIN_X_)
#undef STIN_X_
};

const char *stin_technique_name(stin_technique t)
{
    return (unsigned)t < STIN_TECH_COUNT ? technique_names[t] : "unknown technique";
}

static int same_string(const char *a, const char *b)
{
    while (*a && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

stin_technique stin_technique_from_name(const char *name)
{
    int t;
    if (!name)
        return STIN_TECH_NONE;
    for (t = 1; t < STIN_TECH_COUNT; t++)
        if (same_string(technique_names[t], name))
            return (stin_technique)t;
    return STIN_TECH_NONE;
}

const char *stin_stage_name(stin_stage s)
{
    switch (s) {
    case STIN_STAGE_PREPASS: return "prepass";
    case STIN_STAGE_CSG: return "csg";
    case STIN_STAGE_BASE: return "base";
    case STIN_STAGE_TRANSLUCENT: return "translucent";
    case STIN_STAGE_SHADOW: return "shadow";
    case STIN_STAGE_LIGHTING: return "lighting";
    case STIN_STAGE_BLENDED: return "blended";
    case STIN_STAGE_EXPORT: return "export";
    case STIN_STAGE_COUNT: break;
    }
    return "unknown stage";
}
