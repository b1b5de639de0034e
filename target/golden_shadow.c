/* SPDX-License-Identifier: MIT */
/* golden_shadow.c: tests/c/ref_shadow.h on the target, when it is committed. */
#include "orbillum.h"
#include "check.h"

void golden_shadow(void)
{
}
