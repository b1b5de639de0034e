# SPDX-License-Identifier: MIT
"""What every bake shares: constants, the emitter, progress, quadrature."""
