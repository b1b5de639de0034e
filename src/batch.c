/* SPDX-License-Identifier: MIT */
/*
 * batch.c: the batch calls, the single calls over caller-owned arrays with
 * the model (and the camera) validated once per batch (include/orbillum.h,
 * "batch"). Each row goes through the same internal function the single
 * call uses, so its outputs are the single call's bits; the savings are the
 * model's validation per row and, in oi_sun_fraction_batch and
 * oi_illuminate_batch_outputs (src/illuminate_outputs.c), what the outputs
 * mask leaves out.
 */
#include "oi_internal.h"

/* Alignment of a type in C99 (no _Alignof): the offset of a member after a
 * char. */
#define ALIGN_OF(type) offsetof(struct { char c; type t; }, t)

/* A caller's array: its address range, for the alignment and overlap checks. */
typedef struct {
    uintptr_t lo, hi; /* [lo, hi); lo == hi: absent (NULL, optional) */
} span;

/* The span of n elements of size bytes at p; 0 when p is not aligned to
 * align or the size overflows the address space. */
static int span_of(const void *p, long n, size_t size, size_t align, span *s)
{
    const uintptr_t a = (uintptr_t)p;
    s->lo = s->hi = a;
    if (p == NULL) return 1;
    if (a % align != 0) return 0;
    if ((uintptr_t)n > (UINTPTR_MAX - a) / size) return 0;
    s->hi = a + (uintptr_t)n * size;
    return 1;
}

static int spans_overlap(const span *a, const span *b)
{
    return a->lo < a->hi && b->lo < b->hi && a->lo < b->hi && b->lo < a->hi;
}

/* OI_OK when no output span overlaps an input span or another output span;
 * else OI_ERR_INPUT. */
static int check_overlap(const span *in, int n_in, const span *out, int n_out)
{
    int i, j;
    for (i = 0; i < n_out; i++) {
        for (j = 0; j < n_in; j++)
            if (spans_overlap(&out[i], &in[j])) return OI_ERR_INPUT;
        for (j = i + 1; j < n_out; j++)
            if (spans_overlap(&out[i], &out[j])) return OI_ERR_INPUT;
    }
    return OI_OK;
}

/* The checks common to every batch: n, the required pointers. */
static int check_n(long n)
{
    if (n < 0 || n > OI_BATCH_MAX) return OI_ERR_INPUT;
    return OI_OK;
}

/* A batch error: every status set to it, every output row zeroed (when the
 * arrays could be used: not NULL, aligned; not on overlap, where zeroing
 * would write into the inputs). */
static int batch_fail(int st, long n, int *status, void *out, size_t size, int zero_out)
{
    long i;
    span s;
    if (status != NULL && span_of(status, n, sizeof *status, ALIGN_OF(int), &s))
        for (i = 0; i < n; i++) status[i] = st;
    if (zero_out && out != NULL) memset(out, 0, (size_t)n * size);
    return st;
}

/* ---------------------------------------------------------------- Sun */

/* Margin, in cosine, of the batch's certain-region tests: far beyond the
 * rounding of the cosines and of the arctangents the full call forms
 * (a few epsilon). */
#ifdef OI_SINGLE_PRECISION
#define COS_MARGIN OI_R(1e-5)
#else
#define COS_MARGIN OI_R(1e-6)
#endif

/* Height above the surface every grazing ray stays below (twice
 * OI_ATM_TOP_MAX_KM), as in src/illuminate.c. */
#define GRAZING_TOP_KM OI_R(200.0)

#define ROW_UNSURE OI__ROW_UNSURE
#define ROW_LIT OI__ROW_LIT
#define ROW_UMBRA OI__ROW_UMBRA

/*
 * ROW_LIT or ROW_UMBRA when the row certainly is in that region, decided
 * from cosines alone; ROW_UNSURE otherwise (the full call follows). A row is
 * decided only when every check of the full call's geometry (sun_geometry in
 * src/sun_fraction.c) passes, formed the same way, so its status is OI_OK:
 * finite, |point| > 1.001 R (|point|^2 - R^2 >= 0.002 R^2, far beyond the
 * rounding of the full call's compensated form: not below the surface),
 * |sun| > R_sun + R, sun - point finite, |sun - point| > R_sun. Both
 * apparent radii are below pi/2 (sines below 1), so their sum is below pi
 * and the comparison of cosines is the comparison of angles. LIT: the angle between the
 * Sun's centre and the Earth's anti-centre exceeds the sum of the radii of
 * the Sun and of the Earth enlarged by GRAZING_TOP_KM (outside the
 * atmosphere's window too: its fraction is then 1, src/illuminate.c's
 * certainly_lit). UMBRA (only asked without the atmosphere, which lights
 * the umbra): the Sun's disc inside the Earth's, sep + r_sun < r_earth (for
 * the ellipsoid, its inner sphere's: the polar radius).
 */
