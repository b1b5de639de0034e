/* SPDX-License-Identifier: MIT */
/*
 * bench.c: host benchmark of the runtime (make bench; driven by
 * bench/run_bench.py, which also runs it under callgrind and compares the
 * earthshine table with the baker's quadrature).
 *
 *   bench time [reps]          median ns per scene, every configuration
 *   bench count CONFIG N [LIGHT]  run CONFIG N times over the scene mix, or
 *                              over its lit/penumbra/umbra scenes only (for
 *                              valgrind --tool=callgrind: two N, difference)
 *   bench dump                 per scene: orbit, light, region, theta, h, phi, psi
 *   bench points               per scene: light, Sun and target positions (km), and
 *                              oi_sun_fraction's fraction (the peers' inputs)
 *   bench configs              list the configurations
 *
 * Configurations (the scene mix of bench/scenes.h, observer set):
 *   all            oi_illuminate, Sun (shadow) + Earth + Moon
 *   sun            oi_illuminate, Sun only
 *   sun_moon       oi_illuminate, Sun only with the Moon's position given
 *                  (has_moon: the Moon as an occulter of the Sun)
 *   sun_earth      oi_illuminate, Sun + Earth
 *   sun_earth_mean oi_illuminate, Sun + Earth, earthshine reflected from its
 *                  mean direction (OI_EARTH_REFLECT_MEAN): the difference
 *                  with sun_earth is the cost of the sphere's cubature
 *   sun_earth_table  as sun_earth_mean with the angular table's moments
 *                  (OI_EARTH_REFLECT_TABLE)
 *   sun_earth_plate, sun_earth_box_wing, sun_earth_cylinder  as sun_earth with the
 *                  built-in shape (docs/shapes.md) instead of the sphere, the
 *                  scene's attitude the identity: the facets' cost (without
 *                  OI_NO_FACETS; with it, the sphere's)
 *   all_expose     oi_illuminate (all terms) + oi_expose_scene (built-in camera 0)
 *   sun_fraction   oi_sun_fraction alone
 *   sun_fraction_wgs84  oi_sun_fraction, the WGS-84 ellipsoid (OI_EARTH_WGS84)
 *   all_wgs84      oi_illuminate as all, the WGS-84 ellipsoid
 *   earthshine     oi_earthshine alone (the baked table), theta and h of each scene
 *   earthshine_lambert   oi_earthshine with OI_EARTH_LAMBERT (analytic far field)
 *   sun_fraction_batch   oi_sun_fraction_batch, outputs mask 0 (the uniform disc's
 *                  fraction and the region: what the planar peers compute)
 *   sun_fraction_batch_all  oi_sun_fraction_batch, OI_BATCH_ALL (every output of
 *                  the single call)
 *   all_batch      oi_illuminate_batch, Sun + Earth + Moon (as all)
 *   all_batch_observer  oi_illuminate_batch_outputs, mask OI_BATCH_OBSERVER (what
 *                  a planner reads: irradiances, the fluxes at the observer,
 *                  magnitude; no shadow angles, no limb-darkened fraction, no
 *                  directions), as all
 *   all_batch_observer_mean  as all_batch_observer, the sphere's earthshine
 *                  reflected from its mean direction (OI_EARTH_REFLECT_MEAN, what
 *                  oi_illuminate did before the angular distribution)
 *   all_batch_irradiance  the same, mask 0 (the irradiances at the target)
 *   all_batch_full  the same, OI_BATCH_SCENE_ALL (every output of oi_illuminate)
 *   earthshine_batch  oi_earthshine_batch (as earthshine)
 *   expose_batch   oi_expose_scene_batch over the mix (built-in camera 0, no goal; the
 *                  illuminations computed once, outside the count)
 *   expose_batch_all, expose_batch_setting, expose_batch_faint, expose_batch_flags
 *                  oi_expose_scene_batch_outputs, masks OI_EXPOSE_ALL,
 *                  OI_EXPOSE_SETTING, OI_EXPOSE_FAINT, 0 (the geometric flags alone)
 *   expose_batch_moving_all, expose_batch_moving_faint  the same, masks OI_EXPOSE_ALL
 *                  and OI_EXPOSE_FAINT, each target moving at its circular speed about the
 *                  z axis (the trailed search)
 *   sun_earth_knocke, sun_earth_map  as sun_earth under the Knocke albedo
 *                  field and a 1-degree map (docs/earthshine-albedo.md);
 *                  sun_earth_map_9x18 and sun_earth_map_q the same with
 *                  20-degree and 0.25-degree maps
 * The batch configurations make one call over the mix (or over its lit,
 * penumbra or umbra scenes); costs are per scene.
 * Output: `name value unit` lines. Timing with clock_gettime(CLOCK_MONOTONIC)
 * here, never inside the library.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "orbillum.h"
#include "scenes.h"

#ifdef OI_SINGLE_PRECISION
#define PREC "float"
#else
#define PREC "double"
#endif

void oi_target_missing(const char *name);
static int missing_count;
void oi_target_missing(const char *name)
{
    if (missing_count++ == 0) fprintf(stderr, "bench: %s is not in the library (stub)\n", name);
}

static oi_scene scenes[BENCH_NSCENES];
static oi_real es_theta[BENCH_NSCENES], es_h[BENCH_NSCENES];
static bench_scene_d raw[BENCH_NSCENES];
static volatile double sink;

enum { C_ALL, C_SUN, C_SUN_EARTH, C_ALL_EXPOSE, C_SUN_FRACTION, C_EARTHSHINE, C_EARTHSHINE_LAMBERT,
       C_SUN_MOON, C_SUN_EARTH_MEAN, C_SHAPE_PLATE, C_SHAPE_BOX_WING, C_SHAPE_CYLINDER,
       C_SUN_FRACTION_WGS84, C_ALL_WGS84,
       C_SUN_FRACTION_BATCH, C_SUN_FRACTION_BATCH_ALL, C_ALL_BATCH, C_ALL_BATCH_OBSERVER,
       C_ALL_BATCH_IRRADIANCE, C_ALL_BATCH_FULL, C_EARTHSHINE_BATCH,
       C_SUN_EARTH_KNOCKE, C_SUN_EARTH_MAP, C_SUN_EARTH_TABLE, C_SUN_EARTH_MAP_9X18, C_SUN_EARTH_MAP_Q,
       C_ALL_BATCH_OBSERVER_MEAN, C_EXPOSE_BATCH, C_EXPOSE_BATCH_ALL, C_EXPOSE_BATCH_SETTING,
       C_EXPOSE_BATCH_FAINT, C_EXPOSE_BATCH_FLAGS, C_EXPOSE_BATCH_MOVING_ALL,
       C_EXPOSE_BATCH_MOVING_FAINT, C_N };
static const char *const config_name[C_N] = {"all",          "sun",        "sun_earth",
                                             "all_expose",   "sun_fraction", "earthshine",
                                             "earthshine_lambert", "sun_moon", "sun_earth_mean",
                                             "sun_earth_plate", "sun_earth_box_wing",
                                             "sun_earth_cylinder",
                                             "sun_fraction_wgs84", "all_wgs84",
                                             "sun_fraction_batch",
                                             "sun_fraction_batch_all", "all_batch",
                                             "all_batch_observer", "all_batch_irradiance",
                                             "all_batch_full", "earthshine_batch", "sun_earth_knocke",
                                             "sun_earth_map", "sun_earth_table", "sun_earth_map_9x18",
                                             "sun_earth_map_q", "all_batch_observer_mean",
                                             "expose_batch", "expose_batch_all",
                                             "expose_batch_setting", "expose_batch_faint",
                                             "expose_batch_flags", "expose_batch_moving_all",
                                             "expose_batch_moving_faint"};

/* the albedo map of sun_earth_map: 1-degree cells (a CERES grid's size),
 * a smooth zonal and tesseral pattern (filled by setup) */
