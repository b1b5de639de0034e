/* SPDX-License-Identifier: MIT */
/*
 * scenario.c: the built-in scenario (see scenario.h, docs/planner.md).
 *
 * Two circular Keplerian orbits, Earth-centred inertial frame (km):
 *   target     altitude 500 km, inclination 51.6 deg, RAAN 0, argument of
 *              latitude 0 at t = 0;
 *   inspector  1.5 km lower, inclination 0.005 deg higher, 8 km behind the
 *              target along the track at t = 0. Being lower, it is faster:
 *              it drifts 3 pi x 1.5 km = 14 km forward per orbit, so it
 *              passes under the target during the pass.
 * Sun and Moon are fixed (their motion over 95 minutes changes nothing
 * here): the Sun at RA 280 deg, Dec -23 deg, 0.98329 AU (early January,
 * near perihelion); the Moon at RA 110 deg, Dec +18 deg, 384400 km (near
 * full). The orbit's beta angle is then about 28 deg: a 35-minute eclipse.
 * GM of the Earth 398600.4418 km^3/s^2 (IERS Conventions 2010, table 1.1).
 */
#include "scenario.h"

#include <math.h>
#include <string.h>

#include "output.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)
#define GM_KM3_S2 398600.4418

#define TARGET_ALT_KM 500.0
#define INCL_DEG 51.6
#define INSPECTOR_DROP_KM 1.5
#define INSPECTOR_DINCL_DEG 0.005
#define INSPECTOR_BEHIND_KM 8.0
#define SUN_RA_DEG 280.0
#define SUN_DEC_DEG (-23.0)
#define SUN_DIST_AU 0.98329
#define MOON_RA_DEG 110.0
#define MOON_DEC_DEG 18.0
#define MOON_DIST_KM 384400.0

#define FINE_STEP_S 10.0 /* sampling of the summary */

typedef struct orbit {
    double a_km, incl, raan, u0, n; /* n: mean motion (rad/s) */
} orbit;

static orbit make_orbit(double a_km, double incl, double raan, double u0)
{
    orbit o;
    o.a_km = a_km;
    o.incl = incl;
    o.raan = raan;
    o.u0 = u0;
    o.n = sqrt(GM_KM3_S2 / (a_km * a_km * a_km));
    return o;
}

/* Position on a circular orbit at time t (s). */
static void orbit_pos(const orbit *o, double t, oi_real p[3])
{
    double u = o->u0 + o->n * t;
    double cu = cos(u), su = sin(u), co = cos(o->raan), so = sin(o->raan);
    double ci = cos(o->incl), si = sin(o->incl);
    p[0] = (oi_real)(o->a_km * (cu * co - su * ci * so));
    p[1] = (oi_real)(o->a_km * (cu * so + su * ci * co));
    p[2] = (oi_real)(o->a_km * (su * si));
}

static void radec(double ra_deg, double dec_deg, double dist, oi_real p[3])
{
    p[0] = (oi_real)(dist * cos(dec_deg * DEG) * cos(ra_deg * DEG));
    p[1] = (oi_real)(dist * cos(dec_deg * DEG) * sin(ra_deg * DEG));
    p[2] = (oi_real)(dist * sin(dec_deg * DEG));
}

typedef struct sample {
    plan_row row;
    double range_km;
} sample;

