/* SPDX-License-Identifier: MIT */
/* What the viewer asks of stin and of the window, and the keys that change
 * it (viewer_settings.c). */
#ifndef VIEWER_SETTINGS_H
#define VIEWER_SETTINGS_H

#include "stin/stin.h"

typedef struct viewer_settings {
    stin_tier tier;                   /* STIN_TIER_AUTO: the best the context runs */
    stin_technique shadows, surface, transparency; /* STIN_TECH_NONE: stin's choice */
    int samples;                      /* 0, 2, 4 or 8 samples a pixel */
    int srgb;                         /* 1: the framebuffer encodes to sRGB */
} viewer_settings;

/* What a key asks the viewer to do. */
typedef enum viewer_action {
    VIEWER_NOTHING = 0,
    VIEWER_RECREATE_CONTEXT, /* tier or technique: a new stin context */
    VIEWER_RECREATE_WINDOW,  /* samples: a new window (and so context) */
    VIEWER_SRGB,             /* sRGB on or off: the next frame */
    VIEWER_OVERLAY,          /* the status overlay on or off */
    VIEWER_HELP,
    VIEWER_RESET_CAMERA,
    VIEWER_QUIT
} viewer_action;

/* Applies key (a GLFW key code) to s: T tier, S shadows, F surface,
 * P transparency (each cycles auto, then the feature's techniques best
 * first), M samples (0, 2, 4, 8), G sRGB, O overlay, H help, R camera,
 * Esc/Q quit.
 * *feature gets the feature a technique key changed (else
 * STIN_FEATURE_COUNT). */
viewer_action viewer_settings_key(viewer_settings *s, int key, stin_feature *feature);
/* The technique after t in feature f's chain (NONE = auto first, wraps). */
stin_technique viewer_next_technique(stin_feature f, stin_technique t);
/* The keys, one a line, for H and --help. */
extern const char viewer_keys_help[];

#endif
