/* SPDX-License-Identifier: MIT */
/*
 * galactic.c: galactic longitude and latitude of a direction given in the
 * ICRS (the frame every position of this runtime is taken in), by the
 * rotation of the Hipparcos catalogue's definition (docs/camera.md, "Sky
 * background").
 */
#include "camera/camera_internal.h"

#ifndef OI_NO_SKY

/*
 * ESA, The Hipparcos and Tycho Catalogues, ESA SP-1200 (1997), Vol. 1,
 * Sect. 1.5.3: the galactic frame in the ICRS is fixed by the north
 * galactic pole at right ascension 192.85948 deg, declination 27.12825 deg,
 * and the galactic longitude 32.93192 deg of the ascending node of the
 * galactic plane on the equator. The rows below are the galactic x (towards
 * l = 0, b = 0), y (l = 90 deg) and z (the pole) axes in ICRS components,
 * evaluated from those three angles in closed form (30 digits, mpmath;
 * tests/python/test_starlight.py recomputes them and checks the rotation
 * against astropy's Galactic frame). They are the matrix A_G of that
 * section, transposed.
 */
static const oi_real icrs_to_gal[3][3] = {
    { OI_R(-0.054875560416215368), OI_R(-0.87343709023488505), OI_R(-0.48383501554871323) },
    { OI_R(0.49410942787558367), OI_R(-0.44482962996001118), OI_R(0.74698224449721889) },
    { OI_R(-0.8676661490190047), OI_R(-0.19807637343120153), OI_R(0.45598377617506692) }
};

/* oi_galactic_from_icrs: the contract is in include/orbillum.h. */
int oi_galactic_from_icrs(const oi_real dir[3], oi_real *l_rad, oi_real *b_rad)
{
    oi_real u[3], g[3], l;
    int i;
    if (l_rad != NULL) *l_rad = 0;
    if (b_rad != NULL) *b_rad = 0;
    if (dir == NULL || l_rad == NULL || b_rad == NULL) return OI_ERR_NULL;
    if (!oi__finite3(dir)) return OI_ERR_NONFINITE;
    if (!(oi__unit(dir, u) > 0)) return OI_ERR_ZERO_VECTOR;
    for (i = 0; i < 3; i++) g[i] = oi__dot(icrs_to_gal[i], u);
    l = OI_ATAN2(g[1], g[0]);
    if (l < 0) l += OI_R(2.0) * OI_PI_R;
    if (!(l < OI_R(2.0) * OI_PI_R)) l = 0; /* -tiny + 2 pi rounds to 2 pi */
    *l_rad = l;
    *b_rad = OI_ATAN2(g[2], OI_SQRT(g[0] * g[0] + g[1] * g[1]));
    return OI_OK;
}

#endif /* OI_NO_SKY */
