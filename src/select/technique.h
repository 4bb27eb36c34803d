/* SPDX-License-Identifier: MIT */
/* The technique table and the solver that walks it (select/technique_table.c,
 * select/select.c). One row per technique holds everything selection needs, so a
 * new technique is a row, and chain order is the row's rank, not the public
 * enum's value (new public values are appended). */
#ifndef STIN_TECHNIQUE_H
#define STIN_TECHNIQUE_H

#include "stin/stin.h"

typedef struct stin__technique_row {
    stin_technique technique;
    uint8_t rank;            /* place in its feature's chain, 0 = tried first */
    uint64_t needs;          /* STIN_CAP_BIT()s */
    /* The lighting it runs on: STIN_TECH_NONE any, STIN_TECH_LIGHTING_GLSL110
     * any GLSL lighting, else exactly that one. */
    stin_technique lighting;
    uint64_t conflicts;      /* STIN__TECH_BIT()s it cannot be chosen together with */
    uint8_t fragment_units;  /* texture units its draws add (albedo counts to lighting) */
    uint8_t vertex_units;    /* vertex texture units it adds */
    /* Texture units it takes only when they are spare and runs without
     * otherwise (volumes: the screen mask that shares lit passes). */
    uint8_t spare_units;
    /* STIN_CAP_BIT()s that lift `conflicts` where the context has them all
     * (0: never): displacement beside volumes, which cast displaced draws
     * through a depth map of their own (shadow/cast_map.c). */
    uint64_t conflicts_lifted;
} stin__technique_row;

#define STIN__TECH_BIT(t) ((uint64_t)1 << (t))

/* The row of a technique; NULL for STIN_TECH_NONE and unknown values. */
const stin__technique_row *stin__technique_row_of(stin_technique t);
/* The techniques of a feature, best first (rank order); returns the count. */
int stin__feature_chain(stin_feature f, stin_technique out[STIN_TECH_COUNT]);

typedef struct stin__selection {
    stin_tier tier;
    stin_choice choice[STIN_FEATURE_COUNT];
    /* Texture units of the chosen techniques, in feature order from 0:
     * lighting's albedo, then the surface's, then the shadows'. */
    int surface_unit, shadow_unit, units_used, unit_limit;
    int shadow_spare_units; /* the shadow technique's spare units it got (from shadow_unit) */
    int translucent_unit;   /* translucent shadows' first unit (deep: two) */
    int transparency_unit;  /* transparency's first unit (depth-peel: two) */
    int displace_unit;      /* displacement's vertex-stage height map (after units_used) */
    stin_log_item failure;  /* why stin__select failed, for the log: BAD_ARGUMENT,
                             * TIER_UNSUPPORTED (a forced tier) or TECHNIQUE_UNSUPPORTED */
} stin__selection;

/* 1 when tier is a stin_tier and each forced technique (NULL: none) is
 * NONE or one of its feature's; else 0 with the reason in msg. The one
 * check of a desc's enum values: stin_memory_size, stin_create and
 * stin__select all ask it. */
int stin__forced_known(stin_tier tier, const stin_technique forced[STIN_FEATURE_COUNT],
                       char *msg, size_t msg_size);
/* Chooses the tier and one technique per feature. Fails (UNSUPPORTED) if a
 * forced tier or technique cannot run; writes the reason into msg and the
 * log item into out->failure. */
stin_result stin__select(const stin_caps *caps, stin_tier forced,
                         const stin_technique forced_tech[STIN_FEATURE_COUNT],
                         stin__selection *out, char *msg, size_t msg_size);
/* Chooses every feature after lighting again, for the lighting in sel
 * (set-up moved it down a tier). */
stin_result stin__select_after_lighting(const stin_caps *caps, const stin_technique *forced,
                                        stin__selection *sel, char *msg, size_t msg_size);
/* Moves feature f's choice to `to` after set-up found the chosen one
 * cannot run; logs a warning and marks the choice as fallen back. */
void stin__demote(struct stin_context *ctx, stin_feature f, stin_technique to, const char *why);
/* What the layers below the features read of the choices, which they may
 * not ask for (ctx->vertex_chunk: whether programs carry the displacement
 * chunk and are tessellated): set after selection (frame/context.c) and by
 * every stin__demote. */
void stin__selection_hand_down(struct stin_context *ctx);
/* The same at log level `level` (INFO where the caller's own choice, not
 * the context, rules the technique out and it was not forced). */
void stin__demote_at(struct stin_context *ctx, stin_log_level level, stin_feature f,
                     stin_technique to, const char *why);

/* For a module whose feature f's choice cannot run after all (before
 * stin__demote): the next technique down f's chain that runs beside the
 * other features' choices - the context has its capabilities, it runs on
 * the chosen tier and lighting, no other choice conflicts with it, and its
 * fragment units fit from f's first unit on (the units placed after f's
 * stay where they are). The chain's last where none does. */
stin_technique stin__fallback(const stin_caps *caps, const stin__selection *sel, stin_feature f);
/* The technique of another feature that feature f's choice conflicts with
 * on this context (a conflict in either row, not lifted by caps),
 * STIN_TECH_NONE where none does: for a choice that a later fall back of
 * another feature put beside it. */
stin_technique stin__choice_conflict(const stin_caps *caps, const stin__selection *sel,
                                     stin_feature f);

/* Row accessors kept for callers that ask one thing. */
uint64_t stin__technique_needs(stin_technique t);
stin_feature stin__technique_feature(stin_technique t);
stin_tier stin__technique_tier(stin_technique t);
stin_technique stin__technique_lighting(stin_technique t);
/* 1 when technique t can run with this lighting technique. */
int stin__technique_runs_with(stin_technique t, stin_technique lighting);
uint64_t stin__tier_needs(stin_tier t);
/* The needs (a row's or a tier's) as this context reads them: on OpenGL ES
 * a GLSL need's FIXED_FUNCTION (the compatibility context #version 110 asks
 * for on desktop) is met by GLSL ES 1.00; the GL1 rows keep it and are never
 * offered on ES. */
uint64_t stin__needs_here(const stin_caps *caps, uint64_t needs);
/* Names of the bits in `bits`, comma separated. */
void stin__cap_names(uint64_t bits, char *out, size_t size);

#endif
