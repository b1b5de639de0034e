/* SPDX-License-Identifier: MIT */
/* oblate.c: the WGS-84 ellipsoid as the Earth's occulter (oi_model.earth_shape
 * = OI_EARTH_WGS84): inside/outside, its geocentric radius, the angular radius
 * of its silhouette towards a direction, and the visible fraction of a disc
 * (the Sun's, the Moon's) behind its elliptic silhouette cone and, optionally,
 * a second spherical occulter. Internal, declared in src/shadow/shadow_internal.h;
 * removed with OI_NO_OBLATE. Model, method and measured accuracy:
 * docs/shadow.md section 10. */
#include "shadow/shadow_internal.h"

#ifndef OI_NO_OBLATE

/* (a/b)^2 - 1 = f (2 - f) / (1 - f)^2 for the WGS-84 flattening
 * (NIMA TR8350.2, 3rd ed., 2000, table 3.1), a constant expression. */
#define WGS84_F (1.0 / OI_WGS84_INV_FLATTENING)
#define K2M1 ((oi_real)(WGS84_F * (2.0 - WGS84_F) / ((1.0 - WGS84_F) * (1.0 - WGS84_F))))

/* x^2 + y^2 + (a/b)^2 z^2 over a^2: > 1 outside the ellipsoid of
 * equatorial radius a (the frame's z axis the rotation axis). */
static oi_real scaled_norm2(const oi_real p[3], oi_real a)
{
    const oi_real x = p[0] / a, y = p[1] / a, z = p[2] / a;
    return x * x + y * y + z * z + K2M1 * z * z;
}

int oi__oblate_outside(const oi_real p[3], oi_real a)
{
    return scaled_norm2(p, a) > (oi_real)1;
}

oi_real oi__oblate_geocentric_radius(const oi_real p[3], oi_real a)
{
    return oi__norm_bounded(p) / OI_SQRT(scaled_norm2(p, a));
}

/* Distance along the unit direction u from o (outside) to where the ray
 * first meets the ellipsoid, or -1 when it misses: z scaled by a/b, the
 * ray o' + s u' against the sphere of radius a, s^2 |u'|^2 + 2 s o'.u' +
 * |o'|^2 - a^2 = 0, the near root in the form without cancellation. */
oi_real oi__oblate_ray_hit(const oi_real o[3], const oi_real u[3], oi_real a)
{
    const oi_real k2 = (oi_real)1 + K2M1;
    const oi_real uu = u[0] * u[0] + u[1] * u[1] + k2 * u[2] * u[2];
    const oi_real ou = o[0] * u[0] + o[1] * u[1] + k2 * o[2] * u[2];
    const oi_real n = OI_SQRT(scaled_norm2(o, a)) * a; /* |o'| */
    const oi_real c = (n - a) * (n + a), d = ou * ou - uu * c;
    if (!(ou < (oi_real)0) || !(d >= (oi_real)0) || !(c > (oi_real)0)) return (oi_real)-1;
    return c / (-ou + OI_SQRT(d));
}

/*
 * A cone of directions u from the point, in the quadratic form
 *   inside  <=>  (w.u)^2 - c (u.u + e u_z^2) >= 0  and  sigma (w.u) < 0,
 * expressed in the frame (s, eu, ev) of the back disc: u = s + x eu + y ev
 * (gnomonic coordinates about the disc's centre). m: the form's entries
 * ss, su, sv, uu, uv, vv; l: sigma (w.s, w.eu, w.ev).
 * The ellipsoid seen from p (p outside): scaling z by k = a/b maps it to the
 * sphere of radius a, p to p' = (x, y, k z) and u to u' = (u_x, u_y, k u_z);
 * u meets it when (p'.u')^2 >= (|p'|^2 - a^2) |u'|^2 with p'.u' < 0, and
 * p'.u' = w.u for w = (x, y, k^2 z): divided by |p'|^2, w = (x, y, k^2 z)/|p'|,
 * c = 1 - a^2/|p'|^2, e = k^2 - 1, sigma = 1. A sphere of unit direction d
 * and apparent radius r: w = d, c = cos^2 r, e = 0, sigma = -1.
 */
typedef struct {
    oi_real m[6];
    oi_real l[3];
} cone;

