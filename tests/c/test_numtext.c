/* SPDX-License-Identifier: MIT */
/* test_numtext.c: the planner's number text (planner/numtext.c)
 * against the C library it replaces: num_format17 byte for byte against
 * snprintf "%.17g", num_parse bit for bit (and end pointer) against strtod, on
 * millions of random doubles of every exponent, random decimal strings, texts
 * within 1e-19 of a midpoint between doubles, and the edge cases. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "orbillum.h"
#include "oi_test_util.h"

#include "../../planner/numtext.c"

static uint64_t rng_state = 0x9E3779B97F4A7C15ULL;

static uint64_t rand64(void)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return rng_state ^ (rng_state >> 29);
}

static double from_bits(uint64_t u)
{
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
}

static uint64_t to_bits(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static long failures = 0;

/* The reference: strtod, but for the forms the planner refuses (numtext.h:
 * decimal numbers and the words inf, infinity, nan only): text with leading
 * white space or hexadecimal text after the sign is no number (0, end at
 * text). */
static double ref_parse(const char *text, char **end)
{
    const char *p = text + (text[0] == '+' || text[0] == '-');
    if ((text[0] != '\0' && strchr(" \t\n\v\f\r", text[0]) != NULL) ||
        (p[0] == '0' && (p[1] == 'x' || p[1] == 'X'))) {
        *end = (char *)text;
        return 0.0;
    }
    return strtod(text, end);
}

/* num_parse(text) against ref_parse(text): the same bits (NaN: both NaN), the same end. */
static void check_parse(const char *text)
{
    char *e1, *e2;
    double a = ref_parse(text, &e1), b = num_parse(text, &e2);
    int same = (isnan(a) && isnan(b)) || to_bits(a) == to_bits(b);
    if (!same || e1 != e2) {
        if (failures++ < 10)
            print_error("num_parse(\"%s\") = %.17g end +%d, reference %.17g end +%d\n", text, b,
                        (int)(e2 - text), a, (int)(e1 - text));
    }
}

/* num_parse_n(text) read in a buffer with bytes after its NUL (as the CSV
 * record holds the next fields there): the same as strtod. */
static void check_parse_padded(const char *text)
{
    char buf[128], *e1, *e2;
    size_t n = strlen(text), i;
    double a, b;
    int same;
    if (n + 17 > sizeof buf) return;
    memcpy(buf, text, n + 1);
    for (i = n + 1; i < n + 17; i++) buf[i] = "0123456789.e,-"[rand64() % 14u];
    a = ref_parse(buf, &e1);
    b = num_parse_n(buf, n + 17, &e2);
    same = (isnan(a) && isnan(b)) || to_bits(a) == to_bits(b);
    if (!same || e1 != e2) {
        if (failures++ < 10)
            print_error("num_parse_n(\"%s\") = %.17g end +%d, reference %.17g end +%d\n", text, b,
                        (int)(e2 - buf), a, (int)(e1 - buf));
    }
}

/* num_format17(x) against snprintf("%.17g"), then both parsers on the text. */
static void check_format(double x)
{
    char want[64], got[NUM_TEXT_MAX];
    size_t n;
    (void)snprintf(want, sizeof want, "%.17g", x);
    n = num_format17(x, got);
    if (strcmp(want, got) != 0 || n != strlen(want)) {
        if (failures++ < 10) print_error("num_format17(%a) = \"%s\", printf \"%s\"\n", x, got, want);
    }
    check_parse(want);
    check_parse_padded(want);
}

static void test_random_bit_patterns(void **state)
{
    long i;
    (void)state;
    failures = 0;
    for (i = 0; i < 1000000; i++) check_format(from_bits(rand64()));
    assert_int_equal(failures, 0);
}

static void test_random_planner_magnitudes(void **state)
{
    long i;
    (void)state;
    failures = 0;
    for (i = 0; i < 1000000; i++) {
        /* log-uniform over 1e-30 .. 1e30, both signs: the planner's numbers */
        double u = (double)(rand64() >> 11) * (1.0 / 9007199254740992.0);
        double x = pow(10.0, 60.0 * u - 30.0);
        check_format((rand64() & 1u) ? -x : x);
    }
    assert_int_equal(failures, 0);
}

