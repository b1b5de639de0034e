/* SPDX-License-Identifier: MIT */
/*
 * stab_dump.c: every double-precision stability vector (tests/stability/
 * vectors.h) through the runtime, printed as the bit patterns of the
 * outputs. Built twice, natively and for wasm32 (run under node's WASI), by
 * `make test-wasm`: the two dumps must be identical (tests/browser/
 * test_wasm.mjs compares them and names any output that differs).
 * Line: table index status region bits0 bits1 ...
 * The batch calls follow: each over a whole table's vectors in one call
 * (the rows as the single evaluators form them), under the name
 * <table>_batch (and <table>_mask for an outputs mask).
 */
#include <stdio.h>
#include <string.h>

#include "orbillum.h"
#include "stability/vectors.h"
#include "stability/evaluators.h"

/* The table's phi and psi at the vector's (theta, h). */
static int ev_earth_table(const double *in, double *got, int *region)
{
    oi_real phi, psi;
    int st = oi_earthshine((oi_real)in[0], (oi_real)in[1], NULL, &phi, &psi);
    (void)region;
    got[0] = (double)phi;
    got[1] = (double)psi;
    return st;
}

typedef int (*eval_fn)(const double *in, double *got, int *region);

static void bits(double x)
{
    unsigned long long u;
    memcpy(&u, &x, sizeof u);
    printf(" %016llx", u);
}

static void dump(const char *name, const stab_vec *v, size_t n, int nout, eval_fn f)
{
    size_t i;
    for (i = 0; i < n; i++) {
        double got[STAB_MAX_OUT];
        int region = -1, k, st;
        memset(got, 0, sizeof got);
        st = f(v[i].in, got, &region);
        printf("%s %lu %d %d", name, (unsigned long)i, st, region);
        for (k = 0; k < nout; k++) bits(got[k]);
        printf("\n");
    }
}

#define DUMP(name, nout, f) dump(#name, stab_##name##_d, \
                                 sizeof stab_##name##_d / sizeof stab_##name##_d[0], nout, f)

/* ---------------------------------------------------------------- batches */

#define BATCH_MAX 512
#define NV(name) (sizeof stab_##name##_d / sizeof stab_##name##_d[0])
/* every vector table fits the batch arrays (a compile error otherwise) */
typedef char stab_batch_fits[NV(shadow) <= BATCH_MAX && NV(earth_table) <= BATCH_MAX &&
                                     NV(illum) <= BATCH_MAX && NV(camera) <= BATCH_MAX
                                 ? 1
                                 : -1];

static oi_real b_sun[3 * BATCH_MAX], b_pt[3 * BATCH_MAX], b_th[BATCH_MAX], b_h[BATCH_MAX];
static oi_real b_phi[BATCH_MAX], b_psi[BATCH_MAX];
static oi_shadow b_sh[BATCH_MAX];
static oi_scene b_sc[BATCH_MAX];
static oi_illum b_il[BATCH_MAX];
static oi_expose_in b_in[BATCH_MAX];
static oi_exposure b_ex[BATCH_MAX];
static int b_st[BATCH_MAX];

static void line_of(const char *name, size_t i, int st, int region, const double *got, int nout)
{
    int k;
    printf("%s %lu %d %d", name, (unsigned long)i, st, region);
    for (k = 0; k < nout; k++) bits(got[k]);
    printf("\n");
}

/* oi_sun_fraction_batch over the shadow vectors (ev_shadow's model). */
static void dump_shadow_batch(const char *name, unsigned outputs)
{
    const size_t n = NV(shadow);
    oi_model geo;
    size_t i;
    int k;
    memset(&geo, 0, sizeof geo);
    geo.no_atmosphere = 1;
    for (i = 0; i < n; i++)
        for (k = 0; k < 3; k++) {
            b_sun[3 * i + k] = (oi_real)stab_shadow_d[i].in[k];
            b_pt[3 * i + k] = (oi_real)stab_shadow_d[i].in[3 + k];
        }
    (void)oi_sun_fraction_batch((long)n, b_sun, b_pt, &geo, outputs, b_sh, b_st);
    for (i = 0; i < n; i++) {
        const oi_shadow *s = &b_sh[i];
        const double got[6] = {(double)s->fraction, (double)s->sun_radius_rad,
                               (double)s->earth_radius_rad, (double)s->separation_rad,
                               (double)s->sun_distance_km, (double)s->fraction_ld};
        line_of(name, i, b_st[i], s->region, got, 6);
    }
}

static void dump_earth_table_batch(void)
{
    const size_t n = NV(earth_table);
    size_t i;
    for (i = 0; i < n; i++) {
        b_th[i] = (oi_real)stab_earth_table_d[i].in[0];
        b_h[i] = (oi_real)stab_earth_table_d[i].in[1];
    }
    (void)oi_earthshine_batch((long)n, b_th, b_h, NULL, b_phi, b_psi, b_st);
    for (i = 0; i < n; i++) {
        const double got[2] = {(double)b_phi[i], (double)b_psi[i]};
        line_of("earth_table_batch", i, b_st[i], -1, got, 2);
    }
}

