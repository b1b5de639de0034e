/* SPDX-License-Identifier: MIT */
/* facet_earth.c: the earthshine irradiance on a flat facet and the
 * specular earthshine it reflects, by a fixed cubature over the visible
 * sunlit cap clipped by the facet's horizon or, for a sharp lobe, about the
 * lobe (docs/shapes.md), and oi_earthshine_plate. */
#include "target/target_internal.h"

#ifndef OI_NO_FACETS

/* The 8-point Gauss rule of the Legendre weight on [0, 1], its nodes t
 * mapped by a = (1 - cos(pi t)) / 2 (so a piece's endpoint behaviour in
 * sqrt(a - a0), where a circle of the region touches a ring, becomes
 * analytic): the mapped node and the weight times the map's derivative
 * (mpmath, 21 digits; checked in tests/python/test_facets.py). */
#define N_NODES 8
static const oi_real node_map[N_NODES][2] = {
    { OI_R(0.000972393074746595051155), OI_R(0.00495601380754328264479) },
    { OI_R(0.0252873078505905667399), OI_R(0.0548412356676075773844) },
    { OI_R(0.132555030622283849363), OI_R(0.167094698072744440676) },
    { OI_R(0.357916038049035612469), OI_R(0.273108052452103539402) },
    { OI_R(0.642083961950964387531), OI_R(0.273108052452103539402) },
    { OI_R(0.867444969377716150637), OI_R(0.167094698072744440676) },
    { OI_R(0.97471269214940943326), OI_R(0.0548412356676075773844) },
    { OI_R(0.999027606925253404949), OI_R(0.00495601380754328264479) },
};

/* Lowest altitude the cubature integrates at (km): below it, 1 m, the value
 * there (the flat plane's limit to O(h / R) = 2e-7), so that h^4 stays a
 * normal number in single precision. */
#define H_FLOOR_KM OI_R(1e-3)

/* Break points: 0, the horizon, the terminator's tangency, the facet
 * circle's two tangencies and its two crossings with the terminator, and up
 * to N_GEO multiples of the altitude (the 1/d^3 peak under the target). */
#define N_GEO 6
#define N_BREAK (7 + N_GEO)

/* The azimuthal integral over [b1, b2] of (A + B cos b)(C + D cos b + E sin b)
 * (the lit factor n.s and the facet's N.(P - T), both linear in cos b and
 * sin b on a ring about the sub-target point), in closed form. */
static oi_real arc_integral(const oi_real k[5], oi_real b1, oi_real b2)
{
    oi_real s1, c1, s2, c2, ds, dc, db, dsc, dss;
    OI_SINCOS(b1, &s1, &c1);
    OI_SINCOS(b2, &s2, &c2);
    db = b2 - b1;
    ds = s2 - s1;
    dc = c2 - c1;
    dsc = s2 * c2 - s1 * c1;
    dss = s2 * s2 - s1 * s1;
    return k[0] * k[2] * db + (k[0] * k[3] + k[1] * k[2]) * ds - k[0] * k[4] * dc +
           k[1] * k[3] * OI_R(0.5) * (db + dsc) + k[1] * k[4] * OI_R(0.5) * dss;
}

/* Half-width of the arc where c0 + amp cos(b - centre) > 0 on the ring:
 * -1 empty, > pi (as 4) the whole ring. */
static oi_real half_width(oi_real c0, oi_real amp)
{
    oi_real x;
    if (!(amp > (oi_real)0)) return c0 > (oi_real)0 ? OI_R(4.0) : OI_R(-1.0);
    x = -c0 / amp;
    if (x <= OI_R(-1.0)) return OI_R(4.0);
    if (x >= OI_R(1.0)) return OI_R(-1.0);
    return OI_ACOS(x);
}

/* The specular lobe a cap cubature integrates (NULL: the irradiance): the
 * face's unit normal and the unit direction to the observer (local frame),
 * the shininess, and per ring the incoming direction's parts (omega =
 * (rho cos b, rho sin b, zc) / 1, set by the caller). */