/* The radius of the sphere whose umbra is certainly the model Earth's: the
 * sphere itself, or the ellipsoid's inner sphere (its polar radius). */
static oi_real umbra_radius(const oi_model *m)
{
    if (m->earth_shape == OI_EARTH_WGS84)
        return m->earth_radius_km * (oi_real)(1.0 - 1.0 / OI_WGS84_INV_FLATTENING);
    return m->earth_radius_km;
}

int oi__sun_certain_region(const oi_real sun[3], const oi_real p[3], const oi_model *m,
                           int umbra_too)
{
    oi_real ds, dp, dsp, rel[3], sin_e, sin_s, cos_e, cos_s, cos_sep, sin_sep, sin_r, cos_r;
    if (!oi__finite3(sun) || !oi__finite3(p)) return ROW_UNSURE;
    ds = oi__norm(sun);
    dp = oi__norm(p);
    /* (beyond OI_POSITION_MAX_KM the ellipsoid's call refuses the point) */
    if (!(dp > OI_R(1.001) * m->earth_radius_km) || !(dp <= (oi_real)OI_POSITION_MAX_KM))
        return ROW_UNSURE;
    if (!(ds > m->sun_radius_km + m->earth_radius_km)) return ROW_UNSURE;
    oi__sub(sun, p, rel);
    if (!oi__finite3(rel)) return ROW_UNSURE;
    dsp = oi__norm(rel);
    if (!OI_ISFINITE(dsp) || !(dsp > m->sun_radius_km)) return ROW_UNSURE;
    /* the Earth behind the Sun is LIT in the full call too, but rare: left to it */
    sin_s = m->sun_radius_km / dsp;
    if (!(sin_s < (oi_real)1)) return ROW_UNSURE;
    cos_s = OI_SQRT(((oi_real)1 - sin_s) * ((oi_real)1 + sin_s));
    cos_sep = -oi__dot(rel, p) / dsp / dp;
    if (!OI_ISFINITE(cos_sep)) return ROW_UNSURE;
    sin_e = (m->earth_radius_km + GRAZING_TOP_KM) / dp;
    if (sin_e < (oi_real)1) {
        cos_e = OI_SQRT(((oi_real)1 - sin_e) * ((oi_real)1 + sin_e));
        if (cos_sep < cos_e * cos_s - sin_e * sin_s - COS_MARGIN) return ROW_LIT;
    }
    if (!umbra_too) return ROW_UNSURE;
    /* cos(sep + r_sun) > cos(r_earth) + margin: sep + r_sun < r_earth <= pi/2
     * (the ellipsoid's silhouette holds its inner sphere's, the polar radius) */
    sin_r = umbra_radius(m) / dp;
    cos_r = OI_SQRT(((oi_real)1 - sin_r) * ((oi_real)1 + sin_r));
    sin_sep = OI_SQRT(oi__clamp(((oi_real)1 - cos_sep) * ((oi_real)1 + cos_sep), (oi_real)0,
                                (oi_real)1));
    if (cos_sep > (oi_real)0 && cos_sep * cos_s - sin_sep * sin_s > cos_r + COS_MARGIN)
        return ROW_UMBRA;
    return ROW_UNSURE;
}

/* Rows classified at once by classify_block. */
#define CLASSIFY_ROWS 32

/* GCC if-converts the loop's comparisons (and so vectorises it) only when
 * they may not trap: the attribute says so for this one function, whose
 * results do not depend on it (no floating-point exception is read). */
#if defined(__GNUC__) && !defined(__clang__)
#define VECTORISE_COMPARES __attribute__((optimize("no-trapping-math")))
#else
#define VECTORISE_COMPARES
#endif

