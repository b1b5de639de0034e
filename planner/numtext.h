/* SPDX-License-Identifier: MIT */
/* numtext.h: exact decimal text of doubles, faster than printf and strtod (numtext.c). */
#ifndef OI_PLAN_NUMTEXT_H
#define OI_PLAN_NUMTEXT_H

#include <stddef.h>

/* Bytes num_format17 may write (the longest text, 24 with its NUL, and
 * fixed-size copies past it). */
#define NUM_TEXT_MAX 40

/* Writes x as printf's "%.17g" does, byte for byte, into buf (NUM_TEXT_MAX
 * bytes); returns the length. */
size_t num_format17(double x, char *buf);

/* Reads a decimal number as strtod does (the same double, the same end),
 * for the text at s; *end is set as strtod's endptr. Decimal only: the words
 * inf, infinity and nan (any case, with a sign, nan(...)) are read as strtod
 * reads them, but hexadecimal text ("0x1B58", "0x1p3", "0x") and leading
 * white space are no number: 0 returned, *end = s. */
double num_parse(const char *s, char **end);

/* num_parse reading eight digits at a time: s NUL-terminated as for
 * num_parse, and len bytes readable at s, len = strlen(s) or more (bytes
 * past the NUL are read, never used; they must be initialised). */
double num_parse_n(const char *s, size_t len, char **end);

/* The first step of num_parse_n alone: a plain decimal ([sign] digits
 * [. digits], at most 15 digits before the point and 19 in all, no
 * exponent) at s, the bytes up to lim readable and initialised. Returns 1
 * with num_parse_n's double and end, or 0 for any other text (or on a
 * big-endian machine), *out and *end then untouched. */
int num_parse_plain(const char *s, const char *lim, double *out, char **end);

#endif
