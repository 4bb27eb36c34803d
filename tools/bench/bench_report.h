/* SPDX-License-Identifier: MIT */
/* What the sections share when they print: labels, the machine line, and
 * which tiers a section runs (with the SKIP lines for the others). */
#ifndef STIN_BENCH_REPORT_H
#define STIN_BENCH_REPORT_H

#include "bench_section.h"
#include "bench_tech.h"

#include <stddef.h>

/* "tests/scenes/spheres-18k.json" -> "spheres-18k" */
void scene_label(const char *path, char *out, size_t size);
/* "GLSL 1.10, per-pixel lighting" and the like. */
const char *tier_label(stin_tier t);

/* The machine line, once per run. */
void bench_machine_once(bench_env *env);

/* The tiers of `mask` (bit 1 << tier) that --tier allows, into out; 0 and
 * "### what: SKIP (why; --tier X)" when --tier names none of them. */
int bench_tiers(const bench_env *env, unsigned mask, const char *what, const char *why,
                stin_tier *out);
#define TIER_BIT(t) (1u << (t))
#define ALL_TIERS (TIER_BIT(STIN_TIER_GL1) | TIER_BIT(STIN_TIER_GL2) | TIER_BIT(STIN_TIER_GL4))
#define GLSL_TIERS (TIER_BIT(STIN_TIER_GL2) | TIER_BIT(STIN_TIER_GL4))

/* 1 when the context runs `tier`; else prints "### what, tier: SKIP (...)"
 * ("### tier: ..." without what) and sets *rc to EXIT_UNSUPPORTED if
 * --tier forced it. */
int bench_tier_ok(const bench_env *env, stin_tier tier, const char *what, int *rc);

/* A technique section's settings: the run's GL and size, the section's
 * frames and set-ups, a baseline of shadows off and the tier's surface
 * (the caller may change it). */
void bench_tech_settings(const bench_env *env, int section, tech_settings *st);
/* "per side the lowest of S set-ups' median of F frames (..., W warm-up per
 * row)": how a section that times rows against a baseline measures. */
const char *bench_row_timing(const bench_env *env, int setups, int frames, char *buf,
                             size_t size);
/* Runs a technique section's rows on one tier. 1 ran; 0 skipped (rc 0 or
 * EXIT_UNSUPPORTED) or failed (rc EXIT_FAILED). */
int bench_tech_tier(const bench_env *env, tech_settings *st, stin_tier tier, const char *what,
                    const scene *s, tech_row *rows, int row_n, int *rc);
/* A row's time over its baseline's (0 without one). */
double tech_ratio(const tech_row *r);
/* A table of rows (names[i] each) against the baseline (`base` names it:
 * "plain", "off") and against the first row. */
void bench_ratio_table(const char *title, stin_tier tier, const char *base,
                       const char *const *names, const tech_row *rows, int n);

#endif
