/* SPDX-License-Identifier: MIT */
/* local_frame.c: the target's local frame of the Earth's light (z the
 * zenith, x towards the Sun's side in the Sun-Earth-target plane, y normal
 * to it), shared by the sphere's moments and the facets' cubature. */
#include "sources/sources_internal.h"

/* Below this sin(theta) the Sun-Earth-target plane is taken as undefined:
 * the distribution is symmetric about the zenith to within a few sin(theta)
 * (the lit columns' tan(theta) term), so any x normal to r_hat then errs by
 * less than that, while the plane's normal, a cross product of two nearly
 * equal unit vectors, has a direction known only to u / sin(theta). */
#ifdef OI_SINGLE_PRECISION
#define AXIS_SIN OI_R(1.0e-5)
#else
#define AXIS_SIN OI_R(1.0e-10)
#endif

/* A hint this close to the zenith leaves the side undefined too. */
#define HINT_MIN OI_R(1.0e-3)

/* oi__local_frame_toward: r_hat, x and y of the frame at target_km for the
 * Sun at sun_km (both bounded, nonzero), and s_hat the unit vector to the
 * Sun; the three axes orthonormal to rounding at every theta. On the
 * Sun-Earth axis, where the plane is undefined, x is the part of hint (a
 * unit vector, or NULL) normal to the zenith when that part is not
 * negligible: a sum over directions about the zenith then sits the same
 * way relative to hint (e.g. the observer) however the input frame is
 * turned, so its rounding and its cubature error turn with the scene. */
void oi__local_frame_toward(const oi_real target_km[3], const oi_real sun_km[3],
                            const oi_real *hint, oi_real r_hat[3], oi_real s_hat[3],
                            oi_real x[3], oi_real y[3])
{
    oi_real n[3];
    (void)oi__unit_bounded(target_km, r_hat);
    (void)oi__unit_bounded(sun_km, s_hat);
    /* the plane's normal r x s; x = (r x s) x r is s - (s . r) r, normal to
     * r_hat to rounding whatever the normal's own error */
    oi__cross(r_hat, s_hat, n);
    if (oi__norm_bounded(n) > AXIS_SIN && oi__unit_bounded(n, n) > (oi_real)0) {
        oi__cross(n, r_hat, x);
    } else {
        /* on the Sun-Earth axis the distribution is symmetric about the
         * zenith: any x normal to it, the hint's side if it has one */
        const oi_real e[3] = {(oi_real)1, (oi_real)0, (oi_real)0};
        const oi_real f[3] = {(oi_real)0, (oi_real)1, (oi_real)0};
        oi_real h_par = (oi_real)0;
        if (hint != NULL) {
            const oi_real c = oi__dot(hint, r_hat);
            x[0] = hint[0] - c * r_hat[0];
            x[1] = hint[1] - c * r_hat[1];
            x[2] = hint[2] - c * r_hat[2];
            h_par = oi__norm_bounded(x);
        }
        if (!(h_par > HINT_MIN)) oi__cross(r_hat, (r_hat[0] * r_hat[0] < OI_R(0.5)) ? e : f, x);
    }
    (void)oi__unit_bounded(x, x);
    oi__cross(r_hat, x, y);
}

/* oi__local_frame: oi__local_frame_toward without a hint. */
void oi__local_frame(const oi_real target_km[3], const oi_real sun_km[3], oi_real r_hat[3],
                     oi_real s_hat[3], oi_real x[3], oi_real y[3])
{
    oi__local_frame_toward(target_km, sun_km, NULL, r_hat, s_hat, x, y);
}
