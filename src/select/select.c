/* SPDX-License-Identifier: MIT */
/* Tier selection and the per-feature fallback chains. */
#include "internal.h"

/* How a lighting requirement reads in messages. */
static const char *lighting_class(stin_technique need)
{
    return need == STIN_TECH_LIGHTING_GLSL110 ? "GLSL" : stin_technique_name(need);
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
    uint64_t lack;
    if (!caps) {
        if (missing && size)
            missing[0] = '\0';
        return 0;
    }
    lack = stin__needs_here(caps, stin__tier_needs(tier)) & ~caps->present;
    if (missing)
        stin__cap_names(lack, missing, size);
    return tier != STIN_TIER_AUTO && lack == 0;
}

stin_tier stin_best_tier(const stin_caps *caps)
{
    if (!caps)
        return STIN_TIER_AUTO;
    if (stin_tier_supported(caps, STIN_TIER_GL4, NULL, 0))
        return STIN_TIER_GL4;
    if (stin_tier_supported(caps, STIN_TIER_GL2, NULL, 0))
        return STIN_TIER_GL2;
    if (stin_tier_supported(caps, STIN_TIER_GL1, NULL, 0))
        return STIN_TIER_GL1;
    return STIN_TIER_AUTO;
}


/* ---- the solver ----------------------------------------------------------- */

/* What one feature's choice may use. */
typedef struct chain_input {
    const stin_caps *caps;
    stin_tier tier;
    stin_feature feature;
    stin_technique forced, lighting;
    uint64_t chosen;   /* STIN__TECH_BIT()s of the features chosen so far */
    uint64_t forced_all; /* STIN__TECH_BIT()s of every feature's forced technique */
    int units_left;    /* texture units still free for this feature */
    int unit_limit;    /* the context's units for the chosen lighting */
} chain_input;

/* A row's conflicts on this context: none where it has every capability
 * that lifts them. */
static uint64_t row_conflicts(const stin_caps *caps, const stin__technique_row *r)
{
    uint64_t lift = r->conflicts_lifted;
    return lift && (caps->present & lift) == lift ? 0 : r->conflicts;
}

/* The techniques a set conflicts with, from either side's row: a conflict
 * is recorded once, on the technique that has it. */
static uint64_t conflicts_of(const stin_caps *caps, uint64_t set)
{
    uint64_t out = 0;
    int t;
    for (t = 0; t < STIN_TECH_COUNT; t++) {
        const stin__technique_row *r = stin__technique_row_of((stin_technique)t);
        if (r && (set & STIN__TECH_BIT(t)))
            out |= row_conflicts(caps, r);
    }
    return out;
}

static int frag_units(stin_technique t)
{
    const stin__technique_row *r = stin__technique_row_of(t);
    return r ? r->fragment_units : 0;
}

/* Why t cannot be this feature's choice here, or "" if it can. A technique
 * above the tier ceiling or on another lighting path is not a fallback; the
 * return value says so (0: passed over, 1: could not run). */
static int why_not(const chain_input *in, stin_technique t, char *why, size_t size)
{
    const stin__technique_row *r = stin__technique_row_of(t);
    uint64_t lack = stin__needs_here(in->caps, r->needs) & ~in->caps->present;
    char names[160];
    why[0] = '\0';
    stin__cap_names(lack, names, sizeof names);
    if (stin__technique_tier(t) > in->tier) {
        stin__formatf(why, size, "%s needs tier %s%s%s", stin_technique_name(t),
                      stin_tier_name(stin__technique_tier(t)), lack ? ", " : "", names);
        return 0;
    }
    if (lack) {
        stin__formatf(why, size, "%s needs %s", stin_technique_name(t), names);
        return 1;
    }
    if (!stin__technique_runs_with(t, in->lighting)) {
        stin__formatf(why, size, "%s needs %s lighting (lighting is %s)", stin_technique_name(t),
                      lighting_class(r->lighting), stin_technique_name(in->lighting));
        return 0;
    }
    if ((row_conflicts(in->caps, r) & in->chosen) ||
        (conflicts_of(in->caps, in->chosen) & STIN__TECH_BIT(t))) {
        stin__formatf(why, size, "%s cannot run beside the techniques chosen before it",
                      stin_technique_name(t));
        return 1;
    }
    /* an automatic choice leaves room for another feature's forced technique */
    if (in->forced == STIN_TECH_NONE &&
        ((row_conflicts(in->caps, r) & in->forced_all) ||
         (conflicts_of(in->caps, in->forced_all) & STIN__TECH_BIT(t)))) {
        stin__formatf(why, size, "%s cannot run beside a forced technique", stin_technique_name(t));
        return 1;
    }
    if (r->fragment_units > in->units_left) {
        stin__formatf(why, size, "%s needs %d texture units together with the features "
                      "chosen before it, the context has %d", stin_technique_name(t),
                      in->unit_limit - in->units_left + r->fragment_units, in->unit_limit);
        return 1;
    }
    return 1;
}

