/* SPDX-License-Identifier: MIT */
/* magnitude.c: apparent visual magnitude from flux, and back. */
#include "target/target_internal.h"

/*
 * oi_magnitude_v: apparent V magnitude of a flux at the observer.
 * Given:   flux_w_m2  irradiance at the observer from the target (W/m^2)
 *          model      NULL or model (tsi_w_m2); an invalid model means defaults
 * Returns: m = OI_SUN_MAG_V - 2.5 log10(flux / tsi), the Sun's V magnitude at
 *          1 AU being the zero point (docs/physics.md); OI_MAG_DARK for a
 *          flux <= 0, non-finite, or fainter than OI_MAG_DARK.
 * Notes:   1. The target is assumed to reflect sunlight's spectrum unchanged
 *             (grey albedo), so the solar colour carries over to V.
 */
oi_real oi_magnitude_v(oi_real flux_w_m2, const oi_model *model)
{
    oi_model m;
    (void)oi__model_resolve(model, &m);
    return oi__magnitude_v(flux_w_m2, m.tsi_w_m2);
}

/* oi_magnitude_v for a resolved TSI (src/target/target_internal.h). */
oi_real oi__magnitude_v(oi_real flux_w_m2, oi_real tsi_w_m2)
{
    oi_real mag, ratio;
    if (!OI_ISFINITE(flux_w_m2) || !(flux_w_m2 > (oi_real)0)) return (oi_real)OI_MAG_DARK;
    ratio = flux_w_m2 / tsi_w_m2;
    if (ratio > OI_R(1e-30) && ratio < OI_R(1e30)) {
        mag = (oi_real)OI_SUN_MAG_V - OI_R(2.5) * OI_LOG10(ratio);
    } else {
        /* log10 of each factor apart: the ratio may underflow (single
         * precision) or overflow (a tiny model TSI) */
        mag = (oi_real)OI_SUN_MAG_V - OI_R(2.5) * (OI_LOG10(flux_w_m2) - OI_LOG10(tsi_w_m2));
    }
    if (!(mag < (oi_real)OI_MAG_DARK)) return (oi_real)OI_MAG_DARK;
    return mag;
}

/*
 * oi_flux_from_magnitude: irradiance of a source of apparent V magnitude.
 * Given:   mag_v      apparent V magnitude, [OI_MAG_MIN, OI_MAG_MAX]
 *          model      NULL or model (tsi_w_m2)
 * Returned: flux_w_m2 tsi * 10^(-0.4 (mag_v - OI_SUN_MAG_V)) (W/m^2)
 * Returns: OI_OK; OI_ERR_NULL; OI_ERR_MAGNITUDE (non-finite or out of range);
 *          OI_ERR_MODEL / OI_ERR_RADIUS (invalid model). Flux is 0 on error.
 */
int oi_flux_from_magnitude(oi_real mag_v, const oi_model *model, oi_real *flux_w_m2)
{
    oi_model m;
    int status;
    if (flux_w_m2 == NULL) return OI_ERR_NULL;
    *flux_w_m2 = (oi_real)0;
    status = oi__model_resolve(model, &m);
    if (status < 0) return status;
    if (!OI_ISFINITE(mag_v) || mag_v < (oi_real)OI_MAG_MIN || mag_v > (oi_real)OI_MAG_MAX)
        return OI_ERR_MAGNITUDE;
    *flux_w_m2 = m.tsi_w_m2 * OI_POW(OI_R(10.0), OI_R(-0.4) * (mag_v - (oi_real)OI_SUN_MAG_V));
    return OI_OK;
}
