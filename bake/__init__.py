# SPDX-License-Identifier: MIT
"""orbillum baker: earthshine reference, tables, emitter (python -m bake)."""

__version__ = "2.0.0"