typedef struct lobe_ring {
    const oi_real *nrm, *obs;
    oi_real shininess, rho, zc, inv_d;
} lobe_ring;

/* The plain 6-point Gauss rule on [0, 1], its lower half (node, weight;
 * the rule is symmetric), for the specular lobe over an arc (mpmath, 21
 * digits; checked in tests/python/test_facets.py). */
#define N_ARC 6
static const oi_real arc_rule[N_ARC / 2][2] = {
    { OI_R(0.0337652428984239860938), OI_R(0.0856622461895851725201) },
    { OI_R(0.169395306766867743169), OI_R(0.180380786524069303785) },
    { OI_R(0.380690406958401545685), OI_R(0.233956967286345523695) },
};

/* The azimuthal integral over [b1, b2] of (A + B cos b)(C + D cos b + E sin b)
 * f(omega(b) -> obs), f the Phong lobe per unit albedo_specular, by the
 * 6-point rule (the two factors vanish at the arc's ends, where it is cut). */
static oi_real arc_specular(const oi_real k[5], oi_real b1, oi_real b2, const lobe_ring *lr)
{
    oi_real sum = (oi_real)0;
    int i, side;
    for (i = 0; i < N_ARC / 2; i++)
        for (side = 0; side < 2; side++) {
            const oi_real t = side ? (oi_real)1 - arc_rule[i][0] : arc_rule[i][0];
            oi_real sb, cb, lit, face, om[3];
            OI_SINCOS(b1 + (b2 - b1) * t, &sb, &cb);
            lit = k[0] + k[1] * cb;
            face = k[2] + k[3] * cb + k[4] * sb;
            if (!(lit > (oi_real)0) || !(face > (oi_real)0)) continue;
            om[0] = lr->rho * cb;
            om[1] = lr->rho * sb;
            om[2] = lr->zc;
            /* N.omega = face / d */
            sum += arc_rule[i][1] * lit * face *
                   oi__phong_lobe(lr->nrm, face * lr->inv_d, om, lr->obs, lr->shininess);
        }
    return sum * (b2 - b1);
}

/* The ring's integral over the intersection of the lit arc |b| < w1 and the
 * facet's arc |b - beta| < w2 (either may be the whole ring): the
 * irradiance's integrand in closed form, or the specular lobe's (lr). */
static oi_real ring(const oi_real k[5], oi_real w1, oi_real beta, oi_real w2, const lobe_ring *lr)
{
    oi_real sum = (oi_real)0, lo, hi;
    int i;
    if (w1 < (oi_real)0 || w2 < (oi_real)0) return sum;
    if (w1 > OI_PI_R && w2 > OI_PI_R) {
        lo = -OI_PI_R;
        hi = OI_PI_R;
    } else if (w2 > OI_PI_R) {
        lo = -w1;
        hi = w1;
    } else if (w1 > OI_PI_R) {
        lo = beta - w2;
        hi = beta + w2;
    } else {
        /* beta in [-pi, pi]: the facet's arc and its images a turn away */
        for (i = -1; i <= 1; i++) {
            const oi_real shift = (oi_real)(2 * i) * OI_PI_R;
            const oi_real lo1 = beta - w2 + shift, hi1 = beta + w2 + shift;
            lo = lo1 > -w1 ? lo1 : -w1;
            hi = hi1 < w1 ? hi1 : w1;
            if (hi > lo) sum += lr != NULL ? arc_specular(k, lo, hi, lr) : arc_integral(k, lo, hi);
        }
        return sum;
    }
    return lr != NULL ? arc_specular(k, lo, hi, lr) : arc_integral(k, lo, hi);
}

/* The two points where the terminator (the great circle of pole s, the
 * Sun's direction (sin theta, 0, cos theta)) crosses the facet circle (pole
 * nrm, cosine c_n): their polar angles from the zenith (the sub-target
 * point) added as break points (its own frame). */