static void cone_in_frame(const oi_real w[3], oi_real c, oi_real e, oi_real s2, oi_real sigma,
                          const oi_real f[3][3], cone *k)
{
    /* (w.a)(w.b) - c a.b = -(w x a).(w x b) + (|w|^2 - c) a.b: the cross
     * products are small where the form is (directions near the cone's
     * boundary, far from its axis ... or near it), without the cancellation
     * of two numbers near 1; s2 = |w|^2 - c is formed by the caller */
    oi_real x[3][3];
    const oi_real ce = c * e;
    int i;
    for (i = 0; i < 3; ++i) oi__cross(w, f[i], x[i]);
    k->m[0] = s2 - oi__dot(x[0], x[0]) - ce * f[0][2] * f[0][2];
    k->m[1] = -oi__dot(x[0], x[1]) - ce * f[0][2] * f[1][2];
    k->m[2] = -oi__dot(x[0], x[2]) - ce * f[0][2] * f[2][2];
    k->m[3] = s2 - oi__dot(x[1], x[1]) - ce * f[1][2] * f[1][2];
    k->m[4] = -oi__dot(x[1], x[2]) - ce * f[1][2] * f[2][2];
    k->m[5] = s2 - oi__dot(x[2], x[2]) - ce * f[2][2] * f[2][2];
    k->l[0] = sigma * oi__dot(w, f[0]);
    k->l[1] = sigma * oi__dot(w, f[1]);
    k->l[2] = sigma * oi__dot(w, f[2]);
}

/* The ellipsoid's cone seen from p (outside), world coordinates; *s2 =
 * |w|^2 - c = (k^2 (k^2 - 1) z^2 + a^2) / |p'|^2 without cancellation. */
static void earth_cone_world(const oi_real p[3], oi_real a, oi_real w[3], oi_real *c,
                             oi_real *s2)
{
    const oi_real n2 = scaled_norm2(p, a); /* |p'|^2 / a^2 > 1 */
    const oi_real n = OI_SQRT(n2);
    const oi_real inv = (oi_real)1 / (n * a), z = p[2] / a;
    w[0] = p[0] * inv;
    w[1] = p[1] * inv;
    w[2] = p[2] * ((oi_real)1 + K2M1) * inv;
    *c = (n - (oi_real)1) * (n + (oi_real)1) / n2;
    *s2 = (((oi_real)1 + K2M1) * K2M1 * z * z + (oi_real)1) / n2;
}

/* Largest |x| a root may take: beyond every chord (|x| <= tan r < 1e16). */
#define FAR_X OI_R(1e30)

/*
 * The part of the chord x in [-h, h] at height y inside the cone: 1 with
 * [*xa, *xb] (xa < xb), or 0 when none. Along the line the form is
 * alpha x^2 + 2 beta x + gamma, the front condition l0 + l1 x < 0; the
 * point where the line crosses the plane w.u = 0 has a negative form, so
 * the front part of {form >= 0} is one interval.
 */
static int chord_cover(const cone *k, oi_real y, oi_real h, oi_real *xa, oi_real *xb)
{
    const oi_real alpha = k->m[3];
    const oi_real beta = k->m[1] + y * k->m[4];
    const oi_real gamma = k->m[0] + y * ((oi_real)2 * k->m[2] + y * k->m[5]);
    const oi_real l0 = k->l[0] + y * k->l[2], l1 = k->l[1];
    oi_real lo = -h, hi = h, r1, r2, disc, q, t;
    /* the front half-line */
    if (l1 > (oi_real)0) {
        t = -l0 / l1;
        if (t < hi) hi = t;
    } else if (l1 < (oi_real)0) {
        t = -l0 / l1;
        if (t > lo) lo = t;
    } else if (!(l0 < (oi_real)0)) {
        return 0;
    }
    if (!(lo < hi)) return 0;
    disc = beta * beta - alpha * gamma;
    if (alpha == (oi_real)0) {
        /* linear: 2 beta x + gamma >= 0 */
        if (beta == (oi_real)0) {
            if (!(gamma >= (oi_real)0)) return 0;
        } else {
            t = -gamma / ((oi_real)2 * beta);
            if (beta > (oi_real)0) {
                if (t > lo) lo = t;
            } else if (t < hi) {
                hi = t;
            }
        }
    } else if (!(disc >= (oi_real)0)) {
        if (alpha < (oi_real)0) return 0; /* the form negative on the whole line */
    } else {
        q = -(beta + (beta < (oi_real)0 ? -OI_SQRT(disc) : OI_SQRT(disc)));
        if (q == (oi_real)0) {
            r1 = r2 = (oi_real)0;
        } else {
            r1 = q / alpha;
            r2 = gamma / q;
            if (r1 > r2) {
                t = r1;
                r1 = r2;
                r2 = t;
            }
        }
        if (alpha < (oi_real)0) {
            if (r1 > lo) lo = r1;
            if (r2 < hi) hi = r2;
        } else if (l1 > (oi_real)0 || (l1 == (oi_real)0 && r1 - lo >= hi - r2)) {
            /* the front nappe is the side below r1 */
            if (r1 < hi) hi = r1;
        } else if (r2 > lo) {
            lo = r2;
        }
    }
    if (!(lo < hi)) return 0;
    *xa = lo;
    *xb = hi;
    return 1;
}

