/* SPDX-License-Identifier: MIT */
/*
 * selftest.c: the bare-metal self-test of the runtime on a Cortex-M under
 * qemu-system-arm (make target-test). Prints one line per failed check, a
 * pass count, the measured stack use of the public calls, and returns 0 if
 * every check passed, 1 otherwise (the semihosting exit status).
 *
 * References are independent of the library: closed forms written here
 * (Lambert phase function, spherical lune, cap area, inverse-square law,
 * magnitudes), a Simpson quadrature of the sub-solar earthshine integral
 * computed here in double precision, and the golden vectors that the other
 * test suites commit (tests/c/ref_*.h, generated with mpmath), included when
 * present (target/golden_*.c).
 *
 * Built once per core: Cortex-M4F with OI_SINGLE_PRECISION, Cortex-M7 in
 * double. Tolerances are per precision.
 */
#include <stddef.h>
#include <stdint.h>

#include "orbillum.h"
#include "check.h"
#include "semihost.h"

#ifdef OI_SINGLE_PRECISION
#define TOL_REL (2e-5)
#define TOL_ABS (1e-6)
#define TOL_ES (2e-3)   /* earthshine table against this quadrature: goal 1e-3 + float inputs */
#else
#define TOL_REL (1e-12)
#define TOL_ABS (1e-14)
#define TOL_ES (1e-3)   /* earthshine table against this quadrature: the table's goal */
#endif

static const double PI = 3.14159265358979323846;
static const double AU = 149597870.7;
static const double TSI = 1361.0;
static const double RE = 6378.137;

static int n_pass, n_fail, n_known;

/* Called by the stubs of target/stubs.c when a public function is missing
 * from the library being tested: counts as a failure. */
void oi_target_missing(const char *name);
void oi_target_missing(const char *name)
{
    sh_puts("MISSING ");
    sh_puts(name);
    sh_puts(" (stub linked: the library does not define it)\n");
    n_fail++;
}

static double dabs(double x) { return x < 0 ? -x : x; }

void check_real(const char *what, double want, double got, double abs_tol, double rel_tol)
{
    double err = dabs(got - want);
    if (err <= abs_tol + rel_tol * dabs(want)) {
        n_pass++;
        return;
    }
    n_fail++;
    sh_puts("FAIL ");
    sh_puts(what);
    sh_puts(": want ");
    sh_putreal(want);
    sh_puts(" got ");
    sh_putreal(got);
    sh_puts("\n");
}

void check_int(const char *what, long want, long got)
{
    if (want == got) {
        n_pass++;
        return;
    }
    n_fail++;
    sh_puts("FAIL ");
    sh_puts(what);
    sh_puts(": want ");
    sh_putint(want);
    sh_puts(" got ");
    sh_putint(got);
    sh_puts("\n");
}

void check_true(const char *what, int cond)
{
    check_int(what, 1L, cond ? 1L : 0L);
}

void note_known(void)
{
    n_known++;
}

void check_known(const char *what, double want, double got, double abs_tol, double rel_tol,
                 const char *why)
{
#ifndef OI_TARGET_STRICT
    double err = dabs(got - want);
    if (!(err <= abs_tol + rel_tol * dabs(want))) {
        n_known++;
        sh_puts("KNOWN ");
        sh_puts(what);
        sh_puts(": want ");
        sh_putreal(want);
        sh_puts(" got ");
        sh_putreal(got);
        sh_puts(" (");
        sh_puts(why);
        sh_puts(")\n");
        return;
    }
#else
    (void)why;
#endif
    check_real(what, want, got, abs_tol, rel_tol);
}

static int str_eq(const char *a, const char *b)
{
    if (a == 0 || b == 0) return a == b;
    while (*a && *a == *b) { a++; b++; }
    return *a == *b;
}

static void set3(oi_real v[3], double x, double y, double z)
{
    v[0] = (oi_real)x;
    v[1] = (oi_real)y;
    v[2] = (oi_real)z;
}

/* ------------------------------------------------------------ references */

static double dsin(double x);
static double dcos(double x);

/* sin and cos by argument reduction to [-pi/4, pi/4] and Taylor series, so
 * that the references do not use the libm that the library uses. */
static double poly_sin(double x)
{
    double x2 = x * x, term = x, sum = x;
    int k;
    for (k = 1; k < 12; k++) {
        term *= -x2 / (double)((2 * k) * (2 * k + 1));
        sum += term;
    }
    return sum;
}

