/* SPDX-License-Identifier: MIT */
/*
 * batch.c: the batch calls, the single calls over caller-owned arrays with
 * the model (and the camera) validated once per batch
 * (include/orbillum/batch.h). Each row goes through the same internal function the single
 * call uses, so its outputs are the single call's bits; the savings are the
 * model's validation per row and, in oi_sun_fraction_batch and
 * oi_illuminate_batch_outputs (src/scene/illuminate_outputs.c), what the outputs
 * mask leaves out. oi_sun_fraction_batch also runs the rows certainly in the
 * sphere's penumbra through the crescent kernel the single call uses for
 * them (src/shadow/sun_crescent.h), eight rows at a time in a vectorised loop.
 */
#include "batch/batch_internal.h"
#include "fp_quiet.h"
#include "shadow/sun_crescent.h"

/* The checks common to every batch: n, the required pointers. */
static int check_n(long n)
{
    if (n < 0 || n > OI_BATCH_MAX) return OI_ERR_INPUT;
    return OI_OK;
}

/* ---------------------------------------------------------------- Sun */

#define ROW_UNSURE OI__ROW_UNSURE
#define ROW_LIT OI__ROW_LIT
#define ROW_UMBRA OI__ROW_UMBRA
/* certainly in the sphere's penumbra (classify_block only): the crescent
 * kernel's row (src/shadow/sun_crescent.h) */
#define ROW_PENUMBRA (OI__ROW_UMBRA + 1)
#define COS_MARGIN OI__CERTAIN_COS_MARGIN
#define GRAZING_TOP_KM OI__GRAZING_TOP_KM

/* Rows classified at once by classify_block. */
#define CLASSIFY_ROWS 32


/*
 * oi__sun_certain_region over CLASSIFY_ROWS rows at once, written so that
 * the compiler vectorises the loop (a fixed count, no call, every value and
 * condition an oi_real, the divisors replaced where a row is not decided;
 * gcc -fopt-info-vec, docs/performance.md). The same tests with the same
 * margins, and stricter checks of the positions: both plain norms within
 * OI_POSITION_MAX_KM (so every component, and the norms neither overflow
 * nor underflow to a wrong decision: |point| > 1.001 R), |sun| > 1.001
 * (R_sun + R), |sun - point| > 1.001 R_sun; the plain norms differ from the full call's scaled
 * ones by a few ulp, far inside those margins and COS_MARGIN. With
 * penumbra_too (the sphere, the uniform disc's fraction alone asked) also
 * ROW_PENUMBRA: the single call's region is then PENUMBRA too. LIT is
 * tested against lit_radius, the Earth's radius enlarged by GRAZING_TOP_KM
 * as in oi__sun_certain_region, or (the sphere, the atmosphere not asked: the
 * fractions then the discs' alone) the sphere's own radius, as the umbra's
 * test is. code[i]: ROW_* as oi_real.
 */
static OI_VECTORISE_COMPARES OI_AVX2_CLONES void
classify_block(const oi_real *restrict sun, const oi_real *restrict p, const oi_model *m,
               oi_real lit_radius, oi_real umbra_too, oi_real penumbra_too,
               oi_real *restrict code)
{
    const oi_real re = m->earth_radius_km, rs = m->sun_radius_km, r_umbra = oi__umbra_radius(m);
    const oi_real far = (oi_real)OI_POSITION_MAX_KM;
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
        oi_real cos_sep, sin_sep2, sin_sep, lit, umb, pen;
        /* both norms bounded, so every component (squares to 3e24 do not
         * overflow; a NaN, an infinity or an overflowed square fails every
         * comparison) */
        /* (three short conditions each: a longer chain is not if-converted) */
        ok = ds <= far && dp0 <= far ? one : zero;
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
        sin_e = lit_radius / dp;
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
        /* the penumbra (the sphere's): r_e - r_s < sep < r_e + r_s, cosines
         * of both sides apart by the margin */
        pen = cos_sep < cos_r * cos_s + sin_r * sin_s - COS_MARGIN &&
                      cos_sep > cos_r * cos_s - sin_r * sin_s + COS_MARGIN
                  ? ok * penumbra_too
                  : zero;
        /* exclusive regions (lit: apart, umbra: inside, penumbra: between) */
        umb -= umb * lit;
        pen *= (one - lit) * (one - umb);
        code[i] = lit * (oi_real)ROW_LIT + umb * (oi_real)ROW_UMBRA + pen * (oi_real)ROW_PENUMBRA;
    }
}