/* Solid angle per unit y of the chord x in [0, x] at height y, the
 * gnomonic element dx dy / (1 + x^2 + y^2)^(3/2) integrated over x. */
static oi_real chord_h(oi_real x, oi_real yy)
{
    return x / (yy * OI_SQRT(yy + x * x));
}

#ifndef OI_NO_LIMB_DARKENING
/* Neckel & Labs (1994) at 559.95 nm, I(mu)/I(1) = sum A_k mu^k (as
 * src/shadow/limb_darkening.c). */
static const oi_real ld_a[6] = {OI_R(0.26892), OI_R(1.34319), OI_R(-1.58427),
                                OI_R(1.91271), OI_R(-1.31350), OI_R(0.37295)};

/*
 * The limb-darkened chord in closed form. On the chord y = const of the
 * gnomonic disc of radius t (half-width h, yy = 1 + y^2) the heliocentric
 * cosine is mu = sqrt(h^2 - x^2) / (t sqrt(yy + x^2)) (mu^2 = 1 - sin^2 rho /
 * sin^2 r exactly). With w = x / sqrt(yy + x^2) the element is dw / yy and
 * mu = m0 cos(phi), w = W sin(phi), W = h / sqrt(yy + h^2), m0 = h / (t
 * sqrt(yy)): the chord's flux from its centre to x is (W / yy) sum_k A_k
 * m0^k C_(k+1)(phi), C_n(phi) = int_0^phi cos^n (the reduction formula
 * C_n = cos^(n-1) sin / n + (n-1)/n C_(n-2)). This returns the sum; phi from
 * its sine and cosine without cancellation at the chord's ends.
 */
static oi_real ld_chord_end(oi_real x, oi_real h, oi_real yy, oi_real m0)
{
    const oi_real q = OI_SQRT(yy + x * x);
    const oi_real sn = x * OI_SQRT(yy + h * h) / (h * q);
    const oi_real cs = OI_SQRT((h - x) * (h + x) * yy) / (h * q);
    const oi_real phi = OI_ATAN2(sn, cs);
    const oi_real c2 = cs * cs;
    const oi_real c1n = sn;                                          /* C_1 */
    const oi_real c2n = OI_R(0.5) * (cs * sn + phi);                 /* C_2 */
    const oi_real c3n = c2 * sn / (oi_real)3 + c1n * OI_R(2.0) / (oi_real)3;
    const oi_real c4n = c2 * cs * sn * OI_R(0.25) + c2n * OI_R(0.75);
    const oi_real c5n = c2 * c2 * sn * OI_R(0.2) + c3n * OI_R(0.8);
    const oi_real c6n = c2 * c2 * cs * sn / (oi_real)6 + c4n * OI_R(5.0) / (oi_real)6;
    return ld_a[0] * c1n +
           m0 * (ld_a[1] * c2n +
                 m0 * (ld_a[2] * c3n + m0 * (ld_a[3] * c4n + m0 * (ld_a[4] * c5n +
                                                                      m0 * ld_a[5] * c6n))));
}

/* ld_chord_end at the chord's end x = h, phi = pi/2: C_n(pi/2) are
 * Wallis's 1, pi/4, 2/3, 3 pi/16, 8/15, 5 pi/32. */
static oi_real ld_chord_half(oi_real m0)
{
    return ld_a[0] +
           m0 * (ld_a[1] * OI_PI_R * OI_R(0.25) +
                 m0 * (ld_a[2] * OI_R(2.0) / (oi_real)3 +
                       m0 * (ld_a[3] * OI_PI_R * OI_R(0.1875) +
                             m0 * (ld_a[4] * OI_R(8.0) / OI_R(15.0) +
                                   m0 * ld_a[5] * OI_PI_R * OI_R(0.15625)))));
}
#endif

/* What a chord gives the quadrature (the four sums of fraction_from_breaks,
 * in this order): the solid angle per unit y the occulters hide of it, the
 * part they leave visible, and (limb-darkened disc of gnomonic radius t)
 * the same of its flux. */
#define Q_HID 0
#define Q_VIS 1
#define Q_LD_HID 2
#define Q_LD_VIS 3
#define N_SUMS 4

/* The chord at height y of half-width h: its four values times w added to
 * sum (the last two only with want_ld). */