/* The illum vectors' scenes (as ev_illum) into b_sc; their count. */
static size_t illum_scenes(oi_model *m)
{
    const size_t n = NV(illum);
    size_t i;
    for (i = 0; i < n; i++) {
        oi_scene *s = &b_sc[i];
        oi_scene_defaults(s);
        to_r3(stab_illum_d[i].in, s->sun_km);
        to_r3(stab_illum_d[i].in + 3, s->target_km);
        to_r3(stab_illum_d[i].in + 6, s->observer_km);
        s->has_observer = 1;
        s->terms = OI_TERM_SUN | OI_TERM_EARTH;
        s->earth_albedo = (oi_real)0.3;
        s->target_albedo = (oi_real)0.2;
        s->target_radius_m = (oi_real)1;
    }
    memset(m, 0, sizeof *m);
    m->no_atmosphere = 1;
    m->earth_model = OI_EARTH_LAMBERT;
    return n;
}

/* oi_illuminate_batch (outputs: OI_BATCH_SCENE_ALL) or _outputs (a mask). */
static void dump_illum_batch(const char *name, int masked, unsigned outputs)
{
    oi_model m;
    const size_t n = illum_scenes(&m);
    size_t i;
    if (masked)
        (void)oi_illuminate_batch_outputs((long)n, b_sc, &m, outputs, b_il, b_st);
    else
        (void)oi_illuminate_batch((long)n, b_sc, &m, b_il, b_st);
    for (i = 0; i < n; i++) {
        const oi_illum *o = &b_il[i];
        const double got[7] = {(double)o->e_sun, (double)o->e_earth, (double)o->earth_theta,
                               (double)o->earth_h_km, (double)o->flux_sun, (double)o->mag_v,
                               (double)o->flux_obs};
        line_of(name, i, b_st[i] > 0 ? OI_OK : b_st[i], -1, got, 7);
    }
}

#ifndef OI_NO_EXPOSURE
/* The exposure's two bits of the region code, as ev_camera's
 * (tests/stability/evaluators.h): TOO_FAINT, and a full well (SATURATED or,
 * the background's, BACKGROUND_SATURATED). */
static int well_bits(unsigned flags)
{
    return ((flags & OI_FLAG_TOO_FAINT) ? 1 : 0) +
           ((flags & (OI_FLAG_SATURATED | OI_FLAG_BACKGROUND_SATURATED)) ? 2 : 0);
}

/* The exposure's outputs of a row and its region code (as ev_camera). */
static void expose_line(const char *name, size_t i)
{
    const oi_exposure *e = &b_ex[i];
    const double got[9] = {(double)e->signal_e, (double)e->background_e, (double)e->peak_e,
                           (double)e->fill, (double)e->snr, (double)e->exposure_s,
                           (double)e->sun_angle_rad, (double)e->background_w_m2_sr,
                           (double)e->detect_margin_mag};
    line_of(name, i, b_st[i], e->time_index * 100 + e->gain_index * 10 + well_bits(e->flags),
            got, 9);
}

/* oi_expose_batch (masked: _outputs) over the camera vectors. */
static void dump_camera_batch(const char *name, int masked, unsigned outputs)
{
    const size_t n = NV(camera);
    size_t i;
    for (i = 0; i < n; i++) {
        b_in[i].flux_w_m2 = (oi_real)stab_camera_d[i].in[0];
        b_in[i].background_w_m2_sr = (oi_real)stab_camera_d[i].in[1];
        b_in[i].flags = 0;
        b_in[i].rate_rad_s = 0;
    }
    if (masked)
        (void)oi_expose_batch_outputs((long)n, test_camera(), b_in, NULL, outputs, b_ex, b_st);
    else
        (void)oi_expose_batch((long)n, test_camera(), b_in, NULL, b_ex, b_st);
    for (i = 0; i < n; i++) expose_line(name, i);
}

/* oi_expose_scene_batch (masked: _outputs) over the illum vectors' scenes,
 * lit by oi_illuminate_batch. */
static void dump_expose_scene_batch(const char *name, int masked, unsigned outputs)
{
    oi_model m;
    const size_t n = illum_scenes(&m);
    size_t i;
    (void)oi_illuminate_batch((long)n, b_sc, &m, b_il, b_st);
    if (masked)
        (void)oi_expose_scene_batch_outputs((long)n, test_camera(), b_sc, b_il, &m, NULL,
                                            outputs, b_ex, b_st);
    else
        (void)oi_expose_scene_batch((long)n, test_camera(), b_sc, b_il, &m, NULL, b_ex, b_st);
    for (i = 0; i < n; i++) expose_line(name, i);
}
#endif

int main(void)
{
    DUMP(phase, 1, ev_phase);
    DUMP(moon, 1, ev_moon);
    DUMP(angle, 1, ev_angle);
    DUMP(overlap, 1, ev_overlap);
    DUMP(shadow, 6, ev_shadow);
    DUMP(magnitude, 1, ev_magnitude);
    DUMP(earth_lambert, 1, ev_earth_lambert);
    DUMP(illum, 7, ev_illum);
    DUMP(earth_table, 2, ev_earth_table);
    DUMP(camera, 5, ev_camera);
    dump_shadow_batch("shadow_batch", OI_BATCH_ALL);
    dump_shadow_batch("shadow_mask", 0u);
    dump_earth_table_batch();
    dump_illum_batch("illum_batch", 0, 0u);
    dump_illum_batch("illum_mask", 1, OI_BATCH_OBSERVER);
#ifndef OI_NO_EXPOSURE
    dump_camera_batch("camera_batch", 0, 0u);
    dump_camera_batch("camera_mask", 1, OI_EXPOSE_SETTING | OI_EXPOSE_FAINT);
    dump_expose_scene_batch("expose_scene_batch", 0, 0u);
    dump_expose_scene_batch("expose_scene_mask", 1, OI_EXPOSE_SETTING | OI_EXPOSE_BACKGROUND);
#endif
    return 0;
}
