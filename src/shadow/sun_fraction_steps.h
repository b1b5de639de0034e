/* SPDX-License-Identifier: MIT */
/* sun_fraction_steps.h: the steps of the Sun's visible fraction, as static
 * functions, for the two units that compose them: oi__sun_shadow and
 * oi_sun_fraction (src/shadow/sun_fraction.c) and the batch's
 * oi__sun_shadow_want (src/shadow/sun_fraction_want.c). Each unit inlines
 * the steps as it alone calls them, so the single call's code is not
 * changed by a second caller (the Sun-only flash budget, make size). A unit
 * defines OI_VECTOR_OUT_OF_LINE before it includes this header (oi__norm,
 * oi__finite3 out of line: the Sun-only build stays small). */
#ifndef OI_SUN_FRACTION_STEPS_H
#define OI_SUN_FRACTION_STEPS_H

#include "shadow/shadow_internal.h"
#include "shadow/sun_crescent.h"


/* a * a = hi + lo exactly (Dekker's product with oi__split, src/oi_vector.h). */
static void two_square(oi_real a, oi_real *hi, oi_real *lo)
{
    oi_real ah, al;
    oi__split(a, &ah, &al);
    *hi = a * a;
    *lo = ((ah * ah - *hi) + (oi_real)2 * ah * al) + al * al;
}

/*
 * q = |p|^2 - R^2 with a relative error of a few epsilon even when |p| is
 * within a few metres of R (then the plain difference of the rounded |p| and
 * R would keep only log10(h/R) fewer digits: at 1 m altitude 7 of 16 in
 * double, none in single precision). Used only when |p| < 2R, where the
 * squares cannot overflow.
 */
static oi_real radial_excess(const oi_real p[3], oi_real r)
{
    oi_real sh = (oi_real)0, sl = (oi_real)0, h, l, e, rh, rl;
    int i;
    for (i = 0; i < 3; ++i) {
        two_square(p[i], &h, &l);
        sh = oi__two_sum(sh, h, &e);
        sl += e + l;
    }
    two_square(r, &rh, &rl);
    /* sh and rh are within a factor 4 of each other: sh - rh is exact */
    return (sh - rh) + (sl - rl);
}

/* Apparent angular radius of a sphere of radius rad at distance dist > rad:
 * atan2(rad, sqrt((dist - rad)(dist + rad))), exact near grazing too. */
static oi_real apparent_radius(oi_real rad, oi_real dist)
{
    return OI_ATAN2(rad, OI_SQRT(dist - rad) * OI_SQRT(dist + rad));
}

/* Largest apparent solar radius for the ellipsoid's exact fraction (beyond,
 * an observer within 2.1 solar radii of the Sun's centre, the equivalent
 * sphere's). */
#define OBLATE_RS_MAX OI_R(0.5)

/* The geometry of one call: distances, and the two discs on the sky of the
 * point. */
typedef struct {
    oi_real dp;      /* |point| (km) */
    oi_real dsp;     /* |sun - point| (km) */
    oi_real q_earth; /* |point|^2 - R^2 near the surface (|point| < 2R), else -1 */
    oi_real sep;     /* angle between the Sun's and the Earth's centres (rad) */
    oi_real rs, re;  /* apparent radii of the Sun and the Earth (rad) */
#ifndef OI_NO_OBLATE
    oi_real s_hat[3]; /* unit vector from the point to the Sun (the ellipsoid) */
#endif
} sun_geom;

/* Step 1: the positions validated (the statuses of the contract, in order),
 * the distances and the separation formed. */
