# SPDX-License-Identifier: MIT
"""Atmosphere profiles: refractivity and extinction versus altitude, and the band.

Everything the ray reference (`bake.atmosphere.rays`) needs about the air, in one
place, with every number stated and sourced. Altitudes are geometric (km)
above a spherical Earth of radius R_EARTH_KM.

Refractivity
------------
N(h) = n(h) - 1. Two profiles:

* `us1976()` (default): N(h) = N_s rho(h) / rho_s, the Gladstone-Dale law
  (refractivity proportional to density) with rho(h) from the 1976 U.S.
  Standard Atmosphere (NOAA/NASA/USAF, 1976, NOAA-S/T 76-1562): seven
  geopotential layers of constant lapse rate up to 84.852 km geopotential
  (86 km geometric), hydrostatic pressure; above that an isothermal
  continuation (refraction there is < 1e-9 and irrelevant).
  N_s = (n - 1) of standard dry air (15 C, 101325 Pa) at 550 nm from Edlen's
  dispersion formula (B. Edlen 1966, Metrologia 2, 71, eq. 1): 2.7784e-4.
* `exponential(N0, H)`: N(h) = N0 exp(-h/H) (docs/physics.md), used for the
  closed-form test N0 sqrt(2 pi R / H) and as a simple alternative.

The atmosphere is cut at TOP_KM = 100 km (N(100 km) ~ 1.5e-10): above the cut
rays go straight and are not dimmed.

Extinction (V band)
-------------------
* Rayleigh: cross-section per molecule of Bodhaine et al. (1999, J. Atmos.
  Oceanic Technol. 16, 1854, eq. 29; 360 ppm CO2), times the molecular number
  density of the profile. Vertical optical depth at 550 nm: 0.097 (their
  Table 3: 0.0973).
* Ozone (Chappuis band): 300 DU column in a Gaussian layer centred at 22 km
  (1-sigma 6.4 km, i.e. FWHM 15 km, peak ~5e18 m^-3: a mid-latitude shape,
  cf. the U.S. Standard Atmosphere 1976 ozone table); cross-sections at
  room temperature read to ~5 % from Serdyuchenko et al. (2014, Atmos. Meas.
  Tech. 7, 625, their Fig. 6; peak 5.1e-21 cm^2 near 600 nm). Vertical
  optical depth in V ~0.03.
* Aerosol, a stated load (not a climatology): boundary layer tau = 0.10 at
  550 nm, scale height 1.5 km, Angstrom exponent 1.3 (below the clouds for
  every ray that passes them, so it matters only without clouds); volcanically
  quiet stratospheric background tau = 0.005 at 550 nm in a Gaussian layer at
  20 km (1-sigma 4 km), Angstrom exponent 1.5 (order of magnitude of SAGE II
  background values, e.g. Thomason et al. 2008, ACP 8, 983).
* Clouds: a ray whose lowest point lies below CLOUD_TOP_KM = 10 km passes
  with 1 - CLOUD_FRACTION of its clear-sky transmission, CLOUD_FRACTION =
  0.68 the global cloud amount of the satellite climatologies (Stubenrauch
  et al. 2013, Bull. Amer. Meteor. Soc. 94, 1031: 0.68 +- 0.03), read as
  the chance that a grazing path meets a cloud near its lowest point; 10 km
  the top of the tropospheric cloud field (tops 5-15 km, under the
  tropopause). cloud_fraction = 1 is an opaque deck. Seed mode: no
  extinction, no clouds; only the solid Earth blocks.

Bands
-----
`Profile.band`: "V" (the default, for cameras) or "total" (total solar
irradiance, for power, thermal and radiation pressure: the 5772 K black
body's energy from 350 to 4000 nm, see TOTAL_LAMBDA_NM; Rayleigh, ozone and
aerosol by the wavelength laws above, extended past 1000 nm as stated in
their functions; no water vapour, O2 or CO2 bands).

Johnson-Cousins V as tabulated by Bessell (1990, PASP 102, 1181, Table 2),
470-700 nm every 10 nm, weighted by the solar spectrum approximated by a
5772 K black body (IAU 2015 B3 nominal effective temperature). The band
transmission is the weighted mean of exp(-tau(lambda)) (not exp of the mean
tau: grazing paths redden the light). Refraction uses the index at 550 nm
(dispersion across V changes the grazing bending by ~1 %: neglected).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..common.constants import R_EARTH_KM
TOP_KM = 100.0              # top of the model atmosphere (km)
CLOUD_TOP_KM = 10.0         # top of the cloud layer (km)
CLOUD_FRACTION = 0.68       # fraction of the rays below the top that the clouds stop (see above)

# --- 1976 U.S. Standard Atmosphere constants (NOAA-S/T 76-1562, 1976)
_G0 = 9.80665               # m s^-2
_M_AIR = 0.0289644          # kg mol^-1
_R_GAS = 8.31432            # J mol^-1 K^-1 (value used by the 1976 standard)
_K_BOLTZ = 1.380622e-23     # J K^-1 (1976 standard value)
_N_AVOGADRO = 6.022169e23
_R0_GEOPOT = 6356.766       # km, radius used for geopotential altitude
_T0 = 288.15                # K
_P0 = 101325.0              # Pa
_GMR = _G0 * _M_AIR / _R_GAS * 1e3   # K per km of geopotential altitude: 34.1632
# layer base geopotential altitudes (km) and lapse rates (K/km)
_HB = np.array([0.0, 11.0, 20.0, 32.0, 47.0, 51.0, 71.0, 84.852])
_LB = np.array([-6.5, 0.0, 1.0, 2.8, 0.0, -2.8, -2.0, 0.0])


def _us1976_bases():
    tb = [_T0]
    pb = [_P0]
    for i in range(len(_HB) - 1):
        dh = _HB[i + 1] - _HB[i]
        t0, p0, lapse = tb[-1], pb[-1], _LB[i]
        if lapse == 0.0:
            p1 = p0 * np.exp(-_GMR * dh / t0)
        else:
            p1 = p0 * (t0 / (t0 + lapse * dh)) ** (_GMR / lapse)
        tb.append(t0 + lapse * dh)
        pb.append(p1)
    return np.array(tb), np.array(pb)


_TB, _PB = _us1976_bases()


def geopotential_km(h):
    """Geopotential altitude (km) of a geometric altitude h (km)."""
    return _R0_GEOPOT * h / (_R0_GEOPOT + h)


def geometric_km(hp):
    """Geometric altitude (km) of a geopotential altitude hp (km)."""
    return _R0_GEOPOT * hp / (_R0_GEOPOT - hp)


def us1976_state(h):
    """Temperature (K), pressure (Pa), lapse rate (K per geopotential km) at
    geometric altitude h (km, array). Isothermal continuation above 86 km."""
    h = np.asarray(h, dtype=float)
    hp = geopotential_km(np.maximum(h, 0.0))
    i = np.clip(np.searchsorted(_HB, hp, side="right") - 1, 0, len(_HB) - 1)
    lapse = _LB[i]
    t = _TB[i] + lapse * (hp - _HB[i])
    with np.errstate(divide="ignore", invalid="ignore"):
        p_grad = _PB[i] * (_TB[i] / np.where(lapse == 0, 1.0, t)) ** (
            _GMR / np.where(lapse == 0, 1.0, lapse))
    p_iso = _PB[i] * np.exp(-_GMR * (hp - _HB[i]) / _TB[i])
    p = np.where(lapse == 0, p_iso, p_grad)
    return t, p, lapse


def edlen_refractivity(lam_um):
    """(n - 1) of standard dry air (15 C, 101325 Pa, 0.03 % CO2) at vacuum
    wavelength lam_um (micrometres): Edlen (1966), Metrologia 2, 71, eq. 1."""
    s2 = 1.0 / np.asarray(lam_um, dtype=float) ** 2
    return 1e-8 * (8342.54 + 2406147.0 / (130.0 - s2) + 15998.0 / (38.9 - s2))


N_S_550 = float(edlen_refractivity(0.55))   # 2.7784e-4
RHO_S = _P0 * _M_AIR / (_R_GAS * _T0)       # kg m^-3, 1.2250
N_AIR_S = _P0 / (_K_BOLTZ * _T0)            # molecules m^-3 at 15 C, 101325 Pa

# --- band: Bessell (1990) V response, 470..700 nm
V_LAMBDA_NM = np.arange(470.0, 701.0, 10.0)
V_RESPONSE = np.array([0.000, 0.030, 0.163, 0.458, 0.780, 0.967, 1.000, 0.973, 0.898,
                       0.792, 0.684, 0.574, 0.461, 0.359, 0.270, 0.197, 0.135, 0.081,
                       0.045, 0.025, 0.017, 0.013, 0.009, 0.000])
T_SUN_K = 5772.0


def planck(lam_nm, t_k):
    """Black-body spectral radiance (arbitrary units) at lam_nm for t_k."""
    lam = np.asarray(lam_nm) * 1e-9
    c2 = 1.438776877e-2  # m K (CODATA 2018 second radiation constant)
    return lam ** -5 / np.expm1(c2 / (lam * t_k))


def band_weights(band="V", t_sun_k=T_SUN_K):
    """Wavelengths (nm) and normalised weights of a band: "V" (solar
    spectrum x V response, 10 nm steps) or "total" (the solar spectrum's
    energy, trapezoid weights on TOTAL_LAMBDA_NM)."""
    if band == "V":
        w = V_RESPONSE * planck(V_LAMBDA_NM, t_sun_k)
        return V_LAMBDA_NM.copy(), w / w.sum()
    if band == "total":
        lam = TOTAL_LAMBDA_NM
        dl = np.zeros_like(lam)
        dl[:-1] += 0.5 * np.diff(lam)
        dl[1:] += 0.5 * np.diff(lam)
        w = planck(lam, t_sun_k) * dl
        return lam.copy(), w / w.sum()
    raise ValueError("unknown band %r (V or total)" % (band,))


# --- band: total solar irradiance. The energy spectrum of a 5772 K black body
# (its integral is the TSI by the definition of the effective temperature)
# from 350 nm to 4000 nm: 10 nm steps to 1000 nm, 50 nm beyond. Outside that
# range lies 8.0 % of the black body's energy (7.0 % below 350 nm, where
# the Huggins and Hartley bands of ozone, not tabulated here, and Rayleigh
# scattering take nearly all of a grazing ray's light; 1.0 % beyond 4 um);
# the weights are normalised over the range, i.e. that light is taken to
# pass as the band's mean does. docs/atmosphere.md states the sensitivity
# to the spectrum.
TOTAL_LAMBDA_NM = np.concatenate([np.arange(350.0, 1000.0, 10.0), np.arange(1000.0, 4001.0, 50.0)])


def _bodhaine_cm2(lam_um):
    num = 1.0455996 - 341.29061 * lam_um ** -2 - 0.90230850 * lam_um ** 2
    den = 1.0 + 0.0027059889 * lam_um ** -2 - 85.968563 * lam_um ** 2
    return 1e-28 * num / den


def rayleigh_cross_section_cm2(lam_nm):
    """Rayleigh cross-section per air molecule (cm^2): Bodhaine et al. (1999),
    eq. 29 (valid 250-1000 nm, 360 ppm CO2); beyond 1000 nm its value there
    times (1000 nm / lambda)^4 (the Rayleigh law: the refractive index and
    the depolarisation change by < 1 % beyond 1 um)."""
    lam = np.asarray(lam_nm, dtype=float) * 1e-3
    far = _bodhaine_cm2(1.0) * np.minimum(lam, 1.0) ** 4 / lam ** 4
    return np.where(lam <= 1.0, _bodhaine_cm2(np.minimum(lam, 1.0)), far)


# Ozone Chappuis band cross-sections (cm^2), room temperature, read from
# Serdyuchenko et al. (2014) Fig. 6 to ~5 %; linearly interpolated.
_O3_LAM = np.array([450., 470., 490., 510., 530., 550., 570., 590., 600., 610.,
                    630., 650., 670., 690., 710.])
_O3_SIG = 1e-21 * np.array([0.30, 0.55, 1.05, 1.55, 2.45, 3.30, 4.20, 4.80, 5.10,
                            5.00, 4.00, 2.80, 2.00, 1.30, 0.90])


def ozone_cross_section_cm2(lam_nm):
    """Chappuis band, 450-710 nm; 0 outside (the Wulf bands beyond 710 nm and
    the minimum near 380 nm are below 1e-22 cm^2, 2 % of the Chappuis peak)."""
    return np.interp(lam_nm, _O3_LAM, _O3_SIG, left=0.0, right=0.0)


DU_M2 = 2.6867e20           # molecules m^-2 per Dobson unit


@dataclass(frozen=True)
class Profile:
    """A spherically symmetric atmosphere.

    kind: "us1976" or "exponential"; n0 and scale_km for the exponential one.
    extinction: False gives the seed mode (refraction only, the solid Earth the
    only obstacle); cloud_top_km, cloud_fraction: the clouds stop that
    fraction of the rays whose lowest point is below the top (ignored in
    seed mode).
    Other fields: the stated loads (see module doc).
    """

    kind: str = "us1976"
    n0: float = N_S_550
    scale_km: float = 7.0
    top_km: float = TOP_KM
    earth_radius_km: float = R_EARTH_KM
    extinction: bool = True
    cloud_top_km: float = CLOUD_TOP_KM
    cloud_fraction: float = CLOUD_FRACTION
    ozone_du: float = 300.0
    ozone_peak_km: float = 22.0
    ozone_sigma_km: float = 6.4
    aer_trop_tau: float = 0.10
    aer_trop_scale_km: float = 1.5
    aer_trop_angstrom: float = 1.3
    aer_strat_tau: float = 0.005
    aer_strat_peak_km: float = 20.0
    aer_strat_sigma_km: float = 4.0
    aer_strat_angstrom: float = 1.5
    band: str = "V"
    label: str = field(default="", compare=False)

    # ---- refractivity
    def refractivity(self, h):
        """N(h) = n - 1 at geometric altitude h (km, array)."""
        h = np.asarray(h, dtype=float)
        if self.kind == "exponential":
            return self.n0 * np.exp(-h / self.scale_km)
        t, p, _ = us1976_state(h)
        return self.n0 * (p / t) / (_P0 / _T0)

    def refractivity_slope(self, h):
        """dN/dh (per km of geometric altitude)."""
        h = np.asarray(h, dtype=float)
        if self.kind == "exponential":
            return -self.refractivity(h) / self.scale_km
        t, _, lapse = us1976_state(h)
        dhp_dh = (_R0_GEOPOT / (_R0_GEOPOT + h)) ** 2
        return -self.refractivity(h) * (_GMR + lapse) / t * dhp_dh

    def breakpoints_km(self):
        """Altitudes where dN/dh jumps (layer boundaries), below the top."""
        if self.kind == "exponential":
            return np.zeros(0)
        hb = geometric_km(_HB[1:])
        return hb[hb < self.top_km]

    # ---- extinction ingredients (per metre of path, at altitude h km)
    def air_density_m3(self, h):
        """Molecular number density (m^-3)."""
        h = np.asarray(h, dtype=float)
        if self.kind == "exponential":
            return N_AIR_S * self.refractivity(h) / self.n0
        t, p, _ = us1976_state(h)
        return p / (_K_BOLTZ * t)

    def ozone_density_m3(self, h):
        col = self.ozone_du * DU_M2
        s = self.ozone_sigma_km * 1e3
        return col / (s * np.sqrt(2 * np.pi)) * np.exp(
            -0.5 * ((np.asarray(h) - self.ozone_peak_km) / self.ozone_sigma_km) ** 2)

    def aerosol_trop_per_m(self, h):
        """Tropospheric aerosol extinction at 550 nm (m^-1)."""
        hs = self.aer_trop_scale_km
        return self.aer_trop_tau / (hs * 1e3) * np.exp(-np.asarray(h) / hs)

    def aerosol_strat_per_m(self, h):
        s = self.aer_strat_sigma_km
        return self.aer_strat_tau / (s * 1e3 * np.sqrt(2 * np.pi)) * np.exp(
            -0.5 * ((np.asarray(h) - self.aer_strat_peak_km) / s) ** 2)

    def species(self, h):
        """Stack of the four extinction ingredients at altitude h:
        air (m^-3), ozone (m^-3), trop. aerosol and strat. aerosol (m^-1 at 550 nm)."""
        return np.stack([self.air_density_m3(h), self.ozone_density_m3(h),
                         self.aerosol_trop_per_m(h), self.aerosol_strat_per_m(h)])

    def species_weights(self, lam_nm):
        """Cross-sections (m^2) / relative extinction per species at lam_nm,
        shape (4, n_lambda): tau(lambda) = weights.T @ columns."""
        lam = np.asarray(lam_nm, dtype=float)
        return np.stack([rayleigh_cross_section_cm2(lam) * 1e-4,
                         ozone_cross_section_cm2(lam) * 1e-4,
                         (lam / 550.0) ** -self.aer_trop_angstrom,
                         (lam / 550.0) ** -self.aer_strat_angstrom])

    def vertical_optical_depth(self, lam_nm=550.0, n=4000):
        """Vertical optical depth per species from the ground to the top."""
        h = np.linspace(0.0, self.top_km, n + 1)
        cols = np.trapezoid(self.species(h), h * 1e3, axis=-1)
        return self.species_weights(np.atleast_1d(lam_nm))[:, 0] * cols


def us1976(**kw) -> Profile:
    """Default profile: 1976 U.S. Standard Atmosphere, clouds, full extinction."""
    return Profile(kind="us1976", label=kw.pop("label", "US1976"), **kw)


def exponential(n0=N_S_550, scale_km=7.0, **kw) -> Profile:
    return Profile(kind="exponential", n0=n0, scale_km=scale_km,
                   label=kw.pop("label", f"exp N0={n0:.3g} H={scale_km:g}"), **kw)


def seed_mode(base: Profile | None = None) -> Profile:
    """Refraction only: no extinction, no clouds (seed Fig. 10)."""
    import dataclasses
    base = base or us1976()
    return dataclasses.replace(base, extinction=False, label=(base.label or "") + " seed")
