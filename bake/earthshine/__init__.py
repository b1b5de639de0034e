# SPDX-License-Identifier: MIT
"""The earthshine tables: quadrature reference, grid and node values, lookup
mirror, measurement, mission scenes, the emitted Table."""
