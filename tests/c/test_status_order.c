/* SPDX-License-Identifier: MIT */
/*
 * test_status_order.c: oi_illuminate's errors come in the order its contract
 * lists them (include/orbillum/scene.h): a scene with two faults gets the
 * first one listed. The pairs are where the list is easy to misread: an
 * albedo's range before a NaN target radius, the albedo model's epoch
 * before the shape.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>

#include "orbillum.h"
#include "oi_test_util.h"

static void lit_scene(oi_scene *s)
{
    oi_scene_defaults(s);
    set3(s->sun_km, 149597870.7, 0, 0);
    set3(s->target_km, 0, 7000.0, 0);
    s->terms = OI_TERM_SUN | OI_TERM_EARTH;
}

static void test_albedo_range_before_radius(void **state)
{
    oi_scene s;
    oi_illum o;
    (void)state;
    lit_scene(&s);
    s.earth_albedo = (oi_real)2;
    s.target_radius_m = (oi_real)NAN;
    check_int(OI_ERR_ALBEDO, oi_illuminate(&s, NULL, &o), "albedo out of range, radius NaN");
    s.earth_albedo = (oi_real)0.3;
    check_int(OI_ERR_NONFINITE, oi_illuminate(&s, NULL, &o), "radius NaN alone");
    s.target_radius_m = (oi_real)-1;
    s.target_albedo = (oi_real)NAN;
    check_int(OI_ERR_NONFINITE, oi_illuminate(&s, NULL, &o), "albedo NaN, radius < 0");
}

#if !defined(OI_NO_ALBEDO_MODELS) && !defined(OI_NO_FACETS)
static void test_epoch_before_shape(void **state)
{
    oi_scene s;
    oi_illum o;
    oi_model m;
    oi_shape bad;
    (void)state;
    lit_scene(&s);
    memset(&m, 0, sizeof m);
    m.albedo_model = OI_ALBEDO_KNOCKE;
    memcpy(&bad, oi_shape_builtin(0), sizeof bad);
    bad.n_facets = 0; /* fails oi_shape_check */
    s.shape = &bad;
    s.epoch_jd = (oi_real)NAN;
    check_int(OI_ERR_NONFINITE, oi_illuminate(&s, &m, &o), "epoch NaN, bad shape");
    s.epoch_jd = (oi_real)1e9;
    check_int(OI_ERR_INPUT, oi_illuminate(&s, &m, &o), "epoch out of range, bad shape");
    s.epoch_jd = (oi_real)2461000.5;
    check_int(OI_ERR_SHAPE, oi_illuminate(&s, &m, &o), "bad shape alone");
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_albedo_range_before_radius),
#if !defined(OI_NO_ALBEDO_MODELS) && !defined(OI_NO_FACETS)
        cmocka_unit_test(test_epoch_before_shape),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
