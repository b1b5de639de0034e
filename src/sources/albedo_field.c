/* SPDX-License-Identifier: MIT */
/* albedo_field.c: the Earth's albedo at a surface point under the Knocke
 * zonal model or a caller's latitude-longitude map. */
#include "sources/sources_internal.h"

#ifndef OI_NO_ALBEDO_MODELS

/*
 * Knocke, Ries & Tapley 1988 (AIAA 88-4292, "Earth radiation pressure
 * effects on satellites"), the albedo's zonal model used by Orekit and
 * Basilisk: a(phi, t) = a0 + a1(t) P1(sin phi) + a2 P2(sin phi),
 * a1(t) = c0 + c1 cos(w (t - t0)) + c2 sin(w (t - t0)), t in days.
 */
#define KNOCKE_A0 OI_R(0.34)
#define KNOCKE_C0 OI_R(0.0)
#define KNOCKE_C1 OI_R(0.10)
#define KNOCKE_C2 OI_R(0.0)
#define KNOCKE_A2 OI_R(0.29)
#define KNOCKE_T0_JD 2444960.5
#define KNOCKE_YEAR_D 365.25

void oi__albedo_field_init(const oi_model *m, const oi_scene *s, oi__albedo_field *f)
{
    f->model = m->albedo_model;
    f->a1 = (oi_real)0;
    f->map = m->albedo_map;
    f->n_lat = m->albedo_map_n_lat;
    f->n_lon = m->albedo_map_n_lon;
    f->cos_rot = (oi_real)1;
    f->sin_rot = (oi_real)0;
    if (f->model == OI_ALBEDO_KNOCKE) {
        /* the phase from the days since t0, taken modulo a year first so that
         * the angle stays small (the epoch's range bounds it anyway) */
        oi_real days = s->epoch_jd - (oi_real)KNOCKE_T0_JD, c, sn;
        days -= (oi_real)KNOCKE_YEAR_D * OI_FLOOR(days / (oi_real)KNOCKE_YEAR_D);
        OI_SINCOS(OI_R(2.0) * OI_PI_R * days / (oi_real)KNOCKE_YEAR_D, &sn, &c);
        f->a1 = KNOCKE_C0 + KNOCKE_C1 * c + KNOCKE_C2 * sn;
    } else {
        OI_SINCOS(s->earth_rotation_rad, &f->sin_rot, &f->cos_rot);
    }
}

/* value of a map cell, 1 when it is in [0, 1] (NaN fails) */
static int cell(const oi__albedo_field *f, int i, int j, oi_real *v)
{
    const float x = f->map[(long)i * f->n_lon + j];
    *v = (oi_real)x;
    return isgreaterequal(x, 0.0f) && islessequal(x, 1.0f); /* quiet: NaN */
}

int oi__albedo_at(const oi__albedo_field *f, const oi_real p[3], oi_real *a)
{
    oi_real xe, ye, rho, fi, fj, ti, tj, v00, v01, v10, v11, v;
    int i0, i1, j0, j1;
    *a = (oi_real)0;
    if (f->model == OI_ALBEDO_KNOCKE) {
        const oi_real z = p[2]; /* sin(latitude) of a unit point */
        v = KNOCKE_A0 + f->a1 * z + KNOCKE_A2 * OI_R(0.5) * (OI_R(3.0) * z * z - OI_R(1.0));
        *a = v < (oi_real)0 ? (oi_real)0 : (v > (oi_real)1 ? (oi_real)1 : v);
        return OI_OK;
    }
    /* the point in the Earth-fixed frame: x towards Greenwich */
    xe = f->cos_rot * p[0] + f->sin_rot * p[1];
    ye = f->cos_rot * p[1] - f->sin_rot * p[0];
    rho = OI_SQRT(xe * xe + ye * ye);
    /* rows from the north pole: colatitude over the row height, minus the
     * half row of the first centre; clamped onto the first and last centres */
    fi = OI_ATAN2(rho, p[2]) * ((oi_real)f->n_lat / OI_PI_R) - OI_R(0.5);
    if (!(fi > (oi_real)0)) fi = (oi_real)0;
    if (fi > (oi_real)(f->n_lat - 1)) fi = (oi_real)(f->n_lat - 1);
    i0 = (int)fi;
    if (i0 > f->n_lat - 1) i0 = f->n_lat - 1;
    ti = fi - (oi_real)i0;
    i1 = i0 + 1 < f->n_lat ? i0 + 1 : i0;
    /* columns from Greenwich eastwards, periodic */
    {
        oi_real lon = OI_ATAN2(ye, xe); /* (-pi, pi] */
        if (lon < (oi_real)0) lon += OI_R(2.0) * OI_PI_R;
        fj = lon * ((oi_real)f->n_lon / (OI_R(2.0) * OI_PI_R)) - OI_R(0.5);
    }
    {
        const oi_real fl = OI_FLOOR(fj);
        tj = fj - fl;
        j0 = (int)fl; /* in [-1, n_lon] after rounding */
    }
    if (j0 < 0) j0 += f->n_lon;
    if (j0 >= f->n_lon) j0 -= f->n_lon;
    if (j0 < 0 || j0 >= f->n_lon) j0 = 0; /* n_lon 1 with rounding at the seam */
    j1 = j0 + 1 < f->n_lon ? j0 + 1 : 0;
    if (!(tj >= (oi_real)0 && tj <= (oi_real)1)) tj = (oi_real)0;
    if (!(ti >= (oi_real)0 && ti <= (oi_real)1)) ti = (oi_real)0;
    if (!cell(f, i0, j0, &v00) || !cell(f, i0, j1, &v01) || !cell(f, i1, j0, &v10) ||
        !cell(f, i1, j1, &v11))
        return OI_ERR_ALBEDO;
    /* a map of one value gives that value exactly (every difference 0) */
    v = v00 + ti * (v10 - v00) + tj * (v01 - v00) + ti * tj * ((v11 - v10) - (v01 - v00));
    *a = v < (oi_real)0 ? (oi_real)0 : (v > (oi_real)1 ? (oi_real)1 : v);
    return OI_OK;
}

#else
typedef int oi__albedo_field_compiled_out; /* ISO C: no empty translation unit */
#endif /* OI_NO_ALBEDO_MODELS */
