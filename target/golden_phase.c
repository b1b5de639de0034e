/* SPDX-License-Identifier: MIT */
/* golden_phase.c: tests/c/ref_phase.h (mpmath, tests/ref/gen_refs.py) on the
 * target, with tests/c/test_phase.c's tolerance. */
#include "orbillum.h"
#include "check.h"

#ifdef OI_HAVE_REF_PHASE
#include "ref_phase.h"

#ifdef OI_SINGLE_PRECISION
#define GOLD_PHASE_REL (1e-5)  /* tests/c/test_phase.c PHASE_REL */
#else
#define GOLD_PHASE_REL (1e-12)
#endif

void golden_phase(void)
{
    unsigned i;
    for (i = 0; i < sizeof ref_phase / sizeof ref_phase[0]; i++) {
        double got = (double)oi_lambert_phase((oi_real)ref_phase[i].x);
        if (ref_phase[i].want == 0.0)
            check_real("golden ref_phase (exact zero)", 0.0, got, 0, 0);
        else
            check_real("golden ref_phase", ref_phase[i].want, got, 0, GOLD_PHASE_REL);
    }
}
#else
void golden_phase(void)
{
}
#endif