/*
 * oi__sun_certain_region over CLASSIFY_ROWS rows at once, written so that
 * the compiler vectorises the loop (a fixed count, no call, every value and
 * condition an oi_real, the divisors replaced where a row is not decided;
 * gcc -fopt-info-vec, docs/performance.md). The same tests with the same
 * margins, and stricter checks of the positions: every component within
 * OI_POSITION_MAX_KM (so the plain norms neither overflow nor underflow to a
 * wrong decision: |point| > 1.001 R), |sun| > 1.001 (R_sun + R), |sun -
 * point| > 1.001 R_sun; the plain norms differ from the full call's scaled
 * ones by a few ulp, far inside those margins and COS_MARGIN. code[i]:
 * ROW_* as oi_real.
 */
static VECTORISE_COMPARES void classify_block(const oi_real *restrict sun,
                                              const oi_real *restrict p, const oi_model *m,
                                              oi_real umbra_too, oi_real *restrict code)
{
    const oi_real re = m->earth_radius_km, rs = m->sun_radius_km, r_umbra = umbra_radius(m);
    const oi_real re_top = re + GRAZING_TOP_KM, far = (oi_real)OI_POSITION_MAX_KM;
    const oi_real one = (oi_real)1, zero = (oi_real)0;
    int i;
    for (i = 0; i < CLASSIFY_ROWS; i++) {
        const oi_real sx = sun[3 * i], sy = sun[3 * i + 1], sz = sun[3 * i + 2];
        const oi_real px = p[3 * i], py = p[3 * i + 1], pz = p[3 * i + 2];
        const oi_real rx = sx - px, ry = sy - py, rz = sz - pz;
        const oi_real ds = OI_SQRT(sx * sx + sy * sy + sz * sz);
        const oi_real dp0 = OI_SQRT(px * px + py * py + pz * pz);
        const oi_real dsp0 = OI_SQRT(rx * rx + ry * ry + rz * rz);
        oi_real ok, dp, dsp, sin_s, cos_s2, cos_s, sin_e, cos_e2, cos_e, sin_r, cos_r2, cos_r;
        oi_real cos_sep, sin_sep2, sin_sep, lit, umb;
        /* every component bounded (NaN fails every comparison) */
        /* (three short conditions each: a longer chain is not if-converted) */
        ok = OI_FABS(sx) <= far && OI_FABS(sy) <= far && OI_FABS(sz) <= far ? one : zero;
        ok *= OI_FABS(px) <= far && OI_FABS(py) <= far && OI_FABS(pz) <= far ? one : zero;
        ok *= dp0 > OI_R(1.001) * re && ds > OI_R(1.001) * (rs + re) &&
                      dsp0 > OI_R(1.001) * rs
                  ? one
                  : zero;
        /* the undecided rows' divisors made harmless */
        dp = ok != zero ? dp0 : one;
        dsp = ok != zero ? dsp0 : one;
        sin_s = rs / dsp;
        cos_s2 = (one - sin_s) * (one + sin_s);
        cos_s = OI_SQRT(cos_s2 > zero ? cos_s2 : zero);
        cos_sep = -(rx * px + ry * py + rz * pz) / dsp / dp;
        sin_e = re_top / dp;
        cos_e2 = (one - sin_e) * (one + sin_e);
        cos_e = OI_SQRT(cos_e2 > zero ? cos_e2 : zero);
        lit = sin_e < one && cos_sep < cos_e * cos_s - sin_e * sin_s - COS_MARGIN ? ok : zero;
        sin_r = r_umbra / dp;
        cos_r2 = (one - sin_r) * (one + sin_r);
        cos_r = OI_SQRT(cos_r2 > zero ? cos_r2 : zero);
        sin_sep2 = (one - cos_sep) * (one + cos_sep);
        sin_sep2 = sin_sep2 < one ? sin_sep2 : one;
        sin_sep = OI_SQRT(sin_sep2 > zero ? sin_sep2 : zero);
        umb = cos_sep > zero && cos_sep * cos_s - sin_sep * sin_s > cos_r + COS_MARGIN
                  ? ok * umbra_too
                  : zero;
        /* exclusive regions (lit: apart, umbra: inside) */
        code[i] = lit * (oi_real)ROW_LIT + (umb - umb * lit) * (oi_real)ROW_UMBRA;
    }
}

/* A row classify_block decided: the full call's fractions (1 or 0) and
 * region, the fields the mask leaves out 0. */