static OI_NOINLINE int add_crossings(oi_real bp[N_BREAK], int n, oi_real cos_theta,
                                     oi_real sin_theta, const oi_real nrm[3], oi_real c_n,
                                     oi_real a_max)
{
    oi_real s[3], k, det, al, be, p0[3], u[3], rest, z;
    int i;
    s[0] = sin_theta;
    s[1] = (oi_real)0;
    s[2] = cos_theta;
    k = oi__dot(s, nrm);
    det = ((oi_real)1 - k) * ((oi_real)1 + k);
    if (!(det > OI_R(1e-12))) return n;
    al = -c_n * k / det;
    be = c_n / det;
    for (i = 0; i < 3; i++) p0[i] = al * s[i] + be * nrm[i];
    rest = (oi_real)1 - oi__dot(p0, p0);
    if (!(rest > (oi_real)0)) return n;
    oi__cross(s, nrm, u);
    if (oi__unit_bounded(u, u) == (oi_real)0) return n;
    rest = OI_SQRT(rest);
    z = p0[2] + rest * u[2];
    n = oi__cap_break_add(bp, N_BREAK, n, OI_ACOS(oi__clamp(z, OI_R(-1.0), OI_R(1.0))), a_max);
    z = p0[2] - rest * u[2];
    return oi__cap_break_add(bp, N_BREAK, n, OI_ACOS(oi__clamp(z, OI_R(-1.0), OI_R(1.0))), a_max);
}

/* cap_cubature's first break points (Note 2) in bp, their count returned:
 * the start (0, the horizon, the terminator's tangency) and the facet
 * circle's tangencies; *a_max the cap's edge. Its own frame, beside the
 * rings' integration. */
static OI_NOINLINE int cap_breaks(oi_real cos_theta, oi_real sin_theta, oi_real hp, oi_real rp,
                                  const oi_real nrm[3], oi_real nh, oi_real c_n,
                                  oi_real bp[N_BREAK], oi_real *a_max)
{
    int n = oi__cap_breaks_start(bp, N_BREAK, hp, rp, cos_theta, sin_theta, a_max);
    if (c_n > OI_R(-1.0)) {
        const oi_real gam = OI_ATAN2(nh, nrm[2]), rho = OI_ACOS(c_n);
        n = oi__cap_break_add(bp, N_BREAK, n, OI_FABS(gam - rho), *a_max);
        n = oi__cap_break_add(bp, N_BREAK, n, gam + rho, *a_max);
    }
    return n;
}

/*
 * cap_cubature: irradiance on the face of unit normal nrm (local frame: z
 * the zenith, x towards the Sun's side) per unit Earth albedo and unit solar
 * irradiance at the Earth, at theta (cos_theta, sin_theta) and h_km above an
 * Earth of radius R (km); with lr, the specular radiance instead (Note 4).
 * Notes:
 *  1. Unit r = |target|: R' = R / r, h' = h / r. A surface point n at polar
 *     angle a, azimuth b about the sub-target point sends radiance
 *     (n.s) / pi; seen from the target at distance d' (d'^2 = h'^2 +
 *     4 R' sin^2(a/2)) it subtends cos(e) dA / d'^2, cos(e) = (cos a - R') / d',
 *     and the face receives it times N.(P - T) / d'. So
 *       E = R'^2 / pi int sin a (cos a - R') / d'^4 J(a) da,
 *     J the azimuthal integral of (n.s)(N.(P - T)) over the arcs where both
 *     are positive (arc_integral, exact).
 *  2. The region is the intersection of three caps (visible, lit, in front of
 *     the face); the a range is split where a circle of theirs touches a
 *     ring or two cross, and at multiples of the altitude; each piece gets
 *     the mapped 8-point rule (node_map). docs/shapes.md measures it.
 *  3. h_km below H_FLOOR_KM is taken as H_FLOOR_KM.
 *  4. With lr, the specular lobe f(omega -> obs) multiplies the azimuthal
 *     integrand, which is then integrated by the 6-point rule over each arc
 *     (arc_specular) instead of in closed form: the same rings.
 */