int stin__forced_known(stin_tier tier, const stin_technique forced[STIN_FEATURE_COUNT],
                       char *msg, size_t msg_size)
{
    int f;
    if (tier != STIN_TIER_AUTO && tier != STIN_TIER_GL1 && tier != STIN_TIER_GL2 &&
        tier != STIN_TIER_GL4) {
        stin__formatf(msg, msg_size, "unknown tier %d", (int)tier);
        return 0;
    }
    for (f = 0; forced && f < STIN_FEATURE_COUNT; f++)
        if (forced[f] != STIN_TECH_NONE &&
            ((unsigned)forced[f] >= STIN_TECH_COUNT ||
             stin__technique_feature(forced[f]) != (stin_feature)f)) {
            stin__formatf(msg, msg_size, "technique %s is not a %s technique",
                          stin_technique_name(forced[f]), stin_feature_name((stin_feature)f));
            return 0;
        }
    return 1;
}

/* in->forced is known and of in->feature (stin__forced_known). */
static stin_result choose_forced(const chain_input *in, stin_choice *out, char *msg,
                                 size_t msg_size)
{
    char why[160];
    why_not(in, in->forced, why, sizeof why);
    if (why[0]) {
        stin__formatf(msg, msg_size, "%s technique %s", stin_feature_name(in->feature), why);
        return STIN_ERROR_UNSUPPORTED;
    }
    out->technique = in->forced;
    out->fell_back = 0;
    stin__formatf(out->reason, sizeof out->reason, "forced by the caller");
    return STIN_OK;
}

/* Walks the feature's chain from the best technique down; records why each
 * better one was passed over. */
static stin_result choose(const chain_input *in, stin_choice *out, char *msg, size_t msg_size)
{
    stin_technique chain[STIN_TECH_COUNT];
    char why[160], fell[160], note[96];
    int n, i;
    if (in->forced != STIN_TECH_NONE)
        return choose_forced(in, out, msg, msg_size);
    fell[0] = note[0] = '\0';
    n = stin__feature_chain(in->feature, chain);
    for (i = 0; i < n; i++) {
        int could_not = why_not(in, chain[i], why, sizeof why);
        if (why[0]) {
            if (could_not)
                stin__formatf(fell, sizeof fell, "%s", why);
            else if (!note[0] && stin__technique_tier(chain[i]) <= in->tier)
                stin__formatf(note, sizeof note, "%s runs with %s lighting only; ",
                              stin_technique_name(chain[i]),
                              lighting_class(stin__technique_lighting(chain[i])));
            continue;
        }
        out->technique = chain[i];
        out->fell_back = fell[0] != '\0';
        if (fell[0])
            stin__formatf(out->reason, sizeof out->reason, "fallback: %s", fell);
        else
            stin__formatf(out->reason, sizeof out->reason, "%sbest for tier %s", note,
                          stin_tier_name(in->tier));
        return STIN_OK;
    }
    stin__formatf(msg, msg_size, "no %s technique runs here (%s)", stin_feature_name(in->feature),
                  fell);
    return STIN_ERROR_UNSUPPORTED;
}

/* The unit limit of a lighting technique's draws; 0 (not reported) is no limit. */
static int unit_limit(const stin_caps *caps, stin_technique lighting)
{
    int n = lighting == STIN_TECH_LIGHTING_FIXED ? caps->max_texture_units
                                                 : caps->max_texture_image_units;
    return n > 0 ? n : 1 << 20;
}

/* Where each feature's texture units start: albedo 0, the surface's, then the
 * shadows'. DOT3 takes a fourth unit (albedo textures) when one is spare, and
 * so does a shadow technique with spare units in its row. */
static void place_units(stin__selection *sel)
{
    stin_technique surface = sel->choice[STIN_FEATURE_SURFACE].technique;
    int shadow = frag_units(sel->choice[STIN_FEATURE_SHADOWS].technique);
    int surf = frag_units(surface);
    sel->surface_unit = frag_units(sel->choice[STIN_FEATURE_LIGHTING].technique);
    if (surface == STIN_TECH_SURFACE_DOT3 && sel->surface_unit + surf + 1 + shadow <= sel->unit_limit)
        surf++;
    sel->shadow_unit = sel->surface_unit + surf;
    sel->units_used = sel->shadow_unit + shadow;
    {
        const stin__technique_row *r =
            stin__technique_row_of(sel->choice[STIN_FEATURE_SHADOWS].technique);
        int spare = r ? r->spare_units : 0;
        sel->shadow_spare_units = sel->units_used + spare <= sel->unit_limit ? spare : 0;
        sel->units_used += sel->shadow_spare_units;
    }
    /* translucent shadows' units after the shadows' */
    sel->translucent_unit = sel->units_used;
    sel->units_used += frag_units(sel->choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].technique);
    /* transparency's after those */
    sel->transparency_unit = sel->units_used;
    sel->units_used += frag_units(sel->choice[STIN_FEATURE_TRANSPARENCY].technique);
    /* the vertex stage's height map: a unit of its own after the fragment
     * stage's (vertex samplers count against the combined units) */
    sel->displace_unit = sel->units_used;
}

