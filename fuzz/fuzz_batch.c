/* SPDX-License-Identifier: MIT */
/*
 * fuzz_batch.c: libFuzzer target for the batch calls (oi_sun_fraction_batch,
 * oi_earthshine_batch, oi_illuminate_batch(_outputs),
 * oi_expose(_scene)_batch(_outputs)) over fuzzed rows and hostile arrays
 * (n < 0, n = 0, NULL, unknown mask bits, misaligned or overlapping
 * outputs). Invariants: the function value is the number of rows in error,
 * or a batch error with every status set to it (nothing written for n < 0);
 * every status is a documented one; a row in error is zeroed; an OK row
 * has no NaN and is, bit for bit, the single call's (the masked calls: the
 * full batch's fields they ask for, the others 0).
 */
#include "fuzz_common.h"

#define ROWS 8

static oi_real f_sun[3 * ROWS], f_pt[3 * ROWS], f_th[ROWS], f_h[ROWS];
static oi_real f_phi[ROWS], f_psi[ROWS];
static oi_shadow f_sh[ROWS + 1], f_sh1;
static oi_scene f_sc[ROWS];
static oi_illum f_il[ROWS + 1], f_il1;
static int f_st[ROWS + 1], f_st2[ROWS];
#ifndef OI_NO_EXPOSURE
static oi_expose_in f_in[ROWS];
static oi_exposure f_ex[ROWS + 1], f_ex2[ROWS], f_ex1;
#endif

/* The arrays' hostility, from one byte: the row count and what is wrong. */
typedef struct {
    long n;          /* rows passed (may be < 0 or 0) */
    int null_out;    /* the output array NULL */
    int misaligned;  /* the output array off by one byte */
    int overlap;     /* the status array over the output */
    unsigned junk;   /* unknown mask bits to add */
} fz_arrays;

static void fz_arrays_of(fz_in *in, fz_arrays *a)
{
    uint8_t b = fz_u8(in), h = fz_u8(in);
    a->n = (long)(b % (ROWS + 1));
    if ((h & 0x07) == 1) a->n = -(long)(1 + b % 3);
    a->null_out = (h & 0x07) == 2;
    a->misaligned = (h & 0x07) == 3;
    a->overlap = (h & 0x07) == 4;
    a->junk = (h & 0x07) == 5 ? 1u << (6 + (h >> 4)) : 0u;
}

/* A real is fully zero (either sign), or all bits of a struct are zero. */
static int all_zero(const void *p, size_t size)
{
    const unsigned char *c = p;
    size_t i;
    for (i = 0; i < size; i++)
        if (c[i] != 0) return 0;
    return 1;
}

static int same_bits(const void *a, const void *b, size_t size)
{
    return memcmp(a, b, size) == 0;
}

/* No NaN among the n reals at p (a record's oi_real fields, by name). */
static int no_nan(const oi_real *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (p[i] != p[i]) return 0;
    return 1;
}

/* The function value and statuses of a call over a's rows: a batch error
 * sets every status (n > 0) or none (n < 0); else the value counts the
 * rows in error. Returns 1 when the rows were computed. */
static int check_result(int r, const fz_arrays *a, const int *st)
{
    long i, bad = 0;
    if (a->n < 0) {
        FZ_CHECK(r == OI_ERR_INPUT);
        for (i = 0; i < ROWS; i++) FZ_CHECK(f_st[i] == 12345);
        return 0;
    }
    if (a->n == 0) {
        FZ_CHECK(r == 0);
        return 0;
    }
    if (r < 0) {
        FZ_CHECK(fz_known_status(r));
        if (!a->overlap)
            for (i = 0; i < a->n; i++) FZ_CHECK(st[i] == r);
        return 0;
    }
    FZ_CHECK(!a->null_out && !a->misaligned && !a->overlap && a->junk == 0u);
    for (i = 0; i < a->n; i++) {
        FZ_CHECK(fz_known_status(st[i]));
        bad += st[i] < 0;
    }
    FZ_CHECK(r == bad);
    return 1;
}

static void fz_model(fz_in *in, oi_model *m, const oi_model **mp)
{
    uint8_t b = fz_u8(in);
    memset(m, 0, sizeof *m);
    *mp = (b & 1) ? NULL : m;
    if (b & 2) m->no_atmosphere = 1;
    if (b & 4) m->limb_darkening = OI_LIMB_DARKENED;
    if (b & 8) m->earth_shape = OI_EARTH_WGS84;
    if (b & 16) m->tsi_w_m2 = fz_real(in);
    if (b & 32) m->earth_model = OI_EARTH_LAMBERT;
}

