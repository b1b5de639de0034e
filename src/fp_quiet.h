/* SPDX-License-Identifier: MIT */
/*
 * fp_quiet.h: the floating-point status kept as the caller had it across
 * the vectorised blocks. A function marked OI_VECTORISE_COMPARES is
 * compiled without trapping math: on every lane the compiler may evaluate
 * both sides of a select, among them values the select then discards (the
 * square root of a negative number on a dark ring, a quotient by zero), and
 * these raise the invalid-operation or division-by-zero flag. Its caller
 * brackets the calls with oi__fp_quiet_begin and oi__fp_quiet_end: the
 * exceptions masked while they run (no trap where the caller enabled
 * traps), the status flags put back as they were after, so that a valid
 * call of the library raises no floating-point exception
 * (tests/c/test_fp_exceptions.c). x86-64: MXCSR; AArch64: FPCR's trap
 * enables and FPSR; 32-bit Arm with a floating-point unit (the Cortex-M4F
 * and M7, which have no traps): FPSCR's flags. Elsewhere nothing is done:
 * there OI_VECTORISE_COMPARES is empty, the blocks keep trapping math, and
 * their source clamps what a discarded lane would take a square root of or
 * divide by, so that they raise nothing either.
 */
#ifndef OI_FP_QUIET_H
#define OI_FP_QUIET_H

#if defined(__GNUC__) && defined(__SSE2__)
#include <xmmintrin.h>
typedef unsigned int oi_fp_status;
static inline oi_fp_status oi__fp_quiet_begin(void)
{
    const unsigned int csr = _mm_getcsr();
    _mm_setcsr(csr | 0x1F80u); /* bits 7-12: every exception masked */
    return csr;
}
static inline void oi__fp_quiet_end(oi_fp_status csr)
{
    _mm_setcsr(csr); /* the masks and flags (bits 0-5) as they were */
}
#elif defined(__GNUC__) && defined(__aarch64__)
typedef struct {
    unsigned long fpcr, fpsr;
} oi_fp_status;
static inline oi_fp_status oi__fp_quiet_begin(void)
{
    oi_fp_status s;
    __asm__ __volatile__("mrs %0, fpcr" : "=r"(s.fpcr));
    __asm__ __volatile__("mrs %0, fpsr" : "=r"(s.fpsr));
    /* trap enables IOE, DZE, OFE, UFE, IXE (bits 8-12) and IDE (15) off */
    __asm__ __volatile__("msr fpcr, %0" : : "r"(s.fpcr & ~0x9F00ul));
    return s;
}
static inline void oi__fp_quiet_end(oi_fp_status s)
{
    __asm__ __volatile__("msr fpsr, %0" : : "r"(s.fpsr));
    __asm__ __volatile__("msr fpcr, %0" : : "r"(s.fpcr));
}
#elif defined(__GNUC__) && defined(__arm__) && defined(__ARM_FP)
typedef unsigned int oi_fp_status;
static inline oi_fp_status oi__fp_quiet_begin(void)
{
    unsigned int fpscr;
    __asm__ __volatile__("vmrs %0, fpscr" : "=r"(fpscr));
    return fpscr;
}
static inline void oi__fp_quiet_end(oi_fp_status fpscr)
{
    __asm__ __volatile__("vmsr fpscr, %0" : : "r"(fpscr));
}
#else
typedef int oi_fp_status;
static inline oi_fp_status oi__fp_quiet_begin(void)
{
    return 0;
}
static inline void oi__fp_quiet_end(oi_fp_status s)
{
    (void)s;
}
#endif

#endif /* OI_FP_QUIET_H */