static OI_NOINLINE oi_real cap_cubature(oi_real cos_theta, oi_real sin_theta, oi_real h_km,
                                        oi_real R, const oi_real nrm[3], lobe_ring *lr)
{
    oi_real bp[N_BREAK], r, rp, hp, nh, c_n, a_max;
    oi_real beta = (oi_real)0, total = (oi_real)0;
    int n, p, q;

    if (!(h_km >= H_FLOOR_KM)) h_km = H_FLOOR_KM;
    r = R + h_km;
    rp = R / r;
    hp = h_km / r;

    nh = OI_SQRT(nrm[0] * nrm[0] + nrm[1] * nrm[1]);
    c_n = nrm[2] / rp;
    if (!(c_n < (oi_real)1)) return (oi_real)0; /* the whole Earth behind the face */
    if (nh > (oi_real)0) beta = OI_ATAN2(nrm[1], nrm[0]);
    n = cap_breaks(cos_theta, sin_theta, hp, rp, nrm, nh, c_n, bp, &a_max);
    if (c_n > OI_R(-1.0)) n = add_crossings(bp, n, cos_theta, sin_theta, nrm, c_n, a_max);
    n = oi__cap_breaks_altitude(bp, N_BREAK, n, N_GEO, hp, rp, a_max);

    for (p = 0; p + 1 < n; p++) {
        const oi_real a0 = bp[p], width = bp[p + 1] - bp[p];
        if (!(width > (oi_real)0)) continue;
        for (q = 0; q < N_NODES; q++) {
            oi_real a = a0 + width * node_map[q][0], sh, ch, sa, ca, sh2, d2, k[5];
            OI_SINCOS(OI_R(0.5) * a, &sh, &ch);
            sa = OI_R(2.0) * sh * ch;
            sh2 = sh * sh;
            ca = (oi_real)1 - OI_R(2.0) * sh2;
            d2 = hp * hp + OI_R(4.0) * rp * sh2;
            k[0] = ca * cos_theta;
            k[1] = sa * sin_theta;
            k[2] = -nrm[2] * (hp + OI_R(2.0) * rp * sh2);
            k[3] = rp * sa * nrm[0];
            k[4] = rp * sa * nrm[1];
            if (lr != NULL) {
                /* omega = (P - T) / d: (R' sin a cos b, R' sin a sin b, R' cos a - 1) / d */
                lr->inv_d = (oi_real)1 / OI_SQRT(d2);
                lr->rho = rp * sa * lr->inv_d;
                lr->zc = -(hp + OI_R(2.0) * rp * sh2) * lr->inv_d;
            }
            total += width * node_map[q][1] * sa * (hp - OI_R(2.0) * sh2) / (d2 * d2) *
                     ring(k, half_width(k[0], k[1]), beta, half_width(k[2], rp * sa * nh), lr);
        }
    }
    total *= rp * rp / OI_PI_R;
    return total > (oi_real)0 ? total : (oi_real)0;
}

/* oi__plate_earth: contract in src/target/target_internal.h; the cap cubature of the
 * irradiance (cap_cubature's Notes). */
oi_real oi__plate_earth(oi_real cos_theta, oi_real sin_theta, oi_real h_km, oi_real R,
                        const oi_real nrm[3])
{
    return cap_cubature(cos_theta, sin_theta, h_km, R, nrm, (lobe_ring *)0);
}

/* The lobe rule's nodes: s = cos^(n + 1) of the angle from the lobe's axis
 * (the weight of the normalised lobe is uniform in s), the 4-point Gauss
 * rule on [0, 1] in s (node, weight; mpmath, 21 digits), and 8 azimuths at
 * (j + 1/2) pi / 4 (cos, sin: the trapezoid rule, exact for the azimuth's
 * low harmonics). */
#define N_LOBE_S 4
#define N_LOBE_PHI 8
static const oi_real lobe_s[N_LOBE_S][2] = {
    { OI_R(0.0694318442029737123881), OI_R(0.173927422568726928687) },
    { OI_R(0.330009478207571867599), OI_R(0.326072577431273071313) },
    { OI_R(0.669990521792428132401), OI_R(0.326072577431273071313) },
    { OI_R(0.930568155797026287612), OI_R(0.173927422568726928687) },
};
static const oi_real lobe_phi[N_LOBE_PHI / 2][2] = {
    { OI_R(0.923879532511286756128), OI_R(0.382683432365089771728) },
    { OI_R(0.382683432365089771728), OI_R(0.923879532511286756128) },
    { OI_R(-0.382683432365089771728), OI_R(0.923879532511286756128) },
    { OI_R(-0.923879532511286756128), OI_R(0.382683432365089771728) },
};