static void chord_values(const cone *k, int n, oi_real y, oi_real h, oi_real t, int want_ld,
                         oi_real w, oi_real sum[N_SUMS])
{
    const oi_real yy = (oi_real)1 + y * y;
    /* zeros only for the analyser, which cannot see that nc == 2 means both
     * covers were written */
    oi_real a[2] = {(oi_real)0, (oi_real)0}, b[2] = {(oi_real)0, (oi_real)0}, hid = (oi_real)0;
    oi_real full;
    int i, nc = 0;
    for (i = 0; i < n; ++i)
        if (chord_cover(&k[i], y, h, &a[nc], &b[nc])) ++nc;
    if (nc == 2 && a[1] < b[0] && a[0] < b[1]) {
        /* overlapping: one union */
        a[0] = a[0] < a[1] ? a[0] : a[1];
        b[0] = b[0] > b[1] ? b[0] : b[1];
        nc = 1;
    }
#ifndef OI_NO_LIMB_DARKENING
    if (want_ld) {
        const oi_real m0 = h / (t * OI_SQRT(yy));
        const oi_real scale = h / (OI_SQRT(yy + h * h) * yy);
        const oi_real half = ld_chord_half(m0);
        oi_real hl = (oi_real)0, whole;
        for (i = 0; i < nc; ++i)
            hl += (a[i] == -h && b[i] == h)
                      ? (oi_real)2 * half
                      : ld_chord_end(b[i], h, yy, m0) - ld_chord_end(a[i], h, yy, m0);
        whole = (oi_real)2 * half * scale;
        hl *= scale;
        hl = hl < whole ? (hl > (oi_real)0 ? hl : (oi_real)0) : whole;
        sum[Q_LD_HID] += w * hl;
        sum[Q_LD_VIS] += w * (whole - hl);
    }
#else
    (void)t;
    (void)want_ld;
#endif
    full = (oi_real)2 * chord_h(h, yy);
    for (i = 0; i < nc; ++i) hid += chord_h(b[i], yy) - chord_h(a[i], yy);
    hid = hid < full ? hid : full;
    sum[Q_HID] += w * hid;
    sum[Q_VIS] += w * (full - hid);
}

/* A circle on the sky in the back disc's frame: the directions
 * cr c + sr (cos th g1 + sin th g2) (c, g1, g2 orthonormal: the rows of f,
 * written there by disc_frame without a copy). */
typedef struct {
    oi_real f[3][3], cr, sr;
} circle;

/* The cone's form at the circle's point of angle th. */
static oi_real circle_form(const cone *k, const circle *q, oi_real th, oi_real u[3])
{
    oi_real s, c;
    int i;
    OI_SINCOS(th, &s, &c);
    for (i = 0; i < 3; ++i) u[i] = q->cr * q->f[0][i] + q->sr * (c * q->f[1][i] + s * q->f[2][i]);
    return k->m[0] * u[0] * u[0] +
           (oi_real)2 * u[0] * (k->m[1] * u[1] + k->m[2] * u[2]) +
           k->m[3] * u[1] * u[1] + (oi_real)2 * k->m[4] * u[1] * u[2] + k->m[5] * u[2] * u[2];
}

#define N_LIMB_SAMPLES 32
/* Breaks of the integrand over psi: each cone crosses the disc's limb at
 * most 4 times (the form on a circle: a trigonometric polynomial of degree
 * 2) and has at most 2 tangent chords; the ellipsoid's cone crosses the
 * Moon's limb at most 4 times. The ellipsoid alone: 6 (8 kept), with the
 * Moon: 16. Beyond its capacity a break is dropped. */
#define MAX_BREAKS 16
#define MAX_BREAKS_EARTH 8
typedef struct {
    oi_real *psi;
    int n, cap;
} breaks;
#define ROOT_MAX_IT 60

static void add_break(breaks *b, oi_real psi)
{
    if (b->n < b->cap && psi > -OI_HALF_PI_R && psi < OI_HALF_PI_R) b->psi[b->n++] = psi;
}

/* The break psi of a crossing point u (frame coordinates) when it lies on
 * or inside the back disc of gnomonic radius t: y = u_v / u_s. */
static void add_point(breaks *b, const oi_real u[3], oi_real t)
{
    oi_real y;
    if (!(u[0] > (oi_real)0)) return;
    if (u[1] * u[1] + u[2] * u[2] > OI_R(1.000001) * t * t * u[0] * u[0]) return;
    y = u[2] / u[0];
    if (!(OI_FABS(y) < t)) return;
    add_break(b, OI_ATAN2(y, OI_SQRT((t - y) * (t + y))));
}

