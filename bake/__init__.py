# SPDX-License-Identifier: MIT
"""orbillum baker: the tables the runtime reads (python -m bake), by subject:
common/ (constants, emitter, progress, quadrature), earthshine/, atmosphere/,
photon/ (an independent method, measured), report/ (make report), config/."""

__version__ = "2.0.0"
