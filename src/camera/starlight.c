/* SPDX-License-Identifier: MIT */
/*
 * starlight.c: the integrated starlight's radiance by galactic direction,
 * from the published Pioneer 10 map (Leinert et al. 1998, Table 35), held
 * here as a cited const table (docs/camera.md, "Sky background").
 *
 * Measured data on a published grid, as the zodiacal light's table
 * (src/camera/zodiacal.c): nothing to compute, so not baked through the table
 * family.
 */
#include "camera/camera_internal.h"

#ifndef OI_NO_SKY

/*
 * Leinert C. et al., "The 1997 reference of diffuse night sky brightness",
 * Astron. Astrophys. Suppl. Ser. 127, 1-99 (1998), Sect. 10, Table 35:
 * Pioneer 10 background starlight in blue (440 nm) from Toller (1981), in
 * S10_sun (stars of the Sun's colour and V = 10 per square degree), by
 * galactic latitude (rows: -80, -70, .., -30, -24, -20, .., +24, +30, .., +80
 * deg) and longitude (columns: 0, 10, .., 350 deg). Taken beyond 2.8 AU,
 * where the zodiacal light is not detected: it holds the stars fainter than
 * about V = 6.5 (the brighter ones were removed) and the diffuse galactic
 * light. Pioneer did not map 28 cells (l 180-240 deg, b +16..+50 deg,
 * marked "fill"): they hold the linear interpolation in longitude between
 * the nearest mapped cells of their row, rounded to the nearest unit.
 */
