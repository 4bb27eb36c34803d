/* SPDX-License-Identifier: MIT */
#include "viewer_status.h"

#include <stdio.h>
#include <string.h>

/* The features the keys choose, in title order. */
static const stin_feature shown[] = {STIN_FEATURE_SHADOWS, STIN_FEATURE_SURFACE,
                                     STIN_FEATURE_TRANSPARENCY};

static size_t put(char *out, size_t size, size_t at, const char *fmt, const char *a,
                  double x)
{
    int n;
    if (at >= size)
        return at;
    n = a ? snprintf(out + at, size - at, fmt, a) : snprintf(out + at, size - at, fmt, x);
    return n < 0 ? at : at + (size_t)n;
}

/* The stages that took time, in the frame plan's order. */
static size_t put_stages(char *out, size_t size, size_t at, const stin_frame_stats *st)
{
    int i;
    if (!st->stage_times)
        return put(out, size, at, "%s", " (no timer queries)", 0);
    at = put(out, size, at, "%s", " [", 0);
    for (i = 0; i < STIN_STAGE_COUNT; i++)
        if (st->stage_ns[i] >= 5000) { /* under 0.005 ms reads 0.00: left out */
            at = put(out, size, at, "%s ", stin_stage_name((stin_stage)i), 0);
            at = put(out, size, at, "%.2f ", NULL, st->stage_ns[i] / 1e6);
        }
    if (at > 0 && at < size && out[at - 1] == ' ')
        at--;
    return put(out, size, at, "%s", "]", 0);
}

static const char *why_text(const viewer_session *v, stin_feature f, stin_choice *c)
{
    int n;
    size_t len = strlen(stin_feature_name(f));
    if (v->refused[0])
        return v->refused;
    for (n = v->log.note_count - 1; n >= 0; n--) /* a fallback of this frame's */
        if (!strncmp(v->log.notes[n], stin_feature_name(f), len))
            return v->log.notes[n];
    *c = stin_query_choice(v->sc.ctx, f);
    return c->reason;
}

/* Samples and sRGB: after the tier on its line, or " | 4x | sRGB". */
static size_t put_target(char *out, size_t size, size_t at, const viewer_window *w, int lines)
{
    if (lines && !w->samples)
        at = put(out, size, at, "%s", ", single-sampled", 0);
    if (w->samples)
        at = put(out, size, at, lines ? ", %.0f samples" : " | %.0fx", NULL, (double)w->samples);
    if (w->srgb_asked && w->srgb_capable)
        at = put(out, size, at, "%s", lines ? ", sRGB" : " | sRGB", 0);
    return at;
}

/* The facts as the title (lines = 0: " | " between them) or the overlay's
 * lines (1: a fact a line, each named). */
static void compose(const viewer_session *v, const viewer_window *w, stin_feature why_feature,
                    double frame_ms, int lines, char *out, size_t size)
{
    size_t at = 0, i;
    stin_frame_stats st = stin_query_frame_stats(v->sc.ctx);
    stin_feature f = why_feature == STIN_FEATURE_COUNT ? STIN_FEATURE_SHADOWS : why_feature;
    const char *sep = lines ? "\n" : " | ";
    stin_choice c;
    at = put(out, size, at, lines ? "tier %s" : "stin %s",
             stin_tier_name(stin_query_tier(v->sc.ctx)), 0);
    if (lines)
        at = put_target(out, size, at, w, 1);
    for (i = 0; i < sizeof shown / sizeof shown[0]; i++) {
        stin_choice ci = stin_query_choice(v->sc.ctx, shown[i]);
        at = put(out, size, at, "%s", sep, 0);
        if (lines)
            at = put(out, size, at, "%s: ", stin_feature_name(shown[i]), 0);
        at = put(out, size, at, "%s", stin_technique_name(ci.technique), 0);
    }
    if (!lines)
        at = put_target(out, size, at, w, 0);
    at = put(out, size, at, "%s", sep, 0);
    at = put(out, size, at, lines ? "frame %.1f ms\nstages" : "%.1f ms", NULL, frame_ms);
    at = put_stages(out, size, at, &st);
    at = put(out, size, at, "%s", sep, 0);
    at = put(out, size, at, lines ? "why %s: " : "%s: ", stin_feature_name(f), 0);
    put(out, size, at, "%s", why_text(v, f, &c), 0);
}

void viewer_status_title(const viewer_session *v, const viewer_window *w,
                         stin_feature why_feature, double frame_ms, char *out, size_t size)
{
    compose(v, w, why_feature, frame_ms, 0, out, size);
}

void viewer_status_lines(const viewer_session *v, const viewer_window *w,
                         stin_feature why_feature, double frame_ms, char *out, size_t size)
{
    compose(v, w, why_feature, frame_ms, 1, out, size);
}

void viewer_status_print(const viewer_session *v, const viewer_window *w)
{
    size_t i;
    const viewer_settings *s = &v->running;
    printf("tier: %s%s\n", stin_tier_name(stin_query_tier(v->sc.ctx)),
           s->tier == STIN_TIER_AUTO ? "" : " (forced)");
    for (i = 0; i < sizeof shown / sizeof shown[0]; i++) {
        stin_choice c = stin_query_choice(v->sc.ctx, shown[i]);
        printf("%s: %s (%s)\n", stin_feature_name(shown[i]), stin_technique_name(c.technique),
               c.reason); /* the reason says where the caller forced it */
    }
    for (i = 0; i < (size_t)v->log.note_count; i++)
        printf("frame fell back: %s\n", v->log.notes[i]);
    printf("samples: %d (asked %d)%s; sRGB: %s\n", w->samples, w->samples_asked,
           w->samples_asked && w->samples < w->samples_asked ? ", more are unavailable here" : "",
           !w->srgb_capable ? "unavailable here (the framebuffer cannot encode)"
           : w->srgb_asked  ? "on"
                            : "off");
    if (v->refused[0])
        printf("refused: %s\n", v->refused);
    fflush(stdout);
}
