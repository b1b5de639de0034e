/* SPDX-License-Identifier: MIT */
/*
 * scenes.h: the benchmark's scene mix, generated deterministically (a fixed
 * linear congruential generator, no libc rand) in double precision.
 *
 * Orbits: LEO (500 km altitude), GEO (42164 km radius), cislunar (200000 km).
 * Lighting: lit (target on the day side, Sun-Earth-target angle 0..80 deg),
 * penumbra (on the shadow cone's edge: distance from the shadow axis
 * R_E + (2f - 1) x alpha_sun, f in [0.15, 0.85], x the distance behind the
 * terminator plane, alpha_sun the Sun's apparent radius), umbra (0.5 R_E from
 * the axis). Sun at 0.983..1.017 AU in a random direction, Moon at 363000..
 * 405000 km, observer 50..1000 km from the target in a random direction.
 * BENCH_PER_CELL scenes per (orbit, lighting) cell.
 */
#ifndef OI_BENCH_SCENES_H
#define OI_BENCH_SCENES_H

#include <math.h>

#define BENCH_PER_CELL (8)
#define BENCH_ORBITS (3)
#define BENCH_LIGHTS (3)
#define BENCH_NSCENES (BENCH_PER_CELL * BENCH_ORBITS * BENCH_LIGHTS)

typedef struct bench_scene_d {
    double sun[3], moon[3], target[3], observer[3];
    int orbit, light;
} bench_scene_d;

static const char *const bench_orbit_name[BENCH_ORBITS] = {"leo", "geo", "cislunar"};
static const char *const bench_light_name[BENCH_LIGHTS] = {"lit", "penumbra", "umbra"};

static unsigned long bench_lcg_state = 12345UL;

static double bench_uniform(void)
{
    /* Numerical Recipes' 32-bit LCG (Press et al., 2007, section 7.1) */
    bench_lcg_state = (1664525UL * bench_lcg_state + 1013904223UL) & 0xFFFFFFFFUL;
    return ((double)bench_lcg_state + 0.5) / 4294967296.0;
}

static void bench_random_unit(double u[3])
{
    double z = 2.0 * bench_uniform() - 1.0, phi = 6.283185307179586 * bench_uniform();
    double s = sqrt(1.0 - z * z);
    u[0] = s * cos(phi);
    u[1] = s * sin(phi);
    u[2] = z;
}

/* unit vector perpendicular to u */
static void bench_perp(const double u[3], double v[3])
{
    double a[3] = {1.0, 0.0, 0.0}, d, n;
    if (fabs(u[0]) > 0.9) {
        a[0] = 0.0;
        a[1] = 1.0;
    }
    d = a[0] * u[0] + a[1] * u[1] + a[2] * u[2];
    v[0] = a[0] - d * u[0];
    v[1] = a[1] - d * u[1];
    v[2] = a[2] - d * u[2];
    n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= n;
    v[1] /= n;
    v[2] /= n;
}

static void bench_make_scenes(bench_scene_d *sc)
{
    static const double radius[BENCH_ORBITS] = {6378.137 + 500.0, 42164.0, 200000.0};
    static const double obs_dist[BENCH_ORBITS] = {50.0, 200.0, 1000.0};
    const double re = 6378.137, au = 149597870.7, rsun = 695700.0;
    int o, l, k, i, n = 0;
    for (o = 0; o < BENCH_ORBITS; o++) {
        for (l = 0; l < BENCH_LIGHTS; l++) {
            for (k = 0; k < BENCH_PER_CELL; k++) {
                bench_scene_d *s = &sc[n++];
                double u[3], v[3], w[3], dsun = au * (0.983 + 0.034 * bench_uniform());
                double r = radius[o], along, perp;
                bench_random_unit(u);
                bench_perp(u, v);
                for (i = 0; i < 3; i++) s->sun[i] = dsun * u[i];
                if (l == 0) {
                    double ang = 1.3962634015954636 * bench_uniform(); /* 0..80 deg */
                    along = r * cos(ang);
                    perp = r * sin(ang);
                } else {
                    double x = sqrt(r * r - re * re);
                    double alpha = asin(rsun / dsun);
                    double f = 0.15 + 0.7 * bench_uniform();
                    perp = l == 1 ? re + (2.0 * f - 1.0) * x * alpha : 0.5 * re;
                    along = -sqrt(r * r - perp * perp);
                }
                for (i = 0; i < 3; i++) s->target[i] = along * u[i] + perp * v[i];
                bench_random_unit(w);
                {
                    double dm = 363000.0 + 42000.0 * bench_uniform();
                    for (i = 0; i < 3; i++) s->moon[i] = dm * w[i];
                }
                bench_random_unit(w);
                for (i = 0; i < 3; i++) s->observer[i] = s->target[i] + obs_dist[o] * w[i];
                s->orbit = o;
                s->light = l;
            }
        }
    }
}

#endif
