/* SPDX-License-Identifier: MIT */
/*
 * oi_internal.h: helpers shared inside the runtime (not part of the API).
 * Small vector operations as static inline functions, and model resolution.
 */
#ifndef OI_INTERNAL_H
#define OI_INTERNAL_H

#include "oi_port.h"

/* GCC and clang: a helper kept out of its caller's frame, so that its locals
 * are not live during the caller's other calls (make stack); elsewhere the
 * compiler decides. */
#if defined(__GNUC__)
#define OI_NOINLINE __attribute__((noinline))
#else
#define OI_NOINLINE
#endif

/* GCC if-converts (and so vectorises) a loop's comparisons and selects only
 * when they may not trap: the attribute says so for one function whose
 * results do not depend on it. Its callers bracket its calls with
 * src/fp_quiet.h, so that the exceptions raised on the lanes a select
 * discards neither trap nor stay flagged; hence only where that bracket
 * has a floating-point status to work on (elsewhere the blocks keep
 * trapping math, and their source raises nothing on a discarded lane). */
#if defined(__GNUC__) && !defined(__clang__) &&                                                  \
    (defined(__SSE2__) || defined(__aarch64__) || (defined(__arm__) && defined(__ARM_FP)))
#define OI_VECTORISE_COMPARES __attribute__((optimize("no-trapping-math")))
#else
#define OI_VECTORISE_COMPARES
#endif

/* GCC and clang: a helper inlined into its caller whatever its size (a
 * block function's loop vectorises only with no call in it). */
#if defined(__GNUC__)
#define OI_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define OI_ALWAYS_INLINE inline
#endif

/* 1 where the processor has vectors of doubles (x86-64, AArch64): there a
 * block function evaluates many rows or nodes at once; elsewhere one at a
 * time, where the block's arrays would only cost stack (a Cortex-M4F's,
 * make stack). The bits do not depend on it. */
#if defined(__x86_64__) || defined(__aarch64__)
#define OI_DOUBLE_VECTORS 1
#else
#define OI_DOUBLE_VECTORS 0
#endif

/* A block function also compiled for AVX2 (4 doubles a vector instead of
 * SSE2's 2), chosen at load time where the processor has it (GCC's function
 * multi-versioning, an ifunc: x86-64 Linux with glibc, whose headers define
 * __GLIBC__); the default clone is the portable code. AVX2 alone does not
 * enable fma, and -std=c99 does not contract: every lane rounds as scalar
 * code does. -DOI_NO_TARGET_CLONES leaves it out. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    defined(__GLIBC__) && !defined(OI_NO_TARGET_CLONES)
#define OI_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define OI_AVX2_CLONES
#endif

static inline oi_real oi__dot(const oi_real a[3], const oi_real b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void oi__sub(const oi_real a[3], const oi_real b[3], oi_real out[3])
{
    out[0] = a[0] - b[0];
    out[1] = a[1] - b[1];
    out[2] = a[2] - b[2];
}

static inline void oi__cross(const oi_real a[3], const oi_real b[3], oi_real out[3])
{
    oi_real x = a[1] * b[2] - a[2] * b[1];
    oi_real y = a[2] * b[0] - a[0] * b[2];
    oi_real z = a[0] * b[1] - a[1] * b[0];
    out[0] = x;
    out[1] = y;
    out[2] = z;
}

/* Euclidean norm, scaled so that large or tiny components neither overflow
 * nor underflow. */
static inline oi_real oi__norm_inline(const oi_real a[3])
{
    oi_real m = OI_FABS(a[0]);
    oi_real t = OI_FABS(a[1]);
    oi_real x, y, z;
    if (t > m) m = t;
    t = OI_FABS(a[2]);
    if (t > m) m = t;
    if (m == (oi_real)0 || !OI_ISFINITE(m)) return m;
    x = a[0] / m;
    y = a[1] / m;
    z = a[2] / m;
    return m * OI_SQRT(x * x + y * y + z * z);
}

/* The same, one out-of-line copy (src/vector.c). */
oi_real oi__norm_outline(const oi_real a[3]);

/* oi__norm (and oi__unit, which calls it) and oi__finite3 are inlined, except
 * in a file that defines OI_VECTOR_OUT_OF_LINE before including this header:
 * there they call the single copies in src/vector.c. The files of the
 * Sun-only build (src/sun_fraction.c, src/phase.c) do, to bring it towards
 * 4 KiB of flash on every Cortex-M configuration (about -200 B at -Os and
 * -450 to -520 B at -O2); the other hot paths keep the inline copies (out of
 * line everywhere cost +3% instructions in make bench's all_expose, in
 * these two files +1.8%). Same values either way. */
static inline oi_real oi__norm(const oi_real a[3])
{
#ifdef OI_VECTOR_OUT_OF_LINE
    return oi__norm_outline(a);
#else
    return oi__norm_inline(a);
#endif
}

