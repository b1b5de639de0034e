# SPDX-License-Identifier: MIT
"""Photon mapping through atmospheric shells: an independent method for the
earthshine (mapping) and the light refracted into the shadow (atmosphere),
measured against the deterministic references."""
