/* SPDX-License-Identifier: MIT */
/*
 * orbillum/geometry.h: the geometry of a sphere's light: the Lambertian phase
 * function, the angle between two vectors, the overlap of two spherical caps.
 *
 * A section of orbillum.h, the header a program includes (it includes every
 * section); compiles alone, and includes the sections it uses.
 */
#ifndef ORBILLUM_GEOMETRY_H
#define ORBILLUM_GEOMETRY_H

#include "base.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- geometry */

/* oi_lambert_phase: the Lambertian sphere's phase function (docs/physics.md)
 *   p(xi) = 2/(3 pi) ((pi - xi) cos xi + sin xi),  p(0) = 2/3, p(pi) = 0,
 * xi the phase angle (radians, [0, pi]; values outside are clamped; NaN
 * gives 0). Near xi = pi it uses a series in t = pi - xi (no cancellation):
 * relative error a few epsilon over [0, pi] (docs/shadow.md).
 * A sphere of radius a, albedo alpha under irradiance E sends
 *   F = E alpha a^2 p(xi) / d^2  to a viewer at distance d. */
oi_real oi_lambert_phase(oi_real xi);

/* oi_angle: the angle between two vectors (any common unit; may be the same
 * array), atan2(|a x b|, a . b) of the vectors scaled to unit length:
 * [0, pi] (radians), absolute error a few epsilon, accurate near 0 and pi
 * too. Returns 0 if either pointer is NULL or either vector is zero or has
 * a non-finite component. */
oi_real oi_angle(const oi_real a[3], const oi_real b[3]);

/* oi_cap_overlap: area (steradians) of the intersection of two spherical
 * caps of angular radii r1, r2 (radians, [0, pi]) whose centres are d apart
 * (radians, [0, pi]); inputs outside are clamped, a NaN gives 0. Exact on the
 * sphere (not the planar two-circle approximation), in forms without
 * cancellation for small caps: disjoint caps give exactly 0, nested ones
 * exactly the smaller cap's area 4 pi sin^2(r/2); otherwise the absolute
 * error is a few epsilon times the smaller cap's area (docs/shadow.md). */
oi_real oi_cap_overlap(oi_real r1, oi_real r2, oi_real d);

#ifdef __cplusplus
}
#endif

#endif /* ORBILLUM_GEOMETRY_H */
