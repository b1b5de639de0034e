/* SPDX-License-Identifier: MIT */
/*
 * fuzz_api.c: libFuzzer target for the public API of include/orbillum.h.
 *
 * The first byte selects a function (or "all"); the rest decodes into its
 * arguments (fuzz_common.h: NaN, +-inf, +-0, subnormals, near-overflow,
 * raw bit patterns and plausible geometry). Invariants, for every call:
 *   - no crash, no ASan/UBSan report (the build aborts on the first one);
 *   - the status is one of enum oi_status;
 *   - on error (status < 0) every output is zero;
 *   - otherwise every real output is finite (outputs are pre-filled with
 *     NaN bit patterns, so an output left unwritten is caught too),
 *     fractions lie in [0, 1], irradiances, fluxes, areas are >= 0,
 *     angles in [0, pi], directions are unit vectors or zero; with a shape
 *     (a fuzzed set of facets or a built-in, a fuzzed attitude), the
 *     specular flux lies in [0, flux_obs].
 * Build and run: make fuzz (mk/analysis.mk).
 */
#include "fuzz_common.h"

#define NAN_FILL(x) memset(&(x), 0xff, sizeof(x))
#define OI_FABS_FZ(x) ((x) < 0 ? -(x) : (x))

static const double PI_D = 3.14159265358979323846;

static int zero_shadow(const oi_shadow *s)
{
    return s->fraction == 0 && s->fraction_ld == 0 && s->fraction_atm == 0 &&
           s->sun_radius_rad == 0 && s->earth_radius_rad == 0 && s->separation_rad == 0 &&
           s->sun_distance_km == 0 && s->region == 0;
}

/* moon_hidden: the part of the Sun the Moon hides (oi_illum.sun_moon_hidden;
 * 0 for oi_sun_fraction): the region is the Earth's shadow, the fraction
 * counts both occulters. */
static void check_shadow(int st, const oi_shadow *s, oi_real moon_hidden)
{
    FZ_CHECK(fz_known_status(st));
    if (st < 0) {
        FZ_CHECK(zero_shadow(s));
        return;
    }
    FZ_CHECK(fz_frac(s->fraction));
    FZ_CHECK(fz_frac(s->fraction_ld));
    FZ_CHECK(fz_frac(s->fraction_atm));
    FZ_CHECK(fz_nonneg(s->sun_radius_rad) && s->sun_radius_rad <= (oi_real)PI_D);
    FZ_CHECK(fz_nonneg(s->earth_radius_rad) && s->earth_radius_rad <= (oi_real)PI_D);
    FZ_CHECK(fz_nonneg(s->separation_rad) && s->separation_rad <= (oi_real)PI_D);
    FZ_CHECK(fz_nonneg(s->sun_distance_km));
    FZ_CHECK(s->region >= OI_SHADOW_LIT && s->region <= OI_SHADOW_ANNULAR);
    /* region and fraction agree: lit sees the whole disc, umbra none */
    if (s->region == OI_SHADOW_LIT && moon_hidden == 0) FZ_CHECK(s->fraction == 1);
    if (s->region == OI_SHADOW_UMBRA) FZ_CHECK(s->fraction == 0);
}

/* Model constants pass through unchanged, NaN, inf, zero, negative,
 * subnormal and huge alike: the model validation (src/model/model.c, bounds
 * OI_MODEL_*) must reject what would overflow (docs/stability.md, findings
 * 7-8, fixed). */
static oi_real fz_model_const(fz_in *in, double def)
{
    (void)def;
    return fz_real(in);
}