static int sun_geometry(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *m,
                        sun_geom *g)
{
    oi_real ds, rel[3], anti[3];
    if (!oi__finite3(sun_km) || !oi__finite3(point_km)) return OI_ERR_NONFINITE;
    ds = oi__norm(sun_km);
    g->dp = oi__norm(point_km);
    if (ds == (oi_real)0 || g->dp == (oi_real)0) return OI_ERR_ZERO_VECTOR;
#ifndef OI_NO_OBLATE
    if (m->earth_shape == OI_EARTH_WGS84) {
        /* the ellipsoid (src/shadow/oblate.c): its outside, and the plain forms,
         * whose squares stay finite for points within OI_POSITION_MAX_KM */
        if (g->dp > (oi_real)OI_POSITION_MAX_KM) return OI_ERR_GEOMETRY;
        if (!oi__oblate_outside(point_km, m->earth_radius_km)) return OI_ERR_BELOW_SURFACE;
        g->q_earth = (oi_real)-1;
    } else
#endif
    if (g->dp < (oi_real)2 * m->earth_radius_km) {
        /* near the surface: the sign of |p|^2 - R^2 decides, and its value
         * gives the Earth's apparent radius atan2(R, sqrt(|p|^2 - R^2)) */
        g->q_earth = radial_excess(point_km, m->earth_radius_km);
        if (!(g->q_earth > (oi_real)0)) return OI_ERR_BELOW_SURFACE;
    } else {
        g->q_earth = (oi_real)-1; /* far: the plain form is accurate */
    }
    if (ds <= m->sun_radius_km + m->earth_radius_km) return OI_ERR_GEOMETRY;
    if (!(ds < OI__HALF_REAL_MAX && g->dp < OI__HALF_REAL_MAX) &&
        !oi__sub_finite(sun_km, point_km))
        return OI_ERR_NONFINITE; /* sun - point overflows: found without forming it */
    oi__sub(sun_km, point_km, rel);
    if (!oi__finite3(rel)) return OI_ERR_NONFINITE;
    g->dsp = oi__norm(rel);
    if (!OI_ISFINITE(g->dsp) || !OI_ISFINITE(g->dp)) return OI_ERR_NONFINITE;
    if (g->dsp <= m->sun_radius_km) return OI_ERR_GEOMETRY;
    /* the angle between sun - point and -point from the unit vectors of the
     * norms just formed (oi_angle would form them again) */
    anti[0] = -point_km[0];
    anti[1] = -point_km[1];
    anti[2] = -point_km[2];
    (void)oi__divide3(anti, g->dp, anti);
    (void)oi__divide3(rel, g->dsp, rel);
    g->sep = oi__angle_unit(rel, anti);
#ifndef OI_NO_OBLATE
    memcpy(g->s_hat, rel, sizeof rel);
#endif
    return OI_OK;
}

/* Step 2: the apparent radii of the two discs (Note 1). */
static void apparent_radii(const oi_real point_km[3], const oi_model *m, sun_geom *g)
{
    g->rs = apparent_radius(m->sun_radius_km, g->dsp);
#ifndef OI_NO_OBLATE
    /* the ellipsoid: its silhouette's angular radius along the great circle
     * from the nadir towards the Sun (the equivalent sphere's) */
    if (m->earth_shape == OI_EARTH_WGS84) {
        g->re = oi__oblate_radius_towards(point_km, m->earth_radius_km, g->s_hat);
        return;
    }
#else
    (void)point_km;
#endif
    g->re = g->q_earth > (oi_real)0 ? OI_ATAN2(m->earth_radius_km, OI_SQRT(g->q_earth))
                                    : apparent_radius(m->earth_radius_km, g->dp);
}

/* The penumbra's uniform-disc fraction. hs: the sines of the triangle (Sun's
 * centre, Earth's centre, a crossing point of the limbs) are written there;
 * *pa_s = pi - a_s, a_s its angle at the Sun's centre. */
static oi_real crescent_fraction(oi_real rs, oi_real re, oi_real sep, oi_real ssun, oi_real hs[4],
                                 oi_real *pa_s)
{
    oi_real a_e, lens;
    /* a_e at the Earth's centre, pi - a_s at the Sun's, from one set of sines */
    oi__half_sines(rs, re, sep, hs);
    a_e = oi__half_angle(hs, 1, 0);
    *pa_s = oi__half_angle(hs, 2, 1);
    if (rs < (oi_real)1) {
        /* the visible part of the Sun's cap directly, as the Sun's segment
         * beyond the chord of the two crossing points minus the Earth's
         * segment (no 1 - overlap/area: keeps the relative accuracy of a thin
         * crescent next to the umbra) */
        return (oi__cap_segment(rs, *pa_s) - oi__cap_segment(re, a_e)) /
               ((oi_real)4 * OI_PI_R * ssun);
    }
    /* a Sun of 1 rad or more (an observer within 0.19 solar radii of its
     * surface): Gauss-Bonnet on the lens, as in oi_cap_overlap,
     * 2 (pi - gamma) - 2 a_s cos rs - 2 a_e cos re (gamma the angle at the
     * crossing point; the chord decomposition degenerates when both limbs
     * approach great circles); absolute error a few eps */
    lens = (oi_real)2 * (oi__half_angle(hs, 3, 1) - oi__half_angle(hs, 2, 0) * OI_COS(rs) -
                         a_e * OI_COS(re));
    return (oi_real)1 - lens / ((oi_real)4 * OI_PI_R * ssun);
}

