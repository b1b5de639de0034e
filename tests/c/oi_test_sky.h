/* SPDX-License-Identifier: MIT */
/*
 * oi_test_sky.h: the scenes the sky-background tests share (test_sky.c,
 * test_starlight.c): a lit target's illumination, oi_expose_scene of an
 * observer looking at a target, and the night side's nadir. Include after
 * "oi_test_util.h"; static inline, under the exposure's option.
 */
#ifndef OI_TEST_SKY_H
#define OI_TEST_SKY_H

#ifndef OI_NO_EXPOSURE
/* A lit target of flux `flux` (W/m^2) at 1 AU, the Moon unshadowed. */
static inline oi_illum oi_test_lit_illum(double flux)
{
    oi_illum il;
    memset(&il, 0, sizeof il);
    il.flux_obs = (oi_real)flux;
    il.e_sun = (oi_real)1361.0;
    il.moon_sun_fraction = 1;
    il.shadow.region = OI_SHADOW_LIT;
    return il;
}

/* oi_expose_scene of the default scene with the Sun, the observer and the
 * target at the given positions (km) and goal.sky = sky (must return
 * OI_OK); the background radiance it used. */
static inline double oi_test_sky_background(const oi_camera *c, const oi_illum *il, unsigned sky,
                                            const oi_real sun[3], const oi_real observer[3],
                                            const oi_real target[3], oi_exposure *out)
{
    oi_scene s;
    oi_expose_goal goal;
    memset(&goal, 0, sizeof goal);
    goal.sky = sky;
    oi_scene_defaults(&s);
    memcpy(s.sun_km, sun, sizeof s.sun_km);
    memcpy(s.observer_km, observer, sizeof s.observer_km);
    memcpy(s.target_km, target, sizeof s.target_km);
    s.has_observer = 1;
    check_int(OI_OK, oi_expose_scene(c, &s, il, NULL, &goal, out), "status");
    return (double)out->background_w_m2_sr;
}

/* Looking straight down at the night side from 1000 km (the target at
 * 500 km, the Sun behind the Earth): the ray ends on the Earth. */
static inline double oi_test_night_nadir(const oi_camera *c, const oi_illum *il, unsigned sky,
                                         oi_exposure *out)
{
    oi_real sun[3], observer[3], target[3];
    set3(sun, -149597870.7, 0, 0);
    set3(observer, 6378.137 + 1000, 0, 0);
    set3(target, 6378.137 + 500, 0, 0);
    return oi_test_sky_background(c, il, sky, sun, observer, target, out);
}
#endif

#endif /* OI_TEST_SKY_H */
