/* Tier selection and the per-feature fallback chains. */
#include "internal.h"

#define BIT(c) STIN_CAP_BIT(STIN_CAP_##c)

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

uint64_t stin__tier_needs(stin_tier t)
{
    switch (t) {
    case STIN_TIER_GL1: return BIT(FIXED_FUNCTION);
    /* GLSL 1.10 shaders need a compatibility context next to GL 2.0. */
    case STIN_TIER_GL2: return BIT(GLSL) | BIT(FIXED_FUNCTION);
    case STIN_TIER_GL4: return BIT(GLSL) | BIT(GEOMETRY_SHADER) | BIT(VBO) | BIT(VAO) | BIT(FBO);
    case STIN_TIER_AUTO: break;
    }
    return 0;
}

uint64_t stin__technique_needs(stin_technique t)
{
    switch (t) {
    case STIN_TECH_LIGHTING_GLSL150: return stin__tier_needs(STIN_TIER_GL4);
    case STIN_TECH_LIGHTING_GLSL110: return stin__tier_needs(STIN_TIER_GL2);
    case STIN_TECH_LIGHTING_FIXED: return stin__tier_needs(STIN_TIER_GL1);
    case STIN_TECH_SHADOWS_VOLUME: return BIT(STENCIL);
    case STIN_TECH_SHADOWS_MAP_DEPTH: return BIT(DEPTH_TEXTURE) | BIT(SHADOW) | BIT(MULTITEXTURE);
    case STIN_TECH_SHADOWS_MAP_PCF:
        return BIT(GLSL) | BIT(FBO) | BIT(DEPTH_TEXTURE) | BIT(SHADOW) | BIT(MULTITEXTURE);
    case STIN_TECH_SHADOWS_MAP_COMBINE: return BIT(TEXTURE_ENV_COMBINE) | BIT(MULTITEXTURE);
    case STIN_TECH_SURFACE_POM:
    case STIN_TECH_SURFACE_PARALLAX:
    case STIN_TECH_SURFACE_NORMAL: /* three samplers: albedo, normal map, height map */
        return BIT(GLSL) | BIT(MULTITEXTURE);
    case STIN_TECH_SURFACE_DOT3:
        return BIT(MULTITEXTURE) | BIT(TEXTURE_ENV_COMBINE) | BIT(TEXTURE_ENV_DOT3) |
               BIT(TEXTURE_CUBE_MAP) | BIT(FIXED_FUNCTION);
    default: return 0;
    }
}

/* Techniques that only run on top of one lighting technique. Features are
 * chosen one after the other (lighting first); a technique whose lighting
 * requirement is not the lighting chosen is passed over like one whose
 * capabilities are missing. DOT3 bump mapping is a fixed-function texture
 * combiner set-up: it draws in the fixed-function path's lit passes only, so
 * the GLSL tiers (whose normal mapping is their own surface technique) never
 * pick it, even where the context has the capabilities. The GLSL surface
 * techniques (normal, parallax, pom) are chunks of the GLSL lit programs:
 * they name STIN_TECH_LIGHTING_GLSL110, which stands for "any GLSL lighting"
 * (stin__technique_runs_with). */
stin_technique stin__technique_lighting(stin_technique t)
{
    switch (t) {
    case STIN_TECH_SURFACE_POM:
    case STIN_TECH_SURFACE_PARALLAX:
    case STIN_TECH_SURFACE_NORMAL:
    case STIN_TECH_SHADOWS_MAP_PCF: /* a chunk of the lit programs too */
        return STIN_TECH_LIGHTING_GLSL110;
    case STIN_TECH_SURFACE_DOT3:
    case STIN_TECH_SHADOWS_MAP_DEPTH: /* texture-environment shadow tests, likewise */
    case STIN_TECH_SHADOWS_MAP_COMBINE:
        return STIN_TECH_LIGHTING_FIXED;
    default:
        return STIN_TECH_NONE;
    }
}

int stin__technique_runs_with(stin_technique t, stin_technique lighting)
{
    stin_technique need = stin__technique_lighting(t);
    if (need == STIN_TECH_NONE || need == lighting)
        return 1;
    /* GLSL 1.10 lighting stands for the GLSL class: 1.50 runs those too */
    return need == STIN_TECH_LIGHTING_GLSL110 && lighting == STIN_TECH_LIGHTING_GLSL150;
}

