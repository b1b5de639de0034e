/* SPDX-License-Identifier: MIT */
/* moon_occultation.c: the Moon as an occulter of the Sun seen from the target
 * (with the Earth at once), and the Earth as an occulter of the Moon's disc
 * (internal, declared in src/shadow/shadow_internal.h). docs/shadow.md section 9. */
#include "shadow/shadow_internal.h"

#ifndef OI_NO_MOON

/* Apparent angular radius of a sphere of radius rad at distance dist > rad,
 * exact near grazing (as in src/shadow/sun_fraction.c). */
static oi_real apparent_radius(oi_real rad, oi_real dist)
{
    return OI_ATAN2(rad, OI_SQRT(dist - rad) * OI_SQRT(dist + rad));
}

/* 1 when two spheres seen from one point are certainly apart on its sky:
 * a, b the vectors from the point to their centres, a2, b2 their squared
 * lengths, ra, rb their radii (a2 > ra^2, b2 > rb^2). The angle between a
 * and b exceeds the sum of the apparent radii when its cosine is below
 * cos(r_a + r_b) = (sqrt(a2 - ra^2) sqrt(b2 - rb^2) - ra rb) / (|a| |b|)
 * (each radius below pi/2, so their sum below pi, where cos decreases); with
 * a margin of 1e-6 relative, far beyond rounding. One dot product and two
 * square roots (no unit vector, no division, no inverse trigonometry; the
 * square roots of squared lengths bounded by OI_POSITION_MAX_KM cannot
 * overflow). */
static int discs_certainly_apart(const oi_real a[3], const oi_real b[3], oi_real a2,
                                 oi_real b2, oi_real ra, oi_real rb)
{
    const oi_real lhs = oi__dot(a, b) + ra * rb;
    const oi_real rhs = OI_SQRT(a2 - ra * ra) * OI_SQRT(b2 - rb * rb);
    return lhs < rhs * (oi_real)(1 - 1e-6);
}

/* The model's choice of disc. */
static oi_real chosen_disc(const oi_model *m, oi_real frac, oi_real frac_ld)
{
    return m->limb_darkening == OI_LIMB_DARKENED ? frac_ld : frac;
}

/*
 * The Earth and the Moon both cover part of the Sun: the visible fractions
 * from the area of the intersection of the three caps (inclusion-exclusion,
 * exact on the sphere for the uniform disc):
 *   visible = fraction_earth - (1 - fraction_moon) + area(S, E, M) / area(S).
 * The limb-darkened disc: a ring integral over the Sun's disc of what both
 * discs leave visible (oi__fraction_ld_two, src/shadow/limb_darkened_union.c).
 * Out of line: its caps' centres and radii are not live while the
 * ellipsoid's silhouette is traced (oblate_both, make stack).
 */
static OI_NOINLINE void both_occulters(const oi_real u_sun[3], const oi_real u_moon[3],
                           const oi_real target_km[3], oi_real rm, oi_real sep_moon, oi_real fm,
                           oi_real fm_ld, oi_shadow *sh)
{
    oi_real c[3][3], r[3], triple, a_sun, lim;
    int i;
    const oi_real dp = oi__norm_bounded(target_km);
    for (i = 0; i < 3; ++i) {
        c[0][i] = u_sun[i];
        c[1][i] = -target_km[i] / dp;
        c[2][i] = u_moon[i];
    }
    r[0] = sh->sun_radius_rad;
    r[1] = sh->earth_radius_rad;
    r[2] = rm;
    triple = oi__cap_triple((const oi_real(*)[3])c, r);
    a_sun = (oi_real)4 * OI_PI_R * oi__sin_half_sq(r[0]);
    lim = sh->fraction < fm ? sh->fraction : fm;
    sh->fraction =
        oi__clamp(sh->fraction - ((oi_real)1 - fm) + triple / a_sun, (oi_real)0, lim);
#ifdef OI_NO_LIMB_DARKENING
    (void)fm_ld;
    (void)sep_moon;
    sh->fraction_ld = sh->fraction;
#else
    sh->fraction_ld = r[0] <= OI_LD_RS_MAX && r[0] > OI_LD_RS_MIN
                          ? oi__fraction_ld_two(r[0], r[1], sh->separation_rad, rm, sep_moon,
                                                oi__angle_unit(c[1], c[2]))
                          : sh->fraction;
    lim = fm_ld < (oi_real)1 ? fm_ld : (oi_real)1;
    if (sh->fraction_ld > lim) sh->fraction_ld = lim;
#endif
}