/* Out of line where the ellipsoid's quadrature follows (make stack); in
 * line without it (the Sun-only build's flash, make size). */
#ifndef OI_NO_OBLATE
#define GEOMETRIC_FRAME OI_NOINLINE
#else
#define GEOMETRIC_FRAME
#endif

/* eclipse_fraction forms the limb-darkened integral: wanted (need_ld,
 * frac_ld not NULL) and the Sun's radius rs within (OI_LD_RS_MIN,
 * OI_LD_RS_MAX] (beyond, an observer within 2.1 solar radii of the Sun's
 * centre, or below 1e-15 rad, the uniform disc stands in). */
static int ld_formed(int need_ld, oi_real rs, const oi_real *frac_ld)
{
#ifdef OI_NO_LIMB_DARKENING
    (void)need_ld;
    (void)rs;
    (void)frac_ld;
    return 0;
#else
    return need_ld && frac_ld != NULL && rs <= OI_LD_RS_MAX && rs > OI_LD_RS_MIN;
#endif
}

/* Step 3, the discs overlapping (penumbra or annular): the region, and the
 * visible fractions of the uniform and the limb-darkened disc (Notes 1-3);
 * out of line with the ellipsoid: not in the frame that calls the
 * geometry's steps.
 * rs: the Sun's apparent radius, re: the occulter's, sep: their separation;
 * need_ld = 0 leaves the limb-darkened integral out (frac_ld = frac);
 * frac_ld may be NULL; crescent: NULL, or the penumbra's uniform fraction
 * already formed (the crescent kernel's, src/shadow/sun_crescent.h), which then
 * stands for the angle-based crescent's: of that only the triangle the
 * limb-darkened integral reads is solved, where it is formed. */
static GEOMETRIC_FRAME int eclipse_fraction(oi_real rs, oi_real re, oi_real sep, int need_ld,
                                            const oi_real *crescent, oi_real *frac,
                                            oi_real *frac_ld)
{
    oi_real ssun = oi__sin_half_sq(rs);
    oi_real pa_s = OI_PI_R; /* pi - alpha_s; pi when annular */
    oi_real hs[4];          /* the triangle's sines (penumbra) */
    const oi_real *tri = NULL;
    int region;
    if (sep <= rs - re) {
        /* 1 - sin^2(re/2)/sin^2(rs/2), the difference of squares factored:
         * sin((rs - re)/2) sin((rs + re)/2) */
        region = OI_SHADOW_ANNULAR;
        *frac = OI_SIN(OI_R(0.5) * (rs - re)) * OI_SIN(OI_R(0.5) * (rs + re)) / ssun;
    } else {
        region = OI_SHADOW_PENUMBRA;
#ifdef OI_CRESCENT_KERNEL
        if (crescent != NULL) {
            *frac = *crescent;
            if (ld_formed(need_ld, rs, frac_ld)) {
                tri = hs;
                oi__half_sines(rs, re, sep, hs);
                pa_s = oi__half_angle(hs, 2, 1);
            }
        } else
#else
        (void)crescent; /* NULL: the single-precision build has no kernel */
#endif
        {
            tri = hs;
            *frac = crescent_fraction(rs, re, sep, ssun, hs, &pa_s);
        }
    }
    *frac = oi__clamp(*frac, (oi_real)0, (oi_real)1);
    if (frac_ld != NULL) *frac_ld = *frac;
    if (ld_formed(need_ld, rs, frac_ld)) {
#ifndef OI_NO_LIMB_DARKENING
        *frac_ld = oi__fraction_limb_darkened(rs, re, sep, pa_s, tri);
#endif
    }
#ifdef OI_NO_LIMB_DARKENING
    (void)pa_s; /* the limb-darkened disc is compiled out: frac_ld = frac */
    (void)tri;
#endif
    return region;
}

/* The region and the visible fractions of a disc of apparent radius rs
 * behind a nearer disc of radius re, centres sep apart; crescent as in
 * eclipse_fraction. */
