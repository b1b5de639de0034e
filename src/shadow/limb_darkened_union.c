/* SPDX-License-Identifier: MIT */
/* limb_darkened_union.c: the visible fraction of the limb-darkened solar disc
 * behind two nearer discs at once, the Earth's and the Moon's
 * (oi__fraction_ld_two; internal, declared in src/shadow/shadow_internal.h).
 * docs/shadow.md section 9. */
#include "shadow/shadow_internal.h"

#if !defined(OI_NO_MOON) && !defined(OI_NO_LIMB_DARKENING)

/* Neckel & Labs (1994) at 559.95 nm, I(mu)/I(1) = sum A_k mu^k (as
 * src/shadow/limb_darkening.c). */
static const oi_real ld_a[6] = {OI_R(0.26892), OI_R(1.34319), OI_R(-1.58427),
                                OI_R(1.91271), OI_R(-1.31350), OI_R(0.37295)};

/* Panels of the 8-point Gauss-Legendre rule (oi__gl8, src/math/math_internal.h:
 * nodes x and 1 - x share the weights) per piece. */
#ifndef PANELS
#define PANELS 2
#endif

/* A disc in front of the Sun: radius r, its centre d from the Sun's. */
typedef struct {
    oi_real r, d;
} front_disc;

/* Half the angle of the ring of radius rho about the Sun's centre inside
 * the disc (the angle at the Sun's centre of the triangle (Sun's centre,
 * disc's centre, crossing point), half-angle formula). */
static oi_real ring_half(oi_real rho, const front_disc *f)
{
    oi_real hs[4];
    if (rho + f->d <= f->r) return OI_PI_R;                 /* the ring inside the disc */
    if (f->d - rho >= f->r || rho - f->d >= f->r) return (oi_real)0; /* apart */
    oi__half_sines(rho, f->r, f->d, hs);
    return oi__half_angle(hs, 2, 0);
}

/* The angle of the ring outside both discs, their centres seen delta apart
 * about the Sun's centre. */
static oi_real ring_visible(oi_real rho, const front_disc *e, const front_disc *m, oi_real delta)
{
    const oi_real he = ring_half(rho, e), hm = ring_half(rho, m);
    const oi_real lo = (oi_real)2 * (he < hm ? he : hm);
    oi_real one = oi__clamp(he + hm - delta, (oi_real)0, lo);
    oi_real two = oi__clamp(he + hm - ((oi_real)2 * OI_PI_R - delta), (oi_real)0, lo);
    oi_real common = one + two < lo ? one + two : lo;
    return oi__clamp((oi_real)2 * OI_PI_R - (oi_real)2 * (he + hm) + common, (oi_real)0,
                     (oi_real)2 * OI_PI_R);
}

/* I(mu)/I(1) at rho from the centre of the disc of radius rs (sin rs = srs),
 * mu = sqrt(1 - sin^2 rho / sin^2 rs) (exact on the sphere). */
static oi_real intensity(oi_real rho, oi_real srs)
{
    oi_real s = OI_SIN(rho), q, mu, v;
    int k;
    q = (srs - s) * (srs + s);
    mu = q > (oi_real)0 ? OI_SQRT(q) / srs : (oi_real)0;
    v = ld_a[5];
    for (k = 4; k >= 0; --k) v = v * mu + ld_a[k];
    return v;
}

/* hav^-1: the angle whose haversine sin^2(x/2) is h. */
static oi_real from_hav(oi_real h)
{
    return (oi_real)2 * OI_ASIN(OI_SQRT(oi__clamp(h, (oi_real)0, (oi_real)1)));
}

/* Insert x into the sorted list b[0..*n-1] when it lies in (0, hi). */
static void add_break(oi_real *b, int *n, oi_real x, oi_real hi)
{
    int i;
    if (!(x > (oi_real)0 && x < hi)) return;
    for (i = *n; i > 0 && b[i - 1] > x; --i) b[i] = b[i - 1];
    b[i] = x;
    ++*n;
}

