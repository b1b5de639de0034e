/* SPDX-License-Identifier: MIT */
/* ori_test_abi.c: struct sizes for the test binding tests/python/_oi_ctypes.py,
 * which checks its ctypes mirrors against them (linked only into
 * build/libori_test.so, never into the runtime). */
#include <stddef.h>

#include "orbillum.h"

size_t ori_test_sizeof(int which);

size_t ori_test_sizeof(int which)
{
    switch (which) {
    case 0: return sizeof(oi_model);
    case 1: return sizeof(oi_shadow);
    case 2: return sizeof(oi_scene);
    case 3: return sizeof(oi_illum);
    case 4: return offsetof(oi_illum, range_km);
    case 5: return offsetof(oi_scene, target_radius_m);
    default: return 0;
    }
}
