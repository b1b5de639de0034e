/* SPDX-License-Identifier: MIT */
/*
 * check.h: the self-test's checkers (defined in selftest.c), shared with the
 * golden-vector files golden_*.c. Each check counts one pass or prints
 * `FAIL what: want ... got ...` and counts one failure.
 */
#ifndef OI_TARGET_CHECK_H
#define OI_TARGET_CHECK_H

/* |got - want| <= abs_tol + rel_tol |want| */
void check_real(const char *what, double want, double got, double abs_tol, double rel_tol);
void check_int(const char *what, long want, long got);
void check_true(const char *what, int cond);
/* A check that fails today because of a deviation already reported (named
 * in `why`): printed as KNOWN and counted apart, unless OI_TARGET_STRICT. */
void check_known(const char *what, double want, double got, double abs_tol, double rel_tol,
                 const char *why);
/* count one known deviation found by a golden group itself */
void note_known(void);

/* Golden-vector groups: each runs the committed tests/c/ref_<name>.h when
 * mk/target.mk found it (-DOI_HAVE_REF_<NAME>) and does nothing otherwise. */
void golden_phase(void);
void golden_moon(void);
void golden_shadow(void);
void golden_earthshine(void);
void golden_stability(void);

#endif
