/* SPDX-License-Identifier: MIT */
/* oi_wasm_math.h: the libm functions the wasm build takes from web/wasm/oi_wasm_math.c
 * instead of wasi-libc (selected with -DOI_LOG10=oi_wasm_log10, the runtime's port hook). */
#ifndef OI_WASM_MATH_H
#define OI_WASM_MATH_H

double oi_wasm_log10(double x);

#endif
