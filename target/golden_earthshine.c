/* SPDX-License-Identifier: MIT */
/* golden_earthshine.c: tests/c/ref_earthshine.h on the target, when it is committed. */
#include "orbillum.h"
#include "check.h"

void golden_earthshine(void)
{
}