#ifdef OI_CRESCENT_KERNEL
/* Rows of the penumbra computed at once by crescent_block. */
#define CRESCENT_ROWS 8

/* oi__crescent_row over the CRESCENT_ROWS rows row[] of sun and p (3 per
 * row), read where they are (no copy), in a loop of fixed count that the
 * compiler vectorises (gcc -fopt-info-vec, docs/performance.md); of the
 * first n rows, the fraction written into out[row[i]].fraction where it is
 * the kernel's (in its domain). Returns the others, bit i for row[i]. */
static OI_VECTORISE_COMPARES OI_AVX2_CLONES unsigned
crescent_block(const oi_real *restrict sun, const oi_real *restrict p,
               const long *restrict row, int n, oi_real re_km, oi_real rs_km,
               oi_shadow *restrict out)
{
    oi_real frac[CRESCENT_ROWS], dom[CRESCENT_ROWS];
    unsigned outside = 0u;
    int i;
    for (i = 0; i < CRESCENT_ROWS; i++) {
        const long r = 3 * row[i];
        frac[i] = oi__crescent_row(sun[r], sun[r + 1], sun[r + 2], p[r], p[r + 1], p[r + 2],
                                   re_km, rs_km, &dom[i]);
    }
    for (i = 0; i < n; i++) {
        if (dom[i] != (oi_real)0)
            out[row[i]].fraction = frac[i];
        else
            outside |= 1u << i;
    }
    return outside;
}

/* The rows classify_block found in the penumbra, gathered for crescent_block. */
typedef struct {
    long row[CRESCENT_ROWS];
    int n;
} crescent_rows;
#endif

/* The outputs of the rows classify_block decides, by ROW_*: the full call's
 * fractions (1 or 0) and region, the fields the mask leaves out 0 (padding
 * too, set once here: each decided row is one copy of its template).
 * ROW_PENUMBRA's template only with the crescent kernel: without it no row
 * is ROW_PENUMBRA (classify_block's penumbra_too is 0). */
#ifdef OI_CRESCENT_KERNEL
#define DECIDED_ROWS (ROW_PENUMBRA + 1)
#else
#define DECIDED_ROWS (ROW_UMBRA + 1)
#endif
typedef struct {
    oi_shadow row[DECIDED_ROWS];
} decided_rows;

static void decided_templates(unsigned outputs, decided_rows *d)
{
    int r;
    memset(d, 0, sizeof *d);
    for (r = ROW_LIT; r <= ROW_UMBRA; r++) {
        const oi_real f = r == ROW_LIT ? (oi_real)1 : (oi_real)0;
        d->row[r].fraction = f;
        if (outputs & OI_BATCH_FRACTION_LD) d->row[r].fraction_ld = f;
        if (outputs & OI_BATCH_ATMOSPHERE) d->row[r].fraction_atm = f;
        d->row[r].region = r == ROW_LIT ? OI_SHADOW_LIT : OI_SHADOW_UMBRA;
    }
#ifdef OI_CRESCENT_KERNEL
    /* the crescent's rows: their fraction written over it */
    d->row[ROW_PENUMBRA].region = OI_SHADOW_PENUMBRA;
#endif
}

/* What is left of a row after decided_block: nothing, the crescent's
 * fraction (crescent_flush), the full call (sun_row). */
#define TODO_NONE 0
#define TODO_CRESCENT 1
#define TODO_FULL 2

/*
 * A classified block's outputs: every row's template by its code, status
 * OI_OK (the rows decided complete; ROW_PENUMBRA's template, its fraction to
 * be written; ROW_UNSURE's, all 0, written over by the full call), and
 * todo[i], what the caller has left to do for the row (TODO_*).
 * One pass of copies of whole records in place of a branch, a memset and
 * stores a row.
 */
