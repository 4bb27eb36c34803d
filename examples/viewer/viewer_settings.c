/* SPDX-License-Identifier: MIT */
#include "viewer_settings.h"

#include <GLFW/glfw3.h>

const char viewer_keys_help[] =
    "  drag          orbit about the camera's target\n"
    "  wheel         zoom\n"
    "  T             tier: auto, gl1, gl2, gl4\n"
    "  S             shadows technique: auto, then each, best first\n"
    "  F             surface technique\n"
    "  P             transparency technique\n"
    "  M             samples: 0, 2, 4, 8 (a new window)\n"
    "  G             sRGB framebuffer on/off\n"
    "  O             status overlay on/off (on at start; off in a --frames script)\n"
    "  R             the file's camera again\n"
    "  H             this help (on stdout)\n"
    "  Q, Esc        quit\n";

stin_technique viewer_next_technique(stin_feature f, stin_technique t)
{
    int i;
    for (i = (int)t + 1; i < STIN_TECH_COUNT; i++) /* the table lists each chain best first */
        if (stin_technique_feature((stin_technique)i) == f)
            return (stin_technique)i;
    return STIN_TECH_NONE;
}

static stin_tier next_tier(stin_tier t)
{
    return t == STIN_TIER_AUTO ? STIN_TIER_GL1
         : t == STIN_TIER_GL1  ? STIN_TIER_GL2
         : t == STIN_TIER_GL2  ? STIN_TIER_GL4
                               : STIN_TIER_AUTO;
}

static viewer_action cycle(stin_technique *t, stin_feature f, stin_feature *changed)
{
    *t = viewer_next_technique(f, *t);
    *changed = f;
    return VIEWER_RECREATE_CONTEXT;
}

viewer_action viewer_settings_key(viewer_settings *s, int key, stin_feature *feature)
{
    *feature = STIN_FEATURE_COUNT;
    switch (key) {
    case GLFW_KEY_T:
        s->tier = next_tier(s->tier);
        return VIEWER_RECREATE_CONTEXT;
    case GLFW_KEY_S:
        return cycle(&s->shadows, STIN_FEATURE_SHADOWS, feature);
    case GLFW_KEY_F:
        return cycle(&s->surface, STIN_FEATURE_SURFACE, feature);
    case GLFW_KEY_P:
        return cycle(&s->transparency, STIN_FEATURE_TRANSPARENCY, feature);
    case GLFW_KEY_M:
        s->samples = s->samples >= 8 ? 0 : s->samples ? s->samples * 2 : 2;
        return VIEWER_RECREATE_WINDOW;
    case GLFW_KEY_G:
        s->srgb = !s->srgb;
        return VIEWER_SRGB;
    case GLFW_KEY_O:
        return VIEWER_OVERLAY;
    case GLFW_KEY_H:
        return VIEWER_HELP;
    case GLFW_KEY_R:
        return VIEWER_RESET_CAMERA;
    case GLFW_KEY_Q:
    case GLFW_KEY_ESCAPE:
        return VIEWER_QUIT;
    default:
        return VIEWER_NOTHING;
    }
}
