/* SPDX-License-Identifier: MIT */
/* semihost.c: semihosting output and exit (see semihost.h). */
#include "semihost.h"

#define SYS_WRITE0 (0x04)
#define SYS_EXIT_EXTENDED (0x20)
#define ADP_STOPPED_APPLICATION_EXIT (0x20026UL)

static unsigned long sh_call(unsigned long op, const void *arg)
{
    register unsigned long r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void sh_puts(const char *s)
{
    (void)sh_call(SYS_WRITE0, s);
}

void sh_putint(long v)
{
    char buf[24];
    int i = (int)sizeof buf - 1;
    unsigned long u = v < 0 ? 0UL - (unsigned long)v : (unsigned long)v;
    buf[i] = '\0';
    do {
        buf[--i] = (char)('0' + (int)(u % 10UL));
        u /= 10UL;
    } while (u != 0UL && i > 1);
    if (v < 0) buf[--i] = '-';
    sh_puts(&buf[i]);
}

void sh_putreal(double v)
{
    char buf[32];
    int n = 0, e = 0, k;
    unsigned long long m;
    if (v != v) { sh_puts("nan"); return; }
    if (v < 0) { buf[n++] = '-'; v = -v; }
    if (v > 1.7976931348623157e308) { buf[n] = '\0'; sh_puts(buf); sh_puts("inf"); return; }
    if (v > 0) {
        /* scale into [1e16, 1e17): 17 digits; crude, for diagnostics only */
        while (v >= 1e17) { v /= 10.0; e++; }
        while (v < 1e16) { v *= 10.0; e--; }
    }
    m = (unsigned long long)(v + 0.5);
    if (m >= 100000000000000000ULL) { m /= 10ULL; e++; }
    e += 16;
    {
        char d[17];
        for (k = 16; k >= 0; k--) { d[k] = (char)('0' + (int)(m % 10ULL)); m /= 10ULL; }
        buf[n++] = d[0];
        buf[n++] = '.';
        for (k = 1; k < 17; k++) buf[n++] = d[k];
    }
    if (v == 0) e = 0;
    buf[n++] = 'e';
    buf[n++] = e < 0 ? '-' : '+';
    if (e < 0) e = -e;
    if (e >= 100) buf[n++] = (char)('0' + e / 100);
    buf[n++] = (char)('0' + (e / 10) % 10);
    buf[n++] = (char)('0' + e % 10);
    buf[n] = '\0';
    sh_puts(buf);
}

void sh_exit(int status)
{
    unsigned long block[2];
    block[0] = ADP_STOPPED_APPLICATION_EXIT;
    block[1] = (unsigned long)(long)status;
    for (;;) (void)sh_call(SYS_EXIT_EXTENDED, block);
}
