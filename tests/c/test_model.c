/* SPDX-License-Identifier: MIT */
/* test_model.c: oi__model_resolve (src/model/model.c), the validation every public
 * function that takes an oi_model goes through. Expected statuses and values
 * are written from the contract in include/orbillum.h (oi_model: zero means
 * default; non-finite, negative or out-of-bounds gives OI_ERR_MODEL, for a
 * radius OI_ERR_RADIUS; on error the output is the default model) and
 * src/oi_internal.h (radii are checked first; a non-finite radius is
 * OI_ERR_MODEL), not from the code under test. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "oi_internal.h"
#include "oi_atm_vband.h"

/* the fields, by name, for the loops below */
enum { F_TSI, F_AU, F_SUN_R, F_EARTH_R, F_MOON_R, F_ALBEDO, N_F };
static oi_real *field(oi_model *m, int f)
{
    switch (f) {
    case F_TSI: return &m->tsi_w_m2;
    case F_AU: return &m->au_km;
    case F_SUN_R: return &m->sun_radius_km;
    case F_EARTH_R: return &m->earth_radius_km;
    case F_MOON_R: return &m->moon_radius_km;
    default: return &m->moon_albedo;
    }
}
static int is_radius(int f)
{
    return f == F_SUN_R || f == F_EARTH_R || f == F_MOON_R;
}
/* bounds from include/orbillum.h */
static oi_real lo_of(int f)
{
    return is_radius(f) ? (oi_real)OI_MODEL_RADIUS_MIN
           : f == F_TSI ? (oi_real)OI_MODEL_TSI_MIN
           : f == F_AU  ? (oi_real)OI_MODEL_AU_MIN
                        : (oi_real)0;
}
static oi_real hi_of(int f)
{
    return is_radius(f) ? (oi_real)OI_MODEL_RADIUS_MAX
           : f == F_TSI ? (oi_real)OI_MODEL_TSI_MAX
           : f == F_AU  ? (oi_real)OI_MODEL_AU_MAX
                        : (oi_real)1;
}

static int check_default(const oi_model *m)
{
    int ok = m->tsi_w_m2 == (oi_real)OI_TSI_W_M2 && m->au_km == (oi_real)OI_AU_KM &&
             m->sun_radius_km == (oi_real)OI_SUN_RADIUS_KM &&
             m->earth_radius_km == (oi_real)OI_EARTH_RADIUS_KM &&
             m->moon_radius_km == (oi_real)OI_MOON_RADIUS_KM &&
             m->moon_albedo == (oi_real)OI_MOON_ALBEDO_DEFAULT && m->earth_model == 0 &&
             m->moon_model == 0 && m->limb_darkening == 0 && m->no_atmosphere == 0 &&
             m->earth_table == NULL && m->atm_table == NULL;
    if (!ok)
        printf("not the default model: tsi %.17g au %.17g rs %.17g re %.17g rm %.17g alb %.17g "
               "opts %d %d %d %d\n",
               (double)m->tsi_w_m2, (double)m->au_km, (double)m->sun_radius_km,
               (double)m->earth_radius_km, (double)m->moon_radius_km, (double)m->moon_albedo,
               m->earth_model, m->moon_model, m->limb_darkening, m->no_atmosphere);
    return ok;
}

static void expect(const oi_model *in, int want, const char *what)
{
    oi_model out;
    int got;
    memset(&out, 0x5a, sizeof out);
    got = oi__model_resolve(in, &out);
    if (got != want) printf("%s: want status %d got %d\n", what, want, got);
    assert_int_equal(got, want);
    if (want != OI_OK) assert_true(check_default(&out));
}

static void test_null_and_zero_are_default(void **state)
{
    oi_model in, out;
    (void)state;
    assert_int_equal(oi__model_resolve(NULL, &out), OI_OK);
    assert_true(check_default(&out));
    memset(&in, 0, sizeof in);
    memset(&out, 0x5a, sizeof out);
    assert_int_equal(oi__model_resolve(&in, &out), OI_OK);
    assert_true(check_default(&out));
    in.moon_albedo = (oi_real)-0.0; /* -0 is zero: the default */
    assert_int_equal(oi__model_resolve(&in, &out), OI_OK);
    assert_true(check_default(&out));
}

static void test_values_are_kept(void **state)
{
    static const oi_earth_table *const tab = (const oi_earth_table *)&tab;
    static const oi_atm_table *const atm = (const oi_atm_table *)&atm;
    oi_model in, out;
    int f;
    (void)state;
    memset(&in, 0, sizeof in);
    for (f = 0; f < N_F; f++) *field(&in, f) = lo_of(f) > 0 ? lo_of(f) : OI_R(0.5);
    in.earth_model = OI_EARTH_LAMBERT;
    in.moon_model = OI_MOON_LAMBERT;
    in.no_atmosphere = 7;
    in.earth_table = tab;
    in.atm_table = atm; /* not checked: the atmosphere is off */
    assert_int_equal(oi__model_resolve(&in, &out), OI_OK);
    for (f = 0; f < N_F; f++) {
        oi_real want = *field(&in, f), got = *field(&out, f);
        if (got != want) printf("field %d: want %.17g got %.17g\n", f, (double)want, (double)got);
        assert_true(got == want);
    }
    assert_int_equal(out.earth_model, OI_EARTH_LAMBERT);
    assert_int_equal(out.moon_model, OI_MOON_LAMBERT);
    assert_int_equal(out.limb_darkening, OI_LIMB_UNIFORM);
    assert_int_equal(out.no_atmosphere, 1);
    assert_true(out.earth_table == tab);
    assert_true(out.atm_table == atm);
    /* the upper bounds are accepted too */
    for (f = 0; f < N_F; f++) *field(&in, f) = hi_of(f);
    assert_int_equal(oi__model_resolve(&in, &out), OI_OK);
    for (f = 0; f < N_F; f++) assert_true(*field(&out, f) == hi_of(f));
}

