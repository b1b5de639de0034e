# SPDX-License-Identifier: MIT
"""Clear-sky V-band optical depth of a line of sight versus its tangent height.

The runtime dims the Moon's light near the Earth's limb, seen from a target,
by the atmosphere's transmission along each line of sight to the Moon's disc
(src/atmosphere_moonlight.c). It needs tau(h) = -ln T(h), T the V-band
transmission of the default profile (bake/atmosphere/profile.py: Rayleigh,
ozone, aerosol; the clouds are applied separately, as in the profile) of the
ray whose lowest point is at h, from the ray reference
(bake/atmosphere/rays.py, `trace` and `band_transmission`). This module
gives tau at h = 0, 1, ..., 99 km (the runtime interpolates ln tau linearly;
tau falls to 0 at the 100 km top), written into src/atmosphere_moonlight.c
with 6 significant digits; tests/python/test_atm.py checks the numbers and
the interpolation error.

    python -m bake.atmosphere.moonlight      # prints the C initialiser
"""
from __future__ import annotations

import numpy as np

from . import profile as ap
from . import rays as ar

H_STEP_KM = 1.0
N_NODES = 100          # h = 0 .. 99 km


def tau_clear(h_km, profile=None):
    """-ln of the clear-sky V-band transmission of the rays of lowest altitude h_km."""
    profile = profile or ap.us1976()
    _, _, cols = ar.trace(profile, np.atleast_1d(np.asarray(h_km, dtype=float)))
    return -np.log(ar.band_transmission(profile, cols))


def nodes():
    h = np.arange(N_NODES) * H_STEP_KM
    return h, np.array([float("%.6g" % v) for v in tau_clear(h)])


def interpolate(h_km, tau_nodes, top_km=ap.TOP_KM):
    """The runtime's interpolation: ln tau linear between nodes, tau linear to 0
    from the last node to the top."""
    h = np.asarray(h_km, dtype=float)
    i = np.clip(np.floor(h / H_STEP_KM).astype(int), 0, N_NODES - 1)
    f = h / H_STEP_KM - i
    last = i >= N_NODES - 1
    lo = np.log(tau_nodes[np.minimum(i, N_NODES - 1)])
    hi = np.log(tau_nodes[np.minimum(i + 1, N_NODES - 1)])
    inner = np.exp(lo + f * (hi - lo))
    h_last = (N_NODES - 1) * H_STEP_KM
    outer = tau_nodes[-1] * np.clip((top_km - h) / (top_km - h_last), 0, 1)
    return np.where(last, outer, inner)


if __name__ == "__main__":
    _, t = nodes()
    rows = [", ".join("OI_R(%.6g)" % v for v in t[k:k + 5]) for k in range(0, t.size, 5)]
    print(",\n".join("    " + r for r in rows))