/* Where cone k's boundary crosses circle q inside the disc: sign changes of
 * the form over N_LIMB_SAMPLES angles, each refined by the Illinois variant
 * of regula falsi to a few ulp (the form on a circle is a trigonometric
 * polynomial of degree 2: at most 4 zeros). */
static OI_NOINLINE void crossing_breaks(const cone *k, const circle *q, oi_real t, breaks *b)
{
    const oi_real step = (oi_real)2 * OI_PI_R / (oi_real)N_LIMB_SAMPLES;
    oi_real u[3], f0 = circle_form(k, q, (oi_real)0, u);
    int i, it;
    for (i = 0; i < N_LIMB_SAMPLES; ++i) {
        oi_real lo = step * (oi_real)i, hi = step * (oi_real)(i + 1);
        oi_real flo = f0, fhi = circle_form(k, q, hi, u), x = lo, fx;
        int side = 0;
        f0 = fhi;
        if (!((flo < (oi_real)0 && fhi >= (oi_real)0) || (flo >= (oi_real)0 && fhi < (oi_real)0)))
            continue;
        for (it = 0; it < ROOT_MAX_IT && hi - lo > OI_R(4e-16) * (oi_real)8; ++it) {
            x = (lo * fhi - hi * flo) / (fhi - flo);
            if (!(x > lo && x < hi)) x = OI_R(0.5) * (lo + hi);
            fx = circle_form(k, q, x, u);
            if ((fx < (oi_real)0) == (flo < (oi_real)0)) {
                lo = x;
                flo = fx;
                if (side == -1) fhi *= OI_R(0.5);
                side = -1;
            } else {
                hi = x;
                fhi = fx;
                if (side == 1) flo *= OI_R(0.5);
                side = 1;
            }
            if (fx == (oi_real)0) break;
        }
        (void)circle_form(k, q, x, u);
        add_point(b, u, t);
    }
}

/* Breaks where a chord y = const is tangent to cone k's boundary: the
 * discriminant of the form along the chord vanishes. */
static void tangent_breaks(const cone *k, oi_real t, breaks *b)
{
    oi_real a2, b2, c2, d, q, y;
    /* chords tangent to the boundary: (m_su + y m_uv)^2 - m_uu (m_ss + 2 y
     * m_sv + y^2 m_vv) = a2 y^2 + 2 b2 y + c2 = 0 */
    a2 = k->m[4] * k->m[4] - k->m[3] * k->m[5];
    b2 = k->m[1] * k->m[4] - k->m[3] * k->m[2];
    c2 = k->m[1] * k->m[1] - k->m[3] * k->m[0];
    d = b2 * b2 - a2 * c2;
    if (!(d >= (oi_real)0)) return;
    q = -(b2 + (b2 < (oi_real)0 ? -OI_SQRT(d) : OI_SQRT(d)));
    if (q == (oi_real)0) return;
    y = c2 / q;
    if (OI_FABS(y) < t) add_break(b, OI_ATAN2(y, OI_SQRT((t - y) * (t + y))));
    if (a2 != (oi_real)0) {
        y = q / a2;
        if (OI_FABS(y) < t) add_break(b, OI_ATAN2(y, OI_SQRT((t - y) * (t + y))));
    }
}

/* Panels per piece between breaks, each an 8-point rule in u with psi = p0
 * + (p1 - p0)(1 - cos pi u)/2 clustering the nodes at both breaks; their
 * edges in u graded towards both ends, where a neighbouring break (a
 * chord's tangency next to a limb crossing) may lie just beyond the piece.
 * Every occulter wider than twice the disc (the Earth up to ~700,000 km):
 * 8 panels; a narrower one (the Earth beyond, the Moon) 14. */
#define N_WIDE 8
#define N_NARROW 14
static const oi_real edge_wide[N_WIDE + 1] = {
    OI_R(0.0), OI_R(0.015625), OI_R(0.0625), OI_R(0.25), OI_R(0.5),
    OI_R(0.75), OI_R(0.9375), OI_R(0.984375), OI_R(1.0)};
static const oi_real edge_narrow[N_NARROW + 1] = {
    OI_R(0.0),   OI_R(0.00390625), OI_R(0.015625), OI_R(0.0625), OI_R(0.125),
    OI_R(0.25),  OI_R(0.375),      OI_R(0.5),      OI_R(0.625),  OI_R(0.75),
    OI_R(0.875), OI_R(0.9375),     OI_R(0.984375), OI_R(0.99609375), OI_R(1.0)};

static void disc_frame(const oi_real s[3], const oi_real toward[3], oi_real f[3][3]);

/* The Earth's cone crossing the Moon's limb (centre m in the frame, radius
 * rm) inside the disc: where the two covered intervals start or stop
 * overlapping. */