static void test_each_field_rejected(void **state)
{
    const oi_real inf = (oi_real)INFINITY, nan = (oi_real)NAN;
    int f, v;
    char what[96];
    (void)state;
    for (f = 0; f < N_F; f++) {
        /* value, and whether it is finite */
        const oi_real bad[6] = {(oi_real)-1, -lo_of(f) - (oi_real)1, nan, inf, -inf,
                                hi_of(f) * (oi_real)2};
        const int finite[6] = {1, 1, 0, 0, 0, 1};
        for (v = 0; v < 6; v++) {
            oi_model in;
            memset(&in, 0, sizeof in);
            *field(&in, f) = bad[v];
            snprintf(what, sizeof what, "field %d value %.17g", f, (double)bad[v]);
            expect(&in, is_radius(f) && finite[v] ? OI_ERR_RADIUS : OI_ERR_MODEL, what);
        }
        if (lo_of(f) > 0) {
            oi_model in;
            memset(&in, 0, sizeof in);
            *field(&in, f) = lo_of(f) * OI_R(0.5); /* positive, below the bound */
            snprintf(what, sizeof what, "field %d below its bound", f);
            expect(&in, is_radius(f) ? OI_ERR_RADIUS : OI_ERR_MODEL, what);
        }
    }
}

static void test_precedence(void **state)
{
    oi_model in;
    (void)state;
    /* a bad radius with a non-finite radius elsewhere: OI_ERR_MODEL, before
     * or after it */
    memset(&in, 0, sizeof in);
    in.sun_radius_km = (oi_real)-1;
    in.moon_radius_km = (oi_real)NAN;
    expect(&in, OI_ERR_MODEL, "negative sun radius, NaN moon radius");
    memset(&in, 0, sizeof in);
    in.sun_radius_km = (oi_real)INFINITY;
    in.moon_radius_km = (oi_real)-1;
    expect(&in, OI_ERR_MODEL, "infinite sun radius, negative moon radius");
    memset(&in, 0, sizeof in);
    in.earth_radius_km = (oi_real)NAN;
    in.moon_radius_km = (oi_real)-1;
    expect(&in, OI_ERR_MODEL, "NaN earth radius, negative moon radius");
    /* radii are checked before the other fields */
    memset(&in, 0, sizeof in);
    in.earth_radius_km = (oi_real)-1;
    in.tsi_w_m2 = (oi_real)NAN;
    in.earth_model = 5;
    expect(&in, OI_ERR_RADIUS, "negative earth radius, NaN tsi, bad option");
    /* a bad non-radius field with finite radii: OI_ERR_MODEL */
    memset(&in, 0, sizeof in);
    in.moon_radius_km = (oi_real)1000;
    in.au_km = (oi_real)-1;
    expect(&in, OI_ERR_MODEL, "negative au");
}

static void test_options(void **state)
{
    static const int bad[] = {2, -1, 3, 1000, -2147483647 - 1};
    oi_model in;
    size_t i;
    (void)state;
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        memset(&in, 0, sizeof in);
        in.earth_model = bad[i];
        expect(&in, OI_ERR_MODEL, "earth_model");
        memset(&in, 0, sizeof in);
        in.moon_model = bad[i];
        expect(&in, OI_ERR_MODEL, "moon_model");
        memset(&in, 0, sizeof in);
        in.limb_darkening = bad[i];
        expect(&in, OI_ERR_MODEL, "limb_darkening");
    }
    memset(&in, 0, sizeof in);
    in.limb_darkening = OI_LIMB_DARKENED;
#ifdef OI_NO_LIMB_DARKENING
    expect(&in, OI_ERR_MODEL, "limb darkening compiled out");
#else
    expect(&in, OI_OK, "limb darkening");
#endif
}

/* A caller's atmosphere table is checked where it is used (atmosphere on)
 * and kept; one that fails its check gives OI_ERR_MODEL and the default
 * model (each failing field: tests/c/test_atmosphere.c). */
static void test_atm_table(void **state)
{
#ifdef OI_NO_ATMOSPHERE
    (void)state;
    printf("test_atm_table: OI_NO_ATMOSPHERE, the table is never used or checked\n");
#else
    oi_atm_table t = oi_atm_vband;
    oi_model in, out;
    (void)state;
    memset(&in, 0, sizeof in);
    in.atm_table = &t;
    assert_int_equal(oi__model_resolve(&in, &out), OI_OK);
    assert_true(out.atm_table == &t);
    t.nt = t.na; /* nt != na + nb */
    expect(&in, OI_ERR_MODEL, "atm_table with nt != na + nb");
    in.no_atmosphere = 1; /* off: not used, not checked */
    assert_int_equal(oi__model_resolve(&in, &out), OI_OK);
    assert_true(out.atm_table == &t);
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_atm_table),
        cmocka_unit_test(test_null_and_zero_are_default),
        cmocka_unit_test(test_values_are_kept),
        cmocka_unit_test(test_each_field_rejected),
        cmocka_unit_test(test_precedence),
        cmocka_unit_test(test_options),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
