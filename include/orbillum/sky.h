/* SPDX-License-Identifier: MIT */
/*
 * orbillum/sky.h: the sky behind the target: the zodiacal light, the
 * integrated starlight, the galactic coordinates of a direction (removed by
 * OI_NO_SKY).
 *
 * A section of orbillum.h, the header a program includes (it includes every
 * section); compiles alone, and includes the sections it uses.
 */
#ifndef ORBILLUM_SKY_H
#define ORBILLUM_SKY_H

#include "base.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- sky */
#ifndef OI_NO_SKY
/*
 * oi_zodiacal_radiance: radiance of the zodiacal light seen from the Earth
 * (W/m^2/sr, as sunlight over the whole spectrum, the convention of
 * oi_expose_in.background_w_m2_sr) in the direction at ecliptic longitude
 * dlambda_rad from the Sun's and ecliptic latitude beta_rad.
 * Given:   dlambda_rad  any finite value (taken modulo 2 pi; the sign does
 *                       not matter); beta_rad: the sign does not matter,
 *                       |beta| above pi/2 is taken as pi/2
 * Returns: the radiance; 0 for a non-finite argument.
 * Notes:   Leinert et al. 1998 (A&AS 127, 1), Table 17 at 500 nm, bilinear
 *          between its nodes, converted to a whole-spectrum radiance with
 *          the 5772 K solar spectrum (7.6353e-9 W/m^2/sr per table unit).
 *          The table has no entries within ~15 deg of the Sun: those cells
 *          hold the nearest tabulated value of their latitude (a lower
 *          bound). src/camera/zodiacal.c, docs/camera.md.
 */
oi_real oi_zodiacal_radiance(oi_real dlambda_rad, oi_real beta_rad);

/*
 * oi_starlight_radiance: radiance of the integrated starlight (W/m^2/sr, as
 * sunlight over the whole spectrum, as oi_zodiacal_radiance) in the
 * direction at galactic longitude l_rad and latitude b_rad.
 * Given:   l_rad  any finite value (taken modulo 2 pi); b_rad: |b| above
 *                 pi/2 is taken as pi/2
 * Returns: the radiance; 0 for a non-finite argument.
 * Notes:   Leinert et al. 1998 (A&AS 127, 1), Table 35: the Pioneer 10 map at
 *          440 nm (Toller 1981) of the stars fainter than V ~ 6.5 and the
 *          diffuse galactic light, in S10_sun on a 10 deg x 4-10 deg grid,
 *          bilinear between its nodes; 8.9971e-9 W/m^2/sr per S10_sun (a
 *          V = 10 Sun per square degree). Beyond |b| = 80 deg, linear to the
 *          mean of the 80 deg row at the pole; 28 cells Pioneer did not map
 *          hold the interpolation of their row. src/camera/starlight.c,
 *          docs/camera.md.
 */
oi_real oi_starlight_radiance(oi_real l_rad, oi_real b_rad);

/*
 * oi_galactic_from_icrs: galactic longitude and latitude of a direction
 * given in ICRS (ICRF/GCRS-aligned) components, the frame of oi_scene.
 * Given:   dir    the direction, any finite nonzero length
 * Returns: OI_OK; OI_ERR_NULL (a NULL pointer), OI_ERR_NONFINITE (a
 *          component NaN/inf), OI_ERR_ZERO_VECTOR (dir is 0): then the
 *          outputs are 0.
 * Outputs: *l_rad in [0, 2 pi), *b_rad in [-pi/2, pi/2].
 * Notes:   the rotation of the Hipparcos catalogue (ESA SP-1200, 1997,
 *          Vol. 1, Sect. 1.5.3): north galactic pole at RA 192.85948 deg,
 *          Dec 27.12825 deg, ascending node at l = 32.93192 deg.
 *          src/camera/galactic.c.
 */
int oi_galactic_from_icrs(const oi_real dir[3], oi_real *l_rad, oi_real *b_rad);
#endif

#ifdef __cplusplus
}
#endif

#endif /* ORBILLUM_SKY_H */