#define MAP_LAT 180
#define MAP_LON 360
static float albedo_map[MAP_LAT * MAP_LON];
/* the maps of sun_earth_map_9x18 (20-degree cells) and sun_earth_map_q
 * (0.25-degree cells), the same pattern: the map's cost grows with the cells
 * under the lit visible cap */
#define MAP9_LAT 9
#define MAP9_LON 18
#define MAPQ_LAT 720
#define MAPQ_LON 1440
static float albedo_map9[MAP9_LAT * MAP9_LON];
static float albedo_mapq[MAPQ_LAT * MAPQ_LON];
static void fill_map(float *a, int n_lat, int n_lon)
{
    int i, k;
    for (i = 0; i < n_lat; i++)
        for (k = 0; k < n_lon; k++) {
            const double lat = 1.5707963267948966 - (i + 0.5) * 3.14159265358979323846 / n_lat;
            const double lon = (k + 0.5) * 6.283185307179586 / n_lon;
            a[i * n_lon + k] =
                (float)(0.3 + 0.2 * sin(lat) * sin(lat) + 0.1 * cos(lat) * cos(lon - 1.0));
        }
}

/* The batch configurations' arrays: the scenes of the mix (or of one
 * lighting class), packed (pack()). */
static long nb;
static oi_real b_sun[3 * BENCH_NSCENES], b_pt[3 * BENCH_NSCENES];
static oi_real b_theta[BENCH_NSCENES], b_h[BENCH_NSCENES], b_phi[BENCH_NSCENES],
    b_psi[BENCH_NSCENES];