/* The Earth's radiance per unit albedo and solar irradiance seen from the
 * target along the unit local direction om (unit r: the target at (0, 0,
 * 1), the Earth of radius rp): (n.s) / pi where the ray meets the sunlit
 * surface, else 0. */
static oi_real earth_radiance(const oi_real om[3], oi_real cos_theta, oi_real sin_theta,
                              oi_real rp, oi_real hp)
{
    const oi_real disc = om[2] * om[2] - hp * ((oi_real)1 + rp);
    oi_real t, lit;
    if (!(om[2] < (oi_real)0) || !(disc >= (oi_real)0)) return (oi_real)0;
    /* the nearer root of |T + t om|^2 = rp^2, in the form without cancellation */
    t = hp * ((oi_real)1 + rp) / (-om[2] + OI_SQRT(disc));
    lit = (cos_theta + t * (om[0] * sin_theta + om[2] * cos_theta)) / rp;
    return lit > (oi_real)0 ? lit / OI_PI_R : (oi_real)0;
}

/*
 * lobe_rule: the specular integral of oi__plate_earth_specular by nodes
 * about the lobe's axis m, the mirror image of obs about nrm. With gamma
 * the angle from m, the normalised lobe's weight (n + 2) / (2 pi) cos^n
 * gamma dOmega is (n + 2) / (n + 1) ds dphi / (2 pi) with s = cos^(n + 1)
 * gamma, so the nodes (s_i, phi_j) sample the Earth's radiance times
 * N.omega where the lobe is, whatever its width; exact for a radiance
 * that is linear across the lobe, in error where the limb or the
 * terminator cuts it (docs/shapes.md measures it).
 */
static OI_NOINLINE oi_real lobe_rule(oi_real cos_theta, oi_real sin_theta, oi_real h_km, oi_real R,
                         const oi_real nrm[3], const oi_real obs[3], oi_real shininess)
{
    oi_real m[3], e1[3], e2[3], rp, hp, total = (oi_real)0, no;
    int i, j, k;
    rp = R / (R + h_km);
    hp = h_km / (R + h_km);
    no = oi__dot(nrm, obs);
    for (k = 0; k < 3; k++) m[k] = OI_R(2.0) * no * nrm[k] - obs[k];
    /* e1 normal to m, from the axis m is least along */
    e1[0] = OI_FABS(m[0]) < OI_R(0.6) ? (oi_real)1 : (oi_real)0;
    e1[1] = e1[0] > (oi_real)0 ? (oi_real)0 : (oi_real)1;
    e1[2] = (oi_real)0;
    oi__cross(m, e1, e2);
    if (oi__unit_bounded(e2, e2) == (oi_real)0) return (oi_real)0;
    oi__cross(e2, m, e1);
    for (i = 0; i < N_LOBE_S; i++) {
        const oi_real mu = OI_POW(lobe_s[i][0], (oi_real)1 / (shininess + (oi_real)1));
        const oi_real sg = OI_SQRT(((oi_real)1 - mu) * ((oi_real)1 + mu));
        oi_real circle = (oi_real)0;
        for (j = 0; j < N_LOBE_PHI; j++) {
            const oi_real c = j < N_LOBE_PHI / 2 ? lobe_phi[j][0] : -lobe_phi[j - N_LOBE_PHI / 2][0];
            const oi_real sn = j < N_LOBE_PHI / 2 ? lobe_phi[j][1] : -lobe_phi[j - N_LOBE_PHI / 2][1];
            oi_real om[3], cn;
            for (k = 0; k < 3; k++) om[k] = mu * m[k] + sg * (c * e1[k] + sn * e2[k]);
            cn = oi__dot(om, nrm);
            if (cn > (oi_real)0) circle += cn * earth_radiance(om, cos_theta, sin_theta, rp, hp);
        }
        total += lobe_s[i][1] * circle;
    }
    return total / (oi_real)N_LOBE_PHI * (shininess + OI_R(2.0)) / (shininess + (oi_real)1);
}

