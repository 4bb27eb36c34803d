// SPDX-License-Identifier: MIT
// VDSM: what every geometry shader of the shadow polygons reads - the
// light, the light depth DC clips at - and which side of a plane a
// homogeneous point lies on.
uniform vec4 u_light;     // world: position (w 1), or the direction toward the light (w 0)
uniform vec4 u_depth_row; // world -> light depth (linear, grows away from the light)

// DC's "no clip": the extrusion goes to infinity.
const float UNCLIPPED = 3.4e38;

float side(vec4 plane, vec4 x) { return dot(plane.xyz, x.xyz) + plane.w * x.w; }
