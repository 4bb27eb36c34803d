/* SPDX-License-Identifier: MIT */
/* One stin render of a scene under the run's profile, read back into the AOV
 * image of the render tool's contract, with the checked build's counters. */
#ifndef STIN_TESTS_CAPTURE_H
#define STIN_TESTS_CAPTURE_H

#include "image_io.h"
#include "scene.h"
#include "stin/stin.h"
#include "stin/stin_debug.h"
#include "stin_platform.h"

/* Every field is part of the frame cache's key (capture_cache.c hashes
 * them one by one): a new one must be added there. */
typedef struct capture_options {
    stin_tier tier;
    stin_technique shadows;   /* forced shadow technique */
    uint64_t debug_flags;     /* STIN_DEBUG_* */
    uint64_t extra_mask;      /* capabilities hidden on top of the profile's */
    uint32_t shadow_map_size; /* 0: stin's default */
    stin_technique surface;   /* forced surface technique; NONE = auto */
    stin_technique displacement; /* forced displacement technique; NONE = auto */
    float guard_band;         /* stin_desc.displacement.guard_band; 0 = stin's default */
    float tess_pixels;        /* stin_desc.displacement.tess_pixels; 0 = stin's default */
    const struct scene_gpu_csg *csg; /* CSG products of the scene's objects (NULL: none) */
    int csg_count;
    stin_technique csg_technique; /* forced CSG technique; NONE = auto */
    uint32_t csg_capacity;    /* desc.csg.max_primitives, _terms, _literals; 0 = stin's */
    /* forced translucent-shadows technique; NONE = translucent-solid: the
     * shadow tests compare the hard visibility (deep_test.c asks for deep) */
    stin_technique translucent;
    uint32_t deep_layers, deep_map_size; /* stin_desc's; 0 = stin's defaults */
    int deep_mono;
    float opaque_threshold; /* stin_desc.translucent.opaque_threshold; 0 = stin's default */
    /* 1: the visibility frame alone, for rows that read only vis, P, Z and
     * the statistics (no beauty or normal frame: R G B A and N hold nothing;
     * P, Z and the background come from that frame's depth) */
    int visibility_only;
} capture_options;

typedef struct capture {
    image img;                /* AOV channels, rows top to bottom */
    stin_debug_counters counters;
    unsigned log_errors;
    char last_error[512];
    unsigned log_fallbacks;   /* STIN_LOG_FALLBACK messages at any level */
    char fallbacks[2048];     /* their text, one a line (cut at the size) */
    uint64_t caps_present;    /* after the masks */
    int separate_specular;
    stin_frame_stats stats;   /* of the last frame (the visibility output) */
    stin_choice choice[STIN_FEATURE_COUNT]; /* what the context chose */
} capture;

/* 1 on success; else err says why. Free with capture_free. */
int capture_render(stin_platform *plat, const stin_profile *profile, const scene *s,
                   const capture_options *o, capture *out, char *err, size_t err_size);
void capture_free(capture *c);
/* The desc capture_render creates its context from, logging into log_into
 * (capture_log_fn): for a test that keeps one such context for several
 * frames. */
void capture_desc(stin_platform *plat, const stin_profile *profile, const scene *s,
                  const capture_options *o, capture *log_into, stin_desc *d);
/* A stin_log_fn recording into the capture passed as log_user: its error
 * count and last error, and the fallbacks' text (for contexts a test makes
 * itself). */
void capture_log_fn(void *user, stin_log_level level, stin_log_item item, const char *msg);

/* 1 where the render's log says its CSG products resolve on the GPU alone
 * (OpenGL ES without a depth read-back: stin.h, "goldfeather"): no
 * read-back resolve, no shadow cast by a product, no layer counted. */
int capture_csg_gpu_alone(const capture *cap);
/* Where cap's products resolve on the GPU alone: `name` reports SKIP with
 * `what` on an OpenGL ES profile and FAIL elsewhere (desktop GL always
 * reads depth back), and 1 is returned; else 0 and nothing reported. */
struct run;
int capture_report_gpu_alone(struct run *r, const char *name, const capture *cap,
                             const char *what);

/* The gl-clean verdict of a render: no GL error, no call outside the
 * profile, no error logged; one PASS/FAIL line under `name`. */
void capture_report_clean(struct run *r, const char *name, const capture *cap);

#endif