/* Chooses every feature after lighting, for the lighting in sel. Forced
 * techniques' units are set aside first, so an automatic choice cannot take
 * what a forced one needs. */
static stin_result choose_after_lighting(const stin_caps *caps, const stin_technique *forced,
                                         stin__selection *sel, char *msg, size_t msg_size)
{
    stin_technique lighting = sel->choice[STIN_FEATURE_LIGHTING].technique;
    int f, reserved = 0, used = frag_units(lighting);
    uint64_t chosen = STIN__TECH_BIT(lighting), forced_all = 0;
    sel->unit_limit = unit_limit(caps, lighting);
    for (f = STIN_FEATURE_LIGHTING + 1; f < STIN_FEATURE_COUNT; f++)
        if (forced && forced[f] != STIN_TECH_NONE) {
            reserved += frag_units(forced[f]);
            if ((unsigned)forced[f] < STIN_TECH_COUNT)
                forced_all |= STIN__TECH_BIT(forced[f]);
        }
    for (f = STIN_FEATURE_LIGHTING + 1; f < STIN_FEATURE_COUNT; f++) {
        chain_input in;
        stin_result r;
        in.caps = caps;
        in.tier = sel->tier;
        in.feature = (stin_feature)f;
        in.forced = forced ? forced[f] : STIN_TECH_NONE;
        in.lighting = lighting;
        in.chosen = chosen;
        in.forced_all = forced_all;
        if (in.forced != STIN_TECH_NONE)
            reserved -= frag_units(in.forced);
        in.units_left = sel->unit_limit - used - reserved;
        in.unit_limit = sel->unit_limit;
        r = choose(&in, &sel->choice[f], msg, msg_size);
        if (r != STIN_OK)
            return r;
        used += frag_units(sel->choice[f].technique);
        chosen |= STIN__TECH_BIT(sel->choice[f].technique);
    }
    place_units(sel);
    return STIN_OK;
}

stin_result stin__select_after_lighting(const stin_caps *caps, const stin_technique *forced,
                                        stin__selection *sel, char *msg, size_t msg_size)
{
    return choose_after_lighting(caps, forced, sel, msg, msg_size);
}

static stin_result select_all(const stin_caps *caps, stin_tier forced,
                              const stin_technique forced_tech[STIN_FEATURE_COUNT],
                              stin__selection *out, char *msg, size_t msg_size)
{
    char missing[256];
    chain_input in;
    stin_result r;
    stin__memzero(out, sizeof *out);
    if (!stin__forced_known(forced, forced_tech, msg, msg_size))
        return STIN_ERROR_INVALID_ARGUMENT;
    if (forced == STIN_TIER_AUTO) {
        out->tier = stin_best_tier(caps);
        if (out->tier == STIN_TIER_AUTO) {
            stin_tier_supported(caps, STIN_TIER_GL1, missing, sizeof missing);
            stin__formatf(msg, msg_size, "no tier runs on this context: GL1 needs %s", missing);
            return STIN_ERROR_UNSUPPORTED;
        }
    } else if (!stin_tier_supported(caps, forced, missing, sizeof missing)) {
        stin__formatf(msg, msg_size, "tier %s needs %s", stin_tier_name(forced), missing);
        out->failure = STIN_LOG_TIER_UNSUPPORTED;
        return STIN_ERROR_UNSUPPORTED;
    } else {
        out->tier = forced;
    }
    /* lighting first: every other feature's chain depends on it */
    stin__memzero(&in, sizeof in);
    in.caps = caps;
    in.tier = out->tier;
    in.feature = STIN_FEATURE_LIGHTING;
    in.forced = forced_tech ? forced_tech[STIN_FEATURE_LIGHTING] : STIN_TECH_NONE;
    in.units_left = in.unit_limit = 1 << 20;
    r = choose(&in, &out->choice[STIN_FEATURE_LIGHTING], msg, msg_size);
    if (r != STIN_OK)
        return r;
    return choose_after_lighting(caps, forced_tech, out, msg, msg_size);
}