static double poly_cos(double x)
{
    double x2 = x * x, term = 1.0, sum = 1.0;
    int k;
    for (k = 1; k < 12; k++) {
        term *= -x2 / (double)((2 * k - 1) * (2 * k));
        sum += term;
    }
    return sum;
}

static double dsin(double x)
{
    double q = x / (PI / 2);
    long n = (long)(q < 0 ? q - 0.5 : q + 0.5);
    double r = x - (double)n * (PI / 2);
    switch (((n % 4) + 4) % 4) {
    case 0: return poly_sin(r);
    case 1: return poly_cos(r);
    case 2: return -poly_sin(r);
    default: return -poly_cos(r);
    }
}

static double dcos(double x)
{
    return dsin(x + PI / 2);
}

static double dsqrt(double x)
{
    double y = x > 1 ? x : 1.0;
    int k;
    if (x <= 0) return 0;
    for (k = 0; k < 200; k++) {
        double n = 0.5 * (y + x / y);
        if (n == y) break;
        y = n;
    }
    return y;
}

static double lambert_ref(double xi)
{
    return 2.0 / (3.0 * PI) * ((PI - xi) * dcos(xi) + dsin(xi));
}

/* Sub-solar earthshine (theta = 0) at distance r from the centre of a
 * Lambertian Earth of radius 1 (docs/physics.md, earthshine):
 *   phi = 2 int_x^1 u (u/x - 1) / (1/x^2 + 1 - 2u/x)^(3/2) du,  x = R/r,
 * u the cosine of the angle at the centre; every visible point is lit.
 * Composite Simpson rule, n intervals (the integrand is smooth). */
static double phi_subsolar_ref(double x)
{
    const int n = 4000;
    double a = x, b = 1.0, h = (b - a) / n, sum = 0.0;
    double r = 1.0 / x;
    int i;
    for (i = 0; i <= n; i++) {
        double u = a + h * i;
        double d2 = r * r + 1.0 - 2.0 * r * u;
        double f = u * (r * u - 1.0) / (d2 * dsqrt(d2));
        double w = (i == 0 || i == n) ? 1.0 : ((i & 1) ? 4.0 : 2.0);
        sum += w * f;
    }
    return 2.0 * sum * h / 3.0;
}

/* ------------------------------------------------------------ stack probe */

extern uint32_t _sstack[];
#define PAINT (0xA5C3E17Bu)

/* Run fn with the free stack painted and return the depth it reached below
 * the caller's stack pointer (bytes). The thunks keep their data in static
 * storage, so their own frames (a return address and alignment) add only
 * a few bytes to the public function's use. */
static uint32_t stack_probe(void (*fn)(void))
{
    uint32_t sp;
    volatile uint32_t *p;
    volatile uint32_t *lo = _sstack;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    for (p = lo; (uint32_t)(uintptr_t)p < sp - 8u; p++) *p = PAINT;
    fn();
    for (p = lo; (uint32_t)(uintptr_t)p < sp - 8u && *p == PAINT; p++) {
    }
    return sp - (uint32_t)(uintptr_t)p;
}

/* ------------------------------------------------------------ checks */

static void test_phase(void)
{
    oi_real x[3], y[3], z[3];
    check_real("lambert_phase(0) = 2/3", 2.0 / 3.0, (double)oi_lambert_phase((oi_real)0), TOL_ABS, TOL_REL);
    check_real("lambert_phase(pi/2) = 2/(3pi)", 2.0 / (3.0 * PI),
               (double)oi_lambert_phase((oi_real)(PI / 2)), TOL_ABS, TOL_REL);
    check_real("lambert_phase(pi) = 0", 0.0, (double)oi_lambert_phase((oi_real)PI), TOL_ABS, 0);
    check_real("lambert_phase(1)", lambert_ref(1.0), (double)oi_lambert_phase(OI_R(1.0)), TOL_ABS, TOL_REL);
    check_real("lambert_phase(2.5)", lambert_ref(2.5), (double)oi_lambert_phase(OI_R(2.5)), TOL_ABS, TOL_REL);
    set3(x, 7000, 0, 0);
    set3(y, 0, 3, 0);
    set3(z, -1e8, 0, 0);
    check_real("angle(x, y) = pi/2", PI / 2, (double)oi_angle(x, y), TOL_ABS, TOL_REL);
    check_real("angle(x, x) = 0", 0.0, (double)oi_angle(x, x), TOL_ABS, 0);
    check_real("angle(x, -x) = pi", PI, (double)oi_angle(x, z), TOL_ABS, TOL_REL);
    set3(z, 0, 0, 0);
    check_real("angle(x, 0) = 0", 0.0, (double)oi_angle(x, z), 0, 0);
}

