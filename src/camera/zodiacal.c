/* SPDX-License-Identifier: MIT */
/*
 * zodiacal.c: the zodiacal light's radiance by direction relative to the
 * Sun, from the published table of Leinert et al. (1998), held here as a
 * cited const table (docs/camera.md, "Sky background").
 *
 * The table is measured data, 19 x 11 published numbers on an irregular
 * grid: there is nothing to compute, so it is not baked through the table
 * family (include/oi_table.h, whose tables are computed grids with their
 * own generator and check); a generator would only copy these numbers.
 */
#include "camera/camera_internal.h"

#ifndef OI_NO_SKY

/*
 * Leinert C. et al., "The 1997 reference of diffuse night sky brightness",
 * Astron. Astrophys. Suppl. Ser. 127, 1-99 (1998), Table 17: zodiacal light
 * seen from the Earth at 500 nm, in 1e-8 W m^-2 sr^-1 um^-1, by the
 * difference of ecliptic longitude from the Sun (rows: 0, 5, .., 45, then
 * 60, 75, .., 180 deg) and the ecliptic latitude (columns: 0, 5, .., 30,
 * then 45, 60, 75, 90 deg). The published table has no entry within about
 * 15 deg of the Sun (the cells of rows 0-10 deg, columns 0-10 deg); those
 * cells hold the first tabulated value below them in the same column
 * (marked "fill"), a lower bound of the real brightness, which rises
 * towards the Sun.
 */
#define ZL_ROWS 19
#define ZL_COLS 11
static const unsigned short zl_table[ZL_ROWS][ZL_COLS] = {
    /* 0 */   { 11500, 6780, 4740, 3140, 1610, 985, 640, 275, 150, 100, 77 }, /* fill 0-10 */
    /* 5 */   { 11500, 6780, 4740, 2940, 1540, 945, 625, 271, 150, 100, 77 }, /* fill 0-10 */
    /* 10 */  { 11500, 6780, 4740, 2470, 1370, 865, 590, 264, 148, 100, 77 }, /* fill 0-5 */
    /* 15 */  { 11500, 6780, 3440, 1860, 1110, 755, 525, 251, 146, 100, 77 },
    /* 20 */  { 6400, 4480, 2410, 1410, 910, 635, 454, 237, 141, 99, 77 },
    /* 25 */  { 3840, 2830, 1730, 1100, 749, 545, 410, 223, 136, 97, 77 },
    /* 30 */  { 2480, 1870, 1220, 845, 615, 467, 365, 207, 131, 95, 77 },
    /* 35 */  { 1650, 1270, 910, 680, 510, 397, 320, 193, 125, 93, 77 },
    /* 40 */  { 1180, 940, 700, 530, 416, 338, 282, 179, 120, 92, 77 },
    /* 45 */  { 910, 730, 555, 442, 356, 292, 250, 166, 116, 90, 77 },
    /* 60 */  { 505, 442, 352, 292, 243, 209, 183, 134, 104, 86, 77 },
    /* 75 */  { 338, 317, 269, 227, 196, 172, 151, 116, 93, 82, 77 },
    /* 90 */  { 259, 251, 225, 193, 166, 147, 132, 104, 86, 79, 77 },
    /* 105 */ { 212, 210, 197, 170, 150, 133, 119, 96, 82, 77, 77 },
    /* 120 */ { 188, 186, 177, 154, 138, 125, 113, 90, 77, 74, 77 },
    /* 135 */ { 179, 178, 166, 147, 134, 122, 110, 90, 77, 73, 77 },
    /* 150 */ { 179, 178, 165, 148, 137, 127, 116, 96, 79, 72, 77 },
    /* 165 */ { 196, 192, 179, 165, 151, 141, 131, 104, 82, 72, 77 },
    /* 180 */ { 230, 212, 195, 178, 163, 148, 134, 105, 83, 72, 77 }
};

/* One table unit (1e-8 W m^-2 sr^-1 um^-1 at 500 nm) as the radiance of
 * sunlight over the whole spectrum (W m^-2 sr^-1): 1e-8 / s500, with s500 =
 * 1.3097021 um^-1 = pi B(500 nm) / (sigma T^4), the solar spectral irradiance at
 * 500 nm over the total, in closed form (mpmath, 30 digits) for
 * the 5772 K Planck spectrum that gives the cameras' band fraction
 * (docs/camera.md). The zodiacal light is then treated as sunlight, as the
 * camera treats every source (grey): Leinert et al. 1998, Sect. 8, find its
 * colour solar within a moderate reddening from 0.2 to 2 um. */
#define ZL_UNIT_W_M2_SR OI_R(7.6353241345209276e-09)

/* Grid position of x (degrees, clamped to [0, top]) on nodes spaced 5 deg
 * up to knee (index knee / 5), then 15 deg up to top: the index of the cell
 * (0 .. n - 2) and the fraction in it. */
static int grid_cell(oi_real x, oi_real knee, int n, oi_real *frac)
{
    const oi_real top = knee + OI_R(15.0) * (oi_real)(n - 1 - (int)(knee / OI_R(5.0)));
    oi_real u;
    int i;
    x = oi__clamp(x, 0, top);
    if (x < knee) {
        u = x / OI_R(5.0);
    } else {
        u = knee / OI_R(5.0) + (x - knee) / OI_R(15.0);
    }
    i = (int)u;
    if (i > n - 2) i = n - 2;
    *frac = u - (oi_real)i;
    return i;
}

/*
 * oi_zodiacal_radiance: the contract is in include/orbillum.h.
 * Bilinear interpolation in the table (linear in the brightness: no log or
 * exp on the way); the table is symmetric in the sign of both angles
 * (Leinert et al. 1998 tabulate one quadrant).
 */
oi_real oi_zodiacal_radiance(oi_real dlambda_rad, oi_real beta_rad)
{
    const oi_real deg = (oi_real)OI_DEG_PER_RAD;
    oi_real dl, b, fl, fb, v0, v1;
    int i, j;
    if (!OI_ISFINITE(dlambda_rad) || !OI_ISFINITE(beta_rad)) return 0;
    dl = OI_FABS(dlambda_rad);
    /* beyond 1e30 rad reduced in radians first and |beta| beyond 4 rad taken
     * as 4 (the same clamped cell): no product overflows (any other angle:
     * the bits of earlier versions) */
    if (dl > OI_R(1e30)) dl = OI_FABS(dl - OI_R(6.283185307179586) * OI_FLOOR(dl / OI_R(6.283185307179586)));
    dl *= deg;
    b = OI_FABS(beta_rad) > OI_R(4.0) ? OI_R(4.0) * deg : OI_FABS(beta_rad) * deg;
    dl -= OI_R(360.0) * OI_FLOOR(dl / OI_R(360.0)); /* [0, 360) */
    if (dl > OI_R(180.0)) dl = OI_R(360.0) - dl;
    i = grid_cell(dl, OI_R(45.0), ZL_ROWS, &fl);
    j = grid_cell(b, OI_R(30.0), ZL_COLS, &fb);
    v0 = (oi_real)zl_table[i][j] + fb * ((oi_real)zl_table[i][j + 1] - (oi_real)zl_table[i][j]);
    v1 = (oi_real)zl_table[i + 1][j] +
         fb * ((oi_real)zl_table[i + 1][j + 1] - (oi_real)zl_table[i + 1][j]);
    return (v0 + fl * (v1 - v0)) * ZL_UNIT_W_M2_SR;
}

#endif /* OI_NO_SKY */