static oi_scene b_scenes[BENCH_NSCENES];
static oi_shadow b_shadow[BENCH_NSCENES];
static oi_illum b_illum[BENCH_NSCENES];
static int b_status[BENCH_NSCENES];
#ifndef OI_NO_EXPOSURE
/* the exposure configurations' scenes (at rest, and moving), their
 * illuminations and exposures */
static oi_scene b_moving[BENCH_NSCENES];
static oi_illum b_ex_illum[BENCH_NSCENES];
static oi_exposure b_ex[BENCH_NSCENES];
#endif

static void setup(void)
{
    int i, k;
    bench_make_scenes(raw);
    fill_map(albedo_map9, MAP9_LAT, MAP9_LON);
    fill_map(albedo_mapq, MAPQ_LAT, MAPQ_LON);
    for (i = 0; i < MAP_LAT; i++)
        for (k = 0; k < MAP_LON; k++) {
            const double lat = 1.5707963267948966 - (i + 0.5) * 3.14159265358979323846 / MAP_LAT;
            const double lon = (k + 0.5) * 6.283185307179586 / MAP_LON;
            albedo_map[i * MAP_LON + k] =
                (float)(0.3 + 0.2 * sin(lat) * sin(lat) + 0.1 * cos(lat) * cos(lon - 1.0));
        }
    for (i = 0; i < BENCH_NSCENES; i++) {
        oi_scene *s = &scenes[i];
        double t[3], r, d, c[3], cn;
        oi_scene_defaults(s);
        for (k = 0; k < 3; k++) {
            s->sun_km[k] = (oi_real)raw[i].sun[k];
            s->moon_km[k] = (oi_real)raw[i].moon[k];
            s->target_km[k] = (oi_real)raw[i].target[k];
            s->observer_km[k] = (oi_real)raw[i].observer[k];
            t[k] = raw[i].target[k];
        }
        s->has_observer = 1;
        /* the albedo models' epoch and Earth rotation (read only by them) */
        s->epoch_jd = (oi_real)(2451545.0 + 3.7 * i);
        s->earth_rotation_rad = (oi_real)(0.1 * i);
        /* theta and h of the earthshine-only configurations, in double */
        r = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        d = raw[i].sun[0] * t[0] + raw[i].sun[1] * t[1] + raw[i].sun[2] * t[2];
        c[0] = raw[i].sun[1] * t[2] - raw[i].sun[2] * t[1];
        c[1] = raw[i].sun[2] * t[0] - raw[i].sun[0] * t[2];
        c[2] = raw[i].sun[0] * t[1] - raw[i].sun[1] * t[0];
        cn = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        es_theta[i] = (oi_real)atan2(cn, d);
        es_h[i] = (oi_real)(r - 6378.137);
    }
}

