/* SPDX-License-Identifier: MIT */
/* A scene as an osgShadow peer (peers_osg.c; built where stin-bench has
 * osgShadow: STIN_BENCH_OSGSHADOW). */
#ifndef STIN_BENCH_PEERS_OSG_H
#define STIN_BENCH_PEERS_OSG_H

#include "bench_section.h"

#include <stddef.h>

struct osgs_peer;

/* The peer drawing s at the bench's size and framebuffer with osgShadow's
 * `technique` (OSGS_*) and maps of map_size; NULL with the reason in why. */
struct osgs_peer *peers_osg_peer(const bench_env *env, const scene *s, int technique,
                                 int map_size, char *why, size_t why_size);

#endif