static void test_edges(void **state)
{
    static const double fixed[] = {
        0.0, -0.0, 1.0, -1.0, 0.1, 0.2, 0.3, 1.0 / 3.0, 2.0 / 3.0, 5e-324, 1e-323,
        2.2250738585072014e-308, 2.2250738585072009e-308, 1.7976931348623157e308,
        9007199254740992.0, 9007199254740993.0, 9007199254740991.0, 1e16, 1e17, 1e-5, 1e-4,
        9.9999999999999995e-5, 0.0001, 123456789012345678.0, 99999999999999999.0,
        9999999999999999.0, 1e280, 1e-280, 1.0000000000000002, 0.99999999999999989,
        1360.9600000000001, 6378.137, 149597870.7};
    size_t i;
    int k, j;
    (void)state;
    failures = 0;
    for (i = 0; i < sizeof fixed / sizeof fixed[0]; i++) {
        check_format(fixed[i]);
        check_format(-fixed[i]);
    }
    check_format(INFINITY);
    check_format(-INFINITY);
    check_format(NAN);
    /* powers of ten and of two and their neighbours, every exponent */
    for (k = -330; k <= 310; k++) {
        double p = pow(10.0, (double)k), q = ldexp(1.0, k * 3 + 10), a = p, b = p;
        for (j = 0; j < 4; j++) {
            check_format(a);
            check_format(b);
            a = nextafter(a, INFINITY);
            b = nextafter(b, 0.0);
        }
        a = b = q;
        for (j = 0; j < 3; j++) {
            check_format(a);
            check_format(b);
            a = nextafter(a, INFINITY);
            b = nextafter(b, 0.0);
        }
    }
    assert_int_equal(failures, 0);
}

static void test_strtod_forms(void **state)
{
    static const char *texts[] = {
        "0", "-0", "+1", "1e", "1e+", "1e-", "1.", ".5", "-.5e-3", "5.e2", "00012", "1.2.3",
        "12abc", "1,5", "inf", "-Infinity", "nan", "NaN(123)", "0x1p3", "0X1.8P1", "-0x",
        "1e400", "-1e400", "1e-400", "4.9e-324", "2.4703282292062328e-324",
        "2.4703282292062327e-324", "1e-320", "9007199254740993", "9007199254740992.5",
        "123456789012345678901234567890", "0.000000000000000000000000000001",
        "1.00000000000000000000000000001", "179769313486231580793728971405303415079934132710037826936173778980444968292764750946649017977587207096330286416692887910946555547851940402630657488671505820681908902000708383676273854845817711531764475730270069855571366959622842914819860834936475292719074168444365510704342711559699508093042880177904174497791.9",
        " 1", "\t2", "e5", ".", "-", "", "1e0001", "1E5", "-7e-22", "7e22", "7e23",
        "9007199254740991e22", "9007199254740993e-22", "1e99999999", "1e-99999999",
        "0x1B58", "-0x1B58", "+0X10", "0x", "0x1.8p1", "0xp3", "00x1", "\n5", "\v5", "\f5",
        "\r5", "-INF", "+nan", "infinity", "nanx", "i", "n"};
    /* hexadecimal text and leading white space: no number, whatever strtod
     * reads (the reference's rule checked by hand) */
    static const char *refused[] = {"0x1B58", "0x1p3", "-0x1p3", "+0X1.8P1", "0x", "-0x",
                                    " 1", "\t2", "\n5", "\v5"};
    size_t i;
    (void)state;
    failures = 0;
    for (i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        check_parse(texts[i]);
        check_parse_padded(texts[i]);
    }
    for (i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        char *e;
        const double x = num_parse(refused[i], &e);
        assert_true(e == refused[i]);
        assert_true(x == 0.0);
        (void)num_parse_n(refused[i], strlen(refused[i]), &e);
        assert_true(e == refused[i]);
    }
    assert_int_equal(failures, 0);
}

static void test_random_decimal_strings(void **state)
{
    long i;
    char text[64];
    (void)state;
    failures = 0;
    for (i = 0; i < 1000000; i++) {
        /* 1 to 20 digits, a point somewhere or none, an exponent or none */
        int nd = 1 + (int)(rand64() % 20u), pt = (int)(rand64() % (uint64_t)(nd + 2)), k, n = 0;
        int ex = (int)(rand64() % 701u) - 350;
        if (rand64() & 1u) text[n++] = '-';
        for (k = 0; k < nd; k++) {
            if (k == pt) text[n++] = '.';
            text[n++] = (char)('0' + (int)(rand64() % 10u));
        }
        if (rand64() % 3u) n += snprintf(text + n, sizeof text - (size_t)n, "e%d", ex);
        text[n] = '\0';
        check_parse(text);
        check_parse_padded(text);
    }
    assert_int_equal(failures, 0);
}