/* out = a / n (out zeroed when n is 0); returns n. out may be a. */
static inline oi_real oi__divide3(const oi_real a[3], oi_real n, oi_real out[3])
{
    if (n > (oi_real)0) {
        out[0] = a[0] / n;
        out[1] = a[1] / n;
        out[2] = a[2] / n;
    } else {
        out[0] = out[1] = out[2] = (oi_real)0;
    }
    return n;
}

/* out = a / |a|; returns |a| (out zeroed when |a| is 0). out may be a. */
static inline oi_real oi__unit(const oi_real a[3], oi_real out[3])
{
    return oi__divide3(a, oi__norm(a), out);
}

/* Norm, unit vector and angle for vectors whose components are known to be
 * finite and at most ~1e18 in magnitude (positions validated against
 * OI_POSITION_MAX_KM, unit vectors): the plain sum of squares cannot
 * overflow in either precision, so the scaling of oi__norm is skipped. A
 * vector shorter than ~1e-150 (double) or ~1e-18 (float) may come out as
 * zero: callers use them only where such lengths are excluded. */
static inline oi_real oi__norm_bounded(const oi_real a[3])
{
    return OI_SQRT(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

static inline oi_real oi__unit_bounded(const oi_real a[3], oi_real out[3])
{
    return oi__divide3(a, oi__norm_bounded(a), out);
}

/* The unit vector from a scene's target to its observer; returns the range
 * (km). One definition: the observer's terms and the facets' use the same
 * bits. */
static inline oi_real oi__observer_direction(const oi_scene *scene, oi_real obs_hat[3])
{
    oi__sub(scene->observer_km, scene->target_km, obs_hat);
    return oi__unit(obs_hat, obs_hat);
}

/* Angle between two unit vectors, atan2(|a x b|, a . b) (see oi_angle). */
static inline oi_real oi__angle_unit(const oi_real ua[3], const oi_real ub[3])
{
    oi_real c[3];
    oi__cross(ua, ub, c);
    return OI_ATAN2(oi__norm_bounded(c), oi__dot(ua, ub));
}

static inline int oi__finite3_inline(const oi_real a[3])
{
    return OI_ISFINITE(a[0]) && OI_ISFINITE(a[1]) && OI_ISFINITE(a[2]);
}

/* The same, one out-of-line copy (src/vector.c); oi__finite3 picks one as
 * oi__norm does (OI_VECTOR_OUT_OF_LINE). */
int oi__finite3_outline(const oi_real a[3]);

static inline int oi__finite3(const oi_real a[3])
{
#ifdef OI_VECTOR_OUT_OF_LINE
    return oi__finite3_outline(a);
#else
    return oi__finite3_inline(a);
#endif
}

/*
 * Error-free transformations (Knuth TAOCP 2, 4.2.2; Dekker 1971), shared by
 * src/sun_fraction.c, src/atan2.c and src/sincos.c. They need round-to-nearest in
 * the working precision (no x87 extended registers). oi__split's product
 * goes through a volatile so that a compiler contracting floating-point
 * expressions (-ffp-contract=fast, the GNU C default on FMA targets) cannot
 * fuse t - a = fl(S a) - a into an exact fma, which would break the split.
 */
#ifdef OI_SINGLE_PRECISION
#define OI_SPLITTER OI_R(4097.0) /* 2^12 + 1 */
#else
#define OI_SPLITTER OI_R(134217729.0) /* 2^27 + 1 */
#endif

/* s + *e = a + b exactly (TwoSum; no condition on the operands); returns s. */
static inline oi_real oi__two_sum(oi_real a, oi_real b, oi_real *e)
{
    const oi_real s = a + b;
    const oi_real bb = s - a;
    *e = (a - (s - bb)) + (b - bb);
    return s;
}

/* a = *hi + *lo exactly, each with half the significand (Veltkamp's split),
 * so that products of halves are exact; |a| below OI_SPLITTER's overflow. */
static inline void oi__split(oi_real a, oi_real *hi, oi_real *lo)
{
    volatile oi_real tv = OI_SPLITTER * a;
    const oi_real t = tv;
    *hi = t - (t - a);
    *lo = a - *hi;
}

/* ---- scalar helpers shared by the model files */

/* pi in two parts: OI_PI_HI is pi rounded to oi_real, OI_PI_LO = pi - OI_PI_HI
 * rounded. (OI_PI_HI - x) is exact for x in [OI_PI_HI/2, 2 OI_PI_HI]
 * (Sterbenz), and adding OI_PI_LO gives pi - x to one rounding. */
#ifdef OI_SINGLE_PRECISION
#define OI_PI_HI (3.14159274f)          /* float(pi) = 13176795 * 2^-22 */
#define OI_PI_LO (-8.74227800e-08f)     /* pi - float(pi) */
#else
#define OI_PI_HI (3.141592653589793116)  /* double(pi) = 884279719003555 * 2^-48 */
#define OI_PI_LO (1.2246467991473532e-16) /* pi - double(pi) */
#endif
#define OI_HALF_PI_R (OI_PI_R * OI_R(0.5))

/* pi - x to one rounding for x near pi (OI_PI_HI, OI_PI_LO). */
static inline oi_real oi__pi_minus(oi_real x)
{
    return (OI_PI_HI - x) + OI_PI_LO;
}

static inline oi_real oi__sqr(oi_real x)
{
    return x * x;
}

/* x limited to [lo, hi]; NaN gives lo. */
static inline oi_real oi__clamp(oi_real x, oi_real lo, oi_real hi)
{
    if (!(x > lo)) return lo; /* also maps NaN to lo */
    return x < hi ? x : hi;
}

/* lo < x <= hi (false for NaN). */
static inline int oi__in_open_closed(oi_real x, oi_real lo, oi_real hi)
{
    return x > lo && x <= hi;
}

/* lo <= x <= hi (false for NaN). */
static inline int oi__in_closed(oi_real x, oi_real lo, oi_real hi)
{
    return x >= lo && x <= hi;
}

/* ---- spherical triangles and caps (src/spherical_triangle.c,
 * src/cap_segment.c, src/limb_darkening.c) */

/* sin^2(r/2): the cap area over 4 pi, without the cancellation of 1 - cos r. */
static inline oi_real oi__sin_half_sq(oi_real r)
{
    return oi__sqr(OI_SIN(OI_R(0.5) * r));
}

/* y + z - x for non-negative x, y, z, accurate when y + z is close to x:
 * the larger of y, z minus x is exact there (Sterbenz), then one rounding. */
static inline oi_real oi__side_excess(oi_real x, oi_real y, oi_real z)
{
    oi_real big = y > z ? y : z;
    oi_real small = y > z ? z : y;
    return (big - x) + small;
}

/* sin of an angle known to lie in [0, pi], accurate near pi too. */
static inline oi_real oi__sin_0_pi(oi_real x)
{
    return x <= OI_HALF_PI_R ? OI_SIN(x) : OI_SIN(oi__pi_minus(x));
}

/*
 * The sines of the spherical triangle with sides a, b, c (radians, triangle
 * inequalities assumed; rounding beyond them is clamped) used by the
 * half-angle formulas, s = (a + b + c)/2: hs[0] = sin s, hs[1] = sin(s - a),
 * hs[2] = sin(s - b), hs[3] = sin(s - c) (src/spherical_triangle.c).
 */
void oi__half_sines(oi_real a, oi_real b, oi_real c, oi_real hs[4]);

/* The angle opposite the side of index i (1: a, 2: b, 3: c) of the triangle
 * of oi__half_sines, or with comp != 0 pi minus it, without cancellation
 * (src/spherical_triangle.c). */
oi_real oi__half_angle(const oi_real hs[4], int i, int comp);

/* Area of the segment of a cap of radius r (<= pi/2) cut off by the great
 * circle through the two points of its boundary seen from the cap's centre
 * at +-alpha; negative for alpha > pi/2 (src/cap_segment.c). */
oi_real oi__cap_segment(oi_real r, oi_real alpha);

/* The 8-point Gauss-Legendre rule on [0, 1] (mpmath at 40 digits by Newton
 * iteration on P_8; tools/coeffs/quadrature.py prints them): the nodes
 * x < 1/2 and their weights, the nodes 1 - x sharing them. The constants
 * for the crescent kernel's unrolled rule (src/sun_crescent.h), and the
 * table oi__gl8 of the same values, rows (x, w), for the loops
 * (src/cap_segment.c, which defines it; src/oblate.c,
 * src/limb_darkened_union.c). */
#define OI_GL8_HALF 4
#define OI_GL8_X1 OI_R(0.0198550717512318841582)
#define OI_GL8_X2 OI_R(0.101666761293186630204)
#define OI_GL8_X3 OI_R(0.237233795041835507091)
#define OI_GL8_X4 OI_R(0.40828267875217509753)
#define OI_GL8_W1 OI_R(0.0506142681451881295763)
#define OI_GL8_W2 OI_R(0.111190517226687235272)
#define OI_GL8_W3 OI_R(0.156853322938943643669)
#define OI_GL8_W4 OI_R(0.181341891689180991483)
extern const oi_real oi__gl8[OI_GL8_HALF][2];

/* The region (OI_SHADOW_*) and the visible fractions, uniform *frac and
 * (frac_ld not NULL) limb-darkened *frac_ld, of the solar disc of apparent
 * radius rs behind a nearer disc of radius re, centres sep apart (radians):
 * the Sun behind the Earth or the Moon; with frac_ld NULL any disc behind
 * another (src/sun_fraction.c). */
int oi__disc_fractions(oi_real rs, oi_real re, oi_real sep, oi_real *frac, oi_real *frac_ld);

#ifndef OI_NO_MOON
/* Area (sr) of the intersection of the three caps of unit centres c[i] and
 * radii r[i] (radians, (0, pi)) (src/cap_triple.c). */
oi_real oi__cap_triple(const oi_real c[3][3], const oi_real r[3]);

/* The Moon's shadow on a point: sh, oi__sun_shadow's result there, gets the
 * fractions with the Moon as a second occulter; *hidden the fraction of the
 * Sun's disc area the Moon covers. OI_OK, or OI_ERR_GEOMETRY for a point in
 * the Moon (src/moon_occultation.c). */
int oi__moon_shadow(const oi_real sun_km[3], const oi_real moon_km[3],
                    const oi_real point_km[3], const oi_model *m, oi_shadow *sh,
                    oi_real *hidden);

/* The top of the air that dims the Moon's light near the Earth's limb (km
 * above the Earth's radius; src/atmosphere_moonlight.c): beyond the
 * apparent radius of that sphere oi__moon_disc_visible is the solid Earth's
 * fraction. */
#define OI_MOON_AIR_TOP_KM OI_R(100.0)

/* Fraction of the Moon's disc seen from the point that the Earth does not
 * hide; u_moon the unit vector to the Moon, dm its distance
 * (src/moon_occultation.c). */
oi_real oi__moon_disc_visible(const oi_real point_km[3], const oi_real u_moon[3], oi_real dm,
                              const oi_model *m);

#ifndef OI_NO_ATMOSPHERE
/* The fraction of the Moon's disc light (apparent radius rm, sep from the
 * Earth's centre of apparent radius re, seen from dp km) through the
 * atmosphere near the limb, in [0, solid] (solid: the solid Earth's
 * visible fraction); src/atmosphere_moonlight.c. */
oi_real oi__atm_moon_visible(oi_real dp, oi_real re, oi_real rm, oi_real sep, oi_real solid,
                             oi_real r_e);
#endif
#endif

#ifndef OI_NO_LIMB_DARKENING
/* Limb darkening is computed for OI_LD_RS_MIN < r_s <= OI_LD_RS_MAX
 * (docs/shadow.md); elsewhere the uniform disc stands in. */
#define OI_LD_RS_MAX OI_R(0.5)
#define OI_LD_RS_MIN OI_R(1e-15)

/* Visible fraction of the limb-darkened solar disc of radius rs with the
 * Earth's disc of radius re at sep: penumbra with tri the sines of
 * oi__half_sines(rs, re, sep) and pa_s = pi - (the angle at the Sun's
 * centre), or annular with tri = NULL (src/limb_darkening.c). */
oi_real oi__fraction_limb_darkened(oi_real rs, oi_real re, oi_real sep, oi_real pa_s,
                                   const oi_real *tri);

#ifndef OI_NO_MOON
/* Visible fraction of the limb-darkened solar disc (radius rs) behind two
 * discs at once (radii re, rm, centres de, dm from the Sun's, dem apart)
 * (src/limb_darkened_union.c). */
oi_real oi__fraction_ld_two(oi_real rs, oi_real re, oi_real de, oi_real rm, oi_real dm,
                            oi_real dem);
#endif
#endif

#ifndef OI_NO_OBLATE
/* The WGS-84 ellipsoid of equatorial radius a, the frame's z axis its
 * rotation axis (oi_model.earth_shape = OI_EARTH_WGS84; src/oblate.c):
 * 1 when p is outside it; its geocentric radius in the direction of p; the
 * angular radius of its silhouette seen from p along the great circle from
 * the nadir towards the unit direction s; the visible fraction of the
 * uniform disc of unit direction s and apparent radius r seen from p behind
 * it and (mo not NULL) a sphere of unit direction mo and apparent radius rm;
 * frac_ld not NULL: the limb-darkened disc's fraction there (the uniform's
 * with OI_NO_LIMB_DARKENING). */
int oi__oblate_outside(const oi_real p[3], oi_real a);
oi_real oi__oblate_geocentric_radius(const oi_real p[3], oi_real a);
oi_real oi__oblate_radius_towards(const oi_real p[3], oi_real a, const oi_real s[3]);
oi_real oi__oblate_visible(const oi_real s[3], oi_real r, const oi_real p[3], oi_real a,
                           const oi_real mo[3], oi_real rm, oi_real *frac_ld);
/* oi__oblate_visible behind the ellipsoid alone (mo NULL), on less stack. */
oi_real oi__oblate_visible_earth(const oi_real s[3], oi_real r, const oi_real p[3], oi_real a,
                                 oi_real *frac_ld);
/* Distance from o (outside) along the unit direction u to the ellipsoid,
 * or -1 when the ray misses it. */
oi_real oi__oblate_ray_hit(const oi_real o[3], const oi_real u[3], oi_real a);
#endif

static inline void oi__zero3(oi_real a[3])
{
    a[0] = a[1] = a[2] = (oi_real)0;
}

/*
 * Copy a model with every zero field replaced by its default; NULL means all
 * defaults. Returns OI_OK, OI_ERR_MODEL (non-finite or negative constant,
 * unknown option value, moon_albedo outside [0, 1]) or OI_ERR_RADIUS (a
 * negative radius). On error *out is the default model.
 */
int oi__model_resolve(const oi_model *in, oi_model *out);

/*
 * oi_sun_fraction (src/sun_fraction.c) for callers that already hold a resolved
 * model (oi__model_resolve) and non-NULL pointers: the model is not
 * validated again. When light_dir is not NULL and the atmosphere is compiled
 * in and enabled, it also returns the unit vector from the point towards
 * where the sunlight comes from on average (refracted light in the shadow;
 * the Sun's direction elsewhere). light_dir is left untouched wherever the
 * light comes straight from the Sun, and when the atmosphere is compiled out
 * or disabled, so the caller sets it to the Sun's direction first.
 */
int oi__sun_shadow(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *resolved,
                   oi_shadow *out, oi_real light_dir[3]);

/* oi__sun_shadow with a choice of outputs (the batch, src/batch.c):
 * OI__WANT_LD forms fraction_ld (else it equals fraction unless the
 * atmosphere or the limb-darkened model needs it), OI__WANT_ATM fraction_atm
 * and its status (else 0, the atmosphere not consulted). Every output formed
 * is the bits of oi__sun_shadow's. */
#define OI__WANT_LD (1u)
#define OI__WANT_ATM (2u)
int oi__sun_shadow_want(const oi_real sun_km[3], const oi_real point_km[3],
                        const oi_model *resolved, unsigned want, oi_shadow *out,
                        oi_real light_dir[3]);

/* The albedo model of a caller's model (albedo_model, albedo_map and its
 * dimensions), checked and copied into the resolved one (oi__model_resolve
 * leaves the uniform default): OI_OK, or OI_ERR_MODEL for an unknown model,
 * a map without its array or with a dimension outside 1..OI_ALBEDO_MAP_MAX_DIM,
 * or any model but the uniform one with OI_NO_ALBEDO_MODELS
 * (src/illuminate.c; called by oi_illuminate and its batch, the functions
 * that read it). */
int oi__albedo_resolve(const oi_model *in, oi_model *out);

/* oi_illuminate (src/illuminate.c) with a resolved model and non-NULL
 * scene and out: the model is not validated again. */
int oi__illuminate_resolved(const oi_scene *scene, const oi_model *m, oi_illum *out);

/* oi__illuminate_resolved with the outputs mask of
 * oi_illuminate_batch_outputs (OI_BATCH_* bits, checked by the caller):
 * src/illuminate_outputs.c. */
int oi__illuminate_outputs(const oi_scene *scene, const oi_model *m, unsigned outputs,
                           oi_illum *out);

/* The batch calls' array checks (src/batch_arrays.c). OI_ALIGN_OF: the
 * alignment of a type in C99 (no _Alignof), the offset of a member after a
 * char. oi__span: a caller's array as its address range [lo, hi), lo == hi
 * when absent (NULL). oi__span_of: the span of n elements of size bytes at
 * p, 0 when p is not aligned to align or the size overflows the address
 * space. oi__check_overlap: OI_OK when no output span overlaps an input
 * span or another output span, else OI_ERR_INPUT. oi__batch_fail: a batch
 * error st, every status set to it (when status can be written) and, when
 * zero_out, every output row (size bytes each) zeroed; returns st. */
#define OI_ALIGN_OF(type) offsetof(struct { char c; type t; }, t)
typedef struct {
    uintptr_t lo, hi;
} oi__span;
int oi__span_of(const void *p, long n, size_t size, size_t align, oi__span *s);
int oi__check_overlap(const oi__span *in, int n_in, const oi__span *out, int n_out);
int oi__batch_fail(int st, long n, int *status, void *out, size_t size, int zero_out);

/* The batch's certain regions of the Sun seen from a point (src/batch.c):
 * OI__ROW_LIT or OI__ROW_UMBRA (asked only with umbra_too) when the point is
 * certainly there, decided from cosines after every check of
 * oi__sun_shadow's geometry passed (its status would be OI_OK, its
 * fractions 1 or 0, the light's direction the Sun's); OI__ROW_UNSURE
 * otherwise. */
#define OI__ROW_UNSURE (0)
#define OI__ROW_LIT (1)
#define OI__ROW_UMBRA (2)
int oi__sun_certain_region(const oi_real sun[3], const oi_real p[3], const oi_model *m,
                           int umbra_too);

/* 1 when oi__moon_shadow would return OI_OK and leave the shadow as it is
 * (the Moon beyond the Sun, or the two discs certainly apart), so that the
 * shadow's angles it reads need not be formed (src/moon_occultation.c). */
int oi__moon_shadow_none(const oi_real sun_km[3], const oi_real moon_km[3],
                         const oi_real point_km[3], const oi_model *m);

/*
 * oi_earthshine (src/earthshine.c) for callers that already hold a resolved
 * model and non-NULL phi, psi: same results and statuses, the model is not
 * validated again. cos_theta, sin_theta: the cosine and sine theta was formed
 * from (theta = atan2(sin, cos) of unit vectors), used instead of OI_COS and
 * OI_SIN where needed; cos_theta > 1 means not given.
 */
int oi__earthshine(oi_real theta, oi_real cos_theta, oi_real sin_theta, oi_real h_km,
                   const oi_model *resolved, oi_real *phi, oi_real *psi);

/* oi_lambert_phase (src/phase.c) for a caller that holds cos(xi) and
 * sin(xi) of the same angle (e.g. the dot and cross products of two unit
 * vectors, xi = atan2(sin, cos)): used where the closed form needs them
 * (pi - xi >= 1), so no cosine or sine is evaluated. cos_xi > 1: not given. */
oi_real oi__lambert_phase_cs(oi_real xi, oi_real cos_xi, oi_real sin_xi);

#ifndef OI_NO_SKYLIGHT
/* The scattered-sunlight table (src/skylight.c): 1 when a caller's table
 * passes the checks of oi_sky_table_default's contract; the table a resolved
 * model uses (*t NULL: none; OI_ERR_MODEL for an invalid caller's table);
 * the lookup at theta in [0, pi] and distance r_km (OI_WARN_TABLE_RANGE
 * below the first row). */
int oi__sky_table_valid(const oi_sky_table *t);
int oi__sky_table_of(const oi_model *m, const oi_sky_table **t);
int oi__sky_lookup(const oi_sky_table *t, oi_real theta, oi_real r_km, oi_real *e_over_sun,
                   oi_real *psi);
#endif

/* The earthshine angular table of a resolved model whose sphere reflects
 * earthshine from its angular distribution (src/earthshine_angular.c;
 * non-NULL for the cubature and the table's moments): NULL for the mean direction
 * (earth_reflection = OI_EARTH_REFLECT_MEAN, the Lambert far field, or the
 * table compiled out). */
const oi_earth_angular_table *oi__earth_angular_of(const oi_model *m);

#if !defined(OI_NO_EARTH_ANGULAR) && !defined(OI_NO_EARTH_TABLE)
/* S(o) = F / phi, the shape of a Lambertian sphere's flux under earthshine
 * towards the unit direction o of the local frame (z zenith, x towards the
 * Sun's side), under the resolved model m (the cubature, or the table's
 * moments with OI_EARTH_REFLECT_TABLE) at theta (with its cosine and sine;
 * theta is OI_ATAN2(sin_theta, cos_theta), bit for bit: the cubature's
 * break at the terminator takes it) and h_km above an Earth of radius R,
 * phi the caller's scalar irradiance
 * (the cubature's flux is F = phi S): returns 1 with *shape >= 0, or 0
 * (shape 0) below the table's first row (src/earthshine_angular.c). */
int oi__earth_sphere_shape(const oi_model *m, oi_real theta, oi_real cos_theta,
                           oi_real sin_theta, oi_real h_km, oi_real R, const oi_real o[3],
                           oi_real phi, oi_real *shape);
#endif

/* Break points of the cap cubatures' polar angle (src/cap_breaks.c): bp
 * sorted, at most cap entries; start: 0, the horizon *a_max and the
 * terminator's tangency; altitude: up to n_geo multiples of it. at: start
 * given theta = OI_ATAN2(sin_theta, cos_theta), the same bits. */
int oi__cap_break_add(oi_real *bp, int cap, int n, oi_real x, oi_real a_max);
int oi__cap_breaks_start(oi_real *bp, int cap, oi_real hp, oi_real rp, oi_real cos_theta,
                         oi_real sin_theta, oi_real *a_max);
int oi__cap_breaks_at(oi_real *bp, int cap, oi_real hp, oi_real rp, oi_real theta,
                      oi_real *a_max);
int oi__cap_breaks_altitude(oi_real *bp, int cap, int n, int n_geo, oi_real hp, oi_real rp,
                            oi_real a_max);

/* The local frame of the Earth's light at the target (src/local_frame.c). */
void oi__local_frame_toward(const oi_real target_km[3], const oi_real sun_km[3],
                            const oi_real *hint, oi_real r_hat[3], oi_real s_hat[3],
                            oi_real x[3], oi_real y[3]);
void oi__local_frame(const oi_real target_km[3], const oi_real sun_km[3], oi_real r_hat[3],
                     oi_real s_hat[3], oi_real x[3], oi_real y[3]);

#ifndef OI_NO_FACETS
/* 1 when a resolved model has the facets' earthshine from the cubature
 * (earth_reflection OI_EARTH_REFLECT_MOMENTS or OI_EARTH_REFLECT_TABLE,
 * which a facet cannot use, with earth_model OI_EARTH_TABLE), 0 for the
 * mean direction. */
static inline int oi__plate_cubature(const oi_model *m)
{
    return m->earth_reflection != OI_EARTH_REFLECT_MEAN && m->earth_model == OI_EARTH_TABLE;
}
/* Earthshine irradiance on a face of unit normal nrm in the local frame, per
 * unit Earth albedo and solar irradiance (src/facet_earth.c). */
oi_real oi__plate_earth(oi_real cos_theta, oi_real sin_theta, oi_real h_km, oi_real R,
                        const oi_real nrm[3]);
/* The specular earthshine radiance a face of unit normal nrm sends towards
 * the unit direction obs (both local frame) per unit albedo_specular, Earth
 * albedo and solar irradiance: the integral over the visible sunlit Earth
 * of L(omega) (N.omega) f(omega -> obs), f the Phong lobe of oi__phong_lobe
 * (src/facet_earth.c): the cap cubature's rings for shininess below
 * OI_LOBE_RULE_SHININESS, nodes about the lobe's axis from it up. */
#ifndef OI_LOBE_RULE_SHININESS
#define OI_LOBE_RULE_SHININESS 64
#endif
oi_real oi__plate_earth_specular(oi_real cos_theta, oi_real sin_theta, oi_real h_km, oi_real R,
                                 const oi_real nrm[3], const oi_real obs[3], oi_real shininess);
/* The attitude quaternion's check and rotation (src/quaternion.c). */
int oi__quat_unit(const oi_real q[4], oi_real out[4]);
void oi__quat_rotate(const oi_real q[4], const oi_real v[3], oi_real out[3]);
/* The specular lobe per unit albedo (src/brdf.c). */
oi_real oi__phong_lobe(const oi_real nrm[3], oi_real cos_in, const oi_real u_in[3],
                       const oi_real u_out[3], oi_real shininess);
/* A scene's shape: its check and its fluxes (src/facet.c). */
int oi__shape_scene_check(const oi_scene *s);
void oi__shape_flux(const oi_scene *s, const oi_model *m, oi_illum *out);
oi_real oi__shape_peak(const oi_scene *s);
#endif

#ifndef OI_NO_ALBEDO_MODELS
/* The Earth's albedo field of a resolved model and a scene, ready to be
 * sampled (src/albedo_field.c): the Knocke model's degree-1 coefficient at
 * the scene's epoch, or the map and the Greenwich meridian's cosine and
 * sine. */
typedef struct oi__albedo_field {
    int model;           /* OI_ALBEDO_KNOCKE or OI_ALBEDO_MAP */
    oi_real a1;          /* Knocke: a1(t) */
    const float *map;    /* map: the caller's grid */
    int n_lat, n_lon;
    oi_real cos_rot, sin_rot; /* map: Greenwich meridian from the frame's x axis */
} oi__albedo_field;

/* Prepare f for the non-uniform model of m and scene s (its epoch_jd and
 * earth_rotation_rad already checked by oi_illuminate). */
void oi__albedo_field_init(const oi_model *m, const oi_scene *s, oi__albedo_field *f);

/* The albedo at the unit surface point p (the scene's frame, z the rotation
 * axis), in [0, 1]: OI_OK, or OI_ERR_ALBEDO for a map value read that is NaN
 * or outside [0, 1] (*a then 0). */
int oi__albedo_at(const oi__albedo_field *f, const oi_real p[3], oi_real *a);

/* Sums over the lit visible cap: weights K (the uniform sphere's
 * earthshine), K da (da the albedo less the reference), the same times the
 * direction omega (target to surface) and times the sphere's phase towards
 * the observer; varies: some da was not 0. */
typedef struct oi__albedo_sums {
    oi_real s0, s1, q, p;
    oi_real w[3], v[3];
    int varies;
} oi__albedo_sums;

/* One earthshine evaluation under a non-uniform albedo field: the field,
 * the target's unit position r_hat and x = R / r, the Sun's unit direction
 * s_hat, the unit direction to the observer (has_obs 0: none), the
 * reference albedo and the sums. Held in one frame by the caller, so that
 * the integrators' frames are not stacked under copies of them. */
typedef struct oi__albedo_job {
    oi__albedo_field f;
    oi_real r_hat[3], s_hat[3], obs_hat[3];
    oi_real x, a_ref;
    int has_obs;
    oi__albedo_sums acc;
} oi__albedo_job;

/* Earthshine under a non-uniform albedo field (src/earthshine_albedo.c), in
 * two steps so that the caller's frame, which holds the job, is the only one
 * above the integrators. oi__albedo_integrate: job->a_ref (the albedo under
 * the target) and the sums job->acc over the lit visible cap, for job's f,
 * r_hat, s_hat, obs_hat (has_obs) and x; OI_OK or OI_ERR_ALBEDO.
 * oi__albedo_mean, after it: *albedo the earthshine-weighted mean albedo
 * over the lit visible cap; dir: given the uniform sphere's mean incidence
 * direction, returned with the field's change; *shape_add: the change of the
 * sphere's shape S(o) = F / phi per unit mean albedo (0 without observer). */
int oi__albedo_integrate(oi__albedo_job *job);
void oi__albedo_mean(const oi__albedo_job *job, oi_real *albedo, oi_real dir[3],
                     oi_real *shape_add);

/* The sums under a map model, patch by patch of its bilinear field
 * (src/earthshine_albedo_map.c), added to job->acc (w and v in the scene's
 * frame) with da from job->a_ref; job's r_hat, s_hat and obs_hat are left
 * in the Earth-fixed frame. OI_OK or OI_ERR_ALBEDO. */
int oi__earthshine_map_cells(oi__albedo_job *job);
#endif

/* oi_magnitude_v (src/magnitude.c) with the model's TSI already resolved. */
oi_real oi__magnitude_v(oi_real flux_w_m2, oi_real tsi_w_m2);

#ifndef OI_NO_EXPOSURE
/* Nonzero when every field of the camera is in range (src/camera.c). */
int oi__camera_valid(const oi_camera *c);

/* oi_expose's choice for a camera that passed oi__camera_valid, out zeroed
 * (src/expose.c); same statuses as oi_expose after its camera check. */
int oi__expose_valid(const oi_camera *camera, const oi_expose_in *in,
                     const oi_expose_goal *goal, oi_exposure *out);

/* The part of oi_expose's choice that depends on the camera and the goal
 * only, formed once per batch (src/expose.c): the goal's defaults and status
 * (a row's statuses come after it), the detection rule, the dark current at
 * the goal's temperature and its status (after a row's own checks). */
typedef struct {
    oi_real goal_fill, snr_min; /* the goal, defaults filled in */
    oi_real det_k, det_z;       /* the detection rule (src/expose.c detect_rule) */
    oi_real dark;               /* dark current (e-/s) at the goal's temperature */
    int goal_st, dark_st;       /* their statuses */
} oi__expose_plan;

/* What oi__expose_planned computes (bits): the search of the setting (with
 * the detection margin and OI_FLAG_SATURATED) and OI_FLAG_TOO_FAINT. */
#define OI__EXPOSE_SEARCH (1u)
#define OI__EXPOSE_FAINT  (2u)

/* What an outputs mask (OI_EXPOSE_*) needs of the choice: OI__EXPOSE_* bits. */
static inline unsigned oi__expose_need(unsigned outputs)
{
    return ((outputs & (OI_EXPOSE_SETTING | OI_EXPOSE_DETECT)) != 0u ? OI__EXPOSE_SEARCH : 0u) |
           ((outputs & OI_EXPOSE_FAINT) != 0u ? OI__EXPOSE_FAINT : 0u);
}

void oi__expose_plan_make(const oi_camera *camera, const oi_expose_goal *goal,
                          oi__expose_plan *p);
/* oi__expose_valid with the plan made (p NULL: from goal, as the single
 * call); out zeroed, need: OI__EXPOSE_* bits (the fields need leaves out
 * stay 0 or partial: the batch clears them). */
int oi__expose_planned(const oi_camera *camera, const oi__expose_plan *p,
                       const oi_expose_goal *goal, const oi_expose_in *in, unsigned need,
                       oi_exposure *out);

/* The set-up of oi_expose_scene_batch_outputs (src/expose_scene.c): the
 * model's constants, the plan, cos(sun_exclusion_rad), the outputs mask. */
typedef struct {
    oi__expose_plan plan;
    oi_real re, au, tsi, rm, moon_albedo; /* the model's (oi_model's units) */
    oi_real cos_excl;                     /* cos(camera->sun_exclusion_rad) */
    int shape;                            /* oi_model.earth_shape */
    unsigned outputs;                     /* OI_EXPOSE_* */
} oi__expose_scene_batch;

/* The set-up: the model's status, then the camera's (src/expose_scene.c). */
int oi__expose_scene_setup(const oi_camera *camera, const oi_model *model,
                           const oi_expose_goal *goal, unsigned outputs,
                           oi__expose_scene_batch *b);
/* One row of oi_expose_scene (b NULL: the single call, every output and
 * every check; else the batch's set-up), out zeroed. */
int oi__expose_scene_row(const oi_camera *camera, const oi_scene *scene, const oi_illum *illum,
                         const oi_model *model, const oi_expose_goal *goal,
                         const oi__expose_scene_batch *b, oi_exposure *out);

/* The Gaussian PSF's sigma (pixels) for a central-pixel fraction p in (0, 1]
 * and the trailed peak's factor for a trail of L pixels (src/trail.c). */
oi_real oi__psf_sigma_px(oi_real p);
oi_real oi__trail_factor(oi_real sigma, oi_real q, oi_real trail);

/* The standard normal quantile of an upper tail in (0, 0.5], and the
 * smallest signal a detection rule accepts (src/detect.c). */
oi_real oi__normal_quantile_upper(oi_real tail);
oi_real oi__signal_min_e(oi_real thr, oi_real z, oi_real c);
#endif

#ifndef OI_NO_ATMOSPHERE
/*
 * Fraction of unobstructed sunlight reaching point_km with the atmosphere's
 * refraction and extinction (src/atmosphere.c, baked table), given the
 * geometric fractions frac (uniform disc) and frac_ld (limb-darkened) of the
 * same geometry and a resolved model. dir (may be NULL, in/out): on entry the
 * unit vector from the point to the Sun; replaced by the unit vector towards
 * where the light comes from only where refracted light arrives (inside the
 * table's window with a nonzero fraction), untouched elsewhere. Returns OI_OK
 * or OI_WARN_TABLE_RANGE (geometric fraction returned).
 */
int oi__atm_fraction(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *m,
                     oi_real frac, oi_real frac_ld, oi_real *fraction_atm, oi_real dir[3]);
/* The same with the table's coordinates about a sphere of radius
 * earth_radius_km instead of m->earth_radius_km (the ellipsoid's). */
int oi__atm_fraction_about(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *m,
                           oi_real earth_radius_km, oi_real frac, oi_real frac_ld,
                           oi_real *fraction_atm, oi_real dir[3]);
#endif

#endif /* OI_INTERNAL_H */
