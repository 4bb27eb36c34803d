/* SPDX-License-Identifier: MIT */
/* Surface detail: DOT3 bump mapping on the fixed-function path
 * (surface/dot3.c) and the GLSL normal / parallax / POM chunks
 * (surface/glsl.c). */
#ifndef STIN_SURFACE_H
#define STIN_SURFACE_H

#include "stin/stin.h"
#include "render/path.h"
#include "render/path_features.h"

/* The lit program's variants are render/path_features.h's STIN__SURF_*:
 * one program each (surface/glsl.c). */
/* Bytes of each surface module's private state (defined in its .c file). */
size_t stin__dot3_state_bytes(const stin_desc *d);
size_t stin__surf_glsl_state_bytes(const stin_desc *d);
size_t stin__displace_state_bytes(const stin_desc *d);

/* ---- surface: DOT3 bump mapping on the fixed-function path (surface/dot3.c) ----
 * Draws whose material has a normal map get their diffuse term per pixel from
 * the normal map; the fixed-function passes keep their ambient and specular
 * (set_material blacks out their diffuse through stin__dot3_material). The
 * fixed path calls material, lights and batch as the surface's hooks
 * (render/path_features.h, lent by frame/hooks.c). */
/* Creates the cube map when the technique is selected (the frame's set-up
 * of the fixed path); a context without the texture units or staging falls
 * back to plain (an error if it was forced). */
stin_result stin__dot3_init(stin_context *ctx);
void stin__dot3_release(stin_context *ctx);
/* 1 when this (opaque) material is drawn with DOT3 in the lit passes. */
int stin__dot3_bumped(const stin_context *ctx, const stin_material *m);
/* After the fixed path's set_material: diffuse off for bumped materials. */
void stin__dot3_material(stin_context *ctx, const stin_material *m);
/* Adds the DOT3 diffuse of the opaque bumped draws for the GL lights
 * 0..count-1 (set up as lights[0..count-1]), one additive pass per light
 * (depth EQUAL), under the caller's stencil test and scissor; the stencil
 * operations are KEEP meanwhile, so a caller that increments where it lights
 * calls this before its own draws of the same light. */
void stin__dot3_lights(stin_context *ctx, const stin_light_desc *lights, int count);
/* As stin__dot3_lights for light batch `batch` of fixed_batches, whose lights
 * set_batch has just set up; restores the batch's scene ambient. */
void stin__dot3_batch(stin_context *ctx, int batch);
/* Per-vertex tangent-space light vectors (xyz, unnormalised) and the normal
 * that points the fixed-function lighting at the light (xyz), 6 floats a
 * vertex, for an object with transform `model` and a light at light_world
 * (w = 1 point, w = 0 direction toward the light). */
void stin__dot3_light_vectors(const stin__vertex *v, uint32_t n, const float model[16],
                              const float light_world[4], float *out);
/* Direction of the cube-map face (0..5 = +X -X +Y -Y +Z -Z) at texture
 * coordinates (s, t), unnormalised; and a face as RGBA8 0.5 + 0.5 n. */
void stin__dot3_cube_direction(int face, float s, float t, float out[3]);
void stin__dot3_cube_face(int face, uint32_t size, unsigned char *rgba);

/* ---- surface: GLSL normal / parallax / POM chunks (surface/glsl.c) --------
 * The lit program is built once per surface variant, from the context's
 * surface choice down to plain; a variant that fails to build lowers the
 * best one (logged). The GLSL path calls these as the surface's hooks
 * (render/path_features.h, lent by frame/hooks.c). */
/* The variant the surface choice asks for (plain for dot3/plain/none). */
int stin__surf_variant_top(const stin_context *ctx);
/* The variant above `built` failed to build (msg): the choice steps down to
 * `built` (logged). */
void stin__surf_variant_failed(stin_context *ctx, int built, const char *msg);
/* The chunk files of a variant (surface_frame.glsl, then the variant's
 * functions) into names; returns how many. */
int stin__surf_chunks(const stin_context *ctx, int variant,
                      const char *names[STIN__FEATURE_CHUNKS]);
/* The variant a draw's material gets (logs a step down once per material). */
int stin__surf_variant_for(stin_context *ctx, const stin_material *m);
/* Uniform locations of the surface chunks. */
void stin__surf_locate(stin_context *ctx, stin__program *p);
/* Sampler units (once per program use). */
void stin__surf_units(stin_context *ctx, const stin__program *p);
/* Per-draw: binds the normal and height maps to units 1 and 2, uploads the
 * material's height scale, bias, steps and self-shadow mode. */
void stin__surf_material(stin_context *ctx, const stin__program *p, const stin_material *m,
                         int variant);
/* Unbinds units 1 and 2 after a frame that bound them; unit 0 active. */
void stin__surf_unbind(stin_context *ctx);

/* ---- displacement: "displace" by vertex texture fetch (surface/displace.c) ----
 * The chunk every mesh-drawing program carries is render/displace_chunk.h's;
 * here the feature's frame set-up and its step down. */
/* Around a frame (frame/state.c): the camera's tessellation scale, and the
 * caller's GL_PATCH_VERTICES saved, set to 3, and given back. */
void stin__displace_frame_begin(stin_context *ctx);
void stin__displace_frame_end(stin_context *ctx);
/* After the shadow module's set-up: volumes cannot shadow displaced
 * geometry, so displacement steps down beside them (logged). */
void stin__displace_init(stin_context *ctx);

#endif
