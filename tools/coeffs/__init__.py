# SPDX-License-Identifier: MIT
"""Generators of the constants the runtime holds as literals in src/ (sin/cos,
atan2, Gauss-Legendre rules, limb darkening, pi in two parts and other
derived values); each module's constants()
returns them by their C names, and tests/python/test_coeffs.py checks every
literal of src/ against it, to the last bit. Run one as a script
(`.venv/bin/python -m tools.coeffs.sincos`) to print its C text."""
