/* SPDX-License-Identifier: MIT */
/*
 * semihost.h: ARM semihosting for the bare-metal self-test (output and exit).
 *
 * Only two operations are used (ARM "Semihosting for AArch32 and AArch64",
 * version 2.0, sections 5.4.3 SYS_WRITE0 (0x04), 5.4.5 SYS_EXIT_EXTENDED
 * (0x20)): a BKPT 0xAB on M-profile cores with r0 = operation, r1 = argument.
 * qemu-system-arm implements both with -semihosting-config enable=on.
 */
#ifndef OI_TARGET_SEMIHOST_H
#define OI_TARGET_SEMIHOST_H

/* Write a NUL-terminated string to the host console. */
void sh_puts(const char *s);
/* Write a decimal integer. */
void sh_putint(long v);
/* Write a real number as sign, 17 significant digits and exponent
 * (d.ddddddddddddddddde+XX); enough to compare against %.17g by eye. */
void sh_putreal(double v);
/* Stop the simulation with the given exit status (0 = success). */
void sh_exit(int status);

#endif