static void test_overlap(void)
{
    double cap = 2 * PI * (1 - dcos(0.1));
    check_real("cap_overlap disjoint = 0", 0.0,
               (double)oi_cap_overlap(OI_R(0.1), OI_R(0.2), OI_R(1.0)), 0, 0);
    check_real("cap_overlap contained = small cap", cap,
               (double)oi_cap_overlap(OI_R(0.1), OI_R(0.5), OI_R(0.2)), TOL_ABS, TOL_REL);
    check_real("cap_overlap concentric equal = cap", cap,
               (double)oi_cap_overlap(OI_R(0.1), OI_R(0.1), OI_R(0.0)), TOL_ABS, TOL_REL);
    /* two hemispheres with centres d apart meet in a lune of angle pi - d */
    check_known("cap_overlap hemispheres = lune 2(pi - d)", 2 * (PI - 1.0),
                (double)oi_cap_overlap((oi_real)(PI / 2), (oi_real)(PI / 2), OI_R(1.0)), TOL_ABS,
                TOL_REL, "src/shadow.c: large caps, docs/stability.md findings");
}

static void test_sun_fraction(void)
{
    oi_real sun[3], pt[3];
    oi_shadow sh;
    int st;
    set3(sun, AU, 0, 0);
    set3(pt, 0, 7000, 0);
    st = oi_sun_fraction(sun, pt, NULL, &sh);
    check_int("sun_fraction lit status", OI_OK, st);
    check_real("sun_fraction lit = 1", 1.0, (double)sh.fraction, 0, 0);
    check_int("sun_fraction lit region", OI_SHADOW_LIT, sh.region);
    set3(pt, -7000, 0, 0);
    st = oi_sun_fraction(sun, pt, NULL, &sh);
    check_int("sun_fraction umbra status", OI_OK, st);
    check_real("sun_fraction umbra = 0", 0.0, (double)sh.fraction, 0, 0);
    check_int("sun_fraction umbra region", OI_SHADOW_UMBRA, sh.region);
    /* on the shadow cylinder's edge, 2884 km behind the terminator plane:
     * inside the penumbra (its width there is ~27 km) */
    set3(pt, -2884.0, RE, 0);
    st = oi_sun_fraction(sun, pt, NULL, &sh);
    check_int("sun_fraction penumbra region", OI_SHADOW_PENUMBRA, sh.region);
    check_true("sun_fraction penumbra in (0, 1)", sh.fraction > 0 && sh.fraction < 1);
    set3(pt, 1000, 0, 0);
    sh.fraction = OI_R(0.5);
    st = oi_sun_fraction(sun, pt, NULL, &sh);
    check_int("sun_fraction below surface", OI_ERR_BELOW_SURFACE, st);
    check_real("sun_fraction error zeroes output", 0.0, (double)sh.fraction, 0, 0);
    set3(pt, 7000, 0, 0);
    pt[1] = pt[1] / (oi_real)0 * (oi_real)0; /* NaN */
    st = oi_sun_fraction(sun, pt, NULL, &sh);
    check_int("sun_fraction NaN", OI_ERR_NONFINITE, st);
}

static void test_earthshine(void)
{
    static const double h_km[3] = {500.0, 35786.0, 384400.0};
    static const char *const name[3] = {"earthshine subsolar LEO", "earthshine subsolar GEO",
                                        "earthshine subsolar lunar distance"};
    oi_real phi, psi;
    int i, st;
    for (i = 0; i < 3; i++) {
        double x = RE / (RE + h_km[i]);
        st = oi_earthshine((oi_real)0, (oi_real)h_km[i], NULL, &phi, &psi);
        check_true("earthshine status >= 0", st >= 0);
        check_real(name[i], phi_subsolar_ref(x), (double)phi, 0, TOL_ES);
        check_real("earthshine subsolar psi = 0", 0.0, (double)psi, 1e-6, 0);
    }
    /* on the anti-solar axis only the night side is visible */
    st = oi_earthshine((oi_real)PI, OI_R(1000.0), NULL, &phi, &psi);
    check_true("earthshine antisolar status >= 0", st >= 0);
    check_real("earthshine antisolar = 0", 0.0, (double)phi, 1e-9, 0);
    st = oi_earthshine(OI_R(1.0), OI_R(-10.0), NULL, &phi, &psi);
    check_int("earthshine below surface", OI_ERR_BELOW_SURFACE, st);
}