#define ISL_ROWS 25
#define ISL_COLS 36
static const signed char isl_lat_deg[ISL_ROWS] = {
    -80, -70, -60, -50, -40, -30, -24, -20, -16, -12, -8, -4, 0,
    4, 8, 12, 16, 20, 24, 30, 40, 50, 60, 70, 80
};
static const unsigned short isl_table[ISL_ROWS][ISL_COLS] = {
    /* -80 */ { 34, 32, 30, 32, 29, 33, 35, 31, 28, 34, 31, 26, 26, 30, 27, 26, 27, 30, 33, 32, 28, 26, 26, 27, 27, 27, 28, 29, 28, 29, 29, 25, 25, 28, 28, 30 },
    /* -70 */ { 32, 28, 33, 35, 39, 32, 32, 34, 35, 31, 24, 34, 33, 30, 30, 36, 33, 32, 32, 32, 30, 30, 32, 30, 26, 26, 33, 29, 26, 25, 32, 29, 29, 31, 34, 35 },
    /* -60 */ { 39, 41, 41, 39, 37, 35, 41, 46, 36, 33, 35, 35, 32, 34, 35, 35, 43, 34, 36, 34, 31, 30, 33, 36, 37, 38, 33, 38, 42, 45, 42, 40, 38, 35, 36, 32 },
    /* -50 */ { 45, 48, 49, 43, 47, 49, 39, 46, 41, 43, 39, 37, 36, 41, 45, 42, 40, 44, 40, 45, 42, 39, 43, 38, 38, 40, 41, 40, 39, 44, 43, 50, 48, 38, 45, 51 },
    /* -40 */ { 56, 68, 53, 57, 63, 56, 57, 63, 46, 46, 48, 44, 48, 45, 41, 46, 47, 46, 51, 50, 56, 48, 52, 46, 42, 47, 52, 55, 58, 55, 68, 58, 62, 59, 61, 58 },
    /* -30 */ { 78, 87, 76, 77, 80, 88, 68, 71, 64, 60, 65, 73, 53, 67, 64, 57, 60, 61, 67, 65, 70, 74, 69, 57, 63, 66, 85, 81, 213, 68, 73, 78, 74, 85, 81, 82 },
    /* -24 */ { 99, 111, 96, 89, 90, 88, 91, 84, 81, 87, 80, 74, 83, 84, 78, 81, 69, 77, 67, 77, 97, 122, 91, 79, 91, 86, 113, 95, 87, 94, 94, 97, 103, 101, 108, 114 },
    /* -20 */ { 120, 133, 124, 105, 101, 124, 105, 94, 103, 105, 93, 95, 108, 97, 95, 78, 84, 79, 53, 90, 119, 122, 109, 109, 106, 101, 115, 119, 116, 107, 103, 116, 135, 130, 133, 156 },
    /* -16 */ { 190, 176, 176, 123, 111, 131, 142, 112, 113, 109, 120, 125, 114, 124, 116, 115, 73, 60, 73, 105, 130, 141, 121, 131, 139, 136, 143, 146, 128, 140, 112, 166, 176, 176, 180, 204 },
    /* -12 */ { 320, 204, 221, 143, 145, 186, 187, 162, 163, 148, 151, 157, 158, 144, 129, 135, 104, 63, 103, 117, 139, 130, 144, 208, 169, 163, 197, 169, 194, 197, 156, 196, 242, 234, 228, 281 },
    /*  -8 */ { 484, 283, 224, 172, 180, 219, 237, 198, 230, 186, 235, 205, 191, 182, 150, 150, 99, 77, 81, 146, 156, 188, 185, 254, 262, 208, 288, 239, 276, 258, 246, 239, 292, 309, 320, 379 },
    /*  -4 */ { 569, 371, 223, 172, 186, 256, 244, 210, 231, 262, 326, 224, 215, 223, 133, 119, 120, 108, 128, 190, 221, 182, 229, 255, 282, 219, 258, 246, 369, 351, 323, 376, 306, 467, 270, 318 },
    /*  +0 */ { 290, 275, 182, 100, 122, 151, 187, 275, 219, 221, 247, 177, 199, 174, 132, 125, 148, 195, 180, 182, 209, 251, 278, 272, 342, 302, 239, 177, 338, 634, 354, 446, 248, 314, 289, 278 },
    /*  +4 */ { 147, 210, 111, 87, 186, 169, 220, 342, 216, 156, 160, 153, 124, 136, 138, 108, 166, 171, 182, 191, 199, 222, 263, 261, 274, 294, 207, 181, 280, 441, 356, 337, 251, 279, 151, 251 },
    /*  +8 */ { 164, 222, 77, 107, 209, 175, 223, 242, 220, 195, 140, 136, 111, 96, 96, 102, 133, 142, 147, 184, 186, 189, 186, 193, 197, 202, 169, 181, 204, 227, 238, 192, 197, 247, 127, 208 },
    /* +12 */ { 169, 142, 81, 167, 163, 155, 170, 174, 169, 160, 116, 124, 115, 95, 91, 84, 107, 129, 134, 146, 154, 149, 149, 143, 147, 126, 131, 142, 144, 159, 173, 208, 175, 209, 158, 182 },
    /* +16 */ { 97, 84, 75, 121, 125, 133, 130, 144, 139, 126, 98, 84, 104, 89, 101, 95, 93, 99, 105, 100, 112, 125, 119, 112, 106, 99, 111, 111, 131, 114, 145, 174, 141, 172, 121, 168 },  /* fill l 220-240 */
    /* +20 */ { 85, 68, 71, 102, 104, 102, 99, 114, 95, 91, 83, 74, 86, 90, 92, 79, 97, 87, 89, 92, 100, 97, 94, 92, 89, 86, 87, 93, 90, 95, 93, 117, 122, 125, 113, 146 },  /* fill l 210-240 */
    /* +24 */ { 92, 72, 68, 85, 86, 90, 84, 85, 80, 86, 73, 75, 79, 73, 70, 72, 75, 81, 77, 81, 81, 81, 81, 80, 80, 80, 75, 73, 82, 84, 80, 95, 95, 99, 87, 106 },  /* fill l 200-240 */
    /* +30 */ { 68, 63, 71, 66, 63, 67, 74, 72, 61, 66, 73, 61, 57, 61, 60, 58, 61, 56, 62, 62, 62, 62, 61, 61, 61, 61, 72, 61, 64, 64, 62, 67, 74, 80, 73, 76 },  /* fill l 190-240 */
    /* +40 */ { 47, 56, 50, 53, 50, 44, 52, 48, 41, 49, 47, 44, 44, 41, 51, 41, 44, 51, 51, 53, 56, 58, 60, 63, 65, 53, 56, 51, 49, 51, 47, 57, 52, 48, 47, 48 },  /* fill l 190-230 */
    /* +50 */ { 44, 43, 44, 32, 41, 38, 39, 39, 35, 27, 40, 39, 33, 37, 37, 45, 37, 44, 49, 53, 58, 63, 67, 72, 63, 53, 45, 46, 44, 41, 42, 50, 64, 46, 46, 42 },  /* fill l 180-220 */
    /* +60 */ { 37, 38, 36, 30, 32, 33, 33, 30, 36, 39, 40, 34, 34, 35, 33, 31, 32, 40, 45, 42, 45, 49, 57, 53, 52, 53, 55, 39, 42, 39, 32, 38, 35, 34, 38, 37 },
    /* +70 */ { 36, 40, 32, 31, 33, 27, 29, 30, 33, 31, 30, 28, 24, 27, 28, 30, 35, 35, 35, 36, 36, 36, 40, 42, 42, 45, 43, 35, 36, 40, 35, 35, 30, 32, 32, 33 },
    /* +80 */ { 29, 27, 29, 30, 28, 27, 27, 30, 31, 32, 35, 31, 28, 29, 30, 29, 28, 29, 31, 30, 29, 29, 31, 32, 31, 31, 30, 30, 30, 31, 33, 29, 25, 25, 29, 31 }
};

