/* SPDX-License-Identifier: MIT */
/*
 * atm_table_check.c: oi__atm_table_valid, the check of a caller's
 * atmosphere table (oi_model.atm_table; contract in include/orbillum.h),
 * called by oi__model_resolve. A translation unit of its own so that a
 * program that takes a model links the check, not the lookup. The whole
 * file disappears with OI_NO_ATMOSPHERE.
 */
#ifndef OI_NO_ATMOSPHERE

#include "model/model_internal.h"
#include "oi_tables_internal.h"

/* Largest node count along either axis of a caller's table: nz nt codes
 * stay below INT_MAX. */
#define ATM_N_MAX 32767

/* 1 when v is finite and lo <= v <= hi (NaN fails). */
static int in_range(oi_real v, oi_real lo, oi_real hi)
{
    return v >= lo && v <= hi && OI_ISFINITE(v);
}

int oi__atm_table_valid(const oi_atm_table *t)
{
    const oi_real big = (oi_real)OI_POSITION_MAX_KM, psi_max = (oi_real)OI_ATM_PSI_MAX_RAD;
    if (t->format != OI_ATM_FORMAT || t->kind != OI_TABLE_KIND_ATMOSPHERE) return 0;
    if (t->q == NULL || t->psi == NULL) return 0;
    if (t->nz < 2 || t->na < 2 || t->nb < 1 || t->nz > ATM_N_MAX || t->na > ATM_N_MAX ||
        t->nb > ATM_N_MAX || t->nt != t->na + t->nb)
        return 0;
    if (!(t->z_min_km > (oi_real)0) || !in_range(t->z_max_km, t->z_min_km, big) ||
        !(t->z_max_km > t->z_min_km) || !(t->h_a_km > (oi_real)0) ||
        !in_range(t->h_a_km, (oi_real)0, big))
        return 0;
    if (!in_range(t->h_c_km, (oi_real)0, t->v_mid_km) || !(t->h_c_km < t->v_mid_km) ||
        !in_range(t->top_km, t->v_mid_km, (oi_real)OI_ATM_TOP_MAX_KM) ||
        !(t->top_km > t->v_mid_km) || !in_range(t->alpha_c_rad, (oi_real)0, (oi_real)1) ||
        !in_range(t->w_rho, (oi_real)0, (oi_real)1) || !in_range(t->f_floor, (oi_real)0, (oi_real)1) ||
        !(t->f_floor > (oi_real)0))
        return 0;
    if (!OI_ISFINITE(t->q_min) || !OI_ISFINITE(t->q_scale) ||
        !in_range(t->psi_min_rad, -psi_max, psi_max) ||
        !in_range(t->psi_min_rad + OI_R(65535.0) * t->psi_scale_rad, -psi_max, psi_max))
        return 0;
    return in_range(t->e_mid, (oi_real)0, (oi_real)1) && t->e_mid > (oi_real)0 &&
           in_range(t->c_iu, (oi_real)0, big) && t->c_iu > (oi_real)0 &&
           in_range(t->ln10, OI_R(2.3), OI_R(2.31));
}

#else
typedef int oi__atm_table_check_removed; /* ISO C forbids an empty translation unit */
#endif /* OI_NO_ATMOSPHERE */