#ifndef OI_NO_MOON
static void test_moon(void)
{
    /* 10^(-0.4 (0.026 a + 4e-9 a^4)) at a = 90 deg: exponent written out */
    double a = 90.0, e = -0.4 * (0.026 * a + 4e-9 * a * a * a * a);
    double want = 1.0, ln10 = 2.302585092994045684, t = e * ln10, term = 1.0;
    int k;
    for (k = 1; k < 40; k++) { /* exp by its series (|t| < 1) */
        term *= t / k;
        want += term;
    }
    check_real("moon_phase_law(0) = 1", 1.0, (double)oi_moon_phase_law((oi_real)0), TOL_ABS, TOL_REL);
    check_real("moon_phase_law(90 deg)", want, (double)oi_moon_phase_law((oi_real)(PI / 2)), TOL_ABS,
               TOL_REL * 10);
}
#endif

static void test_magnitude(void)
{
    oi_real f = OI_R(-1.0);
    int st;
    check_real("magnitude_v(TSI) = m_sun", -26.74, (double)oi_magnitude_v((oi_real)TSI, NULL), 1e-9,
               TOL_REL * 10);
    check_real("magnitude_v(TSI/100) = m_sun + 5", -21.74,
               (double)oi_magnitude_v((oi_real)(TSI / 100), NULL), 1e-9, TOL_REL * 10);
    check_real("magnitude_v(0) = dark", 99.0, (double)oi_magnitude_v((oi_real)0, NULL), 0, 0);
    st = oi_flux_from_magnitude(OI_R(-26.74), NULL, &f);
    check_int("flux_from_magnitude status", OI_OK, st);
    check_real("flux_from_magnitude(m_sun) = TSI", TSI, (double)f, 0, TOL_REL * 10);
    st = oi_flux_from_magnitude(OI_R(60.0), NULL, &f);
    check_int("flux_from_magnitude out of range", OI_ERR_MAGNITUDE, st);
    check_real("flux_from_magnitude error zeroes", 0.0, (double)f, 0, 0);
    check_true("status_name(0) = OK", str_eq(oi_status_name(OI_OK), "OK"));
    check_true("status_name(-2) = ERR_NONFINITE", str_eq(oi_status_name(OI_ERR_NONFINITE), "ERR_NONFINITE"));
    check_true("status_name(999) = UNKNOWN", str_eq(oi_status_name(999), "UNKNOWN"));
}

static void test_illuminate(void)
{
    oi_scene s;
    oi_illum il;
    double d2, xi, want;
    int st;
    oi_scene_defaults(&s);
    set3(s.sun_km, AU, 0, 0);
    set3(s.target_km, 0, 7000, 0);
    set3(s.observer_km, 100, 7000, 0);
    s.has_observer = 1;
    s.terms = OI_TERM_SUN;
    st = oi_illuminate(&s, NULL, &il);
    check_int("illuminate lit status", OI_OK, st);
    d2 = AU * AU + 7000.0 * 7000.0;
    check_real("illuminate e_sun = TSI (AU/d)^2", TSI * AU * AU / d2, (double)il.e_sun, 0, TOL_REL * 10);
    /* phase angle at the target between the Sun and the observer (+x): tiny;
     * flux = E alpha a^2 p(xi) / d^2, radius 1 m, range 100 km */
    xi = 7000.0 / AU; /* angle between (AU, -7000) and (1, 0) */
    want = TSI * AU * AU / d2 * 0.2 * 1.0 * lambert_ref(xi) / (1e5 * 1e5);
    check_real("illuminate flux_sun = Lambert sphere", want, (double)il.flux_sun, 0, TOL_REL * 10);
    set3(s.target_km, -7000, 0, 0);
    set3(s.observer_km, -7000, 100, 0);
    st = oi_illuminate(&s, NULL, &il);
    check_int("illuminate umbra status", OI_OK, st);
    check_real("illuminate umbra e_sun = 0", 0.0, (double)il.e_sun, 0, 0);
    s.terms = 64u;
    st = oi_illuminate(&s, NULL, &il);
    check_int("illuminate bad terms", OI_ERR_TERMS, st);
}