static void fill_rows(fz_in *in, long n)
{
    long i;
    for (i = 0; i < n && i < ROWS; i++) {
        oi_scene *s = &f_sc[i];
        fz_vec(in, f_sun + 3 * i);
        fz_vec(in, f_pt + 3 * i);
        f_th[i] = fz_real(in);
        f_h[i] = fz_real(in);
        oi_scene_defaults(s);
        memcpy(s->sun_km, f_sun + 3 * i, sizeof s->sun_km);
        memcpy(s->target_km, f_pt + 3 * i, sizeof s->target_km);
        fz_vec(in, s->observer_km);
        fz_vec(in, s->moon_km);
        s->has_observer = (fz_u8(in) & 7) != 0;
        s->terms = fz_u8(in) & 0x1f;
        if (fz_u8(in) & 1) {
            s->target_vel_km_s[0] = fz_real(in);
            s->observer_vel_km_s[1] = fz_real(in);
        }
        if (fz_u8(in) & 1) s->target_albedo = fz_real(in);
#ifndef OI_NO_EXPOSURE
        f_in[i].flux_w_m2 = fz_real(in);
        f_in[i].background_w_m2_sr = fz_real(in);
        f_in[i].flags = fz_u8(in);
        f_in[i].rate_rad_s = (fz_u8(in) & 1) ? fz_real(in) : 0;
#endif
    }
}

static void *out_of(void *p, size_t size, const fz_arrays *a)
{
    if (a->null_out) return NULL;
    if (a->misaligned) return (unsigned char *)p + 1;
    (void)size;
    return p;
}

static int *status_of(void *out, const fz_arrays *a)
{
    return a->overlap && out != NULL ? (int *)out : f_st;
}

static void do_sun(fz_in *in, const fz_arrays *a, const oi_model *mp)
{
    const unsigned mask = (fz_u8(in) & (unsigned)OI_BATCH_ALL) | a->junk;
    oi_shadow *out = out_of(f_sh, sizeof *f_sh, a);
    int *st = status_of(out, a);
    long i;
    int r;
    memset(f_sh, 0xff, sizeof f_sh);
    r = oi_sun_fraction_batch(a->n, f_sun, f_pt, mp, mask, out, st);
    if (!check_result(r, a, st)) return;
    for (i = 0; i < a->n; i++) {
        int s1 = oi_sun_fraction(f_sun + 3 * i, f_pt + 3 * i, mp, &f_sh1);
        if (st[i] < 0) {
            FZ_CHECK(all_zero(&f_sh[i], sizeof f_sh[i]));
            FZ_CHECK(st[i] == s1);
            continue;
        }
        FZ_CHECK(s1 >= 0);
        FZ_CHECK(no_nan(&f_sh[i].fraction, 1) && no_nan(&f_sh[i].fraction_ld, 1) &&
                 no_nan(&f_sh[i].fraction_atm, 1) && no_nan(&f_sh[i].separation_rad, 1));
        FZ_CHECK(same_bits(&f_sh[i].fraction, &f_sh1.fraction, sizeof f_sh1.fraction));
        FZ_CHECK(f_sh[i].region == f_sh1.region);
    }
}

static void do_earthshine(fz_in *in, const fz_arrays *a, const oi_model *mp)
{
    oi_real *phi = out_of(f_phi, sizeof *f_phi, a);
    int *st = status_of(phi, a);
    fz_arrays b = *a;
    long i;
    int r;
    (void)in;
    b.junk = 0u; /* no mask here: the junk bits are not a fault */
    memset(f_phi, 0xff, sizeof f_phi);
    r = oi_earthshine_batch(a->n, f_th, f_h, mp, phi, f_psi, st);
    if (!check_result(r, &b, st)) return;
    for (i = 0; i < a->n; i++) {
        oi_real p1, q1;
        int s1 = oi_earthshine(f_th[i], f_h[i], mp, &p1, &q1);
        FZ_CHECK(st[i] == s1);
        if (st[i] < 0) continue;
        FZ_CHECK(no_nan(&f_phi[i], 1) && no_nan(&f_psi[i], 1));
        FZ_CHECK(same_bits(&f_phi[i], &p1, sizeof p1) && same_bits(&f_psi[i], &q1, sizeof q1));
    }
}

/* The oi_real fields of an oi_illum checked for NaN. */
static int illum_no_nan(const oi_illum *o)
{
    return no_nan(&o->shadow.fraction, 1) && no_nan(&o->e_sun, 1) && no_nan(&o->e_earth, 1) &&
           no_nan(&o->e_moon, 1) && no_nan(o->dir_sun, 3) && no_nan(o->dir_earth, 3) &&
           no_nan(&o->flux_obs, 1) && no_nan(&o->mag_v, 1) && no_nan(&o->range_km, 1) &&
           no_nan(&o->e_sky, 1) && no_nan(&o->flux_specular, 1);
}