/* ---- after set-up: falling back and conflicts ------------------------------ */

/* Where feature f's fragment units start (place_units); the features
 * without any start after the rest. */
static int first_unit(const stin__selection *sel, stin_feature f)
{
    switch (f) {
    case STIN_FEATURE_LIGHTING: return 0;
    case STIN_FEATURE_SURFACE: return sel->surface_unit;
    case STIN_FEATURE_SHADOWS: return sel->shadow_unit;
    case STIN_FEATURE_TRANSLUCENT_SHADOWS: return sel->translucent_unit;
    case STIN_FEATURE_TRANSPARENCY: return sel->transparency_unit;
    default: return sel->units_used;
    }
}

/* STIN__TECH_BIT()s of every feature's choice but f's. */
static uint64_t others_chosen(const stin__selection *sel, stin_feature f)
{
    uint64_t bits = 0;
    int g;
    for (g = 0; g < STIN_FEATURE_COUNT; g++)
        if (g != (int)f && (unsigned)sel->choice[g].technique < STIN_TECH_COUNT)
            bits |= STIN__TECH_BIT(sel->choice[g].technique);
    return bits;
}

stin_technique stin__fallback(const stin_caps *caps, const stin__selection *sel, stin_feature f)
{
    stin_technique chain[STIN_TECH_COUNT];
    chain_input in;
    char why[160];
    int n = stin__feature_chain(f, chain), i = 0;
    while (i < n && chain[i] != sel->choice[f].technique)
        i++;
    stin__memzero(&in, sizeof in);
    in.caps = caps;
    in.tier = sel->tier;
    in.feature = f;
    in.forced = STIN_TECH_NONE; /* (forced_all 0: no room is kept for forced ones) */
    in.lighting = sel->choice[STIN_FEATURE_LIGHTING].technique;
    in.chosen = others_chosen(sel, f);
    in.unit_limit = sel->unit_limit;
    in.units_left = sel->unit_limit - first_unit(sel, f);
    for (i++; i < n; i++) {
        why_not(&in, chain[i], why, sizeof why);
        if (!why[0])
            return chain[i];
    }
    return n > 0 ? chain[n - 1] : STIN_TECH_NONE;
}

stin_technique stin__choice_conflict(const stin_caps *caps, const stin__selection *sel,
                                     stin_feature f)
{
    uint64_t own = STIN__TECH_BIT(sel->choice[f].technique);
    int g;
    for (g = 0; g < STIN_FEATURE_COUNT; g++) {
        stin_technique t = sel->choice[g].technique;
        if (g == (int)f || (unsigned)t >= STIN_TECH_COUNT)
            continue;
        if ((conflicts_of(caps, own) & STIN__TECH_BIT(t)) ||
            (conflicts_of(caps, STIN__TECH_BIT(t)) & own))
            return t;
    }
    return STIN_TECH_NONE;
}

void stin__selection_hand_down(stin_context *ctx)
{
    stin_technique t = ctx->sel.choice[STIN_FEATURE_DISPLACEMENT].technique;
    ctx->vertex_chunk.displace = t == STIN_TECH_DISPLACEMENT_VTF || t == STIN_TECH_DISPLACEMENT_TESS;
    ctx->vertex_chunk.tessellate = t == STIN_TECH_DISPLACEMENT_TESS;
}

void stin__demote(stin_context *ctx, stin_feature f, stin_technique to, const char *why)
{
    stin__demote_at(ctx, STIN_LOG_LEVEL_WARNING, f, to, why);
}

void stin__demote_at(stin_context *ctx, stin_log_level level, stin_feature f, stin_technique to,
                     const char *why)
{
    stin_choice *c = &ctx->sel.choice[f];
    stin__log(ctx, level, STIN_LOG_FALLBACK, "%s: %s falls back to %s: %s",
              stin_feature_name(f), stin_technique_name(c->technique), stin_technique_name(to),
              why);
    c->technique = to;
    c->fell_back = 1;
    stin__formatf(c->reason, sizeof c->reason, "fallback: %s", why);
    stin__selection_hand_down(ctx); /* the layers below see every step down */
}

stin_result stin__select(const stin_caps *caps, stin_tier forced,
                         const stin_technique forced_tech[STIN_FEATURE_COUNT],
                         stin__selection *out, char *msg, size_t msg_size)
{
    stin_result r = select_all(caps, forced, forced_tech, out, msg, msg_size);
    if (r == STIN_ERROR_INVALID_ARGUMENT)
        out->failure = STIN_LOG_BAD_ARGUMENT;
    else if (r != STIN_OK && out->failure == STIN_LOG_NONE)
        out->failure = STIN_LOG_TECHNIQUE_UNSUPPORTED;
    return r;
}