static void fz_model(fz_in *in, oi_model *m)
{
    uint8_t flags = fz_u8(in);
    memset(m, 0, sizeof *m);
    if (flags & 1) m->tsi_w_m2 = fz_model_const(in, OI_TSI_W_M2);
    if (flags & 2) m->au_km = fz_model_const(in, OI_AU_KM);
    if (flags & 4) m->sun_radius_km = fz_model_const(in, OI_SUN_RADIUS_KM);
    if (flags & 8) m->earth_radius_km = fz_model_const(in, OI_EARTH_RADIUS_KM);
    if (flags & 16) m->moon_radius_km = fz_model_const(in, OI_MOON_RADIUS_KM);
    if (flags & 32) m->moon_albedo = fz_real(in);
    if (flags & 64) {
        uint8_t o = fz_u8(in);
        /* mostly valid option values, sometimes out of range */
        m->earth_model = (o & 0x80) ? (int)(int8_t)fz_u8(in) : (o & 1);
        m->moon_model = (o >> 1) & 1;
        m->limb_darkening = (o & 0x40) ? 7 : ((o >> 2) & 1);
        m->no_atmosphere = (o >> 3) & 1;
        m->earth_shape = (o >> 4) & 1; /* the sphere or the WGS-84 ellipsoid */
        m->band = (o >> 5) & 1;        /* the V or the total band */
    }
    m->earth_table = NULL; /* a pointer cannot be fuzzed; NULL is the default table */
    if (flags & 128) {
        /* an albedo model: Knocke, or a map of fuzzed values (NaN and out of
         * range included) and dimensions within the array, or an unknown one */
        static float map[8 * 16];
        uint8_t o = fz_u8(in);
        unsigned i;
        m->albedo_model = (o & 0x80) ? (int)(int8_t)fz_u8(in) : 1 + (o & 1);
        for (i = 0; i < sizeof map / sizeof map[0]; i++)
            map[i] = (o & 0x40) ? (float)fz_real(in) : 0.3f;
        m->albedo_map = (o & 0x20) ? NULL : map;
        m->albedo_map_n_lat = 1 + (o >> 1) % 8;
        m->albedo_map_n_lon = 1 + (o >> 2) % 16;
    }
}

static void do_scalars(fz_in *in)
{
    oi_real a[3], b[3], x, y, z, r;
    fz_vec(in, a);
    fz_vec(in, b);
    r = oi_angle(a, b);
    FZ_CHECK(fz_finite(r) && r >= 0 && r <= (oi_real)PI_D * (1 + 4 * FZ_EPS));
    x = fz_real(in);
    r = oi_lambert_phase(x);
    FZ_CHECK(fz_finite(r) && r >= 0 && r <= (oi_real)(2.0 / 3.0) * (1 + 8 * FZ_EPS));
#ifndef OI_NO_MOON
    r = oi_moon_phase_law(x);
    FZ_CHECK(fz_finite(r) && r >= 0 && r <= 1 + 8 * FZ_EPS);
#endif
    x = fz_real(in);
    y = fz_real(in);
    z = fz_real(in);
    r = oi_cap_overlap(x, y, z);
    FZ_CHECK(fz_finite(r) && r >= 0 && r <= (oi_real)(4.0 * PI_D) * (1 + 8 * FZ_EPS));
    if (fz_finite(x) && fz_finite(y) && x >= 0 && y >= 0 && x <= (oi_real)PI_D &&
        y <= (oi_real)PI_D) {
        /* never more than the smaller cap: 2 pi (1 - cos r) = 4 pi sin^2(r/2) */
        double rmin = x < y ? (double)x : (double)y;
        double cap = 4.0 * PI_D * sin(rmin / 2) * sin(rmin / 2);
        FZ_CHECK((double)r <= cap * (1 + 64 * FZ_EPS) + 64 * FZ_MIN_NORMAL);
    }
}

static void do_sun_fraction(fz_in *in)
{
    oi_real sun[3], p[3];
    oi_model m;
    oi_shadow s;
    uint8_t use_model = fz_u8(in);
    int st;
    fz_vec(in, sun);
    fz_vec(in, p);
    fz_model(in, &m);
    NAN_FILL(s);
    st = oi_sun_fraction(sun, p, (use_model & 1) ? &m : NULL, &s);
    check_shadow(st, &s, 0);
    FZ_CHECK(oi_sun_fraction(NULL, p, NULL, &s) == OI_ERR_NULL);
    FZ_CHECK(oi_sun_fraction(sun, p, NULL, NULL) == OI_ERR_NULL);
}

static void do_earthshine(fz_in *in)
{
    oi_model m;
    oi_real theta = fz_real(in), h = fz_real(in), phi, psi;
    uint8_t use_model = fz_u8(in);
    int st;
    fz_model(in, &m);
    NAN_FILL(phi);
    NAN_FILL(psi);
    st = oi_earthshine(theta, h, (use_model & 1) ? &m : NULL, &phi, &psi);
    FZ_CHECK(fz_known_status(st));
    if (st < 0) {
        FZ_CHECK(phi == 0 && psi == 0);
    } else {
        FZ_CHECK(fz_nonneg(phi));
        /* documented: psi in [0, asin(R/r)], and 0 where phi = 0 */
        FZ_CHECK(fz_finite(psi) && psi >= 0 && psi <= (oi_real)(PI_D / 2) * (1 + 4 * FZ_EPS));
        if (phi == 0) FZ_CHECK(psi == 0);
    }
    FZ_CHECK(oi_earthshine(theta, h, NULL, NULL, &psi) == OI_ERR_NULL);
}

