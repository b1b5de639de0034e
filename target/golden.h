/* SPDX-License-Identifier: MIT */
/*
 * golden.h: the committed mpmath golden vectors of the host test suites
 * (tests/c/ref_*.h), run on the target. mk/cross.mk defines OI_HAVE_<NAME>
 * for each reference header present, so the image builds while the suites
 * are still growing. Included once, by selftest.c, after its checkers.
 */
#ifndef OI_TARGET_GOLDEN_H
#define OI_TARGET_GOLDEN_H

static void golden_checks(void)
{
}

#endif