/* One S10_sun as the radiance of sunlight over the whole spectrum (W m^-2
 * sr^-1), the convention of oi_expose_in.background_w_m2_sr: a star of the
 * Sun's spectrum and V = 10 has the irradiance TSI 10^(-0.4 (10 - V_sun)),
 * TSI = OI_TSI_W_M2 (1361 W/m^2), V_sun = OI_SUN_MAG_V (-26.74), and a
 * square degree is (pi/180)^2 sr: 1361 10^-14.696 (180/pi)^2 (mpmath, 30
 * digits). The starlight is then treated as sunlight (grey), as every
 * source of the camera model; docs/camera.md says what that leaves out. */
#define ISL_UNIT_W_M2_SR OI_R(8.9971174530390225e-09)

/* Mean of one edge row (|b| = 80 deg) over longitude: the value taken at
 * its pole, where every longitude meets. */
static oi_real row_mean(int i)
{
    unsigned sum = 0u;
    int j;
    for (j = 0; j < ISL_COLS; j++) sum += isl_table[i][j];
    return (oi_real)sum / (oi_real)ISL_COLS;
}

/* Value of row i at longitude column j and fraction fl towards j + 1. */
static oi_real row_at(int i, int j, oi_real fl)
{
    const int j1 = j + 1 < ISL_COLS ? j + 1 : 0; /* 350 deg to 360 = 0 */
    return (oi_real)isl_table[i][j] +
           fl * ((oi_real)isl_table[i][j1] - (oi_real)isl_table[i][j]);
}

/*
 * oi_starlight_radiance: the contract is in include/orbillum.h.
 * Bilinear in the table (linear in the brightness); beyond |b| = 80 deg,
 * linear in latitude from the edge row to its longitude mean at the pole,
 * so that the value at the pole does not depend on the longitude.
 */
oi_real oi_starlight_radiance(oi_real l_rad, oi_real b_rad)
{
    const oi_real deg = (oi_real)OI_DEG_PER_RAD;
    oi_real l, b, fl, fb, v0, v1, u;
    int i, j;
    if (!OI_ISFINITE(l_rad) || !OI_ISFINITE(b_rad)) return 0;
    /* beyond 1e30 rad reduced in radians first, |b| beyond 4 rad taken as 4
     * (clamped to the pole the same): no product overflows (any other angle:
     * the bits of earlier versions) */
    if (OI_FABS(l_rad) > OI_R(1e30))
        l_rad -= OI_R(6.283185307179586) * OI_FLOOR(l_rad / OI_R(6.283185307179586));
    if (OI_FABS(b_rad) > OI_R(4.0)) b_rad = b_rad > 0 ? OI_R(4.0) : OI_R(-4.0);
    l = l_rad * deg;
    l -= OI_R(360.0) * OI_FLOOR(l / OI_R(360.0));
    u = l / OI_R(10.0);
    j = (int)u;
    if (j > ISL_COLS - 1) j = ISL_COLS - 1; /* l rounded up to 360 */
    if (j < 0) j = 0;
    fl = oi__clamp(u - (oi_real)j, 0, OI_R(1.0));
    b = oi__clamp(b_rad * deg, OI_R(-90.0), OI_R(90.0));
    if (b >= OI_R(80.0) || b <= OI_R(-80.0)) {
        i = b > 0 ? ISL_ROWS - 1 : 0;
        fb = (OI_FABS(b) - OI_R(80.0)) / OI_R(10.0);
        v0 = row_at(i, j, fl);
        return (v0 + fb * (row_mean(i) - v0)) * ISL_UNIT_W_M2_SR;
    }
    i = 0;
    while (i < ISL_ROWS - 2 && b >= (oi_real)isl_lat_deg[i + 1]) i++;
    fb = (b - (oi_real)isl_lat_deg[i]) / (oi_real)(isl_lat_deg[i + 1] - isl_lat_deg[i]);
    v0 = row_at(i, j, fl);
    v1 = row_at(i + 1, j, fl);
    return (v0 + fb * (v1 - v0)) * ISL_UNIT_W_M2_SR;
}

#endif /* OI_NO_SKY */