static OI_NOINLINE void moon_limb_breaks(const cone *k, const oi_real m[3], oi_real rm,
                                         oi_real t, breaks *b)
{
    circle q;
    const oi_real e[3] = {(oi_real)0, (oi_real)1, (oi_real)0};
    disc_frame(m, e, q.f);
    OI_SINCOS(rm, &q.sr, &q.cr);
    crossing_breaks(k, &q, t, b);
}

/* Every break of the cones: each one's crossings of the disc's limb and
 * its tangent chords (with the Moon, the caller adds moon_limb_breaks: not
 * from here, so that the two frames do not stack). */
static OI_NOINLINE void all_breaks(const cone *k, int n, oi_real r, oi_real t, breaks *b)
{
    circle q;
    int i;
    q.f[0][0] = (oi_real)1;
    q.f[0][1] = q.f[0][2] = q.f[1][0] = q.f[1][2] = q.f[2][0] = q.f[2][1] = (oi_real)0;
    q.f[1][1] = q.f[2][2] = (oi_real)1;
    OI_SINCOS(r, &q.sr, &q.cr);
    for (i = 0; i < n; ++i) {
        crossing_breaks(&k[i], &q, t, b);
        tangent_breaks(&k[i], t, b);
    }
}

/* Below this sine of the angle between s and toward the plane they span is
 * taken as undefined: its normal, a cross product of nearly parallel
 * vectors, has a direction known only to eps over that sine. */
#ifdef OI_SINGLE_PRECISION
#define FRAME_AXIS_SIN OI_R(1.0e-5)
#else
#define FRAME_AXIS_SIN OI_R(1.0e-10)
#endif

/* An orthonormal frame (s, eu, ev): eu towards toward's component normal to
 * s, formed as (s x toward) x s so that it is normal to s to rounding
 * however near toward lies to s; within FRAME_AXIS_SIN of it (or along it)
 * any normal: s x (the axis farthest from s, normalised). */
static void disc_frame(const oi_real s[3], const oi_real toward[3], oi_real f[3][3])
{
    oi_real n[3], u[3];
    int i;
    for (i = 0; i < 3; ++i) f[0][i] = s[i];
    oi__cross(s, toward, n);
    if (oi__norm_bounded(n) > FRAME_AXIS_SIN * oi__norm_bounded(toward) &&
        oi__unit_bounded(n, n) > (oi_real)0) {
        oi__cross(n, s, u);
    } else {
        /* the axes (static: not copied to the stack) */
        static const oi_real axis[3][3] = {{(oi_real)1, (oi_real)0, (oi_real)0},
                                           {(oi_real)0, (oi_real)1, (oi_real)0},
                                           {(oi_real)0, (oi_real)0, (oi_real)1}};
        const oi_real ax = OI_FABS(s[0]), ay = OI_FABS(s[1]), az = OI_FABS(s[2]);
        oi__cross(s, axis[(ax <= ay && ax <= az) ? 0 : (ay <= az ? 1 : 2)], u);
    }
    (void)oi__unit_bounded(u, u);
    for (i = 0; i < 3; ++i) f[1][i] = u[i];
    oi__cross(s, u, f[2]);
}

/* The cones in the back disc's frame (s, eu towards the Earth's centre):
 * the ellipsoid's in k[0], the sphere's (mo not NULL) in k[1] with its
 * centre's frame coordinates in mf; returns 1 when an occulter is narrower
 * than twice the disc (the silhouette's sine squared, 1 - c, against
 * 4 sin^2 r). Out of line: its frame is not live during the quadrature. */
static OI_NOINLINE int build_cones(const oi_real s[3], oi_real r, const oi_real p[3], oi_real a,
                                   const oi_real mo[3], oi_real rm, cone *k, oi_real mf[3])
{
    oi_real f[3][3], w[3], c, s2, cm, sm;
    int i;
    w[0] = -p[0];
    w[1] = -p[1];
    w[2] = -p[2];
    disc_frame(s, w, f);
    earth_cone_world(p, a, w, &c, &s2);
    cone_in_frame(w, c, K2M1, s2, (oi_real)1, (const oi_real(*)[3])f, &k[0]);
    if (mo == NULL) return !((oi_real)1 - c > (oi_real)4 * oi__sqr(OI_SIN(r)));
    OI_SINCOS(rm, &sm, &cm);
    cone_in_frame(mo, cm * cm, (oi_real)0, sm * sm, (oi_real)-1, (const oi_real(*)[3])f, &k[1]);
    for (i = 0; i < 3; ++i) mf[i] = oi__dot(mo, f[i]);
    return 1;
}