/* scenes of one lighting class only (-1: all) */
static int only_light = -1;

static void pack(void)
{
    int i, k;
    nb = 0;
    for (i = 0; i < BENCH_NSCENES; i++) {
        if (only_light >= 0 && raw[i].light != only_light) continue;
        for (k = 0; k < 3; k++) {
            b_sun[3 * nb + k] = scenes[i].sun_km[k];
            b_pt[3 * nb + k] = scenes[i].target_km[k];
        }
        b_theta[nb] = es_theta[i];
        b_h[nb] = es_h[i];
        b_scenes[nb] = scenes[i];
        b_scenes[nb].terms = OI_TERM_ALL;
#ifndef OI_NO_EXPOSURE
        {
            /* circular speed about the z axis, sqrt(GM / r) (GM 398600.4418 km^3/s^2) */
            const double x = (double)scenes[i].target_km[0], y = (double)scenes[i].target_km[1];
            const double z = (double)scenes[i].target_km[2], r = sqrt(x * x + y * y + z * z);
            const double rho = sqrt(x * x + y * y), v = sqrt(398600.4418 / r);
            b_moving[nb] = b_scenes[nb];
            b_moving[nb].target_vel_km_s[0] = (oi_real)(rho > 0 ? -v * y / rho : v);
            b_moving[nb].target_vel_km_s[1] = (oi_real)(rho > 0 ? v * x / rho : 0.0);
            (void)oi_illuminate(&b_scenes[nb], NULL, &b_ex_illum[nb]);
        }
#endif
        nb++;
    }
}

#ifndef OI_NO_EXPOSURE
/* One call of an exposure batch configuration; returns a checksum. */
static double run_expose_batch(int cfg)
{
    const oi_camera *cam = oi_camera_builtin(0);
    const int moving = cfg == C_EXPOSE_BATCH_MOVING_ALL || cfg == C_EXPOSE_BATCH_MOVING_FAINT;
    const unsigned mask = cfg == C_EXPOSE_BATCH_SETTING ? OI_EXPOSE_SETTING
                          : cfg == C_EXPOSE_BATCH_FAINT || cfg == C_EXPOSE_BATCH_MOVING_FAINT
                              ? OI_EXPOSE_FAINT
                          : cfg == C_EXPOSE_BATCH_FLAGS ? 0u
                                                        : OI_EXPOSE_ALL;
    double acc = 0.0;
    long i;
    if (cfg == C_EXPOSE_BATCH)
        (void)oi_expose_scene_batch(nb, cam, b_scenes, b_ex_illum, NULL, NULL, b_ex, b_status);
    else
        (void)oi_expose_scene_batch_outputs(nb, cam, moving ? b_moving : b_scenes, b_ex_illum,
                                            NULL, NULL, mask, b_ex, b_status);
    for (i = 0; i < nb; i++) acc += (double)b_ex[i].exposure_s + (double)b_ex[i].flags;
    return acc;
}
#endif