#ifndef OI_NO_EXPOSURE
static void test_exposure(void)
{
    const oi_camera *cam = oi_camera_builtin(0);
    oi_expose_in in;
    oi_exposure ex;
    int st, i, found = 0;
    check_true("camera_builtin(0) exists", cam != NULL);
    if (cam == NULL) return;
    check_true("camera_find(builtin 0 name)", oi_camera_find(cam->name) == cam);
    check_true("camera_find(unknown) = NULL", oi_camera_find("no such camera") == NULL);
    check_true("flag_name(sun_exclusion)", str_eq(oi_flag_name(OI_FLAG_SUN_EXCLUSION), "sun_exclusion"));
    in.rate_rad_s = 0; /* at rest */
    in.flux_w_m2 = OI_R(1e-12);
    in.background_w_m2_sr = (oi_real)0;
    in.flags = 0u;
    st = oi_expose(cam, &in, NULL, &ex);
    check_true("expose status >= 0", st >= 0);
    for (i = 0; i < cam->n_times; i++) found |= ex.exposure_s == cam->times_s[i];
    check_true("expose picks one of the camera's times", found);
    check_true("expose fill within [0, 1] unless saturated",
               (ex.flags & (OI_FLAG_SATURATED | OI_FLAG_BACKGROUND_SATURATED)) || (ex.fill >= 0 && ex.fill <= 1));
}
#endif

#if defined(__ARM_FP)
/* FPSCR's cumulative exception flags: IOC (bit 0), DZC (1), OFC (2); UFC,
 * IXC and IDC (3, 4, 7) are the arithmetic's normal work. */
#define FPSCR_HARMFUL (0x7u)
#define FPSCR_FLAGS (0x9Fu)

static uint32_t fpscr_read(void)
{
    uint32_t v;
    __asm__ __volatile__("vmrs %0, fpscr" : "=r"(v));
    return v;
}

static void fpscr_clear_flags(void)
{
    const uint32_t v = fpscr_read() & ~FPSCR_FLAGS;
    __asm__ __volatile__("vmsr fpscr, %0" : : "r"(v));
}

/* A valid call raises no invalid-operation, division-by-zero or overflow
 * flag on the target either (tests/c/test_fp_exceptions.c on the host):
 * LEO, GEO and cislunar targets, lit, in the penumbra's middle and in the
 * umbra, the Sun on +x, observers 50 km away; the default model, the
 * limb-darkened disc and the WGS-84 Earth. */
static void test_fp_flags(void)
{
    static const double radius[3] = {RE + 500.0, 42164.0, 200000.0};
    oi_scene s;
    oi_illum il;
    oi_model m;
    size_t b;
    int o, l, k;
    for (k = 0; k < 3; k++) {
        for (o = 0; o < 3; o++) {
            for (l = 0; l < 3; l++) {
                const double r = radius[o];
                /* in the penumbra: rho = R + 0.9 r R / AU from the shadow's axis
                 * (between the umbra's edge R - x (R_sun - R) / d and the
                 * penumbra's R + x (R_sun + R) / d, x = sqrt(r^2 - rho^2)
                 * behind the Earth), or in the umbra at rho = 0.3 R */
                const double rho = l == 1 ? RE + 0.9 * r * RE / AU : 0.3 * RE;
                const double x = __builtin_sqrt(r * r - rho * rho);
                oi_shadow sh;
                uint32_t f;
                int st;
                oi_scene_defaults(&s);
                set3(s.sun_km, AU, 0, 0);
                set3(s.moon_km, -300000, 200000, 1000);
                if (l == 0)
                    set3(s.target_km, 0.5 * r, 0.866 * r, 0.01 * r);
                else
                    set3(s.target_km, -x, rho, 0.0);
                set3(s.observer_km, (double)s.target_km[0] + 30.0, (double)s.target_km[1] + 40.0,
                     (double)s.target_km[2]);
                s.has_observer = 1;
                s.terms = OI_TERM_ALL;
                for (b = 0; b < sizeof m; b++) ((unsigned char *)&m)[b] = 0;
                if (k == 1) m.limb_darkening = OI_LIMB_DARKENED;
                if (k == 2) m.earth_shape = OI_EARTH_WGS84;
                fpscr_clear_flags();
                st = oi_illuminate(&s, &m, &il);
                f = fpscr_read() & FPSCR_HARMFUL;
                check_true("fp flags: illuminate computes", st >= 0);
                check_int("fp flags: oi_illuminate raises none", 0, (long)f);
                fpscr_clear_flags();
                (void)oi_sun_fraction(s.sun_km, s.target_km, &m, &sh);
                check_int("fp flags: oi_sun_fraction raises none", 0, (long)(fpscr_read() & FPSCR_HARMFUL));
#ifndef OI_NO_EXPOSURE
                {
                    oi_exposure ex;
                    fpscr_clear_flags();
                    st = oi_expose_scene(oi_camera_builtin(0), &s, &il, &m, NULL, &ex);
                    check_true("fp flags: expose_scene computes", st >= 0);
                    check_int("fp flags: oi_expose_scene raises none", 0, (long)(fpscr_read() & FPSCR_HARMFUL));
                }
#endif
            }
        }
    }
}
#endif