/* How a lighting requirement reads in messages. */
static const char *lighting_class(stin_technique need)
{
    return need == STIN_TECH_LIGHTING_GLSL110 ? "GLSL" : stin_technique_name(need);
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

static size_t append(char *out, size_t size, size_t at, const char *s)
{
    while (*s) {
        if (at + 1 < size)
            out[at] = *s;
        at++;
        s++;
    }
    if (size)
        out[at < size ? at : size - 1] = '\0';
    return at;
}

void stin__cap_names(uint64_t bits, char *out, size_t size)
{
    size_t at = 0;
    int c, first = 1;
    if (size)
        out[0] = '\0';
    for (c = 0; c < STIN_CAP_COUNT; c++) {
        if (!(bits & STIN_CAP_BIT(c)))
            continue;
        if (!first)
            at = append(out, size, at, ", ");
        at = append(out, size, at, stin_cap_name((stin_cap)c));
        first = 0;
    }
}

int stin_tier_supported(const stin_caps *caps, stin_tier tier, char *missing, size_t size)
{
    uint64_t lack = stin__tier_needs(tier) & ~caps->present;
    if (missing)
        stin__cap_names(lack, missing, size);
    return tier != STIN_TIER_AUTO && lack == 0;
}

stin_tier stin_best_tier(const stin_caps *caps)
{
    if (stin_tier_supported(caps, STIN_TIER_GL4, NULL, 0))
        return STIN_TIER_GL4;
    if (stin_tier_supported(caps, STIN_TIER_GL2, NULL, 0))
        return STIN_TIER_GL2;
    if (stin_tier_supported(caps, STIN_TIER_GL1, NULL, 0))
        return STIN_TIER_GL1;
    return STIN_TIER_AUTO;
}

/* Walks the feature's chain from the best technique down; records why each
 * better one was passed over. */
stin_result stin__choose(const stin_caps *caps, stin_tier tier, stin_feature f,
                          stin_technique forced, stin_technique lighting, stin_choice *out,
                          char *msg, size_t msg_size)
{
    char why[160], names[160], note[96];
    int t;
    why[0] = note[0] = '\0';
    if (forced != STIN_TECH_NONE) {
        uint64_t lack = stin__technique_needs(forced) & ~caps->present;
        if ((unsigned)forced >= STIN_TECH_COUNT || tech_feature[forced] != f) {
            stin__formatf(msg, msg_size, "technique %s is not a %s technique",
                          stin_technique_name(forced), stin_feature_name(f));
            return STIN_ERROR_INVALID_ARGUMENT;
        }
        if (tech_tier[forced] > tier || lack) {
            stin__cap_names(lack, names, sizeof names);
            stin__formatf(msg, msg_size, "%s technique %s needs %s%s%s%s", stin_feature_name(f),
                          stin_technique_name(forced),
                          tech_tier[forced] > tier ? "tier " : "",
                          tech_tier[forced] > tier ? stin_tier_name(tech_tier[forced]) : "",
                          tech_tier[forced] > tier && lack ? ", " : "", lack ? names : "");
            return STIN_ERROR_UNSUPPORTED;
        }
        if (!stin__technique_runs_with(forced, lighting)) {
            stin__formatf(msg, msg_size, "%s technique %s needs %s lighting "
                          "(lighting is %s)", stin_feature_name(f), stin_technique_name(forced),
                          lighting_class(stin__technique_lighting(forced)),
                          stin_technique_name(lighting));
            return STIN_ERROR_UNSUPPORTED;
        }
        out->technique = forced;
        stin__formatf(out->reason, sizeof out->reason, "forced by the caller");
        return STIN_OK;
    }
    for (t = 1; t < STIN_TECH_COUNT; t++) {
        uint64_t lack;
        if (tech_feature[t] != f)
            continue;
        lack = stin__technique_needs((stin_technique)t) & ~caps->present;
        if (tech_tier[t] > tier)
            continue; /* above the tier ceiling: not a fallback */
        if (lack) {
            stin__cap_names(lack, names, sizeof names);
            stin__formatf(why, sizeof why, "%s needs %s", stin_technique_name((stin_technique)t),
                          names);
            continue;
        }
        if (!stin__technique_runs_with((stin_technique)t, lighting)) {
            /* not a fallback: the chosen lighting path does not draw it */
            if (!note[0])
                stin__formatf(note, sizeof note, "%s runs with %s lighting only; ",
                              stin_technique_name((stin_technique)t),
                              lighting_class(stin__technique_lighting((stin_technique)t)));
            continue;
        }
        out->technique = (stin_technique)t;
        if (why[0])
            stin__formatf(out->reason, sizeof out->reason, "fallback: %s", why);
        else
            stin__formatf(out->reason, sizeof out->reason, "%sbest for tier %s", note,
                          stin_tier_name(tier));
        return STIN_OK;
    }
    stin__formatf(msg, msg_size, "no %s technique runs here (%s)", stin_feature_name(f), why);
    return STIN_ERROR_UNSUPPORTED;
}

stin_result stin__select(const stin_caps *caps, stin_tier forced,
                         const stin_technique forced_tech[STIN_FEATURE_COUNT],
                         stin__selection *out, char *msg, size_t msg_size)
{
    char missing[256];
    int f;
    stin__memzero(out, sizeof *out);
    if (forced != STIN_TIER_AUTO && forced != STIN_TIER_GL1 && forced != STIN_TIER_GL2 &&
        forced != STIN_TIER_GL4) {
        stin__formatf(msg, msg_size, "unknown tier %d", (int)forced);
        return STIN_ERROR_INVALID_ARGUMENT;
    }
    if (forced == STIN_TIER_AUTO) {
        out->tier = stin_best_tier(caps);
        if (out->tier == STIN_TIER_AUTO) {
            stin_tier_supported(caps, STIN_TIER_GL1, missing, sizeof missing);
            stin__formatf(msg, msg_size, "no tier runs on this context: GL1 needs %s", missing);
            return STIN_ERROR_UNSUPPORTED;
        }
    } else if (!stin_tier_supported(caps, forced, missing, sizeof missing)) {
        stin__formatf(msg, msg_size, "tier %s needs %s", stin_tier_name(forced), missing);
        return STIN_ERROR_UNSUPPORTED;
    } else {
        out->tier = forced;
    }
    for (f = 0; f < STIN_FEATURE_COUNT; f++) {
        /* features in enum order: lighting is chosen before the techniques that need it */
        stin_result r = stin__choose(caps, out->tier, (stin_feature)f,
                               forced_tech ? forced_tech[f] : STIN_TECH_NONE,
                               out->choice[STIN_FEATURE_LIGHTING].technique, &out->choice[f],
                               msg, msg_size);
        if (r != STIN_OK)
            return r;
    }
    return STIN_OK;
}