/* One call of a batch configuration; returns a checksum. */
static double run_batch(int cfg)
{
    double acc = 0.0;
    long i;
    switch (cfg) {
    case C_SUN_FRACTION_BATCH:
    case C_SUN_FRACTION_BATCH_ALL:
        (void)oi_sun_fraction_batch(nb, b_sun, b_pt, NULL,
                                    cfg == C_SUN_FRACTION_BATCH ? 0u : OI_BATCH_ALL, b_shadow,
                                    b_status);
        for (i = 0; i < nb; i++) acc += (double)b_shadow[i].fraction;
        break;
    case C_ALL_BATCH:
        (void)oi_illuminate_batch(nb, b_scenes, NULL, b_illum, b_status);
        for (i = 0; i < nb; i++) acc += (double)b_illum[i].flux_obs;
        break;
    case C_ALL_BATCH_OBSERVER_MEAN: {
        oi_model mean;
        memset(&mean, 0, sizeof mean);
        mean.earth_reflection = OI_EARTH_REFLECT_MEAN;
        (void)oi_illuminate_batch_outputs(nb, b_scenes, &mean, OI_BATCH_OBSERVER, b_illum, b_status);
        for (i = 0; i < nb; i++) acc += (double)(b_illum[i].flux_obs + b_illum[i].e_sun);
        break;
    }
    case C_ALL_BATCH_OBSERVER:
    case C_ALL_BATCH_IRRADIANCE:
    case C_ALL_BATCH_FULL:
        (void)oi_illuminate_batch_outputs(nb, b_scenes, NULL,
                                          cfg == C_ALL_BATCH_OBSERVER ? OI_BATCH_OBSERVER
                                          : cfg == C_ALL_BATCH_FULL   ? OI_BATCH_SCENE_ALL
                                                                      : 0u,
                                          b_illum, b_status);
        for (i = 0; i < nb; i++) acc += (double)(b_illum[i].flux_obs + b_illum[i].e_sun);
        break;
    default:
        (void)oi_earthshine_batch(nb, b_theta, b_h, NULL, b_phi, b_psi, b_status);
        for (i = 0; i < nb; i++) acc += (double)b_phi[i];
        break;
    }
    return acc;
}

