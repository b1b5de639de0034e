# SPDX-License-Identifier: MIT
"""The scattering medium: the refraction table's atmosphere profile seen as scatterers.

Everything here comes from `bake.atmosphere.profile` (the same 1976 U.S. Standard
Atmosphere densities, ozone, aerosol loads, cloud deck and V band); this module
only adds what scattering needs and the profile does not state:

* Rayleigh phase function with depolarisation: P(T) = 3 / (4 (1 + 2 g)) ((1 + 3 g)
  + (1 - g) cos^2 T), g = rho_n / (2 - rho_n) (Chandrasekhar 1950; Hansen &
  Travis 1974, Space Sci. Rev. 16, 527, eq. 2.15), depolarisation factor of air
  rho_n = 0.0279 (Bodhaine et al. 1999, Table 1 at 550 nm, F_air = 1.0493).
* Aerosol: Henyey-Greenstein phase function with asymmetry g = 0.70 and single
  scattering albedo 0.93 (tropospheric: OPAC continental average at 550 nm,
  Hess, Koepke & Schult 1998, BAMS 79, 831, Table 4) and 1.0 (stratospheric
  sulphate droplets, non-absorbing in the visible). The tropospheric load lies
  below the cloud deck and matters only in a clear-sky bake.
* Clouds: the profile's opaque layer below cloud_top_km is the lower boundary of
  the medium (a sphere of radius R + cloud_top_km that blocks sunlight and lines of
  sight alike), as in the refraction table.
* Band: the profile's 24 V-band wavelengths grouped into N_GROUPS consecutive
  groups, each at its weighted mean wavelength with its summed weight (the
  integrand is smooth in wavelength: lambda^-4 and exp(-tau)).

Densities are tabulated once on a 0.02 km grid of log density (exact at the nodes,
linear in log between them: the exponential parts exactly, the Gaussian layers to
1e-7 relative).
"""
from __future__ import annotations

import numpy as np

from ..atmosphere import profile as ap

RHO_N = 0.0279            # depolarisation factor of air (Bodhaine et al. 1999)
AER_G = 0.70              # Henyey-Greenstein asymmetry of both aerosol layers
AER_OMEGA_TROP = 0.93     # single scattering albedo, tropospheric aerosol (OPAC)
AER_OMEGA_STRAT = 1.0     # stratospheric sulphate
N_GROUPS = 6              # wavelength groups of the V band
DH_KM = 0.02              # density table step


def rayleigh_phase(cos_t):
    """Rayleigh phase function with depolarisation (normalised: mean over the
    sphere 1)."""
    g = RHO_N / (2.0 - RHO_N)
    return 0.75 / (1.0 + 2.0 * g) * ((1.0 + 3.0 * g) + (1.0 - g) * cos_t * cos_t)


def hg_phase(cos_t, g=AER_G):
    """Henyey-Greenstein phase function (mean over the sphere 1)."""
    return (1.0 - g * g) / (1.0 + g * g - 2.0 * g * cos_t) ** 1.5


class Medium:
    """Extinction and scattering per wavelength group of a Profile."""

    def __init__(self, profile: ap.Profile | None = None, n_groups=N_GROUPS):
        self.profile = profile or ap.us1976()
        p = self.profile
        self.R = p.earth_radius_km
        self.h_floor = p.cloud_top_km if p.extinction else 0.0
        self.r_floor = self.R + self.h_floor
        self.r_top = self.R + p.top_km
        lam, w = ap.band_weights()
        groups = np.array_split(np.arange(len(lam)), n_groups)
        self.lam = np.array([np.sum(lam[g] * w[g]) / np.sum(w[g]) for g in groups])
        self.weight = np.array([np.sum(w[g]) for g in groups])
        # per species (air, ozone, trop. aerosol, strat. aerosol): extinction weights
        # (n_species, n_groups) and scattering weights
        self.ext_w = p.species_weights(self.lam)
        sca = self.ext_w.copy()
        sca[1] = 0.0
        sca[2] *= AER_OMEGA_TROP
        sca[3] *= AER_OMEGA_STRAT
        self.sca_w = sca
        self.h_nodes = np.arange(0.0, p.top_km + DH_KM / 2, DH_KM)
        self.log_n = np.log(p.species(self.h_nodes))   # (4, n_h), every value > 0

    def species(self, h_km):
        """Species densities at altitudes h (any shape): (4, *shape); 0 above the top."""
        h = np.asarray(h_km, dtype=float)
        flat = h.ravel()
        out = np.empty((4, flat.size))
        for k in range(4):
            out[k] = np.exp(np.interp(flat, self.h_nodes, self.log_n[k]))
        out[:, flat > self.profile.top_km] = 0.0
        return out.reshape((4,) + h.shape)

    def exact_species(self, h_km):
        """The profile's own densities (for the independent Monte Carlo)."""
        h = np.asarray(h_km, dtype=float)
        out = self.profile.species(h)
        return np.where(h > self.profile.top_km, 0.0, out)
