/* SPDX-License-Identifier: MIT */
/* The sections of stin-bench, in the order they run (see bench_section.h). */
#include "bench_section.h"

const bench_section bench_sections[SECTION_COUNT] = {
    {"raw", "libstin against the raw-GL loop per tier and scene; the goal line", section_raw},
    {"shadows", "stencil shadow volumes against shadows off per tier, scene and light count",
     section_shadows},
    {"maps", "GL1 shadow maps per map size, and volumes, against shadows off", section_maps},
    {"pcf", "GL2/GL4 PCF shadow maps per map size and kernel against shadows off", section_pcf},
    {"surface", "GL2/GL4 surface techniques against the plain surface", section_surface},
    {"vdsm", "GL4 VDSM per step set (SP, +EP, +SM, +DC): the seed's P_c, against shadows off, "
             "SP alone and stencil volumes, per --scenes scene", section_vdsm},
    {"displace", "GL2/GL4 displacement (VTF, tessellation) against the surface chain and the "
                 "plain surface, each speed-up on and off", section_displace},
    {"deep", "GL2/GL4 translucent shadows: deep with 1, 2, 4 layers and coloured against map-pcf "
             "and shadows off; deep's early stop on and off, transparency in one cube face and "
             "in all six", section_deep},
    {"csg", "CSG products: scs and goldfeather against OpenCSG's SCS and Goldfeather, n = 2 to "
            "128 primitives and a row along the view", section_csg},
    {"peel", "GL2/GL4 camera transparency: depth-peel and dual-peel (GL4) against sorted "
             "with 0, 2 and 4 transparent layers on screen (passes and time)", section_peel},
    {"update", "stin_update_mesh against destroy and create on UV spheres of 18k and 76k "
               "vertices, per tier: ms and ns per vertex", section_update},
    {"peers", "stin's vdsm, volume and map-pcf against osgShadow's ShadowMap, SoftShadowMap, "
              "StandardShadowMap, LiSPSM, PSSM and ViewDependentShadowMap on the same scenes: "
              "frame time, ratios and mismatch against the exact reference", section_peers},
};