/* The breaks sorted (insertion; at most MAX_BREAKS), the pieces between
 * them integrated, and the visible fraction formed (see oi__oblate_visible);
 * frac_ld not NULL: the limb-darkened disc's there, the visible flux over
 * the disc's (both from the same pieces). Out of line: the breaks' search
 * is over before this frame is live. One frame for the pieces, their panels
 * and the chords (the sums in arrays, per level): a frame per level would
 * save the floating-point registers at each (make stack). The panels
 * (above) in u of each piece, the integrand times dy/dpsi. */
static OI_NOINLINE oi_real fraction_from_breaks(const cone *k, int n, oi_real r, oi_real t,
                                                int narrow, const breaks *b, oi_real *frac_ld)
{
    oi_real tot[N_SUMS], prev, disc, vis, *brk = b->psi;
#ifdef OI_NO_LIMB_DARKENING
    const int want_ld = 0;
#else
    const int want_ld = frac_ld != NULL;
#endif
    const oi_real *const edge = narrow ? edge_narrow : edge_wide;
    const int panels = narrow ? N_NARROW : N_WIDE, nb = b->n;
    int i, j, q;
    for (i = 1; i < nb; ++i) {
        const oi_real v = brk[i];
        for (j = i; j > 0 && brk[j - 1] > v; --j) brk[j] = brk[j - 1];
        brk[j] = v;
    }
    for (q = 0; q < N_SUMS; ++q) tot[q] = (oi_real)0;
    prev = -OI_HALF_PI_R;
    for (i = 0; i <= nb; ++i) {
        const oi_real next = i < nb ? brk[i] : OI_HALF_PI_R;
        const oi_real p0 = prev, hw = OI_R(0.5) * (next - prev);
        oi_real sum[N_SUMS];
        int pn;
        prev = next;
        if (!(next > p0)) continue;
        for (q = 0; q < N_SUMS; ++q) sum[q] = (oi_real)0;
        for (pn = 0; pn < panels; ++pn) {
            const oi_real u0 = edge[pn], du = edge[pn + 1] - edge[pn];
            oi_real part[N_SUMS];
            int g;
            for (q = 0; q < N_SUMS; ++q) part[q] = (oi_real)0;
            for (g = 0; g < 8; ++g) {
                const int gi = g >> 1;
                const oi_real x = (g & 1) ? (oi_real)1 - oi__gl8[gi][0] : oi__gl8[gi][0];
                const oi_real u = u0 + du * x;
                oi_real sc[2], su;
                OI_SINCOS(OI_PI_R * u, &sc[0], &sc[1]);
                su = sc[0];
                OI_SINCOS(p0 + hw * ((oi_real)1 - sc[1]), &sc[0], &sc[1]);
                chord_values(k, n, t * sc[0], t * sc[1], t, want_ld, oi__gl8[gi][1] * t * sc[1] * su,
                             part);
            }
            for (q = 0; q < N_SUMS; ++q) sum[q] += part[q] * du;
        }
        for (q = 0; q < N_SUMS; ++q) tot[q] += sum[q] * hw * OI_PI_R;
    }
    /* the smaller of the two parts keeps its relative accuracy (and is
     * exactly 0 when nothing, or everything, is covered) */
    disc = (oi_real)4 * OI_PI_R * oi__sin_half_sq(r);
    vis = oi__clamp(tot[Q_VIS] < tot[Q_HID] ? tot[Q_VIS] / disc : (oi_real)1 - tot[Q_HID] / disc,
                    (oi_real)0, (oi_real)1);
#ifdef OI_NO_LIMB_DARKENING
    if (frac_ld != NULL) *frac_ld = vis;
#else
    if (frac_ld != NULL) {
        /* in the same form, over the disc's flux as integrated: exactly 0
         * or 1 with the uniform fraction (the same chords' covers) */
        const oi_real ld_hid = tot[Q_LD_HID], ld_vis = tot[Q_LD_VIS], all = ld_hid + ld_vis;
        *frac_ld = !(all > (oi_real)0)
                       ? vis
                       : oi__clamp(ld_vis < ld_hid ? ld_vis / all : (oi_real)1 - ld_hid / all,
                                   (oi_real)0, (oi_real)1);
    }
#endif
    return vis;
}

/* tan r of the disc's apparent radius r: the gnomonic radius of its limb
 * (out of line: the sine and cosine are not kept in the caller's frame). */
static OI_NOINLINE oi_real gnomonic_radius(oi_real r)
{
    oi_real sr, cr;
    OI_SINCOS(r, &sr, &cr);
    return sr / cr;
}