static void decided_row(int region, unsigned outputs, oi_shadow *out)
{
    const oi_real f = region == ROW_LIT ? (oi_real)1 : (oi_real)0;
    memset(out, 0, sizeof *out);
    out->fraction = f;
    if (outputs & OI_BATCH_FRACTION_LD) out->fraction_ld = f;
    if (outputs & OI_BATCH_ATMOSPHERE) out->fraction_atm = f;
    out->region = region == ROW_LIT ? OI_SHADOW_LIT : OI_SHADOW_UMBRA;
}

/* A row classify_block left undecided: the full call's steps under the
 * mask. */
static int sun_row(const oi_real sun[3], const oi_real p[3], const oi_model *m,
                   unsigned outputs, oi_shadow *out)
{
    unsigned want = 0;
    int st;
    if (outputs & OI_BATCH_FRACTION_LD) want |= OI__WANT_LD;
    if (outputs & OI_BATCH_ATMOSPHERE) want |= OI__WANT_ATM;
    st = oi__sun_shadow_want(sun, p, m, want, out, NULL);
    if (!(outputs & OI_BATCH_FRACTION_LD)) out->fraction_ld = (oi_real)0;
    if (!(outputs & OI_BATCH_GEOMETRY)) {
        out->sun_radius_rad = out->earth_radius_rad = (oi_real)0;
        out->separation_rad = out->sun_distance_km = (oi_real)0;
    }
    return st;
}

int oi_sun_fraction_batch(long n, const oi_real *sun_km, const oi_real *point_km,
                          const oi_model *model, unsigned outputs, oi_shadow *out,
                          int *status)
{
    oi_model m;
    span in[2], o[2];
    unsigned char region[CLASSIFY_ROWS];
    oi_real code[CLASSIFY_ROWS];
    long b, bad = 0;
    int st, atm_on = 0;
    if (n == 0) return 0;
    if (check_n(n) != OI_OK) return OI_ERR_INPUT; /* nothing written: n is not the arrays' */
    if (sun_km == NULL || point_km == NULL || out == NULL || status == NULL)
        return batch_fail(OI_ERR_NULL, n, status, NULL, 0, 0);
    if (!span_of(sun_km, n, 3 * sizeof *sun_km, ALIGN_OF(oi_real), &in[0]) ||
        !span_of(point_km, n, 3 * sizeof *point_km, ALIGN_OF(oi_real), &in[1]) ||
        !span_of(out, n, sizeof *out, ALIGN_OF(oi_shadow), &o[0]) ||
        !span_of(status, n, sizeof *status, ALIGN_OF(int), &o[1]) ||
        check_overlap(in, 2, o, 2) != OI_OK)
        return batch_fail(OI_ERR_INPUT, n, status, NULL, 0, 0);
    st = (outputs & ~(unsigned)OI_BATCH_ALL) != 0u ? OI_ERR_FLAGS : oi__model_resolve(model, &m);
    if (st < 0) return batch_fail(st, n, status, out, sizeof *out, 1);
#ifndef OI_NO_ATMOSPHERE
    atm_on = (outputs & OI_BATCH_ATMOSPHERE) && !m.no_atmosphere;
#endif
    memset(region, ROW_UNSURE, sizeof region);
    for (b = 0; b < n; b += CLASSIFY_ROWS) {
        const int k = n - b < CLASSIFY_ROWS ? (int)(n - b) : CLASSIFY_ROWS;
        int j;
        /* without the geometry asked, the rows certainly lit (or in the
         * umbra) first, from cosines; the others in full */
        if (!(outputs & OI_BATCH_GEOMETRY)) {
            if (k == CLASSIFY_ROWS) {
                classify_block(sun_km + 3 * b, point_km + 3 * b, &m,
                               atm_on ? (oi_real)0 : (oi_real)1, code);
                for (j = 0; j < k; j++) region[j] = (unsigned char)code[j];
            } else {
                /* the last rows: one by one (the block's loop has a fixed count,
                 * which lets -O2 vectorise it) */
                for (j = 0; j < k; j++)
                    region[j] = (unsigned char)oi__sun_certain_region(
                        sun_km + 3 * (b + j), point_km + 3 * (b + j), &m, !atm_on);
            }
        }
        for (j = 0; j < k; j++) {
            const long i = b + j;
            if (region[j] != ROW_UNSURE) {
                decided_row(region[j], outputs, &out[i]);
                status[i] = OI_OK;
            } else {
                status[i] = sun_row(sun_km + 3 * i, point_km + 3 * i, &m, outputs, &out[i]);
                bad += status[i] < 0;
            }
        }
    }
    return (int)bad;
}

