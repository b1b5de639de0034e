/* SPDX-License-Identifier: MIT */
/* quaternion.c: the attitude quaternion's check and normalisation, and the
 * rotation of a body-frame vector into the positions' frame. */
#include "target/target_internal.h"

#ifndef OI_NO_FACETS

/* Largest accepted |norm - 1| of a caller's quaternion (oi_scene.attitude_q). */
#define QUAT_NORM_TOL OI_R(1e-6)

/*
 * oi__quat_unit: the unit quaternion (w, x, y, z) of q: all four zero gives
 * the identity; a non-finite component or a norm off 1 by more than
 * QUAT_NORM_TOL gives OI_ERR_SHAPE (out the identity); else q / |q| and
 * OI_OK.
 */
int oi__quat_unit(const oi_real q[4], oi_real out[4])
{
    oi_real n2 = (oi_real)0, n;
    int i;
    out[0] = (oi_real)1;
    out[1] = out[2] = out[3] = (oi_real)0;
    for (i = 0; i < 4; i++) {
        /* a component above 2 is no unit quaternion's (nor squared to overflow) */
        if (!OI_ISFINITE(q[i]) || !(OI_FABS(q[i]) <= (oi_real)2)) return OI_ERR_SHAPE;
        n2 += q[i] * q[i];
    }
    /* all four zero: the identity; a nonzero quaternion whose squared
     * norm underflows (1e-300, 0, 0, 0) is no unit quaternion (below) */
    if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0) return OI_OK;
    n = OI_SQRT(n2);
    if (!(OI_FABS(n - (oi_real)1) <= QUAT_NORM_TOL)) return OI_ERR_SHAPE;
    for (i = 0; i < 4; i++) out[i] = q[i] / n;
    return OI_OK;
}

/* oi__quat_rotate: out = q v q* for a unit quaternion q (may alias v):
 * v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z). */
void oi__quat_rotate(const oi_real q[4], const oi_real v[3], oi_real out[3])
{
    oi_real t[3], c[3];
    const oi_real u[3] = {q[1], q[2], q[3]};
    int i;
    oi__cross(u, v, t);
    for (i = 0; i < 3; i++) t[i] *= OI_R(2.0);
    oi__cross(u, t, c);
    for (i = 0; i < 3; i++) out[i] = v[i] + q[0] * t[i] + c[i];
}

#endif /* OI_NO_FACETS */
