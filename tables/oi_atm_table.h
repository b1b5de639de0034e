/* SPDX-License-Identifier: MIT */
/*
 * oi_atm_table.h: transitional names of the atmosphere table oi_atm_vband
 * for src/atmosphere.c and tests/c/test_atmosphere.c until they read the
 * struct (generated with it by `python -m bake atmosphere`; do not edit).
 */
#ifndef OI_ATM_TABLE_H
#define OI_ATM_TABLE_H

#include "oi_atm_vband.h"

#define OI_ATM_TABLE_FORMAT 2
#define OI_ATM_NZ (48)
#define OI_ATM_NT (85)
#define OI_ATM_NA (72)
#define OI_ATM_NB (13)
#define OI_ATM_N_BISECT (48)
#define OI_ATM_Z_MIN_KM (500.0)
#define OI_ATM_Z_MAX_KM (500000.0)
#define OI_ATM_H_A_KM (6.5)
#define OI_ATM_V_MID_KM (60.0)
#define OI_ATM_ALPHA_C_RAD (0.007199403794924052)
#define OI_ATM_H_C_KM (10.0)
#define OI_ATM_TOP_KM (100.0)
#define OI_ATM_W_RHO (0.5)
#define OI_ATM_F_FLOOR (1e-08)
#define OI_ATM_EARTH_RADIUS_KM (6378.137)
#define OI_ATM_SUN_RADIUS_KM (695700.0)
#define OI_ATM_AU_KM (149597870.7)
#define OI_ATM_Q_MIN (-8.0)
#define OI_ATM_Q_SCALE (0.00012208743419546807)
#define OI_ATM_PSI_MIN_RAD (-0.001)
#define OI_ATM_PSI_SCALE_RAD (1.983672846570535e-07)
#define oi__atm_q (oi_atm_vband.q)
#define oi__atm_psi (oi_atm_vband.psi)

#endif /* OI_ATM_TABLE_H */