/*
 * Visible fraction of the limb-darkened solar disc (radius rs) behind the
 * Earth's disc (re, centre de from the Sun's) and the Moon's (rm, dm), the
 * two centres dem apart. A ring integral about the Sun's centre of the
 * intensity times the angle each ring keeps outside both discs, over
 * [0, rs] split where a ring starts or stops being cut by either disc and
 * at the distances of the two limbs' crossing points (the integrand is
 * smooth between), each piece by two 8-point Gauss-Legendre panels in
 * u with rho = a + (b - a)(1 - cos pi u)/2 (which removes the square-root
 * ends); the disc's own flux by the same rule. Used only when both discs
 * cover part of the Sun (rare): at most 9 pieces, 16 nodes each. Measured
 * against an mpmath ring quadrature: 2.6e-8 (docs/shadow.md section 9).
 */
oi_real oi__fraction_ld_two(oi_real rs, oi_real re, oi_real de, oi_real rm, oi_real dm,
                            oi_real dem)
{
    front_disc e, m;
    oi_real b[12], hs[4], delta, vis = (oi_real)0, all = (oi_real)0, srs = OI_SIN(rs);
    int n = 0, i, k;
    e.r = re;
    e.d = de;
    m.r = rm;
    m.d = dm;
    /* the centres' azimuth difference about the Sun's centre */
    oi__half_sines(de, dm, dem, hs);
    delta = oi__half_angle(hs, 3, 0);
    b[n++] = (oi_real)0;
    add_break(b, &n, OI_FABS(de - re), rs);
    add_break(b, &n, de + re, rs);
    add_break(b, &n, OI_FABS(dm - rm), rs);
    add_break(b, &n, dm + rm, rs);
    if (dem < re + rm && dem > OI_FABS(re - rm)) {
        /* the crossing points: at +-beta from the Moon's direction about the
         * Earth's centre, the Sun's direction at psi from it; their distance
         * from the Sun's centre by the haversine law (no cancellation) */
        oi_real beta, psi, sde = OI_SIN(de) * OI_SIN(re);
        oi__half_sines(re, rm, dem, hs);
        beta = oi__half_angle(hs, 2, 0);
        oi__half_sines(de, dem, dm, hs);
        psi = oi__half_angle(hs, 3, 0);
        add_break(b, &n, from_hav(oi__sin_half_sq(de - re) + sde * oi__sin_half_sq(psi - beta)), rs);
        add_break(b, &n, from_hav(oi__sin_half_sq(de - re) + sde * oi__sin_half_sq(psi + beta)), rs);
    }
    b[n++] = rs;
    for (i = 0; i + 1 < n; ++i) {
        const oi_real lo = b[i], w = b[i + 1] - b[i];
        if (!(w > (oi_real)0)) continue;
        for (k = 0; k < PANELS * OI_GL8_HALF * 2; ++k) {
            {
                const int p = k / (2 * OI_GL8_HALF), q = k % (2 * OI_GL8_HALF);
                const int j = q % OI_GL8_HALF, s = q / OI_GL8_HALF;
                oi_real x = s ? (oi_real)1 - oi__gl8[j][0] : oi__gl8[j][0], su, cu, rho, jac, g;
                oi_real u = ((oi_real)p + x) / (oi_real)PANELS;
                OI_SINCOS(OI_PI_R * u, &su, &cu);
                rho = lo + w * OI_R(0.5) * ((oi_real)1 - cu);
                jac = oi__gl8[j][1] / (oi_real)PANELS * w * OI_R(0.5) * OI_PI_R * su;
                g = jac * intensity(rho, srs) * OI_SIN(rho);
                vis += g * ring_visible(rho, &e, &m, delta);
                all += g * (oi_real)2 * OI_PI_R;
            }
        }
    }
    return all > (oi_real)0 ? oi__clamp(vis / all, (oi_real)0, (oi_real)1) : (oi_real)0;
}

#else
typedef int oi__limb_darkened_union_removed; /* ISO C forbids an empty translation unit */
#endif
