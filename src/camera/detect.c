/* SPDX-License-Identifier: MIT */
/*
 * detect.c: the detection rule of a camera (docs/camera.md, "Detection"):
 * the faintest signal in the brightest pixel that the rule detects, and
 * the normal quantile it needs.
 */
#include "camera/camera_internal.h"

#ifndef OI_NO_EXPOSURE

#define SQRT2 OI_R(1.4142135623730951)
#define SQRT2PI_INV OI_R(0.3989422804014327) /* 1 / sqrt(2 pi) */

/*
 * oi__normal_quantile_upper: z with 1 - Phi(z) = tail for tail in (0, 0.5]:
 * the standard normal quantile of the upper tail, taken as given (not as
 * 1 - p, which loses the digits of a small tail), by Newton's method on
 * ln Q(z) = ln(tail), Q(z) =
 * erfc(z / sqrt 2) / 2 the upper tail (accurate for p near 1; ln Q is
 * concave, so Newton converges from the tail bound sqrt(-2 ln(tail)),
 * above the root, without overshoot); 12 steps are past double precision
 * for tails down to 1e-15 (tests/c/test_detect.c).
 */
oi_real oi__normal_quantile_upper(oi_real tail)
{
    const oi_real ln_tail = OI_LOG(tail);
    oi_real z, q;
    int i;
    if (!(tail < OI_R(0.5))) return 0;
    z = OI_SQRT(OI_R(-2.0) * ln_tail);
    for (i = 0; i < 12; i++) {
        q = OI_R(0.5) * OI_ERFC(z / SQRT2);
        z += (OI_LOG(q) - ln_tail) * q / (SQRT2PI_INV * OI_EXP(OI_R(-0.5) * z * z));
    }
    return z > 0 ? z : OI_R(0.0);
}

/*
 * oi__signal_min_e: the smallest signal s (electrons) with
 * s >= thr + z sqrt(s + c), thr >= 0 the threshold above the background,
 * z >= 0 the margin in the target pixel's noise, c = background + read
 * noise^2 (electrons): the larger root of (s - thr)^2 = z^2 (s + c),
 *   s = thr + z^2 / 2 + z sqrt(thr + z^2 / 4 + c),
 * (every term positive: no cancellation).
 */
oi_real oi__signal_min_e(oi_real thr, oi_real z, oi_real c)
{
    return thr + OI_R(0.5) * z * z + z * OI_SQRT(thr + OI_R(0.25) * z * z + c);
}

#endif /* OI_NO_EXPOSURE */
