/* SPDX-License-Identifier: MIT */
/* A command line's technique options (--shadows, --surface, --csg,
 * --transparency), shared by stin-render and the viewer. */
#ifndef STIN_TOOLS_TECHNIQUE_OPTION_H
#define STIN_TOOLS_TECHNIQUE_OPTION_H

#include "stin/stin.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A technique name of feature f, "auto" (or NULL: STIN_TECH_NONE), "off"
 * for the feature's "<feature>-off" technique, or for shadows "map"
 * (map-depth; technique_option_narrow_map picks the path the context has).
 * An unknown name: 0 and one stderr line, "PROGRAM: unknown ... this build
 * knows: ...". */
int technique_option_parse(const char *program, const char *name, stin_feature f,
                           stin_technique *out);
/* "map" on a context without depth textures and shadow compare: map-combine. */
void technique_option_narrow_map(stin_get_proc_fn get_proc, void *user, stin_desc *desc);

#ifdef __cplusplus
}
#endif
#endif
