/* SPDX-License-Identifier: MIT */
/*
 * bench_target.c: instructions per scene on the Cortex-M builds (make
 * target-bench), the same scene mix as the host benchmark (bench/scenes.h).
 *
 * qemu-system-arm runs with -icount shift=0: every guest instruction advances
 * the virtual clock by 1 ns, and SysTick (processor clock, 25 MHz on the MPS2
 * boards) then counts one tick per 40 instructions. The count of a
 * configuration is (ticks(12 passes) - ticks(2 passes)) x 40 / (10 x scenes):
 * the difference cancels the set-up, the division bounds the quantisation to
 * 40 / 720 of an instruction. These are instructions, not cycles: on a real
 * M4F or M7 the cycle count also depends on the memory system (flash wait
 * states, caches) and on multi-cycle instructions (VDIV, VSQRT, and in
 * particular double-precision arithmetic in software on the M4F).
 * ARMv7-M ARM B3.3 (SysTick); qemu docs, "TCG Instruction Counting".
 */
#include <stddef.h>
#include <stdint.h>

#include "orbillum.h"
#include "semihost.h"
#include "../bench/scenes.h"

void oi_target_missing(const char *name);
void oi_target_missing(const char *name)
{
    sh_puts("MISSING ");
    sh_puts(name);
    sh_puts("\n");
}

#define SYST_CSR (*(volatile uint32_t *)0xE000E010UL)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014UL)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018UL)
#define TICK_INSNS (40UL) /* 1 ns per instruction, 25 MHz SysTick */

static oi_scene scenes[BENCH_NSCENES];
static bench_scene_d raw[BENCH_NSCENES];
static oi_real es_theta[BENCH_NSCENES], es_h[BENCH_NSCENES];
static oi_illum il;
#ifndef OI_NO_EXPOSURE
static oi_exposure ex;
#endif
static volatile double sink;

enum { C_ALL, C_SUN, C_SUN_EARTH, C_ALL_EXPOSE, C_SUN_FRACTION, C_EARTHSHINE, C_N };
static const char *const config_name[C_N] = {"all",        "sun",          "sun_earth",
                                             "all_expose", "sun_fraction", "earthshine"};

static void setup(void)
{
    int i, k;
    bench_make_scenes(raw);
    for (i = 0; i < BENCH_NSCENES; i++) {
        oi_scene *s = &scenes[i];
        oi_scene_defaults(s);
        for (k = 0; k < 3; k++) {
            s->sun_km[k] = (oi_real)raw[i].sun[k];
            s->moon_km[k] = (oi_real)raw[i].moon[k];
            s->target_km[k] = (oi_real)raw[i].target[k];
            s->observer_km[k] = (oi_real)raw[i].observer[k];
        }
        s->has_observer = 1;
        es_theta[i] = oi_angle(s->sun_km, s->target_km);
        {
            double r = sqrt(raw[i].target[0] * raw[i].target[0] + raw[i].target[1] * raw[i].target[1] +
                            raw[i].target[2] * raw[i].target[2]);
            es_h[i] = (oi_real)(r - 6378.137);
        }
    }
}

static void run_config(int cfg)
{
    oi_real phi, psi;
    double acc = 0.0;
    int i;
    for (i = 0; i < BENCH_NSCENES; i++) {
        oi_scene *s = &scenes[i];
        switch (cfg) {
        case C_ALL:
        case C_ALL_EXPOSE:
            s->terms = OI_TERM_ALL;
            break;
        case C_SUN:
            s->terms = OI_TERM_SUN;
            break;
        default:
            s->terms = OI_TERM_SUN | OI_TERM_EARTH;
            break;
        }
        switch (cfg) {
        case C_SUN_FRACTION:
            (void)oi_sun_fraction(s->sun_km, s->target_km, NULL, &il.shadow);
            acc += (double)il.shadow.fraction;
            break;
        case C_EARTHSHINE:
            (void)oi_earthshine(es_theta[i], es_h[i], NULL, &phi, &psi);
            acc += (double)phi;
            break;
        default:
            (void)oi_illuminate(s, NULL, &il);
            acc += (double)il.flux_obs;
#ifndef OI_NO_EXPOSURE
            if (cfg == C_ALL_EXPOSE) {
                (void)oi_expose_scene(oi_camera_builtin(0), s, &il, NULL, NULL, &ex);
                acc += (double)ex.exposure_s;
            }
#endif
            break;
        }
    }
    sink = acc;
}

static uint32_t ticks_of(int cfg, int passes)
{
    uint32_t t0, t1;
    int k;
    SYST_CSR = 0;
    SYST_RVR = 0x00FFFFFFUL;
    SYST_CVR = 0;
    SYST_CSR = 0x5UL; /* enable, processor clock, no interrupt */
    t0 = SYST_CVR;
    for (k = 0; k < passes; k++) run_config(cfg);
    t1 = SYST_CVR;
    return (t0 - t1) & 0x00FFFFFFUL; /* counts down; < 2^24 ticks per measurement */
}

int main(void)
{
    int c;
#ifdef OI_SINGLE_PRECISION
    const char *prec = "float";
#else
    const char *prec = "double";
#endif
    setup();
    for (c = 0; c < C_N; c++) {
        uint32_t a = ticks_of(c, 2), b = ticks_of(c, 12);
        unsigned long per = (unsigned long)(b - a) * TICK_INSNS / (10UL * BENCH_NSCENES);
        sh_puts("target.");
        sh_puts(prec);
        sh_puts(".");
        sh_puts(config_name[c]);
        sh_puts(".instructions ");
        sh_putint((long)per);
        sh_puts(" instructions\n");
    }
    return 0;
}