#ifndef OI_NO_FACETS
/* The fuzzed shape's storage (the scene points into it during the call). */
static oi_facet fz_facets[4];
static oi_shape fz_shape_store;

/* A shape: a built-in, or up to 4 fuzzed facets (n_facets fuzzed too, so
 * counts out of range are tried), and an attitude. */
static void fz_shape(fz_in *in, oi_scene *s)
{
    uint8_t how = fz_u8(in);
    int i;
    if (how & 1) {
        s->shape = oi_shape_builtin((int)(how >> 1) % 4);
    } else {
        for (i = 0; i < 4; i++) {
            fz_vec(in, fz_facets[i].normal);
            fz_facets[i].area_m2 = fz_real(in);
            fz_facets[i].two_sided = (int)(fz_u8(in) & 1u);
            fz_facets[i].albedo_diffuse = fz_real(in);
            fz_facets[i].albedo_specular = fz_real(in);
            fz_facets[i].shininess = fz_real(in);
        }
        fz_shape_store.facets = (how & 2) ? NULL : fz_facets;
        /* 0..4 (0 is refused; more would read past the array: a caller's bug) */
        fz_shape_store.n_facets = (unsigned)(how >> 2) % 5u;
        fz_shape_store.diffuse_from_scene = (how & 128) != 0;
        fz_shape_store.name = NULL;
        s->shape = &fz_shape_store;
    }
    for (i = 0; i < 4; i++) s->attitude_q[i] = fz_real(in);
    if (how & 64) {
        /* a plausible unit quaternion, so that the facets are reached */
        oi_real n = (oi_real)0;
        for (i = 0; i < 4; i++) n += s->attitude_q[i] * s->attitude_q[i];
        if (n > (oi_real)0 && n < (oi_real)FZ_MAX) {
            n = (oi_real)sqrt((double)n);
            for (i = 0; i < 4; i++) s->attitude_q[i] /= n;
        }
    }
}
#endif

static void fz_scene(fz_in *in, oi_scene *s)
{
    uint8_t flags = fz_u8(in);
    oi_scene_defaults(s);
    fz_vec(in, s->sun_km);
    fz_vec(in, s->target_km);
    fz_vec(in, s->moon_km);
    if (flags & 1) {
        s->has_observer = 1;
        if (flags & 2) {
            /* observer near the target: exercises tiny ranges */
            oi_real d[3];
            int i;
            fz_vec(in, d);
            for (i = 0; i < 3; i++) s->observer_km[i] = s->target_km[i] + d[i];
        } else {
            fz_vec(in, s->observer_km);
        }
    }
    if (flags & 4) s->terms = fz_u8(in) % 16u;
    if (flags & 8) s->earth_albedo = fz_real(in);
    if (flags & 16) s->target_albedo = fz_real(in);
    if (flags & 32) s->target_radius_m = fz_real(in);
#ifndef OI_NO_FACETS
    if (flags & 64) fz_shape(in, s);
#endif
    if (flags & 128) {
        /* the albedo models' epoch and Earth rotation (read only by them) */
        s->epoch_jd = (flags & 64) ? fz_real(in) : (oi_real)2451545.0 + fz_real(in);
        s->earth_rotation_rad = fz_real(in);
    }
}

/* On a violation, the scene and the result are printed before the abort. */
static const oi_scene *g_scene;
static const oi_model *g_model;

