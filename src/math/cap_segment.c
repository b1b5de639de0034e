/* SPDX-License-Identifier: MIT */
/* cap_segment.c: the area of a spherical cap's segment cut off by a great
 * circle (oi__cap_segment; internal, declared in src/math/math_internal.h), the
 * building block of the cap overlap and of the visible solar crescent.
 * Accuracy: docs/shadow.md. References: Todhunter, I. 1886, Spherical
 * Trigonometry, 5th ed. (spherical excess from two sides and the included
 * angle). */
#include "math/math_internal.h"

/* ---------------------------------------------------------------- quadrature */

/* The 8-point Gauss-Legendre rule on [0, 1] (src/math/math_internal.h): the nodes
 * x and 1 - x share the weights. */
const oi_real oi__gl8[OI_GL8_HALF][2] = {
    {OI_GL8_X1, OI_GL8_W1},
    {OI_GL8_X2, OI_GL8_W2},
    {OI_GL8_X3, OI_GL8_W3},
    {OI_GL8_X4, OI_GL8_W4},
};

/* J(alpha) = int_0^alpha sin^2 u / (1 - k2 sin^2 u) du, k2 = sin^2 r <= 1,
 * alpha < 1/2: Gauss-Legendre, 8 nodes on [0, alpha] when alpha < 1/4, on
 * each half of it otherwise. The integrand's nearest singularity,
 * sin^2 u = 1/k2, lies at least pi/2 - 1/2 from [0, alpha], so the error
 * factor of a panel is below (z + sqrt(z^2 - 1))^-16 with z >= 9.6 (the
 * distance over the half-width): < 4e-21 (measured with mpmath: one
 * 8-point panel on [0, 1/2] at k2 = 1 errs by 7e-15 relative). */
static oi_real gauss_j(oi_real alpha, oi_real k2)
{
    int panels = alpha < OI_R(0.25) ? 1 : 2, k, i, j;
    oi_real sum = (oi_real)0, h = alpha / (oi_real)panels;
    for (k = 0; k < panels; ++k) {
        oi_real lo = (oi_real)k * h;
        for (i = 0; i < OI_GL8_HALF; ++i) {
            for (j = 0; j < 2; ++j) {
                oi_real x = j ? (oi_real)1 - oi__gl8[i][0] : oi__gl8[i][0];
                oi_real su = OI_SIN(lo + h * x);
                oi_real s2 = su * su;
                sum += oi__gl8[i][1] * s2 / ((oi_real)1 - k2 * s2);
            }
        }
    }
    return h * sum;
}

/*
 * Area of the "segment" of a cap of radius r (<= pi/2) cut off by the great
 * circle through the two points of its boundary seen from the cap's centre
 * at +-alpha.
 * alpha >= 1/2: the sector 4 alpha sin^2(r/2) minus the isosceles triangle
 * (centre and the two points, apex angle 2 alpha) whose spherical excess E is
 *   tan(E/2) = S sin 2a / (C + S cos 2a),  S = sin^2(r/2), C = cos^2(r/2)
 * (the two-sides-and-included-angle excess formula with tan^2(r/2) = S/C);
 * for alpha > pi/2 the excess is negative: the triangle is added, as the
 * cap's centre then lies inside the segment. The two terms cancel by at most
 * a factor 1.5/alpha^2 = 6.
 * alpha < 1/2 (thin segments, where sector and triangle cancel): the same
 * area as an integral without cancellation, obtained by differentiating the
 * above in alpha:
 *   seg = 2 sin^2 r cos r  J(alpha),  J = int_0^alpha sin^2 u / (1 - sin^2 r sin^2 u) du,
 * J by the 8-point Gauss-Legendre rule (gauss_j).
 * Planar check: for small r, seg -> (r^2/2)(2 alpha - sin 2 alpha).
 */
oi_real oi__cap_segment(oi_real r, oi_real alpha)
{
    oi_real s, c, e;
    if (alpha < OI_R(0.5)) {
        oi_real sr = OI_SIN(r);
        return (oi_real)2 * sr * sr * OI_COS(r) * gauss_j(alpha, sr * sr);
    }
    s = oi__sin_half_sq(r);
    c = oi__sqr(OI_COS(OI_R(0.5) * r));
    e = (oi_real)2 * OI_ATAN2(s * OI_SIN((oi_real)2 * alpha), c + s * OI_COS((oi_real)2 * alpha));
    return (oi_real)4 * alpha * s - e;
}