static void do_illuminate(fz_in *in, const fz_arrays *a, const oi_model *mp)
{
    const uint8_t b = fz_u8(in);
    const int masked = b & 1;
    const unsigned mask = ((unsigned)(b >> 1) & (unsigned)OI_BATCH_SCENE_ALL) | a->junk;
    oi_illum *out = out_of(f_il, sizeof *f_il, a);
    int *st = status_of(out, a);
    long i;
    int r;
    memset(f_il, 0xff, sizeof f_il);
    r = masked ? oi_illuminate_batch_outputs(a->n, f_sc, mp, mask, out, st)
               : oi_illuminate_batch(a->n, f_sc, mp, out, st);
    if (!masked && a->junk != 0u) {
        /* no mask in the full call: the junk bits are not a fault there */
        fz_arrays b = *a;
        b.junk = 0u;
        if (!check_result(r, &b, st)) return;
    } else if (!check_result(r, a, st)) {
        return;
    }
    for (i = 0; i < a->n; i++) {
        if (st[i] < 0) {
            FZ_CHECK(all_zero(&f_il[i], sizeof f_il[i]));
            continue;
        }
        FZ_CHECK(illum_no_nan(&f_il[i]));
        if (!masked || mask == (unsigned)OI_BATCH_SCENE_ALL) {
            FZ_CHECK(oi_illuminate(&f_sc[i], mp, &f_il1) == st[i]);
            FZ_CHECK(same_bits(&f_il[i], &f_il1, sizeof f_il1));
        }
    }
}

#ifndef OI_NO_EXPOSURE
static void fz_camera(fz_in *in, oi_camera *c)
{
    uint8_t b = fz_u8(in);
    *c = *oi_camera_builtin(0);
    if (b & 1) c->full_well_e = fz_real(in);
    if (b & 2) c->max_trail_px = fz_real(in);
    if (b & 4) c->detect_false_alarm = (oi_real)1e-6;
    if (b & 8) c->sun_exclusion_rad = fz_real(in);
}

static int exposure_no_nan(const oi_exposure *e)
{
    return no_nan(&e->exposure_s, 1) && no_nan(&e->gain, 1) && no_nan(&e->signal_e, 1) &&
           no_nan(&e->background_e, 1) && no_nan(&e->fill, 1) && no_nan(&e->snr, 1) &&
           no_nan(&e->sun_angle_rad, 1) && no_nan(&e->background_w_m2_sr, 1) &&
           no_nan(&e->rate_rad_s, 1) && no_nan(&e->trail_px, 1) && no_nan(&e->trail_factor, 1) &&
           no_nan(&e->signal_min_e, 1) && no_nan(&e->detect_margin_mag, 1);
}

/* Masked row m against the full row f: each field asked for equal, the
 * others 0. */
static void check_masked(unsigned mask, const oi_exposure *f, const oi_exposure *m)
{
    const int set = (mask & OI_EXPOSE_SETTING) != 0u;
    unsigned flags = f->flags;
    if (!set) flags &= ~(OI_FLAG_SATURATED | OI_FLAG_BACKGROUND_SATURATED);
    if (!(mask & OI_EXPOSE_FAINT)) flags &= ~OI_FLAG_TOO_FAINT;
    if (!(mask & (OI_EXPOSE_SETTING | OI_EXPOSE_FAINT))) flags &= ~OI_FLAG_TRAILED;
    FZ_CHECK(m->flags == flags);
    FZ_CHECK(set ? same_bits(&m->exposure_s, &f->exposure_s, sizeof f->exposure_s)
                 : m->exposure_s == 0);
    FZ_CHECK(set ? same_bits(&m->snr, &f->snr, sizeof f->snr) : m->snr == 0);
    FZ_CHECK(set ? m->time_index == f->time_index : m->time_index == 0);
    FZ_CHECK((mask & OI_EXPOSE_DETECT)
                 ? same_bits(&m->detect_margin_mag, &f->detect_margin_mag, sizeof f->snr)
                 : m->detect_margin_mag == 0);
    FZ_CHECK((mask & OI_EXPOSE_SUN_ANGLE)
                 ? same_bits(&m->sun_angle_rad, &f->sun_angle_rad, sizeof f->snr)
                 : m->sun_angle_rad == 0);
    FZ_CHECK((mask & OI_EXPOSE_BACKGROUND)
                 ? same_bits(&m->background_w_m2_sr, &f->background_w_m2_sr, sizeof f->snr)
                 : m->background_w_m2_sr == 0);
    FZ_CHECK((mask & OI_EXPOSE_RATE) ? same_bits(&m->rate_rad_s, &f->rate_rad_s, sizeof f->snr)
                                     : m->rate_rad_s == 0);
}

