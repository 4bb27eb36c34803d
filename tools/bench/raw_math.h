/* SPDX-License-Identifier: MIT */
/* Column-major matrix helpers for the raw loop (what stin computes per draw). */
#ifndef STIN_BENCH_RAW_MATH_H
#define STIN_BENCH_RAW_MATH_H

void raw_mat4_mul(float out[16], const float a[16], const float b[16]);
/* Inverse transpose of the upper 3x3, for normals. */
void raw_mat3_normal(float out[9], const float m[16]);

#endif