static void dump_illum(const oi_illum *o)
{
    const oi_scene *s = g_scene;
    if (s != NULL)
        fprintf(stderr,
                "scene: sun %.17g %.17g %.17g\n moon %.17g %.17g %.17g\n target %.17g %.17g "
                "%.17g\n observer(%d) %.17g %.17g %.17g\n terms %u albedo %.17g/%.17g "
                "radius %.17g\n",
                (double)s->sun_km[0], (double)s->sun_km[1], (double)s->sun_km[2],
                (double)s->moon_km[0], (double)s->moon_km[1], (double)s->moon_km[2],
                (double)s->target_km[0], (double)s->target_km[1], (double)s->target_km[2],
                s->has_observer, (double)s->observer_km[0], (double)s->observer_km[1],
                (double)s->observer_km[2], s->terms, (double)s->earth_albedo,
                (double)s->target_albedo, (double)s->target_radius_m);
    if (g_model != NULL)
        fprintf(stderr, "model: tsi %.17g au %.17g rsun %.17g rearth %.17g rmoon %.17g "
                        "moon_albedo %.17g earth %d moon %d limb %d noatm %d shape %d band %d\n",
                (double)g_model->tsi_w_m2, (double)g_model->au_km,
                (double)g_model->sun_radius_km, (double)g_model->earth_radius_km,
                (double)g_model->moon_radius_km, (double)g_model->moon_albedo,
                g_model->earth_model, g_model->moon_model, g_model->limb_darkening,
                g_model->no_atmosphere, g_model->earth_shape, g_model->band);
    fprintf(stderr,
            "illum: fraction %.17g e_sun %.17g e_earth %.17g e_moon %.17g theta %.17g h %.17g "
            "phi %.17g psi %.17g moon_frac %.17g flux %.17g %.17g %.17g obs %.17g mag %.17g "
            "range %.17g\n",
            (double)o->shadow.fraction, (double)o->e_sun, (double)o->e_earth,
            (double)o->e_moon, (double)o->earth_theta, (double)o->earth_h_km,
            (double)o->earth_phi, (double)o->earth_psi, (double)o->moon_sun_fraction,
            (double)o->flux_sun, (double)o->flux_earth, (double)o->flux_moon,
            (double)o->flux_obs, (double)o->mag_v, (double)o->range_km);
}