/* thunks for the stack probe: the worst inputs we know (penumbra, all
 * terms, observer) */
static oi_scene probe_s;
static oi_illum probe_il;

static void setup_illuminate(void)
{
    oi_scene_defaults(&probe_s);
    set3(probe_s.sun_km, AU, 0, 0);
    set3(probe_s.moon_km, -300000, 200000, 1000);
    set3(probe_s.target_km, -2884.0, RE, 0);
    set3(probe_s.observer_km, -2884.0, RE + 50.0, 10);
    probe_s.has_observer = 1;
}

static void probe_illuminate(void)
{
    (void)oi_illuminate(&probe_s, NULL, &probe_il);
}

static void probe_sun_fraction(void)
{
    set3(probe_s.sun_km, AU, 0, 0);
    set3(probe_s.target_km, -2884.0, RE, 0);
    (void)oi_sun_fraction(probe_s.sun_km, probe_s.target_km, NULL, &probe_il.shadow);
}

static void probe_earthshine(void)
{
    (void)oi_earthshine(OI_R(1.6), OI_R(400.0), NULL, &probe_il.earth_phi, &probe_il.earth_psi);
}

#ifndef OI_NO_EXPOSURE
static oi_exposure probe_ex;

static void probe_expose_scene(void)
{
    (void)oi_expose_scene(oi_camera_builtin(0), &probe_s, &probe_il, NULL, NULL, &probe_ex);
}

static void setup_expose_scene(void)
{
    oi_scene s;
    oi_scene_defaults(&s);
    set3(s.sun_km, AU, 0, 0);
    set3(s.moon_km, -300000, 200000, 1000);
    set3(s.target_km, 0, 7000, 0);
    set3(s.observer_km, 0, 7000, 100);
    s.has_observer = 1;
    probe_s = s;
    (void)oi_illuminate(&probe_s, NULL, &probe_il);
}
#endif

static void report_stack(const char *name, void (*fn)(void))
{
    uint32_t used = stack_probe(fn);
    sh_puts("stack.measured.");
    sh_puts(name);
    sh_puts(" ");
    sh_putint((long)used);
    sh_puts(" bytes\n");
}

int main(void)
{
#ifdef OI_SINGLE_PRECISION
    sh_puts("orbillum self-test (single precision)\n");
#else
    sh_puts("orbillum self-test (double precision)\n");
#endif
    test_phase();
    test_overlap();
    test_sun_fraction();
    test_earthshine();
#ifndef OI_NO_MOON
    test_moon();
#endif
    test_magnitude();
    test_illuminate();
#ifndef OI_NO_EXPOSURE
    test_exposure();
#endif
    golden_phase();
    golden_moon();
    golden_shadow();
    golden_earthshine();
    golden_stability();
#if defined(__ARM_FP)
    test_fp_flags();
#endif
    report_stack("oi_sun_fraction", probe_sun_fraction);
    report_stack("oi_earthshine", probe_earthshine);
    setup_illuminate();
    report_stack("oi_illuminate", probe_illuminate);
#ifndef OI_NO_EXPOSURE
    setup_expose_scene();
    report_stack("oi_expose_scene", probe_expose_scene);
#endif
    sh_puts("passed ");
    sh_putint(n_pass);
    sh_puts(" failed ");
    sh_putint(n_fail);
    sh_puts(" known ");
    sh_putint(n_known);
    sh_puts("\n");
    return n_fail == 0 ? 0 : 1;
}