/* Compute one instant; returns 1 when the library succeeded. */
static int compute(const orbit *tgt, const orbit *insp, const oi_camera *cam, double t,
                   sample *out)
{
    oi_scene sc;
    oi_real d[3];
    int st;
    memset(out, 0, sizeof *out);
    oi_scene_defaults(&sc);
    radec(SUN_RA_DEG, SUN_DEC_DEG, SUN_DIST_AU * (double)OI_AU_KM, sc.sun_km);
    radec(MOON_RA_DEG, MOON_DEC_DEG, MOON_DIST_KM, sc.moon_km);
    orbit_pos(tgt, t, sc.target_km);
    orbit_pos(insp, t, sc.observer_km);
    sc.has_observer = 1;
    d[0] = sc.target_km[0] - sc.observer_km[0];
    d[1] = sc.target_km[1] - sc.observer_km[1];
    d[2] = sc.target_km[2] - sc.observer_km[2];
    out->range_km = sqrt((double)(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    st = oi_illuminate(&sc, NULL, &out->row.illum);
    out->row.status = st;
    out->row.status_name = oi_status_name(st);
    if (st < 0) return 0;
    st = oi_expose_scene(cam, &sc, &out->row.illum, NULL, NULL, &out->row.expo);
    if (st < 0) {
        out->row.status = st;
        out->row.status_name = oi_status_name(st);
        return 0;
    }
    out->row.flags = out->row.expo.flags;
    out->row.has_numbers = 1;
    out->row.has_observer = 1;
    return 1;
}

/* A good observation: target in full sunlight, Sun out of the exclusion
 * cone, target not behind the Earth, not saturated, SNR at the goal. */
static int is_good(const sample *s, double snr_goal)
{
    unsigned bad = OI_FLAG_ECLIPSED | OI_FLAG_PENUMBRA | OI_FLAG_SUN_EXCLUSION |
                   OI_FLAG_OCCULTED | OI_FLAG_SATURATED | OI_FLAG_MOON_SHADOW |
                   OI_FLAG_TOO_FAINT | OI_FLAG_BACKGROUND_SATURATED;
    return s->row.has_numbers && !(s->row.flags & bad) && (double)s->row.expo.snr >= snr_goal;
}

/* An interval tracker over the fine samples. */
typedef struct span {
    int open;
    double start, last, best_snr, best_t, best_mag, best_exp, best_gain, min_range;
} span;

static void span_print_head(FILE *fp)
{
    fprintf(fp, "  %3s %9s %9s %9s %9s %9s %7s %9s %6s %9s\n", "#", "start", "end", "duration",
            "best SNR", "at", "mag_V", "exposure", "gain", "min range");
    fprintf(fp, "  %3s %9s %9s %9s %9s %9s %7s %9s %6s %9s\n", "", "[min]", "[min]", "[min]", "",
            "[min]", "", "[s]", "", "[km]");
}

static void span_print(FILE *fp, int k, const span *w, double step)
{
    double end = w->last + step;
    fprintf(fp, "  %3d %9.2f %9.2f %9.2f %9.4g %9.2f %7.2f %9.3g %6.2g %9.3f\n", k,
            w->start / 60.0, end / 60.0, (end - w->start) / 60.0, w->best_snr, w->best_t / 60.0,
            w->best_mag, w->best_exp, w->best_gain, w->min_range);
}

static void describe_camera(FILE *fp, const oi_camera *c)
{
    fprintf(fp, "  camera     %s: aperture %.1f mm, focal length %.0f mm, pixel %.1f um, "
                "field %.2f deg, Sun exclusion %.0f deg,\n"
                "             exposures %.3g..%.3g s (%d steps), gains %.3g..%.3g (%d)\n",
            c->name ? c->name : "(unnamed)", (double)c->aperture_m * 1e3,
            (double)c->focal_length_m * 1e3, (double)c->pixel_pitch_m * 1e6,
            (double)c->fov_rad / DEG, (double)c->sun_exclusion_rad / DEG, (double)c->times_s[0],
            (double)c->times_s[c->n_times - 1], c->n_times, (double)c->gains[0],
            (double)c->gains[c->n_gains - 1], c->n_gains);
}

int scenario_run(FILE *out, const oi_camera *camera, double step_s)
{
    const double re = OI_EARTH_RADIUS_KM;
    const double a_t = re + TARGET_ALT_KM;
    const double snr_goal = 5.0; /* oi_expose_goal default */
    orbit tgt = make_orbit(a_t, INCL_DEG * DEG, 0.0, 0.0);
    orbit insp = make_orbit(a_t - INSPECTOR_DROP_KM, (INCL_DEG + INSPECTOR_DINCL_DEG) * DEG, 0.0,
                            -INSPECTOR_BEHIND_KM / a_t);
    double period = 2.0 * PI / tgt.n, t, next_print = 0.0;
    double total_good = 0.0, total_ecl = 0.0;
    long i, n_fine = (long)floor(period / FINE_STEP_S);
    int failures = 0, n_windows = 0, k;
    span win, ecl, excl;
    span windows[64];
    span eclipses[8], exclusions[16];
    int n_ecl = 0, n_excl = 0;
    oi_real sun[3], h[3];
    double beta;

    memset(&win, 0, sizeof win);
    ecl = excl = win;
    radec(SUN_RA_DEG, SUN_DEC_DEG, 1.0, sun);
    /* orbit normal of the target: (sin i sin raan, -sin i cos raan, cos i) */
    h[0] = (oi_real)(sin(tgt.incl) * sin(tgt.raan));
    h[1] = (oi_real)(-sin(tgt.incl) * cos(tgt.raan));
    h[2] = (oi_real)cos(tgt.incl);
    beta = asin((double)(sun[0] * h[0] + sun[1] * h[1] + sun[2] * h[2]));

    fprintf(out, "oi-plan: built-in scenario: an inspector photographs a target over one orbit\n\n");
    fprintf(out, "  target     circular LEO, altitude %.0f km, inclination %.1f deg, "
                 "period %.1f min; sphere of radius 1 m, albedo 0.2\n",
            TARGET_ALT_KM, INCL_DEG, period / 60.0);
    fprintf(out, "  inspector  circular, %.1f km lower, %.0f km behind at t = 0, "
                 "inclination +%.3f deg (drifts %.0f km forward per orbit)\n",
            INSPECTOR_DROP_KM, INSPECTOR_BEHIND_KM, INSPECTOR_DINCL_DEG,
            3.0 * PI * INSPECTOR_DROP_KM);
    fprintf(out, "  Sun        fixed: RA %.0f deg, Dec %.0f deg, %.5f AU; beta angle %.1f deg\n",
            SUN_RA_DEG, SUN_DEC_DEG, SUN_DIST_AU, beta / DEG);
    fprintf(out, "  Moon       fixed: RA %.0f deg, Dec %+.0f deg, %.0f km; Earth albedo 0.30\n",
            MOON_RA_DEG, MOON_DEC_DEG, MOON_DIST_KM);
    describe_camera(out, camera);
    fprintf(out, "  goal       brightest pixel at 0.5 of saturation, SNR >= %.0f\n\n", snr_goal);
    out_table_header(out);

    for (i = 0; i <= n_fine; i++) {
        sample s;
        int good, in_ecl, in_excl;
        t = (double)i * FINE_STEP_S;
        if (!compute(&tgt, &insp, camera, t, &s)) failures++;
        if (t + 1e-9 >= next_print) {
            out_table_row(out, t, s.range_km, &s.row);
            next_print += step_s;
        }
        good = is_good(&s, snr_goal);
        in_ecl = s.row.has_numbers && (s.row.flags & OI_FLAG_ECLIPSED);
        in_excl = s.row.has_numbers && (s.row.flags & OI_FLAG_SUN_EXCLUSION);
        if (good) {
            if (!win.open) {
                memset(&win, 0, sizeof win);
                win.open = 1;
                win.start = t;
                win.min_range = s.range_km;
            }
            win.last = t;
            if (s.range_km < win.min_range) win.min_range = s.range_km;
            if ((double)s.row.expo.snr > win.best_snr) {
                win.best_snr = (double)s.row.expo.snr;
                win.best_t = t;
                win.best_mag = (double)s.row.illum.mag_v;
                win.best_exp = (double)s.row.expo.exposure_s;
                win.best_gain = (double)s.row.expo.gain;
            }
        }
        if (win.open && (!good || i == n_fine)) {
            win.open = 0;
            if (n_windows < (int)(sizeof windows / sizeof windows[0])) windows[n_windows++] = win;
            total_good += win.last + FINE_STEP_S - win.start;
        }
        if (in_ecl && !ecl.open) {
            ecl.open = 1;
            ecl.start = t;
        }
        if (in_ecl) ecl.last = t;
        if (ecl.open && (!in_ecl || i == n_fine)) {
            ecl.open = 0;
            if (n_ecl < 8) eclipses[n_ecl++] = ecl;
            total_ecl += ecl.last + FINE_STEP_S - ecl.start;
        }
        if (in_excl && !excl.open) {
            excl.open = 1;
            excl.start = t;
        }
        if (in_excl) excl.last = t;
        if (excl.open && (!in_excl || i == n_fine)) {
            excl.open = 0;
            if (n_excl < 16) exclusions[n_excl++] = excl;
        }
    }

    fprintf(out, "\nSummary (sampled every %.0f s over %.1f min)\n", FINE_STEP_S, period / 60.0);
    for (k = 0; k < n_ecl; k++) {
        fprintf(out, "  target in the Earth's umbra: %.2f to %.2f min\n", eclipses[k].start / 60.0,
                (eclipses[k].last + FINE_STEP_S) / 60.0);
    }
    for (k = 0; k < n_excl; k++) {
        fprintf(out, "  Sun inside the camera's exclusion angle: %.2f to %.2f min\n",
                exclusions[k].start / 60.0, (exclusions[k].last + FINE_STEP_S) / 60.0);
    }
    fprintf(out, "\nBest observation windows (target in full sunlight, Sun outside the "
                 "exclusion angle,\nnot behind the Earth, not saturated, SNR >= %.0f):\n",
            snr_goal);
    if (n_windows == 0) {
        fprintf(out, "  none\n");
    } else {
        span_print_head(out);
        for (k = 0; k < n_windows; k++) span_print(out, k + 1, &windows[k], FINE_STEP_S);
    }
    fprintf(out, "  total %.1f min of %.1f min observable; %.1f min in eclipse\n",
            total_good / 60.0, period / 60.0, total_ecl / 60.0);
    if (failures > 0) fprintf(out, "  %d samples failed (see the table)\n", failures);
    return failures > 0 ? 1 : 0;
}
