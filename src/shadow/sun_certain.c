/* SPDX-License-Identifier: MIT */
/* sun_certain.c: oi__sun_certain_region, the regions of the Sun a point is
 * certainly in, decided from cosines (src/shadow/shadow_internal.h); the
 * batches (src/batch/batch.c) and the scene batch's Sun term
 * (src/scene/illuminate_outputs.c) answer those points without the
 * shadow's angles. */
#include "shadow/shadow_internal.h"

/*
 * OI__ROW_LIT or OI__ROW_UMBRA when the point certainly is in that region, decided
 * from cosines alone; OI__ROW_UNSURE otherwise (the full call follows). A row is
 * decided only when every check of the full call's geometry (sun_geometry in
 * src/shadow/sun_fraction.c) passes, formed the same way, so its status is OI_OK:
 * finite, |point| > 1.001 R (|point|^2 - R^2 >= 0.002 R^2, far beyond the
 * rounding of the full call's compensated form: not below the surface),
 * |sun| > R_sun + R, sun - point finite, |sun - point| > R_sun. Both
 * apparent radii are below pi/2 (sines below 1), so their sum is below pi
 * and the comparison of cosines is the comparison of angles. LIT: the angle between the
 * Sun's centre and the Earth's anti-centre exceeds the sum of the radii of
 * the Sun and of the Earth enlarged by OI__GRAZING_TOP_KM (outside the
 * atmosphere's window too: its fraction is then 1, src/scene/illuminate_terms.h's
 * certainly_lit). UMBRA (only asked without the atmosphere, which lights
 * the umbra): the Sun's disc inside the Earth's, sep + r_sun < r_earth (for
 * the ellipsoid, its inner sphere's: the polar radius).
 */
int oi__sun_certain_region(const oi_real sun[3], const oi_real p[3], const oi_model *m,
                           int umbra_too)
{
    oi_real ds, dp, dsp, rel[3], sin_e, sin_s, cos_e, cos_s, cos_sep, sin_sep, sin_r, cos_r;
    if (!oi__finite3(sun) || !oi__finite3(p)) return OI__ROW_UNSURE;
    ds = oi__norm(sun);
    dp = oi__norm(p);
    /* (beyond OI_POSITION_MAX_KM the ellipsoid's call refuses the point) */
    if (!(dp > OI_R(1.001) * m->earth_radius_km) || !(dp <= (oi_real)OI_POSITION_MAX_KM))
        return OI__ROW_UNSURE;
    if (!(ds > m->sun_radius_km + m->earth_radius_km)) return OI__ROW_UNSURE;
    /* the full call's test of sun - point, in its form (sun_geometry) */
    if (!(ds < OI__HALF_REAL_MAX && dp < OI__HALF_REAL_MAX) && !oi__sub_finite(sun, p))
        return OI__ROW_UNSURE;
    oi__sub(sun, p, rel);
    if (!oi__finite3(rel)) return OI__ROW_UNSURE;
    dsp = oi__norm(rel);
    if (!OI_ISFINITE(dsp) || !(dsp > m->sun_radius_km)) return OI__ROW_UNSURE;
    /* the Earth behind the Sun is LIT in the full call too, but rare: left to it */
    sin_s = m->sun_radius_km / dsp;
    if (!(sin_s < (oi_real)1)) return OI__ROW_UNSURE;
    cos_s = OI_SQRT(((oi_real)1 - sin_s) * ((oi_real)1 + sin_s));
    cos_sep = -oi__dot(rel, p) / dsp / dp;
    if (!OI_ISFINITE(cos_sep)) return OI__ROW_UNSURE;
    sin_e = (m->earth_radius_km + OI__GRAZING_TOP_KM) / dp;
    if (sin_e < (oi_real)1) {
        cos_e = OI_SQRT(((oi_real)1 - sin_e) * ((oi_real)1 + sin_e));
        if (cos_sep < cos_e * cos_s - sin_e * sin_s - OI__CERTAIN_COS_MARGIN) return OI__ROW_LIT;
    }
    if (!umbra_too) return OI__ROW_UNSURE;
    /* cos(sep + r_sun) > cos(r_earth) + margin: sep + r_sun < r_earth <= pi/2
     * (the ellipsoid's silhouette holds its inner sphere's, the polar radius) */
    sin_r = oi__umbra_radius(m) / dp;
    cos_r = OI_SQRT(((oi_real)1 - sin_r) * ((oi_real)1 + sin_r));
    sin_sep = OI_SQRT(oi__clamp(((oi_real)1 - cos_sep) * ((oi_real)1 + cos_sep), (oi_real)0,
                                (oi_real)1));
    if (cos_sep > (oi_real)0 && cos_sep * cos_s - sin_sep * sin_s > cos_r + OI__CERTAIN_COS_MARGIN)
        return OI__ROW_UMBRA;
    return OI__ROW_UNSURE;
}