/* ---------------------------------------------------------------- earthshine */

int oi_earthshine_batch(long n, const oi_real *theta, const oi_real *h_km,
                        const oi_model *model, oi_real *phi, oi_real *psi, int *status)
{
    oi_model m;
    span in[2], o[3];
    oi_real psi_row;
    long i, bad = 0;
    int st;
    if (n == 0) return 0;
    if (check_n(n) != OI_OK) return OI_ERR_INPUT; /* nothing written: n is not the arrays' */
    if (theta == NULL || h_km == NULL || phi == NULL || status == NULL)
        return batch_fail(OI_ERR_NULL, n, status, NULL, 0, 0);
    if (!span_of(theta, n, sizeof *theta, ALIGN_OF(oi_real), &in[0]) ||
        !span_of(h_km, n, sizeof *h_km, ALIGN_OF(oi_real), &in[1]) ||
        !span_of(phi, n, sizeof *phi, ALIGN_OF(oi_real), &o[0]) ||
        !span_of(psi, n, sizeof *psi, ALIGN_OF(oi_real), &o[1]) ||
        !span_of(status, n, sizeof *status, ALIGN_OF(int), &o[2]) ||
        check_overlap(in, 2, o, 3) != OI_OK)
        return batch_fail(OI_ERR_INPUT, n, status, NULL, 0, 0);
    st = oi__model_resolve(model, &m);
    if (st < 0) {
        if (psi != NULL) memset(psi, 0, (size_t)n * sizeof *psi);
        return batch_fail(st, n, status, phi, sizeof *phi, 1);
    }
    for (i = 0; i < n; i++) {
        /* oi_earthshine's own checks: NULL outputs are excluded above */
        status[i] = oi__earthshine(theta[i], (oi_real)2, (oi_real)0, h_km[i], &m, &phi[i],
                                   &psi_row);
        if (psi != NULL) psi[i] = psi_row;
        bad += status[i] < 0;
    }
    return (int)bad;
}

/* ---------------------------------------------------------------- illuminate */

/* The array checks of both illuminate batches (n != 0): OI_OK, or the
 * batch's error with the statuses set (nothing else written). */
static int illuminate_arrays(long n, const oi_scene *scenes, const oi_illum *out, int *status)
{
    span in[1], o[2];
    if (check_n(n) != OI_OK) return OI_ERR_INPUT; /* nothing written: n is not the arrays' */
    if (scenes == NULL || out == NULL || status == NULL)
        return batch_fail(OI_ERR_NULL, n, status, NULL, 0, 0);
    if (!span_of(scenes, n, sizeof *scenes, ALIGN_OF(oi_scene), &in[0]) ||
        !span_of(out, n, sizeof *out, ALIGN_OF(oi_illum), &o[0]) ||
        !span_of(status, n, sizeof *status, ALIGN_OF(int), &o[1]) ||
        check_overlap(in, 1, o, 2) != OI_OK)
        return batch_fail(OI_ERR_INPUT, n, status, NULL, 0, 0);
    return OI_OK;
}

/* The set-up of both illuminate batches (n != 0): the arrays checked, the
 * outputs mask checked, the model and its albedo resolved into *m. OI_OK,
 * or the batch's error with the statuses set and the outputs zeroed. */
static int illuminate_setup(long n, const oi_scene *scenes, const oi_model *model,
                            unsigned outputs, oi_model *m, oi_illum *out, int *status)
{
    int st = illuminate_arrays(n, scenes, out, status);
    if (st < 0) return st;
    st = (outputs & ~(unsigned)OI_BATCH_SCENE_ALL) != 0u ? OI_ERR_FLAGS
                                                        : oi__model_resolve(model, m);
    if (st == OI_OK) st = oi__albedo_resolve(model, m);
    if (st < 0) return batch_fail(st, n, status, out, sizeof *out, 1);
    return OI_OK;
}