static int disc_fractions(oi_real rs, oi_real re, oi_real sep, int need_ld,
                          const oi_real *crescent, oi_real *frac, oi_real *frac_ld)
{
    if (sep >= re + rs) {
        *frac = (oi_real)1;
        if (frac_ld != NULL) *frac_ld = (oi_real)1;
        return OI_SHADOW_LIT;
    }
    if (sep <= re - rs) {
        *frac = (oi_real)0;
        if (frac_ld != NULL) *frac_ld = (oi_real)0;
        return OI_SHADOW_UMBRA;
    }
    return eclipse_fraction(rs, re, sep, need_ld, crescent, frac, frac_ld);
}

#ifdef OI_CRESCENT_KERNEL
/* disc_fractions' region is OI_SHADOW_PENUMBRA: |re - rs| < sep < re + rs. */
static int discs_in_penumbra(oi_real rs, oi_real re, oi_real sep)
{
    return sep < re + rs && sep > re - rs && sep > rs - re;
}
#endif


#ifndef OI_NO_OBLATE
/* The ellipsoid's shadow (docs/shadow.md section 10): the equivalent
 * sphere's region and fractions (the silhouette's radius along the great
 * circle towards the Sun), and where the Sun's disc comes within a hundredth
 * of its radius of that sphere's edges the exact visible fraction of the
 * uniform and the limb-darkened disc behind the elliptic silhouette
 * (oblate_exact). The region follows the exact fraction. 1 when the exact
 * fractions are wanted. */
static int oblate_wants_exact(const sun_geom *g)
{
    const oi_real margin = OI_R(0.01) * g->rs;
    return !(g->dp >= g->dsp || !(g->rs <= OBLATE_RS_MAX) || g->sep >= g->re + g->rs + margin ||
             g->sep <= g->re - g->rs - margin);
}

/* The exact fractions behind the ellipsoid of equatorial radius a
 * (src/shadow/oblate.c) in place of the equivalent sphere's in *out. Called once
 * the geometry's frame is gone (make stack): the unit vector to the Sun is
 * formed again by the operations of sun_geometry, from the distance it kept
 * in *out. */
static OI_NOINLINE void oblate_exact(const oi_real sun_km[3], const oi_real point_km[3], oi_real a,
                                     oi_shadow *out)
{
    oi_real s_hat[3], exact;
    oi__sub(sun_km, point_km, s_hat);
    (void)oi__divide3(s_hat, out->sun_distance_km, s_hat);
    exact = oi__oblate_visible_earth(s_hat, out->sun_radius_rad, point_km, a, &out->fraction_ld);
    out->fraction = exact;
    if (exact == (oi_real)1) {
        out->fraction_ld = (oi_real)1;
        out->region = OI_SHADOW_LIT;
    } else if (exact == (oi_real)0) {
        out->fraction_ld = (oi_real)0;
        out->region = OI_SHADOW_UMBRA;
    } else if (out->region != OI_SHADOW_ANNULAR) {
        out->region = OI_SHADOW_PENUMBRA;
    }
}
#endif

/* shadow_geometric's value when the ellipsoid's exact fraction is to
 * replace the equivalent sphere's (oblate_exact); no status is positive there */
#define GEOMETRIC_WANTS_EXACT 1

/* shadow_discs' flags: the Earth behind the Sun (a point beyond the Sun:
 * whenever the discs overlap the three bodies are nearly collinear, so the
 * nearer one is in front), and the ellipsoid's exact fraction wanted. */
#define DISCS_BEHIND 1
#define DISCS_WANT_EXACT 2

/* Steps 1-2: *out zeroed, then the two discs' radii, their separation and
 * the Sun's distance written there. Returns an error status of
 * sun_geometry or the DISCS_* flags (>= 0). Out of line with the
 * ellipsoid: the geometry's frame is not live during step 3. */
static GEOMETRIC_FRAME int shadow_discs(const oi_real sun_km[3], const oi_real point_km[3],
                                        const oi_model *m, oi_shadow *out)
{
    sun_geom g;
    int st;
    memset(out, 0, sizeof *out);
    st = sun_geometry(sun_km, point_km, m, &g);
    if (st != OI_OK) return st;
    apparent_radii(point_km, m, &g);
    out->earth_radius_rad = g.re;
    out->sun_radius_rad = g.rs;
    out->separation_rad = g.sep;
    out->sun_distance_km = g.dsp;
    st = g.dp >= g.dsp ? DISCS_BEHIND : 0;
#ifndef OI_NO_OBLATE
    if (m->earth_shape == OI_EARTH_WGS84 && oblate_wants_exact(&g)) st |= DISCS_WANT_EXACT;
#endif
    return st;
}