#undef FZ_CHECK
#define FZ_CHECK(cond)                                                              \
    do {                                                                            \
        if (!(cond)) {                                                              \
            fprintf(stderr, "%s:%d: invariant violated: %s\n", __FILE__, __LINE__, \
                    #cond);                                                         \
            if (g_dump_illum != NULL) dump_illum(g_dump_illum);                     \
            abort();                                                                \
        }                                                                           \
    } while (0)
static const oi_illum *g_dump_illum;

static void check_illum(int st, const oi_illum *o)
{
    FZ_CHECK(fz_known_status(st));
    if (st < 0) {
        /* every field zero (compare field-wise through a zero struct copy) */
        FZ_CHECK(zero_shadow(&o->shadow));
        FZ_CHECK(o->e_sun == 0 && o->e_earth == 0 && o->e_moon == 0);
        FZ_CHECK(o->flux_obs == 0 && o->mag_v == 0 && o->range_km == 0);
        FZ_CHECK(o->earth_theta == 0 && o->earth_h_km == 0 && o->earth_phi == 0);
        return;
    }
    FZ_CHECK(fz_frac(o->sun_moon_hidden));
    check_shadow(OI_OK, &o->shadow, o->sun_moon_hidden);
    FZ_CHECK(fz_nonneg(o->e_sun) && fz_nonneg(o->e_earth) && fz_nonneg(o->e_moon));
    FZ_CHECK(fz_finite3(o->dir_sun) && fz_unit_or_zero(o->dir_sun));
    FZ_CHECK(fz_finite3(o->dir_earth) && fz_unit_or_zero(o->dir_earth));
    FZ_CHECK(fz_finite3(o->dir_moon) && fz_unit_or_zero(o->dir_moon));
    FZ_CHECK(fz_finite(o->earth_theta) && o->earth_theta >= 0 &&
             o->earth_theta <= (oi_real)PI_D * (1 + 4 * FZ_EPS));
    FZ_CHECK(fz_finite(o->earth_h_km));
    FZ_CHECK(fz_nonneg(o->earth_phi) && fz_finite(o->earth_psi) && o->earth_psi >= 0 &&
             o->earth_psi <= (oi_real)(PI_D / 2) * (1 + 4 * FZ_EPS));
    FZ_CHECK(fz_frac(o->moon_sun_fraction));
    FZ_CHECK(fz_nonneg(o->phase_sun) && o->phase_sun <= (oi_real)PI_D * (1 + 4 * FZ_EPS));
    FZ_CHECK(fz_nonneg(o->phase_earth) && o->phase_earth <= (oi_real)PI_D * (1 + 4 * FZ_EPS));
    FZ_CHECK(fz_nonneg(o->phase_moon) && o->phase_moon <= (oi_real)PI_D * (1 + 4 * FZ_EPS));
    FZ_CHECK(fz_nonneg(o->flux_sun) && fz_nonneg(o->flux_earth) && fz_nonneg(o->flux_moon));
    FZ_CHECK(fz_nonneg(o->flux_obs));
    FZ_CHECK(fz_nonneg(o->flux_specular) &&
             o->flux_specular <= o->flux_obs * (1 + 8 * FZ_EPS) + (oi_real)FZ_MIN_NORMAL);
    FZ_CHECK(fz_finite(o->mag_v) && o->mag_v <= (oi_real)OI_MAG_DARK);
    FZ_CHECK(fz_nonneg(o->range_km));
}

#ifndef OI_NO_EXPOSURE
static const char fz_name[] = "fuzz camera";

static void fz_camera(fz_in *in, oi_camera *c)
{
    int i;
    uint8_t base = fz_u8(in);
    const oi_camera *b = oi_camera_builtin(base % 4);
    if (b != NULL && (base & 0x80) == 0) {
        *c = *b; /* a real camera with a few fields perturbed */
        if (base & 0x10) c->full_well_e = fz_real(in);
        if (base & 0x20) c->times_s[fz_u8(in) % OI_CAMERA_MAX_TIMES] = fz_real(in);
        if (base & 0x40) c->n_times = (int)(int8_t)fz_u8(in);
        if (base & 0x04) c->dark_doubling_c = fz_real(in); /* the temperature model */
        if (base & 0x08) c->temp_max_c = fz_real(in);
        return;
    }
    memset(c, 0, sizeof *c);
    c->name = (base & 1) ? NULL : fz_name;
    c->aperture_m = fz_real(in);
    c->focal_length_m = fz_real(in);
    c->pixel_pitch_m = fz_real(in);
    c->transmission = fz_real(in);
    c->quantum_efficiency = fz_real(in);
    c->band_fraction = fz_real(in);
    c->photon_energy_j = fz_real(in);
    c->full_well_e = fz_real(in);
    c->dark_current_e_s = fz_real(in);
    c->psf_peak_fraction = fz_real(in);
    c->fov_rad = fz_real(in);
    c->sun_exclusion_rad = fz_real(in);
    c->n_times = (int)(int8_t)fz_u8(in);
    c->n_gains = (int)(int8_t)fz_u8(in);
    for (i = 0; i < OI_CAMERA_MAX_TIMES; i++) c->times_s[i] = fz_real(in);
    for (i = 0; i < OI_CAMERA_MAX_GAINS; i++) c->gains[i] = fz_real(in);
    for (i = 0; i < OI_CAMERA_MAX_GAINS; i++) c->read_noise_e[i] = fz_real(in);
}

static void check_exposure(int st, const oi_camera *c, const oi_exposure *e)
{
    FZ_CHECK(fz_known_status(st));
    if (st < 0) {
        FZ_CHECK(e->exposure_s == 0 && e->gain == 0 && e->time_index == 0 &&
                 e->gain_index == 0 && e->signal_e == 0 && e->background_e == 0 &&
                 e->peak_e == 0 && e->saturation_e == 0 && e->fill == 0 && e->snr == 0 &&
                 e->sun_angle_rad == 0 && e->flags == 0);
        return;
    }
    FZ_CHECK(c != NULL);
    FZ_CHECK(e->time_index >= 0 && e->time_index < c->n_times);
    FZ_CHECK(e->gain_index >= 0 && e->gain_index < c->n_gains);
    FZ_CHECK(e->exposure_s == c->times_s[e->time_index]);
    FZ_CHECK(e->gain == c->gains[e->gain_index]);
    FZ_CHECK(fz_nonneg(e->exposure_s) && fz_nonneg(e->gain));
    FZ_CHECK(fz_nonneg(e->signal_e) && fz_nonneg(e->background_e) && fz_nonneg(e->peak_e));
    FZ_CHECK(fz_nonneg(e->saturation_e) && fz_nonneg(e->fill) && fz_nonneg(e->snr));
    FZ_CHECK(fz_nonneg(e->sun_angle_rad) && e->sun_angle_rad <= (oi_real)PI_D * (1 + 4 * FZ_EPS));
    {
        /* every flag set is one the library names */
        unsigned bit;
        for (bit = 1u; bit != 0u; bit <<= 1)
            if (e->flags & bit) FZ_CHECK(oi_flag_name(bit) != NULL);
    }
}

static void do_expose(fz_in *in)
{
    oi_camera cam;
    oi_expose_in x;
    oi_expose_goal g;
    oi_exposure e;
    uint8_t which = fz_u8(in);
    int st;
    fz_camera(in, &cam);
    x.flux_w_m2 = fz_real(in);
    x.background_w_m2_sr = fz_real(in);
    x.flags = fz_u8(in);
    x.rate_rad_s = 0;
    g.fill = fz_real(in);
    g.snr_min = fz_real(in);
    g.sky = 0u;
    g.has_sensor_temp = (which & 8) ? 1u : 0u;
    g.sensor_temp_c = (which & 8) ? fz_real(in) : 0;
    NAN_FILL(e);
    st = oi_expose((which & 1) ? NULL : &cam, &x, (which & 2) ? NULL : &g, &e);
    check_exposure(st, &cam, &e);
    if (which & 1) FZ_CHECK(st == OI_ERR_NULL);
}

static void do_expose_scene(fz_in *in, const oi_scene *s, oi_illum *il, const oi_model *m)
{
    oi_camera cam;
    oi_expose_goal g;
    oi_exposure e;
    uint8_t which = fz_u8(in);
    int st;
    fz_camera(in, &cam);
    g.fill = fz_real(in);
    g.snr_min = fz_real(in);
    g.sky = 0u;
    g.has_sensor_temp = (which & 8) ? 1u : 0u;
    g.sensor_temp_c = (which & 8) ? fz_real(in) : 0;
    if (which & 4) {
        /* corrupted telemetry: an illumination record that oi_illuminate did
         * not produce */
        il->flux_obs = fz_real(in);
        il->e_sun = fz_real(in);
        il->shadow.fraction = fz_real(in);
        il->shadow.region = (int)(int8_t)fz_u8(in);
        il->range_km = fz_real(in);
        il->mag_v = fz_real(in);
    }
    NAN_FILL(e);
    st = oi_expose_scene(&cam, s, il, m, (which & 2) ? NULL : &g, &e);
    check_exposure(st, &cam, &e);
}
#endif

/* (a / |v|)^2 without overflow or underflow of |v|^2 */
static double inv_sq_scaled(double a, const double v[3])
{
    double m = fabs(v[0]), q;
    int i;
    for (i = 1; i < 3; i++)
        if (fabs(v[i]) > m) m = fabs(v[i]);
    if (m == 0) return HUGE_VAL;
    q = (v[0] / m) * (v[0] / m) + (v[1] / m) * (v[1] / m) + (v[2] / m) * (v[2] / m);
    return (a / m) * (a / m) / q;
}

static void do_illuminate(fz_in *in)
{
    oi_scene s;
    oi_model m;
    oi_illum o;
    uint8_t use_model = fz_u8(in);
    int st;
    fz_scene(in, &s);
    fz_model(in, &m);
    NAN_FILL(o);
    st = oi_illuminate(&s, (use_model & 1) ? &m : NULL, &o);
    g_scene = &s;
    g_model = (use_model & 1) ? &m : NULL;
    g_dump_illum = &o;
    check_illum(st, &o);
    if (st >= 0) {
        /* physical upper bounds: direct sunlight at most the unobstructed
         * solar irradiance at the target's distance; earthshine at most
         * albedo E0 phi with phi <= 2 (a Lambertian plane filling half the
         * sky); both with the model's constants */
        double tsi = ((use_model & 1) && m.tsi_w_m2 > 0) ? (double)m.tsi_w_m2 : OI_TSI_W_M2;
        double au = ((use_model & 1) && m.au_km > 0) ? (double)m.au_km : OI_AU_KM;
        double d[3], sv[3], e_max, e0;
        /* slack: relative, and a few units of the smallest subnormal times
         * the factor applied after (AU/d)^2 may have been rounded there */
        double tiny = 8.0 * (double)FZ_MIN_NORMAL * (double)FZ_EPS * (tsi > 1 ? tsi : 1);
        int i;
        for (i = 0; i < 3; i++) {
            d[i] = (double)s.sun_km[i] - (double)s.target_km[i];
            sv[i] = (double)s.sun_km[i];
        }
        e_max = tsi * inv_sq_scaled(au, d);
        e0 = tsi * inv_sq_scaled(au, sv);
        FZ_CHECK((double)o.e_sun <= e_max * (1 + 1e-5) + tiny);
        /* the albedo e_earth is formed with: earth_albedo, or the albedo
         * model's weighted mean, in [0, 1] */
        FZ_CHECK(fz_frac(o.earth_albedo_eff));
        FZ_CHECK((double)o.e_earth <= (double)o.earth_albedo_eff * e0 * 2.02 + tiny);
        if (!((use_model & 1) && m.albedo_model != OI_ALBEDO_UNIFORM) && (s.terms & OI_TERM_EARTH))
            FZ_CHECK(o.earth_albedo_eff == s.earth_albedo);
    }
    g_dump_illum = NULL;
#ifndef OI_NO_EXPOSURE
    do_expose_scene(in, &s, &o, (use_model & 1) ? &m : NULL);
#endif
}

static void do_misc(fz_in *in)
{
    oi_real f, x = fz_real(in), mag;
    char name[24] = {0};
    size_t i, n = fz_u8(in) % sizeof name;
    int st = (int)(int8_t)fz_u8(in);
    const char *sn = oi_status_name(st);
    FZ_CHECK(sn != NULL && sn[0] != '\0');
    mag = oi_magnitude_v(x, NULL);
    FZ_CHECK(fz_finite(mag) && mag <= (oi_real)OI_MAG_DARK);
    NAN_FILL(f);
    st = oi_flux_from_magnitude(x, NULL, &f);
    FZ_CHECK(st == OI_OK || st == OI_ERR_MAGNITUDE);
    FZ_CHECK(fz_nonneg(f));
    if (st < 0) FZ_CHECK(f == 0);
#ifndef OI_NO_EXPOSURE
    (void)oi_flag_name(1u << (fz_u8(in) % 32u));
    (void)oi_flag_name(0);
    (void)oi_flag_name(3);
    for (i = 0; i + 1 < n; i++) name[i] = (char)fz_u8(in);
    name[i < n ? i : 0] = '\0';
    if (n == 0) name[0] = '\0';
    {
        const oi_camera *c = oi_camera_find(name);
        if (c != NULL) FZ_CHECK(c->n_times >= 1 && c->n_times <= OI_CAMERA_MAX_TIMES);
    }
    (void)oi_camera_find(NULL);
#endif
#ifndef OI_NO_FACETS
    {
        /* the plate's earthshine and the BRDF: finite, non-negative, zeroed on error */
        oi_real nrm[3], e, th = fz_real(in), h = fz_real(in), b;
        oi_facet fc;
        oi_model m;
        fz_vec(in, nrm);
        fz_model(in, &m);
        NAN_FILL(e);
        st = oi_earthshine_plate(th, h, nrm, (fz_u8(in) & 1) ? &m : NULL, &e);
        FZ_CHECK(fz_known_status(st));
        FZ_CHECK(fz_nonneg(e));
        if (st < 0) FZ_CHECK(e == 0);
        fz_vec(in, fc.normal);
        fc.area_m2 = fz_real(in);
        fc.two_sided = (int)(fz_u8(in) & 1u);
        fc.albedo_diffuse = fz_real(in);
        fc.albedo_specular = fz_real(in);
        fc.shininess = fz_real(in);
        b = oi_facet_brdf(&fc, nrm, fc.normal);
        if (oi_shape_check(&(oi_shape){&fc, 1u, 0, NULL}) == OI_OK) FZ_CHECK(fz_nonneg(b));
        (void)oi_shape_find(name);
    }
#endif
#ifndef OI_NO_EXPOSURE
    FZ_CHECK(oi_camera_builtin(-1) == NULL);
    {
        const oi_camera *c = oi_camera_builtin((int)(int8_t)fz_u8(in));
        if (c != NULL) FZ_CHECK(c->n_gains >= 1 && c->n_gains <= OI_CAMERA_MAX_GAINS);
    }
#else
    (void)name;
    (void)i;
    (void)n;
#endif
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    uint8_t sel;
    in.p = data;
    in.n = size;
    sel = fz_u8(&in);
    switch (sel % 8) {
    case 0: do_scalars(&in); break;
    case 1: do_sun_fraction(&in); break;
    case 2: do_earthshine(&in); break;
    case 3: case 4: do_illuminate(&in); break;
#ifndef OI_NO_EXPOSURE
    case 5: do_expose(&in); break;
#endif
    case 6: do_misc(&in); break;
    default:
        do_scalars(&in);
        do_sun_fraction(&in);
        do_earthshine(&in);
        do_illuminate(&in);
        do_misc(&in);
        break;
    }
    return 0;
}
