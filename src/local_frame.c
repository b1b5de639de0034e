/* SPDX-License-Identifier: MIT */
/* local_frame.c: the target's local frame of the Earth's light (z the
 * zenith, x towards the Sun's side in the Sun-Earth-target plane, y normal
 * to it), shared by the sphere's moments and the facets' cubature. */
#include "oi_internal.h"

/* oi__local_frame: r_hat, x and y of the frame at target_km for the Sun at
 * sun_km (both bounded, nonzero); along: s_hat . r_hat, the cosine of
 * theta; s_hat the unit vector to the Sun. */
void oi__local_frame(const oi_real target_km[3], const oi_real sun_km[3], oi_real r_hat[3],
                     oi_real s_hat[3], oi_real x[3], oi_real y[3])
{
    oi_real along;
    int i;
    (void)oi__unit_bounded(target_km, r_hat);
    (void)oi__unit_bounded(sun_km, s_hat);
    along = oi__dot(s_hat, r_hat);
    for (i = 0; i < 3; i++) x[i] = s_hat[i] - along * r_hat[i];
    /* near the Sun-Earth axis x is rounding noise that need not be normal to
     * r_hat: orthogonalised once more after scaling (the distribution is then
     * symmetric about the zenith to within sin(theta), so any normal x does) */
    if (oi__unit_bounded(x, x) > (oi_real)0) {
        const oi_real dr = oi__dot(x, r_hat);
        for (i = 0; i < 3; i++) x[i] -= dr * r_hat[i];
    }
    if (oi__unit_bounded(x, x) == (oi_real)0) {
        /* on the Sun-Earth axis the distribution is symmetric about the
         * zenith: any x normal to it */
        const oi_real e[3] = {(oi_real)1, (oi_real)0, (oi_real)0};
        const oi_real f[3] = {(oi_real)0, (oi_real)1, (oi_real)0};
        oi__cross(r_hat, (r_hat[0] * r_hat[0] < OI_R(0.5)) ? e : f, x);
        (void)oi__unit_bounded(x, x);
    }
    oi__cross(r_hat, x, y);
}