int oi_illuminate_batch(long n, const oi_scene *scenes, const oi_model *model, oi_illum *out,
                        int *status)
{
    oi_model m;
    long i, bad = 0;
    int st;
    if (n == 0) return 0;
    st = illuminate_setup(n, scenes, model, OI_BATCH_SCENE_ALL, &m, out, status);
    if (st < 0) return st;
    for (i = 0; i < n; i++) {
        status[i] = oi__illuminate_resolved(&scenes[i], &m, &out[i]);
        bad += status[i] < 0;
    }
    return (int)bad;
}

int oi_illuminate_batch_outputs(long n, const oi_scene *scenes, const oi_model *model,
                                unsigned outputs, oi_illum *out, int *status)
{
    oi_model m;
    long i, bad = 0;
    int st;
    if (n == 0) return 0;
    st = illuminate_setup(n, scenes, model, outputs, &m, out, status);
    if (st < 0) return st;
    for (i = 0; i < n; i++) {
        status[i] = oi__illuminate_outputs(&scenes[i], &m, outputs, &out[i]);
        bad += status[i] < 0;
    }
    return (int)bad;
}

/* ---------------------------------------------------------------- exposure */
#ifndef OI_NO_EXPOSURE

int oi_expose_batch(long n, const oi_camera *camera, const oi_expose_in *in,
                    const oi_expose_goal *goal, oi_exposure *out, int *status)
{
    span si[1], o[2];
    long i, bad = 0;
    if (n == 0) return 0;
    if (check_n(n) != OI_OK) return OI_ERR_INPUT; /* nothing written: n is not the arrays' */
    if (camera == NULL || in == NULL || out == NULL || status == NULL)
        return batch_fail(OI_ERR_NULL, n, status, NULL, 0, 0);
    if (!span_of(in, n, sizeof *in, ALIGN_OF(oi_expose_in), &si[0]) ||
        !span_of(out, n, sizeof *out, ALIGN_OF(oi_exposure), &o[0]) ||
        !span_of(status, n, sizeof *status, ALIGN_OF(int), &o[1]) ||
        check_overlap(si, 1, o, 2) != OI_OK)
        return batch_fail(OI_ERR_INPUT, n, status, NULL, 0, 0);
    if (!oi__camera_valid(camera)) return batch_fail(OI_ERR_CAMERA, n, status, out, sizeof *out, 1);
    for (i = 0; i < n; i++) {
        memset(&out[i], 0, sizeof out[i]);
        status[i] = oi__expose_valid(camera, &in[i], goal, &out[i]);
        if (status[i] < 0) memset(&out[i], 0, sizeof out[i]);
        bad += status[i] < 0;
    }
    return (int)bad;
}

int oi_expose_scene_batch(long n, const oi_camera *camera, const oi_scene *scenes,
                          const oi_illum *illum, const oi_model *model,
                          const oi_expose_goal *goal, oi_exposure *out, int *status)
{
    span in[2], o[2];
    oi_model m;
    long i, bad = 0;
    int st;
    if (n == 0) return 0;
    if (check_n(n) != OI_OK) return OI_ERR_INPUT; /* nothing written: n is not the arrays' */
    if (camera == NULL || scenes == NULL || illum == NULL || out == NULL || status == NULL)
        return batch_fail(OI_ERR_NULL, n, status, NULL, 0, 0);
    if (!span_of(scenes, n, sizeof *scenes, ALIGN_OF(oi_scene), &in[0]) ||
        !span_of(illum, n, sizeof *illum, ALIGN_OF(oi_illum), &in[1]) ||
        !span_of(out, n, sizeof *out, ALIGN_OF(oi_exposure), &o[0]) ||
        !span_of(status, n, sizeof *status, ALIGN_OF(int), &o[1]) ||
        check_overlap(in, 2, o, 2) != OI_OK)
        return batch_fail(OI_ERR_INPUT, n, status, NULL, 0, 0);
    /* the batch's errors: the model, then the camera (a row's own checks
     * come before the camera's in the single call, so a valid model and
     * camera are the batch's condition, the rows' statuses the single call's) */
    st = oi__model_resolve(model, &m);
    if (st == OI_OK && !oi__camera_valid(camera)) st = OI_ERR_CAMERA;
    if (st < 0) return batch_fail(st, n, status, out, sizeof *out, 1);
    for (i = 0; i < n; i++) {
        status[i] = oi_expose_scene(camera, &scenes[i], &illum[i], model, goal, &out[i]);
        bad += status[i] < 0;
    }
    return (int)bad;
}

#endif /* OI_NO_EXPOSURE */