/* One pass of a configuration over the scene mix; returns a checksum. */
static double run_config(int cfg)
{
    static oi_illum il;
#ifndef OI_NO_EXPOSURE
    static oi_exposure ex;
    const oi_camera *cam = oi_camera_builtin(0);
#endif
    oi_model lambert, mean, wgs84, knocke, map, table, map9, mapq;
    oi_real phi, psi;
    double acc = 0.0;
    int i;
    if ((cfg >= C_SUN_FRACTION_BATCH && cfg <= C_EARTHSHINE_BATCH) || cfg == C_ALL_BATCH_OBSERVER_MEAN)
        return run_batch(cfg);
    if (cfg >= C_EXPOSE_BATCH) {
#ifndef OI_NO_EXPOSURE
        return run_expose_batch(cfg);
#else
        return 0.0;
#endif
    }
    memset(&lambert, 0, sizeof lambert);
    lambert.earth_model = OI_EARTH_LAMBERT;
    memset(&mean, 0, sizeof mean);
    mean.earth_reflection = OI_EARTH_REFLECT_MEAN;
    memset(&table, 0, sizeof table);
    table.earth_reflection = OI_EARTH_REFLECT_TABLE;
    memset(&wgs84, 0, sizeof wgs84);
    wgs84.earth_shape = OI_EARTH_WGS84;
    memset(&knocke, 0, sizeof knocke);
    knocke.albedo_model = OI_ALBEDO_KNOCKE;
    memset(&map, 0, sizeof map);
    map.albedo_model = OI_ALBEDO_MAP;
    map.albedo_map = albedo_map;
    map.albedo_map_n_lat = MAP_LAT;
    map.albedo_map_n_lon = MAP_LON;
    map9 = map;
    map9.albedo_map = albedo_map9;
    map9.albedo_map_n_lat = MAP9_LAT;
    map9.albedo_map_n_lon = MAP9_LON;
    mapq = map;
    mapq.albedo_map = albedo_mapq;
    mapq.albedo_map_n_lat = MAPQ_LAT;
    mapq.albedo_map_n_lon = MAPQ_LON;
    for (i = 0; i < BENCH_NSCENES; i++) {
        oi_scene *s = &scenes[i];
        if (only_light >= 0 && raw[i].light != only_light) continue;
        switch (cfg) {
        case C_ALL:
            s->terms = OI_TERM_ALL;
            (void)oi_illuminate(s, NULL, &il);
            acc += (double)il.flux_obs;
            break;
        case C_SUN:
            s->terms = OI_TERM_SUN;
            (void)oi_illuminate(s, NULL, &il);
            acc += (double)il.flux_obs;
            break;
        case C_SUN_MOON:
            s->terms = OI_TERM_SUN;
            s->has_moon = 1;
            (void)oi_illuminate(s, NULL, &il);
            s->has_moon = 0;
            acc += (double)il.flux_obs;
            break;
        case C_SUN_EARTH:
            s->terms = OI_TERM_SUN | OI_TERM_EARTH;
            (void)oi_illuminate(s, NULL, &il);
            acc += (double)il.flux_obs;
            break;
        case C_SUN_EARTH_KNOCKE:
        case C_SUN_EARTH_MAP:
        case C_SUN_EARTH_MAP_9X18:
        case C_SUN_EARTH_MAP_Q:
            s->terms = OI_TERM_SUN | OI_TERM_EARTH;
            (void)oi_illuminate(s, cfg == C_SUN_EARTH_KNOCKE ? &knocke
                                   : cfg == C_SUN_EARTH_MAP_9X18 ? &map9
                                   : cfg == C_SUN_EARTH_MAP_Q   ? &mapq
                                                                : &map,
                                &il);
            acc += (double)il.flux_obs;
            break;
        case C_SUN_EARTH_MEAN:
        case C_SUN_EARTH_TABLE:
            s->terms = OI_TERM_SUN | OI_TERM_EARTH;
            (void)oi_illuminate(s, cfg == C_SUN_EARTH_MEAN ? &mean : &table, &il);
            acc += (double)il.flux_obs;
            break;
        case C_SHAPE_PLATE:
        case C_SHAPE_BOX_WING:
        case C_SHAPE_CYLINDER:
            s->terms = OI_TERM_SUN | OI_TERM_EARTH;
#ifndef OI_NO_FACETS
            s->shape = oi_shape_builtin(cfg - C_SHAPE_PLATE);
#endif
            (void)oi_illuminate(s, NULL, &il);
            s->shape = NULL;
            acc += (double)il.flux_obs;
            break;
        case C_ALL_EXPOSE:
            s->terms = OI_TERM_ALL;
            (void)oi_illuminate(s, NULL, &il);
#ifndef OI_NO_EXPOSURE
            (void)oi_expose_scene(cam, s, &il, NULL, NULL, &ex);
            acc += (double)ex.exposure_s;
#endif
            break;
        case C_SUN_FRACTION:
            (void)oi_sun_fraction(s->sun_km, s->target_km, NULL, &il.shadow);
            acc += (double)il.shadow.fraction;
            break;
        case C_SUN_FRACTION_WGS84:
            (void)oi_sun_fraction(s->sun_km, s->target_km, &wgs84, &il.shadow);
            acc += (double)il.shadow.fraction;
            break;
        case C_ALL_WGS84:
            s->terms = OI_TERM_ALL;
            (void)oi_illuminate(s, &wgs84, &il);
            acc += (double)il.flux_obs;
            break;
        case C_EARTHSHINE:
            (void)oi_earthshine(es_theta[i], es_h[i], NULL, &phi, &psi);
            acc += (double)phi;
            break;
        default:
            (void)oi_earthshine(es_theta[i], es_h[i], &lambert, &phi, &psi);
            acc += (double)phi;
            break;
        }
    }
    return acc;
}

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int find_config(const char *name)
{
    int c;
    for (c = 0; c < C_N; c++)
        if (strcmp(config_name[c], name) == 0) return c;
    return -1;
}