/*
 * Visible fraction of the uniform disc of unit direction s and apparent
 * radius r (<= 0.5 rad) seen from p (outside the ellipsoid of equatorial
 * radius a), behind the ellipsoid alone. The solid angle it covers, as
 * chords of the gnomonic disc (closed form along each chord), integrated
 * over y = tan(r) sin(psi) piecewise between the breaks (all_breaks) by
 * Gauss-Legendre; over the disc's solid angle 4 pi sin^2(r/2); in [0, 1].
 * Apart from oi__oblate_visible so that the Sun's shadow (one occulter)
 * does not carry the second occulter's breaks on its stack (make stack).
 */
oi_real oi__oblate_visible_earth(const oi_real s[3], oi_real r, const oi_real p[3], oi_real a,
                                 oi_real *frac_ld)
{
    oi_real t, psi[MAX_BREAKS_EARTH];
    breaks b;
    cone k[1];
    const int narrow = build_cones(s, r, p, a, NULL, (oi_real)0, k, NULL);
    b.psi = psi;
    b.n = 0;
    b.cap = MAX_BREAKS_EARTH;
    t = gnomonic_radius(r);
    all_breaks(k, 1, r, t, &b);
    return fraction_from_breaks(k, 1, r, t, narrow, &b, frac_ld);
}

/*
 * The same behind the ellipsoid and a sphere of unit direction mo and
 * apparent radius rm (oi__oblate_visible, mo not NULL): its cone joins the
 * chords, and the breaks where the ellipsoid's cone crosses its limb
 * (moon_limb_breaks).
 */
static OI_NOINLINE oi_real visible_two(const oi_real s[3], oi_real r, const oi_real p[3],
                                       oi_real a, const oi_real mo[3], oi_real rm,
                                       oi_real *frac_ld)
{
    oi_real t, psi[MAX_BREAKS], mf[3];
    breaks b;
    cone k[2];
    const int narrow = build_cones(s, r, p, a, mo, rm, k, mf);
    b.psi = psi;
    b.n = 0;
    b.cap = MAX_BREAKS;
    t = gnomonic_radius(r);
    all_breaks(k, 2, r, t, &b);
    moon_limb_breaks(&k[0], mf, rm, t, &b);
    return fraction_from_breaks(k, 2, r, t, narrow, &b, frac_ld);
}

oi_real oi__oblate_visible(const oi_real s[3], oi_real r, const oi_real p[3], oi_real a,
                           const oi_real mo[3], oi_real rm, oi_real *frac_ld)
{
    return mo != NULL ? visible_two(s, r, p, a, mo, rm, frac_ld)
                      : oi__oblate_visible_earth(s, r, p, a, frac_ld);
}

/* Angular radius of the ellipsoid's silhouette seen from p, along the great
 * circle from the nadir n = -p/|p| towards s (e the unit normal towards s).
 * Scaling z by k = a/b (S) makes the ellipsoid the sphere of radius a, whose
 * cone from p' = S p is circular: half-angle beta, tan(beta) = a /
 * sqrt(|p'|^2 - a^2). The direction n + tau e maps to A + tau B (A = S n,
 * B = S e) and lies on the cone when its angle from A is beta:
 * tau (|A x B| - tan(beta) A.B) = tan(beta) |A|^2. No difference of nearly
 * equal terms at any distance (the quadratic form's entries lose (|p|/a)^2
 * ulps far away); beyond 90 deg the denominator is negative and atan2 says so. */
oi_real oi__oblate_radius_towards(const oi_real p[3], oi_real a, const oi_real s[3])
{
    /* f[0], f[1] become A and B in place, c beside them */
    oi_real f[3][3], n[3], pn, q, tb;
    oi_real *const big_a = f[0], *const big_b = f[1], *const c = n;
    int i;
    const oi_real k = OI_SQRT((oi_real)1 + K2M1);
    const oi_real dp = oi__norm_bounded(p);
    for (i = 0; i < 3; ++i) n[i] = -p[i] / dp;
    disc_frame(n, s, f);
    big_a[2] *= k;
    big_b[2] *= k;
    pn = dp * oi__norm_bounded(big_a);
    q = (pn - a) * (pn + a);
    if (!(q > (oi_real)0)) return OI_HALF_PI_R; /* on the surface (callers check outside) */
    tb = a / OI_SQRT(q);
    oi__cross(big_a, big_b, c);
    return OI_ATAN2(tb * oi__dot(big_a, big_a), oi__norm_bounded(c) - tb * oi__dot(big_a, big_b));
}

#else
typedef int oi__oblate_removed; /* ISO C forbids an empty translation unit */
#endif /* OI_NO_OBLATE */