static OI_AVX2_CLONES void decided_block(const oi_real *restrict code,
                                        const decided_rows *restrict d,
                                        oi_shadow *restrict out, int *restrict status,
                                        unsigned char *restrict todo)
{
    static const unsigned char todo_of[ROW_PENUMBRA + 1] = {
        [ROW_UNSURE] = TODO_FULL, [ROW_LIT] = TODO_NONE, [ROW_UMBRA] = TODO_NONE,
        [ROW_PENUMBRA] = TODO_CRESCENT};
    int i;
    for (i = 0; i < CLASSIFY_ROWS; i++) status[i] = OI_OK;
    /* two rows a step: half the loop's own instructions */
    for (i = 0; i < CLASSIFY_ROWS; i += 2) {
        const int r0 = (int)code[i], r1 = (int)code[i + 1];
        memcpy(&out[i], &d->row[r0], sizeof out[i]);
        memcpy(&out[i + 1], &d->row[r1], sizeof out[i + 1]);
        todo[i] = todo_of[r0];
        todo[i + 1] = todo_of[r1];
    }
}

/* No row of todo[0..7] left to the caller (one 8-byte load, not eight). */
static int no_todo8(const unsigned char *todo)
{
    static const unsigned char none[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    return memcmp(todo, none, sizeof none) == 0;
}

#ifdef OI_CRESCENT_KERNEL
/* Every row of todo[0..7] a penumbra row for the crescent. */
static int crescent_todo8(const unsigned char *todo)
{
    static const unsigned char all[8] = {TODO_CRESCENT, TODO_CRESCENT, TODO_CRESCENT,
                                         TODO_CRESCENT, TODO_CRESCENT, TODO_CRESCENT,
                                         TODO_CRESCENT, TODO_CRESCENT};
    return memcmp(todo, all, sizeof all) == 0;
}
#endif

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

#ifdef OI_CRESCENT_KERNEL
/* The gathered penumbra rows through crescent_block (the unused rows the
 * first again), their outputs written: the crescent's fraction where it
 * holds (into the penumbra's template decided_block wrote, status OI_OK),
 * the full call elsewhere. Returns the rows with an error. */
static long crescent_flush(crescent_rows *c, const oi_real *sun_km, const oi_real *point_km,
                           const oi_model *m, unsigned outputs, oi_shadow *out, int *status)
{
    unsigned outside;
    long bad = 0;
    int j;
    oi_fp_status fp;
    for (j = c->n; j < CRESCENT_ROWS; j++) c->row[j] = c->row[0];
    fp = oi__fp_quiet_begin();
    outside = crescent_block(sun_km, point_km, c->row, c->n, m->earth_radius_km,
                             m->sun_radius_km, out);
    oi__fp_quiet_end(fp);
    if (outside != 0u) {
        for (j = 0; j < c->n; j++) {
            const long i = c->row[j];
            if (!(outside & (1u << j))) continue;
            status[i] = sun_row(sun_km + 3 * i, point_km + 3 * i, m, outputs, &out[i]);
            bad += status[i] < 0;
        }
    }
    c->n = 0;
    return bad;
}

/* Row i appended to the gathered penumbra rows, which go through
 * crescent_flush when there are CRESCENT_ROWS. Returns the rows with an
 * error. */
static long crescent_push(crescent_rows *c, long i, const oi_real *sun_km,
                          const oi_real *point_km, const oi_model *m, unsigned outputs,
                          oi_shadow *out, int *status)
{
    c->row[c->n++] = i;
    return c->n == CRESCENT_ROWS ? crescent_flush(c, sun_km, point_km, m, outputs, out, status)
                                 : 0;
}
#endif

int oi_sun_fraction_batch(long n, const oi_real *sun_km, const oi_real *point_km,
                          const oi_model *model, unsigned outputs, oi_shadow *out,
                          int *status)
{
    oi_model m;
    oi__span in[2], o[2];
    decided_rows decided;
    unsigned char todo[CLASSIFY_ROWS];
    oi_real code[CLASSIFY_ROWS];
    long b, bad = 0;
    int st, atm_on = 0;
    oi_real pen_on = (oi_real)0, lit_radius;
#ifdef OI_CRESCENT_KERNEL
    crescent_rows pending;
    pending.n = 0;
#endif
    if (n == 0) return 0;
    if (check_n(n) != OI_OK) return OI_ERR_INPUT; /* nothing written: n is not the arrays' */
    if (sun_km == NULL || point_km == NULL || out == NULL || status == NULL)
        return oi__batch_fail(OI_ERR_NULL, n, status, NULL, 0, 0);
    if (!oi__span_of(sun_km, n, 3 * sizeof *sun_km, OI_ALIGN_OF(oi_real), &in[0]) ||
        !oi__span_of(point_km, n, 3 * sizeof *point_km, OI_ALIGN_OF(oi_real), &in[1]) ||
        !oi__span_of(out, n, sizeof *out, OI_ALIGN_OF(oi_shadow), &o[0]) ||
        !oi__span_of(status, n, sizeof *status, OI_ALIGN_OF(int), &o[1]) ||
        oi__check_overlap(in, 2, o, 2) != OI_OK)
        return oi__batch_fail(OI_ERR_INPUT, n, status, NULL, 0, 0);
    st = (outputs & ~(unsigned)OI_BATCH_ALL) != 0u ? OI_ERR_FLAGS : oi__model_resolve(model, &m);
    if (st < 0) return oi__batch_fail(st, n, status, out, sizeof *out, 1);
#ifndef OI_NO_ATMOSPHERE
    atm_on = (outputs & OI_BATCH_ATMOSPHERE) && !m.no_atmosphere;
#endif
#ifdef OI_CRESCENT_KERNEL
    /* the penumbra's rows through the crescent kernel: the uniform disc's
     * fraction alone asked, behind the sphere (src/shadow/sun_crescent.h) */
    if ((outputs & OI_BATCH_ALL) == 0u && m.earth_shape == OI_EARTH_SPHERE) pen_on = (oi_real)1;
#endif
    /* the rays grazing the atmosphere's window are lit by the discs alone
     * where the atmosphere is not asked (the sphere: the ellipsoid's exact
     * silhouette keeps the window) */
    lit_radius = m.earth_radius_km;
    if (atm_on || m.earth_shape != OI_EARTH_SPHERE) lit_radius += GRAZING_TOP_KM;
    decided_templates(outputs, &decided);
    /* written by classify_block and decided_block (through the clones'
     * resolver, which a static analyser cannot follow: set once here) */
    memset(code, 0, sizeof code);
    memset(todo, 0, sizeof todo);
    for (b = 0; b < n; b += CLASSIFY_ROWS) {
        const int k = n - b < CLASSIFY_ROWS ? (int)(n - b) : CLASSIFY_ROWS;
        int j;
        /* without the geometry asked, the rows certainly lit (or in the
         * umbra, or in the penumbra) first, from cosines; the others in full */
        if (!(outputs & OI_BATCH_GEOMETRY) && k == CLASSIFY_ROWS) {
            const oi_fp_status fp = oi__fp_quiet_begin();
            classify_block(sun_km + 3 * b, point_km + 3 * b, &m, lit_radius,
                           atm_on ? (oi_real)0 : (oi_real)1, pen_on, code);
            oi__fp_quiet_end(fp);
            decided_block(code, &decided, out + b, status + b, todo);
            /* eight rows at a time: all decided, all the crescent's, or one by one */
            for (j = 0; j < k; j += 8) {
                int t;
                if (no_todo8(&todo[j])) continue;
#ifdef OI_CRESCENT_KERNEL
                if (crescent_todo8(&todo[j])) {
                    for (t = 0; t < 8; t++)
                        bad += crescent_push(&pending, b + j + t, sun_km, point_km, &m,
                                             outputs, out, status);
                    continue;
                }
#endif
                for (t = 0; t < 8; t++) {
                    const long i = b + j + t;
#ifdef OI_CRESCENT_KERNEL
                    if (todo[j + t] == TODO_CRESCENT) {
                        bad += crescent_push(&pending, i, sun_km, point_km, &m, outputs, out,
                                             status);
                        continue;
                    }
#endif
                    if (todo[j + t] == TODO_NONE) continue;
                    status[i] = sun_row(sun_km + 3 * i, point_km + 3 * i, &m, outputs, &out[i]);
                    bad += status[i] < 0;
                }
            }
            continue;
        }
        /* the geometry asked, or the last rows: one by one (the block's loop
         * has a fixed count, which lets -O2 vectorise it) */
        for (j = 0; j < k; j++) {
            const long i = b + j;
            const int r = outputs & OI_BATCH_GEOMETRY
                              ? ROW_UNSURE
                              : oi__sun_certain_region(sun_km + 3 * i, point_km + 3 * i, &m,
                                                       !atm_on);
            if (r != ROW_UNSURE) {
                memcpy(&out[i], &decided.row[r], sizeof out[i]);
                status[i] = OI_OK;
            } else {
                status[i] = sun_row(sun_km + 3 * i, point_km + 3 * i, &m, outputs, &out[i]);
                bad += status[i] < 0;
            }
        }
    }
#ifdef OI_CRESCENT_KERNEL
    if (pending.n > 0) bad += crescent_flush(&pending, sun_km, point_km, &m, outputs, out, status);
#endif
    return (int)bad;
}

/* ---------------------------------------------------------------- earthshine */

/* oi_earthshine_batch's arrays' alignment and overlap (the spans in this
 * frame only, not under the rows' calls): OI_OK or OI_ERR_INPUT. */
static OI_NOINLINE int earthshine_arrays(long n, const oi_real *theta, const oi_real *h_km,
                                         const oi_real *phi, const oi_real *psi,
                                         const int *status)
{
    oi__span in[2], o[3];
    if (!oi__span_of(theta, n, sizeof *theta, OI_ALIGN_OF(oi_real), &in[0]) ||
        !oi__span_of(h_km, n, sizeof *h_km, OI_ALIGN_OF(oi_real), &in[1]) ||
        !oi__span_of(phi, n, sizeof *phi, OI_ALIGN_OF(oi_real), &o[0]) ||
        !oi__span_of(psi, n, sizeof *psi, OI_ALIGN_OF(oi_real), &o[1]) ||
        !oi__span_of(status, n, sizeof *status, OI_ALIGN_OF(int), &o[2]))
        return OI_ERR_INPUT;
    return oi__check_overlap(in, 2, o, 3);
}

int oi_earthshine_batch(long n, const oi_real *theta, const oi_real *h_km,
                        const oi_model *model, oi_real *phi, oi_real *psi, int *status)
{
    oi_model m;
    oi_real psi_row;
    long i, bad = 0;
    int st;
    if (n == 0) return 0;
    if (check_n(n) != OI_OK) return OI_ERR_INPUT; /* nothing written: n is not the arrays' */
    if (theta == NULL || h_km == NULL || phi == NULL || status == NULL)
        return oi__batch_fail(OI_ERR_NULL, n, status, NULL, 0, 0);
    if (earthshine_arrays(n, theta, h_km, phi, psi, status) != OI_OK)
        return oi__batch_fail(OI_ERR_INPUT, n, status, NULL, 0, 0);
    st = oi__model_resolve(model, &m);
    if (st < 0) {
        if (psi != NULL) memset(psi, 0, (size_t)n * sizeof *psi);
        return oi__batch_fail(st, n, status, phi, sizeof *phi, 1);
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
    oi__span in[1], o[2];
    if (check_n(n) != OI_OK) return OI_ERR_INPUT; /* nothing written: n is not the arrays' */
    if (scenes == NULL || out == NULL || status == NULL)
        return oi__batch_fail(OI_ERR_NULL, n, status, NULL, 0, 0);
    if (!oi__span_of(scenes, n, sizeof *scenes, OI_ALIGN_OF(oi_scene), &in[0]) ||
        !oi__span_of(out, n, sizeof *out, OI_ALIGN_OF(oi_illum), &o[0]) ||
        !oi__span_of(status, n, sizeof *status, OI_ALIGN_OF(int), &o[1]) ||
        oi__check_overlap(in, 1, o, 2) != OI_OK)
        return oi__batch_fail(OI_ERR_INPUT, n, status, NULL, 0, 0);
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
    if (st < 0) return oi__batch_fail(st, n, status, out, sizeof *out, 1);
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