static int do_time(int reps)
{
    double *t = malloc(sizeof(double) * (size_t)reps);
    int c, r, inner;
    if (t == NULL) return 1;
    for (c = 0; c < C_N; c++) {
        double t0, per;
        /* the 0.25-degree map's pass lasts ~1 s: five samples */
        const int n_rep = c == C_SUN_EARTH_MAP_Q && reps > 5 ? 5 : reps;
        missing_count = 0;
        /* inner passes so that one sample lasts >= ~200 microseconds */
        t0 = now_ns();
        sink = run_config(c);
        per = now_ns() - t0;
        inner = per > 0 ? (int)(2e5 / per) + 1 : 1000;
        for (r = 0; r < n_rep; r++) {
            int k;
            t0 = now_ns();
            for (k = 0; k < inner; k++) sink = run_config(c);
            t[r] = (now_ns() - t0) / ((double)inner * BENCH_NSCENES);
        }
        qsort(t, (size_t)n_rep, sizeof *t, cmp_double);
        printf("bench.%s.%s.ns_median %.1f ns\n", PREC, config_name[c], t[n_rep / 2]);
        printf("bench.%s.%s.ns_min %.1f ns\n", PREC, config_name[c], t[0]);
        if (missing_count) printf("bench.%s.%s.incomplete 1 flag  # a stub ran\n", PREC, config_name[c]);
    }
    free(t);
    return 0;
}

static int do_dump(void)
{
    int i;
    static oi_illum il;
    printf("# orbit light region theta h_km phi psi status\n");
    for (i = 0; i < BENCH_NSCENES; i++) {
        oi_real phi = 0, psi = 0;
        int st = oi_earthshine(es_theta[i], es_h[i], NULL, &phi, &psi);
        scenes[i].terms = OI_TERM_ALL;
        (void)oi_illuminate(&scenes[i], NULL, &il);
        printf("%s %s %d %.17g %.17g %.17g %.17g %d\n", bench_orbit_name[raw[i].orbit],
               bench_light_name[raw[i].light], il.shadow.region, (double)es_theta[i], (double)es_h[i],
               (double)phi, (double)psi, st);
    }
    return 0;
}

static int do_points(void)
{
    int i;
    oi_shadow sh;
    printf("# light sun_x sun_y sun_z target_x target_y target_z fraction\n");
    for (i = 0; i < BENCH_NSCENES; i++) {
        const oi_scene *s = &scenes[i];
        (void)oi_sun_fraction(s->sun_km, s->target_km, NULL, &sh);
        printf("%s %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", bench_light_name[raw[i].light],
               (double)s->sun_km[0], (double)s->sun_km[1], (double)s->sun_km[2],
               (double)s->target_km[0], (double)s->target_km[1], (double)s->target_km[2],
               (double)sh.fraction);
    }
    return 0;
}

int main(int argc, char **argv)
{
    setup();
    pack();
    if (argc >= 2 && strcmp(argv[1], "points") == 0) return do_points();
    if (argc >= 2 && strcmp(argv[1], "time") == 0) return do_time(argc >= 3 ? atoi(argv[2]) : 31);
    if (argc >= 2 && strcmp(argv[1], "dump") == 0) return do_dump();
    if (argc >= 2 && strcmp(argv[1], "configs") == 0) {
        int c;
        for (c = 0; c < C_N; c++) printf("%s\n", config_name[c]);
        printf("nscenes %d\n", BENCH_NSCENES);
        return 0;
    }
    if ((argc == 4 || argc == 5) && strcmp(argv[1], "count") == 0) {
        int c = find_config(argv[2]), n = atoi(argv[3]), k;
        if (argc == 5) {
            for (k = 0; k < BENCH_LIGHTS; k++)
                if (strcmp(bench_light_name[k], argv[4]) == 0) only_light = k;
            if (only_light < 0) return 2;
            pack();
        }
        if (c < 0 || n < 0) return 2;
        for (k = 0; k < n; k++) sink = run_config(c);
        return 0;
    }
    fprintf(stderr, "usage: bench time [reps] | count CONFIG N [LIGHT] | dump | points | configs\n");
    return 2;
}
