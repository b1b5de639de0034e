/* SPDX-License-Identifier: MIT */
/*
 * evaluators.h: how each stability-suite table calls the runtime, shared by
 * the host suite (tests/c/test_stability.c) and the Cortex-M self-test
 * (target/golden_stability.c) so both apply the vectors the same way.
 * An evaluator maps a vector's inputs to the runtime's outputs (as double)
 * and returns the status; `region` receives the shadow region where it applies.
 * Include after orbillum.h.
 */
#ifndef OI_STABILITY_EVALUATORS_H
#define OI_STABILITY_EVALUATORS_H

static void to_r3(const double *in, oi_real v[3])
{
    v[0] = (oi_real)in[0];
    v[1] = (oi_real)in[1];
    v[2] = (oi_real)in[2];
}

static int ev_phase(const double *in, double *got, int *region)
{
    (void)region;
    got[0] = (double)oi_lambert_phase((oi_real)in[0]);
    return OI_OK;
}

#ifndef OI_NO_MOON
static int ev_moon(const double *in, double *got, int *region)
{
    (void)region;
    got[0] = (double)oi_moon_phase_law((oi_real)in[0]);
    return OI_OK;
}
#endif

static int ev_angle(const double *in, double *got, int *region)
{
    oi_real a[3], b[3];
    (void)region;
    to_r3(in, a);
    to_r3(in + 3, b);
    got[0] = (double)oi_angle(a, b);
    return OI_OK;
}

static int ev_overlap(const double *in, double *got, int *region)
{
    (void)region;
    got[0] = (double)oi_cap_overlap((oi_real)in[0], (oi_real)in[1], (oi_real)in[2]);
    return OI_OK;
}

static int ev_shadow(const double *in, double *got, int *region)
{
    oi_real sun[3], p[3];
    oi_shadow s;
    oi_model geo; /* the vectors are the geometric (conical) shadow */
    int st;
    memset(&geo, 0, sizeof geo);
    geo.no_atmosphere = 1;
    to_r3(in, sun);
    to_r3(in + 3, p);
    st = oi_sun_fraction(sun, p, &geo, &s);
    got[0] = (double)s.fraction;
    got[1] = (double)s.sun_radius_rad;
    got[2] = (double)s.earth_radius_rad;
    got[3] = (double)s.separation_rad;
    got[4] = (double)s.sun_distance_km;
    got[5] = (double)s.fraction_ld;
    *region = s.region;
    return st;
}

static int ev_magnitude(const double *in, double *got, int *region)
{
    (void)region;
    got[0] = (double)oi_magnitude_v((oi_real)in[0], NULL);
    return OI_OK;
}

static int ev_earth_lambert(const double *in, double *got, int *region)
{
    oi_model m;
    oi_real phi, psi;
    int st;
    (void)region;
    memset(&m, 0, sizeof m);
    m.earth_model = OI_EARTH_LAMBERT;
    st = oi_earthshine((oi_real)in[0], (oi_real)in[1], &m, &phi, &psi);
    got[0] = (double)phi;
    if (psi != 0) return -100;
    return st > 0 ? OI_OK : st;
}

static int ev_illum(const double *in, double *got, int *region)
{
    oi_scene s;
    oi_model m;
    oi_illum o;
    int st;
    (void)region;
    oi_scene_defaults(&s);
    to_r3(in, s.sun_km);
    to_r3(in + 3, s.target_km);
    to_r3(in + 6, s.observer_km);
    s.has_observer = 1;
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
    s.earth_albedo = (oi_real)0.3;
    s.target_albedo = (oi_real)0.2;
    s.target_radius_m = (oi_real)1;
    memset(&m, 0, sizeof m);
    m.no_atmosphere = 1;
    m.earth_model = OI_EARTH_LAMBERT;
    st = oi_illuminate(&s, &m, &o);
    got[0] = (double)o.e_sun;
    got[1] = (double)o.e_earth;
    got[2] = (double)o.earth_theta;
    got[3] = (double)o.earth_h_km;
    got[4] = (double)o.flux_sun;
    got[5] = (double)o.mag_v;
    got[6] = (double)o.flux_obs;
    return st > 0 ? OI_OK : st;
}

#ifndef OI_NO_EXPOSURE
/* The camera of the camera vectors (tests/stability/gen_vectors.py CAM). */
static const oi_camera *test_camera(void)
{
    static oi_camera c;
    static const double times[6] = {1e-4, 1e-3, 1e-2, 0.1, 1, 10};
    static const double gains[3] = {1, 4, 16}, rn[3] = {10, 4, 2};
    int i;
    memset(&c, 0, sizeof c);
    c.name = "stability test camera";
    c.aperture_m = (oi_real)0.15;
    c.focal_length_m = (oi_real)1.2;
    c.pixel_pitch_m = (oi_real)5.5e-6;
    c.transmission = (oi_real)0.8;
    c.quantum_efficiency = (oi_real)0.6;
    c.band_fraction = (oi_real)0.4;
    c.photon_energy_j = (oi_real)3.6e-19;
    c.full_well_e = (oi_real)30000;
    c.dark_current_e_s = (oi_real)10;
    c.psf_peak_fraction = (oi_real)0.3;
    c.fov_rad = (oi_real)0.02;
    c.sun_exclusion_rad = (oi_real)0.5;
    c.n_times = 6;
    c.n_gains = 3;
    for (i = 0; i < 6; i++) c.times_s[i] = (oi_real)times[i];
    for (i = 0; i < 3; i++) {
        c.gains[i] = (oi_real)gains[i];
        c.read_noise_e[i] = (oi_real)rn[i];
    }
    return &c;
}

static int ev_camera(const double *in, double *got, int *region)
{
    oi_expose_in x;
    oi_exposure e;
    int st;
    x.flux_w_m2 = (oi_real)in[0];
    x.background_w_m2_sr = (oi_real)in[1];
    x.flags = 0;
    x.rate_rad_s = 0;
    st = oi_expose(test_camera(), &x, NULL, &e);
    got[0] = (double)e.signal_e;
    got[1] = (double)e.background_e;
    got[2] = (double)e.peak_e;
    got[3] = (double)e.fill;
    got[4] = (double)e.snr;
    /* the choice and two bits: TOO_FAINT, and a full well (fill >= 1:
     * SATURATED or, the background's, BACKGROUND_SATURATED; which one is
     * tests/c/test_flag_rules.c's), as the vectors were generated */
    *region = e.time_index * 100 + e.gain_index * 10 + ((e.flags & OI_FLAG_TOO_FAINT) ? 1 : 0) +
              ((e.flags & (OI_FLAG_SATURATED | OI_FLAG_BACKGROUND_SATURATED)) ? 2 : 0);
    return st;
}
#endif

#endif /* OI_STABILITY_EVALUATORS_H */