/* Steps 1-3: *out zeroed, then everything but fraction_atm (the sphere's,
 * or the ellipsoid's equivalent sphere's, fractions; the region, Note 2).
 * Returns OI_OK, GEOMETRIC_WANTS_EXACT or an error status of sun_geometry.
 * Out of line with the ellipsoid: the geometry's frame is not live during
 * the later steps. */
static GEOMETRIC_FRAME int shadow_geometric(const oi_real sun_km[3], const oi_real point_km[3],
                                        const oi_model *m, int need_ld, oi_shadow *out)
{
    const int st = shadow_discs(sun_km, point_km, m, out);
    if (st < 0) return st;
    if (st & DISCS_BEHIND) {
        out->fraction = out->fraction_ld = (oi_real)1;
        out->region = OI_SHADOW_LIT;
    } else {
        const oi_real *crescent = NULL;
#ifdef OI_CRESCENT_KERNEL
        /* the sphere's penumbra: the batch's branch-free crescent (src/shadow/sun_crescent.h) */
        oi_real kernel;
        if (m->earth_shape == OI_EARTH_SPHERE &&
            discs_in_penumbra(out->sun_radius_rad, out->earth_radius_rad, out->separation_rad)) {
            int in_domain;
            kernel = oi__crescent_fraction(sun_km, point_km, m->earth_radius_km,
                                           m->sun_radius_km, &in_domain);
            if (in_domain) crescent = &kernel;
        }
#endif
        out->region = disc_fractions(out->sun_radius_rad, out->earth_radius_rad,
                                     out->separation_rad, need_ld, crescent, &out->fraction,
                                     &out->fraction_ld);
    }
    return (st & DISCS_WANT_EXACT) ? GEOMETRIC_WANTS_EXACT : OI_OK;
}

#if !defined(OI_NO_OBLATE) && !defined(OI_NO_ATMOSPHERE)
/* The atmosphere over the ellipsoid: the table's coordinates about the
 * equivalent sphere, the one of the silhouette's angular radius towards the
 * Sun (out->earth_radius_rad, already set), radius |point| sin(r_e): the
 * grazing rays' heights are measured above the ellipsoid's limb there.
 * The geometric fractions are read from *out after the sine (none kept in
 * registers across the call). */
static OI_NOINLINE int oblate_atmosphere(const oi_real sun_km[3], const oi_real point_km[3],
                                         const oi_model *m, oi_shadow *out, oi_real light_dir[3])
{
    const oi_real radius = oi__norm_bounded(point_km) * OI_SIN(out->earth_radius_rad);
    return oi__atm_fraction_about(sun_km, point_km, m, radius, out->fraction, out->fraction_ld,
                                  &out->fraction_atm, light_dir);
}
#endif

/* Step 4, the atmosphere (Note 5): the single place where refraction and
 * extinction modify the sunlight reaching the point; without it the
 * model's choice of disc, uniform or limb-darkened (out->fraction,
 * out->fraction_ld). */
static int atmosphere_fraction(const oi_real sun_km[3], const oi_real point_km[3],
                               const oi_model *m, oi_shadow *out, oi_real light_dir[3])
{
    out->fraction_atm = m->limb_darkening == OI_LIMB_DARKENED ? out->fraction_ld : out->fraction;
#ifdef OI_NO_ATMOSPHERE
    (void)sun_km;
    (void)point_km;
    (void)light_dir;
    return OI_OK;
#else
    /* src/shadow/atmosphere.c: refraction and extinction from the baked table;
     * OI_WARN_TABLE_RANGE outside its z range (geometric kept). */
    if (m->no_atmosphere) return OI_OK;
#ifndef OI_NO_OBLATE
    if (m->earth_shape == OI_EARTH_WGS84)
        return oblate_atmosphere(sun_km, point_km, m, out, light_dir);
#endif
    return oi__atm_fraction(sun_km, point_km, m, out->fraction, out->fraction_ld,
                            &out->fraction_atm, light_dir);
#endif
}


#endif /* OI_SUN_FRACTION_STEPS_H */