#ifndef OI_NO_OBLATE
/* both_occulters on the ellipsoid: its silhouette and the Moon's disc
 * (src/shadow/oblate.c) replace the sphere's fractions, both discs exact. */
static OI_NOINLINE void oblate_both(const oi_real u_sun[3], const oi_real u_moon[3],
                                    const oi_real target_km[3], oi_real rm, const oi_model *m,
                                    oi_shadow *sh)
{
    sh->fraction = oi__oblate_visible(u_sun, sh->sun_radius_rad, target_km, m->earth_radius_km,
                                      u_moon, rm, &sh->fraction_ld);
}
#endif

/*
 * The Moon's shadow on a point: sh holds oi__sun_shadow's result for the
 * point (the Earth as occulter); its fractions are replaced by those with
 * the Moon as a second occulter. *hidden: the fraction of the Sun's disc
 * area the Moon alone covers (0 when it covers none). fraction_atm: the
 * atmosphere's fraction times the ratio of the model's disc with and without
 * the Moon (the Moon's disc cuts the direct and the refracted light alike);
 * equal to the model's disc where the atmosphere changed nothing.
 * region stays the Earth's. Returns OI_OK, or OI_ERR_GEOMETRY for a point
 * inside or on the Moon.
 * Cost: when the discs are certainly apart, three dot products and two
 * square roots (discs_certainly_apart).
 */
int oi__moon_shadow(const oi_real sun_km[3], const oi_real moon_km[3],
                    const oi_real point_km[3], const oi_model *m, oi_shadow *sh,
                    oi_real *hidden)
{
    oi_real u_sun[3], u_moon[3], ds, dm, rm, sep, fm, fm_ld, old, new_disc;
    int region;
    *hidden = (oi_real)0;
    oi__sub(moon_km, point_km, u_moon);
    oi__sub(sun_km, point_km, u_sun);
    dm = oi__dot(u_moon, u_moon); /* squared distances first */
    ds = oi__dot(u_sun, u_sun);
    if (!(dm > m->moon_radius_km * m->moon_radius_km)) return OI_ERR_GEOMETRY;
    if (dm >= ds) return OI_OK; /* the Moon beyond the Sun */
    if (discs_certainly_apart(u_sun, u_moon, ds, dm, m->sun_radius_km, m->moon_radius_km))
        return OI_OK;
    dm = oi__unit_bounded(u_moon, u_moon);
    (void)oi__unit_bounded(u_sun, u_sun);
    rm = apparent_radius(m->moon_radius_km, dm);
    sep = oi__angle_unit(u_sun, u_moon);
    region = oi__disc_fractions(sh->sun_radius_rad, rm, sep, &fm, &fm_ld);
    if (region == OI_SHADOW_LIT) return OI_OK;
    *hidden = (oi_real)1 - fm;
    old = chosen_disc(m, sh->fraction, sh->fraction_ld);
    if (sh->region == OI_SHADOW_LIT) {
        sh->fraction = fm;
        sh->fraction_ld = fm_ld;
    } else if (sh->region != OI_SHADOW_UMBRA) {
        both_occulters(u_sun, u_moon, point_km, rm, sep, fm, fm_ld, sh);
#ifndef OI_NO_OBLATE
        if (m->earth_shape == OI_EARTH_WGS84 && sh->sun_radius_rad <= OI_R(0.5))
            oblate_both(u_sun, u_moon, point_km, rm, m, sh);
#endif
    }
    new_disc = chosen_disc(m, sh->fraction, sh->fraction_ld);
    if (sh->fraction_atm == old)
        sh->fraction_atm = new_disc; /* no atmosphere here */
    else
        sh->fraction_atm *= old > (oi_real)0 ? oi__clamp(new_disc / old, (oi_real)0, (oi_real)1)
                                             : chosen_disc(m, fm, fm_ld);
    return OI_OK;
}

