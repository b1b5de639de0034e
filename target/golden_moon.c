/* SPDX-License-Identifier: MIT */
/* golden_moon.c: the lunar phase law part of tests/c/ref_phase.h (mpmath,
 * tests/ref/gen_refs.py) on the target, with tests/c/test_moon.c's tolerance. */
#include "orbillum.h"
#include "check.h"

#if defined(OI_HAVE_REF_PHASE) && !defined(OI_NO_MOON)
#define REF_MOON_ONLY
#include "ref_phase.h"

#ifdef OI_SINGLE_PRECISION
#define GOLD_MOON_REL (2e-6)   /* tests/c/test_moon.c MOON_REL */
#else
#define GOLD_MOON_REL (4e-15)
#endif

void golden_moon(void)
{
    unsigned i;
    for (i = 0; i < sizeof ref_moon / sizeof ref_moon[0]; i++)
        check_real("golden ref_moon", ref_moon[i].want, (double)oi_moon_phase_law((oi_real)ref_moon[i].x),
                   0, GOLD_MOON_REL);
}
#else
void golden_moon(void)
{
}
#endif