/* oi__plate_earth_specular: contract in src/target/target_internal.h. */
oi_real oi__plate_earth_specular(oi_real cos_theta, oi_real sin_theta, oi_real h_km, oi_real R,
                                 const oi_real nrm[3], const oi_real obs[3], oi_real shininess)
{
    lobe_ring lr;
    if (!(h_km >= H_FLOOR_KM)) h_km = H_FLOOR_KM;
    if (!(oi__dot(nrm, obs) > (oi_real)0)) return (oi_real)0;
    if (shininess >= (oi_real)OI_LOBE_RULE_SHININESS)
        return lobe_rule(cos_theta, sin_theta, h_km, R, nrm, obs, shininess);
    lr.nrm = nrm;
    lr.obs = obs;
    lr.shininess = shininess;
    lr.rho = lr.zc = lr.inv_d = (oi_real)0;
    return cap_cubature(cos_theta, sin_theta, h_km, R, nrm, &lr);
}

/* What oi_earthshine_plate needs of its model and inputs once they are
 * checked: the Sun's angle (cosine, sine), the altitude, the unit normal,
 * the Earth's radius, phi and psi, and the irradiance from the mean
 * direction where the cubature does not serve (cubature 0). */
typedef struct plate_in {
    oi_real cs, sn, h_km, nrm[3], radius_km, phi, psi, mean;
    int cubature;
} plate_in;

/* The irradiance from the mean direction, (sin psi, 0, -cos psi) in the
 * local frame (its own frame: not on the stack during oi__earthshine). */
static OI_NOINLINE void plate_mean(plate_in *p)
{
    oi_real c, s, dot;
    OI_SINCOS(p->psi, &s, &c);
    dot = p->nrm[0] * s - p->nrm[2] * c;
    p->mean = dot > (oi_real)0 ? p->phi * dot : (oi_real)0;
}

/* oi_earthshine_plate's checks and oi__earthshine, in a frame of its own:
 * the resolved model is not on the stack while the cubature runs (make
 * stack). */
static OI_NOINLINE int plate_setup(oi_real theta, oi_real h_km, const oi_real normal[3],
                                   const oi_model *model, plate_in *p)
{
    oi_model m;
    int st = oi__model_resolve(model, &m);
    if (st < 0) return st;
    if (!oi__finite3(normal)) return OI_ERR_NONFINITE;
    if (!OI_ISFINITE(theta) || !OI_ISFINITE(h_km)) return OI_ERR_NONFINITE;
    p->h_km = h_km;
    theta = oi__clamp(theta, (oi_real)0, OI_PI_R);
    OI_SINCOS(theta, &p->sn, &p->cs);
    st = oi__earthshine(theta, p->cs, p->sn, p->h_km, &m, &p->phi, &p->psi);
    if (st < 0) return st;
    if (oi__unit_scaled(normal, p->nrm) == (oi_real)0) return OI_ERR_ZERO_VECTOR;
    p->radius_km = m.earth_radius_km;
    p->cubature = oi__plate_cubature(&m);
    if (!p->cubature) plate_mean(p);
    return st;
}

/* oi_earthshine_plate: contract in include/orbillum.h. */
int oi_earthshine_plate(oi_real theta, oi_real h_km, const oi_real normal[3],
                        const oi_model *model, oi_real *irradiance)
{
    plate_in p;
    int st;

    if (irradiance != NULL) *irradiance = (oi_real)0;
    if (irradiance == NULL || normal == NULL) return OI_ERR_NULL;
    st = plate_setup(theta, h_km, normal, model, &p);
    if (st < 0) return st;
    *irradiance = p.cubature ? oi__plate_earth(p.cs, p.sn, p.h_km, p.radius_km, p.nrm) : p.mean;
    return st;
}

#endif /* OI_NO_FACETS */