static void test_near_midpoints(void **state)
{
#if LDBL_MANT_DIG >= 64
    long i;
    char text[64];
    (void)state;
    failures = 0;
    for (i = 0; i < 300000; i++) {
        /* the midpoint between a double and the next, exact in long double,
         * printed to 19 digits: within 1e-19 of the boundary strtod rounds at */
        double d = from_bits(rand64() & 0x7FEFFFFFFFFFFFFFULL), up = nextafter(d, INFINITY);
        long double mid = ((long double)d + (long double)up) / 2.0L;
        (void)snprintf(text, sizeof text, "%.18Le", mid);
        check_parse(text);
        (void)snprintf(text, sizeof text, "%.17Le", mid);
        check_parse(text);
    }
    assert_int_equal(failures, 0);
#else
    (void)state;
    skip();
#endif
}

/* Integers (the formatter's own path: every digit, no point), decimals with
 * few digits (trailing zeros dropped), exact halfway cases of the 17th digit
 * (odd multiples of 2^-s: round half to even), subnormals. */
static void test_integers_short_and_halfway(void **state)
{
    long i;
    int s;
    (void)state;
    failures = 0;
    for (i = 0; i <= 100000; i++) check_format((double)i);
    for (i = 0; i < 400000; i++) {
        /* an integer of 1 to 18 digits, and its neighbours */
        uint64_t m = rand64() % 1000000000000000000ULL;
        double x = (double)(m >> (rand64() % 60u));
        check_format(x);
        check_format(nextafter(x, INFINITY));
        check_format(-nextafter(x, 0.0));
    }
    for (i = 0; i < 300000; i++) {
        /* 1 to 6 significant digits times a power of ten */
        double d = (double)(rand64() % 1000000u);
        int k = (int)(rand64() % 80u) - 40;
        check_format(d * pow(10.0, (double)k));
    }
    for (s = 1; s <= 40; s++) {
        for (i = 0; i < 20000; i++) {
            /* odd m 2^-s: 18 significant digits ending in 5 for s near 2..4 */
            uint64_t m = (rand64() >> 11) | 1u;
            check_format(ldexp((double)m, -s));
            check_format(ldexp((double)(m >> (rand64() % 40u) | 1u), -s));
        }
    }
    for (i = 0; i < 200000; i++) {
        /* subnormals and the smallest normals */
        check_format(from_bits(rand64() & 0x001FFFFFFFFFFFFFULL));
    }
    assert_int_equal(failures, 0);
}

static void test_digits_with_zeros(void **state)
{
    /* 17 significant digits with a run of zeros at each place and the rest
     * random (half of them zeros), at exponents -6..20: every lane of the
     * sixteen-digit step and its count up to the last nonzero digit */
    char text[64];
    long i;
    int z, k;
    (void)state;
    failures = 0;
    for (i = 0; i < 20000; i++) {
        for (z = 0; z <= 16; z++) {
            char d[18];
            double x;
            for (k = 0; k < 17; k++) {
                uint64_t u = rand64();
                d[k] = (char)('0' + ((u & 1u) ? (int)((u >> 1) % 10u) : 0));
            }
            if (d[0] == '0') d[0] = '1';
            for (k = 17 - z; k < 17; k++) d[k] = '0'; /* z trailing zeros */
            d[17] = '\0';
            (void)snprintf(text, sizeof text, "%c.%se%d", d[0], d + 1, (int)(rand64() % 27u) - 6);
            x = strtod(text, NULL);
            check_format(x);
            check_format(-x);
            check_format(nextafter(x, INFINITY));
        }
    }
    assert_int_equal(failures, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_edges),
        cmocka_unit_test(test_strtod_forms),
        cmocka_unit_test(test_random_bit_patterns),
        cmocka_unit_test(test_random_planner_magnitudes),
        cmocka_unit_test(test_random_decimal_strings),
        cmocka_unit_test(test_near_midpoints),
        cmocka_unit_test(test_integers_short_and_halfway),
        cmocka_unit_test(test_digits_with_zeros),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