static void do_expose(fz_in *in, const fz_arrays *a, const oi_model *mp, int scene)
{
    oi_camera cam;
    oi_expose_goal g, *gp;
    const uint8_t b = fz_u8(in);
    const unsigned mask = ((unsigned)fz_u8(in) & (unsigned)OI_EXPOSE_ALL) | a->junk;
    oi_exposure *out = out_of(f_ex, sizeof *f_ex, a);
    int *st = status_of(out, a);
    long i;
    int r, r2;
    fz_camera(in, &cam);
    memset(&g, 0, sizeof g);
    gp = (b & 1) ? NULL : &g;
    if (b & 2) g.fill = fz_real(in);
    g.sky = (unsigned)(b >> 2) & 7u;
    if (b & 0x20) {
        g.has_sensor_temp = 1u;
        g.sensor_temp_c = fz_real(in);
    }
    if (scene) {
        long k = a->n < 0 ? 0 : a->n;
        (void)oi_illuminate_batch(k, f_sc, mp, f_il, f_st2);
    }
    memset(f_ex, 0xff, sizeof f_ex);
    /* the full batch first (no hostility but the rows'), then the masked one */
    r2 = scene ? oi_expose_scene_batch(a->n < 0 ? 0 : a->n, &cam, f_sc, f_il, mp, gp, f_ex2, f_st2)
               : oi_expose_batch(a->n < 0 ? 0 : a->n, &cam, f_in, gp, f_ex2, f_st2);
    r = scene ? oi_expose_scene_batch_outputs(a->n, &cam, f_sc, f_il, mp, gp, mask, out, st)
              : oi_expose_batch_outputs(a->n, &cam, f_in, gp, mask, out, st);
    if (!check_result(r, a, st)) return;
    FZ_CHECK(r2 >= 0);
    for (i = 0; i < a->n; i++) {
        if (st[i] != f_st2[i]) {
            /* documented: without the choice and the background, the
             * background's checks (OI_ERR_NONFINITE, OI_ERR_INPUT) are not
             * made */
            FZ_CHECK((mask & (OI_EXPOSE_SETTING | OI_EXPOSE_FAINT | OI_EXPOSE_DETECT |
                              OI_EXPOSE_BACKGROUND)) == 0u);
            FZ_CHECK((f_st2[i] == OI_ERR_INPUT || f_st2[i] == OI_ERR_NONFINITE) && st[i] >= 0);
            r++; /* counted in the full batch's value */
            continue;
        }
        if (st[i] < 0) {
            FZ_CHECK(all_zero(&f_ex[i], sizeof f_ex[i]));
            continue;
        }
        FZ_CHECK(exposure_no_nan(&f_ex[i]));
        check_masked(mask, &f_ex2[i], &f_ex[i]);
        if (!scene) {
            FZ_CHECK(oi_expose(&cam, &f_in[i], gp, &f_ex1) == st[i]);
        } else {
            FZ_CHECK(oi_expose_scene(&cam, &f_sc[i], &f_il[i], mp, gp, &f_ex1) == st[i]);
        }
        FZ_CHECK(same_bits(&f_ex1, &f_ex2[i], sizeof f_ex1));
    }
    FZ_CHECK(r == r2);
}
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    fz_arrays a;
    oi_model m;
    const oi_model *mp;
    uint8_t sel;
    in.p = data;
    in.n = size;
    sel = fz_u8(&in);
    fz_arrays_of(&in, &a);
    fz_model(&in, &m, &mp);
    fill_rows(&in, a.n < 0 ? 0 : a.n);
    memset(f_st, 0, sizeof f_st);
    if (a.n < 0) {
        int i;
        for (i = 0; i < ROWS; i++) f_st[i] = 12345;
    }
    switch (sel % 5) {
    case 0: do_sun(&in, &a, mp); break;
    case 1: do_earthshine(&in, &a, mp); break;
    case 2: do_illuminate(&in, &a, mp); break;
#ifndef OI_NO_EXPOSURE
    case 3: do_expose(&in, &a, mp, 0); break;
    case 4: do_expose(&in, &a, mp, 1); break;
#endif
    default: break;
    }
    return 0;
}