/*
 * Fraction of the Moon's disc, seen from the point, that the Earth's solid
 * body does not hide and, with the atmosphere on, whose light the air along
 * the grazing lines of sight lets through (the disc taken as uniform). u_moon: unit vector from
 * the point to the Moon, dm its distance (> moon radius). 1 when the Earth's
 * centre is farther than the Moon's (the Moon in front), 0 when the Earth's
 * disc covers the Moon's.
 */
oi_real oi__moon_disc_visible(const oi_real point_km[3], const oi_real u_moon[3], oi_real dm,
                              const oi_model *m)
{
    oi_real anti[3], dp, re, rm, sep, frac;
    dp = oi__norm_bounded(point_km);
    if (dp >= dm) return (oi_real)1;
    anti[0] = -point_km[0] / dp;
    anti[1] = -point_km[1] / dp;
    anti[2] = -point_km[2] / dp;
    rm = apparent_radius(m->moon_radius_km, dm);
    sep = oi__angle_unit(u_moon, anti);
#ifndef OI_NO_OBLATE
    if (m->earth_shape == OI_EARTH_WGS84) {
        /* the ellipsoid: its silhouette's radius towards the Moon decides
         * the certain cases (a hundredth of the Moon's radius to spare), the
         * exact fraction behind it the others (src/shadow/oblate.c) */
        const oi_real margin = OI_R(0.01) * rm;
        re = oi__oblate_radius_towards(point_km, m->earth_radius_km, u_moon);
        if (sep >= re + rm + margin)
            frac = (oi_real)1;
        else if (sep <= re - rm - margin)
            frac = (oi_real)0;
        else if (rm <= OI_R(0.5))
            frac = oi__oblate_visible_earth(u_moon, rm, point_km, m->earth_radius_km, NULL);
        else
            (void)oi__disc_fractions(rm, re, sep, &frac, NULL);
    } else
#endif
    {
        re = apparent_radius(m->earth_radius_km, dp);
        (void)oi__disc_fractions(rm, re, sep, &frac, NULL);
    }
#ifndef OI_NO_ATMOSPHERE
    /* the air along the grazing lines of sight (src/shadow/atmosphere_moonlight.c;
     * with the ellipsoid, about its silhouette's radius towards the Moon) */
    if (!m->no_atmosphere) frac = oi__atm_moon_visible(dp, re, rm, sep, frac, m->earth_radius_km);
#endif
    return frac;
}

/* oi__moon_shadow's first tests alone (src/shadow/shadow_internal.h): 1 when it would
 * return OI_OK without reading or changing the shadow; 0 when not certain
 * (the point inside the Moon included: the full call returns its error).
 * Positions bounded by OI_POSITION_MAX_KM, as there. */
int oi__moon_shadow_none(const oi_real sun_km[3], const oi_real moon_km[3],
                         const oi_real point_km[3], const oi_model *m)
{
    oi_real u_sun[3], u_moon[3], ds, dm;
    oi__sub(moon_km, point_km, u_moon);
    oi__sub(sun_km, point_km, u_sun);
    dm = oi__dot(u_moon, u_moon);
    ds = oi__dot(u_sun, u_sun);
    if (!(dm > m->moon_radius_km * m->moon_radius_km)) return 0;
    if (dm >= ds) return 1;
    return discs_certainly_apart(u_sun, u_moon, ds, dm, m->sun_radius_km, m->moon_radius_km);
}

#endif /* OI_NO_MOON */
