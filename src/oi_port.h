/* SPDX-License-Identifier: MIT */
/*
 * oi_port.h: the only place the runtime includes system headers. Math calls
 * go through OI_* hooks so a flight project can supply its own libm: define
 * any of them before this header (e.g. -DOI_SQRT=my_sqrt).
 */
#ifndef OI_PORT_H
#define OI_PORT_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "orbillum.h"

#ifdef OI_SINGLE_PRECISION
#define OI_FN(fn) fn##f
#else
#define OI_FN(fn) fn
#endif

#ifndef OI_SQRT
#define OI_SQRT OI_FN(sqrt)
#endif
#ifndef OI_SIN
/* the runtime's own (src/math/sincos.c): a small fixed frame (no huge-argument
 * reduction), the same bits on every target; -DOI_SIN=sin (sinf) and
 * -DOI_COS=cos (cosf) select the libm's */
#define OI_SIN oi__sin
#define OI__OWN_SIN 1
#endif
#ifndef OI_COS
#define OI_COS oi__cos
#define OI__OWN_COS 1
#endif
oi_real oi__sin(oi_real x);
oi_real oi__cos(oi_real x);
void oi__sincos(oi_real x, oi_real *s, oi_real *c);
/* OI_SINCOS(x, s, c): *s = OI_SIN(x), *c = OI_COS(x), with one argument
 * reduction when both are the runtime's own (bit-identical to the pair) */
#ifndef OI_SINCOS
#if defined(OI__OWN_SIN) && defined(OI__OWN_COS)
#define OI_SINCOS(x, s, c) oi__sincos((x), (s), (c))
#else
#define OI_SINCOS(x, s, c) (*(s) = OI_SIN(x), *(c) = OI_COS(x))
#endif
#endif
#ifndef OI_TAN
#define OI_TAN OI_FN(tan)
#endif
#ifndef OI_ASIN
#define OI_ASIN OI_FN(asin)
#endif
#ifndef OI_ACOS
#define OI_ACOS OI_FN(acos)
#endif
#ifndef OI_ATAN
#define OI_ATAN OI_FN(atan)
#endif
#ifndef OI_ATAN2
/* the runtime's own (src/math/atan2.c): ~4x cheaper than a general libm's, the
 * same bits on every target; -DOI_ATAN2=atan2 (atan2f) selects the libm's */
#define OI_ATAN2 oi__atan2
#endif
oi_real oi__atan2(oi_real y, oi_real x);
#ifndef OI_EXP
#define OI_EXP OI_FN(exp)
#endif
#ifndef OI_LOG
#define OI_LOG OI_FN(log)
#endif
#ifndef OI_LOG10
#define OI_LOG10 OI_FN(log10)
#endif
#ifndef OI_POW
#define OI_POW OI_FN(pow)
#endif
#ifndef OI_ERF
#define OI_ERF OI_FN(erf)
#endif
#ifndef OI_ERFC
#define OI_ERFC OI_FN(erfc)
#endif
#ifndef OI_FABS
#define OI_FABS OI_FN(fabs)
#endif
#ifndef OI_FLOOR
#define OI_FLOOR OI_FN(floor)
#endif
#ifndef OI_HYPOT
#define OI_HYPOT OI_FN(hypot)
#endif
/* isfinite is a macro on every C99 libm; a project without one overrides it. */
#ifndef OI_ISFINITE
#define OI_ISFINITE(x) isfinite(x)
#endif

#ifndef OI_SIGNBIT
#define OI_SIGNBIT(x) signbit(x)
#endif

/* Constants as oi_real (no double promotion in the float build). */
#define OI_PI_R ((oi_real)OI_PI)

#endif /* OI_PORT_H */
