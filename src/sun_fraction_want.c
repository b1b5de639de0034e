/* SPDX-License-Identifier: MIT */
/* sun_fraction_want.c: oi__sun_shadow_want, the batch's Sun fraction with a
 * choice of outputs (src/oi_internal.h), from the same steps as
 * oi__sun_shadow: src/sun_fraction.c compiled a second time with only that
 * function public, so that the single call's code is not changed by a
 * second caller of its steps (make size). */
#define OI_SUN_FRACTION_WANT_ONLY
#include "sun_fraction.c"
