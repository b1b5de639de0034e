/* SPDX-License-Identifier: MIT */
/*
 * startup.c: minimal Cortex-M startup for the MPS2 boards (AN386 Cortex-M4,
 * AN500 Cortex-M7) under qemu-system-arm.
 *
 * Vector table (ARMv7-M Architecture Reference Manual, B1.5.3), a reset
 * handler that copies .data from its load address, zeroes .bss, enables the
 * FPU (CPACR, ARMv7-M ARM B3.2.20: CP10 and CP11 full access) and calls
 * main(); main's return value becomes the semihosting exit status. Faults
 * print a message and exit with status 3.
 */
#include <stdint.h>

#include "semihost.h"

extern uint32_t _sidata[], _sdata[], _edata[], _sbss[], _ebss[], _estack[];
int main(void);
void Reset_Handler(void);
void Fault_Handler(void);

#define CPACR (*(volatile uint32_t *)0xE000ED88UL)

void Reset_Handler(void)
{
    uint32_t *src = _sidata, *dst = _sdata;
    while (dst < _edata) *dst++ = *src++;
    for (dst = _sbss; dst < _ebss; dst++) *dst = 0U;
    CPACR |= (0xFUL << 20);           /* CP10, CP11: full access */
    __asm__ volatile("dsb\n\tisb" ::: "memory");
    sh_exit(main());
}

void Fault_Handler(void)
{
    sh_puts("FAULT: hard fault or unexpected exception\n");
    sh_exit(3);
}

typedef void (*vector_fn)(void);

/* Initial stack pointer, then the handlers: reset, NMI, HardFault,
 * MemManage, BusFault, UsageFault. The rest of the table is unused. */
__attribute__((section(".vectors"), used))
const uintptr_t oi_target_vectors[16] = {
    (uintptr_t)_estack,
    (uintptr_t)Reset_Handler,
    (uintptr_t)Fault_Handler,
    (uintptr_t)Fault_Handler,
    (uintptr_t)Fault_Handler,
    (uintptr_t)Fault_Handler,
    (uintptr_t)Fault_Handler,
    0, 0, 0, 0,
    (uintptr_t)Fault_Handler, /* SVCall */
    (uintptr_t)Fault_Handler, /* DebugMonitor */
    0,
    (uintptr_t)Fault_Handler, /* PendSV */
    (uintptr_t)Fault_Handler  /* SysTick */
};
